// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_bordered_solver_h
#define fluid_surface_model_bordered_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>

#include <fluid_surface/linear_algebra/bordered_system.h>
#include <fluid_surface/linear_algebra/reused_factorization_solver.h>
#include <fluid_surface/model/step_failure.h>
#include <fluid_surface/model/step_request.h>
#include <fluid_surface/model/step_system.h>

#include <string>
#include <vector>

namespace FluidSurface
{
  /**
   * The solve of the step system bordered by its global constraints c_k·x = g_k with multipliers μ_k
   * (BorderedSystem: the volume row and the rigid-motion rows), by GMRES preconditioned by an LU factorization
   * kept across steps (ReusedFactorizationSolver, `subsection linear solver`), or by a fresh factorization
   * for the safety valve's solves (MUMPS, KLU where MUMPS refuses the matrix); then the constraints are made to hold to round-off.
   */
  class BorderedSolver
  {
  public:
    /// The outcome of one solve.
    struct Outcome
    {
      StepFailure         failure = StepFailure::none; ///< linear_solver or not_finite if it failed
      std::string         message;                     ///< why it failed, one line
      std::string         details;                     ///< the linear solver's own report (for error.log)
      unsigned int        iterations = 0;              ///< GMRES iterations
      bool                factorized = false;          ///< whether the solve computed a new factorization
      std::vector<double> multipliers;                 ///< μ_k
    };

    BorderedSolver();

    /// Reads `linear solver` (shared with scene fixed surface).
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// The start of the solves of a step: the last step's solution if it has the same constraints, else 0.
    BorderedSystem::BlockVector
    initial_guess(const BorderedSystem &system, const VectorType &rhs, const unsigned int n_constraints) const;
    /**
     * Solves the @p system of @p step_system, assembled with the step size @p tau, with the constraint values
     * @p values by the solver @p solver, from and into @p solution; distributes the hanging-node constraints.
     * @p same_step: a solve of the geometry iteration after the step's first one, which takes over Z = A₀⁻¹C of
     * the kept factors from the step's earlier solves (BorderedFactorizationPreconditioner::KeptColumns: the
     * columns of one step differ by the move of its surface).
     */
    Outcome
    solve(const BorderedSystem        &system,
          const StepSystem            &step_system,
          const double                 tau,
          const std::vector<double>   &values,
          const StepRequest::Solver    solver,
          BorderedSystem::BlockVector &solution,
          const bool                   same_step = false);

    /**
     * The accepted step turned the mesh and the vector unknowns by @p rotation (the co-rotating step's frame
     * over τ): the next steps' matrices are close to those of the kept factors turned by the rotations since
     * the factorization, and GMRES is preconditioned by the turned factors (doc/scheme.md, "The co-rotating
     * step").
     */
    void
    turn_kept_factors(const dealii::Tensor<2, 3> &rotation)
    {
      rotation_since_factorization = rotation * rotation_since_factorization;
    }
    /// The next solve factorizes its matrix (the surface jumped: a restore, a re-parametrization).
    void
    request_factorization()
    {
      kept.request_factorization();
    }
    /// The next step starts its GMRES from zero instead of the last solution.
    void
    forget_last_solution()
    {
      last_solution.reinit(0);
    }
    /// Frees the kept LU factorization (MUMPS) while the rest of the program is still alive.
    void
    release_factorization()
    {
      kept.release();
    }
    /// Frees the factorizations of the StepRequest::Solver::fresh_factorization solves; the next valve tries
    /// MUMPS again.
    void
    release_fresh_factorization()
    {
      fresh.release();
      fresh_fallback.release();
      fresh_refused = false;
    }
    /// Number of LU factorizations of the kept solver so far (kept in checkpoints).
    unsigned int
    n_factorizations() const
    {
      return kept.n_factorizations();
    }
    /// Continues the count of a checkpoint.
    void
    set_n_factorizations(const unsigned int n)
    {
      kept.set_n_factorizations(n);
    }
    /// Sections "factorization" and "linear solve" go to @p timer.
    void
    set_timer(dealii::TimerOutput &timer)
    {
      kept.set_timer(&timer);
    }

  private:
    /// solve() with @p linear_solver and the assembled right-hand side @p rhs.
    Outcome
    solve_with(ReusedFactorizationSolver         &linear_solver,
               const BorderedSystem              &system,
               const StepSystem                  &step_system,
               const double                       tau,
               const BorderedSystem::BlockVector &rhs,
               BorderedSystem::BlockVector       &solution,
               const bool                         same_step);

    /// The step's LU factorization, kept across steps (`subsection linear solver`; MUMPS by default).
    ReusedFactorizationSolver kept;
    /// The fresh solves (MUMPS): KLU stalled for more than 10 minutes on the relaxation matrix of the map's
    /// (0.65, 40) prolate start at mesh quality 0.10, which MUMPS factorizes in seconds.
    ReusedFactorizationSolver fresh;
    /// KLU, for the fresh solves MUMPS refused: the mesh-law matrix of a sheared refinement-3 mesh (error −22,
    /// tests/mesh_reparametrization).
    ReusedFactorizationSolver fresh_fallback;
    /// Whether MUMPS refused a fresh solve since the last release_fresh_factorization().
    bool fresh_refused = false;
    /// Z = A₀⁻¹C of the step's first solve with the kept factors.
    BorderedFactorizationPreconditioner::KeptColumns kept_columns;
    /// The rotation of the vector unknowns since the kept factorization (turn_kept_factors()).
    dealii::Tensor<2, 3> rotation_since_factorization = dealii::unit_symmetric_tensor<3>();
    /// The state and multipliers of the last solve: the initial guess of the next step's GMRES.
    BorderedSystem::BlockVector last_solution;
  };
} // namespace FluidSurface

#endif
