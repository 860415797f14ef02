// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_scenes_full_model_scene_h
#define fluid_surface_scenes_full_model_scene_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/model/fluid_deformable_surface.h>
#include <fluid_surface/postprocess/diagnostics.h>
#include <fluid_surface/scenes/scene.h>
#include <fluid_surface/scenes/step_controller.h>
#include <fluid_surface/time_stepping/energy_step_controller.h>
#include <fluid_surface/time_stepping/end_state_stability.h>
#include <fluid_surface/time_stepping/steady_state.h>
#include <fluid_surface/time_stepping/time_stepper.h>

#include <array>
#include <string>

namespace FluidSurface
{
  class StopSignals;

  /**
   * Scene `full`: the fluid deformable surface of the seed paper (surface
   * Navier–Stokes, bending, volume constraint, mesh redistribution) on the
   * moving surface. The time loop takes a step, checks its energy
   * (EnergyStepController), accepts or retries it, records diagnostics,
   * writes output and checkpoints; it ends with the summary. A run stopped by
   * SIGINT/SIGTERM or after `checkpoint/steps per run` writes a checkpoint and
   * throws RunStopped; a later run continues it bit for bit.
   */
  class FullModelScene : public Scene
  {
  public:
    /// See Scene; @p wall_timer is the Simulation's clock (the wall time of the run).
    FullModelScene(const MPI_Comm                    communicator,
                   SurfaceGeometry                  &geometry,
                   OutputWriter                     &output,
                   StatisticsFile                   &statistics,
                   const dealii::ConditionalOStream &pcout,
                   const dealii::Timer              &wall_timer);

    /// Every subsection but `fixed surface`, `fixed surface solver` and `stability`.
    ParametersRead
    parameters_read() const override;

    /// Reads the time stepping, the model, the diagnostics and the checkpoints.
    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    /// Sets up the checkpoint directory and finds the checkpoint chosen by `checkpoint/resume`.
    bool
    find_checkpoint() override;

    /// The time loop, from step 0 or from the checkpoint find_checkpoint() chose.
    void
    run() override;

  private:
    /// Sets up the model at t = 0 and records and writes the initial state.
    void
    set_up_initial_state();
    /// Restores every component from the checkpoint and checks that it reproduces its total energy.
    void
    resume_from_checkpoint();
    /**
     * One attempt of a time step by @p controller (solve, check the error estimate and the energy, accept or
     * set up the retry); an accepted step is followed by the safety valve if due, the record and the files.
     * Returns false when the run has reached its steady state.
     */
    bool
    attempt_step(StepController &controller, const StopSignals &stop_signals);

    /**
     * At a state the steady-state check calls an end state or a plateau: its class (EndStateStability); at a saddle the
     * surface is displaced along its falling class and the check starts again. Returns whether it was a saddle.
     */
    bool
    leave_saddle(const Diagnostics::Values &values);
    /**
     * One statistics row and screen report of the accepted state (with the @p jumps of the re-parametrization
     * of this step, zero if none); returns its measures.
     */
    Diagnostics::Values
    record_step(const double                           tau,
                const SurfaceStep::Result             &step,
                const SurfaceReparametrization::Jumps &jumps = {{0, 0, 0, 0}});
    /**
     * With `time stepping/energy budget`: one row of the file energy_budget for the accepted @p step of size
     * @p tau whose final kinetic and bending energies are @p kinetic and @p bending (rank 0 writes).
     */
    void
    write_energy_budget(const double tau, const SurfaceStep::Result &step, const double kinetic, const double bending) const;
    /**
     * The safety valve after an accepted step: re-parametrizes the surface when its mesh quality is due
     * (SurfaceReparametrization::due()), records it with the valve and returns the jumps, measured as the
     * statistics measure them.
     */
    SurfaceReparametrization::Jumps
    reparametrize_if_due();
    /// K − |L|²/(2λ₃) of @p v: zero only for a rigid rotation about the axis of largest inertia.
    static double
    kinetic_energy_excess(const Diagnostics::Values &v);
    /// Anchors the mesh law once the flow of @p v, after having been non-rigid, rotates rigidly (`mesh
    /// redistribution/anchor non-rigid energy`).
    void
    anchor_if_rigid(const Diagnostics::Values &v);
    /// Throws RunFailed when the mesh quality fell below `mesh quality floor`.
    void
    check_mesh_quality() const;
    /// Writes the VTU file of the current state.
    void
    write_output();
    /// Writes everything a resumed run needs to continue bit for bit; returns whether it was written.
    bool
    write_checkpoint();
    /**
     * After an accepted step: writes a checkpoint if one is due or if the run
     * stops (on @p signal, or after `steps per run`); then throws RunStopped.
     */
    void
    checkpoint_or_stop(const int signal);
    /**
     * Writes the file `summary`, whose first line is `status: @p status` ("completed", or "stopped at t = …:
     * reason"), and prints it (without the wall time unless `report wall time`).
     */
    void
    write_summary(const std::string &status) const;
    /// The summary of a run that stops before its end time because of @p reason (rank 0, never throws).
    void
    write_summary_of_stopped_run(const std::string &reason);
    /// Appends @p text to `error.log` in the output directory (rank 0).
    void
    log_error(const std::string &text) const;
    /// Writes the wall time per section (file `timing`; the screen if `report wall time`).
    void
    write_timing();
    /// Wall time of the run in seconds, including the part before a restart.
    double
    elapsed_wall_time() const
    {
      return wall_time_before_restart + wall_timer.wall_time();
    }

    MPI_Comm             communicator;
    const dealii::Timer &wall_timer;
    /// Wall time per section: assembly, factorization, linear solve, curvature and energy, diagnostics,
    /// output. Printed at the end when `output/report wall time` is on; always written to the file `timing`.
    dealii::TimerOutput computing_timer;

    TimeStepper            time;
    EnergyStepController   energy_control;
    FluidDeformableSurface model;
    Diagnostics            diagnostics;
    Checkpoint             checkpoint;
    SteadyState            steady_state;
    EndStateStability      end_state_stability;
    /// How the end state was reached (empty until then).
    std::string steady_state_report;
    /// The energetic class of the end state (empty until then, or when it was not assessed).
    std::string end_state_class;

    bool         resuming = false;
    double       total_energy = 0;             ///< F = kinetic + bending energy of the accepted state
    double       willmore     = 0;             ///< ½∫H² of the accepted state
    double       wall_time_before_restart = 0; ///< wall time of the runs before the checkpoint resumed from
    unsigned int steps_this_run           = 0;
    /// The flow has been non-rigid (above `anchor non-rigid energy`) since the start (checkpoint key
    /// `simulation/flow was non-rigid`).
    bool flow_was_non_rigid = false;
    unsigned int last_checkpoint_step     = 0; ///< the step of the last checkpoint written or resumed from
  };
} // namespace FluidSurface

#endif
