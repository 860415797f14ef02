// SPDX-License-Identifier: LGPL-2.1-or-later
// FixedPointAcceleration (Anderson's mixing) on a linear map G(x) = A x + b in ℝ^12 whose iteration matrix A has two eigenvalues
// outside the unit disc (−1.5 and 1.2) and the rest inside (±0.1 … ±0.6): the plain fixed point diverges, Aitken's
// single relaxation factor cannot tame both bad eigenvalues, Anderson's mixing of depth 5 converges (it is GMRES on
// (I − A) x = b). Printed: the residual |G(x_k) − x_k| after 5, 10 and 20 iterations (below 1e-6 as such) and the error |x − x*|.
#include <deal.II/base/mpi.h>
#include <deal.II/base/index_set.h>

#include <fluid_surface/model/geometry_iteration.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

int
main(int argc, char **argv)
{
  using namespace FluidSurface;
  using VectorType = FixedPointAcceleration::VectorType;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int n = 12;
  dealii::IndexSet   all(n);
  all.add_range(0, n);
  const double eigenvalues[n] = {-1.5, 1.2, 0.6, -0.6, 0.5, -0.5, 0.4, -0.4, 0.3, -0.3, 0.1, -0.1};
  const auto   apply          = [&](const VectorType &x, VectorType &y) {
    // y = A x + b with A = S D S⁻¹, S the upper bidiagonal matrix with ones (S⁻¹ in closed form).
    std::vector<double> z(n), w(n);
    // z = S⁻¹ x: back substitution of z_i + z_{i+1} = x_i
    z[n - 1] = x[n - 1];
    for (int i = n - 2; i >= 0; --i)
      z[i] = x[i] - z[i + 1];
    for (unsigned int i = 0; i < n; ++i)
      w[i] = eigenvalues[i] * z[i];
    for (unsigned int i = 0; i < n; ++i)
      y[i] = w[i] + (i + 1 < n ? w[i + 1] : 0.0) + 1.0; // S w + b, b = (1, …, 1)
    y.compress(dealii::VectorOperation::insert);
  };
  const auto dot = [](const VectorType &a, const VectorType &b) { return a * b; };

  // The fixed point x* = (I − A)⁻¹ b.
  VectorType exact(all, MPI_COMM_WORLD);
  {
    std::vector<double> z(n), x(n);
    // (I − A) x = b ⇔ (I − D) S⁻¹ x = S⁻¹ b
    std::vector<double> sb(n);
    sb[n - 1] = 1;
    for (int i = n - 2; i >= 0; --i)
      sb[i] = 1 - sb[i + 1];
    for (unsigned int i = 0; i < n; ++i)
      z[i] = sb[i] / (1 - eigenvalues[i]);
    for (unsigned int i = 0; i < n; ++i)
      exact[i] = z[i] + (i + 1 < n ? z[i + 1] : 0.0);
    exact.compress(dealii::VectorOperation::insert);
  }

  // The plain fixed point and Aitken's relaxation (one factor ω_k = −ω_{k−1} r_{k−1}·(r_k − r_{k−1})/|r_k −
  // r_{k−1}|², clipped to [0.1, 2]) as the references; Anderson's mixing is the library's.
  for (const std::string method : {"none", "aitken", "anderson"})
    {
      FixedPointAcceleration acceleration(dot, 5);
      VectorType             x(all, MPI_COMM_WORLD), image(all, MPI_COMM_WORLD), last_residual;
      double                 omega = 1;
      const auto             advance = [&](VectorType &x, const VectorType &image, const unsigned int k) {
        if (method == "anderson")
          return acceleration.advance(x, image);
        VectorType residual = image;
        residual -= x;
        if (method == "none")
          x = image;
        else
          {
            if (k > 1)
              {
                VectorType difference = residual;
                difference -= last_residual;
                const double denominator = dot(difference, difference);
                if (denominator > 0)
                  omega = std::min(2.0, std::max(0.1, -omega * dot(last_residual, difference) / denominator));
              }
            x.add(omega, residual);
          }
        last_residual = residual;
      };
      std::printf("%s:", method.c_str());
      for (unsigned int k = 1; k <= 20; ++k)
        {
          apply(x, image);
          VectorType residual = image;
          residual -= x;
          const double r = std::sqrt(dot(residual, residual));
          if (k == 5 || k == 10 || k == 20)
            {
              if (r >= 1e-6)
                std::printf("  |r_%u| = %.1e", k, r);
              else
                std::printf("  |r_%u| < 1e-6", k);
            }
          advance(x, image, k);
        }
      VectorType error = x;
      error -= exact;
      const double e = std::sqrt(dot(error, error));
      std::printf("  |x - x*| %s\n", e < 1e-8 ? "< 1e-8" : e > 1 ? "> 1" : "between 1e-8 and 1");
    }
}
