// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_surface_step_h
#define fluid_surface_model_surface_step_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <fluid_surface/geometry/surface_geometry.h>
#include <fluid_surface/model/bordered_solver.h>
#include <fluid_surface/model/local_error_estimate.h>
#include <fluid_surface/model/membrane_pull.h>
#include <fluid_surface/model/rigid_motion.h>
#include <fluid_surface/model/step_candidate.h>
#include <fluid_surface/model/step_components.h>
#include <fluid_surface/model/step_failure.h>
#include <fluid_surface/model/step_frame.h>
#include <fluid_surface/model/step_request.h>
#include <fluid_surface/model/step_system.h>
#include <fluid_surface/model/surface_state.h>
#include <fluid_surface/model/time_scheme.h>
#include <fluid_surface/time_stepping/time_stepper.h>

#include <array>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace FluidSurface
{
  class CheckpointData;
  class StepAssembly;
  struct StepAssemblyData;

  /**
   * One step of the fluid deformable surface (seed eqs. 1–4, doc/scheme.md): the full 3D velocity u ∈ [Q2]³,
   * surface pressure p ∈ Q1, curvature κ and bending scalar y ∈ Q_k, the new position Y ∈ [Q_k]³ and the
   * global multipliers, solved as one linear system on the frozen surface S^m of the accepted SurfaceState
   * (all nonlinear coefficients lagged), so that the chain u → Y → κ → y → bending force is implicit.
   *
   * Built like step-38: the StepSystem (setup_system()), the StepAssembly of the terms of the StepComponents
   * (assemble), the BorderedSolver (solve), a TimeScheme that writes the step in backward-Euler form, the
   * optional GeometryIteration on the step's own surface and the LocalErrorEstimate; the ConservationProjection
   * restores A, V and the momenta after the solve.
   */
  class SurfaceStep
  {
  public:
    /// Result of one step attempt.
    struct Result
    {
      bool         solved = false;
      StepFailure  failure = StepFailure::none; ///< why the step was not solved
      std::string  message;                     ///< the failure in one line
      std::string  failure_details; ///< the linear solver's own report of the failure (for error.log)
      unsigned int linear_iterations = 0;
      double       gamma             = 0;
      double       dissipation_rate  = 0; ///< (2/Re)‖σ(u)‖² on S^m
      bool         factorized        = false; ///< whether this step computed a new factorization
      double       rigid_force       = 0; ///< Stokes limit: |λ| of the multipliers of ∫u = 0, ∫X×u = 0
      double       node_correction   = 0; ///< ConservationProjection: the largest normal move of a node
      double       momentum_correction = 0; ///< ConservationProjection: |P₀ − P| + |L₀ − L| before it
      unsigned int geometry_iterations = 0; ///< re-assemblies on the step's own surface (GeometryIteration)
      double       geometry_change     = 0; ///< the last iterate's largest node move over h (0 without iteration)
      /// The local error estimate of the step (LocalErrorEstimate); negative when there is none (first step).
      double       error_estimate      = -1;
      /**
       * With the energy budget on (set_energy_budget()): the energies of the step at its stages and the power
       * of the bending force, from which its ΔB = ΔF + τD splits into the bending defect, the transport's, the
       * projections' (doc/scheme.md, "The discrete energy law"; NaN when off or in the valve's steps).
       */
      struct EnergyBudget
      {
        double bending_start    = std::numeric_limits<double>::quiet_NaN(); ///< W^m on S^m
        double kinetic_start    = std::numeric_limits<double>::quiet_NaN(); ///< K^m on S^m
        double bending_power    = std::numeric_limits<double>::quiet_NaN(); ///< P = (1/Be)(y ñ, ũ) of the solve
        /// P_μ = −Σ_k μ_k (c_k, ũ): the power of the multipliers' forces (γ, momenta) on the step's velocity
        double multiplier_power = 0;
        double bending_solved   = std::numeric_limits<double>::quiet_NaN(); ///< W of the solved surface Y
        double kinetic_solved   = std::numeric_limits<double>::quiet_NaN(); ///< K of the solved u on Y
        double kinetic_projected = std::numeric_limits<double>::quiet_NaN(); ///< K of u after the area and volume projection
      } energy_budget;
    };

    /// A step on @p geometry from the accepted @p state (both kept by reference).
    SurfaceStep(SurfaceGeometry &geometry, const SurfaceState &state);
    ~SurfaceStep();

    /// Declares the subsections of the components (StepComponents).
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Reads them and `linear solver`; τ_max = @p maximum_time_step bounds the drift-correction time from below.
    void
    parse_parameters(dealii::ParameterHandler &prm, const double maximum_time_step);

    /// Distributes the DoFs of (u, p, κ, y, Y) on the current mesh and sizes the step system.
    void
    setup_system();

    /**
     * Assembles and solves one step of size @p tau as @p request asks, on the surface X^m of the state, into
     * @p candidate (its fields, its surface and the curvature and kinetic energy there), and moves the geometry
     * to that surface. The caller accepts the candidate (accept_history(), then the state) or moves the geometry
     * back.
     */
    Result
    advance(const StepRequest &request, const double tau, StepCandidate &candidate);

    /// The parsed components of the step.
    const StepComponents &
    components() const
    {
      return parts;
    }
    /// The DoFs of (u, p, κ, y, Y).
    const dealii::DoFHandler<2, 3> &
    dof_handler() const
    {
      return system.dof_handler();
    }
    /// The geometry the step moves.
    SurfaceGeometry &
    moved_geometry() const
    {
      return geometry;
    }
    /// The hanging-node constraints of the flow DoFs.
    const dealii::AffineConstraints<double> &
    hanging_node_constraints() const
    {
      return system.constraints();
    }
    /// Y of @p flow_solution → the geometry's position field.
    void
    copy_new_position_to_geometry(const VectorType &flow_solution)
    {
      system.copy_new_position_to_geometry(flow_solution);
    }
    /// The position @p x (geometry numbering) → the Y components of @p flow_vector (owned).
    void
    copy_position_into(const VectorType &x, VectorType &flow_vector) const
    {
      system.copy_position_into(x, flow_vector);
    }
    /// ½∫|u|² of @p flow_vector on the current surface (EnergyFunctionals::kinetic_energy).
    double
    kinetic_energy(const VectorType &flow_vector) const;

    /// The step's solver (its factorization, its initial guess).
    BorderedSolver &
    solver()
    {
      return bordered_solver;
    }
    const BorderedSolver &
    solver() const
    {
      return bordered_solver;
    }
    /// Whether advance() records the energy budget of flow steps in Result::energy_budget (`output/energy budget`).
    void
    set_energy_budget(const bool on)
    {
      record_energy_budget = on;
    }
    /// Whether advance() estimates the error of flow steps (`time stepping/error tolerance` > 0).
    void
    set_error_estimation(const bool on)
    {
      error_estimate.set_enabled(on);
    }
    /// The time scheme named @p name of the flow steps (`time stepping/scheme`; its history is kept in
    /// checkpoints), solved in the frame @p frame (`time stepping/frame`).
    void
    set_time_scheme(const std::string &name, const FlowStepFrame frame);
    /// The time scheme of the flow steps: its rules (TimeScheme::name(), step_ratio_limit(), start_up(), …).
    const TimeScheme &
    flow_time_scheme() const
    {
      return *time_scheme;
    }
    /// Whether the next flow step iterates its geometry.
    bool
    iterating_geometry() const
    {
      return corrected_steps.iterating(parts.geometry_iteration);
    }
    /// After a rejected step: with `geometry iteration/apply = after rejection` and a lagged step rejected, the
    /// retry and the next K accepted steps iterate their geometry. Returns whether it started them.
    bool
    start_corrected_steps()
    {
      return corrected_steps.start_after_rejection(parts.geometry_iteration);
    }
    /// After a rejected BDF2 step: the retry and the next @p steps accepted steps are backward Euler
    /// (`time stepping/backward Euler steps after rejection`). Returns whether it started them.
    bool
    fall_back_to_backward_euler(const unsigned int steps)
    {
      return steps > 0 && time_scheme->fall_back_to_backward_euler(steps);
    }
    /// The step @p candidate was accepted (called before the state moves on): the histories of the time
    /// scheme, the error estimate, the corrected steps, the membrane pull and the kept factors move on.
    void
    accept_history(const StepCandidate &candidate);
    /// The mesh law slowed down tenfold more for the retry of a step (MembranePull::slow_down()); false if it cannot be.
    bool
    slow_down_mesh_law()
    {
      return membrane_pull.slow_down();
    }
    /// The factor by which the mesh law is slowed down now (1: not at all).
    double
    mesh_law_slowdown() const
    {
      return membrane_pull.current_slowdown();
    }
    /// From now on the membrane energy acts with its full weight (`mesh redistribution/anchor time`).
    void
    pull_fully()
    {
      membrane_pull.pull_fully();
    }
    /// The next step has no error estimate and starts its time scheme afresh (the state jumped).
    void
    forget_history()
    {
      time_scheme->forget_history();
      error_estimate.forget_history();
    }
    /// Writes the histories into a checkpoint. Collective.
    void
    save_history(CheckpointData &data) const;
    /// Reads them, if the checkpoint has them.
    void
    load_history(const CheckpointData &data);
    /// Sections "assembly", "factorization", "linear solve", "diagnostics" of advance() go to @p timer.
    void
    set_timer(dealii::TimerOutput &timer)
    {
      step_timer = &timer;
      bordered_solver.set_timer(timer);
    }

  private:
    /// The global constraints of a step: the bordering columns and rows and their values.
    struct GlobalConstraints;
    /// What the steps of one advance() share: the request, its start, the assembly and the constraints.
    struct StepUnderWay;

    /// The frame a step as @p request asks is solved in, from the accepted state (once per step).
    StepFrame
    frame_of(const StepRequest &request) const;
    /// The rigid motion of the shape of @p flow_vector (RigidMotion::fit() with the mesh law's cutoff).
    RigidMotion
    rigid_motion(const StepRequest &request, const VectorType &flow_vector) const;
    /// The data of an assembly with the normal field @p normal.
    StepAssemblyData
    assembly_data(const StepUnderWay &step, const VectorType &normal) const;
    /**
     * The bordering of the step: the volume row (u·ñ, 1) = −(V^m − V₀)/τ_c (multiplier γ) and the rigid-motion
     * rows (momentum targets in the frame of the step), as the request asks.
     */
    void
    set_up_global_constraints(const StepUnderWay &step, GlobalConstraints &constraints) const;
    /**
     * The constraint values of the momentum rows of @p step, linearized about the surface it is assembled on
     * (@p on_old_surface: S^m): their constant parts are the momenta of the velocity of the rows' correction
     * terms, the start's û (u^m; BDF2: its backward-Euler form's combination of u^m and u^{m−1}).
     */
    void
    set_constraint_values(StepUnderWay &step, const bool on_old_surface) const;
    /// Solves the bordered system into @p solution; records the solve in @p result. Returns whether it solved.
    /// @p same_step: a solve of the geometry iteration (BorderedSolver::solve()).
    bool
    solve(StepUnderWay &step, BorderedSystem::BlockVector &solution, Result &result, const bool same_step = false);
    /// The implicit geometry: the step assembled again on the surface of its own solution until the nodes
    /// stop moving (GeometryIteration). Returns whether it converged (else @p result says why).
    bool
    iterate_geometry(StepUnderWay &step, BorderedSystem::BlockVector &solution, Result &result);
    /// Out of the carried frame, onto the geometry, the error estimate and the conservation projection, into
    /// @p candidate.
    void
    finish(StepUnderWay &step, VectorType &solution, Result &result, StepCandidate &candidate);
    /**
     * The power P = (1/Be)(y ñ, ũ) of the bending force on the velocity of @p solution (in the frame of the step),
     * with the assembly's Gauss rule on the surface the step was last assembled on: the force's work as the step
     * itself saw it.
     */
    double
    bending_power(const VectorType &solution) const;
    /// D = (2/Re)‖σ(u)‖² + γ_gd‖div_P u − s‖² of @p flow_vector on the current surface, s = @p area_rate
    /// (EnergyFunctionals::dissipation_rate).
    double
    dissipation_rate(const VectorType &flow_vector, const double area_rate) const;
    /// The area rate s = −(A^m − A₀)/(τ_c A^m) of the continuity row div_P u = s of @p step.
    double
    area_rate(const StepUnderWay &step) const;
    /// The geometry's position back to X^m.
    void
    restore_old_geometry();
    /// The relaxation time τ_c = max(τ_drift, τ_max) of the drift corrections (≥ τ, independent of τ).
    double
    drift_time(const double tau) const
    {
      return parts.volume_constraint.drift_time(tau);
    }

    SurfaceGeometry    &geometry;
    const SurfaceState &state;
    StepComponents      parts;
    StepSystem          system;
    BorderedSolver      bordered_solver;
    /// The scheme of the flow steps and backward Euler for the rest (the valve's solves).
    std::unique_ptr<TimeScheme> time_scheme;
    /// The frame of the flow steps (`time stepping/frame`).
    FlowStepFrame               flow_step_frame = FlowStepFrame::lab;
    BackwardEuler               backward_euler;
    LocalErrorEstimate          error_estimate;
    CorrectedSteps              corrected_steps;
    MembranePull                membrane_pull;
    bool                        record_energy_budget = false;
    dealii::TimerOutput *step_timer = nullptr;
  };
} // namespace FluidSurface

#endif
