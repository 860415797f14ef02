// SPDX-License-Identifier: LGPL-2.1-or-later
// Phase-2 accuracy of the mesh law (issue 22): the seeded prolate of prm/prolate.prm at refinement 3, relaxed to
// t = 3.5. Its ⟨ω⟩[2.5, 3.5] and its smallest L² distance to the rotating equilibrium at L₀ are errors of the
// discrete shape. The membrane law relative to the initial surface (the default, `tangential law = membrane`)
// resolves the relaxed prolate worse than BGN's conformal distribution (+0.46 % against −0.16 % in ⟨ω⟩[5, 10]);
// the experiments' law (conformal rows, the membrane energy only from the first step with mesh quality below 0.2)
// must be at least 1.2 times more accurate than the membrane law in both figures. The check fails if the pull acts
// in phase 2 (the error then goes back to the membrane law's, doc/scheme.md) or if the two laws become the same.
// Each run prints its lowest mesh quality: the experiments' law stays above 0.2, so its pull never acts here, and
// since the body spins about its axis of symmetry (no rigid motion to carry) its step is then law `bgn`'s to
// round-off (⟨ω⟩ equal to 2e-8 relative): comparing with `bgn`, as this test did before, could not fail.
#include <deal.II/base/mpi.h>

#include <fluid_surface/scenes/run_program.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>

using namespace FluidSurface;

namespace
{
  struct PhaseTwoErrors
  {
    double omega    = 0; ///< |⟨ω⟩ − ω_eq| / ω_eq
    double distance = 0; ///< min E(L²)
  };

  /// The smallest value of the column @p name of the statistics file @p path (`# N: name` header lines).
  double
  column_minimum(const std::string &path, const std::string &name)
  {
    std::ifstream file(path);
    int           column  = -1;
    double        minimum = std::numeric_limits<double>::infinity();
    for (std::string line; std::getline(file, line);)
      if (line.rfind("# ", 0) == 0)
        {
          if (const auto colon = line.find(": "); colon != std::string::npos && line.substr(colon + 2) == name)
            column = std::stoi(line.substr(2, colon - 2)) - 1;
        }
      else
        {
          std::istringstream values(line);
          double             value;
          for (int c = 0; values >> value; ++c)
            if (c == column)
              minimum = std::min(minimum, value);
        }
    return minimum;
  }

  /// Runs the relaxing prolate with the entries @p law of `subsection mesh redistribution`; its errors.
  PhaseTwoErrors
  run(const std::string &name, const std::string &law)
  {
    const std::string directory = "results_" + name;
    std::filesystem::remove_all(directory);
    std::ofstream(name + ".prm") << "subsection model\n  set scene = full\nend\n"
                                    "subsection geometry\n  set shape = ellipsoid\n"
                                    "  set semi-axes = 0.61, 0.61, 2.02\n  set refinement = 3\nend\n"
                                    "subsection flow\n  set conserve momenta = true\nend\n"
                                    "subsection initial state\n  set angular velocity = 4\n"
                                    "  set shape perturbation = 3e-5\n  set random seed = 1\nend\n"
                                    "subsection time stepping\n  set end time = 3.5\n  set time step = 0.01\n"
                                    "  set maximum time step = 0.1\nend\n"
                                    "subsection geometry iteration\n  set maximum iterations = 1\n"
                                    "  set tolerance = 0\n  set apply = after rejection\nend\n"
                                    "subsection diagnostics\n  set angular velocity window = 2.5, 3.5\n"
                                    "  set reference equilibrium = prolate\nend\n"
                                    "subsection mesh redistribution\n" +
                                      law +
                                      "end\n"
                                      "subsection output\n  set output directory = " +
                                      directory +
                                      "\n  set write vtu = false\n  set report wall time = false\nend\n";
    std::ostringstream screen, errors;
    const int          status = run_program({name + ".prm"}, screen, errors, MPI_COMM_WORLD);
    std::map<std::string, std::string> summary;
    std::ifstream                      file(directory + "/summary");
    for (std::string line; std::getline(file, line);)
      if (const auto colon = line.find(": "); colon != std::string::npos)
        summary[line.substr(0, colon)] = line.substr(colon + 2);
    const double omega     = std::stod(summary["mean angular velocity"]);
    const double reference = std::stod(summary["reference equilibrium angular velocity"]);
    const PhaseTwoErrors e{std::abs(omega - reference) / reference,
                           std::stod(summary["min L2 distance to equilibrium"])};
    std::cout << name << ": exit status " << status << ", " << summary["status"] << std::setprecision(1)
              << std::scientific << ", <omega> error " << e.omega << ", min E(L2) " << e.distance
              << std::defaultfloat << std::setprecision(3) << ", min mesh quality "
              << column_minimum(directory + "/statistics", "mesh quality") << std::setprecision(6) << std::endl;
    return e;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double factor = 1.2;
  const PhaseTwoErrors experiments =
    run("conformal_with_pull",
        "  set tangential law = conformal\n  set pull onset quality = 0.2\n  set full pull quality = 0.2\n");
  const PhaseTwoErrors membrane = run("membrane", "  set tangential law = membrane\n");
  const bool better = experiments.omega * factor <= membrane.omega && experiments.distance * factor <= membrane.distance;
  std::cout << "conformal_with_pull at least " << factor << " x more accurate than membrane in both: "
            << (better ? "yes" : "no") << std::endl;
}
