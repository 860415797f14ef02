// SPDX-License-Identifier: LGPL-2.1-or-later
// Shared by the checkpoint_* tests: runs scene full in-process through run_simulation (main's exit statuses and
// messages; the rotating prolate of full_rotation.prm, refinement 2, adaptive τ, t ∈ [0, 0.06]: 6 steps) with
// prm overrides, captures the screen,
// and reads `statistics` and `summary` without their wall-time entries (the only values that may
// differ between an interrupted and an uninterrupted run).
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <fluid_surface/scenes/run_program.h>
#include <fluid_surface/scenes/simulation.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "parameter_overrides.h"

namespace CheckpointTest
{
  using FluidSurface::Overrides;

  struct Outcome
  {
    int         status = 0; ///< what main() would return
    std::string message;    ///< RunStopped's or the error's text
    std::string screen;     ///< what the run printed on rank 0
  };

  /// The text of the last "fluid_surface: [error: ]..." message in @p text ("" if none).
  inline std::string
  program_message(const std::string &text)
  {
    std::istringstream in(text);
    std::string        message;
    for (std::string line; std::getline(in, line);)
      if (line.rfind("fluid_surface: ", 0) == 0)
        {
          message = line.substr(15);
          if (message.rfind("error: ", 0) == 0)
            message = message.substr(7);
        }
    return message;
  }

  /// Runs the test case into @p directory with @p overrides on @p comm.
  inline Outcome
  run(const std::string &directory, const Overrides &overrides, const MPI_Comm comm = MPI_COMM_WORLD)
  {
    using namespace FluidSurface;
    dealii::ParameterHandler prm;
    Simulation::declare_parameters(prm);
    Overrides all = {{"model/scene", "full"},
                     {"geometry/shape", "ellipsoid"},
                     {"geometry/semi-axes", "0.61, 0.61, 2.02"},
                     {"geometry/refinement", "2"},
                     // Direct solves: with the factorization kept across steps (the default) or with
                     // single-precision factors (the default; every solve is then GMRES from the last
                     // solution) a run agrees bit for bit only with runs that checkpoint at the same steps
                     // (see checkpoint/resume; checkpoint_resume_schemes tests that case).
                     {"linear solver/reuse factorization", "false"},
                     {"linear solver/factor precision", "double"},
                     {"initial state/angular velocity", "4"},
                     {"time stepping/end time", "0.06"},
                     {"time stepping/time step", "0.01"},
                     {"output/output directory", directory},
                     {"output/overwrite", "false"},
                     {"output/write vtu", "false"},
                     {"output/screen interval", "100"},
                     {"output/report wall time", "false"},
                     {"checkpoint/wall time between checkpoints", "0"}};
    all.insert(all.end(), overrides.begin(), overrides.end());
    FluidSurface::set_overrides(prm, all);
    Outcome            outcome;
    std::ostringstream screen, errors;
    outcome.status  = FluidSurface::run_simulation(prm, screen, errors, comm);
    outcome.screen  = screen.str();
    outcome.message = program_message(outcome.status == 0 ? outcome.screen : errors.str());
    return outcome;
  }

  /// The lines of @p file; the column (statistics) or line (summary) named "wall time" removed.
  inline std::vector<std::string>
  lines_without_wall_time(const std::string &file)
  {
    std::ifstream            in(file);
    std::vector<std::string> lines;
    int                      wall_column = -1, n_columns = 0;
    for (std::string line; std::getline(in, line);)
      {
        if (line.rfind("wall time:", 0) == 0)
          continue;
        if (line.rfind("# ", 0) == 0)
          {
            if (line.size() > 11 && line.compare(line.size() - 11, 11, ": wall time") == 0)
              wall_column = n_columns;
            ++n_columns;
            lines.push_back(line);
            continue;
          }
        if (line.find(':') != std::string::npos)
          {
            lines.push_back(line);
            continue;
          }
        std::istringstream words(line);
        std::string        word, kept;
        for (int c = 0; words >> word; ++c)
          if (c != wall_column)
            kept += (kept.empty() ? "" : " ") + word;
        lines.push_back(kept);
      }
    return lines;
  }

  /// Number of data rows of a statistics file.
  inline unsigned int
  n_rows(const std::vector<std::string> &lines)
  {
    unsigned int n = 0;
    for (const auto &line : lines)
      n += (line.rfind("#", 0) != 0);
    return n;
  }

  /// The screen lines that start with "--" or contain "warning" (checkpoint and resume messages).
  inline std::string
  messages(const std::string &screen)
  {
    std::istringstream in(screen);
    std::string        out;
    for (std::string line; std::getline(in, line);)
      if ((line.rfind("-- ", 0) == 0 && line.rfind("-- fluid_surface:", 0) != 0) ||
          line.find("warning") != std::string::npos)
        out += line + "\n";
    return out;
  }

  /// The newest checkpoint slot of the run in @p directory (the one `checkpoint/last` names).
  inline std::string
  newest_slot(const std::string &directory)
  {
    std::ifstream last(directory + "/checkpoint/last");
    std::string   slot;
    last >> slot;
    return directory + "/checkpoint/" + slot;
  }

  /// Corrupts @p file: flips one bit of its middle byte.
  inline void
  flip_byte(const std::string &file)
  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(0, std::ios::end);
    const auto size = static_cast<long>(f.tellg());
    f.seekg(size / 2);
    char c;
    f.get(c);
    f.seekp(size / 2);
    f.put(static_cast<char>(c ^ 0x10));
  }

  inline const char *
  yes_no(const bool b)
  {
    return b ? "yes" : "no";
  }

  inline bool
  is_root()
  {
    return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }
} // namespace CheckpointTest
