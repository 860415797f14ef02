#!/usr/bin/env python3
"""benchmarks/end_states: the phase diagram of end states, v against L₀, one panel per start (prolate, oblate);
marker by shape class, colour by F − W (the rotational energy |L|²/(2λ₃) of a rigid end state).
    /usr/bin/python3 benchmarks/end_states/plot.py results.csv phase_diagram.png"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

rows = [r for r in csv.DictReader(open(sys.argv[1])) if r.get("F")]
markers = {"sphere": "o", "prolate": "s", "oblate": "D", "triaxial": "^"}
values = [float(r["F"]) - float(r["W"]) for r in rows] or [0.0]
fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), sharey=True)
for ax, start in zip(axes, ("prolate", "oblate")):
    for shape, marker in markers.items():
        sel = [r for r in rows if r["start"] == start and r["shape"] == shape]
        if not sel:
            continue
        sc = ax.scatter([float(r["L0"]) for r in sel], [float(r["v"]) for r in sel], marker=marker, s=120,
                        c=[float(r["F"]) - float(r["W"]) for r in sel], cmap="viridis", vmin=min(values),
                        vmax=max(values), edgecolors=["black" if r["status"] == "steady" else "red" for r in sel],
                        label=shape)
    ax.set_xlabel("L₀")
    ax.set_title(f"from a {start} spheroid (red edge: not steady)")
    ax.legend(fontsize=8, loc="lower right")
axes[0].set_ylabel("reduced volume v")
fig.colorbar(plt.cm.ScalarMappable(norm=plt.Normalize(min(values), max(values)), cmap="viridis"), ax=axes,
             label="F − W")
fig.savefig(sys.argv[2], dpi=110)
