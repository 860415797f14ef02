// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_time_stepping_time_stepper_h
#define fluid_surface_time_stepping_time_stepper_h

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <string>
#include <vector>

namespace FluidSurface
{
  class CheckpointData;

  /// The frames of `time stepping/frame` the flow steps are solved in (StepFrame).
  enum class FlowStepFrame
  {
    lab,      ///< the lab frame (law reference: the frame of the shape's rigid motion)
    tisserand ///< the frame that turns with the fluid's rigid motion Ω = I⁻¹L
  };

  /**
   * Time and step size τ of a run (`subsection time stepping`): a rejected
   * step (its solve failed, or EnergyStepController rejected its energy) is
   * retried with τ·shrink; after a number of easy steps τ grows by a factor,
   * up to τ_max.
   */
  class TimeStepper
  {
  public:
    /// A stepper with the declared defaults of every entry.
    TimeStepper();

    /// Declares `subsection time stepping`.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Reads it (InputError if τ_min > τ_max, or τ₀ > τ_max with adaptive τ) and starts at t = 0.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// The constant steps of a run that reads only `end time` T and `time step` τ (scene fixed surface).
    struct ConstantSteps
    {
      double       end_time  = 0; ///< T
      double       time_step = 0; ///< τ
      unsigned int n_steps   = 0; ///< round(T/τ)
    };
    /**
     * Reads `end time` and `time step` of `subsection time stepping` (none of its adaptive entries). With
     * @p must_step, InputError unless 1 ≤ round(T/τ) fits an unsigned int; @p problem names the run in the message.
     */
    static ConstantSteps
    parse_constant_steps(dealii::ParameterHandler &prm, const bool must_step, const std::string &problem);

    /// The time t of the current (accepted) state.
    double
    time() const
    {
      return current_time;
    }
    /// τ for the next attempt (never past the end time).
    double
    step_size() const;
    /// The number of accepted steps.
    unsigned int
    step_number() const
    {
      return n_accepted;
    }
    /// The number of rejected step attempts.
    unsigned int
    n_rejected_steps() const
    {
      return n_rejected;
    }
    /// Whether t has not reached the end time T (to rounding).
    bool
    before_end() const
    {
      return prescribed_steps.empty() ? current_time < end_time * (1 - 1e-12) : n_accepted < prescribed_steps.size();
    }
    /// The end time T.
    double
    final_time() const
    {
      return end_time;
    }

    /// τ_max of `maximum time step`.
    double
    maximum_step_size() const
    {
      return tau_max;
    }

    /// ε_F of `energy tolerance`: the largest relative rate at which the total energy may rise.
    double
    energy_tolerance() const
    {
      return relative_energy_tolerance;
    }
    /// ε_L of `energy law tolerance`: the largest relative rate at which B = F + ∫D may rise unnoticed.
    double
    energy_law_tolerance() const
    {
      return relative_energy_law_tolerance;
    }

    /// What a step that breaks the energy law does (`energy law`): "count", "retry" or "stop".
    const std::string &
    energy_law_action() const
    {
      return law_action;
    }

    /// Whether scene full writes the split of each step's energy change into `energy_budget` (`energy budget`).
    bool
    energy_budget() const
    {
      return write_energy_budget;
    }

    /**
     * Advances time by the τ just used. With error control (error_control()) and an @p error estimate e ≥ 0 of
     * the step, the next τ is τ·min(2, 0.9 (ε_t/e)^½); otherwise τ grows by the growth factor after enough easy
     * steps.
     */
    void
    accept(const double tau_used, const double error = -1);
    /// Whether τ follows a local error estimate (`error tolerance` ε_t > 0).
    bool
    error_control() const
    {
      return error_tolerance > 0;
    }
    /**
     * From t = 0, the steps @p sizes and no others (a time map of scene stability): step_size() is the next of
     * them, and a rejected step ends the run (RunFailed), as with `adaptive = false`.
     */
    void
    prescribe_steps(const std::vector<double> &sizes);
    /// The name of the time scheme of the flow steps (`scheme`; TimeScheme::create()).
    const std::string &
    scheme() const
    {
      return scheme_name;
    }
    /// The frame of the flow steps (`frame`).
    FlowStepFrame
    frame() const
    {
      return frame_kind;
    }
    /**
     * The scheme's zero-stability bounds the ratio of successive steps by @p largest_ratio (for @p reason):
     * an input error if `growth factor` exceeds it.
     */
    void
    limit_step_ratio(const double largest_ratio, const std::string &reason) const;
    /// K of `backward Euler steps after rejection` (BDF2 only; 0: off).
    unsigned int
    backward_euler_steps_after_rejection() const
    {
      return fallback_steps;
    }
    /// ε_t of `error tolerance`.
    double
    error_bound() const
    {
      return error_tolerance;
    }
    /// The factor 0.9 (ε_t/e)^½ by which a step with the error estimate @p error changes τ (2 for e = 0).
    double
    error_step_factor(const double error) const;

