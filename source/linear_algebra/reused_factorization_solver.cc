// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/patterns.h>
#include <deal.II/lac/solver_gmres.h>

#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/io/run_stopped.h>
#include <fluid_surface/linear_algebra/bordered_system.h>
#include <fluid_surface/linear_algebra/factorization_preconditioner.h>
#include <fluid_surface/linear_algebra/reused_factorization_solver.h>

#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>

namespace FluidSurface
{
  using namespace dealii;

  void
  ReusedFactorizationSolver::Parameters::declare_parameters(ParameterHandler &prm)
  {
    const Parameters defaults;
    prm.enter_subsection("linear solver");
    prm.declare_entry("reuse factorization",
                      Patterns::Tools::to_string(defaults.reuse_factorization),
                      Patterns::Bool(),
                      "Keep the last LU factorization and use it as the right preconditioner of GMRES on the "
                      "matrices of the following steps (scene full: every step; scene fixed surface with "
                      "linear solver = direct: with convection) until GMRES needs more than `max reuse "
                      "iterations`; false: factorize every new matrix.");
    prm.declare_entry("max reuse iterations",
                      Patterns::Tools::to_string(defaults.max_reuse_iterations),
                      Patterns::Integer(1, 1000),
                      "GMRES iterations, 1 to 1000, above which a solve with the kept factorization is abandoned: the "
                      "step's matrix is factorized and the system solved directly. A rejected step or a "
                      "failed solve also makes the next solve factorize.");
    prm.declare_entry("tolerance",
                      Patterns::Tools::to_string(defaults.tolerance),
                      RealRange::closed(1e-14, 1e-2),
                      "Relative residual ‖b − Kx‖/‖b‖ (true residual), 1e-14 ≤ tolerance ≤ 1e-2, at which GMRES stops "
                      "(below 1e-14 rounding prevents convergence); also the tolerance of the block-preconditioned solver of scene fixed surface.");
    prm.declare_entry("factorize on step change",
                      Patterns::Tools::to_string(defaults.step_change),
                      RealRange::at_least(0),
                      "Relative change |τ/τ_f − 1| ≥ 0 of the step size τ against the step size τ_f of the kept "
                      "factorization above which the next solve of scene full factorizes its matrix, whatever GMRES "
                      "would do: the mass term (1/τ)(u, v) dominates the matrix, and the old factors of another τ "
                      "cost GMRES iterations for as long as the new τ lasts. 0: the step size does not count.");
    prm.declare_entry("direct solver",
                      defaults.direct_solver,
                      Patterns::Selection("default|Amesos_Klu|Amesos_Mumps"),
                      "Amesos package of the LU factorizations. default: Amesos_Mumps in scene full, "
                      "Amesos_Klu in scene fixed surface.");
    prm.declare_entry("low rank tolerance",
                      Patterns::Tools::to_string(defaults.low_rank_tolerance),
                      RealRange::closed(0, 1e-2),
                      "Dropping threshold ε_BLR, 0 ≤ ε_BLR ≤ 1e-2, of MUMPS' block-low-rank factorization (with "
                      "Amesos_Mumps and `factor precision = double`; the single-precision factors are full "
                      "rank): off-diagonal blocks of the fronts are compressed to rank-revealing products "
                      "accurate to ε_BLR, in the factorization and in the substitutions; the factors are then those "
                      "of a matrix within about ε_BLR of the step's and precondition GMRES, which reaches the "
                      "`tolerance` as before. 0: full-rank factors.");
    prm.declare_entry("factor precision",
                      defaults.factor_precision,
                      Patterns::Selection("double|single"),
                      "Floating-point precision of the LU factors of Amesos_Mumps (Amesos_Klu factorizes in "
                      "double). single: MUMPS' factorization of the matrix rounded to single precision, always "
                      "the preconditioner of flexible GMRES, which works in double precision and reaches "
                      "`tolerance` also on the step whose matrix was factorized; half the memory and memory "
                      "traffic of the factors (doc/scheme.md, \"Single-precision factors\"). double: the factors "
                      "in double precision; a solve with the factors of the step's own matrix is then direct.");
    prm.leave_subsection();
  }

