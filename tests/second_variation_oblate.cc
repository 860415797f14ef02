// SPDX-License-Identifier: LGPL-2.1-or-later
// The second variation at the spinning oblate of v = 0.95, L = 20 (A = 4π, Be = 1), doc/stability.md:
// (1) `fluid_surface --equilibrium` with modes 0..3, 2 eigenvalues, 16 basis functions per parity: the lowest
//     eigenvalues (8 digits; they agree with 24 and 32 basis functions to 1e-9), isolated and driven. The lowest,
//     m = 2 even, is negative: the spinning oblate is a saddle at fixed A, V and L.
// (2) Rigid motions through SecondVariation::quadratic_form, against the rigid-body values: the tilt f = (r cos ψ −
//     z sin ψ) cos φ (a rotation about y) has δ²E = L²(1/I_xx − 1/I_zz) isolated and ω²(I_zz − I_xx) driven
//     (I_xx = ½I_zz + ∫z² dA by an independent quadrature); the translations along x (m = 1) and z (m = 0) are
//     neutral, δ²E = 0.
// (3) NormalGraphExpansion against finite differences of the exact perturbed densities (central differences at
//     h = 1e-3 and 5e-4, Richardson-extrapolated), at five points of the curve for m = 0..3: the ε and ε²
//     coefficients agree to 1e-8 relative to the densities.
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>

#include <fluid_surface/reference/axisymmetric_equilibrium.h>
#include <fluid_surface/reference/normal_graph_expansion.h>
#include <fluid_surface/reference/second_variation.h>
#include <fluid_surface/scenes/run_program.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

using namespace FluidSurface;

namespace
{
  constexpr double pi = dealii::numbers::PI;

  /// (1): the report's second-variation lines, eigenvalues to 8 significant digits.
  void
  report_spectrum()
  {
    std::ofstream("oblate.prm") << "subsection equilibrium\n  set reduced volume = 0.95\n  set branch = oblate\n"
                                   "  set angular momentum = 20\n  set output file = curve.csv\nend\n"
                                   "subsection second variation\n  set modes = 0, 1, 2, 3\n  set eigenvalues = 2\n"
                                   "  set basis size = 16\nend\n";
    std::ostringstream screen, errors;
    const int          status = run_program({"--equilibrium", "oblate.prm"}, screen, errors, MPI_COMM_WORLD);
    std::cout << "exit status " << status << errors.str() << std::endl;
    std::istringstream report(screen.str());
    for (std::string line; std::getline(report, line);)
      if (line.rfind("angular velocity:", 0) == 0 || line.rfind("second variation isolated", 0) == 0 ||
          line.rfind("second variation driven", 0) == 0)
        {
          const std::size_t  colon = line.find(':');
          std::istringstream values(line.substr(colon + 1));
          std::cout << line.substr(0, colon + 1) << std::setprecision(8);
          for (double value; values >> value;)
            std::cout << ' ' << value;
          std::cout << std::endl;
        }
  }

  /// ∫z² dA of @p equilibrium by Gauss–Legendre quadrature in arc length.
  double
  second_moment_z(const AxisymmetricEquilibrium &equilibrium)
  {
    const dealii::QGauss<1> gauss(200);
    double                  sum = 0;
    for (unsigned int q = 0; q < gauss.size(); ++q)
      {
        const double              s = equilibrium.curve_length() * gauss.point(q)[0];
        const std::vector<double> c = equilibrium.curve_point(s);
        sum += equilibrium.curve_length() * gauss.weight(q) * 2 * pi * c[0] * c[1] * c[1];
      }
    return sum;
  }

