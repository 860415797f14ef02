// SPDX-License-Identifier: LGPL-2.1-or-later
// Initial state from a rotating equilibrium (geometry/shape = equilibrium, initial state/equilibrium
// rotation = true): the refined cube sphere mapped onto the prolate and oblate equilibria (A = 4π, v = 0.75,
// ω = 2) reproduces their area, volume and Willmore energy ½∫H² (weak curvature) at the rates of the Q2
// geometry, and the initial velocity is the equilibrium's rigid rotation (ω(t=0) = ω, rigid fraction 1).
#include <cmath>
#include <cstdio>

#include "surface_run.h"

using namespace FluidSurface;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const std::string branch : {"prolate", "oblate"})
    {
      std::printf("%s equilibrium\n", branch.c_str());
      double previous[3] = {0, 0, 0};
      for (unsigned int r = 1; r <= 4; ++r)
        {
          SurfaceRun                     run("equilibrium", "1, 1, 1", r, branch, true);
          const AxisymmetricEquilibrium &shape    = *run.geometry.equilibrium_shape();
          const SurfaceGeometry::Measures m        = run.geometry.measure();
          const double                    willmore = run.geometry.willmore_energy();
          const double                    error[3] = {std::abs(m.area / shape.area() - 1),
                                                      std::abs(m.volume / shape.volume() - 1),
                                                      std::abs(willmore / shape.bending_energy() - 1)};
          std::printf("  refinement %u: errors area %.1e volume %.1e willmore %.1e", r, error[0], error[1], error[2]);
          if (r > 1)
            std::printf("  rates %.1f %.1f %.1f", std::log2(previous[0] / error[0]), std::log2(previous[1] / error[1]),
                        std::log2(previous[2] / error[2]));
          std::printf("\n");
          for (unsigned int i = 0; i < 3; ++i)
            previous[i] = error[i];
          if (r == 2)
            {
              const Diagnostics::Values v =
                run.diagnostics.evaluate(run.geometry, run.model.dof_handler(), run.model.solution());
              std::printf("  refinement 2: omega(0) - omega_equilibrium %.1e  rigid fraction %.10f\n",
                          std::abs(v.angular_velocity - shape.angular_velocity()), v.rigid_fraction);
            }
        }
    }
}
