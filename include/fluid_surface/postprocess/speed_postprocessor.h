// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_postprocess_speed_postprocessor_h
#define fluid_surface_postprocess_speed_postprocessor_h

#include <deal.II/numerics/data_postprocessor.h>

#include <vector>

namespace FluidSurface
{
  /// The speed |u| from the first three components of a field (the velocity), for the VTU files.
  class SpeedPostprocessor : public dealii::DataPostprocessorScalar<3>
  {
  public:
    SpeedPostprocessor();

    void
    evaluate_vector_field(const dealii::DataPostprocessorInputs::Vector<3> &inputs,
                          std::vector<dealii::Vector<double>>              &computed) const override;
  };
} // namespace FluidSurface

#endif
