// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_scenes_geometry_scene_h
#define fluid_surface_scenes_geometry_scene_h

#include <deal.II/base/timer.h>

#include <fluid_surface/scenes/scene.h>

namespace FluidSurface
{
  /**
   * Scene `geometry`: measures the surface (area, volume, reduced volume,
   * Willmore energy ½∫H², mesh quality) into one statistics row and one screen
   * report, and writes it; no time steps.
   */
  class GeometryScene : public Scene
  {
  public:
    /// See Scene; @p wall_timer is the Simulation's clock, for the statistics.
    GeometryScene(SurfaceGeometry                  &geometry,
                  OutputWriter                     &output,
                  StatisticsFile                   &statistics,
                  const dealii::ConditionalOStream &pcout,
                  const dealii::Timer              &wall_timer);

    /// `model`, `geometry`, `equilibrium`, `output`.
    ParametersRead
    parameters_read() const override;

    /// The scene has no parameters of its own.
    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    void
    run() override;

  private:
    const dealii::Timer &wall_timer;
  };
} // namespace FluidSurface

#endif
