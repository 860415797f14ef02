// SPDX-License-Identifier: LGPL-2.1-or-later
// Sphere limit of the equilibrium solver: at reduced volume 1 the shape is the sphere with ½∫H² = 8π; near
// the sphere both branches obey ½∫H² − 8π ≈ 16π(1 − v) (l = 2 mode) with p0 → 6/R², γ → 2p0/R; and along a
// family of rotating equilibria dF_bend/dI_zz = ½ω² (first variation at fixed A and V), checked by central
// differences in ω² near the sphere.
#include <fluid_surface/reference/axisymmetric_equilibrium.h>

#include <cmath>
#include <cstdio>

using namespace FluidSurface;
using Equilibrium = AxisymmetricEquilibrium;

int
main()
{
  const double pi = 3.14159265358979323846;
  {
    Equilibrium::Parameters parameters;
    parameters.reduced_volume = 1;
    Equilibrium sphere(parameters);
    sphere.solve();
    std::printf("v 1: half int H^2 / (8 pi) %.10f  area %.10f  volume / (4pi/3) %.10f  I_zz / (8pi/3) %.10f\n",
                sphere.bending_energy() / (8 * pi), sphere.area(), sphere.volume() / (4 * pi / 3),
                sphere.inertia_zz() / (8 * pi / 3));
    std::printf("     equatorial radius %.10f  polar half height %.10f\n", sphere.equatorial_radius(),
                sphere.polar_height());
  }

  for (const double v : {0.999, 0.99})
    for (const Equilibrium::Branch branch : {Equilibrium::Branch::prolate, Equilibrium::Branch::oblate})
      {
        Equilibrium::Parameters parameters;
        parameters.reduced_volume = v;
        parameters.branch         = branch;
        Equilibrium equilibrium(parameters);
        equilibrium.solve();
        std::printf("v %g %s: (half int H^2 - 8 pi) / (16 pi (1 - v)) %.6f  p0 %.6f  gamma / p0 %.6f\n", v,
                    branch == Equilibrium::Branch::prolate ? "prolate" : "oblate ",
                    (equilibrium.bending_energy() - 8 * pi) / (16 * pi * (1 - v)), equilibrium.p0(),
                    equilibrium.gamma() / equilibrium.p0());
      }

  for (const Equilibrium::Branch branch : {Equilibrium::Branch::prolate, Equilibrium::Branch::oblate})
    {
      const double omega2 = 0.5, h = 1e-3;
      double       F[2], I[2];
      for (unsigned int k = 0; k < 2; ++k)
        {
          Equilibrium::Parameters parameters;
          parameters.reduced_volume   = 0.95;
          parameters.branch           = branch;
          parameters.angular_velocity = std::sqrt(omega2 + (k == 0 ? -h : h));
          Equilibrium equilibrium(parameters);
          equilibrium.solve();
          F[k] = equilibrium.bending_energy();
          I[k] = equilibrium.inertia_zz();
        }
      std::printf("v 0.95 %s omega^2 %g: dF/dI_zz / (omega^2/2) %.6f\n",
                  branch == Equilibrium::Branch::prolate ? "prolate" : "oblate ", omega2,
                  (F[1] - F[0]) / (I[1] - I[0]) / (0.5 * omega2));
    }
}
