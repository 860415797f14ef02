// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_linear_algebra_bordered_system_h
#define fluid_surface_linear_algebra_bordered_system_h

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <fluid_surface/linear_algebra/amesos_factorization.h>

#include <vector>

namespace FluidSurface
{
  /**
   * The system matrix A bordered by a few global constraints with multipliers μ_k:
   * @f[ K \begin{pmatrix} x \\ \mu \end{pmatrix} =
   *     \begin{pmatrix} A x + \sum_k \mu_k c_k \\ (r_j \cdot x)_j \end{pmatrix}, @f]
   * with columns c_k (the forces of the multipliers) and rows r_j (the constraints), which may differ.
   * Block 0 of a vector is the state, block 1 the multipliers, all owned by the first rank. A is square,
   * and there are as many rows as columns, each partitioned like the rows of A, and fewer than A has.
   */
  class BorderedSystem
  {
  public:
    using Vector      = dealii::TrilinosWrappers::MPI::Vector;
    using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

    BorderedSystem(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                   const std::vector<const Vector *>             &columns,
                   const std::vector<const Vector *>             &rows);

    /// dst = K src.
    void
    vmult(BlockVector &dst, const BlockVector &src) const;

    /// A vector with block 0 partitioned as @p state and one multiplier per constraint.
    BlockVector
    make_vector(const Vector &state) const;

    /// The multipliers of @p v, on every rank.
    static std::vector<double>
    multipliers(const BlockVector &v);

    /// Sets the multipliers of @p v (the same values on every rank; collective).
    static void
    set_multipliers(BlockVector &v, const std::vector<double> &values);

    /// The constraint values (r_j · x)_j of the state @p x.
    std::vector<double>
    constraint_values(const Vector &x) const;

    const dealii::TrilinosWrappers::SparseMatrix &matrix;
    const std::vector<const Vector *>            &columns;
    const std::vector<const Vector *>            &rows;
  };

  /**
   * The exact inverse of the bordered matrix K₀ = [A₀ C; Rᵀ 0] of a factorized A₀, by its Schur complement
   * S = Rᵀ Z with Z = A₀⁻¹ C (one solve with the factors per constraint, at construction). Exact for the
   * step whose matrix was factorized, and a preconditioner for later steps (A close to A₀): GMRES on K then
   * needs as many iterations as on A alone, and one preconditioner application costs a single solve with
   * the factors, however many constraints there are.
   */
  class BorderedFactorizationPreconditioner
  {
  public:
    /**
     * Z = A₀⁻¹C of an earlier solve with the same factors, kept by the caller: the solves of one step (the
     * geometry iteration's) take it over instead of solving for Z again. The preconditioner is then the exact
     * inverse of [A₀ A₀Z; Rᵀ 0], the bordered matrix with the earlier columns and the current rows; S = RᵀZ is
     * formed anew, so the constraints of enforce_constraints() hold to round-off all the same.
     */
    struct KeptColumns
    {
      std::vector<BorderedSystem::Vector> z;
      unsigned int                        factors = 0; ///< AmesosFactorization::n_numeric_factorizations() of z
      bool                                valid   = false;
    };

    /// A preconditioner of @p system; initialize() gives it the factors. With @p kept: see KeptColumns.
    explicit BorderedFactorizationPreconditioner(const BorderedSystem &system, KeptColumns *kept = nullptr);

    /**
     * Uses the factors of A₀ (kept by the caller): Z = A₀⁻¹ C and S⁻¹. With a change of variables T
     * (@p change, not nullptr), A₀⁻¹ stands for T A₀⁻¹ Tᵀ, the inverse of T A₀ Tᵀ.
     */
    void
    initialize(AmesosFactorization &factorization, const AmesosFactorization::ChangeOfVariables *change = nullptr);

    /// dst = K₀⁻¹ src: y = A₀⁻¹ r, μ = S⁻¹(Rᵀy − s), x = y − Zμ.
    void
    vmult(BorderedSystem::BlockVector &dst, const BorderedSystem::BlockVector &src) const;

    /**
     * Makes the constraints of @p v hold to round-off, Rᵀx = g: x −= Zδμ, μ += δμ with δμ = S⁻¹(Rᵀx − g).
     * The change of the state residual is (A − A₀)Zδμ, with δμ of the order of the Krylov residual.
     */
    void
    enforce_constraints(BorderedSystem::BlockVector &v, const std::vector<double> &g) const;

  private:
    /// μ = S⁻¹(Rᵀx − g).
    std::vector<double>
    schur_solve(const BorderedSystem::Vector &x, const std::vector<double> &g) const;

    AmesosFactorization                          *factorization = nullptr;
    const AmesosFactorization::ChangeOfVariables *change        = nullptr;
    const BorderedSystem                         &system;
    KeptColumns                                  *kept;
    std::vector<BorderedSystem::Vector> z;
    dealii::FullMatrix<double>          schur_inverse;
  };
} // namespace FluidSurface

#endif
