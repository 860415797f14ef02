// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_linear_algebra_single_precision_lu_h
#define fluid_surface_linear_algebra_single_precision_lu_h

#include <Epetra_CrsMatrix.h>
#include <Epetra_Import.h>
#include <Epetra_Map.h>
#include <Epetra_MultiVector.h>

#include <memory>
#include <vector>

namespace FluidSurface
{
  /**
   * An LU factorization PAQ = LU of an Epetra_CrsMatrix in single precision by MUMPS (smumps), for a
   * preconditioner: its factors take half the memory and half the memory traffic of the double-precision
   * ones, and a kept factorization preconditions GMRES on the following steps' matrices anyway, whose
   * difference from the factorized one is far larger than single precision's rounding (doc/scheme.md,
   * "Single-precision factors"). The matrix enters distributed (MUMPS' ICNTL(18) = 3), the right-hand sides
   * and solutions are gathered on the first process and scattered back.
   */
  class SinglePrecisionLU
  {
  public:
    /// A solver on the communicator of @p matrix; analyse() before factorize().
    explicit SinglePrecisionLU(const Epetra_CrsMatrix &matrix, int mumps_ordering);
    ~SinglePrecisionLU();
    SinglePrecisionLU(const SinglePrecisionLU &) = delete;
    SinglePrecisionLU &
    operator=(const SinglePrecisionLU &) = delete;

    /// The symbolic analysis of the pattern of @p matrix (collective); throws if MUMPS fails.
    void
    analyse(const Epetra_CrsMatrix &matrix);

    /// The numeric factorization of the values of @p matrix, whose pattern was analysed (collective).
    void
    factorize(const Epetra_CrsMatrix &matrix);

    /// Replaces each column of @p columns (vectors of the matrix's row map) by (LU)⁻¹ of it, all columns in
    /// one MUMPS solve phase (collective).
    void
    solve(Epetra_MultiVector &columns);

  private:
    /// Calls MUMPS with the job @p job; throws with MUMPS' INFOG(1), INFOG(2) if it failed.
    void
    call(int job, const char *phase);
    /// Throws with MUMPS' INFOG(1), INFOG(2) if the last call failed.
    void
    check(const char *phase) const;

    struct Instance;
    std::unique_ptr<Instance> mumps;
    std::vector<int>          rows, cols; ///< 1-based global indices of the local entries
    std::vector<float>        values;
    std::unique_ptr<Epetra_Map>    root_map; ///< every row on the first process
    std::unique_ptr<Epetra_Import> to_root;
    std::vector<float>             root_columns;
  };
} // namespace FluidSurface

#endif
