// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_flow_surface_flow_h
#define fluid_surface_flow_surface_flow_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fluid_surface/flow/flow_point_values.h>
#include <fluid_surface/flow/surface_fluid.h>
#include <fluid_surface/geometry/surface_geometry.h>
#include <fluid_surface/io/output_writer.h>
#include <fluid_surface/linear_algebra/block_stokes_preconditioner.h>
#include <fluid_surface/linear_algebra/reused_factorization_solver.h>
#include <fluid_surface/io/statistics_file.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace FluidSurface
{
  /**
   * A flow given by formulas in R³ (an exact solution or a prescribed field),
   * evaluated at points of the discrete surface.
   */
  struct FlowField
  {
    /// u(x, t), full 3D vector.
    std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &, const double)> velocity;
    /// Ambient Jacobian (∇u^e)_{ij} = ∂u_i/∂x_j of the extension of u used by the formulas.
    std::function<dealii::Tensor<2, 3>(const dealii::Point<3> &, const double)> velocity_gradient;
    /// p(x, t); compared modulo its mean.
    std::function<double(const dealii::Point<3> &, const double)> pressure;
  };

  /**
   * Surface Navier–Stokes on a frozen surface S_h with Günther derivatives,
   * Taylor–Hood u ∈ [Q2]³ (full 3D vector), p ∈ Q1: the solver of scene fixed surface.
   *
   *   (α₀/τ)(u, v) + c(w; u, v) + (2/Re)(σ(u), σ(v)) − (p, div_P v) − (div_P u, q)
   *     + η (u·n, v·n) = (f, v) + (1/τ)(Σ_k β_k u^{m−k}, v),
   *
   * σ(u) = ½(∇_P u + ∇_P uᵀ), ∇_P u = P ∇_C u, div_P u = tr ∇_C u. The mass, viscous, pressure,
   * continuity and convection integrands are those of scene full (SurfaceFluid). Tangentiality
   * u·ν = 0 is imposed by the penalty η = β h_K^{−q} with a normal n that can be
   * the exact normal of the analytic surface, the continuous normal ñ of the
   * geometry, or the cell normal ν_h; or by a Lagrange multiplier λ ∈ Q_d,
   * (λ, v·n) + (u·n, μ) (direct solver only). Convection is the skew-symmetric form
   * c(w; u, v) = ½[(∇_w u, v) − (∇_w v, u)] of SurfaceFluid::convection_term with w extrapolated
   * from the old steps (energy neutral on the fixed surface: c(w; u, u) = 0). Time derivative: BDF1 or BDF2.
   * The mass and convection terms are assembled only when switched on. Which rows it shares with scene full,
   * and why convection and BDF differ: doc/architecture.md, "The fixed-surface scene and the model's flow terms".
   *
   * Translation units: surface_flow.cc (parameters, DoFs, constraints, matrices, initial state),
   * surface_flow_assembly.cc (cell terms, velocity AMG matrices, global system), surface_flow_solvers.cc,
   * surface_flow_diagnostics.cc (energies, error norms).
   */
  class SurfaceFlow
  {
  public:
    /// Backward differentiation formula of the time derivative.
    enum class TimeScheme
    {
      bdf1,
      bdf2
    };
    /// How u·n = 0 is imposed.
    enum class Tangentiality
    {
      penalty,   ///< η(u·n, v·n), η = β h_K^{−q}
      multiplier ///< a Lagrange multiplier λ ∈ Q1 or Q2: (λ, v·n) + (u·n, μ) (direct solver only)
    };
    /// The normal n of the tangentiality penalty η(u·n, v·n) (or of the multiplier constraint).
    enum class PenaltyNormal
    {
      exact,      ///< normal of the analytic surface (set_exact_normal)
      continuous, ///< ñ ∈ [Q_k]³ of SurfaceGeometry::normal_field()
      cell        ///< ν_h of the mapped cell
    };
    /// Linear solver of the saddle-point system.
    enum class LinearSolver
    {
      direct,              ///< Amesos (KLU or MUMPS); with convection the old factorization preconditions GMRES
      block_preconditioned ///< GMRES + block-triangular preconditioner: AMG(A_uu), Schur ≈ Cahouet–Chabard
    };
    /// The matrix on which the velocity AMG of the block preconditioner is built.
    enum class VelocityAMGOperator
    {
      q2,               ///< the Q2 velocity block A itself
      low_order_refined ///< A assembled with Q1 on the 4 sub-cells of each cell (same DoFs as Q2)
    };

    /// Work done by one linear solve.
    struct SolveInfo
    {
      unsigned int iterations   = 0;     ///< Krylov iterations (0 for a plain direct solve)
      bool         factorized   = false; ///< a new factorization (or AMG hierarchy) was built
      double       assemble_time = 0;    ///< wall seconds of assembly
      double       solve_time    = 0;    ///< wall seconds of the solver, setup included
    };

    /// Errors against an exact flow (Killing components and pressure means removed first).
    struct Errors
    {
      double velocity          = 0; ///< ‖u − u_h‖_L2
      double tangential        = 0; ///< ‖P(u − u_h)‖_L2
      double gradient          = 0; ///< ‖∇_P u − ∇_P u_h‖_L2
      double pressure          = 0; ///< ‖(p − p̄) − (p_h − p̄_h)‖_L2
      double normal_velocity   = 0; ///< ‖u_h·n‖_L2
    };

    /**
     * The discretization and solver of scene fixed surface (`subsection fixed surface solver`), and what it
     * takes from the fluid (`subsection flow`, SurfaceFluid).
     */
    struct Parameters
    {
      /// The fluid's terms and Re, as parsed once from `subsection flow` by SurfaceFluid (not re-read).
      SurfaceFluid fluid;

      // `subsection fixed surface solver`, set by parse().
      TimeScheme          time_scheme{};                       ///< `time scheme`
      Tangentiality       tangentiality{};                     ///< how u·n = 0 is imposed
      unsigned int        multiplier_degree{};                 ///< polynomial degree of the multiplier λ ∈ Q_d
      PenaltyNormal       penalty_normal{};                    ///< n of the penalty η(u·n, v·n)
      double              penalty_factor{};                    ///< β of η = β h^{−q}
      double              penalty_exponent{};                  ///< q of η = β h^{−q}
      LinearSolver        solver{};                            ///< `linear solver`: direct or block preconditioned
      std::string         velocity_amg_smoother;               ///< ML smoother of the velocity AMG
      double              velocity_amg_aggregation_threshold{}; ///< ML aggregation threshold of the velocity AMG
      VelocityAMGOperator velocity_amg_operator{};             ///< matrix of the velocity AMG
      bool                velocity_amg_node_frames{};          ///< velocity AMG in node frames [t₁ t₂ n]
      unsigned int        max_linear_iterations{};             ///< Krylov iterations of one solve at most
      /// `subsection linear solver`: the direct solver and the tolerance of both solvers.
      ReusedFactorizationSolver::Parameters linear_solver;

      /// Declares `subsection fixed surface solver` (and the linear-solver entries of `subsection flow`).
      static void
      declare(dealii::ParameterHandler &prm);
      /// Reads them and keeps the parsed @p fluid.
      void
      parse(dealii::ParameterHandler &prm, const SurfaceFluid &fluid);
    };

    /// A flow on @p geometry with parsed @p parameters.
    SurfaceFlow(const SurfaceGeometry &geometry, const Parameters &parameters);

    /// Declares `subsection fixed surface solver` (Parameters::declare).
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// The parameters given to the constructor.
    const Parameters &
    get_parameters() const
    {
      return parameters;
    }

    /// Switches the time derivative and the convection term (a scene decides; Stokes: both off).
    void
    set_terms(const bool time_derivative, const bool convection);

    /// The normal of the analytic surface, for PenaltyNormal::exact and for the error norms.
    void
    set_exact_normal(const std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &)> &normal);

    /// Body force f(x, t) of the momentum equation (only its projection onto the test functions enters).
    void
    set_body_force(const std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &, const double)> &force);

    /**
     * Distributes the Taylor–Hood DoFs and builds constraints and matrices. For
     * a stationary Stokes problem on a surface with Killing fields
     * (rotations a × x that leave S invariant), pass the rotation axes; the
     * right-hand side is made orthogonal to them, and each is removed by
     * fixing one velocity component at the velocity node nearest to a ray ⊥ a
     * (where that rotation is largest); InputError if the mesh has no node
     * near that ray.
     */
    void
    setup(const std::vector<dealii::Tensor<1, 3>> &killing_axes = {});

    /// u_h = I_h u(·, t) (nodal interpolation on the curved surface) for the current and all old steps.
    void
    set_initial_velocity(const FlowField &initial, const double time);

    /// Solves the stationary problem (time derivative off).
    SolveInfo
    solve_stationary();

    /// One BDF step from t − τ to @p time (the first BDF2 step is a BDF1 step).
    SolveInfo
    advance(const double time, const double tau);

    /// F_kin = ½∫|u_h|² (EnergyFunctionals::kinetic_energy).
    double
    kinetic_energy() const;
    /// D = (2/Re)∫|σ(u_h)|², so dF_kin/dt = −D for the exact flow (EnergyFunctionals::dissipation_rate).
    double
    dissipation_rate() const;

    /// Errors of the current solution against @p exact at @p time.
    Errors
    compute_errors(const FlowField &exact, const double time) const;

    /// The DoFs of (u, p[, λ]), velocity block first.
    const dealii::DoFHandler<2, 3> &
    dof_handler() const
    {
      return flow_dofs;
    }
    /// (u, p), ghosted; components 0–2 velocity, 3 pressure (4: the tangentiality multiplier λ, if any).
    const VectorType &
    solution() const
    {
      return current;
    }
    /// Number of velocity DoFs (the first block).
    dealii::types::global_dof_index
    n_velocity_dofs() const
    {
      return n_u;
    }
    /// Number of pressure DoFs (the second block).
    dealii::types::global_dof_index
    n_pressure_dofs() const
    {
      return n_p;
    }
    /// Re.
    double
    reynolds_number() const
    {
      return parameters.fluid.Re;
    }
    /// One line naming the discretization and solver choices, for the screen.
    std::string
    description() const;

  private:
    struct ScratchData;
    struct CopyData;
    /// The rotations R_k = [t₁ t₂ n] of the 9 velocity nodes of a cell (the identity where Cartesian).
    using NodeFrames = std::array<dealii::Tensor<2, 3>, 9>;

    /// Tables of the low-order-refined operator: the 12 velocity DoFs and the quadrature points of each of the
    /// 4 sub-cells, and the node (0–8) of each local velocity DoF.
    void
    index_lor_subcells();
    /// The sparsity patterns and matrices of the system (and of the block preconditioner).
    void
    reinit_matrices();
    /// The constraints fixing the Killing fields at one node per axis (direct solver).
    void
    pin_killing_fields();
    /// The cell of the geometry's DoFHandler (position X, normal ñ) that is @p cell of the flow's.
    typename dealii::DoFHandler<2, 3>::active_cell_iterator
    geometry_cell(const typename dealii::DoFHandler<2, 3>::active_cell_iterator &cell) const;
    /// I_h of @p field at @p time on the curved surface (the multiplier λ, if any, is 0).
    VectorType
    interpolate(const FlowField &field, const double time) const;
    /// α₀ and the history coefficients β₁, β₂ of (α₀u^{m+1} − β₁u^m − β₂u^{m−1})/τ of the next step (the
    /// first BDF2 step is a BDF1 step).
    std::array<double, 3>
    bdf_coefficients() const;

    /**
     * The system at @p time with step @p tau: the right-hand side, the matrix if @p assemble_matrix (and the
     * preconditioner matrices if they are outdated); stationary runs with Killing fields then remove the
     * Killing components of the right-hand side.
     */
    void
    assemble(const double time, const double tau, const bool assemble_matrix);
    /// One cell of assemble(): the flow terms (SurfaceFluid), the body force, the penalty or multiplier.
    void
    local_assemble(const typename dealii::DoFHandler<2, 3>::active_cell_iterator &cell,
                   ScratchData                                                   &scratch,
                   CopyData                                                      &copy) const;
    /// Reinitializes the cell's values and clears @p copy: shape functions, ñ (continuous penalty normal) and
    /// the old velocities (time derivative).
    void
    reinit_cell(const typename dealii::DoFHandler<2, 3>::active_cell_iterator &cell,
                ScratchData                                                   &scratch,
                CopyData                                                      &copy) const;
    /// The normal n of the tangentiality penalty (or multiplier) at quadrature point @p q of the cell.
    dealii::Tensor<1, 3>
    penalty_normal_at(const ScratchData &scratch, const unsigned int q) const;
    /// The BDF history β₁u^m + β₂u^{m−1} and the extrapolated convection velocity at quadrature point @p q.
    void
    set_old_velocities(ScratchData &scratch, const unsigned int q, const std::array<double, 3> &bdf) const;
    /**
     * Adds the integrands at quadrature point @p q (scratch.point) to the cell's matrix and right-hand side,
     * and to the preconditioner matrices if @p build_preconditioner.
     */
    void
    add_point_terms(ScratchData                 &scratch,
                    CopyData                    &copy,
                    const unsigned int           q,
                    const double                 penalty,
                    const std::array<double, 3> &bdf,
                    const bool                   build_preconditioner) const;
    /**
     * The cell's matrices of the velocity AMG (block preconditioner): its velocity block rotated into node
     * frames [t₁ t₂ n], or the low-order-refined operator on the 4 sub-cells with the penalty @p penalty.
     */
    void
    assemble_amg_matrices(const typename dealii::DoFHandler<2, 3>::active_cell_iterator &cell,
                          ScratchData                                                   &scratch,
                          CopyData                                                      &copy,
                          const double                                                   penalty) const;
    /// The node frames of the cell's 9 velocity nodes (Cartesian at constrained nodes).
    NodeFrames
    node_frames(const typename dealii::DoFHandler<2, 3>::active_cell_iterator &cell,
                ScratchData                                                   &scratch,
                const CopyData                                                &copy) const;
    /**
     * The low-order-refined velocity block (2/Re)(σ(u), σ(v)) + η(u·n, v·n) [+ (α₀/τ)(u, v)] with the penalty
     * @p penalty of this cell, for the piecewise bilinear functions on its 4 sub-cells, in the node frames
     * @p frames.
     */
    void
    assemble_lor_matrices(const typename dealii::DoFHandler<2, 3>::active_cell_iterator &cell,
                          ScratchData                                                   &scratch,
                          CopyData                                                      &copy,
                          const double                                                   penalty,
                          const NodeFrames                                              &frames) const;
    /// A_R = QᵀAQ of the local matrix @p A on the cell DoFs @p dofs, Q the node frames @p frames (the
    /// identity on pressure DoFs).
    void
    rotate_into_frames(const std::vector<unsigned int> &dofs,
                       const NodeFrames                &frames,
                       const dealii::FullMatrix<double> &A,
                       dealii::FullMatrix<double>       &A_R) const;
    /// Adds one cell's matrices and vectors to the global ones, with the constraints.
    void
    copy_local_to_global(const CopyData &copy);
    /// Quadrature of the low-order-refined operator: 2×2 Gauss points on each of the 4 sub-cells.
    static dealii::Quadrature<2>
    lor_quadrature();
    /// The orthonormal frame [t₁ t₂ n] at a velocity node x (n exact if known, else ñ/|ñ|); the
    /// identity at a @p cartesian (constrained) node and on meshes with hanging nodes.
    dealii::Tensor<2, 3>
    lor_frame(const dealii::Point<3> &x, const dealii::Tensor<1, 3> &smooth_normal, const bool cartesian) const;
    /// The stationary right-hand side made orthogonal to the Killing fields (k_aᵀF = 0).
    void
    remove_killing_components_from_rhs();

    /// The owned velocity nodes with their positions, normals ñ/|ñ| and frames, for the velocity AMG.
    std::vector<BlockStokesPreconditioner::VelocityNode>
    velocity_nodes() const;
    /**
     * Solves the assembled system into the current solution: the kept factorization (or AMG hierarchies) is
     * rebuilt when τ or α₀ changed (@p coefficients_changed); @p matrix_changed tells the direct solver that
     * the matrix is new.
     */
    SolveInfo
    solve(const bool matrix_changed, const bool coefficients_changed);
    /// GMRES with the block preconditioner, whose AMG hierarchies are built if they are not.
    unsigned int
    solve_block_preconditioned(VectorType &x);

    const SurfaceGeometry &geometry;
    MPI_Comm               communicator;

    Parameters parameters;

    // Terms switched by the scene.
    bool with_time_derivative = false;
    bool with_convection      = false;

    std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &)>               exact_normal;
    std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &, const double)> body_force;
    std::vector<dealii::Tensor<1, 3>>                                            killing;

    dealii::FESystem<2, 3>            fe;
    /// [Q1 iso Q2]³ × Q1: piecewise bilinear on the 4 sub-cells, with the DoF layout of fe.
    dealii::FESystem<2, 3>            lor_fe;
    /// Per sub-cell of the low-order-refined operator: its 12 local velocity DoFs, its quadrature points.
    std::vector<std::vector<unsigned int>> lor_subcell_dofs, lor_subcell_points;
    std::vector<unsigned int>              lor_dof_node; ///< local velocity DoF → its node (0–8) in the cell
    bool hanging_nodes = false; ///< the mesh has hanging nodes (node frames are then Cartesian)
    dealii::DoFHandler<2, 3>          flow_dofs;
    dealii::types::global_dof_index   n_u = 0, n_p = 0;
    dealii::IndexSet                  owned, relevant;
    std::vector<dealii::IndexSet>     owned_partitioning, relevant_partitioning;
    dealii::AffineConstraints<double> constraints;

    dealii::TrilinosWrappers::SparseMatrix      system_matrix;
    dealii::TrilinosWrappers::BlockSparseMatrix preconditioner_matrix; ///< A_uu without convection; M_p
    dealii::TrilinosWrappers::BlockSparseMatrix pressure_laplace;      ///< L_p (time-dependent runs)
    dealii::TrilinosWrappers::SparseMatrix      lor_velocity_matrix;   ///< A_uu with Q1 on the sub-cells
    VectorType                                  system_rhs;
    VectorType                                  unconstrained_rhs; ///< F before constraints (stationary)
    std::vector<VectorType>                     killing_moments;   ///< m_a = (a × x, φ_i)
    VectorType                                  current, old, older; ///< u^{m+1}, u^m, u^{m−1} (ghosted)
    unsigned int                                n_steps_done           = 0;
    double                                      current_tau            = 0;
    double                                      current_time_for_force = 0;
    double                                      assembled_tau          = 0; ///< τ of the assembled matrix
    double                                      assembled_alpha0       = 0; ///< α₀ of the assembled matrix

    // What the last solve leaves for the next one: the kept factorization (`linear solver = direct`) or
    // the AMG hierarchies (block preconditioned).
    ReusedFactorizationSolver                                      linear_solver;
    BlockStokesPreconditioner                                      block_preconditioner;
    bool                                                           matrix_assembled = false;
    bool preconditioner_outdated = true; ///< the next assembly must build the preconditioner matrices
  };

} // namespace FluidSurface

#endif
