#ifndef fluid_surface_model_surface_reparametrization_h
#define fluid_surface_model_surface_reparametrization_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>

#include <fluid_surface/geometry/surface_geometry.h>

namespace FluidSurface
{
  /**
   * The safety valve of the mesh law: a re-parametrization of the current discrete surface S_h at fixed
   * connectivity, for a mesh whose quality (min over cells of σ_min/σ_max of the Jacobian) fell below
   * `quality threshold` q_r.
   *
   * - New nodes, all on S_h: `relaxation iterations` solves of the mesh law alone (the velocity held at zero,
   *   the tangential damping weak: τ = 10 T_r; FluidDeformableSurface::reparametrize()), each followed by the
   *   closest-point projection of every node onto the surface before it (closest_points()) and the transfer
   *   of the fields. With law `reference` this approaches the minimizer of the membrane energy relative to S₀
   *   among the parametrizations of S_h, which the law itself approaches only on the time scale T_r. The
   *   surface changes by its interpolation error once per iteration.
   * - Fields (transfer()): every degree of freedom of the flow takes the value of the old field at the point
   *   of the old surface where its support point now lies (closest-point location, cell by cell).
   *
   * The model (FluidDeformableSurface::reparametrize()) then restores A, V, the discrete incompressibility and
   * the momenta. Owns `subsection reparametrization`.
   */
  class SurfaceReparametrization
  {
  public:
    /// Declares `subsection reparametrization`.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Reads it; the threshold must lie above the @p mesh_quality_floor at which a run stops.
    void
    parse_parameters(dealii::ParameterHandler &prm, const double mesh_quality_floor);

    /// Whether the valve is on (q_r > 0).
    bool
    enabled() const
    {
      return quality_threshold > 0;
    }

    /**
     * Whether a mesh of quality @p quality needs a re-parametrization: below q_r and, if an earlier one left
     * the quality @p quality_after_last below q_r too, 10 % below that (so that a shape whose best mesh of
     * this connectivity is below q_r is not re-parametrized at every step).
     */
    bool
    due(const double quality, const double quality_after_last) const;

    /**
     * The closest points on the surface @p old_position (ghosted, geometry numbering) of the nodes of the
     * current position field of @p geometry (each searched from its own cell), locally owned entries.
     */
    static VectorType
    closest_points(const SurfaceGeometry &geometry, const VectorType &old_position);

    /**
     * The field @p old_field (ghosted, DoFHandler @p field_dofs on the same triangulation as @p geometry, an
     * element with support points) on the surface @p old_position (ghosted) → @p new_field (owned entries set)
     * on the surface @p new_position (ghosted), both surfaces in the numbering of @p geometry: each degree of
     * freedom takes the old field's value at the closest point on the old surface of its new support point.
     */
    static void
    transfer(const SurfaceGeometry          &geometry,
             const VectorType               &old_position,
             const VectorType               &new_position,
             const dealii::DoFHandler<2, 3> &field_dofs,
             const VectorType               &old_field,
             VectorType                     &new_field);

    double       quality_threshold = 0.1; ///< q_r
    unsigned int iterations        = 5;   ///< n_r, solves of the mesh law that place the new nodes
    double       maximum_energy_jump = 1e-2; ///< ε_F: a re-parametrization that changes F by more is not taken
  };
} // namespace FluidSurface

#endif
