// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_membrane_pull_h
#define fluid_surface_model_membrane_pull_h

#include <fluid_surface/model/mesh_redistribution.h>

#include <algorithm>
#include <cmath>

namespace FluidSurface
{
  class CheckpointData;

  /**
   * The weight of the membrane energy of mesh law reference: a latch at the largest w(q) of the accepted steps
   * so far (MeshRedistribution::membrane_weight() of the mesh quality q). A weight that followed q up and down
   * kept the mesh moving in a rigidly rotating end state, and F rose. Checkpoint key `model/membrane pull`.
   *
   * With `time stepping/energy law = retry`, a step whose break of the energy law is mostly its bending defect
   * (the tangential node motion changed the discrete W by more than the bending force's work) is retried with the
   * mesh law slowed down (slow_down(): the weight divided by a factor s, as T_r multiplied by s), and s returns
   * to 1 over the following time units (doc/scheme.md, "The discrete energy law"). Checkpoint key
   * `model/membrane slowdown` (while s > 1).
   */
  class MembranePull
  {
  public:
    /// The weight of a flow step from a surface of mesh quality @p quality (held until accept()), over the slowdown.
    double
    flow_step_weight(const MeshRedistribution &redistribution, const double quality)
    {
      candidate    = std::max(accepted, redistribution.membrane_weight(quality));
      step_quality = quality;
      return candidate / slowdown;
    }
    /// The step of size @p tau was accepted: its weight is the latch's, and the slowdown decays by e^{−τ/T_s}.
    void
    accept(const double tau)
    {
      accepted = candidate;
      slowdown = std::max(1.0, slowdown * std::exp(-tau / recovery_time));
    }
    /**
     * The mesh law slowed down by the factor 10 more, up to 1000 (the weight divided by it, as the relaxation time
     * T_r multiplied by it). Returns false, and changes nothing, when there is nothing (more) to slow down (a zero
     * weight, or the largest slowdown already) or when the step's surface has a mesh quality below 0.15: there the
     * mesh needs its pull (the map's (0.65, 20) prolate start, slowed down at quality 0.15 and 0.13, fell to 0.10,
     * below the safety valve's threshold, and then made no step for minutes).
     */
    bool
    slow_down()
    {
      if (candidate == 0 || slowdown >= max_slowdown || step_quality < min_quality)
        return false;
      slowdown = std::min(max_slowdown, 10 * slowdown);
      return true;
    }
    /// The factor s ≥ 1 by which the mesh law is slowed down now.
    double
    current_slowdown() const
    {
      return slowdown;
    }
    /// From now on the membrane energy acts with its full weight (`mesh redistribution/anchor time`).
    void
    pull_fully()
    {
      accepted = candidate = 1;
    }
    /// Writes the latch into a checkpoint (nothing while it is 0).
    void
    save(CheckpointData &data) const;
    /// Reads it (0 if the checkpoint has none).
    void
    load(const CheckpointData &data);

  private:
    /// T_s: the slowdown decays by e^{−τ/T_s} per accepted step, from 10 back to 1 in about 1.2 time units.
    static constexpr double recovery_time = 0.5;
    static constexpr double max_slowdown  = 1000;
    static constexpr double min_quality   = 0.15;
    double                  accepted = 0, candidate = 0;
    double                  step_quality = 1; ///< the mesh quality of the surface of the last flow step
    double                  slowdown = 1;
  };
} // namespace FluidSurface

#endif
