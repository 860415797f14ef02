# SPDX-License-Identifier: LGPL-2.1-or-later
"""amplitude.csv and amplitude.png from the cases of amplitude.sh: python3 amplitude_plot.py DIR CSV PNG."""
import glob
import os
import sys

import statistics_columns

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

directory, csv_path, png_path = sys.argv[1:4]
paper = {"prolate": (11.6, 16.0), "oblate": (0.9, 3.1)}


def summary(path):
    values = {}
    try:
        for line in open(path):
            key, _, value = line.partition(": ")
            values[key.strip()] = value.strip()
    except OSError:
        pass
    return values


rows = ["case,shape,refinement,epsilon,e(0),t reached,t_sym_1e-4,t_sym_1e-2,paper t_sym_1e-4,paper t_sym_1e-2,"
        "mean angular velocity (window),steps,rejected,status"]
shapes = sorted({os.path.basename(p).split("_")[0] for p in glob.glob(os.path.join(directory, "*.statistics"))})
fig, axes = plt.subplots(1, len(shapes), figsize=(5.5 * len(shapes), 4), squeeze=False)
for ax, shape in zip(axes[0], shapes):
    paths = glob.glob(os.path.join(directory, shape + "_*.statistics"))
    for path in sorted(paths, key=lambda p: float(p.rsplit("_", 1)[1].replace(".statistics", ""))):
        name = os.path.basename(path).replace(".statistics", "")
        _, r, eps = name.split("_")
        c = statistics_columns.read(path)
        s = summary(path.replace(".statistics", ".summary"))
        status = s.get("status", "completed" if s else "no summary")
        rows.append(",".join([name, shape, r[1:], eps, f"{c['symmetry deviation'][0]:.2e}", f"{c['time'][-1]:.4g}",
                              s.get("t_sym_1e-4", "?"), s.get("t_sym_1e-2", "?"), *map(str, paper[shape]),
                              s.get("mean angular velocity", "?"), s.get("steps", str(len(c["time"]) - 1)),
                              s.get("rejected steps", "?"), '"' + status + '"']))
        ax.semilogy(c["time"], [max(e, 1e-17) for e in c["symmetry deviation"]], label=f"ε = {eps}")
    for level, t in zip((1e-4, 1e-2), paper[shape]):
        ax.plot([t], [level], "k*", ms=9)
    ax.axhline(1e-4, color="0.7", lw=0.6)
    ax.axhline(1e-2, color="0.7", lw=0.6)
    ax.set_title(f"prm/{shape}.prm, shape perturbation ε (★ the paper's t_sym)", fontsize=9)
    ax.set_xlabel("t")
    ax.set_ylabel("symmetry deviation e(λ)")
    ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(png_path, dpi=110)
open(csv_path, "w").write("\n".join(rows) + "\n")
