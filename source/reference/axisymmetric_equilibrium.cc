// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fluid_surface/geometry/exact_geometry.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/reference/axisymmetric_equilibrium.h>
#include <fluid_surface/reference/equilibrium_continuation.h>
#include <fluid_surface/reference/generating_curve_collocation.h>
#include <fluid_surface/reference/second_variation.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace FluidSurface
{
  namespace
  {
    constexpr double pi = dealii::numbers::PI;

    /**
     * Largest residual of the shape equations (the four collocated fields) at the state @p x, rotating with
     * @p omega, relative to the half length S.
     */
    double
    shape_equation_residual_of(GeneratingCurveCollocation &problem, const std::vector<double> &x, const double omega,
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
    GeneratingCurveCollocation problem(nodes, barycentric_weights, quadrature_weights);
    problem.Be = prm.bending_number;
    problem.A0 = prm.area;

    std::vector<double> x;
    if (prm.reduced_volume >= 1 - 1e-14)
      {
        if ((prm.prescribed == Prescribed::angular_momentum ? prm.angular_momentum : prm.angular_velocity) != 0)
          throw std::runtime_error("AxisymmetricEquilibrium: at reduced volume 1 only the sphere at rest exists.");
        x     = EquilibriumContinuation::sphere_state(problem);
        omega = 0;
      }
    else
      {
        x     = EquilibriumContinuation::resting_shape(problem, prm);
        omega = EquilibriumContinuation::continue_in_rotation(problem, prm, x);
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
    GeneratingCurveCollocation       problem(nodes, barycentric_weights, quadrature_weights);
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

    // k_s = H − sin ψ / r from the ψ equation (at the pole k_s = k_φ = H/2), then k_s' by one differentiation.
    meridian_curvature_values.resize(N + 1);
    meridian_curvature_slopes.assign(N + 1, 0.);
    for (unsigned int j = 0; j <= N; ++j)
      meridian_curvature_values[j] = (j == 0 ? 0.5 * curvature[0] : curvature[j] - std::sin(psi[j]) / r[j]);
    for (unsigned int j = 0; j <= N; ++j)
      for (unsigned int i = 0; i <= N; ++i)
        meridian_curvature_slopes[j] += problem.D[j * (N + 1) + i] * meridian_curvature_values[i] / S;

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
    SecondVariation::declare_parameters(prm);
    parse_parameter_file(prm, parameter_file);
    AxisymmetricEquilibrium equilibrium;
    equilibrium.parse_parameters(prm);
    SecondVariation second_variation;
    second_variation.parse_parameters(prm);
    solve_equilibrium_of_entries(equilibrium);
    equilibrium.print(out);
    equilibrium.write_curve_csv(equilibrium.parameters().output_file);
    out << "output file: " << equilibrium.parameters().output_file << '\n';
    if (second_variation.active())
      {
        second_variation.compute(equilibrium);
        second_variation.print(out);
        const std::string &file = second_variation.parameters().eigenfunction_file;
        if (!file.empty())
          {
            second_variation.write_eigenfunctions_csv(file);
            out << "second variation eigenfunction file: " << file << '\n';
          }
      }
    return 0;
  }
} // namespace FluidSurface
