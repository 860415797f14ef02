// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/time_stepping/energy_step_controller.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace FluidSurface
{
  EnergyStepController::EnergyStepController(const double       energy_tolerance,
                                             const double       energy_law_tolerance,
                                             const std::string &law_action)
    : energy_tolerance(energy_tolerance)
    , energy_law_tolerance(energy_law_tolerance)
    , law_action(law_action == "stop" ? LawAction::stop : law_action == "count" ? LawAction::count : LawAction::retry)
  {}

  bool
  EnergyStepController::acceptable(const double old_energy, const double new_energy, const double tau) const
  {
    // The 1e-9 floor is the level at which F is computed reliably (solver and quadrature rounding).
    return std::isfinite(new_energy) &&
           new_energy <= old_energy + (energy_tolerance * tau + 1e-9) * std::abs(old_energy);
  }

  EnergyStepController::Decision
  EnergyStepController::decide(const double old_energy, const double new_energy, const double tau, const double dissipation)
  {
    Decision decision;
    decision.rise     = new_energy - old_energy;
    const double rise = decision.rise;
    // B = F + ∫D over the step, with ∫D by the step's own dissipation τD^{m+1}. That rectangle rule is off by at
    // most τ|D^{m+1} − D^m| while D is monotone in the step, and BDF2 keeps its energy law in its G-norm, not in F:
    // the bound allows twice the rule's error (large only in fast transients; doc/scheme.md, "The discrete energy
    // law") and ε_L τ|F|, above the rounding of F (1e-9|F|, as in acceptable()).
    const double law_rise  = rise + tau * dissipation;
    const double law_bound = 2 * tau * std::abs(dissipation - last_dissipation) +
                             (energy_law_tolerance * tau + 1e-9) * std::abs(old_energy);
    const bool   breaks_law = !(law_rise <= law_bound);
    const bool   judge_law  = law_action != LawAction::count;
    // The rise the controller judges: of F + ∫D when the law acts, of F otherwise.
    const double judged_rise = judge_law ? law_rise : rise;
    decision.law_rise        = law_rise;
    // A break no faster than twice the last one that halving τ showed to be a space error is one too: it is
    // accepted without a retry (a persistent space error, as the plateau of a rigid rotation on a coarse mesh,
    // would otherwise cost a rejection per step).
    const bool known_space_error = judge_law && breaks_law && space_law_rate > 0 && law_rise / tau <= 2 * space_law_rate;
    if (!acceptable(old_energy, new_energy, tau) || (judge_law && breaks_law && !known_space_error))
      {
        // A rise whose rate rise/τ does not fall when τ is halved is a space-discretization
        // effect that no step size removes: accept it and count it, unless it exceeds 1e-3 F
        // in one step (then the run stops once τ < τ_min).
        const double rate = judged_rise / tau;
        if (!(std::isfinite(rise) && previous_rate > 0 && rate > 0.5 * previous_rate &&
              rise < 1e-3 * std::abs(old_energy)))
          {
            if (previous_rate == 0)
              tau_before_rejections = tau;
            previous_rate = rate;
            std::ostringstream reason;
            // A step that blew up gets 4 digits: they are all of it that does not depend on rounding.
            const bool blown_up = !(std::abs(rise) < std::abs(old_energy));
            reason << "energy " << std::setprecision(10) << old_energy << " → " << std::setprecision(blown_up ? 4 : 10)
                   << new_energy;
            if (judge_law && breaks_law && !blown_up)
              reason << ", F + ∫D rose by " << std::setprecision(3) << law_rise << " > " << law_bound;
            decision.verdict  = Verdict::reject;
            decision.reason   = reason.str();
            decision.law_only = acceptable(old_energy, new_energy, tau);
            return decision;
          }
        if (law_action == LawAction::stop && breaks_law)
          {
            std::ostringstream reason;
            reason << "F + ∫D rose by " << std::setprecision(3) << law_rise << " > " << law_bound
                   << " at a rate that did not fall when τ was halved (space discretization)";
            decision.verdict = Verdict::stop;
            decision.reason  = reason.str();
            return decision;
          }
        if (judge_law && breaks_law)
          space_law_rate = law_rise / tau;
        ++n_energy_rises;
        decision.verdict   = Verdict::accept_with_warning;
        decision.step_size = tau_before_rejections;
      }
    else if (previous_rate > 0 && judged_rise > 0 && judged_rise / tau > 0.5 * previous_rate)
      {
        // The retry after a rejection passed, but its rise rate hardly fell with τ: the rejection
        // did not remove a time-step error, so τ returns to its value before the rejections (otherwise
        // a steady rise rate just below the tolerance shrinks τ towards τ_min, one rejection at a time).
        // The retry may pass only because its smaller rise fell under the bound's rounding floor: the
        // break's rate is then a known space error too.
        decision.step_size = tau_before_rejections;
        if (judge_law)
          space_law_rate = std::max(space_law_rate, previous_rate);
      }
    previous_rate       = 0;
    slowed_bending_rate = 0;
    max_law_rise_rate = std::max(max_law_rise_rate, law_rise / (tau * std::abs(old_energy)));
    // A kept step forgets the space error only once its rate has clearly fallen: near the rounding floor of the
    // bound a persistent space error flips between kept and breaking steps, and each forgetting would cost a retry.
    if (breaks_law)
      ++n_law_breaking_steps;
    else if (law_rise / tau <= 0.5 * space_law_rate)
      space_law_rate = 0;
    last_dissipation = dissipation;
    if (rise > 1e-11 * std::abs(old_energy)) // above the rounding of F
      {
        ++n_rising_steps;
        max_rise_rate = std::max(max_rise_rate, rise / (tau * std::abs(old_energy)));
      }
    return decision;
  }

  bool
  EnergyStepController::wants_mesh_slowdown(const double bending_defect, const double tau, const double law_rise)
  {
    if (law_action != LawAction::retry || !std::isfinite(bending_defect))
      return false;
    const double rate = bending_defect / tau;
    if (slowed_bending_rate > 0 && rate > 0.5 * slowed_bending_rate)
      futile_bending_rate = std::max(futile_bending_rate, rate);
    if (!(bending_defect > 0.5 * law_rise) || rate <= 2 * futile_bending_rate)
      return false;
    slowed_bending_rate = rate;
    return true;
  }

  void
  EnergyStepController::write_summary(std::ostream &out) const
  {
    out << "energy rises accepted: " << n_energy_rises << '\n';
    out << "steps with rising energy: " << n_rising_steps << '\n';
    out << "max relative energy rise rate: " << std::setprecision(3) << max_rise_rate << '\n';
    out << "steps breaking the energy law: " << n_law_breaking_steps << '\n';
    out << "max relative rise rate of F + ∫D: " << std::setprecision(3) << max_law_rise_rate << '\n';
  }

  void
  EnergyStepController::save(CheckpointData &data) const
  {
    data.set("simulation/previous rate", previous_rate);
    data.set("simulation/tau before rejections", tau_before_rejections);
    data.set("simulation/energy rises", n_energy_rises);
    data.set("simulation/rising steps", n_rising_steps);
    data.set("simulation/max rise rate", max_rise_rate);
    data.set("simulation/law breaking steps", n_law_breaking_steps);
    data.set("simulation/max law rise rate", max_law_rise_rate);
    data.set("simulation/last dissipation", last_dissipation);
    data.set("simulation/space law rate", space_law_rate);
    data.set("simulation/slowed bending rate", slowed_bending_rate);
    data.set("simulation/futile bending rate", futile_bending_rate);
  }

  void
  EnergyStepController::load(const CheckpointData &data)
  {
    previous_rate         = data.get_double("simulation/previous rate");
    tau_before_rejections = data.get_double("simulation/tau before rejections");
    n_energy_rises        = data.get_unsigned("simulation/energy rises");
    n_rising_steps        = data.get_unsigned("simulation/rising steps");
    max_rise_rate         = data.get_double("simulation/max rise rate");
    // Checkpoints written before the count of the energy law have none.
    n_law_breaking_steps = data.has("simulation/law breaking steps") ? data.get_unsigned("simulation/law breaking steps") : 0;
    max_law_rise_rate    = data.has("simulation/max law rise rate") ? data.get_double("simulation/max law rise rate") : 0;
    last_dissipation     = data.has("simulation/last dissipation") ? data.get_double("simulation/last dissipation") : 0;
    space_law_rate       = data.has("simulation/space law rate") ? data.get_double("simulation/space law rate") : 0;
    slowed_bending_rate =
      data.has("simulation/slowed bending rate") ? data.get_double("simulation/slowed bending rate") : 0;
    futile_bending_rate =
      data.has("simulation/futile bending rate") ? data.get_double("simulation/futile bending rate") : 0;
  }
} // namespace FluidSurface
