// SPDX-License-Identifier: LGPL-2.1-or-later
// Convergence of the Chebyshev collocation solver for the rotating axisymmetric equilibria in the number N of
// collocation intervals (the shapes of the reference table: A = 4π, Be = 1, v = 0.75, Be ω² ∈ {0, 4}), and the
// predicted equilibria for the seed runs (spheroids [0.61, 0.61, 2.02] and [1.27, 1.27, 0.47] rotating at
// ω0 = 4: same area, reduced volume and angular momentum L0 = 4 I_zz(spheroid)).
//
// Usage: convergence [--quick] RESULTS.csv   (summary on stdout)
#include <fluid_surface/geometry/exact_geometry.h>
#include <fluid_surface/reference/axisymmetric_equilibrium.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace FluidSurface;
using Equilibrium = AxisymmetricEquilibrium;

namespace
{
  struct Shape
  {
    const char         *name;
    Equilibrium::Branch branch;
    double              Be_omega2;
    double              reference_bending, reference_inertia; // reference table, 6 digits
  };

  /// Solves @p repetitions times; returns the fastest wall time of solve() in seconds.
  double
  timed_solve(Equilibrium &equilibrium, const unsigned int repetitions)
  {
    double best = 1e300;
    for (unsigned int k = 0; k < repetitions; ++k)
      {
        const auto start = std::chrono::steady_clock::now();
        equilibrium.solve();
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      }
    return best;
  }
} // namespace

