// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_step_candidate_h
#define fluid_surface_model_step_candidate_h

#include <deal.II/base/tensor.h>

#include <fluid_surface/base/types.h>
#include <fluid_surface/geometry/surface_geometry.h>

namespace FluidSurface
{
  /**
   * A solved step that is not yet accepted: its fields, its surface X^{m+1} with the curvature of that surface,
   * its kinetic energy there, and what the histories need once it is accepted. SurfaceStep::advance() fills it;
   * its owner (FluidDeformableSurface, or the safety valve for its own solves) accepts it or drops it. The
   * geometry shows this surface after advance() until the owner accepts it or moves the geometry back to X^m;
   * nothing reads the candidate from the geometry.
   */
  struct StepCandidate
  {
    double     tau = 0;  ///< the step's size
    VectorType solution; ///< u, p, κ, y, Y = X^{m+1} (flow numbering), ghosted
    VectorType position; ///< X^{m+1} (geometry numbering), ghosted
    /// The curvature of X^{m+1}, with its Willmore energy ½∫|κ|².
    SurfaceGeometry::Curvature curvature;
    double                     kinetic_energy = 0; ///< ½∫|u|² on X^{m+1}
    /// The rotation of the mesh by the step's frame (co-rotating steps; else the identity): the kept
    /// factorization is turned by it on acceptance.
    dealii::Tensor<2, 3> mesh_rotation = dealii::unit_symmetric_tensor<3>();
  };
} // namespace FluidSurface

#endif
