// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_rigid_motion_h
#define fluid_surface_model_rigid_motion_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>

#include <fluid_surface/geometry/surface_geometry.h>

#include <array>

namespace FluidSurface
{
  /**
   * The momenta of a velocity field, and the rigid motion R(x) = U + Ω × (x − x_c) of the surface it moves:
   * the motion of the shape, not of the fluid (fit()). The mesh law follows R (its damping target, or the
   * frame carried by R with law `reference`); the momentum constraints take the momenta of u^m from it.
   */
  struct RigidMotion
  {
    std::array<double, 6> momenta = {{0, 0, 0, 0, 0, 0}}; ///< ∫u and ∫x × u about the origin: (r_k, u)
    dealii::Point<3>      centre;                        ///< x_c = ∫x / |S|
    dealii::Tensor<1, 3>  translation;                   ///< U
    dealii::Tensor<1, 3>  rotation;                      ///< Ω

    /// R(x) = U + Ω × (x − x_c), whose normal part is closest to u·ν (see fit()).
    dealii::Tensor<1, 3>
    value(const dealii::Point<3> &x) const;
    /// Q = exp(τ[Ω]×), the rotation by the angle τ|Ω| about Ω (Rodrigues' formula).
    dealii::Tensor<2, 3>
    rotation_over(const double tau) const;
    /// The exact flow of the (stationary) rigid velocity R over a step @p tau, applied to @p x (a screw
    /// motion), Q = rotation_over(τ).
    dealii::Point<3>
    carry(const dealii::Point<3> &x, const double tau) const;

    /**
     * The momenta of the velocity (components 0–2 of @p state on @p dofs, or the function @p velocity at the
     * quadrature points if it is given) on the current surface of @p geometry, and the rigid motion R whose
     * normal velocity R·ν fits u·ν in L², regularized by the cutoff ε = @p cutoff (`mesh redistribution/rigid
     * motion cutoff`, relative to |S|): a Tikhonov term ε|S| |c|² on the coefficients c of R, or with
     * @p spectral_cutoff (law `reference`) a smooth spectral filter of the Gram matrix that fits the motions
     * with ∫(R·ν)² ≥ 2ε|S| exactly and those below ε|S| not at all. Collective.
     */
    /**
     * The Tisserand motion of the velocity (components 0–2 of @p state on @p dofs): the rigid motion
     * R = P/|S| + Ω × (x − x_c) with Ω = I⁻¹L about the centre of mass x_c and I = ∫(|x − x_c|² 1 − (x − x_c) ⊗
     * (x − x_c)) the surface's inertia tensor, so that u − R carries neither momentum nor angular momentum. The
     * spin of a body of revolution counts (unlike fit()), and a rigid velocity is reproduced to round-off.
     * The momenta are those of fit(). Collective.
     */
    static RigidMotion
    tisserand(const SurfaceGeometry &geometry, const dealii::DoFHandler<2, 3> &dofs, const VectorType &state);

    static RigidMotion
    fit(const SurfaceGeometry          &geometry,
        const dealii::DoFHandler<2, 3> &dofs,
        const VectorType               &state,
        const dealii::Function<3>      *velocity,
        const double                    cutoff,
        const bool                      spectral_cutoff);
  };
} // namespace FluidSurface

#endif