  void
  ReusedFactorizationSolver::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("linear solver");
    reuse_factorization  = prm.get_bool("reuse factorization");
    max_reuse_iterations = prm.get_integer("max reuse iterations");
    tolerance            = prm.get_double("tolerance");
    step_change          = prm.get_double("factorize on step change");
    direct_solver        = prm.get("direct solver");
    low_rank_tolerance   = prm.get_double("low rank tolerance");
    factor_precision     = prm.get("factor precision");
    prm.leave_subsection();
  }

  ReusedFactorizationSolver::ReusedFactorizationSolver(const std::string &scene_direct_solver,
                                                       const Parameters  &parameters)
    : parameters(parameters)
    , scene_direct_solver(scene_direct_solver)
  {}

  ReusedFactorizationSolver::ReusedFactorizationSolver(const std::string &scene_direct_solver)
    : ReusedFactorizationSolver(scene_direct_solver, Parameters())
  {}

  void
  ReusedFactorizationSolver::parse_parameters(ParameterHandler &prm)
  {
    Parameters new_parameters;
    new_parameters.parse_parameters(prm);
    set_parameters(new_parameters);
  }

  void
  ReusedFactorizationSolver::set_parameters(const Parameters &new_parameters)
  {
    parameters = new_parameters;
    release();
  }

  std::string
  ReusedFactorizationSolver::direct_solver() const
  {
    return parameters.direct_solver == "default" ? scene_direct_solver : parameters.direct_solver;
  }

  void
  ReusedFactorizationSolver::matrix_changed(const double tau)
  {
    matrix_changed();
    step_size = tau;
    if (parameters.step_change > 0 && factors_step_size > 0 &&
        std::abs(tau / factors_step_size - 1) > parameters.step_change)
      factorization_requested = true;
  }

  void
  ReusedFactorizationSolver::release()
  {
    factorization.reset();
    factorization_requested = true;
  }

  void
  ReusedFactorizationSolver::factorize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    std::optional<TimerOutput::Scope> section;
    if (step_timer)
      section.emplace(*step_timer, "factorization");
    if (!factorization)
      {
        AmesosFactorization::Options options;
        options.package            = direct_solver();
        options.low_rank_tolerance = parameters.low_rank_tolerance;
        options.single_precision   = parameters.factor_precision == "single" && options.package == "Amesos_Mumps";
        factorization   = std::make_unique<AmesosFactorization>(options);
      }
    factorization->factorize(matrix, step_timer);
    change_of_variables       = nullptr;
    factors_of_current_matrix = true;
    factors_step_size         = step_size;
    factorization_requested   = false;
    ++factorization_count;
  }

  template <typename SystemType, typename VectorType, typename PreconditionerType>
  bool
  ReusedFactorizationSolver::solve_with_kept_factors(const SystemType   &system,
                                                     VectorType         &x,
                                                     const VectorType   &b,
                                                     PreconditionerType &preconditioner,
                                                     unsigned int       &iterations)
  {
    std::optional<TimerOutput::Scope> section;
    if (step_timer)
      section.emplace(*step_timer, "linear solve");
    preconditioner.initialize(*factorization, change_of_variables ? &change_of_variables : nullptr);
    // Right preconditioning: GMRES measures the true residual ‖b − Kx‖. A basis of max_reuse_iterations
    // vectors: the solve is abandoned before GMRES would restart.
    SolverControl control(parameters.max_reuse_iterations, parameters.tolerance * b.l2_norm());
    try
      {
        // Single-precision factors round their input: the preconditioner is not linear to double precision,
        // and GMRES, which applies it once more to the combination of its basis, would miss the residual it
        // reports by about that rounding. Flexible GMRES keeps the preconditioned vectors instead.
        if (factorization->rounds_to_single())
          {
            SolverFGMRES<VectorType> fgmres(control,
                                            typename SolverFGMRES<VectorType>::AdditionalData(
                                              parameters.max_reuse_iterations + 2));
            fgmres.solve(system, x, b, preconditioner);
          }
        else
          {
            SolverGMRES<VectorType> gmres(control,
                                          typename SolverGMRES<VectorType>::AdditionalData(
                                            parameters.max_reuse_iterations + 2, true));
            gmres.solve(system, x, b, preconditioner);
          }
        iterations = control.last_step();
        return true;
      }
    catch (const SolverControl::NoConvergence &)
      {
        iterations = parameters.max_reuse_iterations;
        return false;
      }
  }

  template <typename SystemType, typename VectorType, typename PreconditionerType>
  ReusedFactorizationSolver::Result
  ReusedFactorizationSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                                   const SystemType                     &system,
                                   VectorType                           &x,
                                   const VectorType                     &b,
                                   PreconditionerType                   &preconditioner)
  {
    Result result;
    // Amesos_Mumps reports its errors on std::cerr: a failure keeps them for LinearSolverError::details(),
    // a successful solve passes them on.
    struct CerrCapture
    {
      std::ostringstream report;
      std::streambuf    *screen = std::cerr.rdbuf(report.rdbuf());
      bool               failed = false;
      ~CerrCapture()
      {
        std::cerr.rdbuf(screen);
        if (!failed)
          std::cerr << report.str() << std::flush;
      }
    } capture;
    std::string stage = "the GMRES solve preconditioned by the kept " + direct_solver() + " factors";
    try
      {
        if (!factorization || !factorization->has_factors() || factorization_requested ||
            (!parameters.reuse_factorization && !factors_of_current_matrix))
          {
            stage = "the " + direct_solver() + " factorization";
            factorize(matrix);
            result.factorized = true;
          }
        if (!factors_of_current_matrix)
          {
            if (solve_with_kept_factors(system, x, b, preconditioner, result.iterations))
              return result;
            stage = "the " + direct_solver() + " factorization";
            factorize(matrix);
            result.factorized = true;
          }
        // Single-precision or low-rank factors of this very matrix are still a preconditioner only.
        if (!factorization->exact())
          {
            stage = "the GMRES solve preconditioned by the fresh approximate " + direct_solver() + " factors";
            AssertThrow(solve_with_kept_factors(system, x, b, preconditioner, result.iterations),
                        ExcMessage("GMRES preconditioned by the approximate factors of the step's own matrix did "
                                   "not reach 'linear solver/tolerance' in 'max reuse iterations' iterations; "
                                   "set 'factor precision = double' and 'low rank tolerance = 0'"));
            return result;
          }
        stage = "the direct solve with the " + direct_solver() + " factors";
        std::optional<TimerOutput::Scope> section;
        if (step_timer)
          section.emplace(*step_timer, "linear solve");
        preconditioner.initialize(*factorization);
        preconditioner.vmult(x, b);
      }
    catch (const std::exception &exc)
      {
        factorization_requested = true;
        capture.failed          = true;
        throw LinearSolverError(stage + " failed (" + one_line_message(exc, 200) + ")",
                                capture.report.str() + exc.what());
      }
    return result;
  }

  template ReusedFactorizationSolver::Result
  ReusedFactorizationSolver::solve(const TrilinosWrappers::SparseMatrix &,
                                   const TrilinosWrappers::SparseMatrix &,
                                   TrilinosWrappers::MPI::Vector &,
                                   const TrilinosWrappers::MPI::Vector &,
                                   FactorizationPreconditioner &);
  template ReusedFactorizationSolver::Result
  ReusedFactorizationSolver::solve(const TrilinosWrappers::SparseMatrix &,
                                   const BorderedSystem &,
                                   BorderedSystem::BlockVector &,
                                   const BorderedSystem::BlockVector &,
                                   BorderedFactorizationPreconditioner &);
} // namespace FluidSurface
