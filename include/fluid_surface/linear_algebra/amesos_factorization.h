// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_linear_algebra_amesos_factorization_h
#define fluid_surface_linear_algebra_amesos_factorization_h

#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

class Amesos_BaseSolver;
class Epetra_Comm;
class Epetra_CrsMatrix;
class Epetra_LinearProblem;
class Epetra_Map;

namespace FluidSurface
{
  class SinglePrecisionLU;

  /**
   * A sparse LU factorization PAQ = LU of a TrilinosWrappers::SparseMatrix by an Amesos package (Amesos_Klu,
   * Amesos_Mumps), split into the symbolic analysis (fill-reducing ordering, elimination tree, memory) and
   * the numeric factorization. The analysis depends on the sparsity pattern only, so factorize() redoes it
   * only when the matrix is another Epetra object than the analysed one or its pattern changed (new DoFs,
   * a checkpoint loaded), and otherwise only the numeric factorization of the new values.
   *
   * With Amesos_Mumps, `mumps_ordering` is MUMPS' ICNTL(7) (0 AMD, 2 AMF, 3 SCOTCH, 4 PORD, 5 METIS,
   * 6 QAMD, 7 automatic) and `low_rank_tolerance` > 0 switches on MUMPS' block-low-rank factorization
   * (ICNTL(35) = 2) with dropping threshold CNTL(7) = `low_rank_tolerance`: the factors are then those of
   * a matrix within about that relative distance, a preconditioner, not an inverse.
   */
  class AmesosFactorization
  {
  public:
    /// The Amesos package and the MUMPS controls of the factorizations.
    struct Options
    {
      std::string package            = "Amesos_Mumps";
      int         mumps_ordering     = 7;   ///< ICNTL(7); 7: MUMPS chooses
      double      low_rank_tolerance = 0.0; ///< CNTL(7) of the block-low-rank factorization; 0: full rank
      bool        single_precision   = false; ///< Amesos_Mumps only: the factors in single precision (SinglePrecisionLU)
    };

    explicit AmesosFactorization(const Options &options);
    ~AmesosFactorization();
    AmesosFactorization(const AmesosFactorization &) = delete;
    AmesosFactorization &
    operator=(const AmesosFactorization &) = delete;

    /**
     * Factorizes @p matrix (collective): the symbolic analysis if the pattern is not the analysed one, then
     * the numeric factorization. Time goes to the section "symbolic factorization" of @p timer (nullptr:
     * none) for the analysis; the caller times the whole. A failure throws ExcTrilinosError (the Amesos
     * error code) and leaves no factors; a failed analysis is redone by the next call.
     */
    void
    factorize(const dealii::TrilinosWrappers::SparseMatrix &matrix, dealii::TimerOutput *timer = nullptr);

    /// dst = (LU)⁻¹ src with the factors of the last factorize() (collective).
    void
    solve(dealii::TrilinosWrappers::MPI::Vector &dst, const dealii::TrilinosWrappers::MPI::Vector &src);

    /**
     * An orthogonal change of variables T of the unknowns: T(v, false) replaces v by Tv, T(v, true) by Tᵀv
     * (e.g. a rotation of the vector unknowns node by node).
     */
    using ChangeOfVariables = std::function<void(dealii::TrilinosWrappers::MPI::Vector &, bool)>;

    /// dst = T (LU)⁻¹ Tᵀ src, the inverse of T A Tᵀ for the factorized A; solve() if @p change is nullptr.
    void
    solve(dealii::TrilinosWrappers::MPI::Vector       &dst,
          const dealii::TrilinosWrappers::MPI::Vector &src,
          const ChangeOfVariables                     *change);

    /// dst[k] = T (LU)⁻¹ Tᵀ src[k] for all k; with Amesos_Mumps on one process in one solve phase.
    void
    solve(std::vector<dealii::TrilinosWrappers::MPI::Vector>              &dst,
          const std::vector<const dealii::TrilinosWrappers::MPI::Vector *> &src,
          const ChangeOfVariables                                          *change);
    /// Whether the factors are those of the matrix to round-off in double precision (not single precision,
    /// not block low rank): a solve with them is a direct solve, not only a preconditioner.
    bool
    exact() const
    {
      return !options.single_precision && options.low_rank_tolerance == 0;
    }

    /// Whether a solve rounds its input and output to single precision (`single_precision`): a preconditioner
    /// that is linear only to that precision.
    bool
    rounds_to_single() const
    {
      return options.single_precision;
    }

    /// Whether factorize() succeeded since construction or the last failure.
    bool
    has_factors() const
    {
      return factorized;
    }

    /// The number of numeric factorizations so far: which factors these are.
    unsigned int
    n_numeric_factorizations() const
    {
      return numeric_count;
    }
    /// The number of symbolic analyses so far.
    unsigned int
    n_symbolic_factorizations() const
    {
      return symbolic_count;
    }

  private:
    /// The symbolic analysis of @p matrix by a new solver (collective); throws if it fails.
    void
    analyse(const Epetra_CrsMatrix &matrix);
    /// Whether the analysis of the kept solver is that of @p matrix (collective).
    bool
    analysis_fits(const Epetra_CrsMatrix &matrix, std::uint64_t pattern_hash) const;
    /// Destroys the Amesos solver while its linear problem points at a live matrix (MUMPS frees its
    /// instance on the matrix's communicator).
    void
    destroy_solver();

    Options                               options;
    std::unique_ptr<Epetra_LinearProblem> problem;
    std::unique_ptr<Amesos_BaseSolver>    solver;
    std::unique_ptr<SinglePrecisionLU>    single;        ///< the factors of `single_precision`
    std::unique_ptr<Epetra_Comm>          comm;          ///< a copy of the analysed matrix's communicator
    std::unique_ptr<Epetra_Map>           empty_map;     ///< of the placeholder matrix
    std::unique_ptr<Epetra_CrsMatrix>     placeholder;   ///< empty, on `comm`: the operator while destroying
    const Epetra_CrsMatrix               *analysed       = nullptr;
    std::uint64_t                         analysed_hash  = 0;
    bool                                  factorized     = false;
    unsigned int                          symbolic_count = 0;
    unsigned int                          numeric_count  = 0;
  };
} // namespace FluidSurface

#endif
