// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_base_types_h
#define fluid_surface_base_types_h

#include <deal.II/lac/trilinos_vector.h>

namespace FluidSurface
{
  /// The distributed vector of every field (position, curvature, the step's unknowns): Trilinos, ghosted or not.
  using VectorType = dealii::TrilinosWrappers::MPI::Vector;
} // namespace FluidSurface

#endif
