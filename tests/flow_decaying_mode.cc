// SPDX-License-Identifier: LGPL-2.1-or-later
// u = exp(-λt) curl_S Y_l⁰ on the unit sphere, Navier–Stokes (convection on), Re = 10, BDF2,
// refinement 2 and 3, τ = 0.05, t ∈ [0, 1]: the measured decay rate −ln(F(1)/F(0))/2 against
// λ = (l(l+1) − 2)/Re, for l = 2 and 3; the last line uses the block-preconditioned solver.
#include "flow_common.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int l : {2u, 3u})
    for (unsigned int r = 2; r <= 3; ++r)
      {
        const auto result = FlowTest::run({{"geometry/shape", "sphere"},
                                           {"geometry/refinement", std::to_string(r)},
                                           {"fixed surface/problem", "decaying mode"},
                                           {"fixed surface/mode number", std::to_string(l)},
                                           {"flow/Re", "10"},
                                           {"time stepping/time step", "0.05"},
                                           {"time stepping/end time", "1"}});
        if (FlowTest::is_root())
          std::printf("l %u refinement %u  rate %.4f  exact %.4f  relative deviation %s\n", l, r,
                      result.measured_decay_rate, result.exact_decay_rate,
                      FlowTest::scientific(std::abs(result.measured_decay_rate / result.exact_decay_rate - 1)).c_str());
      }
  const auto result = FlowTest::run({{"geometry/shape", "sphere"},
                                     {"geometry/refinement", "2"},
                                     {"fixed surface/problem", "decaying mode"},
                                     {"flow/Re", "10"},
                                     {"fixed surface solver/linear solver", "block preconditioned"},
                                     {"time stepping/time step", "0.05"},
                                     {"time stepping/end time", "1"}});
  if (FlowTest::is_root())
    std::printf("block preconditioned, l 2 refinement 2  rate %.4f  iterations per step below 40: %s\n",
                result.measured_decay_rate, result.max_iterations < 40 ? "yes" : "no");
}
