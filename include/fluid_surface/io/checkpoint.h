// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_io_checkpoint_h
#define fluid_surface_io_checkpoint_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>

#include <fluid_surface/base/types.h>

#include <cstdint>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace FluidSurface
{
  /**
   * The contents of one checkpoint: named scalars (written as exact hexadecimal
   * floating-point text, so that a resumed run continues bit for bit) and named
   * field blocks (the degrees of freedom of every locally owned cell, keyed by
   * its CellId, so that a checkpoint can be read on any number of MPI ranks).
   * Each component writes and reads its own keys ("time stepping/tau", …).
   */
  class CheckpointData
  {
  public:
    void
    set(const std::string &key, const double value);
    void
    set(const std::string &key, const unsigned int value);
    void
    set(const std::string &key, const std::uint64_t value);
    void
    set(const std::string &key, const bool value);
    void
    set(const std::string &key, const dealii::Tensor<1, 3> &value);
    void
    set(const std::string &key, const char *value);
    /// A string without line breaks.
    void
    set(const std::string &key, const std::string &value);

    /// These throw std::runtime_error naming the key when it is missing or malformed.
    double
    get_double(const std::string &key) const;
    unsigned int
    get_unsigned(const std::string &key) const;
    std::uint64_t
    get_uint64(const std::string &key) const;
    bool
    get_bool(const std::string &key) const;
    dealii::Tensor<1, 3>
    get_tensor(const std::string &key) const;
    const std::string &
    get_string(const std::string &key) const;
    bool
    has(const std::string &key) const
    {
      return scalars.count(key) > 0;
    }

    /**
     * Stores the values of @p vectors (ghosted, on @p dofs) on the locally
     * owned cells under @p name. Collective: the cells of every rank are
     * gathered on rank 0, which alone writes the files.
     */
    void
    set_fields(const std::string                    &name,
               const dealii::DoFHandler<2, 3>       &dofs,
               const std::vector<const VectorType *> &vectors);

    /**
     * Reads the block @p name into @p vectors (without ghosts, locally owned
     * entries; compressed here) on the same mesh, partitioned in any way.
     */
    void
    get_fields(const std::string              &name,
               const dealii::DoFHandler<2, 3> &dofs,
               const std::vector<VectorType *> &vectors) const;

    /// The scalars as text: one `key = value` line each.
    std::string
    state_text() const;
    /// The field blocks as one binary buffer (complete on rank 0 only).
    std::vector<char>
    field_bytes() const;

    /// Rebuilds the data from the two buffers (on every rank); throws std::runtime_error if they are malformed.
    static CheckpointData
    from_buffers(const std::string &state, const std::vector<char> &fields);

  private:
    std::map<std::string, std::string>       scalars;
    std::map<std::string, std::vector<char>> fields;
  };

  /**
   * Checkpoints of a long run in `<output directory>/checkpoint/`: two slots,
   * `slot-0` and `slot-1`, written alternately; each is written as
   * `slot-N.tmp`, made durable (fsync) and renamed only when complete, and then
   * the text file `last` names it. A slot holds `fields` (binary),
   * `state` (text) and `manifest` (size and CRC-32 of both), so that a
   * truncated or corrupt slot is recognized on resume and the other one used.
   * A checkpoint that cannot be written (disk full, permissions) is reported
   * and the previous slot kept; the run goes on.
   */
  class Checkpoint
  {
  public:
    /// `resume`: never, always (an error if there is no usable checkpoint), or when a usable one exists.
    enum class Resume
    {
      no,
      yes,
      automatic
    };

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Sets the directory (`<output directory>/checkpoint/`, with a trailing '/') and the communicator.
    void
    initialize(const std::string &directory, const MPI_Comm communicator);

    Resume
    resume_mode() const
    {
      return resume;
    }
    /// Sets `resume` (scene stability reads the newest checkpoint of another run: automatic).
    void
    set_resume_mode(const Resume mode)
    {
      resume = mode;
    }
    /// Whether checkpoints are written at all (by steps or by wall time).
    bool
    enabled() const
    {
      return steps_between > 0 || wall_time_between > 0;
    }
    /// The number of steps a run takes before it checkpoints and stops (0: no limit).
    unsigned int
    steps_per_run() const
    {
      return max_steps_per_run;
    }

    /**
     * Finds the checkpoint to resume from according to `resume`: the newest
     * verified slot (the one `last` names; the other one, with a message on
     * @p log, if that one is missing, truncated or corrupt). Returns false for
     * a fresh start. Throws an InputError if `resume = true` and no slot is
     * usable. Collective (rank 0 decides).
     */
    bool
    find(std::ostream &log);

    /// The data of the slot that find() chose (collective: rank 0 reads, every rank receives).
    CheckpointData
    read() const;

    /// Removes the checkpoints of an earlier run (a fresh start). Collective.
    void
    clear();

    /// Whether a checkpoint is due after step @p step (every N steps, or T seconds of wall time since the last one).
    bool
    due(const unsigned int step) const;

    /**
     * Writes @p data into the slot that does not hold the last good
     * checkpoint. Returns false (after a message on @p log) if it could not be
     * written; the previous slot is then untouched. Collective.
     */
    bool
    write(const CheckpointData &data, const unsigned int step, const double time, std::ostream &log);

    /// The path of the last checkpoint written or resumed from ("" if none).
    std::string
    last_slot() const
    {
      return current_slot.empty() ? std::string() : directory + current_slot;
    }

  private:
    /// Checks one slot: "" if it is complete and its checksums match, else what is wrong.
    std::string
    verify(const std::string &slot) const;

    Resume       resume            = Resume::no;
    unsigned int steps_between     = 0;
    double       wall_time_between = 600;
    unsigned int max_steps_per_run = 0;

    std::string directory;
    MPI_Comm    communicator = MPI_COMM_WORLD;
    std::string current_slot;        ///< "slot-0" or "slot-1": the last good checkpoint
    double      last_write_wall_time = 0;
  };
} // namespace FluidSurface

#endif
