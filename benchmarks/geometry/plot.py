# SPDX-License-Identifier: LGPL-2.1-or-later
"""Plots benchmarks/geometry/results.csv: relative error against position DoFs (left) and against
wall time (right), log-log, one line per geometry degree k (colour) and quantity (line style);
prolate spheroid in the top row, oblate in the bottom row.

Usage: /usr/bin/python3 plot.py [results.csv] [geometry.png]
       /usr/bin/python3 plot.py --table [results.csv]   (prints the README's markdown table instead)
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
if len(sys.argv) > 1 and sys.argv[1] == "--table":
    rows = list(csv.DictReader(open(sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "results.csv"))))
    print("| shape | k | ref. | DoFs | area error | rate | volume error | rate | ½∫H² error | rate | wall time [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        cells = [r["shape"], r["k"], r["refinement"], r["dofs"]]
        for q in ("area", "volume", "willmore"):
            cells += [f"{float(r[q + '_error']):.2e}", f"{float(r[q + '_rate']):.2f}" if r[q + "_rate"] else ""]
        cells.append(f"{float(r['wall_time_s']):.3f}")
        print("| " + " | ".join(cells) + " |")
    sys.exit(0)
csv_file = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "results.csv")
png_file = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "geometry.png")

rows = list(csv.DictReader(open(csv_file)))
shapes = [("prolate", "prolate [0.61, 0.61, 2.02]"), ("oblate", "oblate [1.27, 1.27, 0.47]")]
quantities = [("area_error", "area", "-", "o"),
              ("volume_error", "volume", "--", "s"),
              ("willmore_error", "½∫H²", ":", "^")]
colours = {1: "tab:blue", 2: "tab:orange", 3: "tab:green"}

fig, axes = plt.subplots(2, 2, figsize=(12, 9.5), sharey=True)
for row_index, (shape, title) in enumerate(shapes):
    for k in (1, 2, 3):
        data = [r for r in rows if r["shape"] == shape and int(r["k"]) == k]
        if not data:
            continue
        dofs = [int(r["dofs"]) for r in data]
        times = [float(r["wall_time_s"]) for r in data]
        for key, name, style, marker in quantities:
            errors = [float(r[key]) for r in data]
            for column, x in ((0, dofs), (1, times)):
                axes[row_index][column].loglog(x, errors, linestyle=style, marker=marker, color=colours[k],
                                               markersize=5, label=f"k={k} {name}")
    # Reference slopes h^2, h^4, h^6 (h ~ DoFs^(-1/2)) on the DoF plot.
    ax = axes[row_index][0]
    n0, n1 = 1e3, 1e5
    for p, e0 in ((2, 3e-2), (4, 3e-4), (6, 3e-7)):
        ax.loglog([n0, n1], [e0, e0 * (n1 / n0) ** (-p / 2)], color="grey", linewidth=0.8)
        ax.annotate(f"$h^{p}$", (n1, e0 * (n1 / n0) ** (-p / 2)), color="grey", fontsize=9,
                    xytext=(3, 0), textcoords="offset points", va="center")
    axes[row_index][0].set_title(f"{title}: error against DoFs")
    axes[row_index][1].set_title(f"{title}: error against wall time")
    axes[row_index][0].set_xlabel("position DoFs")
    axes[row_index][1].set_xlabel("wall time of create + measure + willmore_energy [s] (median of 3)")
    axes[row_index][0].set_ylabel("relative error")
    for ax in axes[row_index]:
        ax.grid(True, which="major", alpha=0.4)
        ax.grid(True, which="minor", alpha=0.1)
axes[0][1].legend(fontsize=8, ncol=3, loc="lower left")
fig.suptitle("SurfaceGeometry work–precision: Q_k geometry of spheroids (colour: k; line: quantity)")
fig.tight_layout()
fig.savefig(png_file, dpi=110)
print(f"wrote {png_file}")
