#include <deal.II/base/work_stream.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>

#include <fluid_surface/flow/energy_functionals.h>
#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/io/run_stopped.h>
#include <fluid_surface/model/nodal_point_values.h>
#include <fluid_surface/model/surface_step.h>

#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace FluidSurface
{
  using namespace dealii;

  SurfaceStep::SurfaceStep(SurfaceGeometry &geometry, const SurfaceState &state)
    : geometry(geometry)
    , state(state)
    , dofs(geometry.triangulation())
    , linear_solver("Amesos_Mumps") // `direct solver = default` of this scene
    , valve_solver("Amesos_Klu")
  {}

  void
  SurfaceStep::declare_parameters(ParameterHandler &prm)
  {
    SurfaceFluid::declare_parameters(prm);
    BendingForce::declare_parameters(prm);
    VolumeConstraint::declare_parameters(prm);
    MeshRedistribution::declare_parameters(prm);
    ConservationProjection::declare_parameters(prm);
    GeometryIteration::declare_parameters(prm);
  }

  void
  SurfaceStep::parse_parameters(ParameterHandler &prm, const double maximum_time_step)
  {
    flow.parse_parameters(prm);
    bending.parse_parameters(prm);
    volume_constraint.parse_parameters(prm, maximum_time_step);
    redistribution.parse_parameters(prm);
    conservation.parse_parameters(prm);
    geometry_iteration.parse_parameters(prm);
    momentum_constraints = MomentumConstraints(flow);
    // The linear solver of the step (entries shared with scene fixed surface).
    linear_solver.parse_parameters(prm);
    ReusedFactorizationSolver::Parameters valve_parameters = linear_solver.get_parameters();
    valve_parameters.reuse_factorization                    = false;
    valve_parameters.direct_solver                          = "Amesos_Klu";
    valve_solver.set_parameters(valve_parameters);
  }

  RigidMotion
  SurfaceStep::rigid_motion(const VectorType &flow_vector) const
  {
    return RigidMotion::fit(geometry,
                            dofs,
                            flow_vector,
                            request.prescribed_velocity(),
                            redistribution.rigid_motion_cutoff,
                            request.law == MeshRedistribution::Law::reference);
  }

  void
  SurfaceStep::setup_dofs()
  {
    const unsigned int k = geometry.degree();
    fe = std::make_unique<FESystem<2, 3>>(FE_Q<2, 3>(2), 3, FE_Q<2, 3>(1), 1, FE_Q<2, 3>(k), 1, FE_Q<2, 3>(k), 1,
                                          FE_Q<2, 3>(k), 3);
    layout = std::make_unique<const DofLayout>(*fe);
    dofs.distribute_dofs(*fe);
    owned = dofs.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    constraints.clear();
    constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    constraints.close();

    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, geometry.get_communicator(), relevant);
    system_matrix.reinit(owned, owned, dsp, geometry.get_communicator());
    system_rhs.reinit(owned, geometry.get_communicator());
    volume_column.reinit(owned, geometry.get_communicator());
    for (auto &column : rigid_columns)
      column.reinit(owned, geometry.get_communicator());
    for (auto &row : rigid_rows)
      row.reinit(owned, geometry.get_communicator());
    linear_solver.release();
    candidate_solution.reinit(owned, relevant, geometry.get_communicator());

    // The nodes of u and Y: the three DoFs of each (for the carried frame of law reference).
    velocity_nodes.clear();
    new_position_nodes.clear();
    {
      std::vector<types::global_dof_index> indices(fe->n_dofs_per_cell());
      std::vector<bool>                    listed(owned.n_elements(), false);
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(indices);
            for (const unsigned int i : layout->velocity)
              if (fe->system_to_component_index(i).first == DofLayout::velocity_component && owned.is_element(indices[i]) &&
                  !listed[owned.index_within_set(indices[i])])
                {
                  listed[owned.index_within_set(indices[i])] = true;
                  std::array<types::global_dof_index, 3> node;
                  for (const unsigned int j : layout->velocity)
                    if (fe->system_to_component_index(j).second == fe->system_to_component_index(i).second)
                      node[fe->system_to_component_index(j).first - DofLayout::velocity_component] = indices[j];
                  velocity_nodes.push_back(node);
                }
            for (const auto &rows : layout->new_position_nodes)
              if (owned.is_element(indices[rows[0]]) && !listed[owned.index_within_set(indices[rows[0]])])
                {
                  listed[owned.index_within_set(indices[rows[0]])] = true;
                  new_position_nodes.push_back({{indices[rows[0]], indices[rows[1]], indices[rows[2]]}});
                }
          }
    }

    // Y_d and X_d share the nodes of Q_k: pair their DoFs cell by cell.
    position_pairs.clear();
    const FiniteElement<2, 3>           &gfe = geometry.fe();
    std::vector<types::global_dof_index> flow_indices(fe->n_dofs_per_cell()), geo_indices(gfe.n_dofs_per_cell());
    std::vector<bool>                    seen(geometry.locally_owned_dofs().n_elements(), false);
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(flow_indices);
          typename DoFHandler<2, 3>::active_cell_iterator geo_cell(&geometry.triangulation(),
                                                                   cell->level(),
                                                                   cell->index(),
                                                                   &geometry.dof_handler());
          geo_cell->get_dof_indices(geo_indices);
          for (unsigned int i = 0; i < fe->n_dofs_per_cell(); ++i)
            {
              const auto ci = fe->system_to_component_index(i);
              if (ci.first < DofLayout::new_position_component)
                continue;
              for (unsigned int j = 0; j < gfe.n_dofs_per_cell(); ++j)
                {
                  const auto cj = gfe.system_to_component_index(j);
                  if (cj.first + DofLayout::new_position_component == ci.first && cj.second == ci.second &&
                      geometry.locally_owned_dofs().is_element(geo_indices[j]))
                    {
                      const auto local = geometry.locally_owned_dofs().index_within_set(geo_indices[j]);
                      if (!seen[local])
                        position_pairs.emplace_back(flow_indices[i], geo_indices[j]);
                      seen[local] = true;
                    }
                }
            }
        }
    // The geometry DoFs of the owned nodes of Y (the error estimate reads X^m and ñ^m there).
    std::map<types::global_dof_index, types::global_dof_index> geometry_dof;
    for (const auto &pair : position_pairs)
      geometry_dof[pair.first] = pair.second;
    new_position_geometry_dofs.clear();
    for (const auto &node : new_position_nodes)
      {
        std::array<types::global_dof_index, 3> geo;
        for (unsigned int d = 0; d < 3; ++d)
          {
            const auto found = geometry_dof.find(node[d]);
            AssertThrow(found != geometry_dof.end(), ExcMessage("a node of Y without its position DoF"));
            geo[d] = found->second;
          }
        new_position_geometry_dofs.push_back(geo);
      }
  }

  double
  SurfaceStep::largest_node_move(const VectorType &a, const VectorType &b) const
  {
    double largest = 0;
    for (const auto &node : new_position_nodes)
      {
        double square = 0;
        for (unsigned int d = 0; d < 3; ++d)
          square += (a[node[d]] - b[node[d]]) * (a[node[d]] - b[node[d]]);
        largest = std::max(largest, square);
      }
    return std::sqrt(Utilities::MPI::max(largest, geometry.get_communicator()));
  }

  double
  SurfaceStep::estimate_error(const VectorType &new_state, const VectorType &old_normal, const double tau)
  {
    if (candidate_normal_speed.size() != state.solution.size())
      candidate_normal_speed.reinit(owned, geometry.get_communicator());
    double largest_difference = 0;
    for (unsigned int n = 0; n < new_position_nodes.size(); ++n)
      {
        const auto  &node = new_position_nodes[n];
        Tensor<1, 3> move, normal;
        for (unsigned int d = 0; d < 3; ++d)
          {
            move[d]   = new_state[node[d]] - state.position[new_position_geometry_dofs[n][d]];
            normal[d] = old_normal[new_position_geometry_dofs[n][d]];
          }
        const double w = move * normal / tau;
        candidate_normal_speed[node[0]] = w;
        if (normal_speed_step > 0)
          largest_difference = std::max(largest_difference, std::abs(w - normal_speed[node[0]]));
      }
    candidate_normal_speed.compress(VectorOperation::insert);
    largest_difference = Utilities::MPI::max(largest_difference, geometry.get_communicator());
    if (normal_speed_step == 0)
      return -1;
    return tau * tau / (tau + normal_speed_step) * largest_difference / shape_radius;
  }

  bool
  SurfaceStep::iterate_geometry_after_rejection()
  {
    if (!geometry_iteration.enabled() || geometry_iteration.apply != GeometryIteration::Apply::after_rejection ||
        corrected_steps_left > 0)
      return false;
    corrected_steps_left = geometry_iteration.corrected_steps;
    return true;
  }

  void
  SurfaceStep::accept_history()
  {
    if (corrected_steps_left > 0)
      --corrected_steps_left;
    membrane_pull = candidate_membrane_pull;
    if (bdf2)
      {
        previous_solution.reinit(owned, relevant, geometry.get_communicator());
        previous_solution = state.solution;
        previous_step     = last_tau;
      }
    if (!estimating_error)
      return;
    normal_speed.reinit(owned, relevant, geometry.get_communicator());
    normal_speed      = candidate_normal_speed;
    normal_speed_step = last_tau;
  }

  void
  SurfaceStep::save_history(CheckpointData &data) const
  {
    if (corrected_steps_left > 0)
      data.set("model/corrected steps left", corrected_steps_left);
    if (membrane_pull > 0)
      data.set("model/membrane pull", membrane_pull);
    if (bdf2 && previous_step > 0)
      {
        data.set("model/previous step", previous_step);
        data.set_fields("previous state", dofs, {&previous_solution});
      }
    if (estimating_error && normal_speed_step > 0)
      {
        data.set("model/normal speed step", normal_speed_step);
        data.set_fields("normal speed", dofs, {&normal_speed});
      }
  }

  void
  SurfaceStep::load_history(const CheckpointData &data)
  {
    corrected_steps_left = data.has("model/corrected steps left") ? data.get_unsigned("model/corrected steps left") : 0;
    membrane_pull           = data.has("model/membrane pull") ? data.get_double("model/membrane pull") : 0;
    candidate_membrane_pull = membrane_pull;
    normal_speed_step    = 0;
    previous_step        = 0;
    // A field of the history (ghosted) and the step it belongs to.
    const auto read = [&](const std::string &field, const std::string &step_key, VectorType &vector, double &step) {
      VectorType x;
      data.get_fields(field, dofs, {&x});
      vector.reinit(owned, relevant, geometry.get_communicator());
      vector = x;
      step   = data.get_double(step_key);
    };
    if (bdf2 && data.has("model/previous step"))
      read("previous state", "model/previous step", previous_solution, previous_step);
    if (estimating_error && data.has("model/normal speed step"))
      read("normal speed", "model/normal speed step", normal_speed, normal_speed_step);
  }

  void
  SurfaceStep::restore_old_geometry()
  {
    VectorType position(geometry.locally_owned_dofs(), geometry.get_communicator());
    position = state.position;
    geometry.set_position(position);
  }

  double
  SurfaceStep::position_dot(const VectorType &a, const VectorType &b) const
  {
    double sum = 0;
    for (const auto &node : new_position_nodes)
      for (unsigned int d = 0; d < 3; ++d)
        sum += a[node[d]] * b[node[d]];
    return Utilities::MPI::sum(sum, geometry.get_communicator());
  }

  void
  SurfaceStep::copy_new_position_to_geometry(const VectorType &flow_solution)
  {
    VectorType position(geometry.locally_owned_dofs(), geometry.get_communicator());
    for (const auto &pair : position_pairs)
      position[pair.second] = flow_solution[pair.first];
    position.compress(VectorOperation::insert);
    geometry.set_position(position);
  }

  void
  SurfaceStep::copy_position_into(const VectorType &x, VectorType &flow_vector) const
  {
    for (const auto &pair : position_pairs)
      flow_vector[pair.first] = x[pair.second];
    flow_vector.compress(VectorOperation::insert);
  }

  void
  SurfaceStep::prepare_bdf2_start(const RigidMotion &carried, const bool carried_frame, const double tau)
  {
    // x̃^{m−1}: the previous state in the frame of the step (law reference: frame coordinates at t^m − τ_p,
    // i.e. carried forward by τ_p; otherwise the previous state itself).
    VectorType previous(owned, geometry.get_communicator());
    previous = previous_solution;
    if (carried_frame)
      carry_fields(carried, previous_step, previous);
    // Variable-step BDF2, ω = τ/τ_p: (α₀x − (1+ω)x^m + ω²/(1+ω)x^{m−1})/τ = f, α₀ = (1+2ω)/(1+ω), written as the
    // backward-Euler step (x − x̂)/(τ/α₀) = f from x̂ = ((1+ω)x^m − ω²/(1+ω)x^{m−1})/α₀; the lagged
    // coefficients (the transport velocity and gradient of the convection) from u* = (1+ω)u^m − ωu^{m−1}.
    const double omega = tau / previous_step, alpha0 = (1 + 2 * omega) / (1 + omega);
    VectorType   start(owned, geometry.get_communicator()), lagged(owned, geometry.get_communicator());
    start = state.solution;
    lagged = start;
    start.sadd((1 + omega) / alpha0, -omega * omega / ((1 + omega) * alpha0), previous);
    lagged.sadd(1 + omega, -omega, previous);
    start_fields.reinit(owned, relevant, geometry.get_communicator());
    lagged_fields.reinit(owned, relevant, geometry.get_communicator());
    start_fields  = start;
    lagged_fields = lagged;
    VectorType start_x(geometry.locally_owned_dofs(), geometry.get_communicator());
    for (const auto &pair : position_pairs)
      start_x[pair.second] = start[pair.first];
    start_x.compress(VectorOperation::insert);
    start_position.reinit(geometry.locally_owned_dofs(), geometry.locally_relevant_dofs(), geometry.get_communicator());
    start_position = start_x;
  }

  void
  SurfaceStep::carry_fields(const RigidMotion &carried, const double tau, VectorType &solution) const
  {
    const Tensor<2, 3> Q = carried.rotation_over(tau);
    for (const auto &node : velocity_nodes)
      {
        Tensor<1, 3> u;
        for (unsigned int d = 0; d < 3; ++d)
          u[d] = solution[node[d]];
        u = Q * u;
        for (unsigned int d = 0; d < 3; ++d)
          solution[node[d]] = u[d];
      }
    for (const auto &node : new_position_nodes)
      {
        Point<3> y;
        for (unsigned int d = 0; d < 3; ++d)
          y[d] = solution[node[d]];
        y = carried.carry(y, tau);
        for (unsigned int d = 0; d < 3; ++d)
          solution[node[d]] = y[d];
      }
    solution.compress(VectorOperation::insert);
  }

  namespace
  {
    /// A TimerOutput section for the lifetime of the object (nothing without a timer).
    class TimerSection
    {
    public:
      TimerSection(TimerOutput *timer, const std::string &name)
        : timer(timer)
        , name(name)
      {
        if (timer)
          timer->enter_subsection(name);
      }
      ~TimerSection()
      {
        if (timer)
          timer->leave_subsection(name);
      }
      TimerSection(const TimerSection &) = delete;
      TimerSection &
      operator=(const TimerSection &) = delete;

    private:
      TimerOutput *timer;
      std::string  name;
    };

  } // namespace

  /// Per-thread FEValues (flow and geometry elements, Gauss and nodal rules) and point values of a cell.
  struct SurfaceStep::AssemblyScratch
  {
    AssemblyScratch(const Mapping<2, 3>       &mapping,
                    const FiniteElement<2, 3> &flow_fe,
                    const FiniteElement<2, 3> &geometry_fe,
                    const Quadrature<2>       &gauss,
                    const Quadrature<2>       &nodal)
      : flow(mapping, flow_fe, gauss, update_values | update_gradients | update_normal_vectors |
                                        update_quadrature_points | update_JxW_values)
      , flow_nodal(mapping, flow_fe, nodal, update_values | update_gradients | update_quadrature_points |
                                              update_JxW_values)
      , geometry(mapping, geometry_fe, gauss, update_values | update_gradients)
      , geometry_nodal(mapping, geometry_fe, nodal, update_values)
      , point(flow_fe.n_dofs_per_cell())
      , nodal_point(flow_fe.n_dofs_per_cell())
      , smooth_normal(gauss.size())
      , smooth_normal_gradient(gauss.size())
      , old_velocity(gauss.size())
      , transport_velocity(gauss.size())
      , old_velocity_gradient(gauss.size())
      , nodal_smooth_normal(nodal.size())
      , old_position(gauss.size())
      , nodal_old_position(nodal.size())
      , reference_gradient(gauss.size())
    {}
    AssemblyScratch(const AssemblyScratch &other)
      : AssemblyScratch(other.flow.get_mapping(),
                        other.flow.get_fe(),
                        other.geometry.get_fe(),
                        other.flow.get_quadrature(),
                        other.flow_nodal.get_quadrature())
    {}

    FEValues<2, 3>            flow, flow_nodal, geometry, geometry_nodal;
    SurfacePointValues        point;
    NodalPointValues          nodal_point;
    std::vector<Tensor<1, 3>> smooth_normal;          ///< ñ^m at the Gauss points
    std::vector<Tensor<2, 3>> smooth_normal_gradient; ///< ∇ñ^m
    std::vector<Tensor<1, 3>> old_velocity;           ///< u^m
    std::vector<Tensor<1, 3>> transport_velocity;     ///< w of the convection (u^m, or BDF2's u*)
    std::vector<Tensor<2, 3>> old_velocity_gradient;  ///< G^m
    std::vector<Tensor<1, 3>> nodal_smooth_normal;    ///< ñ^m at the nodal points
    std::vector<Tensor<1, 3>> old_position;           ///< X^m at the Gauss points
    std::vector<Tensor<1, 3>> nodal_old_position;     ///< X^m at the nodal points
    // Law reference: ∇_{S^m}X₀ at the Gauss points, ñ^m by node, the rows of Y before their projection.
    std::vector<Tensor<2, 3>> reference_gradient;
    std::vector<Tensor<1, 3>> node_normals;
    FullMatrix<double>        normal_rows, tangential_rows;
    Vector<double>            tangential_rhs;
  };

  void
  SurfaceStep::assemble(const double tau, const RigidMotion &motion, const SurfaceGeometry::Measures &old_measures)
  {
    system_matrix = 0;
    system_rhs    = 0;
    volume_column = 0;
    for (auto &column : rigid_columns)
      column = 0;
    for (auto &row : rigid_rows)
      row = 0;
    const bool rigid = rigid_constraints();

    const SurfaceGeometry::Measures m = geometry.measure();
    // div_P u = s with s = −(A^m − A₀)/(τ_c A^m) returns any area drift (∫div_P u = dA/dt);
    // τ_c = max(τ, τ_drift) keeps the correction bounded when a rejected step shrinks τ.
    const double area_rate = -(old_measures.area - state.target_area) / (drift_time(tau) * old_measures.area);
    // The mesh moves along with the rigid motion R of the shape (fit of u^m·ν): law bgn relaxes towards
    // X^m + τR, law reference carries the nodes by the rotation itself.
    const bool        carry   = redistribution.follow_rigid_motion &&
                        (request.law == MeshRedistribution::Law::reference || redistribution.damping(tau) > 0);
    const RigidMotion carried = carry ? motion : RigidMotion();
    const double      area_scale = state.target_area / m.area;
    // The valve's relaxation solves (velocity at rest) always pull with full weight.
    if (request.velocity == StepRequest::Velocity::flow)
      candidate_membrane_pull =
        std::max(membrane_pull, redistribution.membrane_weight(old_measures.mesh_quality));
    const double membrane_weight = request.velocity == StepRequest::Velocity::flow ? candidate_membrane_pull : 1.0;

    const QGauss<2>     gauss(fe->degree + 1);
    const Quadrature<2> nodal = redistribution.nodal_quadrature(gauss, geometry.degree());

    auto worker = [&](const typename DoFHandler<2, 3>::active_cell_iterator &cell,
                      AssemblyScratch                                      &scratch,
                      LocalSystem                                          &local) {
      assemble_cell(cell, tau, area_rate, carried, area_scale, membrane_weight, scratch, local);
    };
    auto copier = [&](const LocalSystem &local) {
      constraints.distribute_local_to_global(local.matrix, local.rhs, local.indices, system_matrix, system_rhs);
      constraints.distribute_local_to_global(local.volume_column, local.indices, volume_column);
      if (rigid)
        for (unsigned int k = 0; k < 6; ++k)
          {
            constraints.distribute_local_to_global(local.rigid_columns[k], local.indices, rigid_columns[k]);
            constraints.distribute_local_to_global(local.rigid_rows[k], local.indices, rigid_rows[k]);
          }
    };

    using Iterator = typename DoFHandler<2, 3>::active_cell_iterator;
    WorkStream::run(FilteredIterator<Iterator>(IteratorFilters::LocallyOwnedCell(), dofs.begin_active()),
                    FilteredIterator<Iterator>(IteratorFilters::LocallyOwnedCell(), dofs.end()),
                    worker,
                    copier,
                    AssemblyScratch(geometry.mapping(), *fe, geometry.fe(), gauss, nodal),
                    LocalSystem());
    system_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
    volume_column.compress(VectorOperation::add);
    if (rigid)
      for (unsigned int k = 0; k < 6; ++k)
        {
          rigid_columns[k].compress(VectorOperation::add);
          rigid_rows[k].compress(VectorOperation::add);
        }
  }

  void
  SurfaceStep::assemble_cell(const typename DoFHandler<2, 3>::active_cell_iterator &cell,
                             const double                                         tau,
                             const double                                         area_rate,
                             const RigidMotion                                   &carried,
                             const double                                         area_scale,
                             const double                                         membrane_weight,
                             AssemblyScratch                                     &scratch,
                             LocalSystem                                         &local) const
  {
    const bool rigid = momentum_constraints.active();
    local.reinit(fe->n_dofs_per_cell(), rigid);
    cell->get_dof_indices(local.indices);
    const typename DoFHandler<2, 3>::active_cell_iterator geometry_cell(&geometry.triangulation(),
                                                                        cell->level(),
                                                                        cell->index(),
                                                                        &geometry.dof_handler());
    const FEValuesExtractors::Vector vector(0);
    const bool reference_law = request.law == MeshRedistribution::Law::reference;
    // Law reference: (∇_S Y, ∇_S η) only defines κ (normal rows), the membrane energy moves the nodes
    // tangentially, and both are projected at the nodes after the nodal loop.
    const Tensor<2, 3> rotation = unit_symmetric_tensor<3>(); // the carried frame: Z = X^m
    if (reference_law)
      {
        scratch.normal_rows.reinit(fe->n_dofs_per_cell(), fe->n_dofs_per_cell());
        scratch.tangential_rows.reinit(fe->n_dofs_per_cell(), fe->n_dofs_per_cell());
        scratch.tangential_rhs.reinit(fe->n_dofs_per_cell());
        scratch.node_normals.resize(layout->new_position_nodes.size());
      }

    // Gauss points: the flow terms, the bending force and scalar, (∇_S Y, ∇_S η), the global columns.
    scratch.flow.reinit(cell);
    scratch.geometry.reinit(geometry_cell);
    const VectorType &normal = assembly_normal != nullptr ? *assembly_normal : geometry.normal_field();
    scratch.geometry[vector].get_function_values(normal, scratch.smooth_normal);
    scratch.geometry[vector].get_function_gradients(normal, scratch.smooth_normal_gradient);
    scratch.flow[vector].get_function_values(*old_fields, scratch.old_velocity);
    if (lagged_field != old_fields)
      scratch.flow[vector].get_function_values(*lagged_field, scratch.transport_velocity);
    else
      scratch.transport_velocity = scratch.old_velocity;
    scratch.flow[vector].get_function_gradients(*lagged_field, scratch.old_velocity_gradient);
    scratch.geometry[vector].get_function_values(*old_position, scratch.old_position);
    if (reference_law)
      scratch.flow[FEValuesExtractors::Vector(DofLayout::new_position_component)].get_function_gradients(
        state.reference_position, scratch.reference_gradient);
    SurfacePointValues &point = scratch.point;
    for (unsigned int q = 0; q < scratch.flow.n_quadrature_points; ++q)
      {
        point.reinit(scratch.flow,
                     q,
                     scratch.smooth_normal[q],
                     scratch.smooth_normal_gradient[q],
                     scratch.old_velocity[q],
                     scratch.transport_velocity[q],
                     scratch.old_velocity_gradient[q]);
        assemble_flow_terms(point, Point<3>(scratch.old_position[q]), tau, area_rate, carried, local);
        if (request.prescribed_velocity() == nullptr)
          bending.assemble_force(point, *layout, local.matrix);
        bending.assemble_bending_scalar(point, *layout, local.matrix);
        if (reference_law)
          {
            redistribution.assemble_surface_laplacian(point, *layout, scratch.normal_rows);
            if (redistribution.conformal_tangential)
              redistribution.assemble_surface_laplacian(point, *layout, scratch.tangential_rows);
            if ((redistribution.shear_stiffness > 0 || redistribution.area_stiffness > 0) && membrane_weight > 0)
              redistribution.assemble_reference_terms(point,
                                                    scratch.reference_gradient[q],
                                                    rotation,
                                                    area_scale,
                                                    membrane_weight,
                                                    *layout,
                                                    scratch.tangential_rows,
                                                    scratch.tangential_rhs);
          }
        else
          redistribution.assemble_surface_laplacian(point, *layout, local.matrix);
        volume_constraint.assemble_column(point, *layout, local.volume_column);
        if (rigid)
          momentum_constraints.assemble_columns(point, *layout, local.rigid_columns);
        if (momentum_constraints.on_new_surface())
          momentum_constraints.assemble_new_surface_rows(point, *layout, local.rigid_rows);
      }
    // The constraint rows equal the columns in the velocity DoFs.
    if (rigid)
      for (unsigned int k = 0; k < 6; ++k)
        for (const unsigned int i : layout->velocity)
          local.rigid_rows[k](i) = local.rigid_columns[k](i);

    // Nodal points: the kinematics (κ rows) and the nodal terms of the redistribution (Y rows).
    scratch.flow_nodal.reinit(cell);
    scratch.geometry_nodal.reinit(geometry_cell);
    scratch.geometry_nodal[vector].get_function_values(normal, scratch.nodal_smooth_normal);
    scratch.geometry_nodal[vector].get_function_values(*old_position, scratch.nodal_old_position);
    NodalPointValues &nodal = scratch.nodal_point;
    for (unsigned int q = 0; q < scratch.flow_nodal.n_quadrature_points; ++q)
      {
        nodal.reinit(scratch.flow_nodal, q, scratch.nodal_smooth_normal[q]);
        const Point<3> x(scratch.nodal_old_position[q]); // X^m (the mapped point unless the geometry is iterated)
        if (reference_law)
          {
            // In the carried frame: Ỹ·ñ = X^m·ñ + τ(ũ − R)·ñ, damped towards X^m.
            redistribution.assemble_kinematics(nodal,
                                               *layout,
                                               tau,
                                               x - tau * carried.value(frame_velocity_on_new_surface ? nodal.position : x),
                                               local.matrix,
                                               local.rhs);
            redistribution.assemble_nodal_terms(nodal, *layout, tau, x, local.matrix, local.rhs);
            // The nodal rule's points are the nodes: the node whose shape function is 1 here.
            for (unsigned int n = 0; n < layout->new_position_nodes.size(); ++n)
              if (std::abs(nodal.new_position[layout->new_position_nodes[n][0]][0] - 1.0) < 1e-8)
                scratch.node_normals[n] = nodal.smooth_normal;
          }
        else
          {
            redistribution.assemble_kinematics(nodal, *layout, tau, x, local.matrix, local.rhs);
            redistribution.assemble_nodal_terms(
              nodal, *layout, tau, x + tau * carried.value(x), local.matrix, local.rhs);
          }
      }
    if (reference_law)
      MeshRedistribution::project_position_rows(scratch.node_normals,
                                                *layout,
                                                scratch.normal_rows,
                                                scratch.tangential_rows,
                                                scratch.tangential_rhs,
                                                local.matrix,
                                                local.rhs);
  }

  void
  SurfaceStep::assemble_flow_terms(const SurfacePointValues &point,
                                   const Point<3>           &old_point,
                                   const double              tau,
                                   const double              area_rate,
                                   const RigidMotion        &carried,
                                   LocalSystem              &local) const
  {
    const FlowPointValues &p       = point.flow;
    const double           dA      = p.JxW;
    const double           inv_tau = 1.0 / tau;
    if (request.prescribed_velocity() != nullptr)
      {
        // (u, v) = (u_prescribed, v) and (p, q) = 0: the L² projection of the prescribed velocity.
        // In the carried frame: Qᵀ u_prescribed at the carried point.
        const Point<3> y = carried.carry(p.position, tau);
        Tensor<1, 3>   u;
        for (unsigned int d = 0; d < 3; ++d)
          u[d] = request.prescribed_velocity()->value(y, d);
        u = transpose(carried.rotation_over(tau)) * u;
        for (const unsigned int i : layout->velocity)
          {
            local.rhs(i) += (u * p.velocity[i]) * dA;
            for (const unsigned int j : layout->velocity)
              local.matrix(i, j) += (p.velocity[i] * p.velocity[j]) * dA;
          }
        for (const unsigned int i : layout->pressure)
          for (const unsigned int j : layout->pressure)
            local.matrix(i, j) += p.pressure[i] * p.pressure[j] * dA;
        return;
      }
    // The mass term: the inertia (1/τ)(u, v), or the Stokes limit's regularization ε(u, v).
    const double mass = flow.inertia ? inv_tau : momentum_constraints.regularization();
    // Law reference solves the step in the frame carried by the rigid motion R of the shape (ũ = Qᵀu, the new
    // position relative to the carry; advance() maps back): the frame's rotation adds (Ω × ũ, v), and the mesh
    // velocity in the convection is R + (Ỹ − X^m)/τ, i.e. W = X^m − τR.
    const bool     carried_frame = request.law == MeshRedistribution::Law::reference;
    const Point<3> frame_point   = frame_velocity_on_new_surface ? p.position : old_point;
    const Point<3> start         = carried_frame ? old_point - tau * carried.value(frame_point) : old_point;
    for (const unsigned int i : layout->velocity)
      {
        if (flow.inertia)
          local.rhs(i) += SurfaceFluid::mass_term_rhs(p, i, inv_tau) * dA;
        if (flow.convection)
          local.rhs(i) += SurfaceFluid::mesh_motion_term_rhs(p, i, inv_tau, start) * dA;
        for (const unsigned int j : layout->velocity)
          {
            double a = flow.viscous_term(p, i, j);
            a += SurfaceFluid::mass_term(p, i, j, mass);
            if (carried_frame && flow.inertia)
              a += SurfaceFluid::frame_rotation_term(p, i, j, carried.rotation);
            // (∇_w u, v) with w = u^m, consistent (not skew-symmetrized; doc/scheme.md).
            if (flow.convection)
              a += SurfaceFluid::convection_term(p, i, j);
            local.matrix(i, j) += a * dA;
          }
        for (const unsigned int j : layout->pressure)
          local.matrix(i, j) += SurfaceFluid::pressure_term(p, i, j) * dA;
        if (flow.convection)
          for (const unsigned int j : layout->new_position)
            local.matrix(i, j) += SurfaceFluid::mesh_motion_term(p, i, point.new_position[j], inv_tau) * dA;
      }
    for (const unsigned int i : layout->pressure)
      {
        local.rhs(i) += SurfaceFluid::continuity_term_rhs(p, i, area_rate) * dA;
        for (const unsigned int j : layout->velocity)
          local.matrix(i, j) += SurfaceFluid::continuity_term(p, i, j) * dA;
      }
  }

  ReusedFactorizationSolver::Result
  SurfaceStep::solve_system(const BorderedSystem              &system,
                            BorderedSystem::BlockVector       &x,
                            const BorderedSystem::BlockVector &b)
  {
    ReusedFactorizationSolver &solver = request.solver == StepRequest::Solver::fresh_klu ? valve_solver : linear_solver;
    solver.matrix_changed(); // every step assembles its matrix on the new surface
    BorderedFactorizationPreconditioner     preconditioner(system);
    const ReusedFactorizationSolver::Result result = solver.solve(system_matrix, system, x, b, preconditioner);
    preconditioner.enforce_constraints(x, BorderedSystem::multipliers(b)); // a few vector operations, not timed
    return result;
  }

  SurfaceStep::Result
  SurfaceStep::advance(const StepRequest &step_request, const double tau)
  {
    request = step_request;
    Result result;
    // X^m: the accepted state's surface; the valve's solves move the geometry itself between them.
    old_position  = request.velocity == StepRequest::Velocity::flow ? &state.position : &geometry.position();
    old_fields    = &state.solution;
    frame_velocity_on_new_surface = false;
    lagged_field  = &state.solution;
    // The momenta of u^m and the rigid motion of the shape, once per step (the mesh damping target and the
    // constant parts of the momentum constraints).
    const bool need_motion =
      (redistribution.follow_rigid_motion &&
       (redistribution.relaxation_time > 0 || request.law == MeshRedistribution::Law::reference)) ||
      (rigid_constraints() && flow.inertia);
    const RigidMotion motion      = need_motion ? rigid_motion(state.solution) : RigidMotion();
    // Law reference solves the step in the frame carried by the rigid motion of the shape (assemble_cell()).
    const bool carried_frame = request.law == MeshRedistribution::Law::reference &&
                               redistribution.follow_rigid_motion;
    // BDF2 (after a first backward-Euler step): the backward-Euler form of size τ/α₀ from x̂ (prepare_bdf2_start()).
    const bool bdf2_step = bdf2 && previous_step > 0 && request.velocity == StepRequest::Velocity::flow &&
                           request.global_constraints;
    double     tau_solve = tau;
    if (bdf2_step)
      {
        prepare_bdf2_start(motion, carried_frame, tau);
        const double omega = tau / previous_step;
        tau_solve          = tau * (1 + omega) / (1 + 2 * omega);
        old_position       = &start_position;
        frame_velocity_on_new_surface = true;
        old_fields         = &start_fields;
        lagged_field       = &lagged_fields;
      }
    const SurfaceGeometry::Measures old_measures = geometry.measure();
    shape_radius                                 = std::sqrt(old_measures.area / (4 * numbers::PI));
    const VectorType                old_normal(geometry.normal_field()); // ñ^m (the geometry may be iterated)
    {
      TimerSection section(step_timer, "assembly");
      assemble(tau_solve, motion, old_measures);
    }

    // Bordering: the global constraints c_k·x = g_k with multipliers μ_k (force μ_k c_k in the
    // momentum rows): the volume row (u·ñ, 1) = −(V^m − V₀)/τ_c (μ = γ) and, in the Stokes limit,
    // ∫u = 0, ∫x × u = 0; one solve of the bordered system per step (BorderedSystem).
    std::vector<const VectorType *> columns, rows;
    std::vector<double>             rates;
    // The mesh relaxation of reparametrize() moves no surface: none of the global constraints.
    const bool volume_row = volume_constraint.enabled && request.global_constraints;
    const bool rigid_rows_on = rigid_constraints() && request.global_constraints;
    if (volume_row)
      {
        columns.push_back(&volume_column);
        rows.push_back(&volume_column);
        rates.push_back(-(old_measures.volume - state.target_volume) / drift_time(tau_solve));
      }
    // The momentum targets in the frame of the step (the constant parts of the rows are added by set_rates()).
    std::array<double, 6> targets = {{0, 0, 0, 0, 0, 0}};
    if (rigid_rows_on)
      {
        // The constant parts of the linearized momenta on S^{m+1} (see assemble()) move to the right:
        // with δ = Y − X^m and div_S X^m = 2 they are −2∫u^m and −3∫x × u^m.
        // A drift P^m − P₀ (from the linearization) is returned by the fraction τ/τ_c per step, like the area
        // and volume drifts, so that a retry with a smaller τ asks for a smaller change of u.
        const std::array<double, 6> old_momenta =
          flow.inertia ? motion.momenta : std::array<double, 6>{{0, 0, 0, 0, 0, 0}};
        const double fraction = flow.inertia ? std::min(1.0, tau / drift_time(tau)) : 1.0;
        for (unsigned int k = 0; k < 6; ++k)
          targets[k] = old_momenta[k] + fraction * (state.rigid_targets[k] - old_momenta[k]);
        if (carried_frame)
          {
            // In the carried frame (Y = QỸ + c, u = Qũ): P̃ = QᵀP, L̃ = Qᵀ(L − c × P).
            const Tensor<2, 3> Q = motion.rotation_over(tau);
            const Tensor<1, 3> c = motion.carry(Point<3>(), tau);
            Tensor<1, 3>       P, L;
            for (unsigned int d = 0; d < 3; ++d)
              {
                P[d] = targets[d];
                L[d] = targets[3 + d];
              }
            const Tensor<1, 3> P_frame = transpose(Q) * P, L_frame = transpose(Q) * (L - cross_product_3d(c, P));
            for (unsigned int d = 0; d < 3; ++d)
              {
                targets[d]     = P_frame[d];
                targets[3 + d] = L_frame[d];
              }
          }
        for (unsigned int k = 0; k < rigid_columns.size(); ++k)
          {
            columns.push_back(&rigid_columns[k]);
            rows.push_back(&rigid_rows[k]);
          }
      }
    const unsigned int first_rigid = volume_row ? 1 : 0;
    // The rows are linearized about the surface they were assembled on: their constant parts are the momenta
    // of u^m there (@p assembly_momenta).
    const auto set_rates = [&](const std::array<double, 6> &assembly_momenta) {
      rates.resize(first_rigid);
      if (rigid_rows_on)
        for (unsigned int k = 0; k < 6; ++k)
          rates.push_back(targets[k] + (k < 3 ? 2.0 : 3.0) * (flow.inertia ? assembly_momenta[k] : 0.0));
    };
    set_rates(motion.momenta);

    AssertDimension(columns.size(), (volume_row ? 1 : 0) + (rigid_rows_on ? 6 : 0));
    AssertDimension(rates.size(), columns.size());
    const BorderedSystem system(system_matrix, columns, rows);
    BorderedSystem::BlockVector solution = system.make_vector(system_rhs), rhs = solution;
    if (last_solution.n_blocks() == 2 && last_solution.block(1).size() == columns.size())
      solution = last_solution;
    const auto solve = [&]() {
      rhs.block(0) = system_rhs;
      BorderedSystem::set_multipliers(rhs, rates);
      try
        {
          const ReusedFactorizationSolver::Result solve = solve_system(system, solution, rhs);
          result.linear_iterations += solve.iterations;
          result.factorized = result.factorized || solve.factorized;
          last_solution     = solution;
          const std::vector<double> mu = BorderedSystem::multipliers(solution);
          if (volume_row)
            result.gamma = mu[0];
          double rigid = 0;
          for (unsigned int k = first_rigid; k < mu.size(); ++k)
            rigid += mu[k] * mu[k];
          result.rigid_force = std::sqrt(rigid);
        }
      catch (const LinearSolverError &exc)
        {
          linear_solver.request_factorization();
          result.failure         = std::string("linear solver failed: ") + exc.what();
          result.failure_details = exc.details();
          return false;
        }
      catch (const std::exception &exc)
        {
          linear_solver.request_factorization();
          result.failure         = "linear solver failed: " + one_line_message(exc, 200);
          result.failure_details = exc.what();
          return false;
        }
      if (!std::isfinite(solution.block(0).l2_norm()))
        {
          result.failure = "the solution is not finite";
          return false;
        }
      constraints.distribute(solution.block(0));
      return true;
    };
    if (!solve())
      return result;

    // The implicit geometry: the same step assembled again on the surface of its own solution (in the frame of
    // the step, before the carry), until the nodes stop moving.
    if (iterating_geometry() && request.prescribed_velocity() == nullptr && request.global_constraints)
      {
        const double node_spacing =
          std::sqrt(old_measures.area / geometry.triangulation().n_global_active_cells()) / geometry.degree();
        using Implicit            = GeometryIteration::Implicit;
        const Implicit   implicit = geometry_iteration.implicit;
        VectorType       iterate_normal;
        bool             converged = false;
        // The surface Ỹ_k the step is assembled on; the next one from Ỹ_k and G(Ỹ_k), the solve's new position.
        VectorType             surface = solution.block(0);
        FixedPointAcceleration acceleration(geometry_iteration,
                                            [this](const VectorType &a, const VectorType &b) { return position_dot(a, b); });
        for (unsigned int k = 1; k <= geometry_iteration.max_iterations && !converged; ++k)
          {
            candidate_solution = surface;
            copy_new_position_to_geometry(candidate_solution);
            if (geometry_iteration.time_level < 1)
              {
                // S^{m+θ}: X^m + θ (Ỹ_k − X^m)
                VectorType level(geometry.locally_owned_dofs(), geometry.get_communicator()),
                  old(geometry.locally_owned_dofs(), geometry.get_communicator());
                level = geometry.position();
                old   = *old_position;
                level.sadd(geometry_iteration.time_level, 1 - geometry_iteration.time_level, old);
                geometry.set_position(level);
              }
            {
              TimerSection section(step_timer, "assembly");
              geometry.compute_curvature();
              if (implicit == Implicit::normal)
                {
                  iterate_normal = geometry.normal_field();
                  assembly_normal = &iterate_normal;
                  restore_old_geometry();
                }
              else if (implicit == Implicit::metric)
                assembly_normal = &old_normal;
              assemble(tau_solve, motion, old_measures);
              assembly_normal = nullptr;
              if (rigid_rows_on && flow.inertia && implicit != Implicit::normal)
                set_rates(rigid_motion(state.solution).momenta);
            }
            if (!solve())
              return result;
            result.geometry_iterations = k;
            result.geometry_change     = largest_node_move(solution.block(0), surface) / node_spacing;
            converged                  = geometry_iteration.converged(k, result.geometry_change);
            if (!converged)
              acceleration.advance(surface, solution.block(0));
          }
        if (!converged)
          {
            std::ostringstream why;
            why << "the geometry iteration did not converge: after " << geometry_iteration.max_iterations
                << " re-assemblies the nodes still moved by " << std::setprecision(3) << result.geometry_change
                << " h (tolerance 'geometry iteration/tolerance' = " << geometry_iteration.tolerance << ")";
            result.failure = why.str();
            return result;
          }
      }
    VectorType &x1 = solution.block(0);
    if (estimating_error && request.velocity == StepRequest::Velocity::flow)
      result.error_estimate = estimate_error(x1, old_normal, tau);
    candidate_solution = x1;
    {
      TimerSection section(step_timer, "diagnostics");
      result.dissipation_rate = dissipation_rate(candidate_solution); // of ũ on S^m, that of u on the carried surface
    }
    if (carried_frame)
      {
        carry_fields(motion, tau, x1); // out of the carried frame: u = Qũ, Y = carry(Ỹ)
        candidate_solution = x1;
      }
    copy_new_position_to_geometry(candidate_solution);
    if (conservation.enabled && request.prescribed_velocity() == nullptr)
      {
        result.node_correction =
          conservation.project_area_and_volume(geometry, state.target_area, state.target_volume, volume_constraint.enabled);
        VectorType projected(owned, geometry.get_communicator());
        projected = candidate_solution;
        copy_position_into(geometry.position(), projected);
        if (flow.conserve_momenta && flow.inertia)
          result.momentum_correction = conservation.project_momenta(geometry, dofs, state.rigid_targets, projected);
        candidate_solution = projected;
      }
    last_tau = tau;
    result.solved = true;
    return result;
  }

  double
  SurfaceStep::kinetic_energy(const VectorType &flow_vector) const
  {
    return EnergyFunctionals::kinetic_energy(
      geometry.mapping(), dofs, flow_vector, geometry.quadrature(), geometry.get_communicator());
  }

  double
  SurfaceStep::dissipation_rate(const VectorType &flow_vector) const
  {
    return EnergyFunctionals::dissipation_rate(
      geometry.mapping(), dofs, flow_vector, geometry.quadrature(), flow.Re, geometry.get_communicator());
  }
} // namespace FluidSurface
