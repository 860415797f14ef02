// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/numbers.h>

#include <fluid_surface/reference/normal_graph_expansion.h>

#include <cmath>

namespace FluidSurface::NormalGraphExpansion
{
  namespace
  {
    /// A power series c₀ + c₁ε + c₂ε² truncated after ε²: exact Taylor coefficients through arithmetic.
    struct Jet
    {
      double c[3] = {0, 0, 0};

      Jet() = default;
      Jet(const double value)
        : c{value, 0, 0}
      {}
      Jet(const double c0, const double c1, const double c2)
        : c{c0, c1, c2}
      {}
    };

    Jet
    operator+(const Jet &a, const Jet &b)
    {
      return {a.c[0] + b.c[0], a.c[1] + b.c[1], a.c[2] + b.c[2]};
    }

    Jet
    operator-(const Jet &a, const Jet &b)
    {
      return {a.c[0] - b.c[0], a.c[1] - b.c[1], a.c[2] - b.c[2]};
    }

    Jet
    operator*(const Jet &a, const Jet &b)
    {
      return {a.c[0] * b.c[0], a.c[0] * b.c[1] + a.c[1] * b.c[0], a.c[0] * b.c[2] + a.c[1] * b.c[1] + a.c[2] * b.c[0]};
    }

    Jet
    operator/(const Jet &a, const Jet &b)
    {
      const double q0 = a.c[0] / b.c[0];
      const double q1 = (a.c[1] - q0 * b.c[1]) / b.c[0];
      return {q0, q1, (a.c[2] - q0 * b.c[2] - q1 * b.c[1]) / b.c[0]};
    }

    Jet
    sqrt(const Jet &a)
    {
      const double s0 = std::sqrt(a.c[0]);
      const double s1 = a.c[1] / (2 * s0);
      return {s0, s1, (a.c[2] - s1 * s1) / (2 * s0)};
    }

    using std::sqrt;

    template <typename Number>
    using Vec = std::array<Number, 3>;

