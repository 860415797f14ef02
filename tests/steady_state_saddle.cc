// SPDX-License-Identifier: LGPL-2.1-or-later
// `steady state/symmetry growth tolerance` (issue 49): a body of revolution whose symmetry-breaking mode grows is a
// saddle, not an end state, even while F and the inertia eigenvalues are flat to δ. SteadyState is fed the samples
// of such a state: F constant, λ₁ = λ₃/2 − g λ₃, λ₂ = λ₃/2 with the gap g growing like e^{σt} from 2e-7 (the seeded
// spinning oblate of v = 0.95, L = 20 at refinement 3: σ = 0.46), so that every |Δλ_i|/(T_w λ₃) stays below
// δ = 1e-6. Printed: the first time at which the check reports the end state, for σ = 0.46 (never: the gap grows),
// σ = 0 (a steady gap: after one window), σ = −0.5 (a decaying mode: after one window), σ = 0.46 below the
// rounding floor g < 1e-12 (the gap is not judged: after one window), and σ = 0.46 with a tolerance σ_s = 1 above
// the growth (after one window: the check the entry turns off). Last, the steady gap while the flow dissipates
// D = 2e-6|F| with F flat (a plateau the discretization feeds: not an end state, reported after one window) and
// D = 5e-7|F| (below δ: an end state); and F falling at a fraction of D: at 0.9 of D = 1.1e-6|F| (|ΔF| under δ T_w|F|,
// the law kept to 10 % of D: still relaxing, the run goes on, as the map's (0.65, 10) prolate start at refinement 4,
// which this check stopped as a plateau before) and at 0.4 of D = 2e-6|F| (more than half of D supplied: a plateau).
// Last, a mode growing at 1e-3 < σ_s from g = 2e-4: an end state after one window, unless a saddle was left before
// (restart_after_saddle(): the gap may then grow no faster than δ; the transient of the displaced resting discocyte
// of v = 0.75 at refinement 4),
// and a steady gap after a saddle was left (an end state).
#include <deal.II/base/parameter_handler.h>

#include <fluid_surface/time_stepping/steady_state.h>

#include <cmath>
#include <iostream>

using namespace FluidSurface;

namespace
{
  void
  run(const char  *name,
      const double rate,
      const double g0,
      const char  *tolerance   = "0.01",
      const double dissipation  = 0,
      const double falling      = 0,
      const bool   after_saddle = false)
  {
    dealii::ParameterHandler prm;
    SteadyState::declare_parameters(prm);
    prm.enter_subsection("steady state");
    prm.set("rate tolerance", "1e-6");
    prm.set("window", "1");
    prm.set("symmetry growth tolerance", tolerance);
    prm.leave_subsection();
    SteadyState steady;
    steady.parse_parameters(prm);
    if (after_saddle)
      steady.restart_after_saddle();
    const double lambda3 = 10;
    for (int k = 0; k <= 200; ++k)
      {
        const double        t = 0.05 * k;
        const double        g = g0 * std::exp(rate * t);
        SteadyState::Sample sample{t, 47.6 - falling * dissipation * t, {{lambda3 / 2 - g * lambda3, lambda3 / 2, lambda3}}, 0};
        const SteadyState::Verdict verdict = steady.assess(sample, 0, 0.05, dissipation);
        if (verdict != SteadyState::Verdict::running)
          {
            std::cout << name << ": " << (verdict == SteadyState::Verdict::reached ? "end state" : "plateau")
                      << " at t = " << t << std::endl;
            return;
          }
      }
    std::cout << name << ": no end state up to t = 10" << std::endl;
  }
} // namespace

int
main()
{
  run("growing mode", 0.46, 2e-7);
  run("steady gap", 0, 2e-7);
  run("decaying mode", -0.5, 2e-7);
  run("below the rounding floor", 0.46, 1e-14);
  run("growing mode, σ_s = 1", 0.46, 2e-7, "1");
  run("steady gap, dissipating 2e-6 F with F flat", 0, 2e-7, "0.01", 2e-6 * 47.6);
  run("steady gap, dissipating 5e-7 F with F flat", 0, 2e-7, "0.01", 5e-7 * 47.6);
  run("steady gap, dissipating 1.1e-6 F with F falling at 0.9 of it", 0, 2e-7, "0.01", 1.1e-6 * 47.6, 0.9);
  run("steady gap, dissipating 2e-6 F with F falling at 0.4 of it", 0, 2e-7, "0.01", 2e-6 * 47.6, 0.4);
  run("slow mode, σ = 1e-3 < σ_s", 1e-3, 2e-4);
  run("slow mode, σ = 1e-3, after a saddle was left", 1e-3, 2e-4, "0.01", 0, 0, true);
  run("steady gap, after a saddle was left", 0, 2e-4, "0.01", 0, 0, true);
}
