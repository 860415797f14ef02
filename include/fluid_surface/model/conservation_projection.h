// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_conservation_projection_h
#define fluid_surface_model_conservation_projection_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>

#include <fluid_surface/geometry/surface_geometry.h>

#include <array>

namespace FluidSurface
{
  /**
   * The exact correction after a step of what the continuous model conserves: the area A (inextensibility),
   * the enclosed volume V (with the volume constraint) and, with `flow/conserve momenta`, the momenta ∫u and
   * ∫x × u. The step itself holds them only to first order in τ (linearized on S^{m+1}, drifts returned over
   * τ_c); the projection removes the rest:
   *
   * - A and V: the nodes move along ñ by a ñ + b H ñ (H the nodal mean curvature), a and b from Newton's
   *   method on (V − V₀, A − A₀) with the first variations dV = ∫δ·ν, dA = −∫Hδ·ν (κ = Hν = Δ_S X), whose
   *   Jacobian is invertible unless H is constant; without the volume constraint the mode a ñ alone.
   * - Momenta: u += Σ c_k r_k with the rigid motions r = e_d, e_d × x, c from the 6 × 6 Gram system of the r_k
   *   on the new surface. A rigid motion has σ(r) = 0 and div_S r = 0: the correction changes neither the
   *   dissipation nor the area rate.
   *
   * Owns `subsection conservation projection`.
   */
  class ConservationProjection
  {
  public:
    /// Declares `subsection conservation projection`.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Reads it.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * Moves the nodes of @p geometry normally so that its area is @p target_area and, if @p hold_volume, its
     * volume @p target_volume (to 1e-13 relative, at most 8 Newton steps), along the modes ñ and Hñ of
     * @p modes (the curvature of the surface the correction starts from, held fixed over the Newton steps).
     * Returns the largest nodal displacement.
     */
    double
    project_area_and_volume(SurfaceGeometry                  &geometry,
                            const SurfaceGeometry::Curvature &modes,
                            const double                      target_area,
                            const double     target_volume,
                            const bool       hold_volume) const;

    /**
     * Adds to the velocity (components 0–2) of @p state (owned) on the current surface of @p geometry the rigid
     * motion that makes ∫u and ∫x × u (about the origin) equal @p targets. Returns the norm of the change of
     * the momenta.
     */
    double
    project_momenta(const SurfaceGeometry          &geometry,
                    const dealii::DoFHandler<2, 3> &dofs,
                    const std::array<double, 6>    &targets,
                    VectorType                     &state) const;

    /// ∫u and ∫x × u (about the origin) of the velocity (components 0–2) of @p state (ghosted) on the current
    /// surface of @p geometry, with its quadrature (the one project_momenta() and the diagnostics use).
    static std::array<double, 6>
    momenta(const SurfaceGeometry &geometry, const dealii::DoFHandler<2, 3> &dofs, const VectorType &state);

    bool enabled = true; ///< `enabled`
  };
} // namespace FluidSurface

#endif
