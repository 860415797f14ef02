// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/model/membrane_pull.h>

namespace FluidSurface
{
  void
  MembranePull::save(CheckpointData &data) const
  {
    if (accepted > 0)
      data.set("model/membrane pull", accepted);
    if (slowdown > 1)
      data.set("model/membrane slowdown", slowdown);
  }

  void
  MembranePull::load(const CheckpointData &data)
  {
    accepted  = data.has("model/membrane pull") ? data.get_double("model/membrane pull") : 0;
    candidate = accepted;
    slowdown  = data.has("model/membrane slowdown") ? data.get_double("model/membrane slowdown") : 1;
  }
} // namespace FluidSurface
