// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_flow_flow_point_values_h
#define fluid_surface_flow_flow_point_values_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_values.h>

#include <vector>

namespace FluidSurface
{
  /**
   * The data of the flow terms at one quadrature point of a cell: the point, its weight and cell normal,
   * the old velocity, and the velocity and pressure parts of every shape function of the cell (velocity in
   * components 0–2, pressure in component 3, as in both scenes' elements). reinit() evaluates the shape
   * functions once per point; the term functions of SurfaceFluid read them.
   */
  struct FlowPointValues
  {
    /// Room for the shape functions of a cell with @p dofs_per_cell DoFs.
    explicit FlowPointValues(const unsigned int dofs_per_cell);

    /**
     * The point data and the shape functions at point @p q of @p fe_values (which needs values, gradients,
     * normal vectors, quadrature points and JxW). The old velocities are left to the caller.
     */
    void
    reinit(const dealii::FEValues<2, 3> &fe_values, const unsigned int q);

    double               JxW = 0;  ///< quadrature weight times the surface element
    dealii::Point<3>     position; ///< x, the point on the frozen surface S^m
    dealii::Tensor<1, 3> normal;   ///< ν, the cell normal at x

    /// u^m in the inertia (1/τ)(u − u^m, v); with BDF2 the history β₁u^m + β₂u^{m−1}.
    dealii::Tensor<1, 3> old_velocity;
    /// w of the convection (∇_w u, v): u^m (scene full) or the extrapolated velocity (scene fixed surface).
    dealii::Tensor<1, 3> transport_velocity;
    /// G^m = ∇_C u^m, the gradient of the old velocity (the mesh-motion part of the convection, scene full).
    dealii::Tensor<2, 3> old_velocity_gradient;

    std::vector<dealii::Tensor<1, 3>> velocity;          ///< φ_i
    std::vector<dealii::Tensor<2, 3>> velocity_gradient; ///< G(φ_i) = ∇_C φ_i (tangential columns)
    std::vector<dealii::Tensor<2, 3>> strain_rate;       ///< σ(φ_i) = sym(P G(φ_i))
    std::vector<double>               divergence;        ///< div_P φ_i = tr G(φ_i)
    std::vector<double>               pressure;          ///< ψ_i
  };
} // namespace FluidSurface

#endif
