// SPDX-License-Identifier: LGPL-2.1-or-later
// Bad input ends a run before any computation with one message that names the file, the
// line or entry, and what was expected: missing file, unknown subsection, unknown entry, a value
// failing its pattern, a non-positive semi-axis, BDF2 without the geometry it needs or with a growth factor
// beyond its zero-stability, meshes with triangles or a boundary, and an
// output directory that holds another run.
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
  /// Checks (or, if @p run, runs) the file @p name as the program would; prints its error message or "accepted".
  void
  try_file(const std::string &name, const std::string &content, const bool run = false)
  {
    if (!content.empty())
      std::ofstream(name) << content;
    const std::vector<std::string> args = run ? std::vector<std::string>{name} : std::vector<std::string>{"--validate", name};
    std::ostringstream             screen, errors;
    if (run_program(args, screen, errors, MPI_COMM_WORLD) == 0)
      std::cout << name << ": accepted" << std::endl;
    else
      {
        const std::string prefix = "fluid_surface: error: ";
        std::string       message = errors.str();
        if (message.rfind(prefix, 0) == 0)
          message = message.substr(prefix.size());
        std::cout << message << std::flush;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try_file("missing.prm", "");
  try_file("unknown_subsection.prm", "subsection geometri\n  set refinement = 2\nend\n");
  try_file("unknown_entry.prm", "subsection geometry\n  set refinment = 2\nend\n");
  try_file("bad_pattern.prm", "subsection geometry\n  set position degree = 4\nend\n");
  try_file("bad_axes.prm", "subsection geometry\n  set semi-axes = 1, -1, 2\nend\n");
  try_file("valve_below_floor.prm",
           "subsection model\n  set scene = full\nend\nsubsection mesh redistribution\n  set mesh quality floor = 0.2\n"
           "end\nsubsection reparametrization\n  set quality threshold = 0.1\nend\n");
  try_file("bdf2_lagged.prm",
           "subsection model\n  set scene = full\nend\nsubsection time stepping\n  set scheme = BDF2\nend\n");
  try_file("bdf2_growth.prm",
           "subsection model\n  set scene = full\nend\nsubsection time stepping\n  set scheme = BDF2\n"
           "  set growth factor = 3\nend\nsubsection geometry iteration\n  set maximum iterations = 1\nend\n");
  try_file("pull_without_conformal.prm",
           "subsection model\n  set scene = full\nend\nsubsection mesh redistribution\n"
           "  set pull onset quality = 0.2\n  set full pull quality = 0.15\nend\n");
  try_file("anchor_with_bgn.prm",
           "subsection model\n  set scene = full\nend\nsubsection mesh redistribution\n"
           "  set law = bgn\n  set anchor time = 4\nend\n");
  try_file("azimuthal_without_amplitude.prm",
           "subsection model\n  set scene = full\nend\nsubsection initial state\n"
           "  set perturbation form = azimuthal\nend\n");
  try_file("stability_without_equilibrium.prm", "subsection model\n  set scene = stability\nend\n");
  // The equilibrium of Be = 1 under a bending force of Be = 2 is not at rest: the unperturbed map drifts.
  try_file("stability_not_equilibrium.prm",
           "subsection model\n  set scene = stability\nend\nsubsection geometry\n  set shape = equilibrium\n"
           "  set refinement = 1\n  set position degree = 2\nend\nsubsection equilibrium\n"
           "  set area = 12.600857094577847\n  set reduced volume = 0.7549530890154922\n  set branch = oblate\n"
           "  set Be = 1\n  set angular momentum = 46.64242839801514\nend\nsubsection flow\n  set conserve momenta = "
           "true\nend\nsubsection bending\n  set Be = 2\nend\nsubsection initial state\n  set equilibrium rotation = "
           "true\nend\nsubsection time stepping\n  set time step = 0.05\nend\nsubsection stability\n"
           "  set map time = 0.1\nend\nsubsection output\n  set output directory = stability_not_equilibrium\n"
           "  set overwrite = true\n  set report wall time = false\nend\n",
           true);
  try_file("missing_mesh.prm", "subsection geometry\n  set shape = mesh file\n  set mesh file = nowhere.msh\nend\n");

  // A mesh with a triangle, and an open surface (one quadrilateral).
  std::ofstream("triangles.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n"
                                    "3 1 1 0\n4 0 1 1\n$EndNodes\n$Elements\n2\n1 3 2 0 1 1 2 3 4\n"
                                    "2 2 2 0 1 1 3 4\n$EndElements\n";
  std::ofstream("open.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n"
                               "3 1 1 0\n4 0 1 0\n$EndNodes\n$Elements\n1\n1 3 2 0 1 1 2 3 4\n$EndElements\n";
  const std::string mesh_prm = "subsection geometry\n  set shape = mesh file\n  set refinement = 0\n"
                               "  set project onto ellipsoid = false\n  set mesh file = ";
  const std::string out_prm  = "subsection output\n  set output directory = results_errors\n"
                               "  set write vtu = false\nend\n";
  try_file("triangles.prm", mesh_prm + "triangles.msh\nend\n" + out_prm, true);
  try_file("open.prm", mesh_prm + "open.msh\nend\n" + out_prm, true);

  // A second run into the directory of the first one is refused.
  std::filesystem::remove_all("results_reuse");
  const std::string reuse = "subsection geometry\n  set refinement = 1\nend\n"
                            "subsection output\n  set output directory = results_reuse\n  set write vtu = false\nend\n";
  std::ofstream("first.prm") << reuse;
  std::ostringstream ignored; // the first run's output is not part of this test
  run_program({"first.prm"}, ignored, ignored, MPI_COMM_WORLD);
  try_file("second.prm", reuse, true);
}
