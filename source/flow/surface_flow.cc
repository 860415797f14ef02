// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_q_iso_q1.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <fluid_surface/flow/surface_flow.h>
#include <fluid_surface/io/parameter_file.h>

#include <limits>
#include <map>
#include <sstream>

namespace FluidSurface
{
  using namespace dealii;

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
    this->fluid = fluid;
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
    index_lor_subcells();
  }

  void
  SurfaceFlow::index_lor_subcells()
  {
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
    out << "Taylor–Hood [Q2]³×Q1, " << n_u << " + " << n_p << " DoFs, Re = " << parameters.fluid.Re << ", "
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
    reinit_matrices();
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
  SurfaceFlow::reinit_matrices()
  {
    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(flow_dofs, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, communicator, relevant);
    system_matrix.reinit(owned, owned, dsp, communicator);
    if (parameters.solver != LinearSolver::block_preconditioned)
      return;
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
    if (parameters.velocity_amg_operator != VelocityAMGOperator::low_order_refined)
      return;
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

  typename DoFHandler<2, 3>::active_cell_iterator
  SurfaceFlow::geometry_cell(const typename DoFHandler<2, 3>::active_cell_iterator &cell) const
  {
    return typename DoFHandler<2, 3>::active_cell_iterator(&geometry.triangulation(),
                                                           cell->level(),
                                                           cell->index(),
                                                           &geometry.dof_handler());
  }

  VectorType
  SurfaceFlow::interpolate(const FlowField &field, const double time) const
  {
    VectorType values(owned, communicator);
    VectorTools::interpolate(geometry.mapping(), flow_dofs, FlowFunction(field, time, fe.n_components()), values);
    return values;
  }

  void
  SurfaceFlow::set_initial_velocity(const FlowField &initial, const double time)
  {
    VectorType owned_values = interpolate(initial, time);
    constraints.distribute(owned_values);
    current      = owned_values;
    old          = owned_values;
    older        = owned_values;
    n_steps_done = 0;
  }

  std::array<double, 3>
  SurfaceFlow::bdf_coefficients() const
  {
    if (parameters.time_scheme == TimeScheme::bdf1 || n_steps_done == 0)
      return {{1.0, 1.0, 0.0}};
    return {{1.5, 2.0, -0.5}};
  }
} // namespace FluidSurface
