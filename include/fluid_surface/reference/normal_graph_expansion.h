// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_reference_normal_graph_expansion_h
#define fluid_surface_reference_normal_graph_expansion_h

#include <array>

/**
 * Second-order expansion in ε of the geometric functionals of a normal graph over a surface of revolution
 * (doc/stability.md, "The second variation at an axisymmetric equilibrium").
 *
 * The base surface X₀(s, φ) = r(s) e_r(φ) + z(s) e_z has the tangent t = cos ψ e_r − sin ψ e_z, the outward normal
 * ν₀ = sin ψ e_r + cos ψ e_z and the meridian curvature k = ψ'. The perturbed surface is
 *
 *     X = X₀ + ε f ν₀,     f(s, φ) = a(s) cos(mφ),
 *
 * and its densities (per ds dφ) are those of the exact 3D geometry: the area element J = |X_s × X_φ|, the volume
 * density X·(X_s × X_φ)/3, the bending density ½H²J (H = g^{ij} b_ij, the sum of the principal curvatures), the
 * inertia densities (x² + y²)J, (y² + z²)J, xzJ and the first moments xJ, yJ, zJ. Their Taylor coefficients in ε
 * are computed exactly by arithmetic on truncated power series (no difference quotients): the ε¹ coefficient is a
 * linear form and the ε² coefficient a quadratic form in the local values v = (a, a', a'') (' = d/ds).
 */
namespace FluidSurface::NormalGraphExpansion
{
  /// The functionals expanded, as indices of the arrays below.
  enum Functional : unsigned int
  {
    area,       ///< A = ∫dA
    volume,     ///< V = ⅓∫X·ν dA
    willmore,   ///< W₁ = ½∫H² dA (the bending energy at Be = 1)
    inertia_zz, ///< ∫(x² + y²) dA, about the origin
    inertia_xx, ///< ∫(y² + z²) dA, about the origin
    inertia_xz, ///< ∫xz dA (minus the product of inertia I_xz)
    moment_x,   ///< ∫x dA
    moment_y,   ///< ∫y dA
    moment_z,   ///< ∫z dA
    n_functionals
  };

  /// The generating curve at one arc length s: radius r, height z, tangent angle ψ, k = ψ' and k' = ψ''.
  struct CurvePoint
  {
    double radius          = 0;
    double height          = 0;
    double angle           = 0;
    double curvature       = 0;
    double curvature_slope = 0;
  };

  /**
   * The φ-integrals (over [0, 2π)) of the densities at one point of the curve, per unit arc length, expanded in ε:
   * ∫ρ dφ = value + ε linear·v + ε² vᵀ quadratic v + O(ε³).
   */
  struct LocalExpansion
  {
    std::array<double, n_functionals>                                    value{};
    std::array<std::array<double, 3>, n_functionals>                     linear{};
    std::array<std::array<std::array<double, 3>, 3>, n_functionals>      quadratic{};
    double                mass = 0;          ///< ∫cos²(mφ) dφ · r: the density of ∫f² dA₀ per a²
    std::array<double, 3> translation{};     ///< ∫cos(mφ) ν₀ dφ · r: of ∫f ν₀ dA₀ per a (normal part of translations)
  };

  /**
   * The expansion at @p point for the azimuthal number @p m, with the trapezoidal rule of @p n_phi points in φ
   * (exact for the trigonometric polynomials of degree < n_phi that the coefficients are; 2m + 4 suffice).
   */
  LocalExpansion
  expand(const CurvePoint &point, const unsigned int m, const unsigned int n_phi);

  /**
   * The φ-integrals of the densities of the perturbed surface itself, for the amplitude @p epsilon and the local
   * values @p v = (a, a', a''), in plain arithmetic: what expand() expands (for finite-difference checks).
   */
  std::array<double, n_functionals>
  evaluate(const CurvePoint &point, const unsigned int m, const unsigned int n_phi, const std::array<double, 3> &v,
           const double epsilon);
} // namespace FluidSurface::NormalGraphExpansion

#endif
