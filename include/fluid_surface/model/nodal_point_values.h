// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_nodal_point_values_h
#define fluid_surface_model_nodal_point_values_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_values.h>

#include <vector>

namespace FluidSurface
{
  /**
   * The data of the nodal terms (·,·)_h of scene full (kinematics and mesh redistribution) at one point of
   * the nodal quadrature (Gauss–Lobatto with `mesh redistribution/lumped`, else Gauss): the point, its
   * weight, ñ^m, and the velocity, curvature and new-position parts of every shape function.
   */
  struct NodalPointValues
  {
    /// Room for the shape functions of a cell with @p dofs_per_cell DoFs.
    explicit NodalPointValues(const unsigned int dofs_per_cell);

    /// Evaluates point @p q of @p fe_values (the flow element, nodal quadrature) with ñ^m = @p smooth_normal.
    void
    reinit(const dealii::FEValues<2, 3> &fe_values, const unsigned int q, const dealii::Tensor<1, 3> &smooth_normal);

    double               JxW = 0;       ///< quadrature weight times the surface element
    dealii::Point<3>     position;      ///< X^m at the point
    dealii::Tensor<1, 3> smooth_normal; ///< ñ^m

    std::vector<dealii::Tensor<1, 3>> velocity;     ///< φ_i of u
    std::vector<double>               curvature;    ///< φ_i of κ
    std::vector<dealii::Tensor<1, 3>> new_position; ///< η_i of Y
  };
} // namespace FluidSurface

#endif
