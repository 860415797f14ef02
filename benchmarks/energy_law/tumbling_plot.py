#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""B(t) − B(0) (B = F + ∫D, trapezoidal) and the momentum multipliers |μ| of the tumbling start before and after the
fix of the momentum rows (tumbling_budget.csv) → tumbling.png.

    /usr/bin/python3 benchmarks/energy_law/tumbling_plot.py [tumbling_budget.csv] [tumbling.png]
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
source = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "tumbling_budget.csv")
target = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "tumbling.png")
runs = {}
for row in csv.DictReader(open(source)):
    runs.setdefault((row["step"], row["name"]), []).append(row)
fig, (ax_b, ax_mu) = plt.subplots(1, 2, figsize=(11, 4))
for (step, name), rows in runs.items():
    t = [float(r["t"]) for r in rows]
    b = [float(r["B"]) for r in rows]
    mu = [max(float(r["rigid multiplier"]), 1e-8) for r in rows]
    style = "--" if step == "f0c166e" else "-"
    label = f"{name} ({'before' if step == 'f0c166e' else 'after'}, {step})"
    ax_b.plot(t, [x - b[0] for x in b], style, label=label)
    ax_mu.semilogy(t, mu, style, label=label)
ax_b.set_xlabel("t")
ax_b.set_ylabel("B(t) − B(0),  B = F + ∫D")
ax_b.axhline(0, color="gray", lw=0.5)
ax_mu.set_xlabel("t")
ax_mu.set_ylabel("|μ| (rigid multiplier)")
ax_b.legend(fontsize=7)
fig.suptitle("tests/energy_law_tumbling's start (17° tilt, ω₀ = 4): the energy law before and after the fix")
fig.tight_layout()
fig.savefig(target, dpi=110)