    template <typename Number>
    Vec<Number>
    operator+(const Vec<Number> &a, const Vec<Number> &b)
    {
      return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}};
    }

    /// The vector @p u (of numbers or of fixed components) scaled by the number @p x.
    template <typename Number, typename Component>
    Vec<Number>
    times(const Number &x, const std::array<Component, 3> &u)
    {
      return {{x * u[0], x * u[1], x * u[2]}};
    }

    template <typename Number>
    Number
    dot(const Vec<Number> &a, const Vec<Number> &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    template <typename Number>
    Vec<Number>
    cross(const Vec<Number> &a, const Vec<Number> &b)
    {
      return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
    }

    /**
     * The densities (per ds dφ) of the surface X₀ + f ν₀ at (s, φ), f = a(s) c(φ), for the azimuthal factor
     * c = cos(mφ) with its derivatives @p c (c, c_φ, c_φφ) and the local values a, a', a'' (which carry ε).
     */
    template <typename Number>
    std::array<Number, n_functionals>
    densities(const CurvePoint &p, const double phi, const std::array<double, 3> &c, const Number &a,
              const Number &a_s, const Number &a_ss)
    {
      const double sp = std::sin(p.angle), cp = std::cos(p.angle), k = p.curvature, dk = p.curvature_slope;
      const std::array<double, 3> e_r{{std::cos(phi), std::sin(phi), 0.}}, e_phi{{-std::sin(phi), std::cos(phi), 0.}};
      const std::array<double, 3> t{{cp * e_r[0], cp * e_r[1], -sp}}, nu{{sp * e_r[0], sp * e_r[1], cp}};
      const auto fixed = [](const std::array<double, 3> &u) { return Vec<Number>{{u[0], u[1], u[2]}}; };

      const Number f = a * c[0], f_s = a_s * c[0], f_ss = a_ss * c[0], f_p = a * c[1], f_pp = a * c[2],
                   f_sp = a_s * c[1];
      // ν₀_s = k t, ν₀_φ = sin ψ e_φ, t_s = −k ν₀, t_φ = cos ψ e_φ, e_φ,φ = −e_r.
      const Vec<Number> X = fixed({{p.radius * e_r[0], p.radius * e_r[1], p.height}}) + times(f, nu);
      const Vec<Number> X_s = fixed(t) + times(f_s, nu) + times(f * k, t);
      const Vec<Number> X_p = times(Number(p.radius) + f * sp, e_phi) + times(f_p, nu);
      const Vec<Number> X_ss = times(f_ss - k - f * k * k, nu) + times(Number(2 * k) * f_s + f * dk, t);
      const Vec<Number> X_sp = times(Number(cp) + f_s * sp + f * k * cp, e_phi) + times(f_sp, nu) + times(f_p * k, t);
      const Vec<Number> X_pp = times(Number(-p.radius) - f * sp, e_r) + times(f_pp, nu) + times(Number(2 * sp) * f_p, e_phi);

      const Vec<Number> n = cross(X_s, X_p);
      const Number      J = sqrt(dot(n, n));
      const Vec<Number> N = times(Number(1.) / J, n);
      const Number      g11 = dot(X_s, X_s), g12 = dot(X_s, X_p), g22 = dot(X_p, X_p);
      const Number      H   = (g22 * dot(X_ss, N) - Number(2.) * g12 * dot(X_sp, N) + g11 * dot(X_pp, N)) / (J * J);

      std::array<Number, n_functionals> rho;
      rho[area]       = J;
      rho[volume]     = dot(X, n) * Number(1. / 3);
      rho[willmore]   = Number(0.5) * H * H * J;
      rho[inertia_zz] = (X[0] * X[0] + X[1] * X[1]) * J;
      rho[inertia_xx] = (X[1] * X[1] + X[2] * X[2]) * J;
      rho[inertia_xz] = X[0] * X[2] * J;
      rho[moment_x]   = X[0] * J;
      rho[moment_y]   = X[1] * J;
      rho[moment_z]   = X[2] * J;
      return rho;
    }

    /// c = cos(mφ) and its first two derivatives.
    std::array<double, 3>
    azimuthal_factor(const unsigned int m, const double phi)
    {
      const double cm = std::cos(m * phi), sm = std::sin(m * phi);
      return {{cm, -1. * m * sm, -1. * m * m * cm}};
    }

    /// The φ-integrals of the densities with the local values @p v multiplied by ε (the series of a Jet).
    std::array<Jet, n_functionals>
    integrated_series(const CurvePoint &point, const unsigned int m, const unsigned int n_phi,
                      const std::array<double, 3> &v)
    {
      std::array<Jet, n_functionals> sum;
      const double                   weight = 2 * dealii::numbers::PI / n_phi;
      for (unsigned int q = 0; q < n_phi; ++q)
        {
          const double phi = q * weight;
          const auto   rho = densities<Jet>(point, phi, azimuthal_factor(m, phi), Jet(0, v[0], 0), Jet(0, v[1], 0),
                                          Jet(0, v[2], 0));
          for (unsigned int f = 0; f < n_functionals; ++f)
            sum[f] = sum[f] + rho[f] * Jet(weight);
        }
      return sum;
    }
  } // namespace

  LocalExpansion
  expand(const CurvePoint &point, const unsigned int m, const unsigned int n_phi)
  {
    LocalExpansion result;
    // Probe directions scaled so that a/r², a'/r and a'' enter H alike near the pole (balanced rounding).
    const double r = point.radius;
    const double scale[3] = {r * r, r, 1.};
    std::array<std::array<Jet, n_functionals>, 3> single;
    for (unsigned int i = 0; i < 3; ++i)
      {
        std::array<double, 3> v{{0., 0., 0.}};
        v[i]      = scale[i];
        single[i] = integrated_series(point, m, n_phi, v);
        for (unsigned int f = 0; f < n_functionals; ++f)
          {
            result.value[f]           = single[i][f].c[0];
            result.linear[f][i]       = single[i][f].c[1] / scale[i];
            result.quadratic[f][i][i] = single[i][f].c[2] / (scale[i] * scale[i]);
          }
      }
    // Polarization: the ε² coefficient is exactly quadratic in v.
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i + 1; j < 3; ++j)
        {
          std::array<double, 3> v{{0., 0., 0.}};
          v[i]            = scale[i];
          v[j]            = scale[j];
          const auto pair = integrated_series(point, m, n_phi, v);
          for (unsigned int f = 0; f < n_functionals; ++f)
            {
              const double q = 0.5 * (pair[f].c[2] - single[i][f].c[2] - single[j][f].c[2]) / (scale[i] * scale[j]);
              result.quadratic[f][i][j] = result.quadratic[f][j][i] = q;
            }
        }

    const double weight = 2 * dealii::numbers::PI / n_phi, sp = std::sin(point.angle), cp = std::cos(point.angle);
    for (unsigned int q = 0; q < n_phi; ++q)
      {
        const double phi = q * weight, c = std::cos(m * phi);
        result.mass += weight * c * c * r;
        result.translation[0] += weight * c * sp * std::cos(phi) * r;
        result.translation[1] += weight * c * sp * std::sin(phi) * r;
        result.translation[2] += weight * c * cp * r;
      }
    return result;
  }

  std::array<double, n_functionals>
  evaluate(const CurvePoint &point, const unsigned int m, const unsigned int n_phi, const std::array<double, 3> &v,
           const double epsilon)
  {
    std::array<double, n_functionals> sum{};
    const double                      weight = 2 * dealii::numbers::PI / n_phi;
    for (unsigned int q = 0; q < n_phi; ++q)
      {
        const double phi = q * weight;
        const auto   rho =
          densities<double>(point, phi, azimuthal_factor(m, phi), epsilon * v[0], epsilon * v[1], epsilon * v[2]);
        for (unsigned int f = 0; f < n_functionals; ++f)
          sum[f] += weight * rho[f];
      }
    return sum;
  }
} // namespace FluidSurface::NormalGraphExpansion
