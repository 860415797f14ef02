// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_scenes_run_program_h
#define fluid_surface_scenes_run_program_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <fluid_surface/io/parameter_file.h>

#include <ostream>
#include <string>
#include <vector>

namespace FluidSurface
{
  /**
   * The program fluid_surface with the command-line arguments @p args (without
   * the program name): a run of a parameter file, --validate, --equilibrium,
   * --print-parameters or --help. The run's screen output and the usage text go
   * to @p out, error messages to @p err (both on rank 0 of @p communicator).
   * Returns the exit status: 0 success (or stopped after `checkpoint/steps per
   * run`), 1 a computation failed, 2 bad input, 128 + signal number when
   * stopped by SIGINT/SIGTERM (see RunStopped). main() is a thin wrapper around it.
   */
  int
  run_program(const std::vector<std::string> &args,
              std::ostream                   &out,
              std::ostream                   &err,
              const MPI_Comm                  communicator);

  /**
   * The run of the experiment that @p prm describes (declared by
   * Simulation::declare_parameters() and set): parses it, runs it and turns
   * its exceptions into the exit status and message exactly as run_program()
   * does. @p file is the parameter file @p prm was read from (its name for
   * messages, its entries for the scene rule); by default none, for tests that
   * set parameters in code.
   */
  int
  run_simulation(dealii::ParameterHandler &prm,
                 std::ostream             &out,
                 std::ostream             &err,
                 const MPI_Comm            communicator,
                 const ParameterFile      &file = ParameterFile());
} // namespace FluidSurface

#endif
