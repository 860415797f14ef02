#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>

#include <fluid_surface/parameter_file.h>
#include <fluid_surface/simulation.h>

#include <fstream>
#include <iomanip>

namespace FluidSurface
{
  using namespace dealii;

  Simulation::Simulation(const MPI_Comm communicator)
    : communicator(communicator)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(communicator) == 0)
    , geometry(communicator)
  {}

  void
  Simulation::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("model");
    prm.declare_entry("scene",
                      "geometry",
                      Patterns::Selection("geometry"),
                      "What the run computes. geometry: build the surface, measure it (area, volume, "
                      "reduced volume, Willmore energy ½∫H²) and write it; no time steps.");
    prm.leave_subsection();
    SurfaceGeometry::declare_parameters(prm);
    OutputWriter::declare_parameters(prm);
  }

  void
  Simulation::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("model");
    scene = Scene::geometry;
    prm.leave_subsection();
    geometry.parse_parameters(prm);
    output.parse_parameters(prm);
  }

  void
  Simulation::record_geometry_statistics(const unsigned int step, const double time)
  {
    const SurfaceGeometry::Measures m       = geometry.measure();
    const double                    willmore = geometry.compute_curvature();
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
  }

  void
  Simulation::run(const ParameterHandler &prm)
  {
    wall_timer.restart();
    output.prepare_directory(communicator, false);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::ofstream used(output.directory() + "used_parameters.prm");
        prm.print_parameters(used, ParameterHandler::PRM);
      }

    geometry.create();
    pcout << "-- fluid_surface: " << geometry.description() << '\n'
          << "   " << geometry.triangulation().n_global_active_cells() << " cells, "
          << geometry.dof_handler().n_dofs() << " position DoFs, "
          << Utilities::MPI::n_mpi_processes(communicator) << " MPI rank(s)" << std::endl;

    statistics.open(output.directory() + "statistics", Utilities::MPI::this_mpi_process(communicator));
    record_geometry_statistics(0, 0.0);
    output.write(geometry, 0.0);
  }
} // namespace FluidSurface
