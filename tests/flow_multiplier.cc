// SPDX-License-Identifier: LGPL-2.1-or-later
// Tangentiality by a Lagrange multiplier λ ∈ Q_d, d = 1, 2, instead of the penalty, on the unit sphere
// (direct solver). Stationary manufactured Stokes problem at refinements 2 and 3: the errors of penalty
// (β = 10, q = 3), Q1 and Q2 multiplier, the L2 rate of the velocity, and whether the Q2 multiplier
// is more tangential (smaller ‖u_h·n‖) than the penalty. Killing field u = e_z × x (Re = 10, BDF2,
// τ = 0.05, t ∈ [0, 1]) at refinement 2: the relative kinetic-energy change. A multiplier with the
// block preconditioner is rejected with an InputError.
#include "flow_common.h"

#include <fluid_surface/io/parameter_file.h>

#include <string>
#include <utility>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<std::pair<std::string, FlowTest::Overrides>> variants = {
    {"penalty", {}},
    {"Q1 multiplier", {{"fixed surface solver/tangentiality", "multiplier"}, {"fixed surface solver/multiplier degree", "1"}}},
    {"Q2 multiplier", {{"fixed surface solver/tangentiality", "multiplier"}, {"fixed surface solver/multiplier degree", "2"}}}};
  std::vector<std::vector<FluidSurface::FixedSurfaceScene::Results>> results(variants.size());
  for (unsigned int v = 0; v < variants.size(); ++v)
    for (unsigned int r = 2; r <= 3; ++r)
      {
        FlowTest::Overrides settings = {{"geometry/shape", "sphere"},
                                        {"geometry/refinement", std::to_string(r)},
                                        {"fixed surface/problem", "manufactured sphere"}};
        settings.insert(settings.end(), variants[v].second.begin(), variants[v].second.end());
        results[v].push_back(FlowTest::run(settings));
        const auto &e = results[v].back().errors;
        if (FlowTest::is_root())
          std::printf("%s, stationary refinement %u  dofs %llu  ||u - u_h|| %s  ||grad_P(u - u_h)|| %s  "
                      "||p - p_h|| %s  ||u_h.n|| %s\n",
                      variants[v].first.c_str(), r, (unsigned long long)results[v].back().n_dofs,
                      FlowTest::scientific(e.velocity).c_str(), FlowTest::scientific(e.gradient).c_str(),
                      FlowTest::scientific(e.pressure).c_str(), FlowTest::scientific(e.normal_velocity).c_str());
      }
  if (FlowTest::is_root())
    {
      for (unsigned int v = 0; v < variants.size(); ++v)
        std::printf("%s: L2 rate of the velocity %.2f\n", variants[v].first.c_str(),
                    std::log2(results[v][0].errors.velocity / results[v][1].errors.velocity));
      std::printf("Q2 multiplier more tangential than the penalty at refinement 3: %s\n",
                  results[2][1].errors.normal_velocity < results[0][1].errors.normal_velocity ? "yes" : "no");
    }
  for (unsigned int v = 1; v < variants.size(); ++v)
    {
      FlowTest::Overrides settings = {{"geometry/shape", "sphere"},
                                      {"geometry/refinement", "2"},
                                      {"fixed surface/problem", "killing"},
                                      {"flow/Re", "10"},
                                      {"time stepping/time step", "0.05"},
                                      {"time stepping/end time", "1"}};
      settings.insert(settings.end(), variants[v].second.begin(), variants[v].second.end());
      const auto result = FlowTest::run(settings);
      if (FlowTest::is_root())
        std::printf("%s, Killing field refinement 2: |F(1) - F(0)|/F(0) = %s  ||u(1) - u_h(1)|| = %s\n",
                    variants[v].first.c_str(), FlowTest::scientific(result.energy_change).c_str(),
                    FlowTest::scientific(result.errors.velocity).c_str());
    }
  try
    {
      FlowTest::run({{"geometry/shape", "sphere"},
                     {"geometry/refinement", "1"},
                     {"fixed surface solver/tangentiality", "multiplier"},
                     {"fixed surface solver/linear solver", "block preconditioned"}});
      if (FlowTest::is_root())
        std::printf("multiplier with the block preconditioner: accepted (wrong)\n");
    }
  catch (const FluidSurface::InputError &)
    {
      if (FlowTest::is_root())
        std::printf("multiplier with the block preconditioner: rejected with an InputError\n");
    }
}
