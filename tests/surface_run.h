// SPDX-License-Identifier: LGPL-2.1-or-later
// A surface, its flow model and diagnostics built from the default parameters with a chosen shape
// (shared by the diagnostics and equilibrium tests). The equilibrium is the prolate or oblate rotating
// shape with A = 4π, v = 0.75 and ω = 2. Further entries: @p overrides.
#ifndef fluid_surface_tests_surface_run_h
#define fluid_surface_tests_surface_run_h

#include <fluid_surface/time_stepping/time_stepper.h>
#include <fluid_surface/postprocess/diagnostics.h>
#include <fluid_surface/model/fluid_deformable_surface.h>
#include <fluid_surface/scenes/simulation.h>

#include "parameter_overrides.h"

#include <string>

namespace FluidSurface
{
  struct SurfaceRun
  {
    dealii::ParameterHandler prm;
    SurfaceGeometry          geometry{MPI_COMM_WORLD};
    FluidDeformableSurface   model{geometry};
    Diagnostics              diagnostics;

    SurfaceRun(const std::string &shape,
              const std::string &semi_axes,
              const unsigned int refinement,
              const std::string &branch               = "prolate",
              const bool         equilibrium_rotation = false,
              const Overrides   &overrides            = {})
    {
      Simulation::declare_parameters(prm);
      prm.enter_subsection("geometry");
      prm.set("shape", shape);
      prm.set("semi-axes", semi_axes);
      prm.set("refinement", std::to_string(refinement));
      prm.leave_subsection();
      prm.enter_subsection("equilibrium");
      prm.set("angular velocity", "2");
      prm.set("branch", branch);
      prm.leave_subsection();
      prm.enter_subsection("initial state");
      prm.set("equilibrium rotation", equilibrium_rotation ? "true" : "false");
      prm.leave_subsection();
      set_overrides(prm, overrides);
      geometry.parse_parameters(prm);
      geometry.create();
      TimeStepper time;
      time.parse_parameters(prm);
      model.parse_parameters(prm, time.maximum_step_size());
      model.setup();
      diagnostics.parse_parameters(prm);
    }
  };

} // namespace FluidSurface

#endif
