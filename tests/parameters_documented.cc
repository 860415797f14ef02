// SPDX-License-Identifier: LGPL-2.1-or-later
// doc/parameters.prm (what README points users to) is the output of `fluid_surface --print-parameters`:
// a parameter added, removed or re-documented without regenerating it fails here. Regenerate with
//   ./build/fluid_surface --print-parameters > doc/parameters.prm
#include <deal.II/base/mpi.h>

#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/scenes/simulation.h>

#include <fstream>
#include <iostream>
#include <sstream>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  dealii::ParameterHandler                 prm;
  FluidSurface::Simulation::declare_parameters(prm);
  std::ostringstream printed;
  FluidSurface::print_documented_parameters(prm, printed);
  std::ifstream      file(std::string(FLUID_SURFACE_SOURCE_DIR) + "/doc/parameters.prm");
  std::ostringstream committed;
  committed << file.rdbuf();
  std::istringstream a(printed.str()), b(committed.str());
  unsigned int       line = 1;
  for (std::string x, y; std::getline(a, x);)
    {
      if (!std::getline(b, y) || x != y)
        {
          std::cout << "doc/parameters.prm differs from --print-parameters at line " << line << ":\n  printed:   " << x
                    << "\n  committed: " << y << std::endl;
          return 0;
        }
      ++line;
    }
  std::string rest;
  std::cout << "doc/parameters.prm is the output of --print-parameters: "
            << (std::getline(b, rest) ? "no (the file has extra lines)" : "yes") << std::endl;
}
