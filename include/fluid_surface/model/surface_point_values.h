// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_surface_point_values_h
#define fluid_surface_model_surface_point_values_h

#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_values.h>

#include <fluid_surface/flow/flow_point_values.h>

#include <vector>

namespace FluidSurface
{
  /**
   * The data of the terms of scene full at one Gauss point of a cell of S^m: the flow part (FlowPointValues),
   * the lagged geometry (ñ^m and the bending coefficient c^m), and the curvature, bending-scalar and
   * new-position parts of every shape function (DofLayout's components), evaluated once per point.
   */
  struct SurfacePointValues
  {
    /// Room for the shape functions of a cell with @p dofs_per_cell DoFs.
    explicit SurfacePointValues(const unsigned int dofs_per_cell);

    /**
     * Evaluates point @p q of @p fe_values (the flow element on S^m), with the continuous normal ñ^m, its
     * gradient ∇ñ^m, the old velocity u^m of the inertia, the transport velocity w of the convection and the
     * lagged gradient G^m at the point (backward Euler: w = u^m and G^m = ∇u^m; BDF2: û of the step's start and
     * w, G from the extrapolation u*).
     */
    void
    reinit(const dealii::FEValues<2, 3> &fe_values,
           const unsigned int            q,
           const dealii::Tensor<1, 3>   &smooth_normal,
           const dealii::Tensor<2, 3>   &smooth_normal_gradient,
           const dealii::Tensor<1, 3>   &old_velocity,
           const dealii::Tensor<1, 3>   &transport_velocity,
           const dealii::Tensor<2, 3>   &old_velocity_gradient);

    FlowPointValues flow; ///< x, JxW, ν, u^m, G^m and the velocity and pressure shape functions

    dealii::Tensor<1, 3> smooth_normal;       ///< ñ^m
    double               bending_coefficient; ///< c^m = |B^m|² − ½(H^m)², B^m = −P∇ñ^m, H^m = tr B^m

    std::vector<double>               curvature;               ///< φ_i of κ
    std::vector<dealii::Tensor<1, 3>> curvature_gradient;      ///< ∇_S φ_i of κ
    std::vector<double>               bending_scalar;          ///< φ_i of y
    std::vector<dealii::Tensor<1, 3>> bending_scalar_gradient; ///< ∇_S φ_i of y
    std::vector<dealii::Tensor<1, 3>> new_position;            ///< η_i of Y
    std::vector<dealii::Tensor<2, 3>> new_position_gradient;   ///< ∇_S η_i of Y
  };
} // namespace FluidSurface

#endif
