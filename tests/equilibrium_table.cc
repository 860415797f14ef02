// SPDX-License-Identifier: LGPL-2.1-or-later
// Rotating axisymmetric equilibria at A = 4π, Be = 1, reduced volume 0.75 (the reference table of
// benchmarks/equilibrium/README.md): bending energy ½∫H², I_zz = ∫(x²+y²), the multipliers p0, γ, and the same
// shapes reached by prescribing L = ω I_zz.
#include <fluid_surface/reference/axisymmetric_equilibrium.h>

#include <cmath>
#include <cstdio>

using namespace FluidSurface;
using Equilibrium = AxisymmetricEquilibrium;

int
main()
{
  for (const Equilibrium::Branch branch : {Equilibrium::Branch::prolate, Equilibrium::Branch::oblate})
    for (const double Be_omega2 : {0., 4.})
      {
        Equilibrium::Parameters parameters;
        parameters.reduced_volume   = 0.75;
        parameters.branch           = branch;
        parameters.angular_velocity = std::sqrt(Be_omega2);
        Equilibrium equilibrium(parameters);
        equilibrium.solve();
        std::printf("v 0.75 %s Be*omega^2 %g: half int H^2 %.7f  I_zz %.7f  p0 %.6f  gamma %.6f  virial ok %s\n",
                    branch == Equilibrium::Branch::prolate ? "prolate" : "oblate ", Be_omega2,
                    equilibrium.bending_energy(), equilibrium.inertia_zz(), equilibrium.p0(), equilibrium.gamma(),
                    equilibrium.virial_residual() < 1e-10 ? "yes" : "no");

        if (Be_omega2 > 0)
          {
            // The same state as a critical point of F_bend + L²/(2 I_zz) at the angular momentum found above.
            Equilibrium::Parameters by_momentum = parameters;
            by_momentum.prescribed              = Equilibrium::Prescribed::angular_momentum;
            by_momentum.angular_momentum        = equilibrium.angular_momentum();
            Equilibrium same(by_momentum);
            same.solve();
            std::printf("    prescribed L %.7f: omega %.7f  half int H^2 %.7f  I_zz %.7f\n", by_momentum.angular_momentum,
                        same.angular_velocity(), same.bending_energy(), same.inertia_zz());
          }
      }
}
