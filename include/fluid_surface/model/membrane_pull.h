// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_membrane_pull_h
#define fluid_surface_model_membrane_pull_h

#include <fluid_surface/model/mesh_redistribution.h>

#include <algorithm>

namespace FluidSurface
{
  class CheckpointData;

  /**
   * The weight of the membrane energy of mesh law reference: a latch at the largest w(q) of the accepted steps
   * so far (MeshRedistribution::membrane_weight() of the mesh quality q). A weight that followed q up and down
   * kept the mesh moving in a rigidly rotating end state, and F rose. Checkpoint key `model/membrane pull`.
   */
  class MembranePull
  {
  public:
    /// The weight of a flow step from a surface of mesh quality @p quality (held until accept()).
    double
    flow_step_weight(const MeshRedistribution &redistribution, const double quality)
    {
      candidate = std::max(accepted, redistribution.membrane_weight(quality));
      return candidate;
    }
    /// The step was accepted: its weight is the latch's.
    void
    accept()
    {
      accepted = candidate;
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
    double accepted = 0, candidate = 0;
  };
} // namespace FluidSurface

#endif
