#ifndef fluid_surface_scenes_simulation_h
#define fluid_surface_scenes_simulation_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/postprocess/diagnostics.h>
#include <fluid_surface/model/fluid_deformable_surface.h>
#include <fluid_surface/io/output_writer.h>
#include <fluid_surface/time_stepping/time_stepper.h>
#include <fluid_surface/io/statistics_file.h>
#include <fluid_surface/scenes/fixed_surface_scene.h>
#include <fluid_surface/geometry/surface_geometry.h>

#include <string>

namespace FluidSurface
{
  /**
   * One run of the program: parameters → scene → geometry and fields → steps
   * → diagnostics → files. The scene (`subsection model`) decides which
   * components are assembled at all.
   */
  class Simulation
  {
  public:
    /// What a run computes.
    enum class Scene
    {
      geometry,      ///< builds and measures the surface only (no time steps)
      fixed_surface, ///< surface (Navier–)Stokes on a frozen surface

      full      ///< the fluid deformable surface of the seed paper
    };

    explicit Simulation(const MPI_Comm communicator);

    /// Declares every parameter of every component.
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Reads and checks the parameters of every component (InputError on bad input).
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * Runs the scene; writes into the output directory. @p prm is echoed as
     * used_parameters.prm. Throws RunStopped when a full-model run stops on a
     * signal or after `checkpoint/steps per run` steps (with a checkpoint).
     */
    void
    run(const dealii::ParameterHandler &prm);

  private:
    void
    record_geometry_statistics(const unsigned int step, const double time);
    /// The time loop of scene full, from step 0 or from the checkpoint Checkpoint::find() chose.
    void
    run_full_model(const bool resuming);
    /// Wall time of the run in seconds, including the part before a restart.
    double
    elapsed_wall_time() const
    {
      return wall_time_before_restart + wall_timer.wall_time();
    }
    /// One statistics row and screen report of the full model's accepted state.
    void
    record_full_model_step(const double tau, const double willmore, const FluidDeformableSurface::StepResult &step);
    /// Writes the wall time per section (file `timing`; the screen if `report wall time`).
    void
    write_timing();

    MPI_Comm                   communicator;
    dealii::ConditionalOStream pcout;
    dealii::Timer              wall_timer;
    /// Wall time per section of a full-model run: assembly, factorization, linear solve, curvature and
    /// energy, diagnostics, output. Printed at the end when `output/report wall time` is on; always
    /// written to the file `timing` of the output directory.
    dealii::TimerOutput computing_timer;

    Scene           scene = Scene::geometry;
    SurfaceGeometry geometry;
    OutputWriter    output;
    StatisticsFile  statistics;

    TimeStepper            time;
    FluidDeformableSurface model;
    Diagnostics            diagnostics;
    FixedSurfaceScene      fixed_surface_scene;
    Checkpoint             checkpoint;
    double                 total_energy             = 0;
    double                 wall_time_before_restart = 0;
  };
} // namespace FluidSurface

#endif
