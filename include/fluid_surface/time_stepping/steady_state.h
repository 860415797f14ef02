// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_time_stepping_steady_state_h
#define fluid_surface_time_stepping_steady_state_h

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>
#include <vector>

namespace FluidSurface
{
  class CheckpointData;

  /**
   * When a run of scene full has reached its end state (`subsection steady
   * state`): the total energy F is flat over the window T_w,
   * |F(t) − F(t − T_w)| < δ T_w |F(t)|, and the motion is the one a terminal
   * state must have. Without external torque the angular momentum L is
   * conserved and the kinetic energy K ≥ |L|²/(2λ₃) (λ₃ the largest inertia
   * eigenvalue), with equality only for a rigid rotation about the axis of
   * largest inertia; the excess K − |L|²/(2λ₃) < ε_K |F| is required too,
   * and the shape must be at rest: each inertia eigenvalue changes by less
   * than δ T_w λ₃ over the window. A flat F alone also holds in a metastable
   * rotating state: the prolate spinning about its long axis before its
   * symmetry breaks (its excess is of the order of K), or the oblate spinning
   * about its short axis, its axis of largest inertia, while its symmetry
   * deviation e(λ) grows exponentially from 1e-5 (caught by the eigenvalues,
   * as long as e(λ) grows by more than δ per unit time). A seed of 1e-6 grows
   * more slowly than δ = 1e-6 catches: the gap g = min(λ₂ − λ₁, λ₃ − λ₂)/λ₃
   * of the two closest eigenvalues must also not grow faster than σ_s,
   * ln(g(t)/g(t − T_w))/T_w < σ_s, once g(t − T_w) is above the rounding of
   * the eigenvalues: a growing mode that breaks the symmetry of a body of
   * revolution makes the state a saddle, not an end state (issue 49). Last,
   * an end state of a dissipative flow dissipates nothing: the flow must
   * dissipate less than δ|F| per unit time over the window, ∫D < δ T_w |F|.
   * A state that meets every other test while D is larger is a plateau if F
   * falls by less than half of what the flow dissipated over the window,
   * −ΔF < ½∫D: F stays flat only because the discretization supplies more
   * than half of what the flow dissipates (on coarse meshes, doc/scheme.md, "The discrete
   * energy law"), so the run stops there and says so instead of calling it
   * an end state. If F falls by more, the state is still relaxing with the
   * energy law kept to within half of D, and the run goes on.
   * The samples inside the window are part of a checkpoint.
   */
  class SteadyState
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Whether the check is on (δ > 0).
    bool
    enabled() const
    {
      return rate_tolerance > 0;
    }

    /// What the check samples of a state.
    struct Sample
    {
      double time, total_energy;
      /// The inertia eigenvalues λ₁ ≤ λ₂ ≤ λ₃.
      std::array<double, 3> inertia;
      /// ∫₀ᵗ D, the sum of τD^{m+1} over the accepted steps (set by assess()).
      double dissipated = 0;
    };

    /// What assess() finds.
    enum class Verdict
    {
      running, ///< not yet an end state
      reached, ///< an end state: every test passes
      plateau  ///< every test but the dissipation's passes, and F falls by less than half of ∫D over the window
    };

    /**
     * Records the accepted state @p sample, reached by a step of size @p tau whose flow dissipates at the rate
     * @p dissipation_rate, with kinetic energy excess @p kinetic_excess = K − |L|²/(2λ₃).
     */
    Verdict
    assess(Sample sample, const double kinetic_excess, const double tau, const double dissipation_rate);

    /**
     * Forgets the samples: the window starts again at the next assess(). After the state was displaced along the
     * falling mode of a saddle (EndStateStability), the gap of the inertia eigenvalues must from then on grow no
     * faster than δ instead of σ_s: the mode of a shallow saddle can grow more slowly than σ_s, and the window right
     * after the displacement holds its transient (the resting discocyte of v = 0.75 at refinement 4: the gap grew at
     * 1.1e-3 over that window, and the state was called an end state).
     */
    void
    restart_after_saddle()
    {
      samples.clear();
      left_saddle = true;
    }

    /// The measures of the last assess() as one line, for the screen and the summary.
    std::string
    description() const;

    void
    save(CheckpointData &data) const;
    void
    load(const CheckpointData &data);

  private:
    /// The largest growth rate of the eigenvalues' gap of an end state: σ_s, or δ once a saddle was left.
    double
    gap_growth_limit() const;

    double rate_tolerance     = 0;
    double window                    = 1;
    double kinetic_excess_tolerance  = 1e-4;
    double last_energy_rate          = 0;
    double last_inertia_rate         = 0;
    double last_kinetic_excess       = 0;
    double gap_growth_tolerance      = 0.01;
    double last_gap_growth           = 0;
    double last_dissipation          = 0;
    double last_law_fraction         = 0; ///< −ΔF/∫D over the window
    /// Whether the run has left a saddle (restart_after_saddle(); kept in checkpoints).
    bool left_saddle = false;
    /// ∫₀ᵗ D of the accepted steps so far.
    double dissipated = 0;
    /// At least T_w/20 apart, the oldest at or before t − T_w.
    std::vector<Sample> samples;
  };
} // namespace FluidSurface

#endif
