// SPDX-License-Identifier: LGPL-2.1-or-later
// ASPECT-style checkpoint test of scene full (rotating prolate, adaptive τ): run A goes to t = 0.06
// without checkpoints; run B writes a checkpoint every 3 steps and stops after 4 ('steps per run'),
// then is resumed (resume = true, in a directory that holds its statistics, overwrite = false) to
// t = 0.06. The statistics and summary of A and B must be identical apart from the wall time, and
// resuming the finished run (resume = auto) from its final checkpoint changes nothing.
#include "checkpoint_common.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  using namespace CheckpointTest;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::filesystem::remove_all("A");
  std::filesystem::remove_all("B");

  const Outcome a = run("A", {{"checkpoint/steps between checkpoints", "0"}});
  const auto    reference = lines_without_wall_time("A/statistics");
  std::printf("A: status %d, %u rows, checkpoint slots written: %s\n", a.status, n_rows(reference),
              yes_no(std::filesystem::exists("A/checkpoint/slot-0")));

  const Overrides b_parameters = {{"checkpoint/steps between checkpoints", "3"}};
  Overrides       first        = b_parameters;
  first.push_back({"checkpoint/steps per run", "4"});
  const Outcome b1 = run("B", first);
  std::printf("B, first part: status %d, %u rows\n  %s\n", b1.status, n_rows(lines_without_wall_time("B/statistics")),
              b1.message.c_str());
  std::ifstream last("B/checkpoint/last");
  std::string   slot, word;
  unsigned int  step = 0;
  last >> slot >> word >> step;
  std::printf("  B/checkpoint/last names %s, step %u\n", slot.c_str(), step);

  const Outcome fresh = run("B", b_parameters);
  std::printf("a new run into B without overwrite: status %d\n", fresh.status);

  Overrides second = b_parameters;
  second.push_back({"checkpoint/resume", "true"});
  const Outcome b2      = run("B", second);
  const auto    resumed = lines_without_wall_time("B/statistics");
  std::printf("B, resumed: status %d, %u rows\n%s", b2.status, n_rows(resumed), messages(b2.screen).c_str());
  std::printf("statistics identical to A: %s\n", yes_no(resumed == reference));
  std::printf("summary identical to A: %s\n",
              yes_no(lines_without_wall_time("B/summary") == lines_without_wall_time("A/summary")));

  Overrides again = b_parameters;
  again.push_back({"checkpoint/resume", "auto"});
  const Outcome b3 = run("B", again);
  std::printf("B, resumed after its end: status %d\n%s", b3.status, messages(b3.screen).c_str());
  std::printf("statistics and summary still identical to A: %s\n",
              yes_no(lines_without_wall_time("B/statistics") == reference &&
                     lines_without_wall_time("B/summary") == lines_without_wall_time("A/summary")));
  std::istringstream final_row(reference.back());
  std::string        words[6];
  for (auto &w : words)
    final_row >> w;
  std::printf("last row: step %s  t = %s  tau = %s  F = %s\n", words[0].c_str(), words[1].c_str(),
              words[2].c_str(), words[5].c_str());
}
