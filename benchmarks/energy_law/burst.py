#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The energy budget of runs over one time window (burst.sh): per run the accepted steps ending in (t0, t1],
ΔF, ∫D = Σ τD^{m+1}, ΔB = ΔF + ∫D (> 0: the step put energy in), the steps with B rising, the largest D, the mesh
quality at the end.
    /usr/bin/python3 benchmarks/energy_law/burst.py t0 t1 RUN_DIR ..."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "phase3"))
import statistics_columns  # noqa: E402


def window(run, t0, t1):
    c = statistics_columns.read(os.path.join(run, "statistics"))
    t, tau, F, D = c["time"], c["tau"], c["total energy"], c["dissipation rate"]
    steps = [k for k in range(1, len(t)) if t0 < t[k] <= t1 + 1e-12]
    dB = [F[k] - F[k - 1] + tau[k] * D[k] for k in steps]
    return {"run": os.path.basename(run.rstrip("/")), "end": t[steps[-1]], "steps": len(steps),
            "dF": F[steps[-1]] - F[steps[0] - 1], "intD": sum(tau[k] * D[k] for k in steps), "dB": sum(dB),
            "rising": sum(x > 0 for x in dB), "max D": max(D[k] for k in steps),
            "quality": c["mesh quality"][steps[-1]]}


if __name__ == "__main__":
    t0, t1 = float(sys.argv[1]), float(sys.argv[2])
    print("| run | to t | steps | ΔF | ∫D | ΔB | steps with B rising | largest D | mesh quality at the end |")
    print("|---|---|---|---|---|---|---|---|---|")
    for run in sys.argv[3:]:
        w = window(run, t0, t1)
        print(f"| {w['run']} | {w['end']:.3f} | {w['steps']} | {w['dF']:+.3f} | {w['intD']:.3f} | {w['dB']:+.3f} | "
              f"{w['rising']} | {w['max D']:.2f} | {w['quality']:.3f} |")
