// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_linear_algebra_reused_factorization_solver_h
#define fluid_surface_linear_algebra_reused_factorization_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fluid_surface/linear_algebra/amesos_factorization.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace FluidSurface
{
  /**
   * A factorization or solve of ReusedFactorizationSolver that failed (a singular or non-finite matrix,
   * an Amesos/MUMPS error). what() is one line for the user ("the Amesos_Mumps factorization failed: …");
   * details() is the solver's own report (the Trilinos exception and what Amesos printed), for the
   * output directory's error.log, not for the screen.
   */
  class LinearSolverError : public std::runtime_error
  {
  public:
    LinearSolverError(const std::string &summary, const std::string &details)
      : std::runtime_error(summary)
      , details_text(details)
    {}
    const std::string &
    details() const
    {
      return details_text;
    }

  private:
    std::string details_text;
  };

  /**
   * A sparse LU factorization (Amesos) kept across time steps. A solve whose matrix was factorized is
   * direct; on the nearby matrices of later steps the kept factors are the right preconditioner of GMRES,
   * which stops at the true residual ‖b − Kx‖ ≤ `tolerance` ‖b‖. The matrix is factorized anew when GMRES
   * needs more than `max reuse iterations` (the solve is then repeated directly), after a failed solve, and
   * when the owner asks for it (a rejected step, a changed time step size); the symbolic analysis of the
   * factorization is kept while the matrix keeps its sparsity pattern (AmesosFactorization). Scene full
   * solves its bordered step system with it, scene fixed surface its saddle-point system
   * (`linear solver = direct`).
   */
  class ReusedFactorizationSolver
  {
  public:
    /// The entries of `subsection linear solver`; the declared defaults are these initializers.
    struct Parameters
    {
      bool         reuse_factorization  = true;
      unsigned int max_reuse_iterations = 10;        ///< GMRES iterations above which the factors are replaced
      double       tolerance            = 1e-10;     ///< relative residual ‖b − Kx‖/‖b‖ of a GMRES solve
      double       step_change          = 0;         ///< |τ/τ_f − 1| above which the factors are replaced; 0: never
      std::string  direct_solver        = "default"; ///< Amesos package, or the scene's own choice
      double       low_rank_tolerance   = 0;         ///< MUMPS' block-low-rank threshold ε_BLR; 0: full rank
      std::string  factor_precision     = "single";  ///< "single": MUMPS' factors in single precision

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// The work of one solve.
    struct Result
    {
      unsigned int iterations = 0;     ///< GMRES iterations, those of an abandoned attempt included
      bool         factorized = false; ///< the solve factorized its matrix
    };

    /// A solver with @p parameters whose factorizations use @p scene_direct_solver for `direct solver = default`.
    ReusedFactorizationSolver(const std::string &scene_direct_solver, const Parameters &parameters);
    /// The same with the default parameters.
    explicit ReusedFactorizationSolver(const std::string &scene_direct_solver);

    static void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      Parameters::declare_parameters(prm);
    }
    void
    parse_parameters(dealii::ParameterHandler &prm);
    void
    set_parameters(const Parameters &new_parameters);
    const Parameters &
    get_parameters() const
    {
      return parameters;
    }
    /// The Amesos package of the factorizations (`direct solver`, or the scene's choice for `default`).
    std::string
    direct_solver() const;

    /// Sections "factorization" and "linear solve" of every solve go to @p timer (nullptr: none).
    void
    set_timer(dealii::TimerOutput *timer)
    {
      step_timer = timer;
    }

    /// The matrix was assembled anew since the last solve: the kept factors are a preconditioner now.
    void
    matrix_changed()
    {
      factors_of_current_matrix = false;
    }
    /**
     * The same for a matrix of the step size @p tau (that of its mass term (1/τ)(u, v)): if it differs from the
     * step size of the kept factors by more than `factorize on step change`, the next solve factorizes.
     */
    void
    matrix_changed(const double tau);
    /**
     * The matrices of the next solves are close to T A₀ Tᵀ, A₀ the factorized one, with the change of variables
     * @p change (a rotation of the vector unknowns since the factorization): GMRES is then preconditioned by
     * T A₀⁻¹ Tᵀ. Dropped when a matrix is factorized; an empty function: none.
     */
    void
    set_change_of_variables(AmesosFactorization::ChangeOfVariables change)
    {
      change_of_variables = std::move(change);
    }
    /// The next solve factorizes its matrix, whatever GMRES would do.
    void
    request_factorization()
    {
      factorization_requested = true;
    }
    /// Frees the factors and their analysis (MUMPS keeps its own copy of them); the next solve factorizes.
    void
    release();

    /**
     * Solves @p system x = @p b. @p matrix is what is factorized: @p system itself, or its block when
     * @p system borders it. @p preconditioner is built from the factors by its
     * initialize(AmesosFactorization &), and its vmult() is the exact inverse of @p system when the factors
     * are of @p matrix. @p x is the
     * initial guess of GMRES. A failed factorization or solve throws LinearSolverError (the next solve then
     * factorizes again); what Amesos prints on std::cerr meanwhile goes into its details(), not on the screen.
     *
     * Instantiated for (TrilinosWrappers::SparseMatrix, MPI::Vector, FactorizationPreconditioner) and
     * (BorderedSystem, MPI::BlockVector, BorderedFactorizationPreconditioner).
     */
    template <typename SystemType, typename VectorType, typename PreconditionerType>
    Result
    solve(const dealii::TrilinosWrappers::SparseMatrix &matrix,
          const SystemType                             &system,
          VectorType                                   &x,
          const VectorType                             &b,
          PreconditionerType                           &preconditioner);

    /// The number of factorizations so far.
    unsigned int
    n_factorizations() const
    {
      return factorization_count;
    }
    /// Continues the count of a checkpoint's run.
    void
    set_n_factorizations(const unsigned int n)
    {
      factorization_count = n;
    }

  private:
    void
    factorize(const dealii::TrilinosWrappers::SparseMatrix &matrix);

    /// GMRES preconditioned by the kept factors; false if it needs more than `max reuse iterations`.
    template <typename SystemType, typename VectorType, typename PreconditionerType>
    bool
    solve_with_kept_factors(const SystemType   &system,
                            VectorType         &x,
                            const VectorType   &b,
                            PreconditionerType &preconditioner,
                            unsigned int       &iterations);

    Parameters                           parameters;
    std::string                          scene_direct_solver;
    std::unique_ptr<AmesosFactorization> factorization;
    /// The change of variables T since the factorization (set_change_of_variables()); empty: none.
    AmesosFactorization::ChangeOfVariables change_of_variables;
    bool                 factors_of_current_matrix = false; ///< the factors are of the matrix of the next solve
    bool                 factorization_requested   = true;
    unsigned int         factorization_count       = 0;
    double               step_size                 = 0; ///< τ of the matrix of the next solve (0: not given)
    double               factors_step_size         = 0; ///< τ of the matrix of the kept factors (0: not given)
    dealii::TimerOutput *step_timer                = nullptr;
  };
} // namespace FluidSurface

#endif
