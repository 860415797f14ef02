# SPDX-License-Identifier: LGPL-2.1-or-later
"""Issue 48: bar chart of the energy split of results.csv (benchmarks/energy_law).

    /usr/bin/python3 benchmarks/energy_law/plot.py [results.csv [energy_law.png]]

Left: the sums over the steps ending in t ∈ (2, 4] (the creep before the anchor at t = 4 and the plateau); right:
over (3.5, 4] (the plateau), for every case of results.csv with that interval. Each group: the terms of ΔF − (−∫D)
(symlog axis) and ΔB = ΔF + ∫D as a black mark: ΔB > 0 breaks the energy law.
Defaults: the files next to this script."""
import csv
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "results.csv")
out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "energy_law.png")
rows = list(csv.DictReader(open(src, newline="")))
TERMS = [("minus_int_D", "−∫D", "#1f77b4"), ("area_volume_proj", "area/vol. proj.", "#ff7f0e"),
         ("momentum_proj", "mom. proj.", "#2ca02c"), ("mu_work", "μ work", "#d62728"),
         ("s_gamma_work", "s,γ work", "#9467bd"), ("bending_defect", "bending defect", "#8c564b"),
         ("kinetic_defect", "kinetic defect", "#7f7f7f")]
panels = [("2", "4", "t ∈ (2, 4]"), ("3.5", "4", "t ∈ (3.5, 4]: plateau")]
fig, axes = plt.subplots(1, 2, figsize=(13, 6.2), gridspec_kw={"width_ratios": [6, 8]}, sharey=True)
width = 0.8 / len(TERMS)
for ax, (t0, t1, title) in zip(axes, panels):
    sel = [r for r in rows if r["t0"] == t0 and r["t1"] == t1]
    for j, (key, label, colour) in enumerate(TERMS):
        ax.bar([i - 0.4 + (j + 0.5) * width for i in range(len(sel))], [float(r[key]) for r in sel], width,
               label=label, color=colour)
    ax.plot(range(len(sel)), [float(r["dB"]) for r in sel], "k_", markersize=22, markeredgewidth=2.5, label="ΔB")
    ax.axhline(0, color="k", linewidth=0.6)
    ax.set_yscale("symlog", linthresh=1e-4)
    ax.set_xticks(range(len(sel)))
    ax.set_xticklabels([textwrap.fill(r["case"], 11) for r in sel], fontsize=7.5)
    ax.set_title(title, fontsize=10)
    ax.grid(axis="y", linewidth=0.3)
axes[0].set_ylabel("sum over the accepted steps (symlog, linear below 1e-4)")
handles, labels = axes[1].get_legend_handles_labels()
fig.legend(handles, labels, fontsize=8.5, ncol=len(labels), loc="lower center")
fig.suptitle("Energy split of scene full's step, v = 0.95, L₀ = 40, prolate start (issue 48; results.md)",
             fontsize=11)
fig.tight_layout(rect=(0, 0.05, 1, 1))
fig.savefig(out, dpi=110)
print(f"wrote {out}")
