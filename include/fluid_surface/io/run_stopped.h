#ifndef fluid_surface_io_run_stopped_h
#define fluid_surface_io_run_stopped_h

#include <stdexcept>
#include <string>

namespace FluidSurface
{
  /**
   * A run stopped on request after writing a checkpoint (SIGINT/SIGTERM, or
   * `checkpoint/steps per run`); what() is the message for the user.
   */
  class RunStopped : public std::runtime_error
  {
  public:
    RunStopped(const std::string &message, const int exit_status)
      : std::runtime_error(message)
      , status(exit_status)
    {}

    /**
     * 0 after `steps per run`, 128 + signal number after a signal (the shell's
     * convention), 1 if the checkpoint could not be written.
     */
    int
    exit_status() const
    {
      return status;
    }

  private:
    int status;
  };
} // namespace FluidSurface

#endif
