// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_local_error_estimate_h
#define fluid_surface_model_local_error_estimate_h

#include <fluid_surface/geometry/surface_geometry.h>

namespace FluidSurface
{
  class CheckpointData;
  class StepSystem;

  /**
   * The local error estimate of the flow steps (`time stepping/error tolerance` > 0): the normal speeds of the
   * nodes relative to the carry, w = (Ỹ − X^m)·ñ^m/τ, against those of the last accepted step (w^m, of size
   * τ_p): e = τ²/(τ + τ_p) max|w − w^m| / R, R = √(A/4π), backward Euler's (τ²/2)|ẅ| of the shape's position
   * over its size. The tangential motion (the mesh law) and the rigid motion (the carry, exact) do not enter.
   */
  class LocalErrorEstimate
  {
  public:
    /// Whether the flow steps estimate their error.
    void
    set_enabled(const bool on)
    {
      on_ = on;
    }
    bool
    enabled() const
    {
      return on_;
    }
    /**
     * e of a step of size @p tau whose solution in the frame of the step is @p new_state, from the accepted
     * surface X^m = @p old_position with normal ñ^m = @p old_normal and size R = @p shape_radius. Keeps w for
     * accept(); −1 without a last step.
     */
    double
    estimate(const StepSystem &system,
             const VectorType &new_state,
             const VectorType &old_position,
             const VectorType &old_normal,
             const double      tau,
             const double      shape_radius);
    /// The estimated step of size @p tau was accepted: its w becomes w^m.
    void
    accept(const StepSystem &system, const double tau);
    /// The next step has no estimate (the state jumped).
    void
    forget_history()
    {
      normal_speed_step = 0;
    }
    /// Writes w^m and τ_p into a checkpoint (nothing without them). Collective.
    void
    save(CheckpointData &data, const StepSystem &system) const;
    /// Reads them, if the checkpoint has them.
    void
    load(const CheckpointData &data, const StepSystem &system);

  private:
    bool on_ = false;
    /// w of the last accepted step and of the candidate (in the first component of the Y DoFs of each node).
    VectorType normal_speed, candidate_normal_speed;
    /// τ_p of the step that produced normal_speed; 0: none (the first step, after a re-parametrization).
    double normal_speed_step = 0;
  };
} // namespace FluidSurface

#endif
