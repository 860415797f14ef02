#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Routes (a) and (b) of issue 49, item 3: where the spinning equilibrium of one branch and v stops being stable.

    /usr/bin/python3 benchmarks/stability_chart/routes.py ROUTES_STABILITY_CSV [CHART_CSV] [OUT_MD]

(a) is L_c of the second variation (chart.csv, bisected to its stated resolution); (b) is the zero of scene
stability's leading growth rate σ(L) of the class (routes.sh), by linear interpolation between the two L that
bracket it (by extrapolation from the two nearest if none does, marked so). One row per (branch, v, refinement, τ),
with σ at every L, written as a Markdown table (default: stdout).
"""
import csv
import sys
from collections import defaultdict

rows_csv = sys.argv[1]
chart_csv = sys.argv[2] if len(sys.argv) > 2 else "benchmarks/stability_chart/chart.csv"
out = sys.argv[3] if len(sys.argv) > 3 else None

chart = {}
with open(chart_csv) as f:
    for row in csv.DictReader(f):
        chart[(row["branch"], float(row["v"]))] = (float(row["L_c isolated"]), row["class isolated"],
                                                   row["how isolated"])

leading = defaultdict(dict)
classes = {}
with open(rows_csv) as f:
    for row in csv.DictReader(f):
        key = (row["branch"], float(row["v"]), int(row["refinement"]), float(row["tau"]))
        L, sigma = float(row["L"]), float(row["growth rate"])
        classes[key] = f"m = {row['m']} {row['parity']}"
        if L not in leading[key] or sigma > leading[key][L][0]:
            leading[key][L] = (sigma, float(row["frequency"]), float(row["residual"]))


def zero(points):
    """L where σ(L) crosses zero, and how it was found."""
    points = sorted(points)
    for (L0, s0), (L1, s1) in zip(points, points[1:]):
        if s0 <= 0 <= s1 or s1 <= 0 <= s0:
            return L0 - s0 * (L1 - L0) / (s1 - s0), "interpolated"
    if len(points) < 2:
        return float("nan"), "one L only"
    near = sorted(points, key=lambda p: abs(p[1]))[:2]
    (L0, s0), (L1, s1) = sorted(near)
    return L0 - s0 * (L1 - L0) / (s1 - s0), "extrapolated"


lines = ["| branch | v | class | refinement | τ | σ(L) (frequency) | L_c (b) | how | L_c (a) | (b)/(a) − 1 |",
         "|---|---|---|---|---|---|---|---|---|---|"]
for key in sorted(leading):
    branch, v, r, tau = key
    points = [(L, s[0]) for L, s in leading[key].items()]
    Lc, how = zero(points)
    a = chart.get((branch, v))
    sigmas = ", ".join(f"{L:g}: {s:+.5f} ({w:.1e})" for L, (s, w, _) in sorted(leading[key].items()))
    La = f"{a[0]:.4f}" if a else "—"
    diff = f"{Lc / a[0] - 1:+.4f}" if a and a[0] > 0 else "—"
    lines.append(f"| {branch} | {v:g} | {classes[key]} | {r} | {tau:g} | {sigmas} | {Lc:.4f} | {how} | {La} | {diff} |")
text = "\n".join(lines) + "\n"
if out:
    with open(out, "w") as f:
        f.write(text)
print(text, end="")
