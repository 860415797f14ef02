// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_scenes_simulation_h
#define fluid_surface_scenes_simulation_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <fluid_surface/geometry/surface_geometry.h>
#include <fluid_surface/io/output_writer.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/io/statistics_file.h>
#include <fluid_surface/scenes/scene.h>

#include <iostream>
#include <memory>

namespace FluidSurface
{
  /**
   * One run of the program: parameters → scene → geometry and fields → steps
   * → diagnostics → files. The Simulation owns what every scene works with
   * (the surface, the output directory, the statistics file, the screen and
   * the wall clock) and creates the Scene that `model/scene` selects.
   */
  class Simulation
  {
  public:
    /// A run on @p communicator whose screen output goes to @p screen (on rank 0).
    explicit Simulation(const MPI_Comm communicator, std::ostream &screen = std::cout);

    /// Declares every parameter of every component.
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * Creates the selected scene, rejects every entry that @p file sets outside what the scene reads
     * (Scene::parameters_read(); none for parameters set in code) and reads and checks the parameters of every
     * component (InputError on bad input).
     */
    void
    parse_parameters(dealii::ParameterHandler &prm, const ParameterFile &file = ParameterFile());

    /**
     * Prepares the output directory (@p prm is echoed as used_parameters.prm),
     * builds the surface and runs the scene. Throws RunStopped when a
     * full-model run stops on a signal or after `checkpoint/steps per run`
     * steps (with a checkpoint).
     */
    void
    run(const dealii::ParameterHandler &prm);

  private:
    MPI_Comm                   communicator;
    dealii::ConditionalOStream pcout;
    /// Wall time since run() started.
    dealii::Timer              wall_timer;
    SurfaceGeometry            geometry;
    OutputWriter               output;
    StatisticsFile             statistics;
    std::unique_ptr<Scene>     scene;
  };
} // namespace FluidSurface

#endif
