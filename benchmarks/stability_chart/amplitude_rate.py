#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Super- or subcritical (issue 49, item 2): the growth rate of the seeded mode as a function of its amplitude.

    /usr/bin/python3 benchmarks/stability_chart/amplitude_rate.py [--sigma S] [--fit AMAX] OUT_CSV OUT_PNG LABEL=RUN ...

Each RUN is a run directory of routes_full.sh (azimuthal diagnostics on). The amplitude a = |Q_m| of the seeded mode
(statistics column `mode <m> <parity> amplitude`, m and parity from the directory name) is cut into windows in which
ln a grows by 0.1; each window gives the rate Δln a/Δt at its geometric-mean amplitude and its mid time. Near a
pitchfork the amplitude obeys da/dt = σa + g a³ + …: a rate that rises above σ as a grows (g > 0) is a subcritical
bifurcation, one that falls below it (g < 0) a supercritical one. A rate that depends on the time since the start
rather than on a is the seed's transient; runs from different seeds tell the two apart: where their rates agree at
equal a and differ at equal t, the dependence is the nonlinearity. The first RUN (the smallest seed) is the
reference: each other run's excess rate over it at the same t (its rate interpolated in t) is written against a²,
whose slope is g. --sigma draws the linear rate σ of scene `stability` (route (b)) as a line.

--fit AMAX: a seed of amplitude A also starts slow axisymmetric (m = 0) motion of order A², which shifts the rate
while it decays; the excesses with a ≤ AMAX are fitted, by least squares, to c_run e^{−t/T} + g a² + h a⁴ (c per run;
T, g, h shared; T scanned), and g, h, T and the c are printed.
"""
import csv
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "phase3"))
import statistics_columns  # noqa: E402

args = sys.argv[1:]
sigma, fit_limit = None, None
while args and args[0] in ("--sigma", "--fit"):
    if args[0] == "--sigma":
        sigma = float(args[1])
    else:
        fit_limit = float(args[1])
    args = args[2:]
out_csv, out_png, runs = args[0], args[1], [a.split("=", 1) for a in args[2:]]

rows = []
for label, run in runs:
    m = re.search(r"_m(\d+)(even|odd)$", os.path.basename(os.path.normpath(run)))
    column = f"mode {m.group(1)} {m.group(2)} amplitude" if m else "mode 2 even amplitude"
    c = statistics_columns.read(os.path.join(run, "statistics"))
    t, a = c["time"], c[column]
    k0 = next(k for k in range(len(t)) if t[k] >= 1 and a[k] > 0)  # past the start's first transient
    for k in range(k0 + 1, len(t)):
        if a[k] <= 0 or abs(math.log(a[k] / a[k0])) < 0.1:
            continue
        rows.append({"run": label, "t0": f"{t[k0]:.4f}", "t1": f"{t[k]:.4f}",
                     "amplitude": f"{math.sqrt(a[k] * a[k0]):.5e}",
                     "rate": f"{math.log(a[k] / a[k0]) / (t[k] - t[k0]):.6f}"})
        k0 = k

def mid(r):
    return 0.5 * (float(r["t0"]) + float(r["t1"]))


reference = [(mid(r), float(r["rate"])) for r in rows if r["run"] == runs[0][0]]
for r in rows:
    t = mid(r)
    r["excess over the first run at equal t"] = ""
    if r["run"] != runs[0][0] and reference and reference[0][0] <= t <= reference[-1][0]:
        k = next(k for k in range(1, len(reference)) if reference[k][0] >= t)
        (ta, ra), (tb, rb) = reference[k - 1], reference[k]
        r["excess over the first run at equal t"] = f"{float(r['rate']) - (ra + (rb - ra) * (t - ta) / (tb - ta)):.6f}"

with open(out_csv, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=["run", "t0", "t1", "amplitude", "rate", "excess over the first run at equal t"])
    w.writeheader()
    w.writerows(rows)

if fit_limit is not None:
    import numpy as np

    points = [r for r in rows if r["excess over the first run at equal t"] and float(r["amplitude"]) <= fit_limit]
    labels = sorted({r["run"] for r in points})
    y = np.array([float(r["excess over the first run at equal t"]) for r in points])
    a2 = np.array([float(r["amplitude"]) ** 2 for r in points])
    tm = np.array([mid(r) for r in points])
    best = None
    for T in np.arange(10.0, 1000.0, 1.0):
        columns = [np.exp(-tm / T) * np.array([r["run"] == l for r in points]) for l in labels] + [a2, a2 ** 2]
        design = np.vstack(columns).T
        coefficients = np.linalg.lstsq(design, y, rcond=None)[0]
        residual = float(np.sum((design @ coefficients - y) ** 2))
        if best is None or residual < best[0]:
            best = (residual, T, coefficients)
    residual, T, coefficients = best
    print(f"fit over a <= {fit_limit} ({len(points)} windows): g = {coefficients[-2]:.5f}, h = {coefficients[-1]:.4f}, "
          f"T = {T:.0f}, " + ", ".join(f"c({l}) = {c:.3e}" for l, c in zip(labels, coefficients[:-2])) +
          f", rms {np.sqrt(residual / len(points)):.2e}")

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, (left, right, third) = plt.subplots(1, 3, figsize=(15, 4))
for label, _ in runs:
    mine = [r for r in rows if r["run"] == label]
    left.semilogx([float(r["amplitude"]) for r in mine], [float(r["rate"]) for r in mine], ".-", label=label)
    right.plot([mid(r) for r in mine], [float(r["rate"]) for r in mine], ".-", label=label)
    excess = [r for r in mine if r["excess over the first run at equal t"] and float(r["amplitude"]) <= 0.3]
    third.plot([float(r["amplitude"]) ** 2 for r in excess],
               [float(r["excess over the first run at equal t"]) for r in excess], ".", label=label)
for ax in (left, right):
    if sigma is not None:
        ax.axhline(sigma, color="k", lw=0.8, ls="--", label="σ of scene stability")
    ax.set_ylabel("growth rate d ln|Q| / dt")
    ax.grid(alpha=0.3)
    if sigma is not None:
        ax.set_ylim(0.5 * sigma, 3 * sigma)
left.set_xlabel("amplitude |Q| of the seeded mode")
right.set_xlabel("t")
left.legend(fontsize=8)
third.set_xlabel("a² = |Q|² (a ≤ 0.3)")
third.set_ylabel(f"rate − rate of {runs[0][0]} at equal t")
third.axhline(0, color="k", lw=0.8)
third.grid(alpha=0.3)
third.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out_png, dpi=120)
for r in rows[:: max(1, len(rows) // 40)]:
    print(r)
