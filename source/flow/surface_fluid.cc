// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/flow/surface_fluid.h>
#include <fluid_surface/io/parameter_file.h>

namespace FluidSurface
{
  using namespace dealii;

  void
  SurfaceFluid::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("flow");
    prm.declare_entry("Re",
                      "1",
                      RealRange::closed(1e-6, 1e6),
                      "Reynolds number Re = ρUL/μ, 1e-6 ≤ Re ≤ 1e6; the viscous stress is (2/Re)σ(u). (The model is "
                      "scaled with U and L of order 1; for Re → 0 use inertia = false, the Stokes limit.)");
    prm.declare_entry("inertia",
                      "true",
                      Patterns::Bool(),
                      "Time derivative ∂_t u on (Navier–Stokes or time-dependent Stokes) or off (the Stokes "
                      "limit: the mass and convection terms are not assembled; scene fixed surface solves the "
                      "stationary problems, scene full the quasi-static flow driven by bending).");
    prm.declare_entry("convection",
                      "true",
                      Patterns::Bool(),
                      "Convection ∇_w u on or off (with inertia only). Scene full: the consistent form "
                      "(G u, v) − (1/τ)(G^m (Y − X^m), v), G = ∇_C u, i.e. w = u^m − (Y − X^m)/τ, the velocity "
                      "relative to the moving mesh (not skew-symmetrized, which is inconsistent on a deforming "
                      "surface; doc/scheme.md). Scene fixed surface: the skew-symmetric form "
                      "½[(∇_w u, v) − (∇_w v, u)] with w extrapolated from the old steps (energy neutral on the "
                      "fixed surface).");
    prm.declare_entry("conserve momenta",
                      "false",
                      Patterns::Bool(),
                      "Scene full with inertia: keep the linear and angular momenta ∫u = P₀ and ∫x × u = L₀ (about "
                      "the origin, P₀ and L₀ of the initial state) at every step by six global multipliers μ_k, "
                      "force Σμ_k r_k for the rigid motions r = e_d, e_d × x (the same columns as the Stokes "
                      "limit). The continuous model conserves both exactly; without the multipliers the "
                      "discrete model loses angular momentum while the shape deforms fast (the prolate "
                      "equilibrium perturbed by 2e-2, refinement 3: 11 % of L by the time F has fallen by 10 % "
                      "with τ ≤ 0.05, still 8 % with τ ≤ 0.0125: mostly a space-discretization error). |μ| is "
                      "the statistics column 'rigid multiplier'.");
    prm.declare_entry("grad-div stabilization",
                      "0",
                      RealRange::closed(0, 1e6),
                      "Scene full: γ_gd ≥ 0 of the grad-div term γ_gd(div_P u − s, div_P v) on the momentum rows (s the "
                      "area rate of the continuity row). Consistent (the exact flow has div_P u = s) and dissipative: "
                      "it adds γ_gd‖div_P u − s‖² to the dissipation rate D, which the statistics and the energy law "
                      "then include. It damps the discrete velocity that the Q1 pressure does not see, i.e. the "
                      "parasitic currents of a body at rest or in rigid rotation (doc/scheme.md, \"Grad-div "
                      "stabilization\"). 0: off.");
    prm.declare_entry("rigid motion regularization",
                      "1e-6",
                      RealRange::closed(0, 1),
                      "Scene full with inertia = false (Stokes limit): ε, 0 ≤ ε ≤ 1 (ε ≥ 1e-12 when inertia = false), of the term ε(u, v) that makes the "
                      "step matrix invertible on the rigid motions (translations and rotations dissipate "
                      "nothing and, without the mass term, nothing else fixes them). Their amplitude is "
                      "then set exactly by the multipliers of ∫u = 0 and ∫x × u = 0; ε only adds the "
                      "dissipation ε‖u‖² to the other modes (relative size ε·Re/2).");
    prm.leave_subsection();
  }

  void
  SurfaceFluid::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("flow");
    Re                          = prm.get_double("Re");
    inertia                     = prm.get_bool("inertia");
    convection                  = prm.get_bool("convection") && inertia;
    conserve_momenta            = prm.get_bool("conserve momenta") && inertia;
    rigid_motion_regularization = prm.get_double("rigid motion regularization");
    grad_div                    = prm.get_double("grad-div stabilization");
    if (!inertia && !(rigid_motion_regularization >= 1e-12))
      throw_invalid_entry("flow/rigid motion regularization",
                          prm.get("rigid motion regularization"),
                          "ε ≥ 1e-12 when inertia = false (the step matrix is singular on rigid motions otherwise)");
    prm.leave_subsection();
  }
} // namespace FluidSurface
