// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/geometry/surface_operators.h>
#include <fluid_surface/model/dof_layout.h>
#include <fluid_surface/model/surface_point_values.h>

namespace FluidSurface
{
  using namespace dealii;

  SurfacePointValues::SurfacePointValues(const unsigned int dofs_per_cell)
    : flow(dofs_per_cell)
    , bending_coefficient(0)
    , curvature(dofs_per_cell)
    , curvature_gradient(dofs_per_cell)
    , bending_scalar(dofs_per_cell)
    , bending_scalar_gradient(dofs_per_cell)
    , new_position(dofs_per_cell)
    , new_position_gradient(dofs_per_cell)
  {}

  void
  SurfacePointValues::reinit(const FEValues<2, 3> &fe_values,
                             const unsigned int    q,
                             const Tensor<1, 3>   &smooth_normal,
                             const Tensor<2, 3>   &smooth_normal_gradient,
                             const Tensor<1, 3>   &old_velocity,
                             const Tensor<1, 3>   &transport_velocity,
                             const Tensor<2, 3>   &old_velocity_gradient)
  {
    flow.reinit(fe_values, q);
    flow.old_velocity          = old_velocity;
    flow.transport_velocity    = transport_velocity;
    flow.old_velocity_gradient = old_velocity_gradient;
    this->smooth_normal        = smooth_normal;
    // The lagged shape operator B = −P∇ñ and c = |B|² − ½H² (vanishes on spheres).
    const Tensor<2, 3> P = SurfaceOperators::projection(flow.normal);
    const Tensor<2, 3> B = -P * smooth_normal_gradient;
    const double       H = trace(B);
    bending_coefficient  = scalar_product(B, B) - 0.5 * H * H;

    const FEValuesExtractors::Scalar curvature_part(DofLayout::curvature_component);
    const FEValuesExtractors::Scalar bending_part(DofLayout::bending_component);
    const FEValuesExtractors::Vector position_part(DofLayout::new_position_component);
    for (unsigned int i = 0; i < curvature.size(); ++i)
      {
        curvature[i]               = fe_values[curvature_part].value(i, q);
        curvature_gradient[i]      = fe_values[curvature_part].gradient(i, q);
        bending_scalar[i]          = fe_values[bending_part].value(i, q);
        bending_scalar_gradient[i] = fe_values[bending_part].gradient(i, q);
        new_position[i]            = fe_values[position_part].value(i, q);
        new_position_gradient[i]   = fe_values[position_part].gradient(i, q);
      }
  }
} // namespace FluidSurface
