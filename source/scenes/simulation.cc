// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/linear_algebra/reused_factorization_solver.h>
#include <fluid_surface/model/fluid_deformable_surface.h>
#include <fluid_surface/postprocess/diagnostics.h>
#include <fluid_surface/reference/second_variation.h>
#include <fluid_surface/scenes/fixed_surface_scene.h>
#include <fluid_surface/scenes/full_model_scene.h>
#include <fluid_surface/scenes/geometry_scene.h>
#include <fluid_surface/scenes/simulation.h>
#include <fluid_surface/scenes/stability_scene.h>
#include <fluid_surface/time_stepping/end_state_stability.h>
#include <fluid_surface/time_stepping/steady_state.h>
#include <fluid_surface/time_stepping/time_stepper.h>

#include <fstream>

namespace FluidSurface
{
  using namespace dealii;

  Simulation::Simulation(const MPI_Comm communicator, std::ostream &screen)
    : communicator(communicator)
    , pcout(screen, Utilities::MPI::this_mpi_process(communicator) == 0)
    , geometry(communicator)
  {}

  void
  Simulation::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("model");
    prm.declare_entry("scene",
                      "geometry",
                      Patterns::Selection("geometry|fixed surface|full|stability"),
                      "What the run computes. geometry: build the surface, measure it (area, volume, "
                      "reduced volume, Willmore energy ½∫H²) and write it; no time steps. fixed surface: surface "
                      "(Navier–)Stokes on the frozen surface, the verification problems of subsection fixed "
                      "surface (no geometry update, bending or volume multiplier). full: the fluid "
                      "deformable surface (surface Navier–Stokes, bending, volume constraint, mesh "
                      "redistribution) on the moving surface. stability: the leading eigenvalues, by azimuthal "
                      "wavenumber, of the rotating equilibrium of geometry/shape = equilibrium under the full model "
                      "(subsection stability; doc/stability.md).");
    prm.leave_subsection();
    SurfaceFlow::declare_parameters(prm);
    ReusedFactorizationSolver::declare_parameters(prm);
    FixedSurfaceScene::declare_parameters(prm);
    SurfaceGeometry::declare_parameters(prm);
    OutputWriter::declare_parameters(prm);
    TimeStepper::declare_parameters(prm);
    FluidDeformableSurface::declare_parameters(prm);
    Diagnostics::declare_parameters(prm);
    Checkpoint::declare_parameters(prm);
    SecondVariation::declare_parameters(prm);
    SteadyState::declare_parameters(prm);
    EndStateStability::declare_parameters(prm);
    StabilityScene::declare_parameters(prm);
  }

  void
  Simulation::parse_parameters(ParameterHandler &prm, const ParameterFile &file)
  {
    prm.enter_subsection("model");
    const std::string name = prm.get("scene");
    prm.leave_subsection();
    if (name == "full")
      scene = std::make_unique<FullModelScene>(communicator, geometry, output, statistics, pcout, wall_timer);
    else if (name == "stability")
      scene = std::make_unique<StabilityScene>(communicator, geometry, output, statistics, pcout, wall_timer);
    else if (name == "fixed surface")
      scene = std::make_unique<FixedSurfaceScene>(geometry, output, statistics, pcout);
    else
      scene = std::make_unique<GeometryScene>(geometry, output, statistics, pcout, wall_timer);
    reject_entries_not_read(file, scene->parameters_read());

    geometry.parse_parameters(prm);
    output.parse_parameters(prm);
    scene->parse_parameters(prm);
  }

  void
  Simulation::run(const ParameterHandler &prm)
  {
    Assert(scene != nullptr, ExcMessage("Simulation::run() needs parse_parameters() first."));
    wall_timer.restart();
    const bool resuming = scene->find_checkpoint();
    output.prepare_directory(communicator, resuming);
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
    if (!resuming)
      statistics.open(output.directory() + "statistics", Utilities::MPI::this_mpi_process(communicator));
    scene->run();
  }
} // namespace FluidSurface
