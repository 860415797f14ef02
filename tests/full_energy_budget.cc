// SPDX-License-Identifier: LGPL-2.1-or-later
// The discrete energy budget of scene full: B(T) = F(T) − F(0) + Σ_n τ_n D_n, D_n = (2/Re)‖σ(u^n)‖² the
// dissipation rate of the step (statistics columns), must vanish as τ → 0 (backward Euler: B = O(τ), B < 0,
// the numerical dissipation). Fixed τ = 0.02 … 0.0025 on t ∈ [0, 0.1], refinement 2: the prolate at rest
// (u0 = 0, bending drives the flow) and the rotating prolate (ω0 = 4) with conserve momenta. B over [0, T]
// converges slowly (the initial layer of u); over [T/2, T] the ratios approach 2 (first order).
// Not in the test, measured by hand (doc/scheme.md): at τ = 0.00125 B[T/2, T] turns positive at refinement 2
// (+6.9e-4 F(0): the coarse mesh's unstable semi-discrete mode), while refinement 3 gives −3.4e-3, −2.3e-3,
// −1.5e-3 for τ = 0.005, 0.0025, 0.00125.
#include "checkpoint_common.h"
#include "statistics_columns.h"

#include <cmath>
#include <filesystem>
#include <map>


int
main(int argc, char **argv)
{
  using namespace CheckpointTest;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<std::pair<std::string, Overrides>> cases = {
    {"prolate at rest", {{"initial state/angular velocity", "0"}}},
    {"rotating prolate, conserve momenta", {{"flow/conserve momenta", "true"}}}};
  for (const auto &[name, overrides] : cases)
    {
      std::printf("%s\n", name.c_str());
      double previous = 0, previous_late = 0;
      for (const double tau : {0.02, 0.01, 0.005, 0.0025})
        {
          std::filesystem::remove_all("run");
          Overrides all = overrides;
          all.push_back({"time stepping/adaptive", "false"});
          all.push_back({"time stepping/time step", std::to_string(tau)});
          all.push_back({"time stepping/end time", "0.1"});
          const Outcome outcome = run("run", all);
          auto          stats   = read_statistics_columns("run/statistics");
          const auto   &F = stats["total energy"], &D = stats["dissipation rate"], &steps = stats["tau"];
          const auto   &t = stats["time"];
          // B over [0, T] and over the second half [T/2, T], after the initial layer of u (u jumps from u0 on the
          // viscous time scale, which no τ here resolves).
          double dissipated = 0, late = 0, late_start = 0;
          for (unsigned int n = 1; n < F.size(); ++n)
            {
              dissipated += steps[n] * D[n];
              if (t[n - 1] >= 0.05 - 1e-12)
                late += steps[n] * D[n];
              else
                late_start = F[n];
            }
          const double budget = F.back() - F.front() + dissipated, late_budget = F.back() - late_start + late;
          std::printf("  tau %.4f: status %d, %zu steps, F(T) %.6f, B[0,T]/F(0) %.3e", tau, outcome.status,
                      F.size() - 1, F.back(), budget / F.front());
          if (previous != 0)
            std::printf(" (ratio %.2f)", previous / budget);
          std::printf(", B[T/2,T]/F(0) %.3e", late_budget / F.front());
          if (previous_late != 0)
            std::printf(" (ratio %.2f)", previous_late / late_budget);
          std::printf("\n");
          previous      = budget;
          previous_late = late_budget;
        }
    }
  std::filesystem::remove_all("run");
}
