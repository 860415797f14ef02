// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_scenes_scene_h
#define fluid_surface_scenes_scene_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <fluid_surface/geometry/surface_geometry.h>
#include <fluid_surface/io/output_writer.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/io/statistics_file.h>

namespace FluidSurface
{
  /**
   * What a run computes (`model/scene`): GeometryScene, FixedSurfaceScene,
   * FullModelScene or StabilityScene. Simulation creates the selected scene,
   * rejects every entry of the parameter file that the scene does not read
   * (parameters_read()), lets it read its parameters, prepares the output
   * directory and builds the surface; then run() computes and writes into the
   * output directory.
   */
  class Scene
  {
  public:
    virtual ~Scene() = default;

    /// The subsections of the parameter file that the scene reads (its own and those of the components it
    /// runs), and the entries in them that it ignores; the name of the scene for messages.
    virtual ParametersRead
    parameters_read() const = 0;

    /// Reads and checks the parameters of the scene itself (InputError on bad input).
    virtual void
    parse_parameters(dealii::ParameterHandler &prm) = 0;

    /**
     * Looks for a checkpoint to continue from, before the output directory is
     * prepared; returns whether the run resumes (then the directory and its
     * statistics file are kept). A scene without checkpoints never resumes.
     */
    virtual bool
    find_checkpoint()
    {
      return false;
    }

    /// Computes the scene on the built surface; writes into the prepared output directory.
    virtual void
    run() = 0;

  protected:
    /// A scene works on the surface, the output files and the screen of the Simulation (or of a test).
    Scene(SurfaceGeometry                  &geometry,
          OutputWriter                     &output,
          StatisticsFile                   &statistics,
          const dealii::ConditionalOStream &pcout)
      : geometry(geometry)
      , output(output)
      , statistics(statistics)
      , pcout(pcout)
    {}

    SurfaceGeometry           &geometry;
    OutputWriter              &output;
    StatisticsFile            &statistics;
    dealii::ConditionalOStream pcout; ///< the screen (active on rank 0)
  };
} // namespace FluidSurface

#endif
