// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/model/bending_force.h>

namespace FluidSurface
{
  using namespace dealii;

  void
  BendingForce::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("bending");
    prm.declare_entry("enabled", "true", Patterns::Bool(), "Assemble the Helfrich bending force b.");
    prm.declare_entry("Be",
                      "1",
                      RealRange::closed(1e-6, 1e6),
                      "Bending capillary number Be = ρU²L²/κ_b, 1e-6 ≤ Be ≤ 1e6; the bending energy is (1/2Be)∫H².");
    prm.leave_subsection();
  }

  void
  BendingForce::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("bending");
    enabled = prm.get_bool("enabled");
    Be      = prm.get_double("Be");
    prm.leave_subsection();
  }

  void
  BendingForce::assemble_force(const SurfacePointValues &point, const DofLayout &dofs, FullMatrix<double> &matrix) const
  {
    const double inverse_be = inverse_bending_number();
    const double dA         = point.flow.JxW;
    for (const unsigned int i : dofs.velocity)
      for (const unsigned int j : dofs.bending_scalar)
        matrix(i, j) += -(inverse_be * point.bending_scalar[j] * (point.smooth_normal * point.flow.velocity[i])) * dA;
  }

  void
  BendingForce::assemble_bending_scalar(const SurfacePointValues &point,
                                        const DofLayout          &dofs,
                                        FullMatrix<double>       &matrix) const
  {
    const double dA = point.flow.JxW;
    const double c  = point.bending_coefficient;
    for (const unsigned int i : dofs.bending_scalar)
      {
        for (const unsigned int j : dofs.bending_scalar)
          matrix(i, j) += point.bending_scalar[i] * point.bending_scalar[j] * dA;
        for (const unsigned int j : dofs.curvature)
          matrix(i, j) += (-point.curvature_gradient[j] * point.bending_scalar_gradient[i] +
                           c * point.curvature[j] * point.bending_scalar[i]) *
                          dA;
      }
  }
} // namespace FluidSurface
