// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_step_failure_h
#define fluid_surface_model_step_failure_h

#include <string>

namespace FluidSurface
{
  /// Why a step attempt of scene full was not accepted.
  enum class StepFailure
  {
    none,               ///< the step was solved
    linear_solver,      ///< the bordered solve failed (its report goes to error.log)
    not_finite,         ///< the solution has a non-finite entry
    geometry_iteration, ///< GeometryIteration did not converge within its iterations
    error_estimate,     ///< the local error estimate is above `time stepping/error tolerance`
    energy_rise         ///< the energy rose faster than `time stepping/energy tolerance` allows
  };

  /**
   * What a user can change when every τ tried failed with @p failure: the advice of the error message that
   * stops the run, one table for all failures. @p error_log names the file with the solver's report.
   */
  std::string
  advice(const StepFailure failure, const std::string &error_log);
} // namespace FluidSurface

#endif
