// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_momentum_constraints_h
#define fluid_surface_model_momentum_constraints_h

#include <deal.II/lac/vector.h>

#include <fluid_surface/flow/surface_fluid.h>
#include <fluid_surface/model/dof_layout.h>
#include <fluid_surface/model/surface_point_values.h>

#include <array>

namespace FluidSurface
{
  /**
   * The six rigid-motion multipliers μ_k of scene full, r = e_1, e_2, e_3, e_1 × x, e_2 × x, e_3 × x:
   * forces Σμ_k (r_k, v) in the momentum rows and the constraints (r_k, u) = g_k. In the Stokes limit
   * (`flow/inertia = false`) they fix the rigid motions, ∫u = 0 and ∫x × u = 0, together with the
   * regularization ε(u, v); with `flow/conserve momenta` they keep ∫u = P₀ and ∫x × u = L₀ on the new
   * surface S^{m+1}, linearized in Y (doc/scheme.md, "Momentum conservation").
   */
  class MomentumConstraints
  {
  public:
    /// Inactive until set up.
    MomentumConstraints() = default;
    /// The constraints the @p fluid asks for (`subsection flow`: inertia, conserve momenta, regularization).
    explicit MomentumConstraints(const SurfaceFluid &fluid);

    /// Whether the multipliers are part of the step: the Stokes limit, or `conserve momenta`.
    bool
    active() const
    {
      return stokes_limit || conserve_momenta;
    }

    /// Whether the momenta are held on S^{m+1} (with inertia), so that the rows have Y entries.
    bool
    on_new_surface() const
    {
      return active() && !stokes_limit;
    }

    /// ε of the Stokes limit's regularization ε(u, v) (SurfaceFluid::mass_term with c = ε).
    double
    regularization() const
    {
      return rigid_motion_regularization;
    }

    /**
     * The rigid-motion columns (r_k, v): the forces Σμ_k r_k in the momentum rows. The constraint rows
     * (r_k, u) have the same entries in the velocity DoFs.
     */
    void
    assemble_columns(const SurfacePointValues             &point,
                     const DofLayout                      &dofs,
                     std::array<dealii::Vector<double>, 6> &columns) const;

    /**
     * The Y entries of the constraint rows on S^{m+1}, to first order in δ = Y − X^m (u ≈ u^m in the
     * correction): ∫_{S^{m+1}} u ≈ ∫u + ∫u^m div_S δ and ∫_{S^{m+1}} x × u ≈ ∫x × u + ∫δ × u^m + (x × u^m) div_S δ.
     */
    void
    assemble_new_surface_rows(const SurfacePointValues             &point,
                              const DofLayout                      &dofs,
                              std::array<dealii::Vector<double>, 6> &rows) const;

  private:
    bool   stokes_limit                = false;
    bool   conserve_momenta            = false;
    double rigid_motion_regularization = 0;
  };
} // namespace FluidSurface

#endif
