// SPDX-License-Identifier: LGPL-2.1-or-later
// A factorization that fails (a singular matrix: all entries zero) is reported as one LinearSolverError whose
// message names the solver and the stage, on one line; what Amesos prints on std::cerr and the Trilinos
// exception go into its details (for error.log), nothing onto the screen. Amesos_Klu, and Amesos_Mumps with
// double- and single-precision factors (SinglePrecisionLU reports MUMPS' INFOG(1)).
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fluid_surface/linear_algebra/factorization_preconditioner.h>
#include <fluid_surface/linear_algebra/reused_factorization_solver.h>

#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace FluidSurface;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       n = 6;
  const dealii::IndexSet                   owned = dealii::complete_index_set(n);
  dealii::DynamicSparsityPattern           pattern(n, n);
  for (unsigned int i = 0; i < n; ++i)
    pattern.add(i, i);
  dealii::TrilinosWrappers::SparseMatrix matrix;
  matrix.reinit(owned, owned, pattern, MPI_COMM_WORLD);
  matrix.compress(dealii::VectorOperation::insert);
  dealii::TrilinosWrappers::MPI::Vector x(owned, MPI_COMM_WORLD), b(owned, MPI_COMM_WORLD);
  b = 1.0;

  for (const auto &[package, precision] : std::vector<std::pair<std::string, std::string>>{
         {"Amesos_Klu", "double"}, {"Amesos_Mumps", "double"}, {"Amesos_Mumps", "single"}})
    {
      ReusedFactorizationSolver::Parameters parameters;
      parameters.factor_precision = precision;
      ReusedFactorizationSolver   solver(package, parameters);
      FactorizationPreconditioner preconditioner;
      std::ostringstream          screen;
      std::streambuf             *cerr_buffer = std::cerr.rdbuf(screen.rdbuf());
      try
        {
          solver.solve(matrix, matrix, x, b, preconditioner);
          std::cerr.rdbuf(cerr_buffer);
          std::cout << package << " (" << precision << "): no failure" << std::endl;
        }
      catch (const LinearSolverError &error)
        {
          std::cerr.rdbuf(cerr_buffer);
          const std::string message = error.what();
          std::cout << package << " (" << precision << "): " << message << '\n'
                    << "  one line: " << (message.find('\n') == std::string::npos ? "yes" : "no") << '\n'
                    << "  details name the solver's error: "
                    << (error.details().find("Trilinos") != std::string::npos ||
                            error.details().find("INFOG(1)") != std::string::npos ?
                          "yes" :
                          "no")
                    << '\n'
                    << "  printed on std::cerr meanwhile: " << (screen.str().empty() ? "nothing" : screen.str())
                    << std::endl;
        }
    }
}
