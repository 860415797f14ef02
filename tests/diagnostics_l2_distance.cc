// SPDX-License-Identifier: LGPL-2.1-or-later
// E(L²) (seed eq. 8) and e(λ) against exact answers:
// (1) the sections of a Q2 unit sphere against a sphere of radius 1.1: E = √(2π)·0.1 for both sections;
// (2) a surface mapped onto the prolate rotating equilibrium (A = 4π, v = 0.75, ω = 2) against that
//     equilibrium: E → 0 under refinement (the sections are exact intersections with the discrete surface);
// (3) e(λ) of the triaxial ellipsoid [1, 0.8, 0.6] against its inertia eigenvalues by tensor-product
//     quadrature (Gauss–Legendre in θ, trapezoidal in φ; exact to rounding).
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include "surface_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace FluidSurface;

namespace
{
  /// Inertia eigenvalues (ascending) of the ellipsoid surface with semi-axes a, b, c about its centre.
  std::array<double, 3>
  ellipsoid_inertia(const double a, const double b, const double c)
  {
    const dealii::QGauss<1> gauss(200);
    const unsigned int      n_phi = 400;
    double                  I[3]  = {0, 0, 0};
    for (unsigned int q = 0; q < gauss.size(); ++q)
      for (unsigned int k = 0; k < n_phi; ++k)
        {
          const double theta = dealii::numbers::PI * gauss.point(q)[0], phi = 2 * dealii::numbers::PI * k / n_phi;
          const dealii::Tensor<1, 3> x({a * std::sin(theta) * std::cos(phi), b * std::sin(theta) * std::sin(phi),
                                        c * std::cos(theta)});
          const dealii::Tensor<1, 3> x_theta({a * std::cos(theta) * std::cos(phi), b * std::cos(theta) * std::sin(phi),
                                              -c * std::sin(theta)});
          const dealii::Tensor<1, 3> x_phi({-a * std::sin(theta) * std::sin(phi), b * std::sin(theta) * std::cos(phi), 0.});
          const double dA = dealii::cross_product_3d(x_theta, x_phi).norm() * dealii::numbers::PI * gauss.weight(q) *
                            2 * dealii::numbers::PI / n_phi;
          for (unsigned int d = 0; d < 3; ++d)
            I[d] += (x.norm_square() - x[d] * x[d]) * dA;
        }
    std::array<double, 3> lambda{I[0], I[1], I[2]};
    std::sort(lambda.begin(), lambda.end());
    return lambda;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const dealii::Tensor<1, 3>               ex({1., 0., 0.}), ey({0., 1., 0.}), ez({0., 0., 1.});

  std::printf("(1) unit sphere against radius 1.1: exact E = %.10f\n", std::sqrt(2 * dealii::numbers::PI) * 0.1);
  for (unsigned int r = 2; r <= 3; ++r)
    {
      SurfaceRun                run("sphere", "1, 1, 1", r);
      const std::vector<double> axial = section_polar_radius(run.geometry, dealii::Point<3>(), ez, ex, 256);
      const std::vector<double> equatorial = section_polar_radius(run.geometry, dealii::Point<3>(), ex, ey, 256);
      double                    max_error = 0;
      for (const double rho : axial)
        max_error = std::max(max_error, std::abs(rho - 1));
      for (const double rho : equatorial)
        max_error = std::max(max_error, std::abs(rho - 1));
      const std::vector<double> sphere(256, 1.1);
      std::printf("  refinement %u: E axial %.6f  E equatorial %.6f  max |r_h - 1| %.1e\n", r,
                  polar_l2_distance(axial, sphere), polar_l2_distance(equatorial, sphere), max_error);
    }

  std::printf("(2) prolate equilibrium (A = 4pi, v = 0.75, omega = 2) against itself\n");
  double previous = 0;
  for (unsigned int r = 1; r <= 4; ++r)
    {
      SurfaceRun run("equilibrium", "1, 1, 1", r);
      const auto d = run.diagnostics.l2_distance(run.geometry, *run.geometry.equilibrium_shape());
      const double e = std::hypot(d.first, d.second);
      std::printf("  refinement %u: E %.1e", r, e);
      if (r > 1)
        std::printf("  rate %.1f", std::log2(previous / e));
      std::printf("\n");
      previous = e;
    }

  std::printf("(3) triaxial ellipsoid [1, 0.8, 0.6]\n");
  const std::array<double, 3> lambda = ellipsoid_inertia(1, 0.8, 0.6);
  const double exact = std::min(lambda[1] - lambda[0], lambda[2] - lambda[1]) / ((lambda[0] + lambda[1] + lambda[2]) / 3);
  std::printf("  exact eigenvalues %.8f %.8f %.8f  e(lambda) %.8f\n", lambda[0], lambda[1], lambda[2], exact);
  previous = 0;
  for (unsigned int r = 1; r <= 4; ++r)
    {
      SurfaceRun                run("ellipsoid", "1, 0.8, 0.6", r);
      const Diagnostics::Values v = run.diagnostics.evaluate(run.geometry, run.model.dof_handler(), run.model.solution());
      const double              error = std::abs(v.symmetry_deviation - exact) / exact;
      std::printf("  refinement %u: e(lambda) %.8f  relative error %.1e", r, v.symmetry_deviation, error);
      if (r > 1)
        std::printf("  rate %.1f", std::log2(previous / error));
      std::printf("\n");
      previous = error;
    }
}
