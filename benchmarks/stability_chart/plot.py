#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The stability chart (chart.py's scan.csv and chart.csv) → chart.png: the sign of the lowest eigenvalue of the
second variation at fixed A, V, L over (v, L) for both branches, with L_c(v).

    /usr/bin/python3 benchmarks/stability_chart/plot.py [DIRECTORY]     (default: this benchmark's directory)
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
scan = list(csv.DictReader(open(os.path.join(here, "scan.csv"))))
chart = list(csv.DictReader(open(os.path.join(here, "chart.csv"))))
fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
for ax, branch in zip(axes, ["oblate", "prolate"]):
    rows = [r for r in scan if r["branch"] == branch]
    for sign, colour, label in [(1, "tab:blue", "minimum (all λ > 0)"), (-1, "tab:red", "saddle (some λ < 0)")]:
        pts = [(float(r["v"]), float(r["L"])) for r in rows if (float(r["isolated"]) > 0) == (sign > 0)]
        if pts:
            ax.scatter(*zip(*pts), s=10, color=colour, label=label)
    crit = [(float(r["v"]), float(r["L_c isolated"])) for r in chart
            if r["branch"] == branch and r["L_c isolated"].replace(".", "", 1).isdigit()]
    if crit:
        ax.plot(*zip(*sorted(crit)), "k-", lw=1, label="L_c(v)")
    ax.set_title(f"{branch} branch, spinning about its symmetry axis")
    ax.set_xlabel("reduced volume v")
axes[0].set_ylabel("angular momentum L (A = 4π, Be = 1)")
axes[0].legend(fontsize=8)
fig.suptitle("second variation of W + ½L·I⁻¹L at fixed A, V, L (fluid_surface --equilibrium)")
fig.tight_layout()
fig.savefig(os.path.join(here, "chart.png"), dpi=110)
