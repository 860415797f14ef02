#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The energy budget of runs over one time window (burst.sh): per run the accepted steps ending in (t0, t1],
ΔF, ∫D = Σ τD^{m+1}, ΔB = ΔF + ∫D (> 0: the step put energy in), the steps with B rising, the largest D, the
largest growth rate of D over 0.05 time units (ln(D(t + 0.05)/D(t))/0.05, D linear between the rows), the mesh
quality at the end.
    /usr/bin/python3 benchmarks/energy_law/burst.py t0 t1 RUN_DIR ..."""
import bisect
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "phase3"))
import statistics_columns  # noqa: E402

sys.path.insert(0, os.path.dirname(__file__))
import budget  # noqa: E402


def growth_rate(t, D, k0, k1, span=0.05):
    """The largest ln(D(s + span)/D(s))/span over the rows k0..k1 (D linear in t between the rows)."""
    def at(s):
        j = bisect.bisect_left(t, s, k0, k1 + 1)
        if j <= k0:
            return D[k0]
        w = (s - t[j - 1]) / (t[j] - t[j - 1])
        return (1 - w) * D[j - 1] + w * D[j]
    rates = [math.log(at(t[k] + span) / D[k]) / span for k in range(k0, k1 + 1)
             if t[k] + span <= t[k1] and D[k] > 0 and at(t[k] + span) > 0]
    return max(rates, default=float("nan"))


def window(run, t0, t1):
    c = statistics_columns.read(os.path.join(run, "statistics"))
    t, tau, F, D = c["time"], c["tau"], c["total energy"], c["dissipation rate"]
    steps = [k for k in range(1, len(t)) if t0 < t[k] <= t1 + 1e-12]
    dB = [F[k] - F[k - 1] + tau[k] * D[k] for k in steps]
    return {"run": os.path.basename(run.rstrip("/")), "end": t[steps[-1]], "steps": len(steps),
            "dF": F[steps[-1]] - F[steps[0] - 1], "intD": sum(tau[k] * D[k] for k in steps), "dB": sum(dB),
            "rising": sum(x > 0 for x in dB), "max D": max(D[k] for k in steps),
            "rate": growth_rate(t, D, steps[0] - 1, steps[-1]),
            "quality": c["mesh quality"][steps[-1]],
            "split": budget.split(run, t0, t1) if os.path.exists(os.path.join(run, "energy_budget")) else None}


if __name__ == "__main__":
    t0, t1 = float(sys.argv[1]), float(sys.argv[2])
    print("| run | to t | steps | ΔF | ∫D | ΔB | steps with B rising | largest D | largest growth rate of D | "
          "mesh quality at the end |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    windows = [window(run, t0, t1) for run in sys.argv[3:]]
    for w in windows:
        print(f"| {w['run']} | {w['end']:.3f} | {w['steps']} | {w['dF']:+.3f} | {w['intD']:.3f} | {w['dB']:+.3f} | "
              f"{w['rising']} | {w['max D']:.2f} | {w['rate']:.1f} | {w['quality']:.3f} |")
    split = [w for w in windows if w["split"]]
    if split:
        print()
        print("| run | ΔB (energy_budget) | " + " | ".join(budget.TERMS) + " |")
        print("|" + "---|" * (2 + len(budget.TERMS)))
        for w in split:
            s = w["split"]
            print(f"| {w['run']} | {s['dB']:+.3f} | " + " | ".join(f"{s[n]:+.3f}" for n in budget.TERMS) + " |")
