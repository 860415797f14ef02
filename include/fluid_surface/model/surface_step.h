#ifndef fluid_surface_model_surface_step_h
#define fluid_surface_model_surface_step_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fluid_surface/flow/surface_fluid.h>
#include <fluid_surface/geometry/surface_geometry.h>
#include <fluid_surface/linear_algebra/bordered_system.h>
#include <fluid_surface/linear_algebra/reused_factorization_solver.h>
#include <fluid_surface/model/bending_force.h>
#include <fluid_surface/model/conservation_projection.h>
#include <fluid_surface/model/dof_layout.h>
#include <fluid_surface/model/geometry_iteration.h>
#include <fluid_surface/model/local_system.h>
#include <fluid_surface/model/mesh_redistribution.h>
#include <fluid_surface/model/momentum_constraints.h>
#include <fluid_surface/model/rigid_motion.h>
#include <fluid_surface/model/step_request.h>
#include <fluid_surface/model/surface_point_values.h>
#include <fluid_surface/model/surface_state.h>
#include <fluid_surface/model/volume_constraint.h>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace FluidSurface
{
  class CheckpointData;

  /**
   * One step of the fluid deformable surface (seed eqs. 1–4, doc/scheme.md): the full 3D velocity u ∈ [Q2]³,
   * surface pressure p ∈ Q1, curvature κ and bending scalar y ∈ Q_k, the new position Y ∈ [Q_k]³ and the
   * volume multiplier γ, solved as one linear system on the frozen surface S^m of the accepted SurfaceState
   * (all nonlinear coefficients lagged), so that the chain u → Y → κ → y → bending force is implicit.
   *
   * The step system is assembled from the terms of its components: the surface fluid (SurfaceFluid:
   * inertia, convection, viscous stress, pressure, continuity), the BendingForce, the MeshRedistribution
   * (kinematics and tangential redistribution), the VolumeConstraint and the MomentumConstraints; the global
   * constraints border it (BorderedSystem) and the ConservationProjection restores A, V and the momenta
   * after the solve. Owns the DoFs of (u, p, κ, y, Y), the matrix and the linear solvers.
   */
  class SurfaceStep
  {
  public:
    /// Result of one step attempt.
    struct Result
    {
      bool         solved = false;
      std::string  failure;         ///< why the step was not solved, one line
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
      /// The local error estimate of the step (see estimate_error()); negative when there is none (first step).
      double       error_estimate      = -1;
    };

    /// A step on @p geometry from the accepted @p state (both kept by reference).
    SurfaceStep(SurfaceGeometry &geometry, const SurfaceState &state);

    /// Declares the subsections of the components (flow, bending, volume constraint, mesh redistribution,
    /// conservation projection).
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Reads them and `linear solver`; τ_max = @p maximum_time_step bounds the drift-correction time from below.
    void
    parse_parameters(dealii::ParameterHandler &prm, const double maximum_time_step);

    /// Distributes the DoFs of (u, p, κ, y, Y) on the current mesh and sizes the step system.
    void
    setup_dofs();

    /**
     * Assembles and solves one step of size @p tau as @p request asks, on the surface X^m of the state, and
     * moves the geometry to the new surface; the solution is candidate() until the caller accepts it.
     */
    Result
    advance(const StepRequest &request, const double tau);

    /// The solution of the last advance(): u, p, κ, y, Y (flow numbering), ghosted.
    const VectorType &
    candidate() const
    {
      return candidate_solution;
    }
    /// The DoFs of (u, p, κ, y, Y).
    const dealii::DoFHandler<2, 3> &
    dof_handler() const
    {
      return dofs;
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
      return constraints;
    }

    /// Y of @p flow_solution → the geometry's position field.
    void
    copy_new_position_to_geometry(const VectorType &flow_solution);
    /// The position @p x (geometry numbering) → the Y components of @p flow_vector (owned).
    void
    copy_position_into(const VectorType &x, VectorType &flow_vector) const;
    /// ½∫|u|² of @p flow_vector on the current surface (EnergyFunctionals::kinetic_energy).
    double
    kinetic_energy(const VectorType &flow_vector) const;

    /// The next step factorizes its matrix (the surface jumped: a restore, a re-parametrization).
    void
    request_factorization()
    {
      linear_solver.request_factorization();
    }
    /// The next step starts its GMRES from zero instead of the last solution.
    void
    forget_last_solution()
    {
      last_solution.reinit(0);
    }
    /// Frees the kept LU factorization (MUMPS) while the rest of the program is still alive.
    void
    release_factorization()
    {
      linear_solver.release();
    }
    /// Frees the factorization of the Solver::fresh_klu solves.
    void
    release_fresh_factorization()
    {
      valve_solver.release();
    }
    /// Number of LU factorizations of the step's solver so far (kept in checkpoints).
    unsigned int
    n_factorizations() const
    {
      return linear_solver.n_factorizations();
    }
    /// Continues the count of a checkpoint.
    void
    set_n_factorizations(const unsigned int n)
    {
      linear_solver.set_n_factorizations(n);
    }
    /// Whether advance() computes an error estimate of flow steps (`time stepping/error tolerance` > 0).
    void
    set_error_estimation(const bool on)
    {
      estimating_error = on;
    }
    /**
     * Whether the flow steps are variable-step BDF2 steps (`time stepping/scheme = BDF2`) after a first
     * backward-Euler step (and after each re-parametrization); the history x^{m−1}, τ_p is kept in checkpoints.
     */
    void
    set_bdf2(const bool on)
    {
      bdf2 = on;
    }
    /// Whether the next flow step iterates its geometry (`geometry iteration/apply`: always, or in the K steps
    /// after a rejected lagged step).
    bool
    iterating_geometry() const
    {
      return geometry_iteration.enabled() &&
             (geometry_iteration.apply == GeometryIteration::Apply::always || corrected_steps_left > 0);
    }
    /// After a rejected step: with apply = after rejection and a lagged step rejected, the next K accepted steps
    /// (and the retry) iterate their geometry. Returns whether the rejected step was such a lagged one.
    bool
    iterate_geometry_after_rejection();
    /// The step was accepted: the candidate's normal speeds become the history of the error estimate, and one
    /// corrected step of `apply = after rejection` is used up.
    void
    accept_history();
    /// From now on the membrane energy acts with its full weight (`mesh redistribution/anchor time`).
    void
    pull_fully()
    {
      membrane_pull = candidate_membrane_pull = 1;
    }
    /// The next step has no error estimate and is a backward-Euler step (the state jumped: a re-parametrization).
    void
    forget_error_history()
    {
      normal_speed_step = 0;
      previous_step     = 0;
    }
    /// Writes the history of the error estimate (nothing without one) and the corrected steps left into a
    /// checkpoint. Collective.
    void
    save_history(CheckpointData &data) const;
    /// Reads them, if the checkpoint has them (and the error is estimated).
    void
    load_history(const CheckpointData &data);
    /// Sections "assembly", "factorization", "linear solve", "diagnostics" of advance() go to @p timer.
    void
    set_timer(dealii::TimerOutput &timer)
    {
      step_timer = &timer;
      linear_solver.set_timer(&timer);
    }

    // The components of the step system, each with its own subsection.
    SurfaceFluid           flow;
    BendingForce           bending;
    VolumeConstraint       volume_constraint;
    MeshRedistribution     redistribution;
    MomentumConstraints    momentum_constraints;
    ConservationProjection conservation;
    GeometryIteration      geometry_iteration;

  private:
    /// The rigid motion of the shape of @p flow_vector (RigidMotion::fit() with the mesh law's cutoff).
    RigidMotion
    rigid_motion(const VectorType &flow_vector) const;
    /// Per-thread FEValues and point values of assemble_cell().
    struct AssemblyScratch;
    /**
     * Assembles the step system of size @p tau on the geometry's surface (S^m, or an iterate S^{m+1,k} of
     * GeometryIteration; WorkStream over the cells): matrix, right-hand side, volume column and, if active, the
     * rigid-motion columns and rows. The old position X^m is *old_position (read at the quadrature and nodal
     * points), u^m is the state's. @p motion is the rigid motion of the shape (the target of the tangential
     * damping) and the momenta of u^m; @p old_measures those of S^m (the area drift).
     */
    void
    assemble(const double tau, const RigidMotion &motion, const SurfaceGeometry::Measures &old_measures);
    /// One cell of assemble(): the Gauss-point terms, then the nodal terms (·,·)_h. @p membrane_weight scales μ and K.
    void
    assemble_cell(const typename dealii::DoFHandler<2, 3>::active_cell_iterator &cell,
                  const double                                                   tau,
                  const double                                                   area_rate,
                  const RigidMotion                                             &carried,
                  const double                                                   area_scale,
                  const double                                                   membrane_weight,
                  AssemblyScratch                                               &scratch,
                  LocalSystem                                                   &local) const;
    /**
     * The momentum and continuity rows at one Gauss point (@p old_point: X^m there), the terms of SurfaceFluid:
     * (1/τ)(u − u^m, v) + (G u^m, v) − (1/τ)(G^m (Y − X^m), v) + (2/Re)(σ(u), σ(v)) − (p, div_P v) (in the
     * Stokes limit ε(u, v) instead of the inertia, no convection) and −(div_P u, q) = −(s, q), s = @p area_rate.
     * With law reference in the frame carried by the rigid motion @p carried: (1/τ)(u − Q u^m, v) + (Ω × u, v)
     * and the mesh velocity R + (Y − Z)/τ.
     */
    void
    assemble_flow_terms(const SurfacePointValues &point,
                        const dealii::Point<3>   &old_point,
                        const double              tau,
                        const double              area_rate,
                        const RigidMotion        &carried,
                        LocalSystem              &local) const;
    /// D = (2/Re)‖σ(u)‖² of @p flow_vector on the current surface (EnergyFunctionals::dissipation_rate).
    double
    dissipation_rate(const VectorType &flow_vector) const;
    /**
     * Solves the bordered system K x = b (the step's matrix with its global constraints) with the solver of
     * the request, by GMRES from the initial guess x preconditioned by the bordered factorization
     * (ReusedFactorizationSolver); then makes the constraints hold to round-off.
     */
    ReusedFactorizationSolver::Result
    solve_system(const BorderedSystem &system, BorderedSystem::BlockVector &x, const BorderedSystem::BlockVector &b);
    /**
     * The local error estimate of a step of size @p tau whose solution (in the frame of the step) is @p new_state:
     * the normal speeds of the nodes relative to the carry, w = (Ỹ − X^m)·ñ^m/τ (@p old_normal: ñ^m), against
     * those of the last accepted step (w^m, of size τ_p): e = τ²/(τ + τ_p) max|w − w^m| / R, R = √(A/4π),
     * backward Euler's (τ²/2)|ẅ| of the shape's position over its size. The tangential motion (the mesh law)
     * and the rigid motion (the carry, exact) do not enter. Stores w for accept_history(); −1 without a
     * last step.
     */
    double
    estimate_error(const VectorType &new_state, const VectorType &old_normal, const double tau);
    /// The dot product of the new positions Y of @p a and @p b (flow numbering) over the nodes.
    double
    position_dot(const VectorType &a, const VectorType &b) const;
    /// The largest distance between the new positions Y of @p a and @p b (flow numbering) over the nodes.
    double
    largest_node_move(const VectorType &a, const VectorType &b) const;
    /// The geometry's position back to X^m (its curvature and normal are not recomputed).
    void
    restore_old_geometry();
    /**
     * BDF2: the start x̂ of the step's backward-Euler form (start_fields: û and X̂ in the Y components;
     * start_position: X̂) and the extrapolated u* whose gradient the convection lags (lagged_fields), from the
     * state x^m and previous_solution x^{m−1} (law reference: the latter carried into the frame of the step by
     * @p carried). @p tau: the step.
     */
    void
    prepare_bdf2_start(const RigidMotion &carried, const bool carried_frame, const double tau);
    /**
     * The rigid motion @p carried over the time @p tau applied to the nodal fields of @p solution: u ← Q(τ)u,
     * Y ← carry(Y, τ). Law reference: maps the solution of a step out of the carried frame (τ the step), and the
     * previous state of BDF2 into it (τ_p: the frame coordinates of t^m − τ_p).
     */
    void
    carry_fields(const RigidMotion &carried, const double tau, VectorType &solution) const;
    /// Whether the rigid-motion multipliers are part of the step.
    bool
    rigid_constraints() const
    {
      return momentum_constraints.active();
    }
    /// The relaxation time τ_c = max(τ_drift, τ_max) of the drift corrections (≥ τ, independent of τ).
    double
    drift_time(const double tau) const
    {
      return volume_constraint.drift_time(tau);
    }

    SurfaceGeometry    &geometry;
    const SurfaceState &state;
    /// The request of the advance() under way.
    StepRequest request;

    std::unique_ptr<dealii::FESystem<2, 3>> fe;
    std::unique_ptr<const DofLayout>        layout; ///< the local DoFs of u, p, κ, y, Y
    dealii::DoFHandler<2, 3>               dofs;
    dealii::IndexSet                       owned, relevant;
    dealii::AffineConstraints<double>      constraints;

    dealii::TrilinosWrappers::SparseMatrix system_matrix;
    VectorType                             system_rhs;         ///< owned
    VectorType                             volume_column;      ///< (ñ, v): γ's column and the volume row
    VectorType                             candidate_solution; ///< ghosted result of the last advance()
    /// The flow DoFs (components 0–2) of the locally owned nodes of u and of Y.
    std::vector<std::array<dealii::types::global_dof_index, 3>> velocity_nodes, new_position_nodes;
    /// (flow DoF of Y_d, geometry DoF of X_d) for the locally owned nodes.
    std::vector<std::pair<dealii::types::global_dof_index, dealii::types::global_dof_index>> position_pairs;
    /// The geometry DoFs of the components of each node of new_position_nodes.
    std::vector<std::array<dealii::types::global_dof_index, 3>> new_position_geometry_dofs;
    /// X^m for the assembly: the state's position for flow steps, the geometry's own for the valve's solves.
    const VectorType *old_position = nullptr;
    /// The normal field ñ the assembly uses instead of the geometry's (GeometryIteration::Implicit), or none.
    const VectorType *assembly_normal = nullptr;
    /// τ of the last advance().
    double last_tau = 0;
    /// The fields whose u is u^m of the inertia (the state's, or BDF2's û), and X^m's Y components.
    const VectorType *old_fields = nullptr;
    /// The fields whose velocity gradient the convection lags (the state's, or BDF2's u*).
    const VectorType *lagged_field = nullptr;
    /**
     * Law reference: whether the frame velocity R in the mesh velocity and the kinematics is taken on the
     * surface the step is assembled on (BDF2 steps: at the new time level, for second order) instead of at X^m.
     */
    bool frame_velocity_on_new_surface = false;
    /// Whether the flow steps are BDF2 steps (set_bdf2()).
    bool bdf2 = false;
    /// BDF2: the state x^{m−1} before the last accepted step (flow numbering, ghosted) and that step τ_p; 0: none.
    VectorType previous_solution;
    double     previous_step = 0;
    /// BDF2: x̂ and u* of the step under way (prepare_bdf2_start()), ghosted; X̂ in the geometry numbering.
    VectorType start_fields, lagged_fields, start_position;
    /// Whether advance() estimates the error of flow steps (estimate_error()).
    bool estimating_error = false;
    /// The normal speeds w of the nodes in the last accepted step and in the candidate step (estimate_error();
    /// in the first component of the Y DoFs of each node).
    VectorType normal_speed, candidate_normal_speed;
    /// τ_p of the step that produced `normal_speed`; 0: none (the first step, after a re-parametrization).
    double normal_speed_step = 0;
    /// `geometry iteration/apply = after rejection`: accepted steps with iterated geometry still to come.
    unsigned int corrected_steps_left = 0;
    /// The weight of the membrane energy: the largest w(q) of the accepted steps so far (a latch: a weight
    /// that followed q up and down kept the mesh moving in a rigidly rotating end state, and F rose), and
    /// that of the step under way.
    double membrane_pull = 0, candidate_membrane_pull = 0;
    /// R = √(A^m/4π) of the last advance(): the length scale of the error estimate.
    double shape_radius = 1;

    /// The step's LU factorization, kept across steps (`subsection linear solver`).
    ReusedFactorizationSolver linear_solver;
    /// The Solver::fresh_klu solves, by KLU without reuse: MUMPS refused (error −22) the mesh-law matrix of a
    /// sheared refinement-3 mesh that KLU factorized (tests/mesh_reparametrization).
    ReusedFactorizationSolver valve_solver;
    dealii::TimerOutput      *step_timer = nullptr;
    /// The columns (r_k, v) of the rigid motions r = e_1, e_2, e_3, e_1 × x, e_2 × x, e_3 × x, whose
    /// multipliers enforce ∫u = 0, ∫x × u = 0 (Stokes limit) or hold the momenta (MomentumConstraints).
    std::array<VectorType, 6> rigid_columns;
    /// The constraint rows of the rigid motions: (r_k, u) in the Stokes limit; with inertia the momenta on
    /// the new surface, linearized in Y (their Y entries; MomentumConstraints::assemble_new_surface_rows()).
    std::array<VectorType, 6> rigid_rows;
    /// The state and multipliers of the last step: the initial guess of the GMRES solve.
    BorderedSystem::BlockVector last_solution;
  };
} // namespace FluidSurface

#endif
