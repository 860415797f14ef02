// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/model/dof_layout.h>

namespace FluidSurface
{
  using namespace dealii;

  DofLayout::DofLayout(const FiniteElement<2, 3> &fe)
  {
    AssertDimension(fe.n_components(), n_components);
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const unsigned int c = fe.system_to_component_index(i).first;
        if (c < pressure_component)
          {
            velocity.push_back(i);
            velocity_direction.push_back(c - velocity_component);
          }
        else if (c == pressure_component)
          pressure.push_back(i);
        else if (c == curvature_component)
          curvature.push_back(i);
        else if (c == bending_component)
          bending_scalar.push_back(i);
        else
          {
            new_position.push_back(i);
            const unsigned int node = fe.system_to_component_index(i).second;
            if (node >= new_position_nodes.size())
              new_position_nodes.resize(node + 1);
            new_position_nodes[node][c - new_position_component] = i;
          }
      }
    // u, p are Taylor–Hood [Q2]³ × Q1; κ, y, Y share the degree k of the geometry.
    Assert(fe.base_element(fe.component_to_base_index(velocity_component).first).degree == 2, ExcInternalError());
    Assert(fe.base_element(fe.component_to_base_index(pressure_component).first).degree == 1, ExcInternalError());
    AssertDimension(velocity.size(), 3 * fe.base_element(fe.component_to_base_index(0).first).n_dofs_per_cell());
    AssertDimension(new_position.size(), 3 * curvature.size());
    AssertDimension(bending_scalar.size(), curvature.size());
    AssertDimension(new_position_nodes.size(), curvature.size());
    (void)fe;
  }
} // namespace FluidSurface
