// SPDX-License-Identifier: LGPL-2.1-or-later
// t_sym_1e-4 of the summary (the time e(λ) first exceeds 1e-4) is interpolated in ln e(λ) between the two steps
// around the crossing, not the time of the first step above: the seed's prolate at refinement 2, seeded with 1e-3,
// steps of τ = 0.1 (BDF2, co-rotating). The test reads the steps around the crossing from `statistics` and compares
// the summary's value with the interpolation ln-linear in e(λ).
#include <deal.II/base/mpi.h>

#include <fluid_surface/scenes/run_program.h>

#include "statistics_columns.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace FluidSurface;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        directory = "run_crossing";
  std::filesystem::remove_all(directory);
  std::ofstream("crossing.prm")
    << "subsection model\n  set scene = full\nend\n"
       "subsection geometry\n  set shape = ellipsoid\n  set semi-axes = 0.61, 0.61, 2.02\n  set refinement = 2\nend\n"
       "subsection flow\n  set conserve momenta = true\nend\n"
       "subsection initial state\n  set angular velocity = 4\n  set shape perturbation = 1e-3\nend\n"
       "subsection time stepping\n  set end time = 1\n  set time step = 0.1\n  set adaptive = false\n"
       "  set scheme = BDF2\n  set frame = Tisserand\nend\n"
       "subsection geometry iteration\n  set maximum iterations = 1\n  set tolerance = 0\n  set apply = always\nend\n"
       "subsection output\n  set output directory = "
    << directory << "\n  set write vtu = false\n  set report wall time = false\nend\n";
  std::ostringstream screen, errors;
  if (run_program({"crossing.prm"}, screen, errors, MPI_COMM_WORLD) != 0)
    std::printf("exit: %s\n", errors.str().c_str());
  const auto columns = read_statistics_columns(directory + "/statistics");
  const auto &t = columns.at("time"), &e = columns.at("symmetry deviation");
  std::ifstream summary(directory + "/summary");
  double        t_sym = std::nan("");
  for (std::string line; std::getline(summary, line);)
    if (line.rfind("t_sym_1e-4: ", 0) == 0)
      t_sym = std::stod(line.substr(12));
  for (unsigned int i = 1; i < t.size(); ++i)
    if (e[i - 1] <= 1e-4 && e[i] > 1e-4)
      {
        const double interpolated = t[i - 1] + (t[i] - t[i - 1]) * std::log(1e-4 / e[i - 1]) / std::log(e[i] / e[i - 1]);
        std::printf("e(λ) = %.3e at t = %.1f, %.3e at t = %.1f\n", e[i - 1], t[i - 1], e[i], t[i]);
        std::printf("t_sym_1e-4 = %.4f, strictly between the steps: %s, the ln-linear interpolation to 1e-6 (the printed digits): %s\n",
                    t_sym,
                    t_sym > t[i - 1] && t_sym < t[i] ? "yes" : "no",
                    std::abs(t_sym - interpolated) < 1e-6 ? "yes" : "no");
        return 0;
      }
  std::printf("e(λ) did not cross 1e-4 (t_sym_1e-4 = %g)\n", t_sym);
}
