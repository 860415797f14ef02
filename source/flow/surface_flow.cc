#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_q_iso_q1.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <fluid_surface/flow/energy_functionals.h>
#include <fluid_surface/flow/surface_flow.h>
#include <fluid_surface/geometry/surface_operators.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/linear_algebra/factorization_preconditioner.h>

#include <limits>
#include <map>
#include <sstream>

namespace FluidSurface
{
  using namespace dealii;
  namespace SO = SurfaceOperators;

  // ---------------------------------------------------------------- parameters

  void
  SurfaceFlow::Parameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("fixed surface solver");
    prm.declare_entry("time scheme",
                      "BDF2",
                      Patterns::Selection("BDF1|BDF2"),
                      "Time discretization of ∂_t u: BDF1 (u^{m+1} − u^m)/τ or BDF2 "
                      "(3u^{m+1} − 4u^m + u^{m−1})/(2τ) (first step BDF1).");
    prm.declare_entry("tangentiality",
                      "penalty",
                      Patterns::Selection("penalty|multiplier"),
                      "How u·n = 0 is imposed: penalty η(u·n, v·n), η = β h_K^{−q}; or multiplier, a Lagrange "
                      "multiplier λ ∈ Q_d (d = `multiplier degree`) with (λ, v·n) + (u·n, μ) added to the "
                      "saddle-point system (direct solver only; n as in `penalty normal`).");
    prm.declare_entry("multiplier degree",
                      "1",
                      Patterns::Integer(1, 2),
                      "Degree d, 1 or 2, of the tangentiality multiplier λ ∈ Q_d (tangentiality = multiplier).");
    prm.declare_entry("penalty normal",
                      "exact",
                      Patterns::Selection("exact|continuous|cell"),
                      "Normal n of the tangentiality penalty: the exact normal of the analytic surface "
                      "(fixed-surface verification scenes), the continuous normal ñ ∈ [Q_k]³ (L2 projection "
                      "of ν_h), or the cell normal ν_h.");
    prm.declare_entry("penalty factor",
                      "10",
                      RealRange::closed(1e-6, 1e6),
                      "β, 1e-6 ≤ β ≤ 1e6, of the tangentiality penalty η = β h_K^{−q}, h_K = |K|^{1/2}.");
    prm.declare_entry("penalty exponent",
                      "3",
                      RealRange::closed(0, 6),
                      "q, 0 ≤ q ≤ 6, of the tangentiality penalty η = β h_K^{−q}.");
    prm.declare_entry("linear solver",
                      "direct",
                      Patterns::Selection("direct|block preconditioned"),
                      "direct: sparse LU (Amesos), with convection the last factorization preconditions "
                      "GMRES while it converges fast; block preconditioned: GMRES with a block-triangular "
                      "preconditioner, AMG on the velocity block A and S⁻¹ ≈ (1/Re) M_p⁻¹ + (α₀/τ) L_p⁻¹.");
    prm.declare_entry("velocity AMG smoother",
                      "symmetric block Gauss-Seidel",
                      Patterns::Selection("Chebyshev|symmetric Gauss-Seidel|symmetric block Gauss-Seidel|"
                                          "Block Chebyshev|ILU|exact"),
                      "Smoother of the AMG V-cycle that approximates the velocity block A⁻¹ in the block "
                      "preconditioner (ML names); exact: a sparse LU of A instead of AMG (reference for the "
                      "Schur complement approximation).");
    prm.declare_entry("velocity AMG aggregation threshold",
                      "1e-4",
                      RealRange::closed(0, 1),
                      "ML aggregation threshold θ, 0 ≤ θ ≤ 1, of the velocity AMG (connections weaker than θ are dropped "
                      "when aggregating). Stationary sphere problem, Cartesian components, GMRES iterations at "
                      "refinements 3–5: 35, 58, 139 with θ = 0.02; 30, 44, 46 with θ = 1e-4 "
                      "(benchmarks/surface_stokes).");
    prm.declare_entry("velocity AMG operator",
                      "Q2",
                      Patterns::Selection("Q2|low-order refined"),
                      "Matrix on which the velocity AMG of the block preconditioner is built: Q2, the velocity "
                      "block A itself; low-order refined, the same operator (2/Re)(σ(u), σ(v)) + η(u·n, v·n) "
                      "[+ (α₀/τ)(u, v)] assembled with piecewise bilinear functions on the 4 sub-cells of "
                      "each cell (the Q2 nodes are the vertices of the sub-cells, so the DoFs are the same); "
                      "its V-cycle then preconditions the Q2 block. Stationary sphere, node frames, GMRES "
                      "iterations at refinements 3–6: Q2 29, 26, 31, 33; low-order refined 43, 36, 38 at "
                      "refinements 3–5 (benchmarks/surface_stokes).");
    prm.declare_entry("velocity AMG node frames",
                      "true",
                      Patterns::Bool(),
                      "Build the velocity AMG on the matrix written in node frames [t₁ t₂ n] (tangential and "
                      "normal components at each node, Cartesian at constrained nodes) instead of Cartesian "
                      "components; the penalty η(u·n, v·n) then acts on the normal DoFs only. Stationary "
                      "sphere, GMRES iterations at refinements 3–6 (Q2 operator): 30, 44, 46, 54 Cartesian; "
                      "29, 26, 31, 33 in node frames (benchmarks/surface_stokes).");
    prm.declare_entry("max linear iterations",
                      "1000",
                      Patterns::Integer(1, 100000),
                      "Maximum number of Krylov iterations of one solve, 1 to 100000.");
    prm.leave_subsection();
  }

  void
  SurfaceFlow::Parameters::parse(ParameterHandler &prm, const SurfaceFluid &fluid)
  {
    Re         = fluid.Re;
    inertia    = fluid.inertia;
    convection = fluid.convection;
    prm.enter_subsection("fixed surface solver");
    time_scheme = prm.get("time scheme") == "BDF1" ? TimeScheme::bdf1 : TimeScheme::bdf2;
    const std::string normal = prm.get("penalty normal");
    penalty_normal   = normal == "exact" ? PenaltyNormal::exact :
                       normal == "continuous" ? PenaltyNormal::continuous : PenaltyNormal::cell;
    tangentiality    = prm.get("tangentiality") == "penalty" ? Tangentiality::penalty : Tangentiality::multiplier;
    multiplier_degree = prm.get_integer("multiplier degree");
    penalty_factor   = prm.get_double("penalty factor");
    penalty_exponent = prm.get_double("penalty exponent");
    solver = prm.get("linear solver") == "direct" ? LinearSolver::direct : LinearSolver::block_preconditioned;
    velocity_amg_smoother         = prm.get("velocity AMG smoother");
    velocity_amg_aggregation_threshold = prm.get_double("velocity AMG aggregation threshold");
    velocity_amg_operator = prm.get("velocity AMG operator") == "Q2" ? VelocityAMGOperator::q2 :
                                                              VelocityAMGOperator::low_order_refined;
    velocity_amg_node_frames = prm.get_bool("velocity AMG node frames");
    max_linear_iterations = prm.get_integer("max linear iterations");
    if (tangentiality == Tangentiality::multiplier && solver != LinearSolver::direct)
      throw_invalid_entry("fixed surface solver/tangentiality",
                          "multiplier",
                          "penalty: the multiplier is implemented for `linear solver = direct` only, not for "
                          "block preconditioned");
    prm.leave_subsection();
    linear_solver.parse_parameters(prm);
  }

  void
  SurfaceFlow::declare_parameters(ParameterHandler &prm)
  {
    Parameters::declare(prm);
  }

  // ---------------------------------------------------------------- setup

  namespace
  {
    /// [velocity]³ × Q1 pressure, × Q_d multiplier with Tangentiality::multiplier.
    std::vector<const FiniteElement<2, 3> *>
    flow_elements(const FiniteElement<2, 3> &velocity, const SurfaceFlow::Parameters &parameters)
    {
      static const FE_Q<2, 3> q1(1), q2(2);
      if (parameters.tangentiality == SurfaceFlow::Tangentiality::multiplier)
        return {&velocity, &q1, parameters.multiplier_degree == 2 ? &q2 : &q1};
      return {&velocity, &q1};
    }
    std::vector<unsigned int>
    flow_multiplicities(const SurfaceFlow::Parameters &parameters)
    {
      return std::vector<unsigned int>(parameters.tangentiality == SurfaceFlow::Tangentiality::multiplier ? 3 : 2, 1);
    }
  } // namespace

  SurfaceFlow::SurfaceFlow(const SurfaceGeometry &geometry, const Parameters &parameters)
    : geometry(geometry)
    , communicator(geometry.get_communicator())
    , parameters(parameters)
    , fe(flow_elements(FESystem<2, 3>(FE_Q<2, 3>(2), 3), parameters), flow_multiplicities(parameters))
    , lor_fe(flow_elements(FESystem<2, 3>(FE_Q_iso_Q1<2, 3>(2), 3), parameters), flow_multiplicities(parameters))
    , flow_dofs(geometry.triangulation())
    , linear_solver("Amesos_Klu", parameters.linear_solver) // `direct solver = default` of this scene
  {
    fluid.Re         = parameters.Re;
    fluid.inertia    = parameters.inertia;
    fluid.convection = parameters.convection;
    // Sub-cell s = (s_x, s_y) of the reference cell holds the nodes and quadrature points with
    // coordinates in [s_x/2, (s_x+1)/2] × [s_y/2, (s_y+1)/2]; its 4 nodes carry 12 velocity DoFs.
    const std::vector<Point<2>> &nodes  = fe.base_element(0).get_unit_support_points();
    const Quadrature<2>          quadrature = lor_quadrature();
    const std::vector<Point<2>> &points     = quadrature.get_points();
    lor_subcell_dofs.assign(4, {});
    lor_dof_node.assign(fe.n_dofs_per_cell(), numbers::invalid_unsigned_int);
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      if (fe.system_to_base_index(i).first.first == 0)
        lor_dof_node[i] = fe.base_element(0).system_to_base_index(fe.system_to_base_index(i).second).second;
    lor_subcell_points.assign(4, {});
    const auto inside = [](const Point<2> &x, const unsigned int s) {
      return std::abs(x[0] - 0.25 - 0.5 * (s % 2)) <= 0.25 + 1e-12 && std::abs(x[1] - 0.25 - 0.5 * (s / 2)) <= 0.25 + 1e-12;
    };
    for (unsigned int s = 0; s < 4; ++s)
      {
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          if (fe.system_to_base_index(i).first.first == 0 && inside(nodes[fe.system_to_base_index(i).second], s))
            lor_subcell_dofs[s].push_back(i);
        for (unsigned int q = 0; q < points.size(); ++q)
          if (inside(points[q], s))
            lor_subcell_points[s].push_back(q);
        AssertThrow(lor_subcell_dofs[s].size() == 12 && 4 * lor_subcell_points[s].size() == points.size(),
                    ExcInternalError());
      }
  }

  Quadrature<2>
  SurfaceFlow::lor_quadrature()
  {
    return QIterated<2>(QGauss<1>(2), 2);
  }

  std::string
  SurfaceFlow::description() const
  {
    std::ostringstream out;
    out << "Taylor–Hood [Q2]³×Q1, " << n_u << " + " << n_p << " DoFs, Re = " << parameters.Re << ", "
        << (with_time_derivative ? (parameters.time_scheme == TimeScheme::bdf1 ? "BDF1" : "BDF2") : "stationary")
        << (with_convection ? " + convection" : "") << ", penalty η = " << parameters.penalty_factor
        << " h^-" << parameters.penalty_exponent << " with "
        << (parameters.penalty_normal == PenaltyNormal::exact ?
              "exact" :
              parameters.penalty_normal == PenaltyNormal::continuous ? "continuous" : "cell")
        << " normal"
        << (parameters.tangentiality == Tangentiality::multiplier ?
              " (Lagrange multiplier λ ∈ Q" + std::to_string(parameters.multiplier_degree) + " instead)" :
              std::string())
        << ", "
        << (parameters.solver == LinearSolver::direct ?
              linear_solver.direct_solver() :
              std::string("GMRES + block AMG (") +
                (parameters.velocity_amg_operator == VelocityAMGOperator::q2 ? "Q2" : "low-order refined") +
                (parameters.velocity_amg_node_frames ? ", node frames)" : ", Cartesian)"));
    return out.str();
  }

  void
  SurfaceFlow::set_terms(const bool time_derivative, const bool convection)
  {
    with_time_derivative = time_derivative;
    with_convection      = time_derivative && convection;
  }

  void
  SurfaceFlow::set_exact_normal(const std::function<Tensor<1, 3>(const Point<3> &)> &normal)
  {
    exact_normal = normal;
  }

  void
  SurfaceFlow::set_body_force(const std::function<Tensor<1, 3>(const Point<3> &, const double)> &force)
  {
    body_force = force;
  }

  void
  SurfaceFlow::setup(const std::vector<Tensor<1, 3>> &killing_axes)
  {
    if ((parameters.tangentiality == Tangentiality::multiplier) != (fe.n_components() == 5))
      throw InputError("fixed surface solver/tangentiality was changed after the flow solver was created; parse "
                       "the parameters before constructing SurfaceFlow");
    if (parameters.penalty_normal == PenaltyNormal::exact && !exact_normal)
      throw InputError("fixed surface solver/penalty normal = exact needs the normal of an analytic surface; "
                       "this scene has none (use continuous or cell)");
    killing = killing_axes;
    flow_dofs.distribute_dofs(fe);
    // Velocity block first; inside it the three components of a node stay adjacent, as ML's
    // vector AMG (PDE equations = 3) expects.
    DoFRenumbering::block_wise(flow_dofs);
    const std::vector<types::global_dof_index> dofs_per_block = DoFTools::count_dofs_per_fe_block(flow_dofs);
    n_u   = dofs_per_block[0];
    n_p   = dofs_per_block[1];
    owned = flow_dofs.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(flow_dofs, relevant);
    owned_partitioning    = {owned.get_view(0, n_u), owned.get_view(n_u, n_u + n_p)};
    relevant_partitioning = {relevant.get_view(0, n_u), relevant.get_view(n_u, n_u + n_p)};

    hanging_nodes = geometry.triangulation().has_hanging_nodes();
    constraints.clear();
    constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(flow_dofs, constraints);
    pin_killing_fields();
    constraints.close();

    {
      DynamicSparsityPattern dsp(relevant);
      DoFTools::make_sparsity_pattern(flow_dofs, dsp, constraints, false);
      SparsityTools::distribute_sparsity_pattern(dsp, owned, communicator, relevant);
      system_matrix.reinit(owned, owned, dsp, communicator);
    }
    if (parameters.solver == LinearSolver::block_preconditioned)
      {
        // Only u–u and p–p couplings: the blocks the preconditioner inverts.
        Table<2, DoFTools::Coupling> coupling(4, 4);
        for (unsigned int c = 0; c < 4; ++c)
          for (unsigned int d = 0; d < 4; ++d)
            coupling[c][d] = ((c < 3) == (d < 3)) ? DoFTools::always : DoFTools::none;
        BlockDynamicSparsityPattern bdsp(relevant_partitioning);
        DoFTools::make_sparsity_pattern(flow_dofs, coupling, bdsp, constraints, false);
        SparsityTools::distribute_sparsity_pattern(bdsp, owned, communicator, relevant);
        preconditioner_matrix.reinit(owned_partitioning, bdsp, communicator);
        pressure_laplace.reinit(owned_partitioning, bdsp, communicator);
        if (parameters.velocity_amg_operator == VelocityAMGOperator::low_order_refined)
          {
            // Couplings of the sub-cells only: 9 nodes per row instead of 25. The velocity DoFs are
            // the first n_u, so the constraints apply unchanged.
            DynamicSparsityPattern               lor_dsp(relevant_partitioning[0]);
            std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell()), subcell(12);
            for (const auto &cell : flow_dofs.active_cell_iterators())
              if (cell->is_locally_owned())
                {
                  cell->get_dof_indices(indices);
                  for (const std::vector<unsigned int> &dofs : lor_subcell_dofs)
                    {
                      for (unsigned int a = 0; a < 12; ++a)
                        subcell[a] = indices[dofs[a]];
                      constraints.add_entries_local_to_global(subcell, lor_dsp, false);
                    }
                }
            SparsityTools::distribute_sparsity_pattern(lor_dsp, owned_partitioning[0], communicator,
                                                       relevant_partitioning[0]);
            lor_velocity_matrix.reinit(owned_partitioning[0], owned_partitioning[0], lor_dsp, communicator);
          }
      }
    system_rhs.reinit(owned, communicator);
    current.reinit(owned, relevant, communicator);
    old.reinit(owned, relevant, communicator);
    older.reinit(owned, relevant, communicator);
    n_steps_done     = 0;
    matrix_assembled = false;
    linear_solver.release();
    block_preconditioner.clear();
  }

  void
  SurfaceFlow::pin_killing_fields()
  {
    // A rotation a × x is removed by fixing, at the velocity node nearest to the ray through d ⊥ a,
    // the component along a × d (where that rotation is largest). The node is chosen over all
    // processes (smallest distance of x/|x| to the ray, ties broken by the smallest DoF index), so a
    // mesh without a node exactly on the ray (gmsh) and a parallel run both fix exactly one node.
    if (killing.empty())
      return;
    std::map<types::global_dof_index, Point<3>> support;
    DoFTools::map_dofs_to_support_points(geometry.mapping(), flow_dofs, support);
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const Tensor<1, 3> &axis : killing)
      {
        Tensor<1, 3> ray;
        ray[std::abs(axis[2]) > 0.5 ? 0 : 2] = 1.0;
        const Tensor<1, 3> direction = cross_product_3d(axis, ray);
        unsigned int       component = 0;
        for (unsigned int d = 1; d < 3; ++d)
          if (std::abs(direction[d]) > std::abs(direction[component]))
            component = d;
        double                  distance = std::numeric_limits<double>::max();
        types::global_dof_index nearest  = numbers::invalid_dof_index;
        for (const auto &cell : flow_dofs.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(indices);
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                if (fe.system_to_component_index(i).first == component && !constraints.is_constrained(indices[i]))
                  {
                    const Point<3> &x = support.at(indices[i]);
                    const double    d = (x / x.norm() - Point<3>(ray)).norm();
                    if (d < distance - 1e-12 || (d <= distance + 1e-12 && indices[i] < nearest))
                      distance = d, nearest = indices[i];
                  }
            }
        const double global_distance = Utilities::MPI::min(distance, communicator);
        // Beyond ~30° from the ray the fixed component no longer carries the rotation well.
        if (!(global_distance < 0.5))
          throw InputError("fixed surface: no velocity node within 30° of the direction " +
                           std::to_string(ray[0]) + "," + std::to_string(ray[1]) + "," + std::to_string(ray[2]) +
                           " to fix the Killing field about the axis " + std::to_string(axis[0]) + "," +
                           std::to_string(axis[1]) + "," + std::to_string(axis[2]) + " (refine the mesh)");
        const types::global_dof_index pinned = Utilities::MPI::min(
          distance <= global_distance + 1e-12 ? nearest : numbers::invalid_dof_index, communicator);
        if (relevant.is_element(pinned))
          constraints.add_line(pinned);
      }
  }

  namespace
  {
    /// Adapts a FlowField to a deal.II Function of the 4 flow components (u, p).
    class FlowFunction : public Function<3>
    {
    public:
      FlowFunction(const FlowField &field, const double time, const unsigned int n_components)
        : Function<3>(n_components, time)
        , field(field)
      {}
      double
      value(const Point<3> &x, const unsigned int component) const override
      {
        if (component < 3)
          return field.velocity(x, this->get_time())[component];
        if (component > 3) // the tangentiality multiplier
          return 0.0;
        return field.pressure ? field.pressure(x, this->get_time()) : 0.0;
      }

    private:
      const FlowField &field;
    };
  } // namespace

  void
  SurfaceFlow::set_initial_velocity(const FlowField &initial, const double time)
  {
    VectorType owned_values(owned, communicator);
    VectorTools::interpolate(geometry.mapping(), flow_dofs, FlowFunction(initial, time, fe.n_components()), owned_values);
    constraints.distribute(owned_values);
    current      = owned_values;
    old          = owned_values;
    older        = owned_values;
    n_steps_done = 0;
  }

  // ---------------------------------------------------------------- assembly

  struct SurfaceFlow::ScratchData
  {
    ScratchData(const Mapping<2, 3>       &mapping,
                const FiniteElement<2, 3> &flow_fe,
                const FiniteElement<2, 3> &geometry_fe,
                const Quadrature<2>       &quadrature,
                const FiniteElement<2, 3> &lor_fe,
                const Quadrature<2>       &lor_quadrature)
      : flow_values(mapping,
                    flow_fe,
                    quadrature,
                    update_values | update_gradients | update_normal_vectors | update_JxW_values |
                      update_quadrature_points)
      , geometry_values(mapping, geometry_fe, quadrature, update_values)
      , lor_values(mapping,
                   lor_fe,
                   lor_quadrature,
                   update_values | update_gradients | update_normal_vectors | update_JxW_values |
                     update_quadrature_points)
      , lor_geometry_values(mapping,
                            geometry_fe,
                            Quadrature<2>(flow_fe.base_element(0).base_element(0).get_unit_support_points()),
                            update_values | update_quadrature_points)
      , lor_normal(lor_geometry_values.n_quadrature_points)
      , point(flow_fe.n_dofs_per_cell())
      , phi(flow_fe.n_dofs_per_cell())
      , sigma(flow_fe.n_dofs_per_cell())
      , grad_psi(flow_fe.n_dofs_per_cell())
      , normal_phi(flow_fe.n_dofs_per_cell())
      , multiplier(flow_fe.n_dofs_per_cell())
      , old_u(quadrature.size())
      , older_u(quadrature.size())
      , smooth_normal(quadrature.size())
    {}
    ScratchData(const ScratchData &other)
      : ScratchData(other.flow_values.get_mapping(),
                    other.flow_values.get_fe(),
                    other.geometry_values.get_fe(),
                    other.flow_values.get_quadrature(),
                    other.lor_values.get_fe(),
                    other.lor_values.get_quadrature())
    {}

    FEValues<2, 3>            flow_values;
    FEValues<2, 3>            geometry_values;
    FEValues<2, 3>            lor_values;          ///< low-order-refined velocity operator
    FEValues<2, 3>            lor_geometry_values; ///< ñ at the 9 nodes of the cell
    std::vector<Tensor<1, 3>> lor_normal;
    FlowPointValues           point;      ///< the flow terms' data at one quadrature point
    std::vector<Tensor<1, 3>> phi;        ///< velocity shape values on a sub-cell (low-order refined)
    std::vector<Tensor<2, 3>> sigma;      ///< their σ
    std::vector<Tensor<1, 3>> grad_psi;   ///< pressure gradients (the L_p of the preconditioner)
    std::vector<double>       normal_phi;
    std::vector<double>       multiplier; ///< shape values of λ (Tangentiality::multiplier)
    std::vector<Tensor<1, 3>> old_u, older_u, smooth_normal;
  };

  struct SurfaceFlow::CopyData
  {
    explicit CopyData(const unsigned int n)
      : matrix(n, n)
      , velocity_and_pressure_mass(n, n)
      , pressure_laplace(n, n)
      , rhs(n)
      , indices(n)
      , lor_matrices(4, FullMatrix<double>(12, 12))
      , lor_indices(4, std::vector<types::global_dof_index>(12))
    {}
    FullMatrix<double>                   matrix;
    FullMatrix<double>                   velocity_and_pressure_mass; ///< A_uu (no convection) ⊕ M_p
    FullMatrix<double>                   pressure_laplace;           ///< L_p
    Vector<double>                       rhs;
    std::vector<Vector<double>>          killing_moments; ///< (a × x, φ_i) per Killing axis a
    std::vector<types::global_dof_index> indices;
    bool                                 with_matrix = true;
    bool                                 with_lor    = false; ///< the sub-cell matrices are filled
    std::vector<FullMatrix<double>>                   lor_matrices; ///< per sub-cell, its 12 velocity DoFs
    std::vector<std::vector<types::global_dof_index>> lor_indices;
  };

  namespace
  {
    /// α₀ and the history coefficients β₁, β₂ of (α₀u^{m+1} − β₁u^m − β₂u^{m−1})/τ.
    std::array<double, 3>
    bdf_coefficients(const SurfaceFlow::TimeScheme scheme, const unsigned int steps_done)
    {
      if (scheme == SurfaceFlow::TimeScheme::bdf1 || steps_done == 0)
        return {{1.0, 1.0, 0.0}};
      return {{1.5, 2.0, -0.5}};
    }
  } // namespace

  void
  SurfaceFlow::local_assemble(const typename DoFHandler<2, 3>::active_cell_iterator &cell,
                              ScratchData                                           &scratch,
                              CopyData                                              &copy) const
  {
    FEValues<2, 3> &fv = scratch.flow_values;
    fv.reinit(cell);
    const FEValuesExtractors::Vector velocity(0);
    const FEValuesExtractors::Scalar pressure(3);
    const unsigned int               n      = fe.n_dofs_per_cell();
    const unsigned int               n_q    = fv.n_quadrature_points;
    const double                     tau    = current_tau;
    const std::array<double, 3>      bdf    = bdf_coefficients(parameters.time_scheme, n_steps_done);
    const bool                       build_preconditioner =
      copy.with_matrix && parameters.solver == LinearSolver::block_preconditioned && preconditioner_outdated;

    copy.matrix                     = 0;
    copy.velocity_and_pressure_mass = 0;
    copy.pressure_laplace           = 0;
    copy.rhs                        = 0;
    copy.killing_moments.resize(with_time_derivative ? 0 : killing.size(), Vector<double>(n));
    for (Vector<double> &moment : copy.killing_moments)
      moment = 0;
    cell->get_dof_indices(copy.indices);

    if (parameters.penalty_normal == PenaltyNormal::continuous)
      {
        const typename DoFHandler<2, 3>::active_cell_iterator geometry_cell(&geometry.triangulation(),
                                                                            cell->level(),
                                                                            cell->index(),
                                                                            &geometry.dof_handler());
        scratch.geometry_values.reinit(geometry_cell);
        scratch.geometry_values[velocity].get_function_values(geometry.normal_field(), scratch.smooth_normal);
      }
    if (with_time_derivative)
      {
        fv[velocity].get_function_values(old, scratch.old_u);
        fv[velocity].get_function_values(older, scratch.older_u);
      }

    double cell_area = 0;
    for (unsigned int q = 0; q < n_q; ++q)
      cell_area += fv.JxW(q);
    const bool   with_multiplier = parameters.tangentiality == Tangentiality::multiplier;
    const double penalty =
      with_multiplier ? 0.0 : parameters.penalty_factor * std::pow(cell_area, -0.5 * parameters.penalty_exponent);

    FlowPointValues &point = scratch.point;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        point.reinit(fv, q);
        const double        dA = point.JxW;
        const Point<3>     &x  = point.position;
        Tensor<1, 3>        n_penalty;
        switch (parameters.penalty_normal)
          {
            case PenaltyNormal::exact:
              n_penalty = exact_normal(x);
              break;
            case PenaltyNormal::continuous:
              n_penalty = scratch.smooth_normal[q] / scratch.smooth_normal[q].norm();
              break;
            case PenaltyNormal::cell:
              n_penalty = point.normal;
              break;
          }
        if (with_time_derivative)
          {
            // The BDF history β₁u^m + β₂u^{m−1} and the extrapolated convection velocity (second order with BDF2).
            point.old_velocity = bdf[1] * scratch.old_u[q] + bdf[2] * scratch.older_u[q];
            point.transport_velocity =
              (bdf[2] == 0.0) ? scratch.old_u[q] : Tensor<1, 3>(2.0 * scratch.old_u[q] - scratch.older_u[q]);
          }
        Tensor<1, 3> force;
        if (body_force)
          force = body_force(x, current_time_for_force);

        for (unsigned int i = 0; i < n; ++i)
          {
            scratch.grad_psi[i]   = fv[pressure].gradient(i, q);
            scratch.normal_phi[i] = SO::normal_component(point.velocity[i], n_penalty);
            scratch.multiplier[i] = with_multiplier ? fv[FEValuesExtractors::Scalar(4)].value(i, q) : 0.0;
          }

        for (unsigned int a = 0; a < copy.killing_moments.size(); ++a)
          {
            const Tensor<1, 3> rotation = cross_product_3d(killing[a], x);
            for (unsigned int i = 0; i < n; ++i)
              copy.killing_moments[a](i) += rotation * point.velocity[i] * dA;
          }
        for (unsigned int i = 0; i < n; ++i)
          {
            copy.rhs(i) += force * point.velocity[i] * dA;
            if (with_time_derivative)
              copy.rhs(i) += SurfaceFluid::mass_term_rhs(point, i, 1.0 / tau) * dA;
            if (!copy.with_matrix)
              continue;
            for (unsigned int j = 0; j < n; ++j)
              {
                double velocity_block =
                  fluid.viscous_term(point, i, j) + penalty * scratch.normal_phi[i] * scratch.normal_phi[j];
                if (with_time_derivative)
                  velocity_block += SurfaceFluid::mass_term(point, i, j, bdf[0] / tau);
                // The skew-symmetric form ½[(∇_w u, v) − (∇_w v, u)].
                double convection = 0;
                if (with_convection)
                  convection =
                    0.5 * (SurfaceFluid::convection_term(point, i, j) - SurfaceFluid::convection_term(point, j, i));
                copy.matrix(i, j) += (velocity_block + convection + SurfaceFluid::pressure_term(point, i, j) +
                                      SurfaceFluid::continuity_term(point, i, j) +
                                      scratch.normal_phi[i] * scratch.multiplier[j] +
                                      scratch.multiplier[i] * scratch.normal_phi[j]) *
                                     dA;
                if (build_preconditioner)
                  {
                    copy.velocity_and_pressure_mass(i, j) +=
                      (velocity_block + point.pressure[i] * point.pressure[j]) * dA;
                    if (with_time_derivative)
                      copy.pressure_laplace(i, j) += (scratch.grad_psi[i] * scratch.grad_psi[j] +
                                                      1e-2 * point.pressure[i] * point.pressure[j]) *
                                                     dA;
                  }
              }
          }
      }

    const bool lor = build_preconditioner && parameters.velocity_amg_operator == VelocityAMGOperator::low_order_refined;
    copy.with_lor  = lor;
    if (build_preconditioner && (lor || parameters.velocity_amg_node_frames))
      assemble_amg_matrices(cell, scratch, copy, penalty);
  }

  void
  SurfaceFlow::assemble_amg_matrices(const typename DoFHandler<2, 3>::active_cell_iterator &cell,
                                     ScratchData                                           &scratch,
                                     CopyData                                              &copy,
                                     const double                                           penalty) const
  {
    const FEValuesExtractors::Vector velocity(0);
    const unsigned int               n   = fe.n_dofs_per_cell();
    const double                     Re  = parameters.Re;
    const double                     tau = current_tau;
    const std::array<double, 3>      bdf = bdf_coefficients(parameters.time_scheme, n_steps_done);
    const bool lor = parameters.velocity_amg_operator == VelocityAMGOperator::low_order_refined;

    // Node frames [t₁ t₂ n] (Cartesian at constrained nodes): the AMG sees the velocity block in
    // tangential and normal components, so the penalty, which acts on the normal component only,
    // stays on the normal DoFs instead of mixing all three Cartesian ones.
    std::array<Tensor<2, 3>, 9> frames;
    for (unsigned int k = 0; k < 9; ++k)
      frames[k] = Tensor<2, 3>(unit_symmetric_tensor<3>());
    if (parameters.velocity_amg_node_frames)
      {
        const typename DoFHandler<2, 3>::active_cell_iterator geometry_cell(&geometry.triangulation(),
                                                                            cell->level(),
                                                                            cell->index(),
                                                                            &geometry.dof_handler());
        scratch.lor_geometry_values.reinit(geometry_cell);
        scratch.lor_geometry_values[velocity].get_function_values(geometry.normal_field(), scratch.lor_normal);
        std::array<bool, 9> constrained{};
        for (unsigned int i = 0; i < n; ++i)
          if (lor_dof_node[i] != numbers::invalid_unsigned_int && constraints.is_constrained(copy.indices[i]))
            constrained[lor_dof_node[i]] = true;
        for (unsigned int k = 0; k < 9; ++k)
          frames[k] = lor_frame(scratch.lor_geometry_values.quadrature_point(k), scratch.lor_normal[k], constrained[k]);
      }
    // A_R = QᵀAQ with Q(a, b) = R_k[c_a][c_b] for DoFs a, b at the same node k (c: Cartesian component
    // of a, frame direction of b); the identity on the pressure DoFs.
    // Q has at most 3 entries per column, so A_R = Qᵀ(AQ) costs 6m² operations.
    const auto rotate = [&](const std::vector<unsigned int> &dofs, const FullMatrix<double> &A, FullMatrix<double> &A_R) {
      const unsigned int                                       m = dofs.size();
      std::vector<std::array<std::pair<unsigned int, double>, 3>> column(m);
      std::vector<unsigned int>                                count(m, 0);
      for (unsigned int b = 0; b < m; ++b)
        if (lor_dof_node[dofs[b]] == numbers::invalid_unsigned_int)
          column[b][count[b]++] = {b, 1.0};
        else
          for (unsigned int a = 0; a < m; ++a)
            if (lor_dof_node[dofs[a]] == lor_dof_node[dofs[b]])
              column[b][count[b]++] = {a,
                                       frames[lor_dof_node[dofs[a]]][fe.system_to_component_index(dofs[a]).first]
                                             [fe.system_to_component_index(dofs[b]).first]};
      FullMatrix<double> AQ(m, m);
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int b = 0; b < m; ++b)
          for (unsigned int t = 0; t < count[b]; ++t)
            AQ(i, b) += A(i, column[b][t].first) * column[b][t].second;
      for (unsigned int a = 0; a < m; ++a)
        for (unsigned int b = 0; b < m; ++b)
          {
            double sum = 0;
            for (unsigned int t = 0; t < count[a]; ++t)
              sum += column[a][t].second * AQ(column[a][t].first, b);
            A_R(a, b) = sum;
          }
    };

    if (!lor)
      {
        std::vector<unsigned int> all(n);
        for (unsigned int i = 0; i < n; ++i)
          all[i] = i;
        const FullMatrix<double> cartesian(copy.velocity_and_pressure_mass);
        rotate(all, cartesian, copy.velocity_and_pressure_mass);
        return;
      }

    // Low-order refined: the velocity block (2/Re)(σ(u), σ(v)) + η(u·n, v·n) [+ (α₀/τ)(u, v)], with
    // the η of this cell, for the piecewise bilinear functions on the 4 sub-cells.
    FEValues<2, 3> &lv = scratch.lor_values;
    lv.reinit(typename Triangulation<2, 3>::cell_iterator(cell));
    const double       mass = with_time_derivative ? bdf[0] / tau : 0.0;
    FullMatrix<double> cartesian(12, 12);
    for (unsigned int s = 0; s < 4; ++s)
      {
        const std::vector<unsigned int> &dofs = lor_subcell_dofs[s];
        cartesian                             = 0;
        for (unsigned int a = 0; a < 12; ++a)
          copy.lor_indices[s][a] = copy.indices[dofs[a]];
        for (const unsigned int q : lor_subcell_points[s])
          {
            const double        dA = lv.JxW(q);
            const Tensor<1, 3> &nu = lv.normal_vector(q);
            // The exact normal if the penalty uses it, else ν_h (for a preconditioner, ñ and ν_h are alike).
            const Tensor<1, 3> n_penalty =
              parameters.penalty_normal == PenaltyNormal::exact ? exact_normal(lv.quadrature_point(q)) : nu;
            for (unsigned int a = 0; a < 12; ++a)
              {
                scratch.phi[a]        = lv[velocity].value(dofs[a], q);
                scratch.sigma[a]      = SO::strain_rate(lv[velocity].gradient(dofs[a], q), nu);
                scratch.normal_phi[a] = SO::normal_component(scratch.phi[a], n_penalty);
              }
            for (unsigned int a = 0; a < 12; ++a)
              for (unsigned int b = 0; b < 12; ++b)
                cartesian(a, b) += ((2.0 / Re) * scalar_product(scratch.sigma[a], scratch.sigma[b]) +
                                    penalty * scratch.normal_phi[a] * scratch.normal_phi[b] +
                                    mass * scratch.phi[a] * scratch.phi[b]) *
                                   dA;
          }
        rotate(dofs, cartesian, copy.lor_matrices[s]);
      }
  }

  Tensor<2, 3>
  SurfaceFlow::lor_frame(const Point<3> &x, const Tensor<1, 3> &smooth_normal, const bool cartesian) const
  {
    // Constrained nodes (the Killing pins, hanging nodes) keep the Cartesian frame, in which their
    // constraints are written.
    if (cartesian || hanging_nodes)
      return Tensor<2, 3>(unit_symmetric_tensor<3>());
    // n is the exact normal if there is one, else ñ.
    return BlockStokesPreconditioner::node_frame(exact_normal ? exact_normal(x) :
                                                                Tensor<1, 3>(smooth_normal / smooth_normal.norm()));
  }

  void
  SurfaceFlow::copy_local_to_global(const CopyData &copy)
  {
    if (copy.with_lor)
      for (unsigned int s = 0; s < 4; ++s)
        constraints.distribute_local_to_global(copy.lor_matrices[s], copy.lor_indices[s], lor_velocity_matrix);
    if (!copy.killing_moments.empty())
      {
        unconstrained_rhs.add(copy.indices, copy.rhs);
        for (unsigned int a = 0; a < copy.killing_moments.size(); ++a)
          killing_moments[a].add(copy.indices, copy.killing_moments[a]);
      }
    if (copy.with_matrix)
      {
        constraints.distribute_local_to_global(copy.matrix, copy.rhs, copy.indices, system_matrix, system_rhs);
        if (parameters.solver == LinearSolver::block_preconditioned && preconditioner_outdated)
          {
            constraints.distribute_local_to_global(copy.velocity_and_pressure_mass,
                                                   copy.indices,
                                                   preconditioner_matrix);
            if (with_time_derivative)
              constraints.distribute_local_to_global(copy.pressure_laplace, copy.indices, pressure_laplace);
          }
      }
    else
      constraints.distribute_local_to_global(copy.rhs, copy.indices, system_rhs);
  }

  void
  SurfaceFlow::assemble(const double time, const double tau, const bool assemble_matrix)
  {
    current_tau            = tau;
    current_time_for_force = time;
    system_rhs             = 0;
    const bool make_consistent = !with_time_derivative && !killing.empty();
    if (make_consistent)
      {
        unconstrained_rhs.reinit(owned, communicator);
        killing_moments.assign(killing.size(), unconstrained_rhs);
      }
    if (assemble_matrix)
      {
        system_matrix = 0;
        if (parameters.solver == LinearSolver::block_preconditioned && preconditioner_outdated)
          {
            preconditioner_matrix = 0;
            pressure_laplace      = 0;
            if (parameters.velocity_amg_operator == VelocityAMGOperator::low_order_refined)
              lor_velocity_matrix = 0;
          }
      }
    using CellFilter = FilteredIterator<typename DoFHandler<2, 3>::active_cell_iterator>;
    CopyData copy(fe.n_dofs_per_cell());
    copy.with_matrix = assemble_matrix;
    WorkStream::run(CellFilter(IteratorFilters::LocallyOwnedCell(), flow_dofs.begin_active()),
                    CellFilter(IteratorFilters::LocallyOwnedCell(), flow_dofs.end()),
                    [this](const typename DoFHandler<2, 3>::active_cell_iterator &cell,
                           ScratchData                                           &scratch,
                           CopyData &local) { local_assemble(cell, scratch, local); },
                    [this](const CopyData &local) { copy_local_to_global(local); },
                    ScratchData(geometry.mapping(), fe, geometry.fe(), geometry.quadrature(), lor_fe, lor_quadrature()),
                    copy);
    if (assemble_matrix)
      {
        system_matrix.compress(VectorOperation::add);
        if (parameters.solver == LinearSolver::block_preconditioned && preconditioner_outdated)
          {
            preconditioner_matrix.compress(VectorOperation::add);
            pressure_laplace.compress(VectorOperation::add);
            if (parameters.velocity_amg_operator == VelocityAMGOperator::low_order_refined)
              lor_velocity_matrix.compress(VectorOperation::add);
          }
        matrix_assembled = true;
      }
    system_rhs.compress(VectorOperation::add);
    if (make_consistent)
      {
        unconstrained_rhs.compress(VectorOperation::add);
        for (VectorType &moment : killing_moments)
          moment.compress(VectorOperation::add);
        remove_killing_components_from_rhs();
      }
  }

  void
  SurfaceFlow::remove_killing_components_from_rhs()
  {
    // The stationary operator annihilates the Killing fields k_a = I_h(a × x) (exactly for k ≤ 2 with
    // the exact normal, nearly otherwise), so A u = F needs k_aᵀF = 0. The discrete F misses that by
    // quadrature and geometry errors; the defect would otherwise act as point forces at the fixed
    // nodes. Subtract the Killing force Σ_b μ_b m_b, m_b = (b × x, φ), with k_aᵀ(F − Σ_b μ_b m_b) = 0.
    const unsigned int n_k = killing.size();
    FullMatrix<double> gram(n_k, n_k);
    Vector<double>     moments(n_k), mu(n_k);
    for (unsigned int a = 0; a < n_k; ++a)
      {
        FlowField rotation;
        const Tensor<1, 3> axis = killing[a];
        rotation.velocity = [axis](const Point<3> &x, const double) { return cross_product_3d(axis, x); };
        VectorType interpolant(owned, communicator);
        VectorTools::interpolate(geometry.mapping(), flow_dofs, FlowFunction(rotation, 0.0, fe.n_components()), interpolant);
        moments(a) = interpolant * unconstrained_rhs;
        for (unsigned int b = 0; b < n_k; ++b)
          gram(a, b) = interpolant * killing_moments[b];
      }
    gram.gauss_jordan();
    gram.vmult(mu, moments);
    for (unsigned int b = 0; b < n_k; ++b)
      system_rhs.add(-mu(b), killing_moments[b]);
    constraints.set_zero(system_rhs);
  }

  // ---------------------------------------------------------------- solvers

  std::vector<BlockStokesPreconditioner::VelocityNode>
  SurfaceFlow::velocity_nodes() const
  {
    const IndexSet                                      &owned_velocity = owned_partitioning[0];
    std::vector<BlockStokesPreconditioner::VelocityNode> nodes;
    std::vector<bool>                                    listed(owned_velocity.n_elements(), false);
    const Quadrature<2> support_points(fe.base_element(0).get_unit_support_points());
    FEValues<2, 3>      node_values(geometry.mapping(),
                               geometry.fe(),
                               support_points,
                               update_values | update_quadrature_points);
    std::vector<Tensor<1, 3>>            normals(support_points.size());
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : flow_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(indices);
          const typename DoFHandler<2, 3>::active_cell_iterator geometry_cell(&geometry.triangulation(),
                                                                              cell->level(),
                                                                              cell->index(),
                                                                              &geometry.dof_handler());
          node_values.reinit(geometry_cell);
          node_values[FEValuesExtractors::Vector(0)].get_function_values(geometry.normal_field(), normals);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              // A node is listed at the first cell that has its x component.
              if (fe.system_to_base_index(i).first.first != 0 || fe.system_to_component_index(i).first != 0 ||
                  !owned_velocity.is_element(indices[i]) || listed[owned_velocity.index_within_set(indices[i])])
                continue;
              listed[owned_velocity.index_within_set(indices[i])] = true;
              BlockStokesPreconditioner::VelocityNode node;
              bool                                    constrained = false;
              for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
                if (lor_dof_node[j] == lor_dof_node[i])
                  {
                    node.dofs[fe.system_to_component_index(j).first] = owned_velocity.index_within_set(indices[j]);
                    constrained = constrained || constraints.is_constrained(indices[j]);
                  }
              const unsigned int point = fe.system_to_base_index(i).second;
              node.position            = node_values.quadrature_point(point);
              node.normal              = normals[point] / normals[point].norm();
              node.frame = parameters.velocity_amg_node_frames ? lor_frame(node.position, normals[point], constrained) :
                                                        Tensor<2, 3>(unit_symmetric_tensor<3>());
              nodes.push_back(node);
            }
        }
    return nodes;
  }

  unsigned int
  SurfaceFlow::solve_block_preconditioned(VectorType &x)
  {
    if (!block_preconditioner.initialized())
      {
        const bool lor = parameters.velocity_amg_operator == VelocityAMGOperator::low_order_refined;
        block_preconditioner.initialize(lor ? lor_velocity_matrix : preconditioner_matrix.block(0, 0),
                                        velocity_nodes(),
                                        preconditioner_matrix.block(1, 1),
                                        with_time_derivative ? &pressure_laplace.block(1, 1) : nullptr,
                                        {parameters.velocity_amg_smoother,
                                         parameters.velocity_amg_aggregation_threshold,
                                         !lor,
                                         parameters.velocity_amg_node_frames,
                                         linear_solver.direct_solver()});
      }
    const double alpha0 = with_time_derivative ? bdf_coefficients(parameters.time_scheme, n_steps_done)[0] : 0.0;
    return block_preconditioner.solve(system_matrix,
                                      x,
                                      system_rhs,
                                      1.0 / parameters.Re,
                                      with_time_derivative ? alpha0 / current_tau : 0.0,
                                      linear_solver.get_parameters().tolerance,
                                      parameters.max_linear_iterations);
  }

  SurfaceFlow::SolveInfo
  SurfaceFlow::solve(const bool matrix_changed, const bool coefficients_changed)
  {
    SolveInfo  info;
    Timer      timer;
    VectorType x(owned, communicator);
    x = current;
    if (parameters.solver == LinearSolver::block_preconditioned)
      {
        // The preconditioner blocks (A without convection, M_p, L_p) change only with τ and α₀.
        if (coefficients_changed)
          block_preconditioner.clear();
        info.factorized = !block_preconditioner.initialized();
        info.iterations = solve_block_preconditioned(x);
      }
    else
      {
        // The factorization of a matrix with an older convection velocity preconditions GMRES; one with
        // another τ or α₀ is replaced at once.
        if (coefficients_changed)
          linear_solver.request_factorization();
        if (matrix_changed)
          linear_solver.matrix_changed();
        FactorizationPreconditioner                   preconditioner;
        const ReusedFactorizationSolver::Result result =
          linear_solver.solve(system_matrix, system_matrix, x, system_rhs, preconditioner);
        info.iterations = result.iterations;
        info.factorized = result.factorized;
      }
    constraints.distribute(x);
    current         = x;
    info.solve_time = timer.wall_time();
    return info;
  }

  SurfaceFlow::SolveInfo
  SurfaceFlow::solve_stationary()
  {
    Timer timer;
    preconditioner_outdated = true;
    assemble(0.0, 1.0, true);
    const double assemble_time = timer.wall_time();
    SolveInfo    info          = solve(true, true);
    info.assemble_time         = assemble_time;
    return info;
  }

  SurfaceFlow::SolveInfo
  SurfaceFlow::advance(const double time, const double tau)
  {
    // The matrix depends on τ and α₀ (BDF2 starts with a BDF1 step) and, with convection, on w.
    const double alpha0               = bdf_coefficients(parameters.time_scheme, n_steps_done)[0];
    const bool   coefficients_changed = !matrix_assembled || tau != assembled_tau || alpha0 != assembled_alpha0;
    const bool   matrix_changed       = with_convection || coefficients_changed;
    assembled_tau                     = tau;
    assembled_alpha0                  = alpha0;
    // The preconditioner matrices (A without convection, M_p, L_p) change only with τ and α₀; they are
    // assembled only when the AMG hierarchies are rebuilt.
    preconditioner_outdated = coefficients_changed || !block_preconditioner.initialized();
    Timer timer;
    assemble(time, tau, matrix_changed);
    const double assemble_time = timer.wall_time();
    SolveInfo    info          = solve(matrix_changed, coefficients_changed);
    info.assemble_time         = assemble_time;
    older                      = old;
    old                        = current;
    ++n_steps_done;
    return info;
  }

  // ---------------------------------------------------------------- evaluation

  double
  SurfaceFlow::kinetic_energy() const
  {
    return EnergyFunctionals::kinetic_energy(geometry.mapping(), flow_dofs, current, geometry.quadrature(), communicator);
  }

  double
  SurfaceFlow::dissipation_rate() const
  {
    return EnergyFunctionals::dissipation_rate(
      geometry.mapping(), flow_dofs, current, geometry.quadrature(), parameters.Re, communicator);
  }

  SurfaceFlow::Errors
  SurfaceFlow::compute_errors(const FlowField &exact, const double time) const
  {
    const QGauss<2>           quadrature(geometry.degree() + 3);
    FEValues<2, 3>            fv(geometry.mapping(),
                      fe,
                      quadrature,
                      update_values | update_gradients | update_normal_vectors | update_JxW_values |
                        update_quadrature_points);
    const unsigned int        n_q = quadrature.size();
    std::vector<Tensor<1, 3>> u(n_q);
    std::vector<Tensor<2, 3>> G(n_q);
    std::vector<double>       p(n_q);
    const unsigned int        n_k = killing.size();

    // Pass 1: means of p and p_h, and the L2 projections of u and u_h onto the Killing fields a × x.
    FullMatrix<double> gram(n_k, n_k);
    std::vector<double> sums(3 + 2 * n_k, 0.0); // area, ∫p, ∫p_h, (u, K_a), (u_h, K_a)
    for (const auto &cell : flow_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fv.reinit(cell);
          fv[FEValuesExtractors::Vector(0)].get_function_values(current, u);
          fv[FEValuesExtractors::Scalar(3)].get_function_values(current, p);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const Point<3> &x  = fv.quadrature_point(q);
              const double    dA = fv.JxW(q);
              sums[0] += dA;
              sums[1] += (exact.pressure ? exact.pressure(x, time) : 0.0) * dA;
              sums[2] += p[q] * dA;
              const Tensor<1, 3> u_exact = exact.velocity(x, time);
              for (unsigned int a = 0; a < n_k; ++a)
                {
                  const Tensor<1, 3> K_a = cross_product_3d(killing[a], x);
                  sums[3 + a] += u_exact * K_a * dA;
                  sums[3 + n_k + a] += u[q] * K_a * dA;
                  for (unsigned int b = 0; b < n_k; ++b)
                    gram(a, b) += K_a * cross_product_3d(killing[b], x) * dA;
                }
            }
        }
    Utilities::MPI::sum(sums, communicator, sums);
    for (unsigned int a = 0; a < n_k; ++a)
      for (unsigned int b = 0; b < n_k; ++b)
        gram(a, b) = Utilities::MPI::sum(gram(a, b), communicator);
    Vector<double> c_exact(n_k), c_discrete(n_k);
    if (n_k > 0)
      {
        Vector<double> r_exact(n_k), r_discrete(n_k);
        for (unsigned int a = 0; a < n_k; ++a)
          {
            r_exact(a)    = sums[3 + a];
            r_discrete(a) = sums[3 + n_k + a];
          }
        gram.gauss_jordan();
        gram.vmult(c_exact, r_exact);
        gram.vmult(c_discrete, r_discrete);
      }
    const double mean_p = sums[1] / sums[0], mean_p_h = sums[2] / sums[0];

    // Pass 2: the error integrals.
    std::array<double, 5> squares = {{0, 0, 0, 0, 0}};
    for (const auto &cell : flow_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fv.reinit(cell);
          fv[FEValuesExtractors::Vector(0)].get_function_values(current, u);
          fv[FEValuesExtractors::Vector(0)].get_function_gradients(current, G);
          fv[FEValuesExtractors::Scalar(3)].get_function_values(current, p);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const Point<3>     &x    = fv.quadrature_point(q);
              const double        dA   = fv.JxW(q);
              const Tensor<1, 3> &nu_h = fv.normal_vector(q);
              const Tensor<1, 3>  n    = exact_normal ? exact_normal(x) : nu_h;
              const Tensor<2, 3>  P    = SO::projection(n);
              const Tensor<2, 3>  P_h  = SO::projection(nu_h);
              Tensor<1, 3>        u_exact = exact.velocity(x, time);
              Tensor<2, 3>        J_exact = exact.velocity_gradient(x, time);
              Tensor<1, 3>        u_h     = u[q];
              Tensor<2, 3>        G_h     = G[q];
              for (unsigned int a = 0; a < n_k; ++a)
                {
                  Tensor<2, 3> rotation; // [a]×, the Jacobian of a × x
                  rotation[0][1] = -killing[a][2];
                  rotation[0][2] = killing[a][1];
                  rotation[1][0] = killing[a][2];
                  rotation[1][2] = -killing[a][0];
                  rotation[2][0] = -killing[a][1];
                  rotation[2][1] = killing[a][0];
                  const Tensor<1, 3> K_a = cross_product_3d(killing[a], x);
                  u_exact -= c_exact(a) * K_a;
                  J_exact -= c_exact(a) * rotation;
                  u_h -= c_discrete(a) * K_a;
                  G_h -= c_discrete(a) * rotation * P_h;
                }
              const Tensor<1, 3> e = u_exact - u_h;
              squares[0] += e.norm_square() * dA;
              squares[1] += (P * e).norm_square() * dA;
              squares[2] += (P * J_exact * P - SO::projected_gradient(G_h, nu_h)).norm_square() * dA;
              const double p_exact = exact.pressure ? exact.pressure(x, time) - mean_p : 0.0;
              squares[3] += std::pow(p_exact - (p[q] - mean_p_h), 2) * dA;
              squares[4] += std::pow(SO::normal_component(u[q], n), 2) * dA;
            }
        }
    Utilities::MPI::sum(ArrayView<const double>(squares.data(), 5), communicator, ArrayView<double>(squares.data(), 5));
    Errors errors;
    errors.velocity        = std::sqrt(squares[0]);
    errors.tangential      = std::sqrt(squares[1]);
    errors.gradient        = std::sqrt(squares[2]);
    errors.pressure        = std::sqrt(squares[3]);
    errors.normal_velocity = std::sqrt(squares[4]);
    return errors;
  }
} // namespace FluidSurface
