// SPDX-License-Identifier: LGPL-2.1-or-later
// The approximate factorizations of `linear solver` against the double-precision LU: the prolate [0.61, 0.61,
// 2.02] spinning at ω = 4 about its axis (refinement 2, conserve momenta, the volume multiplier), six steps of
// τ = 0.01 with the factorization kept across steps. With single-precision factors (the default of MUMPS) and
// with MUMPS' block-low-rank factors (ε_BLR = 1e-8) every solve is flexible GMRES or GMRES to the tolerance,
// also right after a factorization: F after every step agrees with that of the double-precision factors to
// 1e-10 relative, and the factorizations are as many. Also on two MPI ranks (SinglePrecisionLU gathers the
// right-hand sides on the first).
#include "surface_run.h"

#include <cmath>
#include <cstdio>
#include <vector>

using namespace FluidSurface;

namespace
{
  struct Trajectory
  {
    std::vector<double> energies;
    unsigned int        factorizations = 0;
  };

  Trajectory
  run(const Overrides &solver)
  {
    Overrides overrides{{"initial state/angular velocity", "4"}, {"flow/conserve momenta", "true"}};
    overrides.insert(overrides.end(), solver.begin(), solver.end());
    SurfaceRun surface("ellipsoid", "0.61, 0.61, 2.02", 2, "prolate", false, overrides);
    Trajectory trajectory;
    double     time = 0;
    for (unsigned int n = 0; n < 6; ++n)
      {
        const auto result = surface.model.advance(0.01);
        if (!result.solved)
          throw std::runtime_error(result.message);
        trajectory.energies.push_back(surface.model.candidate_energies().total);
        time += 0.01;
        surface.model.accept(time);
      }
    trajectory.factorizations = surface.model.step().solver().n_factorizations();
    return trajectory;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const Trajectory reference = run({{"linear solver/factor precision", "double"}});
  if (root)
    std::printf("double-precision LU: F after 6 steps %.8f, %u factorizations\n",
                reference.energies.back(),
                reference.factorizations);
  const std::vector<std::pair<const char *, Overrides>> variants{
    {"single-precision LU", {{"linear solver/factor precision", "single"}}},
    {"block-low-rank LU (1e-8)",
     {{"linear solver/factor precision", "double"}, {"linear solver/low rank tolerance", "1e-8"}}}};
  for (const auto &[name, overrides] : variants)
    {
      const Trajectory trajectory = run(overrides);
      double           difference = 0;
      for (unsigned int n = 0; n < reference.energies.size(); ++n)
        difference = std::max(difference,
                              std::abs(trajectory.energies[n] - reference.energies[n]) /
                                std::abs(reference.energies[n]));
      if (root)
        std::printf("%s: F after every step within 1e-10 of the double-precision LU's: %s; factorizations: %u\n",
                    name,
                    difference < 1e-10 ? "yes" : "no",
                    trajectory.factorizations);
    }
}
