// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>

#include <fluid_surface/io/stop_signals.h>

#include <csignal>

namespace FluidSurface
{
  namespace
  {
    volatile std::sig_atomic_t received_signal = 0;

    extern "C" void
    on_stop_signal(int signal)
    {
      if (received_signal != 0)
        {
          // A second signal: the user insists.
          std::signal(signal, SIG_DFL);
          std::raise(signal);
          return;
        }
      received_signal = signal;
    }
  } // namespace

  StopSignals::StopSignals(const MPI_Comm communicator)
    : communicator(communicator)
  {
    received_signal = 0;
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
  }

  StopSignals::~StopSignals()
  {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  }

  int
  StopSignals::received() const
  {
    return dealii::Utilities::MPI::max(static_cast<int>(received_signal), communicator);
  }
} // namespace FluidSurface
