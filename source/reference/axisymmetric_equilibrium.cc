#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fluid_surface/geometry/exact_geometry.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/reference/axisymmetric_equilibrium.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace FluidSurface
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    using Parameters = AxisymmetricEquilibrium::Parameters;
    using Branch     = AxisymmetricEquilibrium::Branch;

    /**
     * Chebyshev collocation of the half-curve boundary value problem. Unknown vector:
     * ψ_0..ψ_N, r_0..r_N, H_0..H_N, η_0..η_N, S, σ, P [, ω when L is prescribed].
     */
    class Collocation
    {
    public:
      Collocation(const std::vector<double> &t, const std::vector<double> &bary, const std::vector<double> &cc)
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

      unsigned int N;
      std::vector<double> nodes, weights, D;

      double Be = 1, A0 = 4 * pi, V0 = 4 * pi / 3;
      bool   momentum_prescribed = false;
      double omega = 0, L0 = 0;

      /// Number of unknowns without ω: the four fields, S, σ and P.
      unsigned int
      size_at_rest() const
      {
        return 4 * (N + 1) + 3;
      }
      unsigned int
      size() const
      {
        return size_at_rest() + (momentum_prescribed ? 1 : 0);
      }
      unsigned int
      psi(unsigned int j) const
      {
        return j;
      }
      unsigned int
      r(unsigned int j) const
      {
        return N + 1 + j;
      }
      unsigned int
      H(unsigned int j) const
      {
        return 2 * (N + 1) + j;
      }
      unsigned int
      eta(unsigned int j) const
      {
        return 3 * (N + 1) + j;
      }
      unsigned int
      S() const
      {
        return 4 * (N + 1);
      }
      unsigned int
      sigma() const
      {
        return S() + 1;
      }
      unsigned int
      P() const
      {
        return S() + 2;
      }
      unsigned int
      w() const
      {
        return S() + 3;
      }

      double
      omega_of(const std::vector<double> &x) const
      {
        return momentum_prescribed ? x[w()] : omega;
      }

      /// Reference moment of inertia of the sphere of area A0, to scale the angular momentum row.
      double
      inertia_scale() const
      {
        const double R2 = A0 / (4 * pi);
        return 8 * pi / 3 * R2 * R2;
      }

      /// Radius R of the sphere of area A0.
      double
      sphere_radius() const
      {
        return std::sqrt(A0 / (4 * pi));
      }

      /// Volume of a shape of area A0 and reduced volume @p v.
      double
      volume_at(const double v) const
      {
        const double R_area = sphere_radius();
        return v * 4 * pi / 3 * R_area * R_area * R_area;
      }

      /// (Dv)_j for the block of x starting at @p offset.
      double
      derivative(const std::vector<double> &x, const unsigned int offset, const unsigned int j) const
      {
        double d = 0;
        for (unsigned int i = 0; i <= N; ++i)
          d += D[j * (N + 1) + i] * x[offset + i];
        return d;
      }

      /// The residual at @p x: the collocated shape equations with the pole and equator conditions, then the
      /// equator angle and the relative area, volume (and angular momentum) defects.
      void
      residual(const std::vector<double> &x, std::vector<double> &R) const
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

      /// The Jacobian of residual() at @p x.
      void
      jacobian(const std::vector<double> &x, dealii::LAPACKFullMatrix<double> &J) const
      {
        const unsigned int n = size();
        J.reinit(n, n);
        J = 0;
        add_shape_equation_jacobian(x, J);
        add_constraint_jacobian(x, J);
      }

      /// The rows of the collocated shape equations (ψ, r, H, η at every node) of the Jacobian.
      void
      add_shape_equation_jacobian(const std::vector<double> &x, dealii::LAPACKFullMatrix<double> &J) const
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

      /// The rows of the equator condition and the area, volume (and angular momentum) constraints.
      void
      add_constraint_jacobian(const std::vector<double> &x, dealii::LAPACKFullMatrix<double> &J) const
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

      /// Euclidean norm.
      static double
      norm(const std::vector<double> &v)
      {
        double s = 0;
        for (const double a : v)
          s += a * a;
        return std::sqrt(s);
      }

      /// The state is admissible: positive length and r > 0 away from the pole.
      bool
      admissible(const std::vector<double> &x) const
      {
        if (!(x[S()] > 0))
          return false;
        for (unsigned int j = 1; j <= N; ++j)
          if (!(x[r(j)] > 0))
            return false;
        return true;
      }

      /// Damped Newton; returns true when the update fell below @p tolerance and the residual is small.
      bool
      newton(std::vector<double> &x, const double tolerance, unsigned int &iterations) const
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
    };

    /**
     * Least-squares fit of the multipliers η_0..η_N, σ, P to the H and η equations at the shape (ψ, r, H, S)
     * held in @p y, with η(0) = η(S) = 0 as heavily weighted rows; writes them into @p y. Solved with the
     * pseudo-inverse of LAPACK's singular value decomposition.
     */
    void
    fit_multipliers(const Collocation &problem, std::vector<double> &y)
    {
      const unsigned int               N = problem.N, m = 2 * N + 2, n = N + 3;
      const double                     S = y[problem.S()], Be = problem.Be;
      dealii::LAPACKFullMatrix<double> A(m, n);
      dealii::Vector<double>           b(m), fit(n);
      unsigned int                     row = 0;
      for (unsigned int j = 1; j <= N; ++j, ++row)
        {
          const double ps = y[problem.psi(j)], rj = y[problem.r(j)], Hj = y[problem.H(j)];
          const double k  = std::sin(ps) / rj;
          A(row, j)       = -S * Be * k;
          A(row, N + 2)   = S * Be * 0.5 * rj * std::cos(ps);
          b[row]          = -problem.derivative(y, problem.H(0), j);
          ++row;
          for (unsigned int i = 0; i <= N; ++i)
            A(row, i) = problem.D[j * (N + 1) + i];
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
        y[problem.eta(j)] = fit[j];
      y[problem.eta(0)]  = 0;
      y[problem.eta(N)]  = 0;
      y[problem.sigma()] = fit[N + 1];
      y[problem.P()]     = fit[N + 2];
    }

    /// Axis ratio c/a of the spheroid of @p branch with reduced volume @p v (bisection in log(c/a)).
    double
    spheroid_axis_ratio(const Branch branch, const double v)
    {
      double lo = 0, hi = std::log(50.);
      for (unsigned int it = 0; it < 64; ++it)
        {
          const double mid   = 0.5 * (lo + hi);
          const double ratio = std::exp(branch == Branch::prolate ? mid : -mid);
          if (exact_spheroid_measures(1, ratio).reduced_volume > v)
            lo = mid;
          else
            hi = mid;
        }
      return std::exp(branch == Branch::prolate ? lo : -lo);
    }

    /**
     * Initial guess of the resting shape: the spheroid of @p branch with reduced volume @p v, scaled to the
     * area A0, sampled at the collocation nodes by arc length, with the multipliers fitted by least squares.
     */
    std::vector<double>
    spheroid_state(const Collocation &problem, const Branch branch, const double v)
    {
      const unsigned int  N     = problem.N;
      const double        ratio = spheroid_axis_ratio(branch, v);
      const double        scale = std::sqrt(problem.A0 / exact_spheroid_measures(1, ratio).area);
      const double        a = scale, c = scale * ratio;
      const double        S = spheroid_meridian_length(a, c, 0.5 * pi);
      std::vector<double> y(problem.size_at_rest(), 0.);
      y[problem.S()] = S;
      for (unsigned int j = 0; j <= N; ++j)
        {
          // The polar angle θ of arc length s = S t_j, by Newton's method on the meridian length.
          const double s     = S * problem.nodes[j];
          double       theta = 0.5 * pi * problem.nodes[j];
          for (unsigned int it = 0; it < 50; ++it)
            {
              const double g =
                std::sqrt(a * a * std::cos(theta) * std::cos(theta) + c * c * std::sin(theta) * std::sin(theta));
              const double d = (spheroid_meridian_length(a, c, theta) - s) / g;
              theta -= d;
              if (std::abs(d) < 1e-15)
                break;
            }
          const double sn = std::sin(theta), cs = std::cos(theta);
          const double g  = std::sqrt(a * a * cs * cs + c * c * sn * sn);
          y[problem.psi(j)] = std::atan2(c * sn, a * cs);
          y[problem.r(j)]   = a * sn;
          y[problem.H(j)]   = a * c / (g * g * g) + c / (a * g);
        }
      y[problem.psi(0)] = 0;
      y[problem.r(0)]   = 0;
      y[problem.psi(N)] = 0.5 * pi;
      fit_multipliers(problem, y);
      return y;
    }

    /// The sphere of area A0: with σ = P = η = 0 it solves the collocation equations exactly.
    std::vector<double>
    sphere_state(const Collocation &problem)
    {
      const double        R_area = problem.sphere_radius();
      std::vector<double> x(problem.size_at_rest(), 0.);
      for (unsigned int j = 0; j <= problem.N; ++j)
        {
          x[problem.psi(j)] = 0.5 * pi * problem.nodes[j];
          x[problem.r(j)]   = R_area * std::sin(0.5 * pi * problem.nodes[j]);
          x[problem.H(j)]   = 2 / R_area;
        }
      x[problem.S()] = 0.5 * pi * R_area;
      return x;
    }

    /// The state @p y belongs to @p branch: its polar half height exceeds (prolate) or falls below (oblate)
    /// its largest radius.
    bool
    on_branch(const Collocation &problem, const Branch branch, const std::vector<double> &y)
    {
      double h = 0;
      for (unsigned int j = 0; j <= problem.N; ++j)
        h += problem.weights[j] * std::sin(y[problem.psi(j)]);
      h *= y[problem.S()];
      double rmax = 0;
      for (unsigned int j = 0; j <= problem.N; ++j)
        rmax = std::max(rmax, y[problem.r(j)]);
      return branch == Branch::prolate ? (h > rmax) : (h < rmax);
    }

    /// A continuation step is accepted only if Newton converged quickly and the shape moved little, so that
    /// the path cannot jump to another family of solutions.
    bool
    small_change(const Collocation         &problem,
                 const std::vector<double> &y0,
                 const std::vector<double> &y1,
                 const unsigned int         iterations)
    {
      double change = 0;
      for (unsigned int j = 0; j <= problem.N; ++j)
        change = std::max(change, std::abs(y1[problem.r(j)] - y0[problem.r(j)]));
      return iterations <= 10 && change <= 0.1 * problem.sphere_radius();
    }

    /// I_zz = ∫(x² + y²) dA of the state @p y.
    double
    inertia_zz_of(const Collocation &problem, const std::vector<double> &y)
    {
      double I = 0;
      for (unsigned int j = 0; j <= problem.N; ++j)
        I += problem.weights[j] * std::pow(y[problem.r(j)], 3);
      return 4 * pi * y[problem.S()] * I;
    }

    /**
     * The resting shape (ω = 0) of the reduced volume of @p prm: Newton from the spheroid directly, else by
     * continuation in v from near the sphere (v = 0.97).
     */
    std::vector<double>
    resting_shape(Collocation &problem, const Parameters &prm)
    {
      unsigned int iterations     = 0;
      problem.omega               = 0;
      problem.momentum_prescribed = false;
      problem.V0                  = problem.volume_at(prm.reduced_volume);
      std::vector<double> x       = spheroid_state(problem, prm.branch, prm.reduced_volume);
      if (problem.newton(x, prm.newton_tolerance, iterations) && on_branch(problem, prm.branch, x))
        return x;

      double v = std::max(prm.reduced_volume, 0.97), dv = 0.05;
      problem.V0 = problem.volume_at(v);
      x          = spheroid_state(problem, prm.branch, v);
      if (!problem.newton(x, prm.newton_tolerance, iterations) || !on_branch(problem, prm.branch, x))
        throw AxisymmetricEquilibrium::NoSolution(AxisymmetricEquilibrium::NoSolution::Stage::near_sphere,
                                                  1.0,
                                                  "AxisymmetricEquilibrium: no convergence near the sphere.");
      while (v > prm.reduced_volume)
        {
          const double        v_next = std::max(prm.reduced_volume, v - dv);
          std::vector<double> y      = x;
          problem.V0                 = problem.volume_at(v_next);
          if (problem.newton(y, prm.newton_tolerance, iterations) && on_branch(problem, prm.branch, y) &&
              small_change(problem, x, y, iterations))
            {
              x = y;
              v = v_next;
              dv *= 1.5;
            }
          else if ((dv *= 0.5) < 1e-5)
            throw AxisymmetricEquilibrium::NoSolution(AxisymmetricEquilibrium::NoSolution::Stage::reduced_volume,
                                                      v,
                                                      "AxisymmetricEquilibrium: continuation in the reduced volume "
                                                      "stalled at v = " + std::to_string(v) + ".");
        }
      return x;
    }

    /**
     * Continuation in ω² (or in L when the angular momentum is prescribed) from the resting state @p x to the
     * rotation of @p prm; @p x becomes the rotating state (with ω appended when L is prescribed). Returns ω.
     */
    double
    continue_in_rotation(Collocation &problem, const Parameters &prm, std::vector<double> &x)
    {
      const bool   by_L   = (prm.prescribed == AxisymmetricEquilibrium::Prescribed::angular_momentum);
      const double target = by_L ? prm.angular_momentum : prm.angular_velocity * prm.angular_velocity;
      if (by_L)
        {
          problem.momentum_prescribed = true;
          x.push_back(0.);
        }
      unsigned int iterations = 0;
      double       done = 0, step = target;
      while (done != target)
        {
          const double        next = (std::abs(target - done) <= std::abs(step) ? target : done + step);
          std::vector<double> y    = x;
          if (by_L)
            {
              problem.L0     = next;
              y[problem.w()] = next / inertia_zz_of(problem, x);
            }
          else
            problem.omega = std::sqrt(next);
          // On the branch that starts at rest I_zz grows with ω² (G = F − ½ω²I is minimal there) up to the
          // fold, where a continuation in ω cannot pass; a decrease means Newton jumped to another branch.
          if (problem.newton(y, prm.newton_tolerance, iterations) && on_branch(problem, prm.branch, y) &&
              small_change(problem, x, y, iterations) &&
              (by_L || inertia_zz_of(problem, y) >= (1 - 1e-12) * inertia_zz_of(problem, x)))
            {
              x    = y;
              done = next;
              step *= 1.5;
            }
          else if (std::abs(step *= 0.5) < 1e-6 * std::max(1., std::abs(target)))
            throw AxisymmetricEquilibrium::NoSolution(
              AxisymmetricEquilibrium::NoSolution::Stage::rotation,
              done,
              "AxisymmetricEquilibrium: continuation in the rotation stalled at " +
                std::string(by_L ? "L = " : "ω² = ") + std::to_string(done) +
                (by_L ? std::string(".") :
                        std::string(" (the branch of equilibria at fixed ω folds back near there; "
                                    "prescribing the angular momentum may continue it).")));
        }
      return by_L ? x[problem.w()] : prm.angular_velocity;
    }

    /**
     * Largest residual of the shape equations (the four collocated fields) at the state @p x, rotating with
     * @p omega, relative to the half length S.
     */
    double
    shape_equation_residual_of(Collocation &problem, const std::vector<double> &x, const double omega,
                               const double reduced_volume)
    {
      std::vector<double> R;
      problem.omega               = omega;
      problem.momentum_prescribed = false;
      problem.V0                  = problem.volume_at(std::min(1., reduced_volume));
      const std::vector<double> y(x.begin(), x.begin() + problem.size_at_rest());
      problem.residual(y, R);
      double residual = 0;
      for (unsigned int i = 0; i < 4 * (problem.N + 1); ++i)
        residual = std::max(residual, std::abs(R[i]));
      return residual / x[problem.S()];
    }
  } // namespace



  void
  AxisymmetricEquilibrium::declare_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Integer;
    using dealii::Patterns::List;
    prm.enter_subsection("equilibrium");
    prm.declare_entry("area", "12.566370614359172", RealRange::closed(1e-6, 1e6),
                      "Surface area A, 1e-6 ≤ A ≤ 1e6, of the equilibrium (4π is the area of the unit sphere).");
    prm.declare_entry("reduced volume", "0.75", RealRange::closed(0.15, 1),
                      "Reduced volume v = V / ((4π/3)(A/(4π))^{3/2}), v = 1 the sphere; the solver reaches "
                      "0.55 ≤ v ≤ 1 on the prolate branch and 0.15 ≤ v ≤ 1 on the oblate branch (smaller v are "
                      "refused: its continuation from the sphere stalls or takes minutes there).");
    prm.declare_entry("branch", "prolate", dealii::Patterns::Selection("prolate|oblate"),
                      "Branch of up-down symmetric shapes: prolate (elongated along the rotation axis z, "
                      "dumbbell-like at small v) or oblate (flattened, discocyte-like at small v).");
    prm.declare_entry("Be", "1", RealRange::closed(1e-2, 1e2),
                      "Bending capillary number Be, 0.01 ≤ Be ≤ 100 (the range in which the solver's Newton "
                      "converges); the bending energy is F_bend = (1/(2Be))∫H². The shape depends on Be·ω².");
    prm.declare_entry("angular velocity", "", List(RealRange::any(), 0, 1),
                      "Angular velocity ω (a finite number) of the rigid rotation u = ω e_z × X about z. Empty "
                      "means 0 unless 'angular momentum' is given; give at most one of the two.");
    prm.declare_entry("angular momentum", "", List(RealRange::any(), 0, 1),
                      "Angular momentum L (a finite number) = ω I_zz about z (I_zz = ∫(x²+y²)); when given, ω is "
                      "an unknown and the shape is a critical point of F_bend + L²/(2 I_zz). Empty: ω is "
                      "prescribed instead.");
    prm.declare_entry("output file", "equilibrium.csv", dealii::Patterns::FileName(),
                      "CSV file for the generating curve (columns s,r,z,psi,H; s arc length from the north "
                      "pole, ψ tangent angle, H = k_s + k_φ with H = −2/R on a sphere); its directory must exist.");
    prm.declare_entry("collocation points", "48", Integer(8, 512),
                      "N, 8 ≤ N ≤ 512: Chebyshev collocation points 0..N on the half generating curve (pole to "
                      "equator); the error decays exponentially in N (N = 512 takes about 15 s).");
    prm.declare_entry("maximal collocation points", "512", Integer(8, 512),
                      "N is doubled, up to this value (at least 'collocation points', at most 512), while the virial "
                      "identity 3Vγ = 2p0A + 2ω²I_zz (not imposed by the discretization) fails by more than 1e-9; "
                      "equal to 'collocation points' keeps N fixed.");
    prm.declare_entry("output points", "401", Integer(2, 100000),
                      "Number of rows of the CSV, 2 to 100000, equispaced in arc length s from pole to pole.");
    prm.declare_entry("Newton tolerance", "1e-12", RealRange::closed(1e-14, 1e-6),
                      "Newton stops when the largest update relative to the largest unknown is below this "
                      "(1e-14 to 1e-6: below, rounding keeps Newton from converging; above, the start near the "
                      "sphere is not accepted as converged).");
    prm.leave_subsection();
  }



  void
  AxisymmetricEquilibrium::parse_parameters(dealii::ParameterHandler &handler)
  {
    handler.enter_subsection("equilibrium");
    Parameters p;
    p.area           = handler.get_double("area");
    p.reduced_volume = handler.get_double("reduced volume");
    p.branch         = (handler.get("branch") == "oblate" ? Branch::oblate : Branch::prolate);
    p.bending_number = handler.get_double("Be");
    const std::string omega_text = handler.get("angular velocity");
    const std::string L_text     = handler.get("angular momentum");
    const std::string v_text     = handler.get("reduced volume");
    p.output_file                = handler.get("output file");
    p.collocation_points         = handler.get_integer("collocation points");
    p.maximal_collocation_points = handler.get_integer("maximal collocation points");
    p.output_points              = handler.get_integer("output points");
    p.newton_tolerance           = handler.get_double("Newton tolerance");
    handler.leave_subsection();

    const auto blank = [](const std::string &s) { return s.find_first_not_of(" \t") == std::string::npos; };
    if (p.branch == Branch::prolate && p.reduced_volume < 0.55)
      throw_invalid_entry("equilibrium/reduced volume", v_text,
                          "0.55 ≤ v ≤ 1 on the prolate branch (0.15 ≤ v ≤ 1 on the oblate branch)");
    if (!blank(omega_text) && !blank(L_text))
      throw_invalid_entry("equilibrium/angular momentum", L_text,
                          "an empty value when 'angular velocity' is given (prescribe ω or L, not both)");
    if (p.maximal_collocation_points < p.collocation_points)
      throw_invalid_entry("equilibrium/maximal collocation points", std::to_string(p.maximal_collocation_points),
                          "at least 'collocation points' = " + std::to_string(p.collocation_points));
    {
      const std::filesystem::path file(p.output_file), directory = file.parent_path();
      if (file.filename().empty() || std::filesystem::is_directory(file) ||
          !(directory.empty() || std::filesystem::is_directory(directory)))
        throw_invalid_entry("equilibrium/output file", p.output_file,
                            "a file name in an existing directory");
    }
    if (!blank(L_text))
      {
        p.prescribed       = Prescribed::angular_momentum;
        p.angular_momentum = dealii::Utilities::string_to_double(L_text);
      }
    else
      {
        p.prescribed       = Prescribed::angular_velocity;
        p.angular_velocity = blank(omega_text) ? 0. : dealii::Utilities::string_to_double(omega_text);
      }
    const bool rotating = (p.prescribed == Prescribed::angular_momentum ? p.angular_momentum != 0 : p.angular_velocity != 0);
    if (p.reduced_volume >= 1 && rotating)
      throw_invalid_entry("equilibrium/reduced volume", v_text,
                          "a value below 1 for a rotating shape (at v = 1 only the sphere is admissible, and a "
                          "rotating sphere is not an equilibrium)");
    prm = p;
  }



  AxisymmetricEquilibrium::AxisymmetricEquilibrium(const Parameters &parameters)
    : prm(parameters)
  {}




  void
  AxisymmetricEquilibrium::solve()
  {
    // Double N until the scaling identity, which the discretization does not impose, holds to 1e-9.
    for (unsigned int N = prm.collocation_points;; N *= 2)
      {
        solve_collocation(N);
        if (virial_residual() < 1e-9 || 2 * N > prm.maximal_collocation_points)
          break;
      }
  }



  void
  AxisymmetricEquilibrium::set_collocation_nodes(const unsigned int N)
  {
    nodes.resize(N + 1);
    barycentric_weights.resize(N + 1);
    quadrature_weights.assign(N + 1, 0.);
    for (unsigned int j = 0; j <= N; ++j)
      {
        nodes[j]               = 0.5 * (1 - std::cos(pi * j / N));
        barycentric_weights[j] = ((j % 2) ? -1. : 1.) * ((j == 0 || j == N) ? 0.5 : 1.);
      }
    // Clenshaw–Curtis weights on [0, 1].
    for (unsigned int j = 0; j <= N; ++j)
      {
        const double theta = pi * j / N;
        if (j == 0 || j == N)
          {
            quadrature_weights[j] = 0.5 * ((N % 2 == 0) ? 1. / (N * N - 1.) : 1. / (N * N));
            continue;
          }
        double v = 1;
        if (N % 2 == 0)
          {
            for (unsigned int k = 1; k < N / 2; ++k)
              v -= 2 * std::cos(2 * k * theta) / (4. * k * k - 1);
            v -= std::cos(N * theta) / (N * N - 1.);
          }
        else
          for (unsigned int k = 1; k <= (N - 1) / 2; ++k)
            v -= 2 * std::cos(2 * k * theta) / (4. * k * k - 1);
        quadrature_weights[j] = 0.5 * 2 * v / N;
      }
  }



  void
  AxisymmetricEquilibrium::solve_collocation(const unsigned int N)
  {
    set_collocation_nodes(N);
    Collocation problem(nodes, barycentric_weights, quadrature_weights);
    problem.Be = prm.bending_number;
    problem.A0 = prm.area;

    std::vector<double> x;
    if (prm.reduced_volume >= 1 - 1e-14)
      {
        if ((prm.prescribed == Prescribed::angular_momentum ? prm.angular_momentum : prm.angular_velocity) != 0)
          throw std::runtime_error("AxisymmetricEquilibrium: at reduced volume 1 only the sphere at rest exists.");
        x     = sphere_state(problem);
        omega = 0;
      }
    else
      {
        x     = resting_shape(problem, prm);
        omega = continue_in_rotation(problem, prm, x);
      }

    psi.assign(x.begin() + problem.psi(0), x.begin() + problem.psi(0) + N + 1);
    r.assign(x.begin() + problem.r(0), x.begin() + problem.r(0) + N + 1);
    curvature.assign(x.begin() + problem.H(0), x.begin() + problem.H(0) + N + 1);
    eta.assign(x.begin() + problem.eta(0), x.begin() + problem.eta(0) + N + 1);
    // The pole and equator conditions hold to rounding; make them exact for the interpolants.
    psi.front() = r.front() = eta.front() = eta.back() = 0;
    psi.back()  = 0.5 * pi;
    half_length = x[problem.S()];
    sigma       = x[problem.sigma()];
    pressure    = x[problem.P()];
    residual_value = shape_equation_residual_of(problem, x, omega, prm.reduced_volume);
    postprocess();
  }



  void
  AxisymmetricEquilibrium::postprocess()
  {
    const unsigned int N = nodes.size() - 1;
    const double       S = half_length;
    // z' = −sin ψ with z(S) = 0: the differentiation matrix with its last row replaced by the condition.
    Collocation                      problem(nodes, barycentric_weights, quadrature_weights);
    dealii::LAPACKFullMatrix<double> M(N + 1, N + 1);
    dealii::Vector<double>           rhs(N + 1);
    for (unsigned int j = 0; j <= N; ++j)
      {
        for (unsigned int i = 0; i <= N; ++i)
          M(j, i) = (j == N ? (i == N ? 1. : 0.) : problem.D[j * (N + 1) + i]);
        rhs[j] = (j == N ? 0. : -S * std::sin(psi[j]));
      }
    M.compute_lu_factorization();
    M.solve(rhs);
    z.assign(rhs.begin(), rhs.end());

    area_value = volume_value = inertia_value = bending_value = 0;
    for (unsigned int j = 0; j <= N; ++j)
      {
        const double w = quadrature_weights[j] * S;
        area_value += 4 * pi * w * r[j];
        volume_value += 2 * pi * w * r[j] * r[j] * std::sin(psi[j]);
        inertia_value += 4 * pi * w * r[j] * r[j] * r[j];
        bending_value += 0.5 / prm.bending_number * 4 * pi * w * curvature[j] * curvature[j] * r[j];
      }
  }



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



  void
  AxisymmetricEquilibrium::print(std::ostream &out) const
  {
    const auto flags = out.flags();
    const auto precision = out.precision();
    out << std::setprecision(12);
    out << "branch: " << (prm.branch == Branch::prolate ? "prolate" : "oblate") << '\n'
        << "Be: " << prm.bending_number << '\n'
        << "bending energy: " << bending_energy() << '\n'
        << "kinetic energy: " << kinetic_energy() << '\n'
        << "total energy: " << bending_energy() + kinetic_energy() << '\n'
        << "inertia zz: " << inertia_zz() << '\n'
        << "angular velocity: " << angular_velocity() << '\n'
        << "angular momentum: " << angular_momentum() << '\n'
        << "p0: " << p0() << '\n'
        << "gamma: " << gamma() << '\n'
        << "area: " << area() << '\n'
        << "volume: " << volume() << '\n'
        << "reduced volume: " << reduced_volume() << '\n'
        << "equatorial radius: " << equatorial_radius() << '\n'
        << "polar half height: " << polar_height() << '\n'
        << "max radius: " << max_radius() << '\n'
        << "curve length: " << curve_length() << '\n'
        << "collocation points: " << n_collocation_used() << '\n'
        << std::setprecision(2) << std::scientific
        << "virial residual: " << virial_residual() << '\n'
        << "shape equation residual: " << shape_equation_residual() << '\n';
    out.flags(flags);
    out.precision(precision);
  }



  double
  AxisymmetricEquilibrium::bending_energy() const
  {
    return bending_value;
  }

  double
  AxisymmetricEquilibrium::inertia_zz() const
  {
    return inertia_value;
  }

  double
  AxisymmetricEquilibrium::angular_velocity() const
  {
    return omega;
  }

  double
  AxisymmetricEquilibrium::angular_momentum() const
  {
    return omega * inertia_value;
  }

  double
  AxisymmetricEquilibrium::kinetic_energy() const
  {
    return 0.5 * omega * omega * inertia_value;
  }

  double
  AxisymmetricEquilibrium::p0() const
  {
    return -sigma;
  }

  double
  AxisymmetricEquilibrium::gamma() const
  {
    return -pressure;
  }

  double
  AxisymmetricEquilibrium::equatorial_radius() const
  {
    return r.back();
  }

  double
  AxisymmetricEquilibrium::polar_height() const
  {
    return z.front();
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

  double
  AxisymmetricEquilibrium::area() const
  {
    return area_value;
  }

  double
  AxisymmetricEquilibrium::volume() const
  {
    return volume_value;
  }

  double
  AxisymmetricEquilibrium::reduced_volume() const
  {
    return reduced_volume_of(area_value, volume_value);
  }

  double
  AxisymmetricEquilibrium::curve_length() const
  {
    return 2 * half_length;
  }

  double
  AxisymmetricEquilibrium::virial_residual() const
  {
    const double lhs = 3 * volume_value * gamma();
    const double rhs = 2 * p0() * area_value + 2 * omega * omega * inertia_value;
    return std::abs(lhs - rhs) / std::max({std::abs(lhs), std::abs(rhs), bending_value});
  }

  double
  AxisymmetricEquilibrium::shape_equation_residual() const
  {
    return residual_value;
  }



  void
  solve_equilibrium_of_entries(AxisymmetricEquilibrium &equilibrium)
  {
    try
      {
        equilibrium.solve();
      }
    catch (const AxisymmetricEquilibrium::NoSolution &exc)
      {
        using Stage                                  = AxisymmetricEquilibrium::NoSolution::Stage;
        const AxisymmetricEquilibrium::Parameters &p = equilibrium.parameters();
        const auto text = [](const double x) {
          std::ostringstream out;
          out << std::setprecision(10) << x;
          return out.str();
        };
        const std::string branch = (p.branch == AxisymmetricEquilibrium::Branch::prolate ? "prolate" : "oblate");
        const std::string where  = " on the " + branch + " branch at A = " + text(p.area) +
                                  ", v = " + text(p.reduced_volume) + ", Be = " + text(p.bending_number);
        const bool by_L = (p.prescribed == AxisymmetricEquilibrium::Prescribed::angular_momentum);
        if (exc.stage == Stage::rotation && by_L)
          throw_invalid_entry("equilibrium/angular momentum", text(p.angular_momentum),
                              "an angular momentum that the continuation from rest reaches" + where +
                                "; it stalled at L = " + text(exc.reached));
        if (exc.stage == Stage::rotation)
          throw_invalid_entry("equilibrium/angular velocity", text(p.angular_velocity),
                              "an angular velocity below the fold of the branch" + where + "; the continuation in ω² "
                                "stalled at ω² = " + text(exc.reached) + " (prescribing the angular momentum instead "
                                "may continue past the fold)");
        if (exc.stage == Stage::reduced_volume)
          throw_invalid_entry("equilibrium/reduced volume", text(p.reduced_volume),
                              "a reduced volume that the continuation from the sphere reaches" + where +
                                "; it stalled at v = " + text(exc.reached));
        throw InputError((parameter_file_name().empty() ? std::string("parameters") : parameter_file_name()) +
                         ": entries 'equilibrium/area' = '" + text(p.area) + "' and 'equilibrium/Be' = '" +
                         text(p.bending_number) + "': Newton found no equilibrium near the sphere" + where +
                         "; expected an area and Be nearer to the scaling A = 4π, Be = 1.");
      }
  }

  int
  run_equilibrium_command(const std::string &parameter_file, std::ostream &out)
  {
    dealii::ParameterHandler prm;
    AxisymmetricEquilibrium::declare_parameters(prm);
    parse_parameter_file(prm, parameter_file);
    AxisymmetricEquilibrium equilibrium;
    equilibrium.parse_parameters(prm);
    solve_equilibrium_of_entries(equilibrium);
    equilibrium.print(out);
    equilibrium.write_curve_csv(equilibrium.parameters().output_file);
    out << "output file: " << equilibrium.parameters().output_file << '\n';
    return 0;
  }
} // namespace FluidSurface
