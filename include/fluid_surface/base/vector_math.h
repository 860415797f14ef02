// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_base_vector_math_h
#define fluid_surface_base_vector_math_h

#include <deal.II/base/tensor.h>

namespace FluidSurface
{
  /**
   * @p v / |v|, computed without overflow or underflow of |v| for any finite @p v; zero for v = 0.
   */
  dealii::Tensor<1, 3>
  unit_vector(const dealii::Tensor<1, 3> &v);
} // namespace FluidSurface

#endif
