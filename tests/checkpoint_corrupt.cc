// SPDX-License-Identifier: LGPL-2.1-or-later
// A corrupt or truncated newest checkpoint slot is detected on resume and the older slot used: run B
// writes checkpoints every 2 steps and stops after 4 (slots at steps 2 and 4); the newest slot gets
// one flipped byte, the run is resumed from the older one and must end with the statistics of the
// uninterrupted run A. The same with a truncated file; with both slots unusable, resume = true is
// an input error and resume = auto (overwrite = true) starts a new run.
#include "checkpoint_common.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  using namespace CheckpointTest;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const char *d : {"A", "B", "C"})
    std::filesystem::remove_all(d);
  run("A", {});
  const auto reference = lines_without_wall_time("A/statistics");

  const Overrides checkpoints = {{"checkpoint/steps between checkpoints", "2"}};
  Overrides       stop_at_4   = checkpoints;
  stop_at_4.push_back({"checkpoint/steps per run", "4"});
  Overrides resume_true = checkpoints, resume_auto = checkpoints;
  resume_true.push_back({"checkpoint/resume", "true"});
  resume_auto.push_back({"checkpoint/resume", "auto"});
  resume_auto.push_back({"output/overwrite", "true"});

  // A flipped byte in the fields of the newest slot.
  run("B", stop_at_4);
  std::printf("B stopped; newest slot %s\n", newest_slot("B").c_str());
  flip_byte(newest_slot("B") + "/fields");
  Outcome b = run("B", resume_true);
  std::printf("resumed: status %d\n%s", b.status, messages(b.screen).c_str());
  std::printf("statistics identical to A: %s\n", yes_no(lines_without_wall_time("B/statistics") == reference));

  // A truncated fields file in the newest slot.
  run("C", stop_at_4);
  std::filesystem::resize_file(newest_slot("C") + "/fields", 1000);
  Outcome c = run("C", resume_true);
  std::printf("resumed: status %d\n%s", c.status, messages(c.screen).c_str());
  std::printf("statistics identical to A: %s\n", yes_no(lines_without_wall_time("C/statistics") == reference));

  // Both slots unusable.
  run("C", stop_at_4);
  std::filesystem::remove("C/checkpoint/slot-0/manifest");
  flip_byte("C/checkpoint/slot-1/state");
  c = run("C", resume_true);
  std::printf("both slots bad, resume = true: status %d\n  %s\n", c.status, c.message.c_str());
  c = run("C", resume_auto);
  std::printf("both slots bad, resume = auto: status %d\n%s", c.status, messages(c.screen).c_str());
  std::printf("statistics identical to A: %s\n", yes_no(lines_without_wall_time("C/statistics") == reference));
}
