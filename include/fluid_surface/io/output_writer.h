// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_io_output_writer_h
#define fluid_surface_io_output_writer_h

#include <deal.II/base/data_out_base.h>
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
   * Files of a run in the output directory: one file per output step with
   * curved cells, `solution-NNNNN.vtu` plus the `solution.pvd` time series
   * (format vtu) or `solution-NNNNN.h5` plus the `solution.xdmf` time series
   * (format hdf5), both for ParaView; and the directory itself (created; a
   * directory holding another run's results is not overwritten unless asked to).
   */
  class OutputWriter
  {
  public:
    /// The file format of the output steps (`format`).
    enum class Format
    {
      vtu, ///< solution-NNNNN.vtu (one file, written by all ranks with MPI I/O) and solution.pvd
      hdf5 ///< solution-NNNNN.h5 (parallel HDF5, duplicate vertices merged) and solution.xdmf
    };

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

    /// Whether an output step is due at @p time (always at the first and the last step).
    bool
    due(const double time) const;

    /**
     * Writes the geometry fields (H, ν) and whatever @p add_fields attaches
     * to the DataOut, as solution-NNNNN.vtu or .h5 (the `format`), and
     * records it in the time series (solution.pvd or solution.xdmf).
     * Collective.
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

    /// Writes the output counters (the files written, their times and XDMF entries) into a checkpoint.
    void
    save(CheckpointData &data) const;
    /**
     * Restores the counters and rewrites solution.pvd and solution.xdmf with
     * the files up to the checkpoint (the checkpointed run may have written
     * either format, or both if the format was changed on an earlier resume).
     */
    void
    load(const CheckpointData &data, const MPI_Comm communicator);

  private:
    /**
     * Writes the patches of @p data_out as the HDF5 file @p name, duplicate
     * vertices merged (collective), and records its XDMF entry at @p time.
     */
    void
    write_hdf5_file(const dealii::DataOut<2, 3> &data_out,
                    const std::string           &name,
                    const double                 time,
                    const MPI_Comm               communicator);

    /// Rewrites solution.pvd from the record of the VTU files (on the calling rank).
    void
    write_pvd_file() const;

    /// Rewrites solution.xdmf from the XDMF entries of the HDF5 files (on the calling rank).
    void
    write_xdmf_file() const;

    /// The entries of `subsection output`, named as there.
    struct Parameters
    {
      std::string  output_directory = "results";
      double       output_interval  = 0;
      bool         write_vtu        = true; ///< the switch of all solution files, whatever the format
      Format       format           = Format::vtu;
      unsigned int subdivisions     = 2;
      unsigned int screen_interval  = 10;
      bool         report_wall_time = true;
      bool         overwrite        = false;
    } parameters;

    double last_output_time = -1e300;
    /// Every solution file written, in order, with its time (the counter NNNNN is its index).
    std::vector<std::pair<double, std::string>> times_and_names;
    /// The XDMF entries of the HDF5 files among them, in order.
    std::vector<dealii::XDMFEntry> xdmf_entries;
  };
} // namespace FluidSurface

#endif
