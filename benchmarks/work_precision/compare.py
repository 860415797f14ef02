#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Tabulates run summaries against a reference run's (benchmarks/work_precision, issue 33, item 3).

    benchmarks/work_precision/compare.py <summary directory> <reference run> <run> ... > table.csv

Each run is <summary directory>/<run>.summary. Columns: status, steps, rejected steps, LU factorizations, wall time,
then t_sym_1e-4, t_sym_1e-2, the mean angular velocity ⟨ω⟩ of the prm's window, the final total energy F and the final
angular velocity ω (those of the end state when the run stopped at its steady state), each with its relative
difference from the reference's, and the time the steady state was reached (empty: the run did not stop there).
"""
import os
import sys


def summary(directory, name):
    values = {}
    try:
        for line in open(os.path.join(directory, name + ".summary")):
            if ": " in line:
                key, value = line.split(": ", 1)
                values[key.strip()] = value.strip()
    except OSError:
        pass
    return values


directory, reference, names = sys.argv[1], sys.argv[2], sys.argv[3:]
keys = [("t_sym_1e-4", "t_sym_1e-4"), ("t_sym_1e-2", "t_sym_1e-2"), ("mean angular velocity", "mean omega"),
        ("final total energy", "final F"), ("final angular velocity", "final omega")]
ref = summary(directory, reference)
print("run,status,steps,rejected,LU factorizations,wall s," + ",".join(f"{k},{k} vs reference" for _, k in keys) + ",steady at")
for name in names:
    s = summary(directory, name)
    cells = [name, s.get("status", "missing").split(":")[0], s.get("steps", ""), s.get("rejected steps", ""),
             s.get("LU factorizations", ""), s.get("wall time", "")]
    for key, _ in keys:
        try:
            value, r = float(s[key]), float(ref[key])
            cells += [s[key], f"{(value - r) / abs(r):+.2e}"]
        except (KeyError, ValueError):
            cells += [s.get(key, ""), ""]
    steady = s.get("steady state", "")
    cells.append(steady.split("t = ")[1].split(":")[0] if steady.startswith("reached at t = ") else "")
    print(",".join(cells))
