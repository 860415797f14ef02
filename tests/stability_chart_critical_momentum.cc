// SPDX-License-Identifier: LGPL-2.1-or-later
// The critical angular momentum L_c of the spinning oblate at v = 0.66 (A = 4π, Be = 1): the zero of the lowest
// isolated eigenvalue of the second variation in m = 2 even (doc/stability.md, benchmarks/stability_chart), by the
// secant method from L = 12 and 13, each equilibrium solved anew. Checked against the chart's documented L_c = 12.4373
// (benchmarks/stability_chart/README.md, regula falsi on the basis of 24 functions; 16 here): the root to 4 decimals,
// the eigenvalue below it positive and above it negative, and the lowest of the other classes m = 0…3 positive at L_c
// (the loss is to m = 2 even alone).
#include <deal.II/base/mpi.h>

#include <fluid_surface/reference/axisymmetric_equilibrium.h>
#include <fluid_surface/reference/second_variation.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>

using namespace FluidSurface;

namespace
{
  /// The lowest isolated eigenvalue of m = 2 even at (v = 0.66, L) and the lowest of every other class of m ≤ 3.
  std::array<double, 2>
  lowest_eigenvalues(const double L)
  {
    AxisymmetricEquilibrium::Parameters parameters;
    parameters.reduced_volume   = 0.66;
    parameters.branch           = AxisymmetricEquilibrium::Branch::oblate;
    parameters.prescribed       = AxisymmetricEquilibrium::Prescribed::angular_momentum;
    parameters.angular_momentum = L;
    AxisymmetricEquilibrium equilibrium(parameters);
    equilibrium.solve();
    SecondVariation::Parameters sv;
    sv.modes         = {0, 1, 2, 3};
    sv.n_eigenvalues = 1;
    sv.basis_size    = 16;
    SecondVariation second_variation(sv);
    second_variation.compute(equilibrium);
    double m2_even = std::numeric_limits<double>::quiet_NaN(), others = std::numeric_limits<double>::max();
    for (const SecondVariation::Spectrum &s : second_variation.spectra())
      if (s.energy == SecondVariation::Energy::isolated)
        {
          if (s.m == 2 && !s.odd)
            m2_even = s.eigenvalues[0];
          else
            others = std::min(others, s.eigenvalues[0]);
        }
    return {{m2_even, others}};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  double L0 = 12, L1 = 13, f0 = lowest_eigenvalues(L0)[0], f1 = lowest_eigenvalues(L1)[0];
  std::cout << std::setprecision(6) << "m = 2 even at L = 12: " << f0 << ", at L = 13: " << f1 << std::endl;
  unsigned int iterations = 0;
  while (std::abs(L1 - L0) > 1e-8 && iterations < 20)
    {
      const double L2 = L1 - f1 * (L1 - L0) / (f1 - f0);
      L0 = L1, f0 = f1;
      L1 = L2, f1 = lowest_eigenvalues(L1)[0];
      ++iterations;
    }
  const std::array<double, 2> at_root = lowest_eigenvalues(L1);
  std::cout << std::fixed << std::setprecision(4) << "L_c = " << L1 << " (documented 12.4373): "
            << (std::abs(L1 - 12.4373) < 5e-5 ? "agrees" : "differs") << "\nsecant converged: "
            << (iterations < 20 ? "yes" : "no") << "\nother classes positive at L_c: "
            << (at_root[1] > 0 ? "yes" : "no") << std::endl;
}
