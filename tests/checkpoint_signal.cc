// SPDX-License-Identifier: LGPL-2.1-or-later
// SIGINT and SIGTERM stop a run of scene full after the current step with a checkpoint and a
// message (exit status 130 and 143); resumed, the run ends with the statistics of the uninterrupted
// run A (t ∈ [0, 0.1], 10 steps). The signal comes from a second thread once the run has written three steps (the step at
// which it stops varies; the outcome must not).
#include "checkpoint_common.h"

#include <chrono>
#include <csignal>
#include <filesystem>
#include <thread>

namespace
{
  /// Sends @p signal to this process once @p statistics holds three data rows beyond step 0.
  std::thread
  signal_after_three_steps(const std::string &statistics, const int signal)
  {
    return std::thread([statistics, signal]() {
      for (int i = 0; i < 60000; ++i)
        {
          if (CheckpointTest::n_rows(CheckpointTest::lines_without_wall_time(statistics)) >= 4)
            {
              std::raise(signal);
              return;
            }
          std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
    });
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace CheckpointTest;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const char *d : {"A", "B", "C"})
    std::filesystem::remove_all(d);
  run("A", {{"time stepping/end time", "0.1"}});
  const auto reference = lines_without_wall_time("A/statistics");

  for (const auto &[directory, signal] : {std::pair<std::string, int>{"B", SIGINT}, {"C", SIGTERM}})
    {
      std::thread   sender  = signal_after_three_steps(directory + "/statistics", signal);
      const Outcome stopped = run(directory, {{"checkpoint/resume", "auto"}, {"time stepping/end time", "0.1"}});
      sender.join();
      const bool    named   = stopped.message.find(signal == SIGINT ? "interrupted (SIGINT)" : "terminated (SIGTERM)") == 0 &&
                          stopped.message.find("checkpoint written to " + directory + "/checkpoint/slot-0") !=
                            std::string::npos;
      std::printf("%s: %s: exit status %d, the message names the signal and the checkpoint: %s\n",
                  directory.c_str(), signal == SIGINT ? "SIGINT" : "SIGTERM", stopped.status, yes_no(named));
      const Outcome resumed = run(directory, {{"checkpoint/resume", "auto"}, {"time stepping/end time", "0.1"}});
      std::printf("  resumed: status %d, statistics identical to A: %s\n", resumed.status,
                  yes_no(lines_without_wall_time(directory + "/statistics") == reference));
    }
}
