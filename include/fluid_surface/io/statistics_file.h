// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_io_statistics_file_h
#define fluid_surface_io_statistics_file_h

#include <cstdint>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace FluidSurface
{
  class CheckpointData;

  /**
   * The `statistics` file users script against (ASPECT's format): one
   * `# N: name` header line per column, then one whitespace-separated row per
   * step. Components add the values of a row by name; the first completed row
   * fixes the columns. Rows are appended and flushed, so a live run's file can
   * be plotted and a killed run loses at most the row being written.
   * Only MPI rank 0 writes.
   */
  class StatisticsFile
  {
  public:
    /// Starts a new file @p filename (truncating an old one) on rank @p rank.
    void
    open(const std::string &filename, const unsigned int rank);

    /// Sets column @p name of the current row.
    void
    add_value(const std::string &name, const double value);

    /// Writes the current row (and, before the first row, the header).
    void
    end_row();

    /// Writes the column names and the file length (bytes of the complete rows) into a checkpoint; fsyncs the file.
    void
    save(CheckpointData &data) const;

    /**
     * Reopens @p filename after a restart: cut back to the rows of the
     * checkpoint (a row written after it, or half written when the run was
     * killed, is removed) and continued from there.
     */
    void
    resume(const std::string &filename, const unsigned int rank, const CheckpointData &data);

  private:
    std::string                                 path;
    std::uint64_t                               length = 0; ///< bytes of the complete rows
    std::ofstream                               file;
    bool                                        writes = false;
    std::vector<std::string>                    columns;
    std::vector<std::pair<std::string, double>> row;
  };
} // namespace FluidSurface

#endif
