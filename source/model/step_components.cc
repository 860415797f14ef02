// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/model/step_components.h>

namespace FluidSurface
{
  void
  StepComponents::declare_parameters(dealii::ParameterHandler &prm)
  {
    SurfaceFluid::declare_parameters(prm);
    BendingForce::declare_parameters(prm);
    VolumeConstraint::declare_parameters(prm);
    MeshRedistribution::declare_parameters(prm);
    ConservationProjection::declare_parameters(prm);
    GeometryIteration::declare_parameters(prm);
  }

  void
  StepComponents::parse_parameters(dealii::ParameterHandler &prm, const double maximum_time_step)
  {
    flow.parse_parameters(prm);
    bending.parse_parameters(prm);
    volume_constraint.parse_parameters(prm, maximum_time_step);
    redistribution.parse_parameters(prm);
    conservation.parse_parameters(prm);
    geometry_iteration.parse_parameters(prm);
    momentum_constraints = MomentumConstraints(flow);
  }
} // namespace FluidSurface
