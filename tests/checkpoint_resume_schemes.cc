// SPDX-License-Identifier: LGPL-2.1-or-later
// The histories of the second-order schemes survive a checkpoint: BDF2 and SDIRK2 in the Tisserand frame (the
// rotating prolate of checkpoint_common.h, adaptive τ from 0.01, t ∈ [0, 0.06]). Run A goes through without stopping;
// run B stops after 3 steps ('steps per run') and is resumed. Both write a checkpoint every 3 steps, so with
// the factorization kept across steps (dropped at each checkpoint, with the last solution GMRES starts from) and
// single-precision factors (every solve GMRES) they solve with the same factors from the same guesses: the
// statistics and summaries of A and B must be identical apart from the wall time.
#include "checkpoint_common.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  using namespace CheckpointTest;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const std::string scheme : {"BDF2", "SDIRK2"})
    {
      std::filesystem::remove_all("A");
      std::filesystem::remove_all("B");
      const Overrides common = {{"time stepping/scheme", scheme},
                                {"time stepping/frame", "Tisserand"},
                                {"geometry iteration/maximum iterations", "1"},
                                {"geometry iteration/tolerance", "0"},
                                {"linear solver/reuse factorization", "true"},
                                {"linear solver/factor precision", "single"},
                                {"checkpoint/steps between checkpoints", "3"}};
      const Outcome a = run("A", common);
      if (a.status != 0)
        std::printf("%s\n", a.message.c_str());
      const auto reference = lines_without_wall_time("A/statistics");
      Overrides  first     = common;
      first.push_back({"checkpoint/steps per run", "3"});
      const Outcome      b1      = run("B", first);
      const unsigned int b1_rows = n_rows(lines_without_wall_time("B/statistics"));
      Overrides          second  = common;
      second.push_back({"checkpoint/resume", "true"});
      const Outcome      b2 = run("B", second);
      std::istringstream final_row(reference.back());
      std::string        words[6];
      for (auto &w : words)
        final_row >> w;
      std::printf("%s: A status %d (%u rows), B stopped with %d after %u rows, resumed with %d\n"
                  "  statistics identical: %s, summary identical: %s; last row: step %s t = %s F = %.8g\n",
                  scheme.c_str(),
                  a.status,
                  n_rows(reference),
                  b1.status,
                  b1_rows,
                  b2.status,
                  yes_no(lines_without_wall_time("B/statistics") == reference),
                  yes_no(lines_without_wall_time("B/summary") == lines_without_wall_time("A/summary")),
                  words[0].c_str(),
                  words[1].c_str(),
                  std::stod(words[5]));
    }
}
