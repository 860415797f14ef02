// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_step_components_h
#define fluid_surface_model_step_components_h

#include <deal.II/base/parameter_handler.h>

#include <fluid_surface/flow/surface_fluid.h>
#include <fluid_surface/model/bending_force.h>
#include <fluid_surface/model/conservation_projection.h>
#include <fluid_surface/model/geometry_iteration.h>
#include <fluid_surface/model/mesh_redistribution.h>
#include <fluid_surface/model/momentum_constraints.h>
#include <fluid_surface/model/volume_constraint.h>

namespace FluidSurface
{
  /**
   * The physical components of the step of scene full, each with its own subsection and its terms: the surface
   * fluid (`flow`), the BendingForce (`bending`), the VolumeConstraint, the MeshRedistribution, the
   * MomentumConstraints the fluid asks for, the ConservationProjection and the GeometryIteration. Parsed once;
   * the step, its terms and the model read them by const reference.
   */
  struct StepComponents
  {
    /// Declares the subsections of the components.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Reads them; τ_max = @p maximum_time_step bounds the drift-correction time from below.
    void
    parse_parameters(dealii::ParameterHandler &prm, const double maximum_time_step);

    SurfaceFluid           flow;
    BendingForce           bending;
    VolumeConstraint       volume_constraint;
    MeshRedistribution     redistribution;
    MomentumConstraints    momentum_constraints;
    ConservationProjection conservation;
    GeometryIteration      geometry_iteration;
  };
} // namespace FluidSurface

#endif
