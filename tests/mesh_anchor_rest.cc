// SPDX-License-Identifier: LGPL-2.1-or-later
// mesh redistribution/anchor time: the rotating oblate equilibrium of prm/seeded_mode_oblate.prm at refinement 2,
// unperturbed, with BGN's conformal rows (tangential law = conformal), to t = 0.6. The conformal rows let the
// nodes creep and feed energy into the rotating steady state: F rises. Anchored at t = 0 (the membrane energy
// relative to the start, with full weight) the discrete state stays at rest. Printed: whether the relative
// change of F over t ∈ [0.3, 0.6] is below 1e-5 with the anchor and above 1e-4 without (measured: 3.3e-6 and
// 9.5e-4; the creeping run shrinks τ to 5e-3 and takes about a minute).
#include <deal.II/base/mpi.h>

#include <fluid_surface/scenes/run_program.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

using namespace FluidSurface;

namespace
{
  /// The relative change of F between the first step at t ≥ 0.3 and the last, for `anchor time` @p anchor.
  double
  energy_change(const std::string &name, const std::string &anchor)
  {
    const std::string directory = "results_" + name;
    std::filesystem::remove_all(directory);
    std::ofstream(name + ".prm")
      << "subsection model\n  set scene = full\nend\n"
         "subsection geometry\n  set shape = equilibrium\n  set refinement = 2\nend\n"
         "subsection equilibrium\n  set area = 12.600857094577847\n  set reduced volume = 0.7549530890154922\n"
         "  set branch = oblate\n  set angular momentum = 46.64242839801514\n"
         "  set maximal collocation points = 64\nend\n"
         "subsection flow\n  set conserve momenta = true\nend\n"
         "subsection initial state\n  set equilibrium rotation = true\nend\n"
         "subsection time stepping\n  set end time = 0.6\n  set time step = 0.01\n  set maximum time step = 0.1\nend\n"
         "subsection mesh redistribution\n  set tangential law = conformal\n  set pull onset quality = 0.2\n"
         "  set full pull quality = 0.2\n  set anchor time = "
      << anchor
      << "\nend\n"
         "subsection output\n  set output directory = "
      << directory << "\n  set write vtu = false\n  set report wall time = false\nend\n";
    std::ostringstream screen, errors;
    const int          status = run_program({name + ".prm"}, screen, errors, MPI_COMM_WORLD);
    std::ifstream      file(directory + "/statistics");
    int                energy_column = -1, column = 0;
    double             start = 0, end = 0;
    for (std::string line; std::getline(file, line);)
      if (line.rfind("# ", 0) == 0)
        {
          if (line.find(": total energy") != std::string::npos)
            energy_column = column;
          ++column;
        }
      else if (!line.empty())
        {
          std::istringstream values(line);
          double             value = 0, time = 0, energy = 0;
          for (int c = 0; values >> value; ++c)
            {
              if (c == 1)
                time = value;
              if (c == energy_column)
                energy = value;
            }
          if (time >= 0.3 && start == 0)
            start = energy;
          end = energy;
        }
    std::cout << name << ": exit status " << status << std::endl;
    return std::abs(end - start) / start;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double anchored = energy_change("anchored", "0");
  const double creeping = energy_change("not_anchored", "-1");
  std::cout << "F change over [0.3, 0.6] with the anchor below 1e-5: " << (anchored < 1e-5 ? "yes" : "no") << std::endl;
  std::cout << "F change over [0.3, 0.6] without it above 1e-4: " << (creeping > 1e-4 ? "yes" : "no") << std::endl;
}
