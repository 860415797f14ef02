// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/model/step_failure.h>

namespace FluidSurface
{
  std::string
  advice(const StepFailure failure, const std::string &error_log)
  {
    switch (failure)
      {
        case StepFailure::linear_solver:
          return "the linear solver failed (its report is in " + error_log +
                 "); try a smaller 'time stepping/maximum time step', 'linear solver/reuse factorization = false' or "
                 "another 'linear solver/direct solver'; ";
        case StepFailure::geometry_iteration:
          return "the step's geometry iteration did not contract at every τ tried; try a larger 'geometry "
                 "iteration/maximum iterations' or 'geometry iteration/tolerance', or 'maximum iterations = 0' (the "
                 "lagged step); ";
        case StepFailure::not_finite:
          return "the step's solution was not finite; try a smaller 'time stepping/maximum time step' or a finer "
                 "'geometry/refinement', and check that the physical parameters are of order 1; ";
        case StepFailure::none:
        case StepFailure::error_estimate:
        case StepFailure::energy_rise:
          break;
      }
    return "the energy rose faster than 'time stepping/energy tolerance' allows at every τ tried; try a finer "
           "'geometry/refinement' or a smaller 'time stepping/maximum time step' (doc/scheme.md, \"The residual "
           "energy rise\"); ";
  }
} // namespace FluidSurface
