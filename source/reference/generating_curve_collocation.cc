// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/numbers.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fluid_surface/reference/generating_curve_collocation.h>

#include <algorithm>
#include <cmath>

namespace FluidSurface
{
  namespace
  {
    constexpr double pi = dealii::numbers::PI;
  } // namespace

  GeneratingCurveCollocation::GeneratingCurveCollocation(const std::vector<double> &t,
                                                         const std::vector<double> &bary,
                                                         const std::vector<double> &cc)
    : N(t.size() - 1)
    , nodes(t)
    , weights(cc)
    , D((N + 1) * (N + 1), 0.)
  {
    for (unsigned int i = 0; i <= N; ++i)
      {
        double diagonal = 0;
        for (unsigned int j = 0; j <= N; ++j)
          if (j != i)
            {
              D[i * (N + 1) + j] = bary[j] / bary[i] / (t[i] - t[j]);
              diagonal -= D[i * (N + 1) + j];
            }
        D[i * (N + 1) + i] = diagonal;
      }
  }

  double
  GeneratingCurveCollocation::derivative(const std::vector<double> &x, const unsigned int offset, const unsigned int j) const
  {
    double d = 0;
    for (unsigned int i = 0; i <= N; ++i)
      d += D[j * (N + 1) + i] * x[offset + i];
    return d;
  }

  void
  GeneratingCurveCollocation::residual(const std::vector<double> &x, std::vector<double> &R) const
  {
    R.assign(size(), 0.);
    const double S = x[this->S()], sg = x[sigma()], Pr = x[P()], om = omega_of(x);
    for (unsigned int j = 0; j <= N; ++j)
      {
        const double ps = x[psi(j)], rj = x[r(j)], Hj = x[H(j)], ej = x[eta(j)];
        const double sn = std::sin(ps), cs = std::cos(ps);
        if (j == 0)
          {
            R[psi(0)] = ps;
            R[r(0)]   = rj;
            // H' = 0 at the pole: the singular term η sinψ / r vanishes there.
            R[H(0)]   = derivative(x, H(0), 0);
            R[eta(0)] = ej;
            continue;
          }
        const double k = sn / rj;
        R[psi(j)]      = derivative(x, psi(0), j) - S * (Hj - k);
        R[r(j)]        = derivative(x, r(0), j) - S * cs;
        R[H(j)]        = derivative(x, H(0), j) - S * Be * (-0.5 * Pr * rj * cs + ej * k);
        if (j < N)
          R[eta(j)] = derivative(x, eta(0), j) -
                      S * (0.5 / Be * (Hj * Hj - 2 * Hj * k) + sg - Pr * rj * sn - 1.5 * om * om * rj * rj);
        else
          R[eta(j)] = ej;
      }
    double a = 0, v = 0, I = 0;
    for (unsigned int j = 0; j <= N; ++j)
      {
        const double rj = x[r(j)];
        a += weights[j] * rj;
        v += weights[j] * rj * rj * std::sin(x[psi(j)]);
        I += weights[j] * rj * rj * rj;
      }
    R[this->S()] = x[psi(N)] - pi / 2;
    R[sigma()] = (4 * pi * S * a - A0) / A0;
    R[P()]     = (2 * pi * S * v - V0) / V0;
    if (momentum_prescribed)
      R[w()] = (om * 4 * pi * S * I - L0) / inertia_scale();
  }

  void
  GeneratingCurveCollocation::jacobian(const std::vector<double> &x, dealii::LAPACKFullMatrix<double> &J) const
  {
    const unsigned int n = size();
    J.reinit(n, n);
    J = 0;
    add_shape_equation_jacobian(x, J);
    add_constraint_jacobian(x, J);
  }

