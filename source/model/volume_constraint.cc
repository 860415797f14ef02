// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/model/volume_constraint.h>

namespace FluidSurface
{
  using namespace dealii;

  void
  VolumeConstraint::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("volume constraint");
    prm.declare_entry("enabled",
                      "true",
                      Patterns::Bool(),
                      "Keep the enclosed volume V with the global multiplier γ: ∫u·ν = −(V − V₀)/τ_c.");
    prm.declare_entry("drift correction time",
                      "0.01",
                      RealRange::at_least(0),
                      "τ_drift ≥ 0: volume and area drifts are returned at the rate (V − V₀)/τ_c with "
                      "τ_c = max(τ_drift, τ_max) (τ_max = time stepping/maximum time step; likewise for the area "
                      "through div_P u, and with `conserve momenta` the momenta by the fraction τ/τ_c per step). "
                      "τ_c does not depend on the step τ, so a step retried with a smaller τ asks for a "
                      "proportionally smaller correction.");
    prm.leave_subsection();
  }

  void
  VolumeConstraint::parse_parameters(ParameterHandler &prm, const double maximum_time_step)
  {
    prm.enter_subsection("volume constraint");
    enabled               = prm.get_bool("enabled");
    drift_correction_time = prm.get_double("drift correction time");
    prm.leave_subsection();
    this->maximum_time_step = maximum_time_step;
  }

  void
  VolumeConstraint::assemble_column(const SurfacePointValues &point,
                                    const DofLayout          &dofs,
                                    Vector<double>           &column) const
  {
    for (const unsigned int i : dofs.velocity)
      column(i) += (point.flow.velocity[i] * point.smooth_normal) * point.flow.JxW;
  }
} // namespace FluidSurface
