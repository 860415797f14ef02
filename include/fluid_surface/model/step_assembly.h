// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_step_assembly_h
#define fluid_surface_model_step_assembly_h

#include <fluid_surface/model/step_components.h>
#include <fluid_surface/model/step_frame.h>
#include <fluid_surface/model/step_request.h>
#include <fluid_surface/model/step_system.h>

#include <memory>
#include <vector>

namespace FluidSurface
{
  struct CellContext;

  /**
   * The fields and numbers one assembly of the step system reads, in the backward-Euler form of the step
   * (x − x̂)/τ = f that every time scheme is written in (TimeScheme::start()).
   */
  struct StepAssemblyData
  {
    double            tau          = 0;       ///< τ of the backward-Euler form (BDF2: τ/α₀)
    const VectorType *old_position = nullptr; ///< X̂: X^m, or BDF2's start (geometry numbering, ghosted)
    const VectorType *old_fields   = nullptr; ///< û: the fields whose u is that of the inertia (flow numbering)
    const VectorType *transport_fields = nullptr; ///< the fields whose u the convection lags (u^m, or BDF2's u*)
    const VectorType *normal = nullptr; ///< ñ of the assembly (the geometry's, or a GeometryIteration iterate's)
    const VectorType *reference_position = nullptr; ///< S₀ of law reference in the flow numbering
    /**
     * The frame of the step; its `carried` motion R is the one the mesh follows. Co-rotating: the convection is
     * transported by u − R and the mesh moves relative to the frame, ∇_{u* − R} ũ − (1/τ)(G(Ỹ − X̂), v), instead
     * of ∇_{u*} ũ − (1/τ)(G(Ỹ − X̂ + τR), v): the two differ by ∇_R(ũ − u*), of order τ mΩ ∂_t u, which a frame
     * that turns at Ω must not carry.
     */
    const StepFrame *frame = nullptr;
    /// Law reference: the frame velocity R taken on the assembly's surface (BDF2: the new level) instead of X̂.
    bool   frame_velocity_on_new_surface = false;
    double area_rate                     = 0; ///< s = −(A^m − A₀)/(τ_c A^m) of the continuity row
    double area_scale                    = 1; ///< A₀/A of the membrane energy
    double membrane_weight = 0; ///< the weight of the membrane energy (MeshRedistribution::membrane_weight())
  };

  /**
   * One term of the step's weak form, as it adds itself to a cell's LocalSystem: at each Gauss point, at each
   * nodal point, and once the cell is done. Built once per StepRequest (StepAssembly::StepAssembly()), so the
   * cell loop does not branch on modes.
   */
  class StepTerm
  {
  public:
    virtual ~StepTerm() = default;
    /// Before the points of a cell (per-cell data of the term).
    virtual void
    reinit_cell(CellContext &) const
    {}
    /// The term at Gauss point @p q.
    virtual void
    gauss_point(const unsigned int q, CellContext &cell) const = 0;
    /// The term at nodal point @p q (the nodal rule (·,·)_h of the mesh law).
    virtual void
    nodal_point(const unsigned int, CellContext &) const
    {}
    /// After all points of the cell.
    virtual void
    finish_cell(CellContext &) const
    {}
  };

  /**
   * The assembly of the step system: the list of StepTerm objects that the components and the request call for
   * (the surface fluid or a prescribed velocity, the bending force and scalar, the mesh law, the volume column,
   * the momentum constraints), run cell by cell (WorkStream) into the StepSystem.
   */
  class StepAssembly
  {
  public:
    /// The terms of @p request with the parsed @p components, into @p system.
    StepAssembly(const StepComponents &components, const StepRequest &request, StepSystem &system);
    ~StepAssembly();

    /// Assembles matrix, right-hand side and global columns on the geometry's current surface.
    void
    assemble(const StepAssemblyData &data) const;

  private:
    const StepComponents                  &components;
    StepSystem                            &system;
    const bool                             rigid;     ///< the rigid-motion columns and rows are assembled
    const bool                             reference; ///< law reference (its rows are projected at the nodes)
    std::vector<std::unique_ptr<StepTerm>> terms;
  };
} // namespace FluidSurface

#endif