  void
  GeneratingCurveCollocation::add_shape_equation_jacobian(const std::vector<double> &x, dealii::LAPACKFullMatrix<double> &J) const
  {
    const double S = x[this->S()], sg = x[sigma()], Pr = x[P()], om = omega_of(x);
    for (unsigned int j = 0; j <= N; ++j)
      {
        const double ps = x[psi(j)], rj = x[r(j)], Hj = x[H(j)], ej = x[eta(j)];
        const double sn = std::sin(ps), cs = std::cos(ps);
        if (j == 0)
          {
            J(psi(0), psi(0)) = 1;
            J(r(0), r(0))     = 1;
            for (unsigned int i = 0; i <= N; ++i)
              J(H(0), H(i)) = D[i];
            J(eta(0), eta(0)) = 1;
            continue;
          }
        for (unsigned int i = 0; i <= N; ++i)
          {
            const double d = D[j * (N + 1) + i];
            J(psi(j), psi(i)) += d;
            J(r(j), r(i)) += d;
            J(H(j), H(i)) += d;
            if (j < N)
              J(eta(j), eta(i)) += d;
          }
        const double k = sn / rj, k_psi = cs / rj, k_r = -sn / (rj * rj);

        J(psi(j), psi(j)) += S * k_psi;
        J(psi(j), r(j)) += S * k_r;
        J(psi(j), H(j)) += -S;
        J(psi(j), this->S()) += -(Hj - k);

        J(r(j), psi(j)) += S * sn;
        J(r(j), this->S()) += -cs;

        const double fH = Be * (-0.5 * Pr * rj * cs + ej * k);
        J(H(j), psi(j)) += -S * Be * (0.5 * Pr * rj * sn + ej * k_psi);
        J(H(j), r(j)) += -S * Be * (-0.5 * Pr * cs + ej * k_r);
        J(H(j), eta(j)) += -S * Be * k;
        J(H(j), P()) += S * Be * 0.5 * rj * cs;
        J(H(j), this->S()) += -fH;

        if (j < N)
          {
            const double fe = 0.5 / Be * (Hj * Hj - 2 * Hj * k) + sg - Pr * rj * sn - 1.5 * om * om * rj * rj;
            J(eta(j), H(j)) += -S * (Hj - k) / Be;
            J(eta(j), psi(j)) += -S * (-Hj * k_psi / Be - Pr * rj * cs);
            J(eta(j), r(j)) += -S * (-Hj * k_r / Be - Pr * sn - 3 * om * om * rj);
            J(eta(j), sigma()) += -S;
            J(eta(j), P()) += S * rj * sn;
            if (momentum_prescribed)
              J(eta(j), w()) += S * 3 * om * rj * rj;
            J(eta(j), this->S()) += -fe;
          }
        else
          J(eta(j), eta(j)) = 1;
      }
  }

  void
  GeneratingCurveCollocation::add_constraint_jacobian(const std::vector<double> &x, dealii::LAPACKFullMatrix<double> &J) const
  {
    const double S = x[this->S()], om = omega_of(x);
    J(this->S(), psi(N)) = 1;
    double a = 0, v = 0, I = 0;
    for (unsigned int j = 0; j <= N; ++j)
      {
        const double rj = x[r(j)], sn = std::sin(x[psi(j)]), cs = std::cos(x[psi(j)]);
        a += weights[j] * rj;
        v += weights[j] * rj * rj * sn;
        I += weights[j] * rj * rj * rj;
        J(sigma(), r(j)) = 4 * pi * S * weights[j] / A0;
        J(P(), r(j))     = 2 * pi * S * weights[j] * 2 * rj * sn / V0;
        J(P(), psi(j))   = 2 * pi * S * weights[j] * rj * rj * cs / V0;
        if (momentum_prescribed)
          J(w(), r(j)) = om * 4 * pi * S * weights[j] * 3 * rj * rj / inertia_scale();
      }
    J(sigma(), this->S()) = 4 * pi * a / A0;
    J(P(), this->S())     = 2 * pi * v / V0;
    if (momentum_prescribed)
      {
        J(w(), w())       = 4 * pi * S * I / inertia_scale();
        J(w(), this->S()) = om * 4 * pi * I / inertia_scale();
      }
  }

