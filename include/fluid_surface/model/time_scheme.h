// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_time_scheme_h
#define fluid_surface_model_time_scheme_h

#include <fluid_surface/geometry/surface_geometry.h>
#include <fluid_surface/model/geometry_iteration.h>
#include <fluid_surface/model/step_frame.h>

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace FluidSurface
{
  class CheckpointData;
  class StepSystem;

  /**
   * The start of a step written in backward-Euler form, (x − x̂)/τ̂ = f(x): the step τ̂, the start x̂ (its u and
   * its position X̂) and the fields whose velocity the convection lags. Refers to fields of the state or of the
   * scheme, valid until the scheme's next start().
   */
  struct StepStart
  {
    double            tau       = 0;       ///< τ̂
    const VectorType *position  = nullptr; ///< X̂ (geometry numbering, ghosted)
    const VectorType *fields    = nullptr; ///< x̂ (flow numbering): û is the u of the inertia
    const VectorType *transport = nullptr; ///< the lagged fields of the convection (flow numbering)
    /// Law reference: the frame velocity R is taken at the new time level (second order) instead of at X̂.
    bool frame_velocity_on_new_surface = false;
    /// Fields whose Y is the new position predicted from the history in the frame of the step
    /// (GeometryIteration::Predictor); nullptr: no prediction (S^m).
    const VectorType *predicted = nullptr;
  };

  /**
   * A time scheme of the flow steps of scene full (`time stepping/scheme`): how a step of size τ from the
   * accepted state is written in backward-Euler form (start()), the history it keeps across accepted steps, in
   * checkpoints too, and its rules: its name, the largest step ratio, whether it needs the geometry of its new
   * time level, its start-up. A new scheme is one more class and one more line in create().
   */
  class TimeScheme
  {
  public:
    /// The largest ratio τ/τ_p of two successive steps a scheme allows, and why.
    struct StepRatioLimit
    {
      double      ratio = std::numeric_limits<double>::infinity(); ///< ∞: any
      std::string reason;
    };
    /// The steps that replace the first step of size τ of a time map (scene stability), and their description.
    struct StartUp
    {
      std::vector<double> steps;
      std::string         description; ///< empty: the first step itself
    };

    /// The scheme named @p name (`time stepping/scheme`: backward Euler, BDF2, SDIRK2), whose predicted
    /// geometry is by @p predictor.
    static std::unique_ptr<TimeScheme>
    create(const std::string &name, const GeometryIteration::Predictor predictor = GeometryIteration::Predictor::linear);

    virtual ~TimeScheme() = default;
    /// Its name in `time stepping/scheme`.
    virtual std::string
    name() const = 0;
    /// The largest step ratio τ/τ_p of its zero-stability (the step controllers must not grow τ faster).
    virtual StepRatioLimit
    step_ratio_limit() const
    {
      return {};
    }
    /// Whether each of its steps needs the geometry of the new time level (a lagged geometry is first order):
    /// `geometry iteration/maximum iterations` ≥ 1 with apply = always and time level = 1.
    virtual bool
    needs_new_level_geometry() const
    {
      return true;
    }
    /// The steps a time map from a state without history starts with, in place of its first step of size @p tau.
    virtual StartUp
    start_up(const double tau) const
    {
      return {{tau}, ""};
    }
    /**
     * The start of a step of size @p tau from X^m = @p old_position and x^m = @p old_fields, i.e. of its first
     * stage, in the frame @p frame of the step: the history is carried into it when the step is solved there.
     */
    virtual StepStart
    start(const VectorType &old_position,
          const VectorType &old_fields,
          const StepSystem &system,
          const StepFrame  &frame,
          const double      tau) = 0;
    /// The number of solves (stages) of the step that start() began, each written in backward-Euler form.
    virtual unsigned int
    n_stages() const
    {
      return 1;
    }
    /// The time c_s τ at which stage @p stage of the step of size @p tau ends: the frame of its solve and the
    /// time of its momentum targets.
    virtual double
    stage_time(const unsigned int /*stage*/, const double tau) const
    {
      return tau;
    }
    /**
     * Stage @p stage ≥ 1 of the step of size @p tau begun by start(), from @p stage_fields, the solution of the
     * stage before in the frame of the step (not carried out of it, not projected).
     */
    virtual StepStart
    next_stage(const unsigned int stage,
               const VectorType  &stage_fields,
               const StepSystem  &system,
               const StepFrame   &frame,
               const double       tau);
    /// The step of size @p tau from the accepted fields @p old_fields was accepted (called before they move on).
    virtual void
    accept(const VectorType &, const StepSystem &, const double)
    {}
    /// The next step starts afresh (the state jumped: a re-parametrization, a restart).
    virtual void
    forget_history()
    {}
    /// After a rejected step: the retry and the next @p steps accepted steps are backward-Euler steps (BDF2; the
    /// others are backward Euler already). Returns whether it started them (not if they are under way).
    virtual bool
    fall_back_to_backward_euler(const unsigned int)
    {
      return false;
    }
    /// Writes the history into a checkpoint. Collective.
    virtual void
    save(CheckpointData &, const StepSystem &) const
    {}
    /// Reads it, if the checkpoint has it.
    virtual void
    load(const CheckpointData &, const StepSystem &)
    {}
  };

  /// Backward Euler: x̂ = x^m, τ̂ = τ; no history.
  class BackwardEuler : public TimeScheme
  {
  public:
    std::string
    name() const override
    {
      return "backward Euler";
    }
    bool
    needs_new_level_geometry() const override
    {
      return false;
    }
    StepStart
    start(const VectorType &old_position,
          const VectorType &old_fields,
          const StepSystem &system,
          const StepFrame  &frame,
          const double      tau) override;
  };

  /**
   * A scheme that keeps the previous accepted state x^{m−1} and the step τ_p that followed it (checkpoint keys
   * `model/previous step`, `previous state`), for its extrapolations to the new time level: the lagged convection
   * and the predicted geometry. Its steps are backward-Euler steps where there is no history (the first step,
   * after a jump of the state) and after a rejection (fall_back_to_backward_euler()).
   */
  class PreviousStateScheme : public TimeScheme
  {
  public:
    void
    accept(const VectorType &old_fields, const StepSystem &system, const double tau) override;
    void
    forget_history() override
    {
      previous_step = 0;
    }
    bool
    fall_back_to_backward_euler(const unsigned int steps) override
    {
      if (backward_euler_steps > 0)
        return false;
      backward_euler_steps = steps + 1; // the retry and the next `steps`
      return true;
    }
    void
    save(CheckpointData &data, const StepSystem &system) const override;
    void
    load(const CheckpointData &data, const StepSystem &system) override;

  protected:
    /// Whether the step under way is a backward-Euler step (no history, or after a rejection).
    bool
    backward_euler_step() const
    {
      return previous_step == 0 || falling_back();
    }
    /// Whether the step under way is one of the backward-Euler steps after a rejection.
    bool
    falling_back() const
    {
      return backward_euler_steps > 0;
    }
    /// x̃^{m−1}: the previous state in the frame of the step (solved in a frame: frame coordinates at t^m − τ_p,
    /// i.e. carried forward by τ_p; otherwise the previous state itself). Owned.
    VectorType
    previous_in_frame(const StepSystem &system, const StepFrame &frame) const;
    /// The linear extrapolation x^m + (θ/τ_p)(x^m − x̃^{m−1}) of @p old_fields and @p previous to t^m + θ. Owned.
    VectorType
    extrapolation(const VectorType &old_fields, const VectorType &previous, const StepSystem &system, const double theta) const;

    /**
     * The step from x̂ = @p start with the convection lagged at @p lagged, in backward-Euler form of size
     * @p tau_hat: X̂ is the new position of x̂; all three are kept (ghosted) until the next call. StepStart's
     * frame velocity is taken on the new surface, and there is no prediction.
     */
    StepStart
    backward_euler_form(const VectorType &start, const VectorType &lagged, const StepSystem &system, const double tau_hat);

    BackwardEuler first_step;
    /// x^{m−1} (flow numbering, ghosted) and the step τ_p that followed it; τ_p = 0: none.
    VectorType previous_solution;
    double     previous_step = 0;
    /// x̂ and u* of the step or stage under way, ghosted; X̂ in the geometry numbering (backward_euler_form()).
    VectorType start_fields, lagged_fields, start_position;

  private:
    /// Steps left that are taken as backward-Euler steps after a rejection (fall_back_to_backward_euler()).
    unsigned int backward_euler_steps = 0;
  };

  /**
   * Variable-step BDF2 after a first backward-Euler step (and after each jump of the state), ω = τ/τ_p:
   * (α₀x − (1+ω)x^m + ω²/(1+ω)x^{m−1})/τ = f, α₀ = (1+2ω)/(1+ω), i.e. the backward-Euler form of size τ/α₀ from
   * x̂ = ((1+ω)x^m − ω²/(1+ω)x^{m−1})/α₀, with the convection lagged at u* = (1+ω)u^m − ωu^{m−1}. For a quadratic
   * predictor it keeps x^{m−2} and τ_pp too (`model/earlier step`, `earlier state`).
   */
  class VariableBDF2 : public PreviousStateScheme
  {
  public:
    /// BDF2 whose StepStart::predicted is by @p predictor.
    explicit VariableBDF2(const GeometryIteration::Predictor predictor)
      : predictor(predictor)
    {}

    std::string
    name() const override
    {
      return "BDF2";
    }
    StepRatioLimit
    step_ratio_limit() const override
    {
      return {2, "variable-step BDF2 is zero-stable for τ/τ_p < 1 + √2"};
    }
    /**
     * BDF2 starts with a backward-Euler step, whose damping of the fields turning through the nodes (at mω) would
     * bias a time map's growth rate by ln|1 − imωτ|/T; the ramp τ/8, τ/8, τ/4, τ/2 (step ratios ≤ 2, within
     * BDF2's zero-stability) makes that first step short.
     */
    StartUp
    start_up(const double tau) const override
    {
      return {{tau / 8, tau / 8, tau / 4, tau / 2}, "the first in four, τ/8 to τ/2"};
    }
    StepStart
    start(const VectorType &old_position,
          const VectorType &old_fields,
          const StepSystem &system,
          const StepFrame  &frame,
          const double      tau) override;
    void
    accept(const VectorType &old_fields, const StepSystem &system, const double tau) override;
    void
    forget_history() override
    {
      PreviousStateScheme::forget_history();
      earlier_step = 0;
    }
    void
    save(CheckpointData &data, const StepSystem &system) const override;
    void
    load(const CheckpointData &data, const StepSystem &system) override;

  private:
    /// Whether the predictor needs x^{m−2}.
    bool
    quadratic_predictor() const
    {
      return predictor == GeometryIteration::Predictor::quadratic_normal;
    }
    /// The quadratic-normal predictor through x^m = @p old_fields, x^{m−1}, x^{m−2}, the latter carried into the
    /// frame of the step; @p linear is the linear one.
    const VectorType &
    quadratic_prediction(const VectorType &old_fields,
                         const VectorType &previous,
                         const VectorType &linear,
                         const StepSystem &system,
                         const StepFrame  &frame,
                         const double      tau);

    GeometryIteration::Predictor predictor;
    /// x^{m−2} and the step τ_pp that followed it (quadratic predictors only); τ_pp = 0: none.
    VectorType earlier_solution;
    double     earlier_step = 0;
    /// The quadratic prediction of x^{m+1} (StepStart::predicted), ghosted.
    VectorType quadratic_fields;
  };

  /**
   * The two-stage, stiffly accurate SDIRK method of order 2 (Alexander 1977), γ = 1 − 1/√2, as two
   * backward-Euler solves of size γτ: Y₁ from x^m, then x^{m+1} from x̂₂ = x^m + ((1−γ)/γ)(Y₁ − x^m). L-stable like
   * BDF2, but a resolved oscillation λ = iν loses only (γ⁴/2)(ντ)⁴ of its amplitude per step, against BDF2's
   * (ντ)⁴/4 (doc/scheme.md, "SDIRK2"). The convection of stage s is lagged at u* = x^m + (c_sτ/τ_p)(x^m − x̃^{m−1}),
   * c₁ = γ, c₂ = 1, and so is the predicted geometry (second order); the solution of stage 1 replaces the
   * extrapolation where there is no history.
   */
  class SDIRK2 : public PreviousStateScheme
  {
  public:
    /// SDIRK2 whose StepStart::predicted is by @p predictor (linear or old surface).
    explicit SDIRK2(const GeometryIteration::Predictor predictor)
      : predictor(predictor)
    {}

    std::string
    name() const override
    {
      return "SDIRK2";
    }
    StepStart
    start(const VectorType &old_position,
          const VectorType &old_fields,
          const StepSystem &system,
          const StepFrame  &frame,
          const double      tau) override;
    unsigned int
    n_stages() const override
    {
      return stages;
    }
    double
    stage_time(const unsigned int stage, const double tau) const override
    {
      return stage == 0 && stages == 2 ? gamma * tau : tau;
    }
    StepStart
    next_stage(const unsigned int stage,
               const VectorType  &stage_fields,
               const StepSystem  &system,
               const StepFrame   &frame,
               const double       tau) override;

    /// γ = 1 − 1/√2.
    static const double gamma;

  private:
    GeometryIteration::Predictor predictor;
    /// The stages of the step under way (1: a backward-Euler step).
    unsigned int stages = 1;
    /// x^m of the step under way, ghosted, and x̃^{m−1} (only with history), owned.
    VectorType old_solution, previous;
  };
} // namespace FluidSurface

#endif
