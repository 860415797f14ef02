// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/scenes/geometry_scene.h>

#include <iomanip>

namespace FluidSurface
{
  using namespace dealii;

  GeometryScene::GeometryScene(SurfaceGeometry          &geometry,
                               OutputWriter             &output,
                               StatisticsFile           &statistics,
                               const ConditionalOStream &pcout,
                               const Timer              &wall_timer)
    : Scene(geometry, output, statistics, pcout)
    , wall_timer(wall_timer)
  {}

  ParametersRead
  GeometryScene::parameters_read() const
  {
    return {"scene geometry", {"model", "geometry", "equilibrium", "output"}, {}};
  }

  void
  GeometryScene::parse_parameters(ParameterHandler &)
  {}

  void
  GeometryScene::run()
  {
    const unsigned int              step     = 0;
    const double                    time     = 0.0;
    const SurfaceGeometry::Measures m        = geometry.measure();
    const double                    willmore = geometry.willmore_energy();
    statistics.add_value("time step", step);
    statistics.add_value("time", time);
    statistics.add_value("bending energy", willmore);
    statistics.add_value("area", m.area);
    statistics.add_value("volume", m.volume);
    statistics.add_value("reduced volume", m.reduced_volume);
    statistics.add_value("mesh quality", m.mesh_quality);
    statistics.add_value("wall time", wall_timer.wall_time());
    statistics.end_row();

    pcout << "*** Step " << step << "  t = " << time << '\n'
          << std::setprecision(10) << "    area = " << m.area << "  volume = " << m.volume
          << "  reduced volume = " << m.reduced_volume << '\n'
          << "    Willmore energy ½∫H² = " << willmore << "  mesh quality = " << std::setprecision(4)
          << m.mesh_quality << std::endl;
    output.write(geometry, time);
  }
} // namespace FluidSurface
