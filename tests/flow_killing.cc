// SPDX-License-Identifier: LGPL-2.1-or-later
// The Killing field u = e_z × x on the fixed unit sphere is a steady Navier–Stokes solution
// (p = ½(x² + y²)); Re = 10, BDF2, τ = 0.05, t ∈ [0, 1], penalty β = 1000: the relative change of
// the kinetic energy must decrease under refinement (the penalty dissipates ‖λ‖²/η, η = β h^-3).
#include "flow_common.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  double previous = 0;
  for (unsigned int r = 2; r <= 3; ++r)
    {
      const auto result = FlowTest::run({{"geometry/shape", "sphere"},
                                         {"geometry/refinement", std::to_string(r)},
                                         {"fixed surface/problem", "killing"},
                                         {"flow/Re", "10"},
                                         {"fixed surface solver/penalty factor", "1000"},
                                         {"time stepping/time step", "0.05"},
                                         {"time stepping/end time", "1"}});
      if (FlowTest::is_root())
        {
          std::printf("refinement %u  F(0) = %.6f  |F(1) - F(0)|/F(0) = %s", r, result.initial_kinetic_energy,
                      FlowTest::scientific(result.energy_change).c_str());
          if (r > 2)
            std::printf("  rate %.1f", std::log2(previous / result.energy_change));
          std::printf("\n  ||u - u_h|| = %s at t = 1\n", FlowTest::scientific(result.errors.velocity).c_str());
        }
      previous = result.energy_change;
    }
}
