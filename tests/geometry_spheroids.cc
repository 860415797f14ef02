// SPDX-License-Identifier: LGPL-2.1-or-later
// Geometry of the seed's prolate [0.61, 0.61, 2.02] and oblate [1.27, 1.27, 0.47] spheroids:
// relative errors of area, volume (expected ~h^(2k)) and, for k = 2, of the Willmore energy ½∫H²
// from the weak curvature (expected ~h^4), against exact values, with observed rates.
#include <deal.II/base/mpi.h>

#include <fluid_surface/geometry/exact_geometry.h>
#include <fluid_surface/geometry/surface_geometry.h>

#include <cmath>
#include <cstdio>

using namespace FluidSurface;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double axes[2][2] = {{0.61, 2.02}, {1.27, 0.47}};
  const char  *names[2]   = {"prolate", "oblate"};
  for (unsigned int shape = 0; shape < 2; ++shape)
    {
      const double           a = axes[shape][0], c = axes[shape][1];
      const SpheroidMeasures exact = exact_spheroid_measures(a, c);
      std::printf("%s [%g, %g, %g]: exact area %.10f volume %.10f willmore %.10f\n",
                  names[shape], a, a, c, exact.area, exact.volume, exact.willmore);
      for (unsigned int k = 1; k <= 3; ++k)
        {
          double previous[3] = {0, 0, 0};
          for (unsigned int r = 1; r <= (k == 3 ? 3u : 4u); ++r)
            {
              dealii::ParameterHandler prm;
              SurfaceGeometry::declare_parameters(prm);
              prm.enter_subsection("geometry");
              prm.set("shape", "ellipsoid");
              prm.set("semi-axes", std::to_string(a) + "," + std::to_string(a) + "," + std::to_string(c));
              prm.set("refinement", std::to_string(r));
              prm.set("position degree", std::to_string(k));
              prm.leave_subsection();
              SurfaceGeometry geometry(MPI_COMM_WORLD);
              geometry.parse_parameters(prm);
              geometry.create();
              const SurfaceGeometry::Measures m = geometry.measure();
              const double                    w = geometry.willmore_energy();
              const double err[3] = {std::abs(m.area - exact.area) / exact.area,
                                     std::abs(m.volume - exact.volume) / exact.volume,
                                     std::abs(w - exact.willmore) / exact.willmore};
              std::printf("  k=%u ref=%u area %.2e volume %.2e", k, r, err[0], err[1]);
              if (k >= 2)
                std::printf(" willmore %.2e", err[2]);
              if (r > 1)
                {
                  std::printf("  rates %.1f %.1f", std::log2(previous[0] / err[0]), std::log2(previous[1] / err[1]));
                  if (k >= 2)
                    std::printf(" %.1f", std::log2(previous[2] / err[2]));
                }
              std::printf("\n");
              for (unsigned int i = 0; i < 3; ++i)
                previous[i] = err[i];
            }
        }
    }
}
