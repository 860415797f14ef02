#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Route (c) of issue 49, item 3: the runs of routes_full.sh, one row each.

    /usr/bin/python3 benchmarks/stability_chart/routes_full.py WORK [WORK ...] OUT_CSV

Per run (full_<branch>_v<v>_L<L>_r<r>_m<m><parity>): the seed's amplitude (its prm), the rate of the symmetry deviation e(λ) (least squares of ln e
over t ∈ [2, 40], where the seeded mode is linear), the end time, the summary's steady-state verdict, and the end
state: F, W, ω, the inertia eigenvalues, the shape (end_states/table.py's classes) and ∫D/|F| over the last unit of
time (the steady-state test's dissipation).
"""
import csv
import glob
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "phase3"))
import statistics_columns  # noqa: E402

rows = []
for run in sorted(p for work in sys.argv[1:-1] for p in glob.glob(os.path.join(work, "full_*"))):
    m = re.match(r"full_([a-z]+)_v([0-9.]+)_L([0-9.]+)_r(\d+)_m(\d+)(even|odd)$", os.path.basename(run))
    if not m or not os.path.isdir(run):
        continue
    branch, v, L, r, mode, parity = m.groups()
    amplitude = re.search(r"set shape perturbation = (\S+)", open(run + ".prm").read()).group(1)
    c = statistics_columns.read(os.path.join(run, "statistics"))
    t, e = c["time"], c["symmetry deviation"]
    fit = [(t[k], math.log(e[k])) for k in range(len(t)) if 2 <= t[k] <= 40 and e[k] > 0]
    n = len(fit)
    mt, me = sum(p[0] for p in fit) / n, sum(p[1] for p in fit) / n
    rate = sum((p[0] - mt) * (p[1] - me) for p in fit) / sum((p[0] - mt) ** 2 for p in fit)
    summary = open(os.path.join(run, "summary")).read() if os.path.exists(os.path.join(run, "summary")) else ""
    verdict = re.search(r"^steady state: (reached|plateau|not reached)", summary, re.M)
    stopped = re.match(r"status: stopped at t = (\S+): terminated", summary)
    lam = sorted(c[f"inertia eigenvalue {k}"][-1] for k in (1, 2, 3))
    shape = ("sphere" if lam[2] - lam[0] < 1e-2 * lam[2] else "prolate" if lam[2] - lam[1] < 1e-2 * lam[2]
             else "oblate" if lam[1] - lam[0] < 1e-2 * lam[2] else "triaxial")
    window = [k for k in range(len(t)) if t[k] > t[-1] - 1]
    span = t[-1] - t[window[0] - 1]
    dissipation = sum(c["tau"][k] * c["dissipation rate"][k] for k in window) / (span * abs(c["total energy"][-1]))
    rows.append({"branch": branch, "v": v, "L": L, "refinement": r, "mode": f"m = {mode} {parity}", "amplitude": amplitude,
                 "rate of e(lambda), t in [2, 40]": f"{rate:.4f}", "end time": f"{t[-1]:.5g}",
                 "verdict": "interrupted" if stopped else verdict.group(1) if verdict else "running",
                 "F start": f"{c['total energy'][0]:.8g}", "F end": f"{c['total energy'][-1]:.8g}",
                 "W end": f"{c['bending energy'][-1]:.8g}", "omega end": f"{c['angular velocity'][-1]:.6g}",
                 "lambda1": f"{lam[0]:.6g}", "lambda2": f"{lam[1]:.6g}", "lambda3": f"{lam[2]:.6g}",
                 "shape": shape, "end dissipation (rel.)": f"{dissipation:.2e}"})
with open(sys.argv[-1], "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
    w.writeheader()
    w.writerows(rows)
for row in rows:
    print(row)
