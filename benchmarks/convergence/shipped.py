#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/convergence: a shipped file's figures against refinement (issue 50, item 4).

    shipped.py OUT.csv REFINEMENT=RUN ...      (at least two; RUN: a run folder, or X for a committed X.summary)

One row per figure and refinement: the value, its change to the next refinement, and where three refinements
differ monotonically the observed order p = log2(|f_r − f_{r+1}| / |f_{r+1} − f_{r+2}|) with the Richardson estimate
of the error of the finest. The growth rate of the symmetry deviation between t_sym_1e-4 and t_sym_1e-2 is
σ = ln(100)/(t_sym_1e-2 − t_sym_1e-4): the leading mode's rate once it dominates (the prolate's m = 2)."""
import csv
import math
import os
import sys

FIGURES = [("t_sym_1e-4", "t_sym_1e-4"), ("t_sym_1e-2", "t_sym_1e-2"), ("sigma", None),
           ("mean angular velocity", "mean angular velocity"),
           ("min L2 distance to equilibrium", "min L2 distance to equilibrium"),
           ("final total energy", "final total energy"), ("final angular velocity", "final angular velocity")]


def summary(folder):
    """The summary of a run folder, or the file FOLDER.summary (a committed one)."""
    values = {}
    path = f"{folder}/summary" if os.path.isdir(folder) else f"{folder}.summary"
    for line in open(path):
        key, _, value = line.partition(":")
        values[key.strip()] = value.strip()
    return values


def figures(folder):
    s = summary(folder)
    out = {}
    for name, key in FIGURES:
        if key:
            try:
                out[name] = float(s[key])
            except (KeyError, ValueError):
                out[name] = float("nan")
    out["sigma"] = math.log(100) / (out["t_sym_1e-2"] - out["t_sym_1e-4"])
    return out


def main():
    out_path, runs = sys.argv[1], sorted((int(a.split("=", 1)[0]), a.split("=", 1)[1]) for a in sys.argv[2:])
    values = {r: figures(folder) for r, folder in runs}
    levels = [r for r, _ in runs]
    with open(out_path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["figure", "refinement", "value", "change to next", "observed order", "Richardson error of finest"])
        for name, _ in FIGURES:
            for i, r in enumerate(levels):
                v = values[r][name]
                change = values[levels[i + 1]][name] - v if i + 1 < len(levels) else ""
                order = error = ""
                if i + 2 < len(levels):
                    d1, d2 = values[levels[i + 1]][name] - v, values[levels[i + 2]][name] - values[levels[i + 1]][name]
                    if d1 * d2 > 0 and abs(d2) < abs(d1):
                        p = math.log2(abs(d1) / abs(d2))
                        order, error = f"{p:.2f}", f"{d2 / (2 ** p - 1):.3g}"
                w.writerow([name, r, f"{v:.10g}", change if change == "" else f"{change:.3g}", order, error])
    print(open(out_path).read())


if __name__ == "__main__":
    main()
