// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>

#include <fluid_surface/reference/axisymmetric_equilibrium.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <stdexcept>

namespace FluidSurface
{
  namespace
  {
    constexpr double pi = dealii::numbers::PI;
  } // namespace

  void
  AxisymmetricEquilibrium::evaluate_half(const double t, double values[4]) const
  {
    const unsigned int N = nodes.size() - 1;
    const std::vector<double> *fields[4] = {&r, &z, &psi, &curvature};
    double                     numerator[4] = {0, 0, 0, 0}, denominator = 0;
    for (unsigned int j = 0; j <= N; ++j)
      {
        const double d = t - nodes[j];
        if (d == 0)
          {
            for (unsigned int f = 0; f < 4; ++f)
              values[f] = (*fields[f])[j];
            return;
          }
        const double c = barycentric_weights[j] / d;
        denominator += c;
        for (unsigned int f = 0; f < 4; ++f)
          numerator[f] += c * (*fields[f])[j];
      }
    for (unsigned int f = 0; f < 4; ++f)
      values[f] = numerator[f] / denominator;
  }

  std::vector<double>
  AxisymmetricEquilibrium::curve_point(const double s) const
  {
    const double S = half_length;
    double       v[4];
    if (s <= S)
      {
        evaluate_half(std::max(0., s / S), v);
        return {v[0], v[1], v[2], -v[3]};
      }
    evaluate_half(std::max(0., 2 - s / S), v);
    return {v[0], -v[1], pi - v[2], -v[3]};
  }

  std::array<double, 2>
  AxisymmetricEquilibrium::meridian_curvature(const double s) const
  {
    const double S     = half_length;
    const bool   lower = (s > S);
    const double t     = lower ? std::max(0., 2 - s / S) : std::max(0., s / S);
    double       numerator[2] = {0, 0}, denominator = 0;
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        const double d = t - nodes[j];
        if (d == 0)
          {
            numerator[0] = meridian_curvature_values[j];
            numerator[1] = meridian_curvature_slopes[j];
            denominator  = 1;
            break;
          }
        const double c = barycentric_weights[j] / d;
        denominator += c;
        numerator[0] += c * meridian_curvature_values[j];
        numerator[1] += c * meridian_curvature_slopes[j];
      }
    // The lower half is the upper half reflected: ψ(s) = π − ψ(2S − s), so k_s is even and k_s' odd about S.
    const double slope = numerator[1] / denominator;
    return {{numerator[0] / denominator, lower ? -slope : slope}};
  }

  dealii::Point<3>
  AxisymmetricEquilibrium::map_from_sphere(const dealii::Point<3> &p) const
  {
    const double              theta = std::atan2(std::hypot(p[0], p[1]), p[2]);
    const double              phi   = std::atan2(p[1], p[0]);
    const std::vector<double> c     = curve_point(2 * half_length * theta / pi);
    return dealii::Point<3>(c[0] * std::cos(phi), c[0] * std::sin(phi), c[1]);
  }

  double
  AxisymmetricEquilibrium::meridian_radius(const double polar_angle) const
  {
    double alpha = std::fmod(polar_angle, 2 * pi);
    if (alpha < 0)
      alpha += 2 * pi;
    if (alpha > pi)
      alpha = 2 * pi - alpha;
    // By mirror symmetry the lower half is the upper half reflected: work with β ∈ [0, π/2].
    const double beta = (alpha > 0.5 * pi ? pi - alpha : alpha);
    if (beta == 0)
      return std::abs(z.front());
    const auto   angle_minus_beta = [&](const double t, double &radius) {
      double v[4];
      evaluate_half(t, v);
      radius = std::hypot(v[0], v[1]);
      return std::atan2(v[0], v[1]) - beta;
    };
    // Bracket every crossing of the ray on a fine grid, refine by bisection, keep the farthest one.
    const unsigned int M = 256;
    double             best = -1, radius = 0;
    double             t0 = 0, f0 = angle_minus_beta(0, radius);
    if (f0 == 0)
      best = radius;
    for (unsigned int k = 1; k <= M; ++k)
      {
        const double t1 = static_cast<double>(k) / M;
        const double f1 = angle_minus_beta(t1, radius);
        if (f1 == 0)
          best = std::max(best, radius);
        else if ((f0 < 0 && f1 > 0) || (f0 > 0 && f1 < 0))
          {
            double a = t0, b = t1, fa = f0;
            for (unsigned int it = 0; it < 60 && b - a > 1e-15; ++it)
              {
                const double m  = 0.5 * (a + b);
                const double fm = angle_minus_beta(m, radius);
                if ((fm < 0) == (fa < 0))
                  {
                    a  = m;
                    fa = fm;
                  }
                else
                  b = m;
              }
            angle_minus_beta(0.5 * (a + b), radius);
            best = std::max(best, radius);
          }
        t0 = t1;
        f0 = f1;
      }
    return best;
  }

  void
  AxisymmetricEquilibrium::write_curve_csv(const std::string &file) const
  {
    std::ofstream out(file);
    if (!out)
      throw std::runtime_error("AxisymmetricEquilibrium: cannot write '" + file + "'.");
    out << "s,r,z,psi,H\n" << std::setprecision(14);
    const unsigned int n = std::max(2u, prm.output_points);
    for (unsigned int k = 0; k < n; ++k)
      {
        const double              s = 2 * half_length * k / (n - 1.);
        const std::vector<double> c = curve_point(s);
        out << s << ',' << c[0] << ',' << c[1] << ',' << c[2] << ',' << c[3] << '\n';
      }
  }

  double
  AxisymmetricEquilibrium::max_radius() const
  {
    // The largest r is where ψ = π/2 (or at the equator); refine the nodal maximum on the interpolant.
    double best = 0;
    for (unsigned int k = 0; k <= 2048; ++k)
      {
        double v[4];
        evaluate_half(k / 2048., v);
        best = std::max(best, v[0]);
      }
    return std::max(best, *std::max_element(r.begin(), r.end()));
  }
} // namespace FluidSurface
