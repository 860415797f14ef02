// SPDX-License-Identifier: LGPL-2.1-or-later
// Resuming on 2 MPI ranks a run checkpointed on 1: rank 0 alone runs A (uninterrupted) and B (stops
// after 4 steps with a checkpoint); then both ranks resume B. The rows must agree with A to
// rounding (the parallel solve orders its sums differently): same steps and τ, energies, area,
// volume, ω, L_z and γ within 1e-9 relative.
#include "checkpoint_common.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace
{
  std::vector<std::vector<double>>
  numbers(const std::vector<std::string> &lines)
  {
    std::vector<std::vector<double>> rows;
    for (const auto &line : lines)
      if (line.rfind("#", 0) != 0)
        {
          std::istringstream in(line);
          rows.emplace_back();
          for (double x; in >> x;)
            rows.back().push_back(x);
        }
    return rows;
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace CheckpointTest;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPI_Comm serial;
  MPI_Comm_split(MPI_COMM_WORLD, is_root() ? 0 : MPI_UNDEFINED, 0, &serial);
  if (is_root())
    {
      std::filesystem::remove_all("A");
      std::filesystem::remove_all("B");
      run("A", {}, serial);
      const Outcome b = run("B", {{"checkpoint/steps per run", "4"}}, serial);
      std::printf("B on 1 rank: status %d\n  %s\n", b.status, b.message.c_str());
      MPI_Comm_free(&serial);
    }
  MPI_Barrier(MPI_COMM_WORLD);
  const Outcome resumed = run("B", {{"checkpoint/resume", "true"}});
  if (is_root())
    {
      std::printf("B resumed on %u ranks: status %d\n%s", dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
                  resumed.status, messages(resumed.screen).c_str());
      const std::vector<std::string> header = [] {
        std::vector<std::string> h;
        for (const auto &line : lines_without_wall_time("A/statistics"))
          if (line.rfind("# ", 0) == 0)
            h.push_back(line.substr(line.find(": ") + 2));
        return h;
      }();
      const auto a = numbers(lines_without_wall_time("A/statistics"));
      const auto r = numbers(lines_without_wall_time("B/statistics"));
      const std::vector<std::string> compared = {"time step", "time", "tau", "kinetic energy", "bending energy",
                                                 "total energy", "area", "volume", "angular velocity",
                                                 "angular momentum z", "volume multiplier"};
      double largest = 0;
      bool   same_shape = (a.size() == r.size());
      for (unsigned int i = 0; same_shape && i < a.size(); ++i)
        for (const auto &name : compared)
          {
            const unsigned int c = std::find(header.begin(), header.end(), name) - header.begin();
            largest = std::max(largest, std::abs(a[i][c] - r[i][c]) / std::max(std::abs(a[i][c]), 1e-12));
          }
      std::printf("rows: %zu and %zu; every compared column within 1e-9 relative: %s\n", a.size(), r.size(),
                  yes_no(same_shape && largest < 1e-9));
      const unsigned int F = std::find(header.begin(), header.end(), "total energy") - header.begin();
      std::printf("final total energy %.9g (1 rank) %.9g (resumed on 2)\n", a.back()[F], r.back()[F]);
    }
}
