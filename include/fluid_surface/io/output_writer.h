#ifndef fluid_surface_io_output_writer_h
#define fluid_surface_io_output_writer_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/numerics/data_out.h>

#include <fluid_surface/geometry/surface_geometry.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace FluidSurface
{
  class CheckpointData;

  /**
   * Files of a run in the output directory: `solution-NNNNN.vtu` with curved
   * cells plus the `solution.pvd` time series for ParaView, and the directory
   * itself (created; a directory holding another run's results is not
   * overwritten unless asked to).
   */
  class OutputWriter
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * Creates the output directory. Throws an InputError if it holds the
     * results of another run (a `statistics` file) and overwriting is off,
     * unless @p resuming.
     */
    void
    prepare_directory(const MPI_Comm communicator, const bool resuming) const;

    /// The output directory, with a trailing '/'.
    std::string
    directory() const;

    /// Whether a VTU file is due at @p time (always at the first and the last step).
    bool
    due(const double time) const;

    /**
     * Writes the geometry fields (H, ν) and whatever @p add_fields attaches
     * to the DataOut, as solution-NNNNN.vtu, and records it in solution.pvd.
     */
    void
    write(const SurfaceGeometry                             &geometry,
          const double                                       time,
          const std::function<void(dealii::DataOut<2, 3> &)> &add_fields = {});

    /// Every how many steps a report goes to the screen (`screen interval`).
    unsigned int
    screen_interval() const
    {
      return parameters.screen_interval;
    }

    /// Whether the screen shows timings (`report wall time`).
    bool
    report_wall_time() const
    {
      return parameters.report_wall_time;
    }

    /// Writes the output counters (the pvd record and the time of the last VTU file) into a checkpoint.
    void
    save(CheckpointData &data) const;
    /// Restores the counters and rewrites solution.pvd with the files up to the checkpoint.
    void
    load(const CheckpointData &data, const MPI_Comm communicator);

  private:
    /// Rewrites solution.pvd from the record of the VTU files (on the calling rank).
    void
    write_pvd_file() const;

    /// The entries of `subsection output`, named as there.
    struct Parameters
    {
      std::string  output_directory = "results";
      double       output_interval  = 0;
      bool         write_vtu        = true;
      unsigned int subdivisions     = 2;
      unsigned int screen_interval  = 10;
      bool         report_wall_time = true;
      bool         overwrite        = false;
    } parameters;

    double                                      last_output_time = -1e300;
    std::vector<std::pair<double, std::string>> times_and_names;
  };
} // namespace FluidSurface

#endif