int
main(int argc, char **argv)
{
  bool        quick = false;
  std::string csv   = "results.csv";
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--quick") == 0)
      quick = true;
    else
      csv = argv[i];

  const std::vector<Shape> shapes = {{"prolate_w2_0", Equilibrium::Branch::prolate, 0, 37.745215, 3.613051},
                                     {"prolate_w2_4", Equilibrium::Branch::prolate, 4, 37.880610, 3.734086},
                                     {"oblate_w2_0", Equilibrium::Branch::oblate, 0, 39.571001, 11.336771},
                                     {"oblate_w2_4", Equilibrium::Branch::oblate, 4, 39.639100, 11.410791}};
  const std::vector<unsigned int> sizes =
    quick ? std::vector<unsigned int>{8, 12, 16, 24, 32, 48}
          : std::vector<unsigned int>{8, 10, 12, 14, 16, 20, 24, 28, 32, 40, 48, 64, 96};
  const unsigned int finest      = 128;
  const unsigned int repetitions = quick ? 1 : 5;

  std::FILE *out = std::fopen(csv.c_str(), "w");
  if (!out)
    {
      std::fprintf(stderr, "cannot write %s\n", csv.c_str());
      return 1;
    }
  std::fprintf(out, "shape,N,unknowns,bending_energy,inertia_zz,p0,gamma,error_bending_energy,error_inertia_zz,"
                    "error_p0,wall_time_s\n");

  std::printf("Reference table (A = 4π, Be = 1, v = 0.75), N = 48 (default):\n");
  std::printf("| branch | Be·ω² | ½∫H² (ours) | ½∫H² (reference) | I_zz (ours) | I_zz (reference) | p0 | γ | solve time |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const Shape &shape : shapes)
    {
      Equilibrium::Parameters parameters;
      parameters.branch           = shape.branch;
      parameters.angular_velocity = std::sqrt(shape.Be_omega2);

      parameters.collocation_points         = finest;
      parameters.maximal_collocation_points = finest;
      Equilibrium reference(parameters);
      reference.solve();

      for (const unsigned int N : sizes)
        {
          parameters.collocation_points         = N;
          parameters.maximal_collocation_points = N; // fixed N: no automatic doubling
          Equilibrium  equilibrium(parameters);
          const double time = timed_solve(equilibrium, repetitions);
          std::fprintf(out, "%s,%u,%u,%.15g,%.15g,%.15g,%.15g,%.3e,%.3e,%.3e,%.3e\n", shape.name, N, 4 * (N + 1) + 3,
                       equilibrium.bending_energy(), equilibrium.inertia_zz(), equilibrium.p0(), equilibrium.gamma(),
                       std::abs(equilibrium.bending_energy() - reference.bending_energy()) / reference.bending_energy(),
                       std::abs(equilibrium.inertia_zz() - reference.inertia_zz()) / reference.inertia_zz(),
                       std::abs(equilibrium.p0() - reference.p0()) / std::abs(reference.p0()), time);
          if (N == 48)
            std::printf("| %s | %g | %.10f | %.6f | %.10f | %.6f | %.8f | %.8f | %.3f s |\n",
                        shape.branch == Equilibrium::Branch::prolate ? "prolate" : "oblate", shape.Be_omega2,
                        equilibrium.bending_energy(), shape.reference_bending, equilibrium.inertia_zz(),
                        shape.reference_inertia, equilibrium.p0(), equilibrium.gamma(), time);
        }
    }
  std::fclose(out);

  std::printf("\nSeed runs: spheroid rotating rigidly at ω0 = 4 -> equilibrium at the same A, v and L0 = 4 I_zz:\n");
  std::printf("| spheroid | A | v | I_zz | ½∫H² | L0 | ω | ½∫H² | I_zz | ½ω²I_zz | p0 | γ | equatorial r | max r | polar half height |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  const double axes[2][2] = {{0.61, 2.02}, {1.27, 0.47}};
  for (unsigned int k = 0; k < 2; ++k)
    {
      const SpheroidMeasures  spheroid = exact_spheroid_measures(axes[k][0], axes[k][1]);
      Equilibrium::Parameters parameters;
      parameters.branch           = (k == 0 ? Equilibrium::Branch::prolate : Equilibrium::Branch::oblate);
      parameters.area             = spheroid.area;
      parameters.reduced_volume   = spheroid.reduced_volume;
      parameters.prescribed       = Equilibrium::Prescribed::angular_momentum;
      parameters.angular_momentum = 4 * spheroid.inertia_zz;
      Equilibrium equilibrium(parameters);
      equilibrium.solve();
      std::printf("| [%g, %g, %g] | %.8f | %.8f | %.8f | %.8f | %.8f | %.6f | %.6f | %.6f | %.6f | %.6f | %.6f | %.6f | "
                  "%.6f | %.6f |\n",
                  axes[k][0], axes[k][0], axes[k][1], spheroid.area, spheroid.reduced_volume, spheroid.inertia_zz,
                  spheroid.willmore, parameters.angular_momentum, equilibrium.angular_velocity(),
                  equilibrium.bending_energy(), equilibrium.inertia_zz(), equilibrium.kinetic_energy(), equilibrium.p0(), equilibrium.gamma(),
                  equilibrium.equatorial_radius(), equilibrium.max_radius(), equilibrium.polar_height());
    }

  std::printf("\nFor comparison, the equilibria at the seed's measured ⟨ω⟩ (same A and v), with their L = ω I_zz:\n");
  std::printf("| branch | ω | ½∫H² | I_zz | L | L / L0 |\n|---|---|---|---|---|---|\n");
  const double seed_omega[2] = {2.324, 3.864};
  for (unsigned int k = 0; k < 2; ++k)
    {
      const SpheroidMeasures  spheroid = exact_spheroid_measures(axes[k][0], axes[k][1]);
      Equilibrium::Parameters parameters;
      parameters.branch           = (k == 0 ? Equilibrium::Branch::prolate : Equilibrium::Branch::oblate);
      parameters.area             = spheroid.area;
      parameters.reduced_volume   = spheroid.reduced_volume;
      parameters.angular_velocity = seed_omega[k];
      Equilibrium equilibrium(parameters);
      equilibrium.solve();
      std::printf("| %s | %.3f | %.6f | %.6f | %.6f | %.4f |\n", k == 0 ? "prolate" : "oblate", seed_omega[k],
                  equilibrium.bending_energy(), equilibrium.inertia_zz(), equilibrium.angular_momentum(),
                  equilibrium.angular_momentum() / (4 * spheroid.inertia_zz));
    }
  return 0;
}
