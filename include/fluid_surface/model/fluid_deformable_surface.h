#ifndef fluid_surface_model_fluid_deformable_surface_h
#define fluid_surface_model_fluid_deformable_surface_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/numerics/data_out.h>

#include <fluid_surface/flow/surface_fluid.h>
#include <fluid_surface/linear_algebra/reused_factorization_solver.h>
#include <fluid_surface/geometry/surface_geometry.h>
#include <fluid_surface/linear_algebra/bordered_system.h>
#include <fluid_surface/model/bending_force.h>
#include <fluid_surface/model/conservation_projection.h>
#include <fluid_surface/model/dof_layout.h>
#include <fluid_surface/model/geometry_iteration.h>
#include <fluid_surface/model/local_system.h>
#include <fluid_surface/model/mesh_redistribution.h>
#include <fluid_surface/model/momentum_constraints.h>
#include <fluid_surface/model/surface_reparametrization.h>
#include <fluid_surface/model/volume_constraint.h>

#include <array>
#include <memory>
#include <random>
#include <string>

namespace FluidSurface
{
  class CheckpointData;

  /**
   * The fluid deformable surface (seed eqs. 1–4): the full 3D velocity u ∈ [Q2]³,
   * surface pressure p ∈ Q1, curvature κ and bending scalar y ∈ Q_k, the new
   * position Y ∈ [Q_k]³ and the volume multiplier γ, solved as one linear
   * system per step on the frozen surface S^m (all nonlinear coefficients
   * lagged), so that the chain u → Y → κ → y → bending force is implicit.
   *
   * The step system is assembled from the terms of its components (doc/scheme.md): the surface fluid
   * (SurfaceFluid: inertia, convection, viscous stress, pressure, continuity), the BendingForce, the
   * MeshRedistribution (kinematics and tangential redistribution), the VolumeConstraint and the
   * MomentumConstraints. It owns `subsection initial state`; the components own theirs.
   */
  class FluidDeformableSurface
  {
  public:
    /// Result of one step attempt.
    struct StepResult
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

    /// What a re-parametrization (reparametrize()) did.
    struct Reparametrization
    {
      bool        done = false;
      std::string failure; ///< why it failed (the state is then unchanged), one line
      double      quality_before = 0, quality_after = 0;
      double      node_correction = 0; ///< the largest normal move of a node that restored A and V
    };

    FluidDeformableSurface(SurfaceGeometry &geometry);

    /// Declares the subsections of the components (flow, bending, volume constraint, mesh redistribution) and
    /// `initial state`.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /**
     * Reads them; τ_max = @p maximum_time_step of the run bounds the drift-correction time from below.
     * Rejects (InputError) entries that scene full does not use.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm, const double maximum_time_step);

    /// Distributes DoFs, sets the initial velocity and remembers V₀ and A₀.
    void
    setup();

    /**
     * Assembles and solves one step of size @p tau on the current surface and
     * moves the geometry to the new surface. The old state is kept until
     * accept() or restore_last_state().
     */
    StepResult
    advance(const double tau);

    /**
     * A prescribed motion instead of the flow: from now on advance() moves the surface with the velocity
     * @p velocity (3 components, evaluated at its current time on S^m; u is its L² projection), through the
     * same mesh law (kinematics and tangential redistribution) as the coupled problem. No bending force acts;
     * the volume and momentum constraints must be off. For tests and benchmarks of the mesh law.
     */
    void
    set_prescribed_velocity(const dealii::Function<3> &velocity);
    /// Whether advance() computes an error estimate (set by the scene when `time stepping/error tolerance` > 0).
    void
    set_error_estimation(const bool on)
    {
      estimating_error = on;
    }
    /// Makes the last advance() the current state.
    void
    accept();

    /// Whether the accepted state's mesh of quality @p quality needs the safety valve (SurfaceReparametrization::due()).
    bool
    reparametrization_due(const double quality, const double quality_after_last) const
    {
      return reparametrization.due(quality, quality_after_last);
    }
    /**
     * Replaces the reference surface S₀ of the mesh law `reference` (set by setup() to the initial surface) by
     * @p position (geometry numbering, the same connectivity): the parametrization the law and the
     * re-parametrization pull towards. Kept in checkpoints.
     */
    void
    set_reference_surface(const VectorType &position);
    /// Whether `reparametrization/quality threshold` is on.
    bool
    reparametrization_enabled() const
    {
      return reparametrization.enabled();
    }
    /**
     * The safety valve: new nodes on the current surface (SurfaceReparametrization), the fields transferred to
     * them; then A and V restored (ConservationProjection), the velocity projected onto the discrete
     * incompressible fields with the step's constraints (volume rate, momenta on the surface) by one step of the
     * scheme with τ = projection_time_step (the limit τ → 0 of the step: the L² projection with the pressure and
     * the multipliers; the nodes stay where they are), and the momenta restored exactly. The accepted state
     * (after accept()) is replaced; the geometry's curvature is that of the new state.
     */
    Reparametrization
    reparametrize();
    /// τ of the projection step of reparametrize(): viscous and bending terms enter it with a weight ~1e-9 relative.
    static constexpr double projection_time_step = 1e-9;

