# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/spectrum: |Q_m| of the seeded runs (less the unperturbed run's) against t, one panel per shape, with
the fitted growth on its window. Arguments: the work folder, the output png, the shapes."""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "phase3"))
import statistics_columns  # noqa: E402
from fit_modes import fit, interpolate, moment  # noqa: E402

work, png, shapes = sys.argv[1], sys.argv[2], sys.argv[3:]
fig, axes = plt.subplots(1, len(shapes), figsize=(6 * len(shapes), 4), squeeze=False)
for ax, shape in zip(axes[0], shapes):
    baseline = os.path.join(work, f"{shape}_baseline")
    b = statistics_columns.read(os.path.join(baseline, "statistics"))
    for m in range(1, 5):
        for parity, style in (("even", "-"), ("odd", "--")):
            run = os.path.join(work, f"{shape}_m{m}_{parity}")
            if not os.path.exists(os.path.join(run, "statistics")):
                continue
            c = statistics_columns.read(os.path.join(run, "statistics"))
            name = f"mode {m} {parity}"
            qb = moment(b, name)
            q = [v - interpolate(b["time"], qb, s) for v, s in zip(moment(c, name), c["time"])]
            line, = ax.semilogy(c["time"], [abs(v) for v in q], style, lw=1,
                                label=f"m = {m} {parity}")
            r = fit(run, m, parity, None, baseline)
            i0 = min(range(len(c["time"])), key=lambda i: abs(c["time"][i] - r["t0"]))
            ax.semilogy([r["t0"], r["t1"]], [abs(q[i0]), abs(q[i0]) * math.exp(r["sigma"] * (r["t1"] - r["t0"]))],
                        ":", color=line.get_color(), lw=2)
    ax.set_title(f"{shape} equilibrium: seeded modes (dotted: fitted growth)", fontsize=9)
    ax.set_xlabel("t")
    ax.set_ylabel("|Q_m − Q_m(unperturbed)|")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
fig.tight_layout()
fig.savefig(png, dpi=120)
