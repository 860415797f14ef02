// SPDX-License-Identifier: LGPL-2.1-or-later
// fluid_surface: fluid deformable surfaces (surface Navier–Stokes + Helfrich bending) with deal.II.
#include <deal.II/base/mpi.h>

#include <fluid_surface/scenes/run_program.h>

#include <iostream>
#include <string>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, dealii::numbers::invalid_unsigned_int);
  return FluidSurface::run_program(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr, MPI_COMM_WORLD);
}
