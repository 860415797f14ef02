// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/io/run_stopped.h>
#include <fluid_surface/model/bordered_solver.h>

#include <cmath>

namespace FluidSurface
{
  BorderedSolver::BorderedSolver()
    : kept("Amesos_Mumps") // `direct solver = default` of scene full
    , fresh("Amesos_Mumps")
    , fresh_fallback("Amesos_Klu")
  {}

  void
  BorderedSolver::parse_parameters(dealii::ParameterHandler &prm)
  {
    kept.parse_parameters(prm);
    ReusedFactorizationSolver::Parameters fresh_parameters = kept.get_parameters();
    fresh_parameters.reuse_factorization                   = false;
    fresh_parameters.direct_solver                         = "Amesos_Mumps";
    fresh.set_parameters(fresh_parameters);
    fresh_parameters.direct_solver = "Amesos_Klu";
    fresh_fallback.set_parameters(fresh_parameters);
  }

  BorderedSystem::BlockVector
  BorderedSolver::initial_guess(const BorderedSystem &system,
                                const VectorType     &rhs,
                                const unsigned int    n_constraints) const
  {
    if (last_solution.n_blocks() == 2 && last_solution.block(1).size() == n_constraints)
      return last_solution;
    return system.make_vector(rhs);
  }

  BorderedSolver::Outcome
  BorderedSolver::solve(const BorderedSystem        &system,
                        const StepSystem            &step_system,
                        const double                 tau,
                        const std::vector<double>   &values,
                        const StepRequest::Solver    solver,
                        BorderedSystem::BlockVector &solution,
                        const bool                   same_step)
  {
    BorderedSystem::BlockVector rhs = system.make_vector(step_system.rhs());
    rhs.block(0)                    = step_system.rhs();
    BorderedSystem::set_multipliers(rhs, values);
    const bool fresh_solve = solver == StepRequest::Solver::fresh_factorization;
    if (fresh_solve && !fresh_refused)
      {
        const Outcome first = solve_with(fresh, system, step_system, tau, rhs, solution, same_step);
        if (first.failure == StepFailure::none)
          return first;
        fresh.release();
        fresh_refused = true;
      }
    return solve_with(fresh_solve ? fresh_fallback : kept, system, step_system, tau, rhs, solution, same_step);
  }

  BorderedSolver::Outcome
  BorderedSolver::solve_with(ReusedFactorizationSolver   &linear_solver,
                             const BorderedSystem        &system,
                             const StepSystem            &step_system,
                             const double                 tau,
                             const BorderedSystem::BlockVector &rhs,
                             BorderedSystem::BlockVector &solution,
                             const bool                   same_step)
  {
    Outcome outcome;
    try
      {
        linear_solver.matrix_changed(tau); // every step assembles its matrix on the new surface
        const dealii::Tensor<2, 3> identity = dealii::unit_symmetric_tensor<3>();
        if (&linear_solver == &kept && rotation_since_factorization != identity)
          kept.set_change_of_variables([this, &step_system](VectorType &v, const bool transpose) {
            step_system.rotate_vector_unknowns(
              transpose ? dealii::transpose(rotation_since_factorization) : rotation_since_factorization, v);
          });
        else if (&linear_solver == &kept)
          kept.set_change_of_variables(nullptr);
        if (!same_step)
          kept_columns.valid = false;
        BorderedFactorizationPreconditioner preconditioner(system, &linear_solver == &kept ? &kept_columns : nullptr);
        const ReusedFactorizationSolver::Result result =
          linear_solver.solve(step_system.matrix(), system, solution, rhs, preconditioner);
        preconditioner.enforce_constraints(solution, BorderedSystem::multipliers(rhs));
        if (result.factorized && &linear_solver == &kept)
          rotation_since_factorization = identity;
        outcome.iterations  = result.iterations;
        outcome.factorized  = result.factorized;
        last_solution       = solution;
        outcome.multipliers = BorderedSystem::multipliers(solution);
      }
    catch (const LinearSolverError &exc)
      {
        kept.request_factorization();
        outcome.failure = StepFailure::linear_solver;
        outcome.message = std::string("linear solver failed: ") + exc.what();
        outcome.details = exc.details();
        return outcome;
      }
    catch (const std::exception &exc)
      {
        kept.request_factorization();
        outcome.failure = StepFailure::linear_solver;
        outcome.message = "linear solver failed: " + one_line_message(exc, 200);
        outcome.details = exc.what();
        return outcome;
      }
    if (!std::isfinite(solution.block(0).l2_norm()))
      {
        outcome.failure = StepFailure::not_finite;
        outcome.message = "the solution is not finite";
        return outcome;
      }
    step_system.constraints().distribute(solution.block(0));
    return outcome;
  }
} // namespace FluidSurface
