// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_dof_layout_h
#define fluid_surface_model_dof_layout_h

#include <deal.II/fe/fe.h>

#include <array>
#include <vector>

namespace FluidSurface
{
  /**
   * The unknowns of scene full in the components of its FESystem — u in 0–2, p in 3, κ in 4, y in 5, Y in
   * 6–8 — and, for the element of a cell, the local DoFs of each unknown (in increasing order).
   */
  struct DofLayout
  {
    static constexpr unsigned int velocity_component     = 0;
    static constexpr unsigned int pressure_component     = 3;
    static constexpr unsigned int curvature_component    = 4;
    static constexpr unsigned int bending_component      = 5;
    static constexpr unsigned int new_position_component = 6;
    static constexpr unsigned int n_components           = 9;

    /// Sorts the local DoFs of @p fe by unknown; asserts the component layout above.
    explicit DofLayout(const dealii::FiniteElement<2, 3> &fe);

    std::vector<unsigned int> velocity;       ///< u ∈ [Q2]³
    /// The direction d of each DoF of u (parallel to `velocity`): its shape function is φ e_d.
    std::vector<unsigned int> velocity_direction;
    std::vector<unsigned int> pressure;       ///< p ∈ Q1
    std::vector<unsigned int> curvature;      ///< κ ∈ Q_k
    std::vector<unsigned int> bending_scalar; ///< y ∈ Q_k
    std::vector<unsigned int> new_position;   ///< Y ∈ [Q_k]³
    /// The local DoFs of Y by node: new_position_nodes[n][d] is the row of component d at node n (the nodes in
    /// the order of the base element, that of κ).
    std::vector<std::array<unsigned int, 3>> new_position_nodes;
  };
} // namespace FluidSurface

#endif
