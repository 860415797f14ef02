// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_reference_equilibrium_continuation_h
#define fluid_surface_reference_equilibrium_continuation_h

#include <fluid_surface/reference/axisymmetric_equilibrium.h>
#include <fluid_surface/reference/generating_curve_collocation.h>

#include <vector>

/**
 * The path of AxisymmetricEquilibrium to its equilibrium along the branch: the start states (the sphere, a
 * spheroid of the same A and V), the continuation in the reduced volume v from near the sphere, and the
 * continuation in the rotation (ω² or L) from rest. Each step is a Newton solve of the
 * GeneratingCurveCollocation; a step is accepted only if it stays on the branch.
 */
namespace FluidSurface::EquilibriumContinuation
{
  /// The sphere of area A0: with σ = P = η = 0 it solves the collocation equations exactly.
  std::vector<double>
  sphere_state(const GeneratingCurveCollocation &problem);

  /**
   * The resting shape (ω = 0) of the reduced volume of @p prm: Newton from the spheroid directly, else by
   * continuation in v from near the sphere (v = 0.97). Throws AxisymmetricEquilibrium::NoSolution.
   */
  std::vector<double>
  resting_shape(GeneratingCurveCollocation &problem, const AxisymmetricEquilibrium::Parameters &prm);

  /**
   * Continuation in ω² (or in L when the angular momentum is prescribed) from the resting state @p x to the
   * rotation of @p prm; @p x becomes the rotating state (with ω appended when L is prescribed). Returns ω.
   * Throws AxisymmetricEquilibrium::NoSolution when the continuation stalls (at a fold of the branch).
   */
  double
  continue_in_rotation(GeneratingCurveCollocation                &problem,
                       const AxisymmetricEquilibrium::Parameters &prm,
                       std::vector<double>                       &x);
} // namespace FluidSurface::EquilibriumContinuation

#endif
