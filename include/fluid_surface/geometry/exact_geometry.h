// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_geometry_exact_geometry_h
#define fluid_surface_geometry_exact_geometry_h

#include <deal.II/base/quadrature_lib.h>

#include <cmath>

namespace FluidSurface
{
  /**
   * Reduced volume v = V / ((4π/3)(A/(4π))^{3/2}) of a closed surface of area @p area enclosing the volume
   * @p volume: 1 for a sphere, smaller for every other shape.
   */
  inline double
  reduced_volume_of(const double area, const double volume)
  {
    return volume / (4.0 * M_PI / 3.0 * std::pow(area / (4.0 * M_PI), 1.5));
  }

  /// Reference values of a spheroid, for verification.
  struct SpheroidMeasures
  {
    double area;           ///< |S|
    double volume;         ///< V = 4π/3 a²c
    double reduced_volume; ///< v = V / ((4π/3)(|S|/(4π))^{3/2})
    double willmore;       ///< ½∫H², H = k₁ + k₂
    double inertia_zz;     ///< ∫(x² + y²) dA
    double inertia_xx;     ///< ∫(y² + z²) dA
  };

  /**
   * Area, volume, reduced volume, Willmore energy and surface inertia of the spheroid
   * x²/a² + y²/a² + z²/c² = 1, by Gauss quadrature in the polar angle θ
   * (x = a sinθ cosφ, z = c cosθ), exact to rounding for smooth integrands.
   * Principal curvatures: k_meridian = ac/q³, k_parallel = c/(aq),
   * q = (a²cos²θ + c²sin²θ)^{1/2}; dA = 2π a sinθ q dθ.
   */
  inline SpheroidMeasures
  exact_spheroid_measures(const double a, const double c)
  {
    static const dealii::QGauss<1> gauss(200);
    SpheroidMeasures               m{0, 4.0 * M_PI / 3.0 * a * a * c, 0, 0, 0, 0};
    for (unsigned int k = 0; k < gauss.size(); ++k)
      {
        const double theta = M_PI * gauss.point(k)[0];
        const double s = std::sin(theta), co = std::cos(theta);
        const double q  = std::sqrt(a * a * co * co + c * c * s * s);
        const double dA = 2.0 * M_PI * a * s * q * M_PI * gauss.weight(k);
        const double H  = a * c / (q * q * q) + c / (a * q);
        const double r2 = a * a * s * s, z2 = c * c * co * co;
        m.area += dA;
        m.willmore += 0.5 * H * H * dA;
        m.inertia_zz += r2 * dA;
        m.inertia_xx += (0.5 * r2 + z2) * dA;
      }
    m.reduced_volume = reduced_volume_of(m.area, m.volume);
    return m;
  }

  /**
   * Arc length of the meridian r = a sinθ, z = c cosθ of the spheroid (a, a, c) from the pole θ = 0 to
   * @p theta ≤ π/2: ∫₀^θ q dθ', q = (a²cos²θ' + c²sin²θ')^{1/2}, by 40-point Gauss quadrature.
   */
  inline double
  spheroid_meridian_length(const double a, const double c, const double theta)
  {
    static const dealii::QGauss<1> gauss(40);
    double                         s = 0;
    for (unsigned int k = 0; k < gauss.size(); ++k)
      {
        const double t = theta * gauss.point(k)[0];
        s += gauss.weight(k) * std::sqrt(a * a * std::cos(t) * std::cos(t) + c * c * std::sin(t) * std::sin(t));
      }
    return s * theta;
  }
} // namespace FluidSurface

#endif
