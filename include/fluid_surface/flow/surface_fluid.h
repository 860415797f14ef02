// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_flow_surface_fluid_h
#define fluid_surface_flow_surface_fluid_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <fluid_surface/flow/flow_point_values.h>

namespace FluidSurface
{
  /**
   * The incompressible viscous surface fluid (seed eqs. 1–2): its parameters (`subsection flow`) and the
   * terms of its momentum and continuity equations on the frozen surface S^m (doc/scheme.md, "Unknowns and
   * one step"). Scene full assembles these terms in SurfaceStep, scene fixed surface in
   * SurfaceFlow.
   *
   * A term function returns the integrand of one entry at one quadrature point @p point, without the weight
   * JxW: of the matrix entry for the test function v = φ_i (q = ψ_i) and the trial function u = φ_j
   * (p = ψ_j), or of the right-hand side entry for v = φ_i (q = ψ_i). The caller sums the terms of an entry
   * and multiplies by JxW once.
   */
  class SurfaceFluid
  {
  public:
    /// Declares `subsection flow`: Re, inertia, convection, conserve momenta, rigid motion regularization.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Reads `subsection flow`; InputError on inconsistent values.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// 2/Re, the factor of the viscous stress.
    double
    viscosity() const
    {
      return 2.0 / Re;
    }

    /// Viscous stress (2/Re)(σ(u), σ(v)).
    double
    viscous_term(const FlowPointValues &point, const unsigned int i, const unsigned int j) const
    {
      return viscosity() * scalar_product(point.strain_rate[i], point.strain_rate[j]);
    }

    /**
     * Inertia (1/τ)(u − u^m, v), its matrix part c (u, v) with c = 1/τ (BDF2: α₀/τ). With c = ε it is the
     * regularization ε(u, v) of the Stokes limit.
     */
    static double
    mass_term(const FlowPointValues &point, const unsigned int i, const unsigned int j, const double c)
    {
      return c * (point.velocity[i] * point.velocity[j]);
    }

    /// Inertia (1/τ)(u − u^m, v), its right-hand side c (u^m, v) with c = 1/τ (u^m: point.old_velocity).
    static double
    mass_term_rhs(const FlowPointValues &point, const unsigned int i, const double c)
    {
      return c * (point.old_velocity * point.velocity[i]);
    }

    /// G(φ_j) w, the trial function's part of the convection, with w = point.transport_velocity.
    static dealii::Tensor<1, 3>
    convected_velocity(const FlowPointValues &point, const unsigned int j)
    {
      return point.velocity_gradient[j] * point.transport_velocity;
    }

    /// Convection (∇_w u, v) = (G w, v) for the trial function's G(φ_j) w = @p convected (convected_velocity()).
    static double
    convection_term(const FlowPointValues &point, const unsigned int i, const dealii::Tensor<1, 3> &convected)
    {
      return convected * point.velocity[i];
    }

    /// Convection (∇_w u, v) = (G w, v), G = ∇_C u, with the transport velocity w = point.transport_velocity.
    static double
    convection_term(const FlowPointValues &point, const unsigned int i, const unsigned int j)
    {
      return convection_term(point, i, convected_velocity(point, j));
    }

    /**
     * The mesh motion in the convection of scene full, −(1/τ)(G^m (Y − X^m), v): its matrix part
     * −(1/τ)(G^m Y, v) for the new position Y = @p new_position (a shape function η_j).
     */
    static double
    mesh_motion_term(const FlowPointValues     &point,
                     const unsigned int          i,
                     const dealii::Tensor<1, 3> &new_position,
                     const double                inverse_tau)
    {
      return -(inverse_tau * ((point.old_velocity_gradient * new_position) * point.velocity[i]));
    }

    /// The mesh motion in the convection, its right-hand side −(1/τ)(G^m W, v) with the start W of the mesh
    /// motion: X^m (point.position), or Z − τR when the nodes are carried by the rigid motion R (doc/scheme.md).
    static double
    mesh_motion_term_rhs(const FlowPointValues   &point,
                         const unsigned int       i,
                         const double             inverse_tau,
                         const dealii::Point<3>  &start)
    {
      return -(inverse_tau * ((point.old_velocity_gradient * start) * point.velocity[i]));
    }

    /**
     * The inertia of a step solved in a frame that turns with the angular velocity Ω (the carried frame of the
     * mesh law `reference`): with u = Qũ and v = Qṽ, (1/τ)(u − Q u^m, v) = (1/τ)(ũ − u^m, ṽ) and the frame adds
     * (Ω × ũ, ṽ), whose trial part for φ_j is Ω × φ_j with @p omega = Ω. Exact when the velocity turns with
     * the body.
     */
    static dealii::Tensor<1, 3>
    turned_velocity(const FlowPointValues &point, const unsigned int j, const dealii::Tensor<1, 3> &omega)
    {
      return dealii::cross_product_3d(omega, point.velocity[j]);
    }

    /// Pressure −(p, div_P v).
    static double
    pressure_term(const FlowPointValues &point, const unsigned int i, const unsigned int j)
    {
      return -(point.pressure[j] * point.divergence[i]);
    }

    /// Continuity (div_P u, q) = (s, q), assembled as −(div_P u, q) = −(s, q): the matrix part −(div_P u, q).
    static double
    continuity_term(const FlowPointValues &point, const unsigned int i, const unsigned int j)
    {
      return -(point.pressure[i] * point.divergence[j]);
    }

    /// Continuity, the right-hand side −(s, q) of the area rate s = @p area_rate.
    static double
    continuity_term_rhs(const FlowPointValues &point, const unsigned int i, const double area_rate)
    {
      return -(area_rate * point.pressure[i]);
    }

    // The entries of `subsection flow`, set by parse_parameters().
    double Re{};                          ///< Reynolds number Re = ρUL/μ
    bool   inertia{};                     ///< ∂_t u is assembled (false: the Stokes limit)
    bool   convection{};                  ///< the convection ∇_w u is assembled (only with inertia)
    bool   conserve_momenta{};            ///< scene full: multipliers keep ∫u and ∫x × u (only with inertia)
    double rigid_motion_regularization{}; ///< scene full, Stokes limit: ε of ε(u, v)
    double grad_div{};                    ///< scene full: γ_gd of the grad-div term γ_gd(div_P u − s, div_P v)
  };
} // namespace FluidSurface

#endif