    /// Undoes the last advance() (geometry and fields).
    void
    restore_last_state();

    /// ½∫|u|² of @p state (default: the current one) on the current surface.
    double
    kinetic_energy(const VectorType &state) const;
    double
    kinetic_energy() const
    {
      return kinetic_energy(current);
    }
    /// The result of the last advance(), before accept().
    const VectorType &
    candidate_solution() const
    {
      return candidate;
    }

    /// (1/2Be)∫|κ|² with κ the weak curvature of the current surface (needs geometry.compute_curvature()).
    double
    bending_energy(const double willmore_energy) const
    {
      return bending.energy(willmore_energy);
    }

    /// Be of the bending force.
    double
    bending_number() const
    {
      return bending.Be;
    }

    const dealii::DoFHandler<2, 3> &
    dof_handler() const
    {
      return dofs;
    }
    /// u, p, κ, y, Y of the current state, ghosted.
    const VectorType &
    solution() const
    {
      return current;
    }
    double
    mesh_quality_floor() const
    {
      return redistribution.mesh_quality_floor;
    }

    /// Sections "assembly", "factorization", "linear solve", "diagnostics" of advance() go to @p timer.
    void
    set_timer(dealii::TimerOutput &timer)
    {
      step_timer = &timer;
      linear_solver.set_timer(&timer);
    }
    /// Number of LU factorizations so far.
    unsigned int
    n_factorizations() const
    {
      return linear_solver.n_factorizations();
    }
    /// Frees the kept LU factorization (MUMPS) while the rest of the program is still alive.
    void
    release_factorization()
    {
      linear_solver.release();
    }
    /// Whether the step iterates its geometry (`geometry iteration/maximum iterations` > 0).
    bool
    iterates_geometry() const
    {
      return geometry_iteration.enabled();
    }
    /// Whether ∂_t u is assembled (false: the Stokes limit, whose energy F is the bending energy alone).
    bool
    has_inertia() const
    {
      return flow.inertia;
    }

    /// Adds u, |u| and p to a DataOut.
    void
    add_output_fields(dealii::DataOut<2, 3> &data_out) const;

    /// The components of u, p, κ, y and Y in the element (DofLayout).
    static constexpr unsigned int velocity_component  = DofLayout::velocity_component;
    static constexpr unsigned int pressure_component  = DofLayout::pressure_component;
    static constexpr unsigned int curvature_component = DofLayout::curvature_component;
    static constexpr unsigned int bending_component   = DofLayout::bending_component;
    static constexpr unsigned int position_component  = DofLayout::new_position_component;

    /// Serialization of the fields a restart needs (u, previous position).
    const VectorType &
    previous_position() const
    {
      return old_position;
    }

    /**
     * Writes the accepted state into a checkpoint: the fields u, p, κ, y, Y
     * (flow DoFs), X^m and X^{m−1} (geometry DoFs), and V₀, A₀, the last τ
     * and the random seed. Collective.
     */
    void
    save(CheckpointData &data) const;

    /**
     * Instead of setup(): distributes DoFs, reads the state of a checkpoint
     * (written on any number of ranks) and moves the geometry to its X^m.
     */
    void
    load(const CheckpointData &data);

