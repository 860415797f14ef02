// SPDX-License-Identifier: LGPL-2.1-or-later
// The scene rule through the program (fluid_surface --validate, --equilibrium): an entry that the file sets
// outside the subsections of its scene is refused with exit status 2 and one message naming the file, the line,
// the entry and the scene, before any component reads its parameters. Scene stability with `steady state/window`
// and `diagnostics/axis` (subsections it does not read) and with `time stepping/end time` (an entry it ignores);
// scene geometry with `bending/Be` and `checkpoint/resume`; --equilibrium with `geometry/refinement`. A geometry
// file with the subsections of its scene is valid.
#include <deal.II/base/mpi.h>

#include <fluid_surface/scenes/run_program.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace FluidSurface;

namespace
{
  /// Writes @p content to @p name and runs fluid_surface @p mode @p name; prints the exit status and the message.
  void
  try_file(const std::string &mode, const std::string &name, const std::string &content)
  {
    std::ofstream(name) << content;
    std::ostringstream screen, errors;
    const int          status = run_program({mode, name}, screen, errors, MPI_COMM_WORLD);
    std::string        message = errors.str().empty() ? screen.str() : errors.str();
    const std::string  prefix  = "fluid_surface: error: ";
    if (message.rfind(prefix, 0) == 0)
      message = message.substr(prefix.size());
    std::cout << mode << ' ' << name << ": exit " << status << ": " << message << std::flush;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string stability = "subsection model\n  set scene = stability\nend\n"
                                "subsection geometry\n  set shape = equilibrium\n  set refinement = 1\nend\n"
                                "subsection initial state\n  set equilibrium rotation = true\nend\n";
  const std::string geometry  = "subsection model\n  set scene = geometry\nend\n"
                                "subsection geometry\n  set refinement = 1\nend\n";
  try_file("--validate",
           "stability_steady_state.prm",
           stability + "subsection steady state\n  set window = 2\nend\nsubsection diagnostics\n  set axis = 0, 0, 1\nend\n");
  try_file("--validate",
           "stability_end_time.prm",
           stability + "subsection time stepping\n  set time step = 0.02\n  set end time = 5\nend\n");
  try_file("--validate",
           "geometry_bending.prm",
           geometry + "subsection bending\n  set Be = 2\nend\nsubsection checkpoint\n  set resume = false\nend\n");
  try_file("--validate",
           "geometry_used.prm",
           geometry + "subsection output\n  set output directory = results_scene_subsections\nend\n");
  try_file("--equilibrium",
           "equilibrium_geometry.prm",
           "subsection equilibrium\n  set branch = oblate\nend\nsubsection geometry\n  set refinement = 2\nend\n");
}
