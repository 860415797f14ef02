// SPDX-License-Identifier: LGPL-2.1-or-later
// Diagnostics against exact answers on the prolate spheroid [0.61, 0.61, 2.02] with the rigid rotation
// u = 1.5 e_z × x: ω = 1.5, the inertia eigenvalues equal the exact spheroid moments (I_xx = I_yy > I_zz),
// e(λ) = 0 to discretization, L = (0, 0, 1.5 I_zz), Ω = I⁻¹L = (0, 0, 1.5), tilt angle 0, rigid fraction 1,
// elongation axis z. Errors at refinements 2 and 3 (Q2 geometry).
#include <deal.II/base/mpi.h>

#include <fluid_surface/time_stepping/time_stepper.h>
#include <fluid_surface/postprocess/diagnostics.h>
#include <fluid_surface/geometry/exact_geometry.h>
#include <fluid_surface/model/fluid_deformable_surface.h>
#include <fluid_surface/scenes/simulation.h>

#include <cmath>
#include <cstdio>

using namespace FluidSurface;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const SpheroidMeasures                   exact = exact_spheroid_measures(0.61, 2.02);
  for (unsigned int r = 2; r <= 3; ++r)
    {
      dealii::ParameterHandler prm;
      Simulation::declare_parameters(prm);
      prm.enter_subsection("geometry");
      prm.set("semi-axes", "0.61, 0.61, 2.02");
      prm.set("refinement", std::to_string(r));
      prm.leave_subsection();
      prm.enter_subsection("initial state");
      prm.set("angular velocity", "1.5");
      prm.leave_subsection();
      SurfaceGeometry geometry(MPI_COMM_WORLD);
      geometry.parse_parameters(prm);
      geometry.create();
      FluidDeformableSurface model(geometry);
      TimeStepper time;
      time.parse_parameters(prm);
      model.parse_parameters(prm, time.maximum_step_size());
      model.setup();
      Diagnostics diagnostics;
      diagnostics.parse_parameters(prm);
      const Diagnostics::Values v = diagnostics.evaluate(geometry, model.dof_handler(), model.solution());
      std::printf("refinement %u\n", r);
      std::printf("  omega error %.1e\n", std::abs(v.angular_velocity - 1.5));
      std::printf("  eigenvalue errors %.1e %.1e %.1e\n",
                  std::abs(v.eigenvalues[0] - exact.inertia_zz) / exact.inertia_zz,
                  std::abs(v.eigenvalues[1] - exact.inertia_xx) / exact.inertia_xx,
                  std::abs(v.eigenvalues[2] - exact.inertia_xx) / exact.inertia_xx);
      std::printf("  symmetry deviation below 1e-10: %s\n", v.symmetry_deviation < 1e-10 ? "yes" : "no");
      std::printf("  L_z error %.1e  |L_xy| below 1e-10: %s\n",
                  std::abs(v.angular_momentum[2] - 1.5 * exact.inertia_zz) / (1.5 * exact.inertia_zz),
                  std::hypot(v.angular_momentum[0], v.angular_momentum[1]) < 1e-10 ? "yes" : "no");
      std::printf("  rotation vector (%.6f, %.6f, %.6f)  tilt %.4f deg  rigid fraction %.6f\n",
                  std::abs(v.rotation_vector[0]), std::abs(v.rotation_vector[1]), v.rotation_vector[2],
                  v.tilt_angle, v.rigid_fraction);
      std::printf("  elongation axis (%.6f, %.6f, %.6f)\n",
                  std::abs(v.elongation_axis[0]), std::abs(v.elongation_axis[1]), v.elongation_axis[2]);
    }
}
