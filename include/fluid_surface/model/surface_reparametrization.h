// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_surface_reparametrization_h
#define fluid_surface_model_surface_reparametrization_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>

#include <fluid_surface/geometry/surface_geometry.h>

#include <array>
#include <functional>
#include <ostream>
#include <string>

namespace FluidSurface
{
  class CheckpointData;
  class StatisticsFile;
  class SurfaceStep;
  struct StepRequest;
  struct SurfaceState;

  /**
   * The safety valve of the mesh law: a re-parametrization of the current discrete surface S_h at fixed
   * connectivity, for a mesh whose quality (min over cells of σ_min/σ_max of the Jacobian) fell below
   * `quality threshold` q_r.
   *
   * - New nodes, all on S_h: `relaxation iterations` solves of the mesh law alone (the velocity held at zero,
   *   the tangential damping weak: τ = 10 T_r; reparametrize()), each followed by the
   *   closest-point projection of every node onto the surface before it (closest_points()) and the transfer
   *   of the fields. With law `reference` this approaches the minimizer of the membrane energy relative to S₀
   *   among the parametrizations of S_h, which the law itself approaches only on the time scale T_r. The
   *   surface changes by its interpolation error once per iteration.
   * - Fields (transfer()): every degree of freedom of the flow takes the value of the old field at the point
   *   of the old surface where its support point now lies (closest-point location, cell by cell).
   *
   * reparametrize() then restores A, V, the discrete incompressibility and the momenta, and refuses a new
   * mesh that is worse or that changes F by more than `maximum energy jump`.
   *
   * Owns `subsection reparametrization`, the count and the largest jumps of the re-parametrizations of a run
   * (record()), their statistics columns, their summary line and their checkpoint keys `reparametrization/…`.
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

    /// What one re-parametrization (reparametrize()) did.
    struct Result
    {
      bool        done = false;
      std::string failure; ///< why it failed (the state is then unchanged), one line
      double      quality_before = 0, quality_after = 0;
      double      node_correction = 0; ///< the largest normal move of a node that restored A and V
    };

    /**
     * The safety valve on the accepted @p state of @p step: new nodes on the current surface (relaxation solves
     * of the mesh law, closest_points(), transfer()), then A and V restored (ConservationProjection), the
     * velocity projected onto the discrete incompressible fields with the step's constraints (volume rate,
     * momenta on the surface) by one step of the flow with τ = projection_time_step (the limit τ → 0 of the
     * step: the L² projection with the pressure and the multipliers; the nodes stay where they are), and the
     * momenta restored exactly. @p run_request is the request of the run's steps (its velocity source and mesh
     * law); @p total_energy evaluates F of the state (computing the curvature of the geometry). On success the
     * state is replaced; otherwise it is restored. Either way the geometry's curvature is that of the state.
     */
    Result
    reparametrize(SurfaceStep                   &step,
                  SurfaceState                  &state,
                  const StepRequest             &run_request,
                  const std::function<double()> &total_energy) const;
    /// τ of the projection step of reparametrize(): viscous and bending terms enter it with a weight ~1e-9 relative.
    static constexpr double projection_time_step = 1e-9;

    /// F, A, V and L = ∫x × u of a state, as the statistics measure them.
    struct Measures
    {
      double               energy = 0, area = 0, volume = 0;
      dealii::Tensor<1, 3> angular_momentum;
    };
    /// The relative jumps |after − before|/|before| of F, A, V and L (|ΔL|/|L|) of a re-parametrization.
    using Jumps = std::array<double, 4>;
    /**
     * Counts the re-parametrization @p result of a mesh of quality @p quality: a success with the measures
     * @p before and @p after it (returns the jumps), or a failure (returns zeros; the next one is then not due
     * before the quality has fallen by another 10 %).
     */
    Jumps
    record(const Result &result, const double quality, const Measures &before, const Measures &after);
    /// Whether the mesh of the accepted state, of quality @p quality, needs a re-parametrization (due()).
    bool
    due(const double quality) const
    {
      return due(quality, quality_after_last);
    }
    /// The statistics columns of a step whose re-parametrization made the @p jumps (zeros: none); none if off.
    void
    add_to_statistics(StatisticsFile &statistics, const Jumps &jumps) const;
    /// The summary line: the count and the largest jumps (nothing if off).
    void
    write_summary(std::ostream &text) const;
    /// The counters under `reparametrization/…`.
    void
    save(CheckpointData &data) const;
    /// Reads them (checkpoints without them: the counters of a run without re-parametrizations).
    void
    load(const CheckpointData &data);

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

  private:
    /**
     * The relaxation of the mesh: `iterations` solves of the mesh law alone (the velocity at rest, no global
     * constraints, law reference towards S₀, a fresh KLU factorization), each followed by the closest-point
     * projection of the nodes onto the surface before it (from @p start_surface) and the transfer of the fields
     * (from @p start_fields) into @p state. Returns why a solve failed, or nothing.
     */
    std::string
    relax_mesh(SurfaceStep &step, const VectorType &start_surface, const VectorType &start_fields, VectorType &state) const;
    /**
     * The velocity of the relaxed mesh back onto the discrete constraints: one step of the scheme with τ =
     * projection_time_step (a fresh KLU factorization), then the momenta restored. Returns why the solve
     * failed, or nothing.
     */
    std::string
    project_velocity(SurfaceStep &step, SurfaceState &accepted, const StepRequest &run_request) const;
    unsigned int count = 0; ///< re-parametrizations so far
    /// The largest relative jumps of F, A, V and L of the re-parametrizations so far.
    Jumps largest_jumps = {{0, 0, 0, 0}};
    /// The mesh quality the last re-parametrization left (1 before any).
    double quality_after_last = 1;
  };
} // namespace FluidSurface

#endif