  private:
    /// The momenta of a velocity field, and the rigid motion of the surface it moves.
    struct RigidMotion
    {
      std::array<double, 6> momenta = {{0, 0, 0, 0, 0, 0}}; ///< ∫u and ∫x × u about the origin: (r_k, u)
      dealii::Point<3>      centre;                        ///< x_c = ∫x / |S|
      dealii::Tensor<1, 3>  translation;                   ///< U
      dealii::Tensor<1, 3>  rotation;                      ///< Ω
      /// R(x) = U + Ω × (x − x_c), whose normal part is closest to u·ν (see rigid_motion()).
      dealii::Tensor<1, 3>
      value(const dealii::Point<3> &x) const;
      /// Q = exp(τ[Ω]×), the rotation by the angle τ|Ω| about Ω (Rodrigues' formula).
      dealii::Tensor<2, 3>
      rotation_over(const double tau) const;
      /// The exact flow of the (stationary) rigid velocity R over a step @p tau, applied to @p x (a screw
      /// motion), Q = rotation_over(τ).
      dealii::Point<3>
      carry(const dealii::Point<3> &x, const double tau) const;
    };
    /// The momenta of @p state on the current surface, and the rigid motion R whose normal velocity R·ν
    /// fits u·ν in L² (regularized by `rigid motion cutoff`): the motion of the shape, not of the fluid. With
    /// a prescribed velocity, R fits that velocity on the current surface.
    RigidMotion
    rigid_motion(const VectorType &state) const;
    void
    setup_dofs();
    void
    set_initial_velocity();
    /// Per-thread FEValues and point values of assemble_cell().
    struct AssemblyScratch;
    /**
     * Assembles the step system of size @p tau on the geometry's surface (S^m, or an iterate S^{m+1,k} of
     * GeometryIteration; WorkStream over the cells): matrix, right-hand side, volume column and, if active, the
     * rigid-motion columns and rows. The old position X^m is current_position, u^m is current. @p motion is the
     * rigid motion of the shape (the target of the tangential damping) and the momenta of u^m; @p old_measures
     * those of S^m (the area drift).
     */
    void
    assemble(const double tau, const RigidMotion &motion, const SurfaceGeometry::Measures &old_measures);
    /// One cell of assemble(): the Gauss-point terms, then the nodal terms (·,·)_h.
    void
    assemble_cell(const typename dealii::DoFHandler<2, 3>::active_cell_iterator &cell,
                  const double                                                   tau,
                  const double                                                   area_rate,
                  const RigidMotion                                             &carried,
                  const double                                                   area_scale,
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
    /**
     * The local error estimate of a step of size @p tau whose solution (in the frame of the step) is @p new_state:
     * the normal speeds of the nodes relative to the carry, w = (Ỹ − X^m)·ñ^m/τ (@p old_normal: ñ^m), against
     * those of the last step (w^m, of size τ_p): e = τ²/(τ + τ_p) max|w − w^m| / R, R = √(A/4π), Backward Euler's
     * (τ²/2)|ẅ| of the shape's position over its size. The tangential motion (the mesh law) and the rigid motion
     * (the carry, exact) do not enter. Stores w for accept(); −1 without a last step.
     */
    double
    estimate_error(const VectorType &new_state, const VectorType &old_normal, const double tau);
    /// The largest distance between the new positions Y of @p a and @p b (flow numbering) over the nodes.
    double
    largest_node_move(const VectorType &a, const VectorType &b) const;
    /// The geometry's position back to X^m (its curvature and normal are not recomputed).
    void
    restore_last_state_geometry();
    /// Y of @p flow_solution → the geometry's position field.
    void
    copy_new_position_to_geometry(const VectorType &flow_solution);
    /// The position @p x (geometry numbering) → the Y components of @p flow_vector (owned).
    void
    copy_position_into(const VectorType &x, VectorType &flow_vector) const;
    /// X₀ (initial_position) → reference_position.
    void
    set_reference_position();
    /// D = (2/Re)‖σ(u)‖² of @p state on the current surface (EnergyFunctionals::dissipation_rate).
    double
    dissipation_rate(const VectorType &state) const;
    /**
     * Solves the bordered system K x = b (the step's matrix with its global constraints) with the kept
     * factorization, by GMRES from the initial guess x preconditioned by the bordered factorization
     * (ReusedFactorizationSolver); then makes the constraints hold to round-off.
     */
    ReusedFactorizationSolver::Result
    solve_system(const BorderedSystem &system, BorderedSystem::BlockVector &x, const BorderedSystem::BlockVector &b);

    SurfaceGeometry &geometry;

    SurfaceFluid        flow;
    BendingForce        bending;
    VolumeConstraint    volume_constraint;
    MeshRedistribution  redistribution;
    MomentumConstraints momentum_constraints;
    ConservationProjection conservation;
    SurfaceReparametrization reparametrization;
    GeometryIteration      geometry_iteration;
    /// The normal field ñ the assembly uses instead of the geometry's (GeometryIteration::Implicit), or none.
    const VectorType      *assembly_normal = nullptr;

    // `subsection initial state`: u₀ = U + ω₀ e × (x − c) + ε_u r(x), the shape perturbed by ε_X.
    dealii::Tensor<1, 3> translation_velocity;    ///< U
    double               angular_velocity{};      ///< ω₀
    bool                 equilibrium_rotation{};  ///< ω₀ from the geometry's equilibrium shape
    dealii::Tensor<1, 3> rotation_axis;           ///< e (normalized)
    dealii::Point<3>     rotation_centre;         ///< c
    double               velocity_perturbation{}; ///< ε_u
    double               shape_perturbation{};    ///< ε_X
    unsigned int         random_seed{};           ///< seed of the perturbations

    std::unique_ptr<dealii::FESystem<2, 3>> fe;
    std::unique_ptr<const DofLayout>        layout; ///< the local DoFs of u, p, κ, y, Y
    dealii::DoFHandler<2, 3>               dofs;
    dealii::IndexSet                       owned, relevant;
    dealii::AffineConstraints<double>      constraints;

    dealii::TrilinosWrappers::SparseMatrix system_matrix;
    VectorType                             system_rhs;       ///< owned
    VectorType                             volume_column;    ///< (ñ, v): γ's column and the volume row
    VectorType                             current;          ///< ghosted state u^m, …
    VectorType                             candidate;        ///< ghosted result of the last advance()
    VectorType                             old_position;     ///< X^{m−1}, geometry numbering, ghosted
    VectorType                             current_position; ///< X^m, geometry numbering, ghosted
    /// X₀, the reference surface of the mesh law (the initial position), geometry numbering, ghosted.
    VectorType                             initial_position;
    /// X₀ in the Y components of the flow numbering, ghosted.
    VectorType                             reference_position;
    /// The velocity of a prescribed motion (set_prescribed_velocity()), or none.
    const dealii::Function<3>             *prescribed_velocity = nullptr;
    /// Whether advance() is a solve of the mesh law alone (reparametrize(): velocity zero, no global constraints).
    bool relaxing_mesh = false;
    /// Whether advance() is one of the solves of reparametrize(), which use valve_solver.
    bool reparametrizing = false;
    /// The flow DoFs (components 0–2) of the locally owned nodes of u and of Y.
    std::vector<std::array<dealii::types::global_dof_index, 3>> velocity_nodes, new_position_nodes;
    /// Law reference: maps the solution of a step in the carried frame back (u = Qũ, Y = the carry of Ỹ).
    void
    leave_carried_frame(const RigidMotion &carried, const double tau, VectorType &solution) const;
    /// (flow DoF of Y_d, geometry DoF of X_d) for the locally owned nodes.
    std::vector<std::pair<dealii::types::global_dof_index, dealii::types::global_dof_index>> position_pairs;
    double                                 last_tau = 0;     ///< τ of the step that produced X^m
    double                                 last_step_tau = 0; ///< τ of the last advance()
    /// Whether advance() estimates its error (estimate_error()).
    bool                                   estimating_error = false;
    /// The normal speeds w of the nodes in the last accepted step and in the candidate step (estimate_error(); in
    /// the first component of the Y DoFs of each node).
    VectorType                             normal_speed, candidate_normal_speed;
    /// τ_p of the step that produced `normal_speed`; 0: none (the first step, after a re-parametrization).
    double                                 normal_speed_step = 0;
    /// R = √(A^m/4π) of the last advance(): the length scale of the error estimate.
    double                                 shape_radius = 1;
    /// The geometry DoFs of the components of each node of new_position_nodes.
    std::vector<std::array<dealii::types::global_dof_index, 3>> new_position_geometry_dofs;
    double                                 target_volume = 0; ///< V₀
    double                                 target_area   = 0; ///< A₀

    /// The step's LU factorization, kept across steps (`subsection linear solver`).
    ReusedFactorizationSolver                       linear_solver;
    /// The solves of reparametrize(), by KLU without reuse: MUMPS refused (error −22) the mesh-law matrix of a
    /// sheared refinement-3 mesh that KLU factorized (tests/mesh_reparametrization).
    ReusedFactorizationSolver                       valve_solver;
    dealii::TimerOutput                            *step_timer            = nullptr;
    /// The columns (r_k, v) of the rigid motions r = e_1, e_2, e_3, e_1 × x, e_2 × x, e_3 × x, whose
    /// multipliers enforce ∫u = 0, ∫x × u = 0 (Stokes limit) or hold the momenta (MomentumConstraints).
    std::array<VectorType, 6>                       rigid_columns;
    /// The constraint rows of the rigid motions: (r_k, u) in the Stokes limit; with inertia the momenta on
    /// the new surface, linearized in Y (their Y entries; MomentumConstraints::assemble_new_surface_rows()).
    std::array<VectorType, 6>                       rigid_rows;
    /// Values g_k of the rigid-motion constraints (r_k, u) = g_k: 0 in the Stokes limit, the initial
    /// ∫u and ∫x × u with `conserve momenta`.
    std::array<double, 6> rigid_targets = {{0, 0, 0, 0, 0, 0}};
    /// Whether the rigid-motion multipliers are part of the step.
    bool
    rigid_constraints() const
    {
      return momentum_constraints.active();
    }
    /// The state and multipliers of the last step: the initial guess of the GMRES solve.
    BorderedSystem::BlockVector                     last_solution;
    /// The relaxation time τ_c = max(τ_drift, τ_max) of the drift corrections (≥ τ, independent of τ).
    double
    drift_time(const double tau) const
    {
      return volume_constraint.drift_time(tau);
    }
  };
} // namespace FluidSurface

#endif
