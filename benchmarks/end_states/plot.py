#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/end_states: the phase diagram of end states, v against L₀, one panel per start (prolate, oblate);
marker by shape class, colour by F − W (the rotational energy |L|²/(2λ₃) of a rigid end state), a red edge for a
run that is not steady, and a ring around the points where the two starts end in different states (F differs by
more than 1e-3 relative, above the
refinement-3 spread of one state reached from the two starts, or the shape class differs, and both are steady). With
a class (`class` of classify.py or `end state class` of table.py) the ring is solid only where both end states are verified minima (bistability) and
dashed otherwise, a saddle gets a red cross, and with the stability chart's CSV the boundary L_c(v) of the spinning
oblate's minima (stability_chart/chart.csv) is drawn on both panels (interpolated between the L₀ columns).
    /usr/bin/python3 benchmarks/end_states/plot.py results.csv phase_diagram.png [chart.csv]"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

rows = [r for r in csv.DictReader(open(sys.argv[1])) if r.get("F")]
markers = {"sphere": "o", "prolate": "s", "oblate": "D", "triaxial": "^"}
l0s = sorted({float(r["L0"]) for r in csv.DictReader(open(sys.argv[1]))})
column = {L0: k for k, L0 in enumerate(l0s)}  # L₀ = 0, 5, 10, 20, 40 equally spaced
# The colour scale of the runs that ended (steady or at a plateau): a run stopped early is far from its end.
ended = [r for r in rows if r["status"] in ("steady", "plateau")] or rows
rotational = [float(r["F"]) - float(r["W"]) for r in ended] or [0.0]
norm = plt.Normalize(min(rotational), max(rotational))


def class_of(r):
    """classify.py's `class` or table.py's `end state class` (minimum …, saddle …, 3D …), "" without either."""
    return r.get("class") or r.get("end state class") or ""


def minimum(r):
    return class_of(r).startswith("minimum")


def column_of(L):
    """The x of angular momentum L between the equally spaced L₀ columns."""
    for k in range(len(l0s) - 1):
        if L <= l0s[k + 1]:
            return k + (L - l0s[k]) / (l0s[k + 1] - l0s[k])
    return len(l0s) - 1


boundary = []
if len(sys.argv) > 3:
    for c in csv.DictReader(open(sys.argv[3])):
        if c["branch"] == "oblate" and c["L_c isolated"] not in ("", "nan"):
            boundary.append((float(c["v"]), float(c["L_c isolated"])))


def differs(a, b):
    if a["status"] != "steady" or b["status"] != "steady":
        return False
    return a["shape"] != b["shape"] or abs(float(a["F"]) - float(b["F"])) > 1e-3 * abs(float(a["F"]))


by_point = {}
for r in rows:
    by_point.setdefault((r["v"], r["L0"]), {})[r["start"]] = r
fig, axes = plt.subplots(1, 2, figsize=(11, 4.8), sharey=True)
for ax, start in zip(axes, ("prolate", "oblate")):
    for r in (r for r in rows if r["start"] == start):
        x, y = column[float(r["L0"])], float(r["v"])
        ax.scatter([x], [y], marker=markers[r["shape"]], s=150, c=[float(r["F"]) - float(r["W"])], cmap="viridis",
                   norm=norm, edgecolors="black" if r["status"] == "steady" else "red", linewidths=1.5, zorder=3)
        if class_of(r).startswith("saddle"):
            ax.scatter([x], [y], marker="x", s=90, c="red", linewidths=2, zorder=4)
        pair = by_point[(r["v"], r["L0"])]
        if len(pair) == 2 and differs(pair["prolate"], pair["oblate"]):
            classified = "class" in r or "end state class" in r
            verified = not classified or (minimum(pair["prolate"]) and minimum(pair["oblate"]))
            ax.scatter([x], [y], marker="o", s=420, facecolors="none", edgecolors="tab:orange", linewidths=1.5,
                       linestyles="solid" if verified else "dashed", zorder=2)
    if boundary:
        points = sorted(boundary)
        ax.plot([column_of(L) for _, L in points], [v for v, _ in points], color="tab:red", zorder=1,
                label="L_c(v), spinning oblate")
    ax.set_xticks(range(len(l0s)), [f"{L0:g}" for L0 in l0s])
    ax.set_xlim(-0.5, len(l0s) - 0.5)
    ax.set_xlabel("L₀")
    ax.set_title(f"start: {start} spheroid")
    ax.grid(alpha=0.3)
axes[0].set_ylabel("reduced volume v")
axes[0].set_ylim(0.6, 1.0)
handles = [Line2D([], [], marker=m, linestyle="none", color="grey", markeredgecolor="black", markersize=9, label=s)
           for s, m in markers.items()]
handles += [Line2D([], [], marker="s", linestyle="none", color="grey", markeredgecolor="red", markersize=9,
                   label="not steady, or a plateau"),
            Line2D([], [], marker="o", linestyle="none", markerfacecolor="none", markeredgecolor="tab:orange",
                   markersize=14, label="starts end apart")]
if any(class_of(r) for r in rows):
    handles.append(Line2D([], [], marker="x", linestyle="none", color="red", markersize=9, label="saddle"))
if boundary:
    handles.append(Line2D([], [], color="tab:red", label="L_c(v) of the spinning oblate"))
fig.legend(handles=handles, loc="lower center", ncol=len(handles), fontsize=9)
fig.subplots_adjust(bottom=0.22, right=0.86)
fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap="viridis"), cax=fig.add_axes([0.89, 0.22, 0.02, 0.66]),
             label="F − W (rotational energy)")
fig.savefig(sys.argv[2], dpi=110)
