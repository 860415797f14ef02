// SPDX-License-Identifier: LGPL-2.1-or-later
// A resumed run with the error-controlled step size and the implicit geometry (time stepping/error tolerance,
// geometry iteration) continues bit for bit: the error estimate's history (the nodes' normal speeds of the last
// step and its τ) is kept in the checkpoint, and with scheme = BDF2 also the state before the last step. Run A
// goes to t = 0.3 without checkpoints; run B writes a checkpoint every 3 steps, stops after 4 and is resumed.
// The statistics of A and B must be identical apart from the wall time, and τ must have grown past its
// initial 0.01. Once with backward Euler, once with BDF2.
#include "checkpoint_common.h"

#include <filesystem>

namespace
{
  using namespace CheckpointTest;

  void
  check_resume(const std::string &scheme)
  {
    std::printf("scheme %s\n", scheme.c_str());
    std::filesystem::remove_all("A");
    std::filesystem::remove_all("B");
    const Overrides controlled = {{"time stepping/end time", "0.3"},
                                  {"time stepping/maximum time step", "0.1"},
                                  {"time stepping/error tolerance", "1e-3"},
                                  {"time stepping/scheme", scheme},
                                  {"geometry iteration/maximum iterations", "10"},
                                  {"geometry iteration/tolerance", "1e-4"}};

    Overrides a_parameters = controlled;
    a_parameters.push_back({"checkpoint/steps between checkpoints", "0"});
    const Outcome a         = run("A", a_parameters);
    const auto    reference = lines_without_wall_time("A/statistics");
    std::printf("A: status %d, %u rows\n", a.status, n_rows(reference));

    Overrides b_parameters = controlled;
    b_parameters.push_back({"checkpoint/steps between checkpoints", "3"});
    Overrides first = b_parameters;
    first.push_back({"checkpoint/steps per run", "4"});
    const Outcome b1 = run("B", first);
    std::printf("B, first part: status %d, %u rows\n", b1.status, n_rows(lines_without_wall_time("B/statistics")));
    Overrides second = b_parameters;
    second.push_back({"checkpoint/resume", "true"});
    const Outcome b2      = run("B", second);
    const auto    resumed = lines_without_wall_time("B/statistics");
    std::printf("B, resumed: status %d, %u rows\n", b2.status, n_rows(resumed));
    std::printf("statistics identical to A: %s\n", yes_no(resumed == reference));
    std::istringstream final_row(reference.back());
    std::string        words[6];
    for (auto &w : words)
      final_row >> w;
    std::printf("last row: step %s  t = %s  tau = %s  F = %s\n", words[0].c_str(), words[1].c_str(),
                words[2].c_str(), words[5].c_str());
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_resume("backward Euler");
  check_resume("BDF2");
}
