// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_flow_energy_functionals_h
#define fluid_surface_flow_energy_functionals_h

#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <fluid_surface/geometry/surface_geometry.h>

namespace FluidSurface
{
  /**
   * The energy functionals of a surface flow, the same for every user (scene full, scene fixed surface,
   * diagnostics): the kinetic energy F_kin = ½∫|u|² and the viscous dissipation rate D = (2/Re)‖σ(u)‖²,
   * dF_kin/dt = −D for the exact flow on a fixed surface. u is components 0–2 of the state of @p dofs.
   */
  namespace EnergyFunctionals
  {
    /// ½|u|², the density of F_kin.
    inline double
    kinetic_energy_density(const dealii::Tensor<1, 3> &u)
    {
      return 0.5 * u.norm_square();
    }

    /// F_kin = ½∫|u|² over the locally owned cells, summed over all ranks of @p communicator.
    double
    kinetic_energy(const dealii::Mapping<2, 3>       &mapping,
                   const dealii::DoFHandler<2, 3>    &dofs,
                   const VectorType                  &state,
                   const dealii::Quadrature<2>       &quadrature,
                   const MPI_Comm                     communicator);

    /// D = (2/Re)‖σ(u)‖² = (2/Re)∫σ(u):σ(u), σ(u) = sym(P ∇_C u) with the cell normal, plus the grad-div
    /// term's γ_gd‖div_P u − s‖² (@p grad_div = γ_gd, @p area_rate = s), summed over all ranks.
    double
    dissipation_rate(const dealii::Mapping<2, 3>    &mapping,
                     const dealii::DoFHandler<2, 3> &dofs,
                     const VectorType               &state,
                     const dealii::Quadrature<2>    &quadrature,
                     const double                    Re,
                     const MPI_Comm                  communicator,
                     const double                    grad_div  = 0,
                     const double                    area_rate = 0);
  } // namespace EnergyFunctionals
} // namespace FluidSurface

#endif
