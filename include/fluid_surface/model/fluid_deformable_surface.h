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

#include <fluid_surface/linear_algebra/bordered_system.h>
#include <fluid_surface/linear_algebra/reused_factorization_solver.h>
#include <fluid_surface/geometry/surface_geometry.h>

#include <array>
#include <memory>
#include <random>
#include <string>

namespace FluidSurface
{
  class CheckpointData;

  /**
   * Helfrich bending force b = (1/Be)(−Δ_S H − H(|B|² − ½H²)) ν, discretized
   * with the bending scalar y: (y, φ) − (∇_S κ, ∇_S φ) + (c κ, φ) = 0 with the
   * lagged coefficient c = |B^m|² − ½(H^m)² (B^m = −P∇ñ^m), and the force
   * (1/Be)(y ñ, v) in the momentum equation. κ is the new surface's mean
   * curvature from MeshRedistribution.
   */
  class BendingForce
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    bool   enabled        = true;
    double bending_number = 1.0; ///< Be = ρU²L²/κ_b; F_bend = (1/2Be)∫H²
  };

  /**
   * Global multiplier γ for the enclosed volume: the force −γν and the
   * constraint (u·ñ, 1) = −(V(S^m) − V₀)/τ, whose right-hand side also removes
   * any volume drift of earlier steps.
   */
  class VolumeConstraint
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    bool enabled = true;
  };

  /**
   * BGN-type tangential mesh redistribution: the new position Y follows the
   * normal velocity, (Y·ñ, φ)_h = (X^m·ñ, φ)_h + τ(u·ñ, φ)_h, and its
   * tangential motion keeps the mesh regular through (κñ, η)_h + (∇_S Y, ∇_S η) = 0,
   * i.e. κñ = Δ_S Y (κ = H of the new surface). (·,·)_h is the nodal
   * (Gauss–Lobatto) quadrature when lumping is on, as in Barrett–Garcke–Nürnberg.
   */
  class MeshRedistribution
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    bool   lumped            = true;
    double relaxation_time   = 0.05; ///< T_r of the tangential damping (0: plain BGN)
    bool   follow_rigid_motion = true; ///< the damping relaxes towards X^m + τR (R: rigid motion of the shape)
    double shape_motion_cutoff = 0.01; ///< ε of the regularized fit of R
    double mesh_quality_floor = 0.05; ///< a run stops when the mesh quality falls below this
  };

  /**
   * Material parameters of the in-plane viscous flow: Reynolds number and
   * which inertial terms are assembled.
   */
  struct FlowCoefficients
  {
    double reynolds_number = 1.0; ///< Re = ρUL/η
    bool   inertia         = true; ///< ∂_t u (the Stokes limit drops it)
    bool   convection      = true; ///< ∇_w u with w = u − ∂_t X
    bool   conserve_momenta = false; ///< multipliers keep ∫u = P₀ and ∫x × u = L₀ (with inertia)
  };

  /**
   * The fluid deformable surface (seed eqs. 1–4): the full 3D velocity u ∈ [Q2]³,
   * surface pressure p ∈ Q1, curvature κ and bending scalar y ∈ Q_k, the new
   * position Y ∈ [Q_k]³ and the volume multiplier γ, solved as one linear
   * system per step on the frozen surface S^m (all nonlinear coefficients
   * lagged), so that the chain u → Y → κ → y → bending force is implicit.
   */
  class FluidDeformableSurface
  {
  public:
    /// Result of one step attempt.
    struct StepResult
    {
      bool         solved = false;
      std::string  failure;
      unsigned int linear_iterations = 0;
      double       gamma             = 0;
      double       dissipation_rate  = 0; ///< (2/Re)‖σ(u)‖² on S^m
      bool         factorized        = false; ///< whether this step computed a new factorization
      double       rigid_force       = 0; ///< Stokes limit: |λ| of the multipliers of ∫u = 0, ∫X×u = 0
    };

    FluidDeformableSurface(SurfaceGeometry &geometry);

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

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

    /// Makes the last advance() the current state.
    void
    accept();

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
      return bending.enabled ? willmore_energy / bending.bending_number : 0.0;
    }

    /// Be of the bending force.
    double
    bending_number() const
    {
      return bending.bending_number;
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
    /// Whether ∂_t u is assembled (false: the Stokes limit, whose energy F is the bending energy alone).
    bool
    has_inertia() const
    {
      return flow.inertia;
    }

    /// Adds u, |u| and p to a DataOut.
    void
    add_output_fields(dealii::DataOut<2, 3> &data_out) const;

    /// Velocity at the quadrature points of a geometry FEValues' cell.
    static constexpr unsigned int velocity_component = 0;
    static constexpr unsigned int pressure_component = 3;
    static constexpr unsigned int curvature_component = 4;
    static constexpr unsigned int bending_component   = 5;
    static constexpr unsigned int position_component  = 6;

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
    };
    /// The momenta of @p state on the current surface, and the rigid motion R whose normal velocity R·ν
    /// fits u·ν in L² (regularized by `shape_motion_cutoff`): the motion of the shape, not of the fluid.
    RigidMotion
    rigid_motion(const VectorType &state) const;
    void
    setup_dofs();
    void
    set_initial_velocity();
    void
    assemble(const double tau, const RigidMotion &motion);
    /// Y of @p flow_solution → the geometry's position field.
    void
    copy_new_position_to_geometry(const VectorType &flow_solution);
    /// The geometry's position X → the Y components of @p flow_vector (owned).
    void
    copy_position_into(VectorType &flow_vector) const;
    /// (2/Re)‖σ(u)‖² of @p state on the current surface.
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

    FlowCoefficients   flow;
    BendingForce       bending;
    VolumeConstraint   volume_constraint;
    MeshRedistribution redistribution;

    // Initial velocity: translation U plus rigid rotation ω e × (x − c) plus seeded noise.
    dealii::Tensor<1, 3> translation_velocity;
    double               initial_angular_velocity = 0;
    bool                 equilibrium_rotation     = false; ///< ω₀ from the geometry's equilibrium shape
    dealii::Tensor<1, 3> rotation_axis;
    dealii::Point<3>     rotation_centre;
    double               velocity_noise   = 0;
    double               shape_noise      = 0;
    unsigned int         random_seed      = 1;

    std::unique_ptr<dealii::FESystem<2, 3>> fe;
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
    /// (flow DoF of Y_d, geometry DoF of X_d) for the locally owned nodes.
    std::vector<std::pair<dealii::types::global_dof_index, dealii::types::global_dof_index>> position_pairs;
    double                                 last_tau = 0;     ///< τ of the step that produced X^m
    double                                 last_step_tau = 0; ///< τ of the last advance()
    double                                 target_volume = 0;
    double                                 target_area   = 0;
    bool                                   area_correction = true;
    double                                 drift_correction_time = 0.01;

    /// The step's LU factorization, kept across steps (`subsection linear solver`).
    ReusedFactorizationSolver                       linear_solver;
    dealii::TimerOutput                            *step_timer            = nullptr;
    /// Stokes limit: ε of the regularization ε(u, v) and the columns (r_k, v) of the rigid motions
    /// r = e_1, e_2, e_3, e_1 × x, e_2 × x, e_3 × x, whose multipliers enforce ∫u = 0, ∫x × u = 0.
    double                                          stokes_regularization = 1e-6;
    std::array<VectorType, 6>                       rigid_columns;
    /// The constraint rows of the rigid motions: (r_k, u) in the Stokes limit; with inertia the momenta on
    /// the new surface, linearized in Y (their Y entries; see assemble()).
    std::array<VectorType, 6>                       rigid_rows;
    /// Values g_k of the rigid-motion constraints (r_k, u) = g_k: 0 in the Stokes limit, the initial
    /// ∫u and ∫x × u with `conserve momenta`.
    std::array<double, 6> rigid_targets = {{0, 0, 0, 0, 0, 0}};
    /// Whether the rigid-motion multipliers are part of the step.
    bool
    rigid_constraints() const
    {
      return !flow.inertia || flow.conserve_momenta;
    }
    /// The state and multipliers of the last step: the initial guess of the GMRES solve.
    BorderedSystem::BlockVector                     last_solution;
    /// The relaxation time τ_c = max(τ_drift, τ_max) of the drift corrections (≥ τ, independent of τ).
    double
    drift_time(const double tau) const
    {
      return std::max(tau, drift_correction_time);
    }
  };
} // namespace FluidSurface

#endif
