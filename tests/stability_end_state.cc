// SPDX-License-Identifier: LGPL-2.1-or-later
// Scene stability with base state = checkpoint (the path of prm/stability_end_state_*.prm): a checkpoint of scene
// full one step after the rotating oblate equilibrium of tests/stability_spectrum.cc (refinement 2), analysed
// without azimuthal classes, from a seed of all modes m ≤ 4. Its leading growth rate must be the oblate's m = 2
// instability that the equilibrium path finds (σ = 2.52 at this refinement and τ = 0.02). Only the leading eigenvalue
// is asked for; the exit status says whether its residual met the tolerance. Printed: the exit status, the number
// of rows, the class of the leading row and σ rounded. Then a checkpoint directory without a checkpoint: exit
// status 2 and one line. About 40 s.
#include <deal.II/base/mpi.h>

#include <fluid_surface/scenes/run_program.h>

#include "spectrum_csv.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace FluidSurface;

namespace
{
  /// The model of the oblate equilibrium at refinement 2 (prm/stability_oblate.prm, coarse).
  const std::string model_entries =
    "subsection geometry\n  set shape = equilibrium\n  set refinement = 2\n  set position degree = 2\nend\n"
    "subsection equilibrium\n  set area = 12.600857094577847\n  set reduced volume = 0.7549530890154922\n"
    "  set branch = oblate\n  set Be = 1\n  set angular momentum = 46.64242839801514\nend\n"
    "subsection flow\n  set Re = 1\n  set conserve momenta = true\nend\n"
    "subsection initial state\n  set equilibrium rotation = true\nend\n"
    "subsection geometry iteration\n  set maximum iterations = 1\n  set tolerance = 0\n  set apply = always\nend\n"
    "subsection mesh redistribution\n  set tangential law = membrane\nend\n";

  /// Runs @p content as @p name; returns the exit status and the first line of the error message.
  std::pair<int, std::string>
  run(const std::string &name, const std::string &content)
  {
    std::ofstream(name) << content;
    std::ostringstream screen, errors;
    const int          status = run_program({name}, screen, errors, MPI_COMM_WORLD);
    std::string        line;
    std::getline(std::istringstream(errors.str()) >> std::ws, line);
    const std::string prefix = "fluid_surface: error: ";
    return {status, line.rfind(prefix, 0) == 0 ? line.substr(prefix.size()) : line};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::filesystem::remove_all("results_full");
  std::filesystem::remove_all("results_end_state");
  const auto full = run("full.prm",
                        "subsection model\n  set scene = full\nend\n" + model_entries +
                          "subsection time stepping\n  set end time = 0.02\n  set time step = 0.02\n"
                          "  set scheme = BDF2\nend\nsubsection checkpoint\n  set steps between checkpoints = 1\nend\n"
                          "subsection output\n  set output directory = results_full\n  set write vtu = false\n"
                          "  set report wall time = false\nend\n");
  std::cout << "scene full: exit status " << full.first << std::endl;

  const std::string stability = "subsection model\n  set scene = stability\nend\n" + model_entries +
                                "subsection time stepping\n  set time step = 0.02\n  set scheme = BDF2\nend\n"
                                "subsection stability\n  set base state = checkpoint\n"
                                "  set maximum Krylov dimension = 20\n  set eigenvalues per wavenumber = 1\n";
  const auto end_state = run("end_state.prm",
                             stability + "  set checkpoint directory = results_full\nend\n"
                                         "subsection output\n  set output directory = results_end_state\n"
                                         "  set report wall time = false\nend\n");
  const std::vector<std::vector<std::string>> rows = read_spectrum_csv("results_end_state/spectrum.csv");
  std::cout << "scene stability from the checkpoint: exit status " << end_state.first << ", rows "
            << (rows.empty() ? 0 : rows.size() - 1) << std::endl;
  if (rows.size() > 1)
    std::cout << "leading: m = " << rows[1][0] << " " << rows[1][1] << ", σ = " << std::fixed << std::setprecision(2)
              << std::stod(rows[1][2]) << ", seed " << rows[1][9] << std::endl;

  std::filesystem::create_directories("no_checkpoint");
  const auto missing = run("missing.prm",
                           stability + "  set checkpoint directory = no_checkpoint\nend\n"
                                       "subsection output\n  set output directory = results_missing\n"
                                       "  set overwrite = true\nend\n");
  std::cout << "no checkpoint: exit status " << missing.first << "\n" << missing.second << std::endl;
}
