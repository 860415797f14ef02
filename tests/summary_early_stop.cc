// SPDX-License-Identifier: LGPL-2.1-or-later
// A run of scene full that stops early still writes its summary, whose first line says why: a mesh quality
// floor of 0.99 stops a coarse prolate run after its first step (exit status 1, one message line); a run
// stopped by `checkpoint/steps per run` (exit 0) says so too; a run that reaches its end time says
// `status: completed`.
#include <deal.II/base/mpi.h>

#include <fluid_surface/scenes/run_program.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

using namespace FluidSurface;

namespace
{
  /// Runs @p name with @p extra entries; prints the exit status, the message and the summary's first line.
  void
  run(const std::string &name, const std::string &extra)
  {
    const std::string directory = "results_" + name;
    std::filesystem::remove_all(directory);
    std::ofstream(name + ".prm") << "subsection model\n  set scene = full\nend\n"
                                    "subsection geometry\n  set shape = ellipsoid\n  set semi-axes = 0.61, 0.61, 2.02\n"
                                    "  set refinement = 1\nend\n"
                                    "subsection initial state\n  set angular velocity = 4\nend\n"
                                    "subsection time stepping\n  set end time = 0.03\n  set time step = 0.01\nend\n"
                                    "subsection output\n  set output directory = " +
                                      directory +
                                      "\n  set write vtu = false\n  set report wall time = false\nend\n" + extra;
    std::ostringstream screen, errors;
    const int          status = run_program({name + ".prm"}, screen, errors, MPI_COMM_WORLD);
    // The message: on the error stream, or (exit status 0) the screen's line "fluid_surface: ...".
    const std::string error_text = errors.str(), screen_text = screen.str();
    const std::size_t at         = screen_text.find("\nfluid_surface: ");
    std::string       message, status_line;
    std::istringstream messages(!error_text.empty() ? error_text :
                                at != std::string::npos ? screen_text.substr(at + 1) :
                                                          std::string());
    std::getline(messages, message);
    std::ifstream summary(directory + "/summary");
    std::getline(summary, status_line);
    std::cout << name << ": exit status " << status << '\n'
              << "  message: " << message << '\n'
              << "  lines on the error stream: " << std::count(error_text.begin(), error_text.end(), '\n') << '\n'
              << "  summary: " << (summary ? status_line : std::string("missing")) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run("mesh_quality_floor",
      "subsection mesh redistribution\n  set mesh quality floor = 0.99\nend\n"
      "subsection reparametrization\n  set quality threshold = 0\nend\n");
  run("steps_per_run", "subsection checkpoint\n  set steps per run = 2\nend\n");
  run("completed", "");
}
