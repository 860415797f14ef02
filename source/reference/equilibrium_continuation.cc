// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/geometry/exact_geometry.h>
#include <fluid_surface/reference/equilibrium_continuation.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace FluidSurface::EquilibriumContinuation
{
  namespace
  {
    constexpr double pi = dealii::numbers::PI;

    using Branch = AxisymmetricEquilibrium::Branch;

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
    spheroid_state(const GeneratingCurveCollocation &problem, const Branch branch, const double v)
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
      problem.fit_multipliers(y);
      return y;
    }


    /// The state @p y belongs to @p branch: its polar half height exceeds (prolate) or falls below (oblate)
    /// its largest radius.
    bool
    on_branch(const GeneratingCurveCollocation &problem, const Branch branch, const std::vector<double> &y)
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
    small_change(const GeneratingCurveCollocation &problem,
                 const std::vector<double>        &y0,
                 const std::vector<double>        &y1,
                 const unsigned int                iterations)
    {
      double change = 0;
      for (unsigned int j = 0; j <= problem.N; ++j)
        change = std::max(change, std::abs(y1[problem.r(j)] - y0[problem.r(j)]));
      return iterations <= 10 && change <= 0.1 * problem.sphere_radius();
    }

    /// I_zz = ∫(x² + y²) dA of the state @p y.
    double
    inertia_zz_of(const GeneratingCurveCollocation &problem, const std::vector<double> &y)
    {
      double I = 0;
      for (unsigned int j = 0; j <= problem.N; ++j)
        I += problem.weights[j] * std::pow(y[problem.r(j)], 3);
      return 4 * pi * y[problem.S()] * I;
    }
  } // namespace

  std::vector<double>
  sphere_state(const GeneratingCurveCollocation &problem)
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

  std::vector<double>
  resting_shape(GeneratingCurveCollocation &problem, const AxisymmetricEquilibrium::Parameters &prm)
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

  double
  continue_in_rotation(GeneratingCurveCollocation                &problem,
                       const AxisymmetricEquilibrium::Parameters &prm,
                       std::vector<double>                       &x)
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
} // namespace FluidSurface::EquilibriumContinuation
