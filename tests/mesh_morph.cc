// SPDX-License-Identifier: LGPL-2.1-or-later
// The mesh law under a prescribed morph whose axis flips: the oblate ellipsoid (1.4, 1.4, 0.6) becomes the
// prolate (2, 0.8, 0.8) with its long axis along x, by the linear velocity u = D x, D = diag(ln(a₁/a₀)),
// t ∈ [0, 1], refinement 1, τ = 0.01. Law reference keeps the mesh quality above half its start at every step
// (the law bgn does not: lowest 0.1736 against 0.3508 at the start).
#include "prescribed_motion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace
{
  class Strain : public dealii::Function<3>
  {
  public:
    Strain()
      : dealii::Function<3>(3)
    {}
    double
    value(const dealii::Point<3> &x, const unsigned int component) const override
    {
      static const double rate[3] = {std::log(2.0 / 1.4), std::log(0.8 / 1.4), std::log(0.8 / 0.6)};
      return rate[component] * x[component];
    }
  };
} // namespace

int
main(int argc, char **argv)
{
  using namespace FluidSurface;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Strain     strain;
  PrescribedMotion run("1.4, 1.4, 0.6", 1, {{"mesh redistribution/law", "reference"}}, strain);
  const double     start = run.geometry.measure().mesh_quality;
  double           lowest = start;
  for (unsigned int n = 0; n < 100; ++n)
    {
      run.step(0.01);
      lowest = std::min(lowest, run.geometry.measure().mesh_quality);
    }
  std::printf("mesh quality at the start %.4f, lowest %.4f (ratio %.3f), at least half the start: %s\n",
              start, lowest, lowest / start, lowest >= 0.5 * start ? "yes" : "no");
  const auto measures = run.geometry.measure();
  std::printf("area %.4f, volume %.4f, mesh quality at the end %.4f\n", measures.area, measures.volume,
              measures.mesh_quality);
}
