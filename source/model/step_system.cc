// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/model/local_system.h>
#include <fluid_surface/model/rigid_motion.h>
#include <fluid_surface/model/step_system.h>

#include <cmath>
#include <map>

namespace FluidSurface
{
  using namespace dealii;

  StepSystem::StepSystem(SurfaceGeometry &geometry)
    : surface(geometry)
    , dofs(geometry.triangulation())
  {}

  void
  StepSystem::setup_system()
  {
    const unsigned int k = surface.degree();
    element    = std::make_unique<FESystem<2, 3>>(FE_Q<2, 3>(2), 3, FE_Q<2, 3>(1), 1, FE_Q<2, 3>(k), 1,
                                               FE_Q<2, 3>(k), 1, FE_Q<2, 3>(k), 3);
    dof_layout = std::make_unique<const DofLayout>(*element);
    dofs.distribute_dofs(*element);
    owned = dofs.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    hanging_nodes.clear();
    hanging_nodes.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dofs, hanging_nodes);
    hanging_nodes.close();

    Table<2, DoFTools::Coupling> coupling(DofLayout::n_components, DofLayout::n_components);
    for (unsigned int row = 0; row < DofLayout::n_components; ++row)
      for (unsigned int column = 0; column < DofLayout::n_components; ++column)
        coupling(row, column) = couples(row, column) ? DoFTools::always : DoFTools::none;
    const unsigned int n_local = element->n_dofs_per_cell();
    local_coupling.assign(n_local, std::vector<bool>(n_local));
    for (unsigned int i = 0; i < n_local; ++i)
      for (unsigned int j = 0; j < n_local; ++j)
        local_coupling[i][j] =
          couples(element->system_to_component_index(i).first, element->system_to_component_index(j).first);
    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(dofs, coupling, dsp, hanging_nodes, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, surface.get_communicator(), relevant);
    system_matrix.reinit(owned, owned, dsp, surface.get_communicator());
    system_rhs.reinit(owned, surface.get_communicator());
    volume.reinit(owned, surface.get_communicator());
    for (auto &column : rigid_motion_columns)
      column.reinit(owned, surface.get_communicator());
    for (auto &row : rigid_motion_rows)
      row.reinit(owned, surface.get_communicator());
    list_nodes();
    pair_position_dofs();
  }

  VectorType
  StepSystem::owned_vector() const
  {
    return VectorType(owned, surface.get_communicator());
  }

  VectorType
  StepSystem::ghosted_vector() const
  {
    return VectorType(owned, relevant, surface.get_communicator());
  }

  VectorType
  StepSystem::read_field(const CheckpointData &data, const std::string &name) const
  {
    VectorType x;
    data.get_fields(name, dofs, {&x});
    VectorType field = ghosted_vector();
    field            = x;
    return field;
  }

  void
  StepSystem::zero()
  {
    coupling_checked = false;
    system_matrix    = 0;
    system_rhs    = 0;
    volume        = 0;
    for (auto &column : rigid_motion_columns)
      column = 0;
    for (auto &row : rigid_motion_rows)
      row = 0;
  }

  bool
  StepSystem::couples(const unsigned int row, const unsigned int column)
  {
    using L            = DofLayout;
    const auto unknown = [](const unsigned int component) {
      return component < L::pressure_component ? L::velocity_component :
             component < L::new_position_component ? component : L::new_position_component;
    };
    const unsigned int r = unknown(row), c = unknown(column);
    switch (r)
      {
        case L::velocity_component:
          return c != L::curvature_component;
        case L::pressure_component:
          return c == L::velocity_component || c == L::pressure_component;
        case L::curvature_component:
          return c == L::velocity_component || c == L::new_position_component;
        case L::bending_component:
          return c == L::bending_component || c == L::curvature_component;
        default:
          return c == L::new_position_component || c == L::curvature_component;
      }
  }

  void
  StepSystem::distribute_local_to_global(const LocalSystem &local, const bool rigid)
  {
    // The terms are the same on every cell: in a Release build the first cell of an assembly is checked.
    bool check = !coupling_checked;
#ifdef DEBUG
    check = true;
#endif
    coupling_checked = true;
    for (unsigned int i = 0; check && i < local.matrix.m(); ++i)
      for (unsigned int j = 0; j < local.matrix.n(); ++j)
        AssertThrow(local_coupling[i][j] || local.matrix(i, j) == 0,
                    ExcMessage("The step's local matrix couples components " +
                               std::to_string(element->system_to_component_index(i).first) + " and " +
                               std::to_string(element->system_to_component_index(j).first) +
                               ", which StepSystem::couples() leaves out of the sparsity pattern."));
    hanging_nodes.distribute_local_to_global(local.matrix, local.rhs, local.indices, system_matrix, system_rhs);
    hanging_nodes.distribute_local_to_global(local.volume_column, local.indices, volume);
    if (rigid)
      for (unsigned int k = 0; k < 6; ++k)
        {
          hanging_nodes.distribute_local_to_global(local.rigid_columns[k], local.indices, rigid_motion_columns[k]);
          hanging_nodes.distribute_local_to_global(local.rigid_rows[k], local.indices, rigid_motion_rows[k]);
        }
  }

  void
  StepSystem::compress(const bool rigid)
  {
    system_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
    volume.compress(VectorOperation::add);
    if (rigid)
      for (unsigned int k = 0; k < 6; ++k)
        {
          rigid_motion_columns[k].compress(VectorOperation::add);
          rigid_motion_rows[k].compress(VectorOperation::add);
        }
  }

  void
  StepSystem::list_nodes()
  {
    velocity_nodes.clear();
    position_nodes.clear();
    const FiniteElement<2, 3>           &fe = *element;
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    std::vector<bool>                    listed(owned.n_elements(), false);
    const auto first_listing = [&](const types::global_dof_index i) {
      if (!owned.is_element(i) || listed[owned.index_within_set(i)])
        return false;
      listed[owned.index_within_set(i)] = true;
      return true;
    };
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(indices);
          for (const unsigned int i : dof_layout->velocity)
            if (fe.system_to_component_index(i).first == DofLayout::velocity_component && first_listing(indices[i]))
              {
                Node node;
                for (const unsigned int j : dof_layout->velocity)
                  if (fe.system_to_component_index(j).second == fe.system_to_component_index(i).second)
                    node[fe.system_to_component_index(j).first - DofLayout::velocity_component] = indices[j];
                velocity_nodes.push_back(node);
              }
          for (const auto &rows : dof_layout->new_position_nodes)
            if (first_listing(indices[rows[0]]))
              position_nodes.push_back({{indices[rows[0]], indices[rows[1]], indices[rows[2]]}});
        }
  }

  void
  StepSystem::pair_position_dofs()
  {
    position_pairs.clear();
    const FiniteElement<2, 3>           &fe  = *element;
    const FiniteElement<2, 3>           &gfe = surface.fe();
    const IndexSet                      &geometry_owned = surface.locally_owned_dofs();
    std::vector<types::global_dof_index> flow_indices(fe.n_dofs_per_cell()), geo_indices(gfe.n_dofs_per_cell());
    std::vector<bool>                    seen(geometry_owned.n_elements(), false);
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(flow_indices);
          typename DoFHandler<2, 3>::active_cell_iterator geo_cell(&surface.triangulation(),
                                                                   cell->level(),
                                                                   cell->index(),
                                                                   &surface.dof_handler());
          geo_cell->get_dof_indices(geo_indices);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const auto ci = fe.system_to_component_index(i);
              if (ci.first < DofLayout::new_position_component)
                continue;
              for (unsigned int j = 0; j < gfe.n_dofs_per_cell(); ++j)
                {
                  const auto cj = gfe.system_to_component_index(j);
                  if (cj.first + DofLayout::new_position_component == ci.first && cj.second == ci.second &&
                      geometry_owned.is_element(geo_indices[j]))
                    {
                      const auto local = geometry_owned.index_within_set(geo_indices[j]);
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
    position_geometry_dofs.clear();
    for (const auto &node : position_nodes)
      {
        Node geo;
        for (unsigned int d = 0; d < 3; ++d)
          {
            const auto found = geometry_dof.find(node[d]);
            AssertThrow(found != geometry_dof.end(), ExcMessage("a node of Y without its position DoF"));
            geo[d] = found->second;
          }
        position_geometry_dofs.push_back(geo);
      }
  }

  void
  StepSystem::copy_new_position_to_geometry(const VectorType &flow_vector) const
  {
    surface.set_position(new_position(flow_vector));
  }

  VectorType
  StepSystem::new_position(const VectorType &flow_vector) const
  {
    VectorType position(surface.locally_owned_dofs(), surface.get_communicator());
    for (const auto &pair : position_pairs)
      position[pair.second] = flow_vector[pair.first];
    position.compress(VectorOperation::insert);
    return position;
  }

  void
  StepSystem::copy_position_into(const VectorType &x, VectorType &flow_vector) const
  {
    for (const auto &pair : position_pairs)
      flow_vector[pair.first] = x[pair.second];
    flow_vector.compress(VectorOperation::insert);
  }

  void
  StepSystem::add_normal_part(const VectorType &difference, const VectorType &normal, VectorType &flow_vector) const
  {
    for (unsigned int n = 0; n < position_nodes.size(); ++n)
      {
        const Node  &node = position_nodes[n];
        Tensor<1, 3> nu;
        double       along = 0;
        for (unsigned int d = 0; d < 3; ++d)
          {
            nu[d] = normal[position_geometry_dofs[n][d]];
            along += difference[node[d]] * nu[d];
          }
        for (unsigned int d = 0; d < 3; ++d)
          flow_vector[node[d]] += along * nu[d];
      }
    flow_vector.compress(VectorOperation::add);
  }

  double
  StepSystem::position_dot(const VectorType &a, const VectorType &b) const
  {
    double sum = 0;
    for (const auto &node : position_nodes)
      for (unsigned int d = 0; d < 3; ++d)
        sum += a[node[d]] * b[node[d]];
    return Utilities::MPI::sum(sum, surface.get_communicator());
  }

  double
  StepSystem::largest_node_move(const VectorType &a, const VectorType &b) const
  {
    double largest = 0;
    for (const auto &node : position_nodes)
      {
        double square = 0;
        for (unsigned int d = 0; d < 3; ++d)
          square += (a[node[d]] - b[node[d]]) * (a[node[d]] - b[node[d]]);
        largest = std::max(largest, square);
      }
    return std::sqrt(Utilities::MPI::max(largest, surface.get_communicator()));
  }

  void
  StepSystem::turn_nodes(const std::vector<Node> &nodes, const Tensor<2, 3> &rotation, VectorType &v)
  {
    for (const auto &node : nodes)
      {
        Tensor<1, 3> x;
        for (unsigned int d = 0; d < 3; ++d)
          x[d] = v[node[d]];
        x = rotation * x;
        for (unsigned int d = 0; d < 3; ++d)
          v[node[d]] = x[d];
      }
  }

  void
  StepSystem::rotate_vector_unknowns(const Tensor<2, 3> &rotation, VectorType &v) const
  {
    turn_nodes(velocity_nodes, rotation, v);
    turn_nodes(position_nodes, rotation, v);
    v.compress(VectorOperation::insert);
  }

  void
  StepSystem::carry_fields(const RigidMotion &carried, const double tau, VectorType &solution) const
  {
    turn_nodes(velocity_nodes, carried.rotation_over(tau), solution);
    for (const auto &node : position_nodes)
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
} // namespace FluidSurface
