// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_scenes_step_controller_h
#define fluid_surface_scenes_step_controller_h

#include <deal.II/base/conditional_ostream.h>

#include <fluid_surface/model/fluid_deformable_surface.h>
#include <fluid_surface/time_stepping/energy_step_controller.h>
#include <fluid_surface/time_stepping/time_stepper.h>

#include <optional>
#include <string>

namespace FluidSurface
{
  /**
   * The control of the time steps of the fluid deformable surface, one loop for scene full and scene stability.
   * An attempt solves the step of the TimeStepper's τ (FluidDeformableSurface::advance()), checks its local error
   * (`time stepping/error tolerance` > 0) and, where the scene asks for it, its energy (EnergyStepController),
   * and accepts it (FluidDeformableSurface::accept(), TimeStepper::accept()), or undoes it and sets up the retry:
   * at the same τ with the iterated geometry (`geometry iteration/apply = after rejection`) or as a backward-Euler
   * step (`backward Euler steps after rejection`), else with a smaller τ (TimeStepper::reject(), which ends the
   * run with RunFailed below τ_min or when τ is not adaptive, as in a time map of scene stability).
   */
  class StepController
  {
  public:
    /// An accepted step.
    struct AcceptedStep
    {
      double              tau = 0;          ///< its size
      SurfaceStep::Result result;           ///< the solve
      double              willmore     = 0; ///< ½∫H² of the new surface (with an energy check)
      double              total_energy = 0; ///< F of the new state (with an energy check)
    };

    /**
     * The steps of @p model with the sizes of @p time, printing to @p pcout; a solver's report of a failure goes
     * to `error.log` in @p output_directory (rank 0 of @p communicator).
     */
    StepController(FluidDeformableSurface           &model,
                   TimeStepper                      &time,
                   const dealii::ConditionalOStream &pcout,
                   const std::string                &output_directory,
                   const MPI_Comm                    communicator);

    /// From now on every solved step passes the energy check @p energy_check (scene full; kept by reference).
    void
    check_energy(EnergyStepController &energy_check)
    {
      energy_control = &energy_check;
    }

    /**
     * One attempt of the step of size TimeStepper::step_size() from the accepted state of total energy @p energy
     * (F(t) of the energy check). Returns the accepted step, or nothing if it was undone and is to be retried;
     * RunFailed if it may not be (TimeStepper::reject()).
     */
    std::optional<AcceptedStep>
    attempt(const double energy);

  private:
    /**
     * Undoes the step of size @p tau (not solved or rejected: @p failure, in one line @p reason; its advice comes
     * from advice()) and shrinks τ for its retry (by @p factor > 0 if that is smaller than the shrink factor); a
     * non-empty @p solver_report goes to error.log.
     */
    void
    retry(const double       tau,
          const StepFailure  failure,
          const std::string &reason,
          const std::string &solver_report,
          const double       factor = 0);
    /// Accepts the step of size @p tau with the energy check's @p decision.
    void
    accept(const double tau, const double error_estimate, const EnergyStepController::Decision &decision);

    FluidDeformableSurface             &model;
    TimeStepper                        &time;
    const dealii::ConditionalOStream   &pcout;
    std::string                         output_directory;
    MPI_Comm                            communicator;
    EnergyStepController               *energy_control = nullptr; ///< the energy check (none: nullptr)
  };
} // namespace FluidSurface

#endif
