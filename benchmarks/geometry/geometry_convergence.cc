// SPDX-License-Identifier: LGPL-2.1-or-later
// Work-precision benchmark of the surface geometry: for the prolate [0.61, 0.61, 2.02] and oblate
// [1.27, 1.27, 0.47] spheroids and geometry degree k = 1, 2, 3, the relative errors of the area,
// the enclosed volume and the Willmore energy ½∫H² (weak curvature, SurfaceGeometry::willmore_energy())
// against exact_spheroid_measures(), the number of position DoFs, and the wall time of
// create() + measure() + willmore_energy() (median of the repetitions).
//
// Usage: geometry_convergence [--quick] [--repetitions N] [--max-time SECONDS] [--finest R1,R2,R3]
// (--finest: the finest refinement for k = 1, 2, 3; default 6,5,4, with --quick 4,3,2)
// Prints CSV on stdout (one header row); progress goes to stderr. A level whose predicted time
// (previous median × DoF ratio) exceeds --max-time is dropped with the finer levels of that k.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <fluid_surface/geometry/exact_geometry.h>
#include <fluid_surface/geometry/surface_geometry.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace FluidSurface;

namespace
{
  struct Result
  {
    unsigned int dofs;
    double       error[3]; // signed relative errors (discrete − exact)/exact: area, volume, willmore
    double       seconds;  // one repetition
  };

  Result
  run_once(const double a, const double c, const unsigned int k, const unsigned int refinement,
           const FluidSurface::SpheroidMeasures &exact)
  {
    dealii::ParameterHandler prm;
    SurfaceGeometry::declare_parameters(prm);
    prm.enter_subsection("geometry");
    prm.set("shape", "ellipsoid");
    prm.set("semi-axes", dealii::Utilities::to_string(a, 17) + "," + dealii::Utilities::to_string(a, 17) + "," +
                           dealii::Utilities::to_string(c, 17));
    prm.set("refinement", std::to_string(refinement));
    prm.set("position degree", std::to_string(k));
    prm.leave_subsection();

    Result r;
    {
      SurfaceGeometry geometry(MPI_COMM_WORLD);
      geometry.parse_parameters(prm);

      const auto start = std::chrono::steady_clock::now();
      geometry.create();
      const SurfaceGeometry::Measures m = geometry.measure();
      const double                    w = geometry.willmore_energy();
      const auto                      stop = std::chrono::steady_clock::now();

      r.seconds  = std::chrono::duration<double>(stop - start).count();
      r.dofs     = geometry.dof_handler().n_dofs();
      r.error[0] = (m.area - exact.area) / exact.area;
      r.error[1] = (m.volume - exact.volume) / exact.volume;
      r.error[2] = (w - exact.willmore) / exact.willmore;
    }
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  bool         quick       = false;
  unsigned int repetitions = 3;
  double       max_time    = 20.0;
  unsigned int finest[4]   = {0, 6, 5, 4}; // by k
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--quick") == 0)
      quick = true;
    else if (std::strcmp(argv[i], "--repetitions") == 0 && i + 1 < argc)
      repetitions = std::max(1, std::atoi(argv[++i]));
    else if (std::strcmp(argv[i], "--max-time") == 0 && i + 1 < argc)
      max_time = std::atof(argv[++i]);
    else if (std::strcmp(argv[i], "--finest") == 0 && i + 1 < argc &&
             std::sscanf(argv[++i], "%u,%u,%u", &finest[1], &finest[2], &finest[3]) == 3)
      ;
    else
      {
        std::fprintf(stderr, "usage: %s [--quick] [--repetitions N] [--max-time SECONDS] [--finest R1,R2,R3]\n", argv[0]);
        return 2;
      }

  if (quick)
    for (unsigned int k = 1; k <= 3; ++k)
      finest[k] = std::min(finest[k], 5u - k); // 4, 3, 2
  const char  *names[2]   = {"prolate", "oblate"};
  const double axes[2][2] = {{0.61, 2.02}, {1.27, 0.47}};

  std::printf("shape,k,refinement,dofs,area_error,volume_error,willmore_error,wall_time_s,"
              "area_rate,volume_rate,willmore_rate\n");
  std::fflush(stdout);

  // One untimed warm-up run: the first run pays for first-touch costs (libraries, allocator).
  run_once(axes[0][0], axes[0][1], 1, 1, exact_spheroid_measures(axes[0][0], axes[0][1]));

  for (unsigned int s = 0; s < 2; ++s)
    {
      const double           a = axes[s][0], c = axes[s][1];
      const SpheroidMeasures exact = exact_spheroid_measures(a, c);
      std::fprintf(stderr, "%s [%g, %g, %g]: exact area %.12g volume %.12g willmore %.12g\n", names[s], a, a, c,
                   exact.area, exact.volume, exact.willmore);
      for (unsigned int k = 1; k <= 3; ++k)
        {
          Result       previous{};
          bool         have_previous = false;
          const unsigned int last = finest[k];
          for (unsigned int refinement = 1; refinement <= last; ++refinement)
            {
              if (have_previous)
                {
                  // Cost grows like the DoFs; the DoFs grow by ~4 per refinement.
                  const double predicted = previous.seconds * 4.0;
                  if (predicted > max_time)
                    {
                      std::fprintf(stderr, "  %s k=%u: refinement %u and finer dropped (predicted %.1f s > %.1f s)\n",
                                   names[s], k, refinement, predicted, max_time);
                      break;
                    }
                }
              std::vector<double> times;
              Result              r{};
              for (unsigned int rep = 0; rep < repetitions; ++rep)
                {
                  r = run_once(a, c, k, refinement, exact);
                  times.push_back(r.seconds);
                }
              std::sort(times.begin(), times.end());
              r.seconds = times[times.size() / 2];

              std::printf("%s,%u,%u,%u,%.6e,%.6e,%.6e,%.6f", names[s], k, refinement, r.dofs, std::abs(r.error[0]),
                          std::abs(r.error[1]), std::abs(r.error[2]), r.seconds);
              for (unsigned int q = 0; q < 3; ++q)
                if (have_previous && r.error[q] != 0 && previous.error[q] != 0)
                  // Rate in h ~ N^{-1/2}: e ~ h^p  ⇔  p = 2 log(e_prev/e) / log(N/N_prev).
                  std::printf(",%.3f", 2.0 * std::log(std::abs(previous.error[q] / r.error[q])) /
                                         std::log(double(r.dofs) / previous.dofs));
                else
                  std::printf(",");
              std::printf("\n");
              std::fflush(stdout);
              std::fprintf(stderr, "  %s k=%u ref=%u dofs=%u  signed errors %+.2e %+.2e %+.2e  %.3f s\n", names[s], k, refinement,
                           r.dofs, r.error[0], r.error[1], r.error[2], r.seconds);
              previous      = r;
              have_previous = true;
            }
        }
    }
}
