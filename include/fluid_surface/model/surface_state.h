// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_surface_state_h
#define fluid_surface_model_surface_state_h

#include <deal.II/dofs/dof_handler.h>

#include <fluid_surface/geometry/surface_geometry.h>

#include <array>
#include <optional>

namespace FluidSurface
{
  class CheckpointData;

  /**
   * The accepted state of the fluid deformable surface: the fields u^m, p, κ, y, Y (flow numbering), the
   * surface X^m and the reference surface S₀ of the mesh law (geometry numbering), and the targets the step
   * holds: the initial area A₀ and volume V₀ and the momenta g_k of the rigid-motion constraints. What a
   * checkpoint keeps of the model (save(), load()).
   */
  struct SurfaceState
  {
    /// Sizes the vectors for the flow DoFs @p flow_dofs and the position DoFs of @p geometry.
    void
    reinit(const dealii::DoFHandler<2, 3> &flow_dofs, const SurfaceGeometry &geometry);

    /**
     * Writes the state into a checkpoint: the fields (block "flow"), X^m (block "geometry", twice: the layout
     * of the checkpoints that also kept X^{m−1}), S₀ (block "mesh reference"), A₀, V₀ and the g_k. Collective.
     */
    void
    save(CheckpointData &data, const dealii::DoFHandler<2, 3> &flow_dofs, const SurfaceGeometry &geometry) const;

    /**
     * Reads what save() wrote (on any number of ranks) and moves @p geometry to X^m. reference_position is
     * not set (it is S₀ in the flow numbering: the caller's DoF map).
     */
    void
    load(const CheckpointData &data, const dealii::DoFHandler<2, 3> &flow_dofs, SurfaceGeometry &geometry);

    VectorType solution; ///< u^m, p, κ, y and Y = X^m of the accepted state (flow numbering), ghosted
    VectorType position; ///< X^m (geometry numbering), ghosted
    /// The curvature of X^m once the state was accepted (a restore is then an assignment); none after a load.
    std::optional<SurfaceGeometry::Curvature> curvature;
    /// X₀, the reference surface S₀ of the mesh law (the initial position unless replaced), geometry
    /// numbering, ghosted.
    VectorType reference_surface;
    /// S₀ in the Y components of the flow numbering, ghosted (the ∇_{S^m}X₀ of law reference).
    VectorType reference_position;
    double     target_volume = 0; ///< V₀
    double     target_area   = 0; ///< A₀
    /// Values g_k of the rigid-motion constraints (r_k, u) = g_k: 0 in the Stokes limit, the initial
    /// ∫u and ∫x × u with `conserve momenta`.
    std::array<double, 6> rigid_targets = {{0, 0, 0, 0, 0, 0}};
  };
} // namespace FluidSurface

#endif
