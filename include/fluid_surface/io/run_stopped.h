// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_io_run_stopped_h
#define fluid_surface_io_run_stopped_h

#include <deal.II/base/exceptions.h>

#include <fstream>
#include <sstream>
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

  /**
   * A run that cannot go on although its input was valid: the energy control would need τ < τ_min, the
   * linear solver failed at every τ tried, or the mesh quality fell below its floor. what() is reason()
   * followed by what to try; the summary's status line gives reason() alone. Exit status 1.
   */
  class RunFailed : public std::runtime_error
  {
  public:
    RunFailed(const std::string &reason, const std::string &advice)
      : std::runtime_error(reason + "; " + advice)
      , reason_text(reason)
    {}

    /// What went wrong, where: "step rejected at t = … with τ = … (…)".
    const std::string &
    reason() const
    {
      return reason_text;
    }

  private:
    std::string reason_text;
  };

  /**
   * The message of @p exc on one line: for a deal.II exception (a failed Trilinos call, an assertion) its
   * additional information without the source location and stack trace, otherwise what() up to its first
   * line break; at most @p max_length characters.
   */
  inline std::string
  one_line_message(const std::exception &exc, const std::size_t max_length = 300)
  {
    std::string text = exc.what();
    if (const auto *deal_ii = dynamic_cast<const dealii::ExceptionBase *>(&exc))
      {
        std::ostringstream info;
        deal_ii->print_info(info);
        text = info.str();
      }
    std::string line;
    bool        in_space = true;
    for (const char c : text)
      {
        const bool space = (c == ' ' || c == '\n' || c == '\t' || c == '\r');
        if (space && !in_space)
          line += ' ';
        if (!space)
          line += c;
        in_space = space;
      }
    while (!line.empty() && line.back() == ' ')
      line.pop_back();
    if (max_length != std::string::npos && line.size() > max_length)
      line = line.substr(0, max_length - 3) + "...";
    return line;
  }

  /**
   * Appends @p text (a paragraph: what failed, where, and the solver's own report) to the file `error.log`
   * of the output @p directory (with its trailing slash). Call on one rank only.
   */
  inline void
  append_to_error_log(const std::string &directory, const std::string &text)
  {
    std::ofstream log(directory + "error.log", std::ios::app);
    log << text << (text.empty() || text.back() == '\n' ? "" : "\n") << '\n';
  }
} // namespace FluidSurface

#endif
