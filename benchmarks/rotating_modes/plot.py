# SPDX-License-Identifier: LGPL-2.1-or-later
"""rotating_modes.png: the measured growth rate of each seeded mode against τ, per scheme and frame, beside the
linearized rate σ and the one-mode prediction.

    /usr/bin/python3 benchmarks/rotating_modes/plot.py [results.csv ...]
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
files = sys.argv[1:] or [os.path.join(here, f) for f in ("results.csv", "results_predictor.csv")
                         if os.path.exists(os.path.join(here, f))]
rows = [r for f in files for r in csv.DictReader(open(f))]
cases = sorted({(r["shape"], r["m"], r["parity"], r["refinement"]) for r in rows})
fig, axes = plt.subplots(1, len(cases), figsize=(4.2 * len(cases), 3.8), squeeze=False)
styles = {("be", "lab"): ("C0", "o", "backward Euler, lab"), ("be", "Tisserand"): ("C1", "s", "backward Euler, co-rotating"),
          ("bdf2s", "lab"): ("C2", "^", "BDF2, lab, from S^m"), ("bdf2s", "Tisserand"): ("C3", "D", "BDF2, co-rotating, from S^m"),
          ("bdf2", "Tisserand"): ("C4", "v", "BDF2, co-rotating, linear predictor (shipped)"),
          ("bdf2q", "Tisserand"): ("C5", "x", "BDF2, co-rotating, quadratic predictor"),
          ("bdf2n", "Tisserand"): ("C6", "P", "BDF2, co-rotating, quadratic normal predictor")}
for ax, case in zip(axes[0], cases):
    sel = [r for r in rows if (r["shape"], r["m"], r["parity"], r["refinement"]) == case]
    sigma = float(sel[-1]["linearized rate"])  # the last file's σ: that of the settled base state
    ax.axhline(sigma, color="k", lw=0.8, label=f"linearized σ = {sigma:.4f}")
    for key, (color, marker, label) in styles.items():
        pts = sorted((float(r["tau"]), float(r["measured rate"]), float(r["predicted rate"]))
                     for r in sel if (r["scheme"], r["frame"]) == key)
        if not pts:
            continue
        ax.plot([p[0] for p in pts], [p[1] for p in pts], color=color, marker=marker, label=label)
        ax.plot([p[0] for p in pts], [p[2] for p in pts], color=color, ls=":", lw=0.8)
    ax.set_xscale("log")
    ax.set_xlabel("τ")
    ax.set_title(f"{case[0]} m = {case[1]} {case[2]}, refinement {case[3]}", fontsize=9)
axes[0][0].set_ylabel("growth rate of |Q_m| (dotted: one-mode prediction)")
axes[0][-1].legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(here, "rotating_modes.png"), dpi=120)
