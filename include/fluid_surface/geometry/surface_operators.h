// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_geometry_surface_operators_h
#define fluid_surface_geometry_surface_operators_h

#include <deal.II/base/tensor.h>

namespace FluidSurface
{
  /**
   * Pointwise surface calculus for vector fields on a codimension-1 surface S ⊂ R³,
   * on the data a flow assembler has at a quadrature point. Conventions:
   *  - ν is a unit normal (the cell normal ν_h, a continuous ñ or an exact normal);
   *  - G is the gradient of a vector field u as FEValues computes it on a
   *    Triangulation<2,3>: rows are components, columns the tangential
   *    derivatives, G = ∇_C u = (∇u^e) P_h for any extension u^e (G ν_h = 0);
   *  - u is the full 3D field (tangential + normal parts); nothing here assumes u·ν = 0.
   * Every function is templated on the number type so that automatic differentiation
   * types (manufactured right-hand sides) go through the same formulas.
   */
  namespace SurfaceOperators
  {
    /// Tangential projection P = I − ν ⊗ ν.
    template <typename Number>
    inline dealii::Tensor<2, 3, Number>
    projection(const dealii::Tensor<1, 3, Number> &normal)
    {
      dealii::Tensor<2, 3, Number> P;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          P[i][j] = (i == j ? Number(1.0) : Number(0.0)) - normal[i] * normal[j];
      return P;
    }

    /**
     * Günther (projected) gradient ∇_P u = P ∇_C u = P G. Since the columns of G
     * are already tangential, this equals P (∇u^e) P.
     */
    template <typename Number>
    inline dealii::Tensor<2, 3, Number>
    projected_gradient(const dealii::Tensor<2, 3, Number> &G, const dealii::Tensor<1, 3, Number> &normal)
    {
      return projection(normal) * G;
    }

    /// Surface rate of strain σ(u) = ½(∇_P u + (∇_P u)ᵀ) from ∇_P u.
    template <typename Number>
    inline dealii::Tensor<2, 3, Number>
    strain_rate(const dealii::Tensor<2, 3, Number> &projected_grad)
    {
      dealii::Tensor<2, 3, Number> sigma;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          sigma[i][j] = 0.5 * (projected_grad[i][j] + projected_grad[j][i]);
      return sigma;
    }

    /// σ(u) = ½(P G + (P G)ᵀ) directly from the FEValues gradient G and the normal ν.
    template <typename Number>
    inline dealii::Tensor<2, 3, Number>
    strain_rate(const dealii::Tensor<2, 3, Number> &G, const dealii::Tensor<1, 3, Number> &normal)
    {
      return strain_rate(projected_gradient(G, normal));
    }

    /**
     * Surface divergence div_P u = tr(P ∇u^e P) = tr G = div_S u, normal part
     * included: div_S(φν) = −φH with B = −∇_C ν, H = tr B.
     */
    template <typename Number>
    inline Number
    surface_divergence(const dealii::Tensor<2, 3, Number> &G)
    {
      return G[0][0] + G[1][1] + G[2][2];
    }

    /**
     * Convective derivative of u along w: [∇_w u]_i = G_i · w, i.e. G w
     * (only the tangential part of w enters, because G w = G P w).
     */
    template <typename Number>
    inline dealii::Tensor<1, 3, Number>
    convective_derivative(const dealii::Tensor<2, 3, Number> &G, const dealii::Tensor<1, 3, Number> &w)
    {
      return G * w;
    }

    /// Normal component u·ν.
    template <typename Number>
    inline Number
    normal_component(const dealii::Tensor<1, 3, Number> &u, const dealii::Tensor<1, 3, Number> &normal)
    {
      return u * normal;
    }

    /// Tangential part P u = u − (u·ν) ν.
    template <typename Number>
    inline dealii::Tensor<1, 3, Number>
    tangential_part(const dealii::Tensor<1, 3, Number> &u, const dealii::Tensor<1, 3, Number> &normal)
    {
      return u - (u * normal) * normal;
    }
  } // namespace SurfaceOperators
} // namespace FluidSurface

#endif
