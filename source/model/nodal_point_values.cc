// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/model/dof_layout.h>
#include <fluid_surface/model/nodal_point_values.h>

namespace FluidSurface
{
  using namespace dealii;

  NodalPointValues::NodalPointValues(const unsigned int dofs_per_cell)
    : velocity(dofs_per_cell)
    , curvature(dofs_per_cell)
    , new_position(dofs_per_cell)
  {}

  void
  NodalPointValues::reinit(const FEValues<2, 3> &fe_values, const unsigned int q, const Tensor<1, 3> &smooth_normal)
  {
    const FEValuesExtractors::Vector velocity_part(DofLayout::velocity_component);
    const FEValuesExtractors::Scalar curvature_part(DofLayout::curvature_component);
    const FEValuesExtractors::Vector position_part(DofLayout::new_position_component);
    JxW                 = fe_values.JxW(q);
    position            = fe_values.quadrature_point(q);
    this->smooth_normal = smooth_normal;
    for (unsigned int i = 0; i < velocity.size(); ++i)
      {
        velocity[i]     = fe_values[velocity_part].value(i, q);
        curvature[i]    = fe_values[curvature_part].value(i, q);
        new_position[i] = fe_values[position_part].value(i, q);
      }
  }
} // namespace FluidSurface
