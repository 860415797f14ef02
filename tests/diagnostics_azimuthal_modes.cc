// SPDX-License-Identifier: LGPL-2.1-or-later
// The azimuthal moments Q_m of diagnostics/azimuthal modes against their first-order values on the unit sphere
// displaced by one mode of `initial state/perturbation form = azimuthal` (ε = 1e-3, radial, refinement 3, Q2
// geometry): x = (1 + εδ)x̂ and dA = (1 + 2εδ)dΩ give Q = (1/4π)∫ h(x̂)(1 + 4εδ) dΩ + O(ε²), so
//   m = 2 even, δ = Re ξ̂²:          Q_2 = (4ε/4π)∫ sin⁴θ cos2φ e^{2iφ} dΩ = 16ε/15,
//   m = 1 odd, δ = 2 Re ζ̂ξ̂ (tilt):  Q_1 = (8ε/4π)∫ cos²θ sin²θ cosφ e^{iφ} dΩ = 8ε/15,
//   m = 1 even, δ = Re ξ̂(5ζ̂² − 1)/g, g = (8/3)(4/15)^{1/2} (h of degree 3: x and dA give 1 + 5εδ):
//                                    Q_1 = (5ε/4πg)∫ sin²θ(5cos²θ − 1)² cos φ e^{iφ} dΩ = (5ε/4g)(32/21),
// both real (phase 0); measured within 1e-4 at refinement 3 (checked to 1e-3). The other moments vanish by the parity and the 90° symmetry of the cube-sphere mesh
// without a perturbation (m = 4 even picks up the mesh itself); with one they stay below 1e-2 |Q| (O(ε²) terms
// and the mesh's m = 4 times ε).
#include <deal.II/base/mpi.h>

#include "surface_run.h"

#include <cmath>
#include <cstdio>
#include <string>

using namespace FluidSurface;

namespace
{
  Diagnostics::Values
  moments(const double epsilon, const unsigned int m, const std::string &parity)
  {
    SurfaceRun run("ellipsoid",
                   "1, 1, 1",
                   3,
                   "prolate",
                   false,
                   {{"initial state/shape perturbation", std::to_string(epsilon)},
                    {"initial state/perturbation form", epsilon > 0 ? "azimuthal" : "random"},
                    {"initial state/azimuthal wavenumber", std::to_string(m)},
                    {"initial state/azimuthal parity", parity},
                    {"diagnostics/azimuthal modes", "1, 2, 3, 4"}});
    return run.diagnostics.evaluate(run.geometry, run.model.dof_handler(), run.model.solution());
  }

  void
  report(const char *title, const Diagnostics::Values &v, const unsigned int index, const double expected)
  {
    std::printf("%s\n", title);
    if (expected != 0)
      std::printf("  |Q| within 1e-3 (relative) of the first-order value: %s, phase below 1e-8: %s\n",
                  std::abs(std::abs(v.azimuthal_moments[index]) - expected) < 1e-3 * expected ? "yes" : "no",
                  std::abs(std::arg(v.azimuthal_moments[index])) < 1e-8 ? "yes" : "no");
    double largest_other = 0;
    for (unsigned int j = 0; j < v.azimuthal_moments.size(); ++j)
      if (j != index && j != 6) // 6: m = 4 even, the mesh's own
        largest_other = std::max(largest_other, std::abs(v.azimuthal_moments[j]));
    // O(ε²) and the mesh's m = 4 times ε feed the others; without a perturbation they vanish to rounding.
    const double bound = expected != 0 ? 1e-2 * expected : 1e-12;
    std::printf("  other moments (m = 4 even aside) below %s: %s\n", expected != 0 ? "1e-2 |Q|" : "1e-12",
                largest_other < bound ? "yes" : "no");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double epsilon = 1e-3;
  const auto   sphere  = moments(0, 2, "even");
  report("unperturbed sphere", sphere, 99, 0);
  std::printf("  m = 4 even (the mesh) below 1e-4: %s\n", std::abs(sphere.azimuthal_moments[6]) < 1e-4 ? "yes" : "no");
  report("m = 2 even", moments(epsilon, 2, "even"), 2, 16 * epsilon / 15);
  report("m = 1 odd", moments(epsilon, 1, "odd"), 1, 8 * epsilon / 15);
  report("m = 1 even", moments(epsilon, 1, "even"), 0, 5 * epsilon / (4 * 8.0 / 3.0 * std::sqrt(4.0 / 15.0)) * 32 / 21);
}
