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
    /// Uses the factors @p lu (kept by the caller), of T A Tᵀ with the change of variables @p change (nullptr: none).
    void
    initialize(AmesosFactorization &lu, const AmesosFactorization::ChangeOfVariables *change = nullptr)
    {
      factors = &lu;
      this->change = change;
    }

    /// dst = LU⁻¹ src.
    template <typename Vector>
    void
    vmult(Vector &dst, const Vector &src) const
    {
      Assert(factors != nullptr, dealii::ExcNotInitialized());
      factors->solve(dst, src, change);
    }

  private:
    AmesosFactorization                            *factors = nullptr;
    const AmesosFactorization::ChangeOfVariables *change  = nullptr;
  };
} // namespace FluidSurface

#endif
