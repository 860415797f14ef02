#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Rows of the map's grid before and after a change of the step: for each run folder (benchmarks/end_states/run.sh's
names, vV_LL0_START) its end and energy-law figures (table.run_row) beside the same row of a committed grid CSV.

    /usr/bin/python3 benchmarks/energy_law/rows.py GRID.csv OUT.csv RUN_DIR ...

Prints a markdown table and writes OUT.csv (one line per row and version)."""
import csv
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "end_states"))
import table  # noqa: E402

FIELDS = ["status", "end time", "F", "steps breaking the law", "largest excess over the bound", "max rise of B (rel.)"]


def main():
    grid_path, out_path, runs = sys.argv[1], sys.argv[2], sys.argv[3:]
    grid = {(r["v"], r["L0"], r["start"]): r for r in csv.DictReader(open(grid_path))}
    rows = []
    for run in runs:
        v, l0, start = re.match(r"v([\d.]+)_L(\d+)_(\w+)", os.path.basename(run.rstrip("/"))).groups()
        before = grid.get((v, l0, start))
        if before:
            rows.append({"v": v, "L0": l0, "start": start, "version": "before", **{f: before[f] for f in FIELDS}})
        after = table.run_row(run)
        rows.append({"v": v, "L0": l0, "start": start, "version": "after", **{f: after[f] for f in FIELDS}})
    with open(out_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["v", "L0", "start", "version"] + FIELDS)
        w.writeheader()
        w.writerows(rows)
    print("| row | step | end | F | steps breaking the law | largest excess over the bound | largest rise of B (rel.) |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| ({r['v']}, {r['L0']}) {r['start']} start | {r['version']} | {r['status']} at t = {r['end time']} | "
              f"{r['F']} | {r['steps breaking the law']} | {r['largest excess over the bound']} | "
              f"{r['max rise of B (rel.)']} |")


if __name__ == "__main__":
    main()
