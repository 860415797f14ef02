# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/output_formats: median write time and bytes per output step, VTU against HDF5 → output_formats.png;
prints the README table."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1] if len(sys.argv) > 1 else "benchmarks/output_formats"
rows = list(csv.DictReader(open(out + "/results.csv")))
cases = sorted({(int(r["refinement"]), int(r["ranks"])) for r in rows})
row = {(int(r["refinement"]), int(r["ranks"]), r["format"]): r for r in rows}
fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
for f, fmt in enumerate(["vtu", "hdf5"]):
    x = [c + 0.4 * f for c in range(len(cases))]
    axes[0].bar(x, [float(row[(*c, fmt)]["median_s"]) for c in cases], width=0.4, label=fmt, color=f"C{f}")
    axes[1].bar(x, [int(row[(*c, fmt)]["bytes_per_step"]) / 1e6 for c in cases], width=0.4, label=fmt, color=f"C{f}")
for ax, label in zip(axes, ["write time per step [s] (median)", "size per step [MB]"]):
    ax.set_xticks([c + 0.2 for c in range(len(cases))])
    ax.set_xticklabels([f"ref {r}\n{n} rank{'s' if n > 1 else ''}" for r, n in cases])
    ax.set_ylabel(label)
    ax.legend(fontsize=8)
fig.suptitle("one output step of the ellipsoid (Q2, 2×2 curved sub-cells, 14 components)")
fig.tight_layout()
fig.savefig(out + "/output_formats.png", dpi=110)
print("| refinement | cells | ranks | VTU write [s] | HDF5 write [s] | VTU bytes/step | HDF5 bytes/step | HDF5/VTU size |")
print("|---|---|---|---|---|---|---|---|")
for r, n in cases:
    v, h = row[(r, n, "vtu")], row[(r, n, "hdf5")]
    print(f"| {r} | {v['cells']} | {n} | {float(v['median_s']):.3f} ({float(v['min_s']):.3f}–{float(v['max_s']):.3f}) | "
          f"{float(h['median_s']):.3f} ({float(h['min_s']):.3f}–{float(h['max_s']):.3f}) | "
          f"{int(v['bytes_per_step']):,} | {int(h['bytes_per_step']):,} | "
          f"{int(h['bytes_per_step']) / int(v['bytes_per_step']):.1f} |")
