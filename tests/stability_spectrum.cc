// SPDX-License-Identifier: LGPL-2.1-or-later
// Scene stability on a coarse mesh (refinement 2): the rotating oblate equilibrium of prm/stability_oblate.prm,
// m = 2 even only. Its leading eigenvalue pair is the oblate's instability: σ = 2.524 and co-rotating frequency
// −2.55 at this refinement (the seeded nonlinear run gives 2.567 and −2.537 at refinement 3, benchmarks/spectrum).
// Printed: the leading row of spectrum.csv rounded, and whether σ is within 2 % of the seeded run's. Then the same
// with at most 4 Krylov vectors and thick restarts: it converges to the σ of the 20 vectors (two restarts). Then
// with at most 3 Krylov vectors and no restart: the eigenvalue cannot converge to the residual tolerance 0.1
// (stability/residual tolerance; default 1e-3, residual 0.178), the run ends with exit status 1 and one line, and
// spectrum.csv keeps its rows. Last, with an equilibrium tolerance of 1e-3 (stability/equilibrium tolerance; default
// 0.02) the interpolated equilibrium, which drifts at 5.7e-3 R per unit time, is refused after the unperturbed map:
// exit status 2 and one line. About 55 s.
#include <deal.II/base/mpi.h>

#include <fluid_surface/scenes/run_program.h>

#include "spectrum_csv.h"

#include <cmath>
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
  /// Runs the oblate's m = 2 even with at most @p krylov vectors and @p restarts restarts and the further entries
  /// @p extra of subsection stability in @p directory; returns the exit status and the rows of spectrum.csv (split at
  /// commas).
  std::pair<int, std::vector<std::vector<std::string>>>
  spectrum(const std::string  &directory,
           const unsigned int  krylov,
           const unsigned int  restarts,
           std::string        &message,
           const std::string  &extra = "")
  {
    std::filesystem::remove_all(directory);
    const std::string file = directory + ".prm";
    std::ofstream(file)
      << "subsection model\n  set scene = stability\nend\n"
         "subsection geometry\n  set shape = equilibrium\n  set refinement = 2\n  set position degree = 2\nend\n"
         "subsection equilibrium\n  set area = 12.600857094577847\n  set reduced volume = 0.7549530890154922\n"
         "  set branch = oblate\n  set Be = 1\n  set angular momentum = 46.64242839801514\nend\n"
         "subsection flow\n  set Re = 1\n  set conserve momenta = true\nend\n"
         "subsection initial state\n  set equilibrium rotation = true\nend\n"
         "subsection time stepping\n  set time step = 0.02\n  set scheme = BDF2\nend\n"
         "subsection geometry iteration\n  set maximum iterations = 1\n  set tolerance = 0\n  set apply = always\nend\n"
         "subsection mesh redistribution\n  set tangential law = membrane\nend\n"
         "subsection stability\n  set wavenumbers = 2\n  set parities = even\n  set map time = 0.3\n"
         "  set maximum Krylov dimension = "
      << krylov << "\n  set maximum restarts = " << restarts << "\n"
      << extra
      << "end\n"
         "subsection output\n  set output directory = "
      << directory << "\n  set report wall time = false\nend\n";
    std::ostringstream screen, errors;
    const int          status = run_program({file}, screen, errors, MPI_COMM_WORLD);
    message                   = errors.str();
    const std::vector<std::vector<std::string>> rows = read_spectrum_csv(directory + "/spectrum.csv");
    return {status, rows};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::string                              message;
  const auto [status, rows] = spectrum("results_spectrum", 20, 5, message);
  std::cout << "exit status " << status << "\nheader: " << (rows.empty() ? std::string() : rows[0][0] + ", " +
                                                               rows[0][1] + ", " + rows[0][2] + ", " + rows[0][3])
            << std::endl;
  if (rows.size() > 1)
    {
      const double sigma = std::stod(rows[1][2]), frequency = std::stod(rows[1][3]);
      std::cout << std::fixed << std::setprecision(2) << "leading: m = " << rows[1][0] << " " << rows[1][1]
                << ", σ = " << sigma << ", frequency = " << frequency << ", converged: "
                << (std::stod(rows[1][6]) < 1e-3 ? "yes" : "no") << ", purity above 0.9: "
                << (std::stod(rows[1][7]) > 0.9 ? "yes" : "no") << "\nσ within 2 % of the seeded run's 2.567: "
                << (std::abs(sigma / 2.567 - 1) < 0.02 ? "yes" : "no") << std::endl;
    }

  const auto [restarted_status, restarted_rows] = spectrum("results_restarted", 4, 5, message);
  if (rows.size() > 1 && restarted_rows.size() > 1)
    std::cout << "at most 4 Krylov vectors, restarted: exit status " << restarted_status << ", converged: "
              << (std::stod(restarted_rows[1][6]) < 1e-3 ? "yes" : "no")
              << ", σ within 1e-3 of the 20 vectors' σ: "
              << (std::abs(std::stod(restarted_rows[1][2]) / std::stod(rows[1][2]) - 1) < 1e-3 ? "yes" : "no")
              << std::endl;

  const auto [short_status, short_rows] = spectrum("results_short", 3, 0, message, "  set residual tolerance = 0.1\n");
  const std::string prefix              = "fluid_surface: error: ";
  std::cout << "at most 3 Krylov vectors: exit status " << short_status << ", rows kept " << short_rows.size() - 1
            << "\n"
            << (message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message) << std::flush;

  const auto [drift_status, drift_rows] =
    spectrum("results_drift", 20, 5, message, "  set equilibrium tolerance = 1e-3\n");
  std::cout << "equilibrium tolerance 1e-3: exit status " << drift_status << ", spectrum.csv written: "
            << (drift_rows.empty() ? "no" : "yes") << "\n"
            << (message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message) << std::flush;
}
