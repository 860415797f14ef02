// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_bending_force_h
#define fluid_surface_model_bending_force_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/full_matrix.h>

#include <fluid_surface/model/dof_layout.h>
#include <fluid_surface/model/surface_point_values.h>

namespace FluidSurface
{
  /**
   * Helfrich bending force b = (1/Be)(−Δ_S H − H(|B|² − ½H²)) ν, discretized with the bending scalar y:
   * (y, φ) − (∇_S κ, ∇_S φ) + (c^m κ, φ) = 0 with the lagged coefficient c^m = |B^m|² − ½(H^m)²
   * (B^m = −P∇ñ^m), and the force −(1/Be)(y ñ, v) in the momentum equation. κ is the new surface's mean
   * curvature from MeshRedistribution. Owns `subsection bending`.
   */
  class BendingForce
  {
  public:
    /// Declares `subsection bending`.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Reads `subsection bending`.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// 1/Be, or 0 without the bending force.
    double
    inverse_bending_number() const
    {
      return enabled ? 1.0 / Be : 0.0;
    }

    /// The bending energy (1/2Be)∫|κ|² from the Willmore energy ½∫|κ|² (0 without the bending force).
    double
    energy(const double willmore_energy) const
    {
      return enabled ? willmore_energy / Be : 0.0;
    }

    /// Bending force in the momentum equation, −(1/Be)(y ñ, v): the rows of u, the columns of y.
    void
    assemble_force(const SurfacePointValues &point, const DofLayout &dofs, dealii::FullMatrix<double> &matrix) const;

    /// Bending scalar (y, φ) − (∇_S κ, ∇_S φ) + (c^m κ, φ) = 0: the rows of y, the columns of y and κ.
    void
    assemble_bending_scalar(const SurfacePointValues  &point,
                            const DofLayout           &dofs,
                            dealii::FullMatrix<double> &matrix) const;

    // The entries of `subsection bending`, set by parse_parameters().
    bool   enabled{}; ///< whether b is assembled
    double Be{};      ///< bending capillary number Be = ρU²L²/κ_b; F_bend = (1/2Be)∫H²
  };
} // namespace FluidSurface

#endif