  /// (2): the rigid motions.
  void
  check_rigid_motions(const AxisymmetricEquilibrium &equilibrium)
  {
    using Energy     = SecondVariation::Energy;
    const double Izz = equilibrium.inertia_zz(), Ixx = 0.5 * Izz + second_moment_z(equilibrium);
    const double L = equilibrium.angular_momentum(), omega = equilibrium.angular_velocity();
    // (ψ, k, k', r, z) at s.
    const auto tilt = [&](const double s) {
      const std::vector<double>   c = equilibrium.curve_point(s);
      const std::array<double, 2> k = equilibrium.meridian_curvature(s);
      const double a = c[0] * std::cos(c[2]) - c[1] * std::sin(c[2]), p = c[0] * std::sin(c[2]) + c[1] * std::cos(c[2]);
      return std::array<double, 3>{{a, 1 - k[0] * p, -k[1] * p - k[0] * k[0] * a}};
    };
    const auto shift_x = [&](const double s) {
      const std::vector<double>   c = equilibrium.curve_point(s);
      const std::array<double, 2> k = equilibrium.meridian_curvature(s);
      return std::array<double, 3>{{std::sin(c[2]), k[0] * std::cos(c[2]),
                                    k[1] * std::cos(c[2]) - k[0] * k[0] * std::sin(c[2])}};
    };
    const auto shift_z = [&](const double s) {
      const std::vector<double>   c = equilibrium.curve_point(s);
      const std::array<double, 2> k = equilibrium.meridian_curvature(s);
      return std::array<double, 3>{{std::cos(c[2]), -k[0] * std::sin(c[2]),
                                    -k[1] * std::sin(c[2]) - k[0] * k[0] * std::cos(c[2])}};
    };
    const double isolated = SecondVariation::quadratic_form(equilibrium, 1, Energy::isolated, tilt)[0];
    const double driven   = SecondVariation::quadratic_form(equilibrium, 1, Energy::driven, tilt)[0];
    const double isolated_exact = L * L * (1 / Ixx - 1 / Izz), driven_exact = omega * omega * (Izz - Ixx);
    std::cout << std::setprecision(8) << "tilt isolated: " << isolated << " (rigid body " << isolated_exact
              << ")\ntilt driven: " << driven << " (rigid body " << driven_exact << ")" << std::endl;
    double translation = 0;
    for (const Energy energy : {Energy::isolated, Energy::driven})
      translation = std::max({translation,
                              std::abs(SecondVariation::quadratic_form(equilibrium, 1, energy, shift_x)[0]),
                              std::abs(SecondVariation::quadratic_form(equilibrium, 0, energy, shift_z)[0])});
    std::cout << "translations x and z neutral (|δ²E| < 1e-8): " << (translation < 1e-8 ? "yes" : "no") << std::endl;
  }

  /// (3): the Taylor coefficients of NormalGraphExpansion against finite differences.
  void
  check_expansion(const AxisymmetricEquilibrium &equilibrium)
  {
    namespace NG                = NormalGraphExpansion;
    const std::array<double, 3> v{{0.3, -0.7, 1.1}};
    const double                h = 1e-3;
    double                      largest = 0;
    for (const double fraction : {0.03, 0.2, 0.45, 0.5, 0.8})
      for (unsigned int m = 0; m <= 3; ++m)
        {
          const double                s = fraction * equilibrium.curve_length();
          const std::vector<double>   c = equilibrium.curve_point(s);
          const std::array<double, 2> k = equilibrium.meridian_curvature(s);
          const NG::CurvePoint        point{c[0], c[1], c[2], k[0], k[1]};
          const NG::LocalExpansion    e = NG::expand(point, m, 2 * m + 4);
          // Central differences at h and h/2, combined by Richardson extrapolation (error O(h⁴)).
          std::array<std::array<double, NG::n_functionals>, 2> first, second;
          for (unsigned int level = 0; level < 2; ++level)
            {
              const double step = h / (1 + level);
              const auto   plus = NG::evaluate(point, m, 2 * m + 4, v, step), minus = NG::evaluate(point, m, 2 * m + 4, v, -step);
              for (unsigned int f = 0; f < NG::n_functionals; ++f)
                {
                  first[level][f]  = (plus[f] - minus[f]) / (2 * step);
                  second[level][f] = (plus[f] - 2 * e.value[f] + minus[f]) / (2 * step * step);
                }
            }
          for (unsigned int f = 0; f < NG::n_functionals; ++f)
            {
              double linear = 0, quadratic = 0;
              for (unsigned int i = 0; i < 3; ++i)
                {
                  linear += e.linear[f][i] * v[i];
                  for (unsigned int j = 0; j < 3; ++j)
                    quadratic += v[i] * e.quadratic[f][i][j] * v[j];
                }
              // Relative to the area density: some functionals vanish (∫y dA for cos mφ).
              const double scale = std::abs(e.value[f]) + std::abs(linear) + std::abs(quadratic) + e.value[NG::area];
              largest = std::max({largest, std::abs((4 * first[1][f] - first[0][f]) / 3 - linear) / scale,
                                  std::abs((4 * second[1][f] - second[0][f]) / 3 - quadratic) / scale});
            }
        }
    std::cout << "expansion against finite differences within 1e-8: " << (largest < 1e-8 ? "yes" : "no") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  report_spectrum();

  AxisymmetricEquilibrium::Parameters parameters;
  parameters.reduced_volume   = 0.95;
  parameters.branch           = AxisymmetricEquilibrium::Branch::oblate;
  parameters.prescribed       = AxisymmetricEquilibrium::Prescribed::angular_momentum;
  parameters.angular_momentum = 20;
  AxisymmetricEquilibrium equilibrium(parameters);
  equilibrium.solve();
  check_rigid_motions(equilibrium);
  check_expansion(equilibrium);
}
