// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_io_stop_signals_h
#define fluid_surface_io_stop_signals_h

#include <deal.II/base/mpi.h>

namespace FluidSurface
{
  /**
   * SIGINT and SIGTERM as a request to stop: while an object of this class
   * exists, either signal only sets a flag (a second one kills the process),
   * so that the time loop can finish its step, write a checkpoint and stop.
   * The default handlers come back when the object is destroyed, however the
   * loop ends.
   */
  class StopSignals
  {
  public:
    /// Installs the handlers; the flag starts cleared.
    explicit StopSignals(const MPI_Comm communicator);
    /// Restores the default handlers.
    ~StopSignals();

    StopSignals(const StopSignals &) = delete;
    StopSignals &
    operator=(const StopSignals &) = delete;

    /// The signal received on any rank since construction (0: none). Collective.
    int
    received() const;

  private:
    MPI_Comm communicator;
  };
} // namespace FluidSurface

#endif
