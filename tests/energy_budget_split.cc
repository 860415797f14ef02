// SPDX-License-Identifier: LGPL-2.1-or-later
// `time stepping/energy budget`: the file energy_budget splits each accepted step's ΔB = ΔF + τD of scene full into
// the bending defect ΔW_solve + τP (P = (1/Be)(y ñ, ũ), the bending force's power taken from the step matrix), the
// multipliers' work τP_μ, the transport defect ΔK_solve − τP − τP_μ + τD and the two projections' ΔF
// (benchmarks/energy_law/budget.py). Checked: the
// file's energies at the start of a step are the previous row's final ones and its final ones those of
// `statistics` (so its ΔB is the statistics' ΔF + τD), and the force's work matches ΔW: in the relaxation of the
// prolate at rest the bending defect is a small part of ΔW (a wrong sign of P would make it 2ΔW, a missing P ΔW).
// Refinement 2, fixed τ; the rotating case steps as the experiments do (BDF2, co-rotating, momenta conserved).
#include "checkpoint_common.h"
#include "statistics_columns.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

int
main(int argc, char **argv)
{
  using namespace CheckpointTest;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<std::pair<std::string, Overrides>> cases = {
    {"prolate at rest, backward Euler", {{"initial state/angular velocity", "0"}, {"time stepping/time step", "0.005"}}},
    {"rotating prolate, BDF2 co-rotating, momenta conserved",
     {{"time stepping/scheme", "BDF2"},
      {"time stepping/frame", "Tisserand"},
      {"flow/conserve momenta", "true"},
      {"geometry iteration/maximum iterations", "1"},
      {"geometry iteration/tolerance", "0"},
      {"geometry iteration/apply", "always"}}}};
  for (const auto &[name, overrides] : cases)
    {
      std::filesystem::remove_all("run");
      Overrides all = overrides;
      all.push_back({"time stepping/adaptive", "false"});
      all.push_back({"time stepping/end time", "0.05"});
      all.push_back({"time stepping/energy budget", "true"});
      const Outcome outcome = run("run", all);
      auto          stats   = read_statistics_columns("run/statistics");
      auto          budget  = read_statistics_columns("run/energy_budget");
      const auto   &F = stats["total energy"], &D = stats["dissipation rate"], &tau = stats["tau"];
      const auto   &W0 = budget["bending energy at the start"], &K0 = budget["kinetic energy at the start"];
      const auto   &P = budget["bending force power"], &Pm = budget["multiplier power"];
      const auto   &Ws = budget["bending energy of the solve"];
      const auto   &Ks = budget["kinetic energy of the solve"];
      const auto   &Kav = budget["kinetic energy after the area and volume projection"];
      const auto   &W = budget["bending energy"], &K = budget["kinetic energy"], &Db = budget["dissipation rate"];
      const auto   &tb = budget["tau"];
      const std::size_t n = W.size();
      std::printf("%s: status %d, %zu steps in statistics, %zu rows in energy_budget\n",
                  name.c_str(), outcome.status, F.size() - 1, n);
      if (n == 0 || n + 1 != F.size())
        continue;
      // The bookkeeping: row m starts where row m − 1 ended, and ends where statistics' row m + 1 does.
      double chain = 0, against_statistics = 0;
      for (std::size_t m = 0; m < n; ++m)
        {
          if (m > 0)
            chain = std::max(chain, std::abs(W0[m] + K0[m] - W[m - 1] - K[m - 1]));
          against_statistics = std::max({against_statistics, std::abs(W[m] + K[m] - F[m + 1]),
                                         std::abs(Db[m] - D[m + 1]), std::abs(tb[m] - tau[m + 1])});
        }
      std::printf("  start energies = the previous row's end: %s; end energies, D, tau = statistics': %s\n",
                  chain <= 1e-9 * std::abs(F[0]) ? "yes" : "no",
                  against_statistics <= 1e-9 * std::abs(F[0]) ? "yes" : "no");
      double dW = 0, work = 0, bending = 0, multipliers = 0, transport = 0, area_volume = 0, momenta = 0, dB = 0;
      for (std::size_t m = 0; m < n; ++m)
        {
          dW += Ws[m] - W0[m];
          work += tb[m] * P[m];
          bending += Ws[m] - W0[m] + tb[m] * P[m];
          multipliers += tb[m] * Pm[m];
          transport += Ks[m] - K0[m] - tb[m] * P[m] - tb[m] * Pm[m] + tb[m] * Db[m];
          area_volume += W[m] - Ws[m] + Kav[m] - Ks[m];
          momenta += K[m] - Kav[m];
          dB += F[m + 1] - F[m] + tau[m + 1] * D[m + 1];
        }
      const double split = bending + multipliers + transport + area_volume + momenta;
      std::printf("  over the run, relative to F(0) = %.6f:\n", F[0]);
      std::printf("    dB %.3e (the split's sum %s)\n", dB / F[0],
                  std::abs(split - dB) <= 1e-9 * std::abs(F[0]) ? "equal" : "different");
      std::printf("    dW of the solves %.3e, the bending force's work tau P %.3e: bending defect %.2e of |dW|\n",
                  dW / F[0], work / F[0], std::abs(bending / dW));
      std::printf("    multiplier work %.2e, transport defect %.2e, area/volume projection %.2e, momentum projection %.2e\n",
                  multipliers / F[0], transport / F[0], area_volume / F[0], momenta / F[0]);
    }
  std::filesystem::remove_all("run");
}
