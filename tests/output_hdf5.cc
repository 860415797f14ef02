// SPDX-License-Identifier: LGPL-2.1-or-later
// HDF5/XDMF output (output/format = hdf5) of scene full (the rotating prolate of checkpoint_common.h, refinement 2):
// 1. Two steps written as VTU (run V) and as HDF5 (run H), each cell as 3×3 curved sub-cells (output/subdivisions
//    = 3; default 2): every field of H/solution-00002.h5 is read back with h5py and agrees, node by node, with
//    V/solution-00002.vtu to the VTU's float32 rounding; the cells are the same curved sub-cells (96 · 9 of them);
//    solution.xdmf lists steps 0, 1, 2 with quadrilateral topology and the sizes of the .h5 files.
// 2. Resume (run R, checkpoints every 2 steps, 6 steps): stopped after step 3, resumed to the end; then its newest
//    checkpoint (step 6) is corrupted and the run resumed from step 4 with end time 0.04, which cuts solution.xdmf
//    back to steps 0-4; resumed once more to t = 0.06. Each time solution.xdmf lists each step once, in order.
// On 2 ranks the .h5 files hold the vertices on the partition boundary once per rank (DataOutFilter merges
// duplicates within a rank). The files are read by output_hdf5.py (Debian's python3 with python3-h5py and numpy).
#include "checkpoint_common.h"

#include <filesystem>

namespace
{
  /// Runs output_hdf5.py with @p arguments on rank 0 and prints what it prints.
  void
  python(const std::string &arguments)
  {
    if (!CheckpointTest::is_root())
      return;
    const std::string command =
      "/usr/bin/python3 " FLUID_SURFACE_SOURCE_DIR "/tests/output_hdf5.py " + arguments + " 2>&1";
    FILE *pipe = popen(command.c_str(), "r");
    char  line[1024];
    while (pipe && std::fgets(line, sizeof line, pipe))
      std::fputs(line, stdout);
    const int status = pipe ? pclose(pipe) : -1;
    if (status != 0)
      std::printf("output_hdf5.py %s failed (status %d)\n", arguments.c_str(), status);
  }

  /// Runs R with @p overrides and prints its status, its messages and the steps solution.xdmf lists.
  void
  run_and_list(const char *what, const CheckpointTest::Overrides &overrides)
  {
    const CheckpointTest::Outcome r = CheckpointTest::run("R", overrides);
    std::printf("R %s: status %d\n%s", what, r.status, CheckpointTest::messages(r.screen).c_str());
    if (!r.message.empty())
      std::printf("  %s\n", r.message.c_str());
    std::fflush(stdout);
    python("series R");
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace CheckpointTest;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (!is_root())
    std::freopen("/dev/null", "w", stdout); // the report comes from rank 0 only
  else
    for (const char *d : {"V", "H", "R"})
      std::filesystem::remove_all(d);
  MPI_Barrier(MPI_COMM_WORLD);

  const Overrides two_steps = {{"output/write vtu", "true"},
                               {"output/subdivisions", "3"},
                               {"time stepping/end time", "0.02"}};
  Overrides       vtu = two_steps, hdf5 = two_steps;
  vtu.push_back({"output/format", "vtu"});
  hdf5.push_back({"output/format", "hdf5"});
  std::printf("V (vtu): status %d\n", run("V", vtu).status);
  std::printf("H (hdf5): status %d\n", run("H", hdf5).status);
  std::fflush(stdout);
  python("compare V/solution-00002.vtu H/solution-00002.h5");
  python("series H");

  Overrides resumed = {{"output/write vtu", "true"},
                       {"output/format", "hdf5"},
                       {"checkpoint/steps between checkpoints", "2"},
                       {"checkpoint/resume", "auto"}};
  Overrides first = resumed;
  first.push_back({"checkpoint/steps per run", "3"});
  run_and_list("stopped after step 3", first);
  run_and_list("resumed", resumed);
  if (is_root())
    flip_byte(newest_slot("R") + "/fields");
  MPI_Barrier(MPI_COMM_WORLD);
  Overrides shorter = resumed;
  shorter.push_back({"time stepping/end time", "0.04"});
  run_and_list("resumed from the older slot with end time 0.04", shorter);
  run_and_list("resumed to t = 0.06", resumed);
}
