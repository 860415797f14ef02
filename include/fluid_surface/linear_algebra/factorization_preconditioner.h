// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_linear_algebra_factorization_preconditioner_h
#define fluid_surface_linear_algebra_factorization_preconditioner_h

#include <deal.II/base/exceptions.h>
#include <fluid_surface/linear_algebra/amesos_factorization.h>

namespace FluidSurface
{
  /**
   * An LU factorization used as a preconditioner: exact for the matrix it was built from, and a good
   * preconditioner for the nearby matrices of later time steps (the factorization kept across steps).
   */
  class FactorizationPreconditioner
  {
  public:
    /// Uses the factors @p lu (kept by the caller).
    void
    initialize(AmesosFactorization &lu)
    {
      factors = &lu;
    }

    /// dst = LU⁻¹ src.
    template <typename Vector>
    void
    vmult(Vector &dst, const Vector &src) const
    {
      Assert(factors != nullptr, dealii::ExcNotInitialized());
      factors->solve(dst, src);
    }

  private:
    AmesosFactorization *factors = nullptr;
  };
} // namespace FluidSurface

#endif
