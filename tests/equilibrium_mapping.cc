// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/quadrature_lib.h>
// Geometry access of the rotating equilibria (v 0.75, Be ω² = 4, A = 4π): the surface X(θ, φ) =
// map_from_sphere(unit sphere point) integrated by a tensor-product Gauss (θ) × trapezoidal (φ) rule gives
// area() and volume() (V = ⅓∫X·ν); the polar representation meridian_radius(α) gives the volume
// (2π/3)∫ρ³ sin α dα, agrees with |X| along the x–z meridian, is mirror symmetric, and yields the
// equatorial radius and polar half height.
#include <fluid_surface/reference/axisymmetric_equilibrium.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace FluidSurface;
using Equilibrium = AxisymmetricEquilibrium;

namespace
{
  const double pi = 3.14159265358979323846;

  /// Gauss–Legendre points and weights on [0, 1].
  void
  gauss(const unsigned int n, std::vector<double> &x, std::vector<double> &w)
  {
    const dealii::QGauss<1> rule(n);
    x.resize(n);
    w.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        x[i] = rule.point(i)[0];
        w[i] = rule.weight(i);
      }
  }

  dealii::Point<3>
  on_sphere(const double theta, const double phi)
  {
    return dealii::Point<3>(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  }
} // namespace

int
main()
{
  std::vector<double> xq, wq;
  gauss(96, xq, wq);
  for (const Equilibrium::Branch branch : {Equilibrium::Branch::prolate, Equilibrium::Branch::oblate})
    {
      Equilibrium::Parameters parameters;
      parameters.branch           = branch;
      parameters.angular_velocity = 2;
      Equilibrium equilibrium(parameters);
      equilibrium.solve();

      // X_θ and X_φ by fourth-order central differences of the map.
      const unsigned int n_phi = 8;
      const double       h     = 1e-3;
      double             area = 0, volume = 0;
      for (unsigned int q = 0; q < xq.size(); ++q)
        for (unsigned int k = 0; k < n_phi; ++k)
          {
            const double theta = pi * xq[q], phi = 2 * pi * k / n_phi;
            const auto   X     = [&](const double t, const double p) { return equilibrium.map_from_sphere(on_sphere(t, p)); };
            const dealii::Tensor<1, 3> X_theta =
              (-X(theta + 2 * h, phi) + 8 * X(theta + h, phi) - 8 * X(theta - h, phi) + X(theta - 2 * h, phi)) / (12 * h);
            const dealii::Tensor<1, 3> X_phi =
              (-X(theta, phi + 2 * h) + 8 * X(theta, phi + h) - 8 * X(theta, phi - h) + X(theta, phi - 2 * h)) / (12 * h);
            const dealii::Tensor<1, 3> normal = dealii::cross_product_3d(X_theta, X_phi);
            const double               weight = pi * wq[q] * 2 * pi / n_phi;
            area += normal.norm() * weight;
            volume += X(theta, phi) * normal / 3 * weight;
          }

      double polar_volume = 0, mismatch = 0, asymmetry = 0;
      for (unsigned int q = 0; q < xq.size(); ++q)
        {
          const double alpha = pi * xq[q], rho = equilibrium.meridian_radius(alpha);
          polar_volume += 2 * pi / 3 * rho * rho * rho * std::sin(alpha) * pi * wq[q];
          asymmetry = std::max({asymmetry, std::abs(rho - equilibrium.meridian_radius(pi - alpha)),
                                std::abs(rho - equilibrium.meridian_radius(2 * pi - alpha))});
          // The point of the x–z meridian at polar angle θ: its own polar angle and distance.
          const dealii::Point<3> X = equilibrium.map_from_sphere(on_sphere(alpha, 0));
          mismatch = std::max(mismatch, std::abs(X.norm() - equilibrium.meridian_radius(std::atan2(X[0], X[2]))));
        }

      std::printf("%s: area %.9f (area() %.9f)  volume %.9f (volume() %.9f)  polar-radius volume %.9f\n",
                  branch == Equilibrium::Branch::prolate ? "prolate" : "oblate ", area, equilibrium.area(), volume,
                  equilibrium.volume(), polar_volume);
      std::printf("    relative differences below 1e-9: %s\n",
                  std::abs(area / equilibrium.area() - 1) < 1e-9 && std::abs(volume / equilibrium.volume() - 1) < 1e-9 &&
                      std::abs(polar_volume / equilibrium.volume() - 1) < 1e-9 ? "yes" : "no");
      std::printf("    |X| = meridian_radius along the meridian to 1e-12: %s  mirror symmetric to 1e-12: %s\n",
                  mismatch < 1e-12 ? "yes" : "no", asymmetry < 1e-12 ? "yes" : "no");
      std::printf("    meridian_radius(pi/2) - equatorial radius %.1e  meridian_radius(0) - polar half height %.1e\n",
                  std::abs(equilibrium.meridian_radius(pi / 2) - equilibrium.equatorial_radius()),
                  std::abs(equilibrium.meridian_radius(0) - equilibrium.polar_height()));
    }
}
