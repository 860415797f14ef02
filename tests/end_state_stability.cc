// SPDX-License-Identifier: LGPL-2.1-or-later
// `steady state/saddle check` (issue 49, item 5): EndStateStability classifies an end state that is a body of
// revolution spinning about its axis by the second variation of its rotating axisymmetric equilibrium at fixed A,
// V, L, and leaves the others to scene stability. Printed per state: whether it is axisymmetric, whether it was
// classified, the falling directions and the lowest eigenvalue with its class. Against doc/stability.md and
// benchmarks/stability_chart: the spinning oblate of v = 0.95, L = 20 is a saddle in m = 2 even (λ = −6.2775, two
// directions); the resting oblate of v = 0.75 barely one (−0.0159); the spinning oblate of v = 0.65, L = 5 a minimum
// (L_c = 13.16 there); the paper's rotating prolate (A = 12.6035, v = 0.74832, L = 13.7733) falls in m = 0 odd,
// 1 even, 1 odd, 2 even and 2 odd (nine directions). A triaxial state and a prolate tumbling about a transverse axis
// are not axisymmetric equilibria.
#include <deal.II/base/parameter_handler.h>

#include <fluid_surface/time_stepping/end_state_stability.h>

#include <iomanip>
#include <iostream>

using namespace FluidSurface;

namespace
{
  void
  classify(const EndStateStability &check,
           const char              *name,
           const double             area,
           const double             v,
           const double             L,
           const std::array<double, 3> &inertia,
           const dealii::Tensor<1, 3> &rotation_axis)
  {
    EndStateStability::Measures state;
    state.area           = area;
    state.reduced_volume = v;
    for (unsigned int i = 0; i < 3; ++i)
      state.inertia[i] = inertia[i];
    state.least_inertia_axis   = dealii::Tensor<1, 3>({0, 0, 1});
    state.largest_inertia_axis = dealii::Tensor<1, 3>({0, 0, 1});
    if (inertia[1] - inertia[0] > inertia[2] - inertia[1]) // a prolate: its long axis is that of λ₁
      state.largest_inertia_axis = dealii::Tensor<1, 3>({1, 0, 0});
    state.angular_momentum = L * rotation_axis;
    state.rotation_vector  = (L / inertia[2]) * rotation_axis;
    state.total_energy     = 50;
    const EndStateStability::Assessment a = check.assess(state);
    std::cout << name << ": " << (a.axisymmetric ? "axisymmetric" : "not axisymmetric") << ", "
              << (a.classified ? "classified" : "not classified");
    if (a.classified)
      std::cout << ", " << (a.saddle() ? "saddle" : "minimum") << ", falling directions " << a.directions
                << ", lowest " << std::setprecision(5) << a.lowest << " (m = " << a.m << (a.odd ? " odd)" : " even)");
    std::cout << std::endl;
  }
} // namespace

int
main()
{
  dealii::ParameterHandler prm;
  EndStateStability::declare_parameters(prm);
  EndStateStability check;
  check.parse_parameters(prm);
  const double               four_pi = 12.566370614359172;
  const dealii::Tensor<1, 3> e_z({0, 0, 1}), e_x({1, 0, 0});
  classify(check, "oblate v = 0.95, L = 20", four_pi, 0.95, 20, {{5, 5, 10}}, e_z);
  classify(check, "oblate v = 0.75, L = 0", four_pi, 0.75, 0, {{5, 5, 10}}, e_z);
  classify(check, "oblate v = 0.65, L = 5", four_pi, 0.65, 5, {{5, 5, 10}}, e_z);
  classify(check, "prolate of the paper", 12.6035, 0.74832, 13.7733, {{3, 15, 15}}, e_z);
  classify(check, "triaxial", four_pi, 0.85, 20, {{5, 7, 10}}, e_z);
  classify(check, "prolate tumbling", four_pi, 0.75, 20, {{3, 15, 15}}, e_x);
}
