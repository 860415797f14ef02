// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/io/run_stopped.h>
#include <fluid_surface/time_stepping/time_stepper.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace FluidSurface
{
  using namespace dealii;

  TimeStepper::TimeStepper()
  {
    ParameterHandler prm;
    declare_parameters(prm);
    parse_parameters(prm);
  }

  void
  TimeStepper::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("time stepping");
    prm.declare_entry("end time",
                      "1",
                      RealRange::at_least(0),
                      "End time T ≥ 0 of the run: 0 (the initial state only) or at least τ_min (a shorter first "
                      "step would be below 'minimum time step').");
    prm.declare_entry("time step",
                      "1e-2",
                      RealRange::at_least(1e-12),
                      "Initial time step τ₀ ≥ 1e-12 (with adaptive = true: τ_min ≤ τ₀ ≤ τ_max).");
    prm.declare_entry("adaptive",
                      "true",
                      Patterns::Bool(),
                      "Adapt τ: shrink on rejected steps, grow on easy ones. false: every step is 'time step' (also "
                      "after a resume) and a rejected step stops the run.");
    prm.declare_entry("minimum time step",
                      "1e-7",
                      RealRange::at_least(1e-12),
                      "τ_min ≥ 1e-12, τ_min ≤ τ_max: a run that needs a smaller step stops with an error.");
    prm.declare_entry("maximum time step",
                      "0.05",
                      RealRange::at_least(1e-12),
                      "τ_max ≥ 1e-12: the largest step the controller takes.");
    prm.declare_entry("relaxation end time",
                      "0",
                      RealRange::at_least(0),
                      "t_r ≥ 0: until t_r, τ ≤ 'relaxation maximum time step' τ_r instead of τ_max (τ grows to τ_max "
                      "after t_r by 'growth factor'). For a relaxation whose oscillations a step of τ_max would damp: "
                      "BDF2 damps a mode of frequency ν at the rate ≈ ν⁴τ³/4 (the oblate's breathing, ν ≈ 22, at "
                      "0.014 per unit time with τ = 0.00625 against its own 0.29; doc/scheme.md, \"The breathing "
                      "of the relaxation\"). 0: τ_max throughout.");
    prm.declare_entry("relaxation maximum time step",
                      "0.00625",
                      RealRange::at_least(1e-12),
                      "τ_r ≥ 1e-12, τ_min ≤ τ_r ≤ τ_max: the largest step before 'relaxation end time' t_r.");
    prm.declare_entry("growth factor",
                      "1.25",
                      RealRange::above(1),
                      "Factor > 1 by which τ grows after easy steps (up to τ_max).");
    prm.declare_entry("shrink factor",
                      "0.5",
                      RealRange::open(0, 1),
                      "Factor in (0, 1) by which τ shrinks after a rejected step.");
    prm.declare_entry("easy steps before growth",
                      "5",
                      Patterns::Integer(1),
                      "Number N ≥ 1 of consecutive accepted steps before τ grows.");
    prm.declare_entry("error tolerance",
                      "0",
                      RealRange::closed(0, 1),
                      "ε_t, 0 ≤ ε_t ≤ 1: with ε_t > 0, τ follows a local error estimate e of the step (e = τ²/(τ + "
                      "τ_p) max|w − w^m|/R: the change of the nodes' normal speed w relative to the rigid carry since "
                      "the last step, over the shape's radius R = √(A/4π); doc/scheme.md): a step with e > ε_t is rejected and retried with τ·max(0.2, 0.9 (ε_t/e)^½), an "
                      "accepted one proposes τ·min(2, 0.9 (ε_t/e)^½) for the next, within [τ_min, τ_max]; 'growth "
                      "factor' and 'easy steps before growth' are then not used. The energy check stays on as a guard. "
                      "0: the step grows by 'growth factor' after easy steps.");
    prm.declare_entry("scheme",
                      "backward Euler",
                      Patterns::Selection("backward Euler|BDF2|SDIRK2"),
                      "The time discretization of the flow steps. backward Euler: first order. BDF2: variable-step "
                      "BDF2 (second order, L-stable; ω = τ/τ_p ≤ 2 by the controllers), u* = (1+ω)u^m − ωu^{m−1} "
                      "in the lagged convection; the first step and the first after a re-parametrization are "
                      "backward Euler. SDIRK2: the two-stage L-stable SDIRK method of order 2, γ = 1 − 1/√2, two "
                      "solves per step; it damps a resolved oscillation of frequency ν by (γ⁴/2)(ντ)⁴ per step where "
                      "BDF2 damps it by (ντ)⁴/4; with the linear predictor and the conformal mesh law it is not robust (doc/scheme.md, \"SDIRK2\"). "
                      "BDF2 and SDIRK2 need 'geometry "
                      "iteration/maximum iterations' ≥ 1 and apply = always (a lagged geometry is "
                      "first order; doc/scheme.md, \"Second order in time\").");
    prm.declare_entry("frame",
                      "lab",
                      Patterns::Selection("lab|Tisserand"),
                      "The frame the flow steps are solved in. lab: the lab frame (law reference: the frame of the "
                      "shape's rigid motion, which does not see the spin of a body of revolution). Tisserand: the "
                      "frame that turns with the fluid's rigid angular velocity Ω = I⁻¹L (I the inertia tensor, L the "
                      "angular momentum about the centre of mass), carried exactly over the step, with the frame term "
                      "(Ω × u, v) in the momentum balance and the mesh carried with it: a mode is damped at its "
                      "co-rotating frequency ν, not at its lab frequency ν + mΩ (doc/scheme.md, \"The co-rotating "
                      "step\"). With either scheme.");
    prm.declare_entry("backward Euler steps after rejection",
                      "0",
                      Patterns::Integer(0, 1000),
                      "K, 0 ≤ K ≤ 1000, with scheme = BDF2 or SDIRK2: a step the energy check rejects is retried at the "
                      "same τ as a backward-Euler step (L-stable, no history), and so are the next K accepted steps; "
                      "then the scheme resumes with the history of the last step. A second rejection within them shrinks τ as usual. "
                      "0: a rejected BDF2 step is retried with a smaller τ only (doc/scheme.md, \"Second order in "
                      "time\").");
    prm.declare_entry("energy tolerance",
                      "1e-3",
                      RealRange::at_least(0),
                      "ε_F ≥ 0: a step is rejected when F(t+τ) > F(t) + (ε_F·τ + 10⁻⁹)·|F(t)|, i.e. when the total "
                      "energy rises faster than the relative rate ε_F (a rate, so that it does not shrink with τ: the "
                      "space discretization is not exactly energy-consistent, see doc/scheme.md).");
    prm.declare_entry("energy law tolerance",
                      "1e-6",
                      RealRange::at_least(0),
                      "ε_L ≥ 0: a step breaks the energy law when B = F + ∫D rises in it by more than the error of its "
                      "∫D and ε_L·τ·|F(t)|, i.e. when F(t+τ) − F(t) + τD > 2τ|D − D_prev| + ε_L τ|F(t)| with D the "
                      "dissipation rate of the step's own velocity and D_prev the last step's (doc/scheme.md, \"The "
                      "discrete energy law\"). The default is the relative rate below which `steady state` calls F "
                      "constant.");
    prm.declare_entry("energy law",
                      "count",
                      Patterns::Selection("count|retry|stop"),
                      "What a step that breaks the energy law (`energy law tolerance`) does. count: it is accepted and "
                      "counted (`steps breaking the energy law` in the summary). retry: it is rejected and retried; a step "
                      "whose rise of F + ∫D is more than half bending defect (the discrete W changed by more than the "
                      "bending force's work: the tangential node motion of the mesh law) first at the same τ with the "
                      "mesh law slowed tenfold (up to 1000-fold, decaying as e^{−t/0.5}), any other with "
                      "the same scheme at a smaller τ (the factor of rejected steps; a step whose F also rose too fast "
                      "is retried as such, with the iterated geometry, as backward Euler or with a smaller τ); a break "
                      "whose rate (F(t+τ) − F(t) + τD)/τ did not fall when τ was halved is a space-discretization effect: "
                      "the step is accepted and counted, and so are later breaks no faster than twice it. stop: such a "
                      "break ends the run instead (refine the mesh). retry costs a solve per break (doc/scheme.md, "
                      "\"The discrete energy law\").");
    prm.declare_entry("energy budget",
                      "false",
                      Patterns::Bool(),
                      "Scene full: write the energy budget of every accepted step into the file energy_budget of the "
                      "output directory: W^m, K^m, the powers P = (1/Be)(y ñ, ũ) of the bending force and P_μ of the "
                      "multipliers on the step's velocity, W and K of the solved surface, K after the area and volume "
                      "projection and the final W, K, from which ΔB = ΔF + τD splits into the bending defect ΔW + τP, "
                      "the multipliers' work, the transport's defect and the projections' ΔF (doc/output.md; "
                      "benchmarks/energy_law/budget.py). Costs a curvature solve and three integrals per step.");
    prm.leave_subsection();
  }

  void
  TimeStepper::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("time stepping");
    end_time                  = prm.get_double("end time");
    tau                       = prm.get_double("time step");
    adaptive                  = prm.get_bool("adaptive");
    tau_min                   = prm.get_double("minimum time step");
    tau_max                   = prm.get_double("maximum time step");
    relaxation_end_time       = prm.get_double("relaxation end time");
    relaxation_tau_max        = prm.get_double("relaxation maximum time step");
    growth                    = prm.get_double("growth factor");
    growth_entry              = prm.get("growth factor");
    shrink                    = prm.get_double("shrink factor");
    easy_steps                = prm.get_integer("easy steps before growth");
    relative_energy_tolerance = prm.get_double("energy tolerance");
    relative_energy_law_tolerance = prm.get_double("energy law tolerance");
    law_action                    = prm.get("energy law");
    write_energy_budget           = prm.get_bool("energy budget");
    error_tolerance           = prm.get_double("error tolerance");
    scheme_name = prm.get("scheme");
    frame_kind  = prm.get("frame") == "Tisserand" ? FlowStepFrame::tisserand : FlowStepFrame::lab;
    fallback_steps = prm.get_integer("backward Euler steps after rejection");
    if (error_tolerance > 0 && !adaptive)
      throw_invalid_entry("time stepping/error tolerance",
                          prm.get("error tolerance"),
                          "0 with adaptive = false (a fixed step has nothing to adapt)");
    if (end_time > 0 && end_time < tau_min)
      throw_invalid_entry("time stepping/end time",
                          prm.get("end time"),
                          "0 or at least 'minimum time step' = " + prm.get("minimum time step"));
    if (tau_min > tau_max)
      throw_invalid_entry("time stepping/minimum time step",
                          prm.get("minimum time step"),
                          "a value not larger than 'maximum time step' = " + prm.get("maximum time step"));
    if (relaxation_end_time > 0 && !(tau_min <= relaxation_tau_max && relaxation_tau_max <= tau_max))
      throw_invalid_entry("time stepping/relaxation maximum time step",
                          prm.get("relaxation maximum time step"),
                          "τ_min ≤ τ_r ≤ τ_max = " + prm.get("maximum time step") + " (relaxation end time > 0)");
    if (tau > tau_max && adaptive)
      throw_invalid_entry("time stepping/time step",
                          prm.get("time step"),
                          "τ₀ ≤ 'maximum time step' = " + prm.get("maximum time step") + " (adaptive = true)");
    if (tau < tau_min && adaptive)
      throw_invalid_entry("time stepping/time step",
                          prm.get("time step"),
                          "τ₀ ≥ 'minimum time step' = " + prm.get("minimum time step") + " (adaptive = true)");
    prm.leave_subsection();
    current_time = 0;
    n_accepted = n_rejected = n_easy = 0;
    if (adaptive)
      tau = std::min(tau, largest_step());
  }

  void
  TimeStepper::limit_step_ratio(const double largest_ratio, const std::string &reason) const
  {
    if (growth <= largest_ratio)
      return;
    std::ostringstream expected;
    expected << "a factor ≤ " << largest_ratio << " with scheme = " << scheme_name << " (" << reason << ")";
    throw_invalid_entry("time stepping/growth factor", growth_entry, expected.str());
  }

  TimeStepper::ConstantSteps
  TimeStepper::parse_constant_steps(ParameterHandler &prm, const bool must_step, const std::string &problem)
  {
    ConstantSteps steps;
    prm.enter_subsection("time stepping");
    steps.end_time     = prm.get_double("end time");
    steps.time_step    = prm.get_double("time step");
    const double ratio = std::round(steps.end_time / steps.time_step);
    if (must_step && !(ratio >= 1))
      throw_invalid_entry("time stepping/end time",
                          prm.get("end time"),
                          "at least one time step (T ≥ τ/2, τ = " + prm.get("time step") +
                            ") for the time-dependent problem " + problem);
    if (must_step && !(ratio <= std::numeric_limits<unsigned int>::max()))
      throw_invalid_entry("time stepping/end time",
                          prm.get("end time"),
                          "at most " + std::to_string(std::numeric_limits<unsigned int>::max()) +
                            " time steps of τ = " + prm.get("time step"));
    prm.leave_subsection();
    steps.n_steps = must_step ? static_cast<unsigned int>(ratio) : 0;
    return steps;
  }

  void
  TimeStepper::prescribe_steps(const std::vector<double> &sizes)
  {
    prescribed_steps = sizes;
    adaptive         = false;
    current_time     = 0;
    end_time         = 0;
    for (const double size : sizes)
      end_time += size;
    n_accepted = n_rejected = n_easy = 0;
  }

  double
  TimeStepper::step_size() const
  {
    if (!prescribed_steps.empty())
      return prescribed_steps[n_accepted];
    const double remaining = end_time - current_time;
    // Avoid a sliver of a last step.
    return (remaining < 1.5 * tau) ? (remaining > tau ? 0.5 * remaining : remaining) : tau;
  }

  double
  TimeStepper::error_step_factor(const double error) const
  {
    // Backward Euler's local error is O(τ²).
    if (!(error > 0))
      return 2.0;
    return 0.9 * std::sqrt(error_tolerance / error);
  }

  void
  TimeStepper::accept(const double tau_used, const double error)
  {
    current_time += tau_used;
    if (end_time - current_time < 1e-12 * std::max(1.0, end_time))
      current_time = end_time;
    ++n_accepted;
    if (error_control() && error >= 0)
      {
        // τ_used may be a shortened last step: the proposal grows from the larger of the two.
        set_step_size(std::max(tau, tau_used) * std::min(2.0, error_step_factor(error)));
        return;
      }
    if (adaptive && ++n_easy >= easy_steps)
      {
        tau    = std::min(tau * growth, largest_step());
        n_easy = 0;
      }
  }

  void
  TimeStepper::reject(const std::string &reason, const std::string &advice, const double factor)
  {
    ++n_rejected;
    n_easy = 0;
    const double shrink = factor > 0 ? std::min(factor, this->shrink) : this->shrink;
    if (!adaptive || tau * shrink < tau_min)
      {
        std::ostringstream msg;
        msg << "step " << n_accepted + 1 << " rejected at t = " << current_time << " with τ = " << tau << " ("
            << reason << ")" << (adaptive ? "; τ would fall below 'minimum time step'" : "; 'adaptive' is off");
        throw RunFailed(msg.str(), advice);
      }
    tau *= shrink;
  }

  void
  TimeStepper::save(CheckpointData &data) const
  {
    data.set("time stepping/time", current_time);
    data.set("time stepping/tau", tau);
    data.set("time stepping/steps", n_accepted);
    data.set("time stepping/rejected steps", n_rejected);
    data.set("time stepping/easy steps", n_easy);
  }

  void
  TimeStepper::load(const CheckpointData &data)
  {
    // With adaptive = false the step is the entry 'time step' of this run, whatever the checkpoint's was.
    set_state({data.get_double("time stepping/time"),
               adaptive ? data.get_double("time stepping/tau") : tau,
               data.get_unsigned("time stepping/steps"),
               data.get_unsigned("time stepping/rejected steps"),
               data.get_unsigned("time stepping/easy steps")});
    // A run resumed with a smaller τ_max or τ_r than the one that wrote the checkpoint starts at this run's bound.
    if (adaptive)
      tau = std::min(tau, largest_step());
  }
} // namespace FluidSurface
