// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/postprocess/speed_postprocessor.h>

#include <cmath>

namespace FluidSurface
{
  using namespace dealii;

  SpeedPostprocessor::SpeedPostprocessor()
    : DataPostprocessorScalar<3>("speed", update_values)
  {}

  void
  SpeedPostprocessor::evaluate_vector_field(const DataPostprocessorInputs::Vector<3> &inputs,
                                            std::vector<Vector<double>>              &computed) const
  {
    for (unsigned int q = 0; q < inputs.solution_values.size(); ++q)
      computed[q](0) = std::sqrt(inputs.solution_values[q](0) * inputs.solution_values[q](0) +
                                 inputs.solution_values[q](1) * inputs.solution_values[q](1) +
                                 inputs.solution_values[q](2) * inputs.solution_values[q](2));
  }
} // namespace FluidSurface
