// SPDX-License-Identifier: LGPL-2.1-or-later
// A checkpoint that cannot be written is reported and the previous slot kept. Run B checkpoints at
// step 2 and stops; it is resumed with files limited to 50 kB (RLIMIT_FSIZE: writes fail with EFBIG
// as on a full disk, also for root), so that its checkpoint at step 4 fails, the run goes on, and
// it stops after 3 more steps without a new checkpoint (exit status 1). Without the limit it resumes from
// the step-2 slot and ends with the statistics of the uninterrupted run A.
#include "checkpoint_common.h"

#include <sys/resource.h>

#include <csignal>
#include <filesystem>

namespace
{
  void
  limit_file_size(const rlim_t bytes)
  {
    rlimit limit;
    getrlimit(RLIMIT_FSIZE, &limit);
    limit.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limit);
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace CheckpointTest;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::filesystem::remove_all("A");
  std::filesystem::remove_all("B");
  run("A", {});
  const auto reference = lines_without_wall_time("A/statistics");

  const Outcome b1 = run("B", {{"checkpoint/steps between checkpoints", "2"}, {"checkpoint/steps per run", "2"}});
  std::printf("B: status %d\n  %s\n", b1.status, b1.message.c_str());

  rlimit original;
  getrlimit(RLIMIT_FSIZE, &original);
  std::signal(SIGXFSZ, SIG_IGN);
  limit_file_size(50000);
  const Outcome b2 = run("B",
                         {{"checkpoint/steps between checkpoints", "2"},
                          {"checkpoint/steps per run", "3"},
                          {"checkpoint/resume", "true"}});
  limit_file_size(original.rlim_cur);
  std::printf("B resumed with 50 kB files: status %d\n%s  %s\n", b2.status, messages(b2.screen).c_str(),
              b2.message.c_str());
  std::printf("no temporary slot left: %s\n", yes_no(!std::filesystem::exists("B/checkpoint/slot-1.tmp")));

  const Outcome b3 = run("B", {{"checkpoint/steps between checkpoints", "2"}, {"checkpoint/resume", "true"}});
  std::printf("B resumed again: status %d\n%s", b3.status, messages(b3.screen).c_str());
  std::printf("statistics identical to A: %s\n", yes_no(lines_without_wall_time("B/statistics") == reference));
}