  double
  GeneratingCurveCollocation::norm(const std::vector<double> &v)
  {
    double s = 0;
    for (const double a : v)
      s += a * a;
    return std::sqrt(s);
  }

  bool
  GeneratingCurveCollocation::admissible(const std::vector<double> &x) const
  {
    if (!(x[S()] > 0))
      return false;
    for (unsigned int j = 1; j <= N; ++j)
      if (!(x[r(j)] > 0))
        return false;
    return true;
  }

  bool
  GeneratingCurveCollocation::newton(std::vector<double> &x, const double tolerance, unsigned int &iterations) const
  {
    const unsigned int               n = size();
    std::vector<double>              R, trial(n), R_trial;
    dealii::LAPACKFullMatrix<double> J;
    dealii::Vector<double>           delta(n);
    residual(x, R);
    double r0 = norm(R);

    for (iterations = 1; iterations <= 60; ++iterations)
      {
        jacobian(x, J);
        J.compute_lu_factorization();
        for (unsigned int i = 0; i < n; ++i)
          delta[i] = R[i];
        J.solve(delta);
        double step_size = 0, x_size = 1;
        for (unsigned int i = 0; i < n; ++i)
          {
            step_size = std::max(step_size, std::abs(delta[i]));
            x_size    = std::max(x_size, std::abs(x[i]));
          }
        if (!std::isfinite(step_size))
          return false;
        if (step_size <= tolerance * x_size)
          {
            // Converged: the last update is at rounding level, take it whole.
            for (unsigned int i = 0; i < n; ++i)
              x[i] -= delta[i];
            residual(x, R);
            return norm(R) < 1e-8;
          }
        double lambda = 1;
        for (; lambda > 1e-4; lambda *= 0.5)
          {
            for (unsigned int i = 0; i < n; ++i)
              trial[i] = x[i] - lambda * delta[i];
            if (!admissible(trial))
              continue;
            residual(trial, R_trial);
            const double r1 = norm(R_trial);
            if (std::isfinite(r1) && (r1 < (1 - 1e-4 * lambda) * r0 || r1 < 1e-13))
              break;
          }
        if (lambda <= 1e-4)
          return false;
        x.swap(trial);
        R.swap(R_trial);
        r0 = norm(R);
      }
    return false;
  }
  void
  GeneratingCurveCollocation::fit_multipliers(std::vector<double> &y) const
  {
    const unsigned int               m = 2 * N + 2, n = N + 3;
    const double                     S = y[this->S()];
    dealii::LAPACKFullMatrix<double> A(m, n);
    dealii::Vector<double>           b(m), fit(n);
    unsigned int                     row = 0;
    for (unsigned int j = 1; j <= N; ++j, ++row)
      {
        const double ps = y[psi(j)], rj = y[r(j)], Hj = y[H(j)];
        const double k  = std::sin(ps) / rj;
        A(row, j)       = -S * Be * k;
        A(row, N + 2)   = S * Be * 0.5 * rj * std::cos(ps);
        b[row]          = -derivative(y, H(0), j);
        ++row;
        for (unsigned int i = 0; i <= N; ++i)
          A(row, i) = D[j * (N + 1) + i];
        A(row, N + 1) = -S;
        A(row, N + 2) = S * rj * std::sin(ps);
        b[row]        = S * 0.5 / Be * (Hj * Hj - 2 * Hj * k);
      }
    A(row, 0) = 10;
    ++row;
    A(row, N) = 10;
    A.compute_inverse_svd();
    A.vmult(fit, b);
    for (unsigned int j = 0; j <= N; ++j)
      y[eta(j)] = fit[j];
    y[eta(0)]  = 0;
    y[eta(N)]  = 0;
    y[sigma()] = fit[N + 1];
    y[P()]     = fit[N + 2];
  }
} // namespace FluidSurface
