// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/model/momentum_constraints.h>

namespace FluidSurface
{
  using namespace dealii;

  MomentumConstraints::MomentumConstraints(const SurfaceFluid &fluid)
    : stokes_limit(!fluid.inertia)
    , conserve_momenta(fluid.conserve_momenta)
    , rigid_motion_regularization(fluid.rigid_motion_regularization)
  {}

  void
  MomentumConstraints::assemble_columns(const SurfacePointValues     &point,
                                        const DofLayout              &dofs,
                                        std::array<Vector<double>, 6> &columns) const
  {
    const double    dA = point.flow.JxW;
    const Point<3> &x  = point.flow.position;
    for (const unsigned int i : dofs.velocity)
      {
        const Tensor<1, 3> &phi = point.flow.velocity[i];
        for (unsigned int d = 0; d < 3; ++d)
          {
            columns[d](i) += phi[d] * dA;
            columns[3 + d](i) += (cross_product_3d(Tensor<1, 3>(Point<3>::unit_vector(d)), x) * phi) * dA;
          }
      }
  }

  void
  MomentumConstraints::assemble_new_surface_rows(const SurfacePointValues     &point,
                                                 const DofLayout              &dofs,
                                                 std::array<Vector<double>, 6> &rows) const
  {
    const double        dA    = point.flow.JxW;
    const Tensor<1, 3> &u_old = point.flow.old_velocity;
    const Tensor<1, 3>  L_old = cross_product_3d(point.flow.position, u_old);
    for (const unsigned int i : dofs.new_position)
      {
        const double       div_Y = trace(point.new_position_gradient[i]);
        const Tensor<1, 3> Y_u   = cross_product_3d(point.new_position[i], u_old);
        for (unsigned int d = 0; d < 3; ++d)
          {
            rows[d](i) += u_old[d] * div_Y * dA;
            rows[3 + d](i) += (Y_u[d] + L_old[d] * div_Y) * dA;
          }
      }
  }
} // namespace FluidSurface
