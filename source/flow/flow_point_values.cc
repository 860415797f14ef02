// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/flow/flow_point_values.h>
#include <fluid_surface/geometry/surface_operators.h>

namespace FluidSurface
{
  using namespace dealii;

  FlowPointValues::FlowPointValues(const unsigned int dofs_per_cell)
    : velocity(dofs_per_cell)
    , velocity_gradient(dofs_per_cell)
    , strain_rate(dofs_per_cell)
    , divergence(dofs_per_cell)
    , pressure(dofs_per_cell)
  {}

  void
  FlowPointValues::reinit(const FEValues<2, 3> &fe_values, const unsigned int q)
  {
    AssertDimension(velocity.size(), fe_values.get_fe().n_dofs_per_cell());
    Assert(fe_values.get_fe().n_components() >= 4, ExcMessage("velocity in components 0–2, pressure in 3"));
    const FEValuesExtractors::Vector velocity_part(0);
    const FEValuesExtractors::Scalar pressure_part(3);
    JxW      = fe_values.JxW(q);
    position = fe_values.quadrature_point(q);
    normal   = fe_values.normal_vector(q);
    for (unsigned int i = 0; i < velocity.size(); ++i)
      {
        velocity[i]          = fe_values[velocity_part].value(i, q);
        velocity_gradient[i] = fe_values[velocity_part].gradient(i, q);
        divergence[i]        = SurfaceOperators::surface_divergence(velocity_gradient[i]);
        strain_rate[i]       = SurfaceOperators::strain_rate(velocity_gradient[i], normal);
        pressure[i]          = fe_values[pressure_part].value(i, q);
      }
  }
} // namespace FluidSurface