    /// Sets τ for the next step (clipped to [τ_min, largest_step()]).
    void
    set_step_size(const double new_tau)
    {
      tau = std::min(std::max(new_tau, tau_min), largest_step());
    }

    /// The largest step at the current time: τ_r of `relaxation maximum time step` before t_r, else τ_max.
    double
    largest_step() const
    {
      return current_time < relaxation_end_time ? relaxation_tau_max : tau_max;
    }

    /**
     * Shrinks τ after a rejected step, by the shrink factor, or by @p factor when it is positive and smaller. When τ would fall below τ_min (or adaptive is off) the run cannot go
     * on: throws RunFailed, whose reason names the step, t, τ and @p reason, followed by @p advice.
     */
    void
    reject(const std::string &reason, const std::string &advice, const double factor = 0);

    /// Counts a rejected step that is retried with the same τ by another scheme (`geometry iteration/apply =
    /// after rejection`); τ and the run go on.
    void
    repeat_step()
    {
      ++n_rejected;
      n_easy = 0;
    }

    /// The state a checkpoint needs to continue bit for bit.
    struct State
    {
      double       time;
      double       tau;
      unsigned int n_accepted;
      unsigned int n_rejected;
      unsigned int n_easy;
    };
    State
    state() const
    {
      return {current_time, tau, n_accepted, n_rejected, n_easy};
    }
    void
    set_state(const State &s)
    {
      current_time = s.time;
      tau          = s.tau;
      n_accepted   = s.n_accepted;
      n_rejected   = s.n_rejected;
      n_easy       = s.n_easy;
    }

    /// Writes time, τ and the controller counters into a checkpoint (keys `time stepping/…`).
    void
    save(CheckpointData &data) const;
    /// Continues from a checkpoint; the end time and the controller parameters stay those of the prm.
    void
    load(const CheckpointData &data);

  private:
    // The parameters; their defaults are those of declare_parameters(), set by the constructor.
    double       end_time;
    double       tau; ///< τ for the next step
    double       tau_min;
    double       tau_max;
    double       relaxation_end_time = 0; ///< t_r of `relaxation end time`
    double       relaxation_tau_max  = 0; ///< τ_r of `relaxation maximum time step`
    double       growth;
    std::string  growth_entry = "2"; ///< `growth factor` as the file writes it (for the message of limit_step_ratio())
    double       shrink;
    unsigned int easy_steps;
    double       relative_energy_tolerance;
    double       relative_energy_law_tolerance = 1e-6;
    std::string  law_action = "count"; ///< `energy law`
    bool         write_energy_budget = false; ///< `energy budget`
    double       error_tolerance = 0; ///< ε_t; 0: no error control
    unsigned int fallback_steps  = 0; ///< K of `backward Euler steps after rejection`
    std::string   scheme_name = "backward Euler";   ///< `scheme`
    FlowStepFrame frame_kind  = FlowStepFrame::lab; ///< `frame`
    bool         adaptive;
    std::vector<double> prescribed_steps; ///< prescribe_steps(); empty: the steps follow from the entries

    double       current_time = 0;
    unsigned int n_accepted   = 0;
    unsigned int n_rejected   = 0;
    unsigned int n_easy       = 0;
  };
} // namespace FluidSurface

#endif
