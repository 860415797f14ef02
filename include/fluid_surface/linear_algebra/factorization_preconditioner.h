#ifndef fluid_surface_linear_algebra_factorization_preconditioner_h
#define fluid_surface_linear_algebra_factorization_preconditioner_h

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/trilinos_solver.h>

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
    initialize(dealii::TrilinosWrappers::SolverDirect &lu)
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
    dealii::TrilinosWrappers::SolverDirect *factors = nullptr;
  };
} // namespace FluidSurface

#endif
