// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_geometry_azimuthal_harmonic_h
#define fluid_surface_geometry_azimuthal_harmonic_h

#include <deal.II/base/tensor.h>

#include <array>
#include <cmath>
#include <complex>

namespace FluidSurface
{
  /**
   * The solid harmonics about an axis e that single out one azimuthal wavenumber m of a shape: with the
   * right-handed orthonormal frame (e₁, e₂, e) and ξ = x·e₁ + i x·e₂, ζ = x·e,
   *   h_m^even(x) = ξ^m (m ≥ 2),  h_1^even(x) = ξ(5ζ² − |x|²),  h_m^odd(x) = ζ ξ^m  (m ≥ 1),
   *   h_0^even(x) = ζ² − |x|²/3,  h_0^odd(x) = ζ(ζ² − 3|x|²/5)  (the axisymmetric P₂ and P₃).
   * (ξ itself would be a translation, and its moment about the centre of mass vanishes identically.)
   * Under a rotation by α about e, h_m picks up the phase e^{imα}; the parity is that under ζ → −ζ. On the unit
   * sphere Re h is the spherical harmonic Y_m^m (even; Y_3^1 for m = 1) or Y_{m+1}^m (odd), up to a factor; m = 1 odd is the tilt
   * of the axis.
   */
  class AzimuthalHarmonic
  {
  public:
    /// The harmonic of wavenumber @p m and parity @p odd about the unit vector @p axis.
    AzimuthalHarmonic(const dealii::Tensor<1, 3> &axis, const unsigned int m, const bool odd)
      : e(axis)
      , m(m)
      , odd(odd)
    {
      const std::array<dealii::Tensor<1, 3>, 2> frame = transverse_frame(e);
      e1                                              = frame[0];
      e2                                              = frame[1];
    }

    /// The unit vectors e₁, e₂ with (e₁, e₂, @p axis) right-handed and orthonormal: φ = arg ξ is measured from e₁.
    static std::array<dealii::Tensor<1, 3>, 2>
    transverse_frame(const dealii::Tensor<1, 3> &axis)
    {
      dealii::Tensor<1, 3> helper;
      helper[std::abs(axis[0]) < 0.9 ? 0 : 1] = 1;
      dealii::Tensor<1, 3> first              = helper - (helper * axis) * axis;
      first /= first.norm();
      return {{first, dealii::cross_product_3d(axis, first)}};
    }

    /// h(x) for x relative to a point on the axis.
    std::complex<double>
    operator()(const dealii::Tensor<1, 3> &x) const
    {
      const double zeta = x * e;
      if (m == 0)
        return odd ? zeta * (zeta * zeta - 0.6 * x.norm_square()) : zeta * zeta - x.norm_square() / 3.0;
      const std::complex<double> xi_m = std::pow(std::complex<double>(x * e1, x * e2), static_cast<int>(m));
      if (odd)
        return zeta * xi_m;
      return m == 1 ? xi_m * (5.0 * zeta * zeta - x.norm_square()) : xi_m;
    }

    /// Re h(x/|x|) / max over the unit sphere of |h|: a smooth displacement amplitude in [−1, 1].
    double
    normalized_real_part(const dealii::Tensor<1, 3> &x) const
    {
      return (*this)(x / x.norm()).real() / sphere_maximum();
    }

  private:
    /// max of |h| on |x| = 1: sin^m θ (cos θ) at its maximum.
    double
    sphere_maximum() const
    {
      if (m == 0)
        return odd ? 0.4 : 2.0 / 3.0;
      if (!odd)
        return m == 1 ? 8.0 / 3.0 * std::sqrt(4.0 / 15.0) : 1.0; // sin θ(4 − 5 sin²θ) at sin²θ = 4/15

      const double c = 1.0 / std::sqrt(m + 1.0); // cos θ of the maximum of cos θ sin^m θ
      return c * std::pow(1.0 - c * c, 0.5 * m);
    }

    dealii::Tensor<1, 3> e, e1, e2;
    unsigned int         m;
    bool                 odd;
  };
} // namespace FluidSurface

#endif
