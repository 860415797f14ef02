// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/base/vector_math.h>

#include <algorithm>
#include <cmath>

namespace FluidSurface
{
  dealii::Tensor<1, 3>
  unit_vector(const dealii::Tensor<1, 3> &v)
  {
    const double largest = std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
    if (largest == 0)
      return v;
    const dealii::Tensor<1, 3> w = v / largest;
    return w / w.norm();
  }
} // namespace FluidSurface
