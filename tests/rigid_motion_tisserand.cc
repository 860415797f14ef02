// SPDX-License-Identifier: LGPL-2.1-or-later
// The Tisserand motion of a rigid velocity (the frame of the co-rotating step, issue 33): on a triaxial ellipsoid
// [1, 0.8, 0.6] (no symmetry axis), u₀ = U + ω e × (x − c) with e = (1, 2, 3)/√14 (not a principal axis), ω = 2.5,
// c = (0.1, −0.2, 0.3), U = (0.3, −0.1, 0.2). RigidMotion::tisserand() must give Ω = ω e and the translation U
// (relative to the centre of mass x_c = 0 of the ellipsoid) to round-off, whatever the axis, so that the step
// sees a rigid spin as a fluid at rest in its frame; rotation_over(τ) must be the rotation by τω about e.
#include <deal.II/base/mpi.h>

#include <fluid_surface/model/fluid_deformable_surface.h>
#include <fluid_surface/model/rigid_motion.h>
#include <fluid_surface/scenes/simulation.h>
#include <fluid_surface/time_stepping/time_stepper.h>

#include <cmath>
#include <cstdio>

using namespace FluidSurface;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const dealii::Tensor<1, 3>               axis = dealii::Tensor<1, 3>({1., 2., 3.}) / std::sqrt(14.);
  const double                             omega = 2.5;
  const dealii::Point<3>                   c(0.1, -0.2, 0.3);
  const dealii::Tensor<1, 3>               U({0.3, -0.1, 0.2});
  for (unsigned int r = 1; r <= 2; ++r)
    {
      dealii::ParameterHandler prm;
      Simulation::declare_parameters(prm);
      prm.enter_subsection("geometry");
      prm.set("semi-axes", "1, 0.8, 0.6");
      prm.set("refinement", std::to_string(r));
      prm.leave_subsection();
      prm.enter_subsection("initial state");
      prm.set("angular velocity", "2.5");
      prm.set("rotation axis", "1, 2, 3");
      prm.set("rotation centre", "0.1, -0.2, 0.3");
      prm.set("translation velocity", "0.3, -0.1, 0.2");
      prm.leave_subsection();
      SurfaceGeometry geometry(MPI_COMM_WORLD);
      geometry.parse_parameters(prm);
      geometry.create();
      FluidDeformableSurface model(geometry);
      TimeStepper            time;
      time.parse_parameters(prm);
      model.parse_parameters(prm, time.maximum_step_size());
      model.setup();
      const RigidMotion motion = RigidMotion::tisserand(geometry, model.dof_handler(), model.solution());
      // The rigid velocity about the centre of mass: U + ω e × (x_c − c) + ω e × (x − x_c).
      const dealii::Tensor<1, 3> translation = U + dealii::cross_product_3d(omega * axis, motion.centre - c);
      std::printf("refinement %u\n", r);
      std::printf("  |Omega - omega e| / omega below 1e-12: %s\n",
                  (motion.rotation - omega * axis).norm() / omega < 1e-12 ? "yes" : "no");
      std::printf("  |U_c - U| / |U| below 1e-12: %s\n",
                  (motion.translation - translation).norm() / U.norm() < 1e-12 ? "yes" : "no");
      // Rodrigues against the rotation it must be: Q e = e, Q orthogonal, and Q v for v ⟂ e turned by τω.
      const double               tau = 0.1;
      const dealii::Tensor<2, 3> Q   = motion.rotation_over(tau);
      const dealii::Tensor<1, 3> v   = dealii::cross_product_3d(axis, dealii::Tensor<1, 3>({0., 0., 1.}));
      const dealii::Tensor<1, 3> v1  = v / v.norm(), v2 = dealii::cross_product_3d(axis, v1);
      const dealii::Tensor<1, 3> expected = std::cos(tau * omega) * v1 + std::sin(tau * omega) * v2;
      std::printf("  |Q e - e| below 1e-12: %s\n", (Q * axis - axis).norm() < 1e-12 ? "yes" : "no");
      std::printf("  |Q^T Q - 1| below 1e-12: %s\n",
                  (dealii::transpose(Q) * Q - dealii::Tensor<2, 3>(dealii::unit_symmetric_tensor<3>())).norm() < 1e-12 ?
                    "yes" :
                    "no");
      std::printf("  Q turns by tau omega about e: %s\n", (Q * v1 - expected).norm() < 1e-12 ? "yes" : "no");
    }
  return 0;
}
