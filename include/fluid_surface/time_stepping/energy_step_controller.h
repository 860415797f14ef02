// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_time_stepping_energy_step_controller_h
#define fluid_surface_time_stepping_energy_step_controller_h

#include <optional>
#include <ostream>
#include <string>

namespace FluidSurface
{
  class CheckpointData;

  /**
   * The energy check of a solved step of scene full: the total energy F must
   * not rise faster than the relative rate ε_F (`time stepping/energy
   * tolerance`, see doc/scheme.md). A step that fails the check is rejected
   * and retried with a smaller τ, unless its rise rate rise/τ did not fall
   * when τ was halved: such a rise is a space-discretization effect that no
   * step size removes, so the step is accepted with a warning (if the rise
   * stays below 10⁻³|F|) and τ returns to its value before the rejections.
   * The controller counts these rises and the accepted steps on which F rose
   * at all, for the summary; the counters are part of a checkpoint. The same
   * step is checked against the discrete energy law (decide()): with
   * `time stepping/energy law = retry` a break is rejected like a rise of F,
   * with `stop` a break that halving τ does not reduce ends the run, with
   * `count` breaks are only counted.
   */
  class EnergyStepController
  {
  public:
    /// The three outcomes of the energy check.
    enum class Verdict
    {
      accept,             ///< F did not rise faster than the tolerance
      reject,             ///< retry the step with a smaller τ
      accept_with_warning, ///< a rise that halving τ did not reduce (space discretization)
      stop                 ///< a break of the energy law that halving τ did not reduce, with `energy law = stop`
    };

    /// What to do with a step, and with τ afterwards.
    struct Decision
    {
      Verdict verdict = Verdict::accept;
      /// For Verdict::reject: the energies, for the message of TimeStepper::reject().
      std::string reason;
      /// The energy change F(t+τ) − F(t).
      double rise = 0;
      /// The rise of B = F + ∫D in the step, F(t+τ) − F(t) + τD.
      double law_rise = 0;
      /// If set, the τ to continue with (the τ before the rejections, which did not remove a time-step error).
      std::optional<double> step_size;
      /// For Verdict::reject: F passed its tolerance and only the energy law was broken. Such a step is retried
      /// with the same scheme at a smaller τ (not by the backward-Euler fallback, whose own dissipation would hide
      /// a space error that returns in the next step: the halving is what tells the two kinds apart).
      bool law_only = false;
    };

    /**
     * A controller for the relative energy rise rate @p energy_tolerance ε_F and the energy law with the
     * relative rate @p energy_law_tolerance ε_L, whose breaks are retried, stop the run or are only counted
     * (@p law_action: "retry", "stop", "count"; `time stepping/energy law`).
     */
    explicit EnergyStepController(const double       energy_tolerance     = 0,
                                  const double       energy_law_tolerance = 0,
                                  const std::string &law_action           = "count");

    /**
     * Whether an energy change from @p old_energy to @p new_energy in a step
     * of size @p tau passes the tolerance: F(t+τ) ≤ F(t) + (ε_F τ + 10⁻⁹)|F(t)|.
     */
    bool
    acceptable(const double old_energy, const double new_energy, const double tau) const;

    /**
     * Judges a solved step from @p old_energy to @p new_energy of size @p tau, whose own velocity dissipates at
     * the rate @p dissipation D, and updates the counters; a rejected step is retried by the caller. A step with
     * F(t+τ) − F(t) + τD > 2τ|D − D_prev| + ε_L τ|F(t)| (D_prev: the last accepted step's; the first term bounds
     * the error of τD as the step's ∫D) breaks the energy law: it is rejected (unless the law's action is
     * "count"), and counted once accepted, which it is only when its rate did not fall with τ (or with "count").
     */
    Decision
    decide(const double old_energy, const double new_energy, const double tau, const double dissipation);

    /// The rejected step is retried with the same τ by another scheme: its rise is not evidence of a rise that
    /// does not fall with τ (decide() compares the retry's rise rate with the rejected one's only after τ shrank).
    void
    forget_rejection()
    {
      previous_rate = 0;
    }

    /**
     * With `energy law = retry`: whether the step just rejected, whose F + ∫D rose by @p law_rise in the step of
     * size @p tau with the bending defect @p bending_defect (ΔW beyond the bending force's work), is to be retried
     * with the mesh law slowed down: the defect is more than half the rise, and its rate is more than twice the
     * largest rate that a slowdown did not halve before (then the mesh law does not feed it).
     */
    bool
    wants_mesh_slowdown(const double bending_defect, const double tau, const double law_rise);
    /// The slowdown that wants_mesh_slowdown() asked for was not possible (the largest one reached).
    void
    forget_mesh_slowdown()
    {
      slowed_bending_rate = 0;
    }

    /// Appends the three summary lines (rises accepted, steps with rising energy, largest relative rise rate).
    void
    write_summary(std::ostream &out) const;

    /// Writes the counters into a checkpoint (keys `simulation/previous rate`, …).
    void
    save(CheckpointData &data) const;
    /// Restores the counters from a checkpoint.
    void
    load(const CheckpointData &data);

  private:
    /// `time stepping/energy law`.
    enum class LawAction
    {
      retry,
      stop,
      count
    };

    double    energy_tolerance;
    double    energy_law_tolerance;
    LawAction law_action;

    /// rise/τ of the last rejected step (0 after an accepted one).
    double previous_rate = 0;
    /// τ of the first step of the current run of rejections.
    double tau_before_rejections = 0;
    /// Steps accepted with a warning.
    unsigned int n_energy_rises = 0;
    /// Accepted steps on which F rose above its rounding, and their largest relative rate rise/(τ|F|).
    unsigned int n_rising_steps = 0;
    double       max_rise_rate  = 0;
    /// Accepted steps that broke the energy law, and the largest relative rise rate of B, (ΔF + τD)/(τ|F|).
    unsigned int n_law_breaking_steps = 0;
    double       max_law_rise_rate    = 0;
    /// D of the last accepted step (of the initial state: 0).
    double last_dissipation = 0;
    /// The rate (F(t+τ) − F(t) + τD)/τ of the last break of the energy law accepted as a space error (0 once a step
    /// keeps the law).
    double space_law_rate = 0;
    /// The bending defect's rate of the last step retried with the mesh law slowed down (0 after an accepted step),
    /// and the largest such rate that the slowdown did not halve.
    double slowed_bending_rate = 0, futile_bending_rate = 0;
  };
} // namespace FluidSurface

#endif
