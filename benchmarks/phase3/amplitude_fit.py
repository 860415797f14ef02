# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/phase3: t_sym against the seed amplitude ε (amplitude.csv). A mode growing at σ from e(0) ∝ ε reaches
e = 1e-2 at t_sym = c − ln(ε)/σ: a line in ln ε of slope −1/σ. Fits it per shape and t_sym level (least squares over
the cases that reached it), prints the σ it implies, and what the paper's t_sym imply about the size of its own
perturbation, ε_paper = ε_ref exp(−σ (t_paper − t_ref)), given σ.

    amplitude_fit.py amplitude.csv [refinement] > amplitude_fit.csv
"""
import csv
import math
import sys

rows = [r for r in csv.DictReader(open(sys.argv[1]))]
refinement = sys.argv[2] if len(sys.argv) > 2 else None
print("shape,level,cases,slope d t_sym / d ln eps,implied sigma,paper t_sym,eps implied by the paper")
for shape in sorted({r["shape"] for r in rows}):
    for level in ("t_sym_1e-4", "t_sym_1e-2"):
        pts = []
        for r in rows:
            if r["shape"] != shape or (refinement and r["refinement"] != refinement):
                continue
            try:
                eps, t = float(r["epsilon"]), float(r[level])
            except ValueError:
                continue
            if eps > 0:
                pts.append((math.log(eps), t))
        if len(pts) < 2:
            continue
        n = len(pts)
        sx, sy = sum(p[0] for p in pts), sum(p[1] for p in pts)
        sxx, sxy = sum(p[0] ** 2 for p in pts), sum(p[0] * p[1] for p in pts)
        slope = (n * sxy - sx * sy) / (n * sxx - sx * sx)
        intercept = (sy - slope * sx) / n
        paper = float(next(r for r in rows if r["shape"] == shape)["paper " + level])
        eps_paper = math.exp((paper - intercept) / slope)
        print(f"{shape},{level},{n},{slope:.4f},{-1 / slope:.4f},{paper},{eps_paper:.2e}")
