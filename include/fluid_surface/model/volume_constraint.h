// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_volume_constraint_h
#define fluid_surface_model_volume_constraint_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <fluid_surface/model/dof_layout.h>
#include <fluid_surface/model/surface_point_values.h>

#include <algorithm>

namespace FluidSurface
{
  /**
   * Global multiplier γ for the enclosed volume: the force γ(ñ, v) and the constraint
   * (u·ñ, 1) = −(V^m − V₀)/τ_c, whose right-hand side also removes any volume drift of earlier steps.
   * τ_c is also the relaxation time of the area and momentum drift corrections. Owns
   * `subsection volume constraint`.
   */
  class VolumeConstraint
  {
  public:
    /// Declares `subsection volume constraint`.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Reads `subsection volume constraint`; @p maximum_time_step is τ_max of the run (a lower bound of τ_c).
    void
    parse_parameters(dealii::ParameterHandler &prm, const double maximum_time_step);

    /// The relaxation time τ_c = max(τ, τ_drift, τ_max) of the drift corrections (≥ τ, independent of τ ≤ τ_max).
    double
    drift_time(const double tau) const
    {
      return std::max(tau, std::max(drift_correction_time, maximum_time_step));
    }

    /// Volume column (ñ, v): γ's force in the momentum rows and, as a row, the constraint (u·ñ, 1).
    void
    assemble_column(const SurfacePointValues &point, const DofLayout &dofs, dealii::Vector<double> &column) const;

    // The entries of `subsection volume constraint`, set by parse_parameters().
    bool   enabled{};               ///< whether γ and the volume row border the step system
    double drift_correction_time{}; ///< τ_drift

  private:
    double maximum_time_step{}; ///< τ_max of `time stepping`, given to parse_parameters()
  };
} // namespace FluidSurface

#endif
