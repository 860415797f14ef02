// SPDX-License-Identifier: LGPL-2.1-or-later
// A surface moved by a prescribed velocity through the mesh law of scene full
// (FluidDeformableSurface::set_prescribed_velocity): the tests of the mesh law alone.
#ifndef fluid_surface_tests_prescribed_motion_h
#define fluid_surface_tests_prescribed_motion_h

#include <fluid_surface/model/fluid_deformable_surface.h>
#include <fluid_surface/scenes/simulation.h>
#include <fluid_surface/time_stepping/time_stepper.h>

#include "parameter_overrides.h"

#include <stdexcept>

namespace FluidSurface
{
  struct PrescribedMotion
  {
    dealii::ParameterHandler prm;
    SurfaceGeometry          geometry{MPI_COMM_WORLD};
    FluidDeformableSurface   model{geometry};
    double                   time = 0; ///< t of the accepted state

    /// An ellipsoid with @p semi_axes at @p refinement, the flow's constraints off, then @p overrides.
    PrescribedMotion(const std::string  &semi_axes,
                     const unsigned int  refinement,
                     const Overrides    &overrides,
                     const dealii::Function<3> &velocity)
    {
      Simulation::declare_parameters(prm);
      set_overrides(prm,
                    {{"geometry/shape", "ellipsoid"},
                     {"geometry/semi-axes", semi_axes},
                     {"geometry/refinement", std::to_string(refinement)},
                     {"volume constraint/enabled", "false"},
                     {"flow/conserve momenta", "false"},
                     {"linear solver/reuse factorization", "false"},
                     // a direct solve: the law's invariants hold to rounding, not to the GMRES tolerance
                     {"linear solver/factor precision", "double"},
                     {"linear solver/tolerance", "1e-13"}});
      set_overrides(prm, overrides);
      geometry.parse_parameters(prm);
      geometry.create();
      TimeStepper time;
      time.parse_parameters(prm);
      model.parse_parameters(prm, time.maximum_step_size());
      model.setup();
      model.set_prescribed_velocity(velocity);
    }

    /// One step of size @p tau, accepted.
    void
    step(const double tau)
    {
      const auto result = model.advance(tau);
      if (!result.solved)
        throw std::runtime_error(result.message);
      time += tau;
      model.accept(time);
    }
  };
} // namespace FluidSurface

#endif
