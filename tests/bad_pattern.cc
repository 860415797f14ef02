// SPDX-License-Identifier: LGPL-2.1-or-later
// A value that fails its pattern ends the run before anything is computed or written: run_program(), which is all
// that main() calls, returns exit status 2 and writes one message to the error stream that names the file, the
// line, the entry, its value and the pattern it was expected to match; nothing goes to the screen, and the output
// directory the file names is not created. The same holds for `--validate`. The output prints the exit status as a
// number and the message verbatim, so a change of either fails the comparison.
#include <deal.II/base/mpi.h>

#include <fluid_surface/scenes/run_program.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace FluidSurface;

namespace
{
  /// Runs the program with @p args; prints its exit status, its error stream, its screen and whether the output
  /// directory exists afterwards.
  void
  run(const std::vector<std::string> &args, const std::string &directory)
  {
    std::filesystem::remove_all(directory);
    std::ostringstream screen, errors;
    const int          status = run_program(args, screen, errors, MPI_COMM_WORLD);
    std::string        command;
    for (const std::string &arg : args)
      command += (command.empty() ? "" : " ") + arg;
    std::cout << command << '\n'
              << "  exit status: " << status << '\n'
              << "  error stream: " << errors.str() << "  screen: " << (screen.str().empty() ? "(nothing)" : screen.str())
              << '\n'
              << "  output directory " << directory << ": "
              << (std::filesystem::exists(directory) ? "created" : "not created") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream("bad_pattern.prm") << "# A value that fails its pattern: the run must stop with exit status 2 before "
                                      "computing.\n"
                                      "subsection output\n  set output directory = results_bad_pattern\nend\n"
                                      "subsection geometry\n  set refinement = two\nend\n";
  run({"bad_pattern.prm"}, "results_bad_pattern");
  run({"--validate", "bad_pattern.prm"}, "results_bad_pattern");
}
