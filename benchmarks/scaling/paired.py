#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The split of a paired benchmark's last pair (NAME/rN_{before,after}.timing) and its paired wall ratios
(rN_farm_bench.txt) -> NAME.csv and NAME.png, for the refinements measured.
    /usr/bin/python3 benchmarks/scaling/paired.py NAME      # single_column or in_place (paired.sh)"""
import csv
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

labels = {"single_column": ("before (48ee798)", "single-column products"),
          "in_place": ("before (37fdd10)", "in-place insertion")}
name = sys.argv[1] if len(sys.argv) > 1 else ""
if name not in labels:
    raise SystemExit(f"usage: paired.py NAME, NAME one of {', '.join(labels)}")
here = os.path.join(os.path.dirname(os.path.abspath(__file__)), name)
sections = ["assembly", "factorization", "linear solve"]


def timing(path):
    """Seconds by section and the whole run of one timing file."""
    seconds = {}
    with open(path) as f:
        for line in f:
            m = re.match(r"# run: ([0-9.]+) s", line)
            if m:
                seconds["run"] = float(m.group(1))
            m = re.match(r'"([^"]+)", (\d+), ([0-9.e+-]+)', line)
            if m:
                seconds[m.group(1)] = float(m.group(3))
    return seconds


def paired_wall_ratio(path):
    """min, median, max of farm-bench's A/B wall ratio."""
    with open(path) as f:
        for line in f:
            if line.startswith("A/B wall"):
                return [float(x) for x in line.split()[2:5]]
    raise SystemExit(f"{path}: no 'A/B wall' line")


rows = []
for refinement in (4, 5, 6):
    if not os.path.exists(os.path.join(here, f"r{refinement}_farm_bench.txt")):
        continue
    before = timing(os.path.join(here, f"r{refinement}_before.timing"))
    after = timing(os.path.join(here, f"r{refinement}_after.timing"))
    ratio = paired_wall_ratio(os.path.join(here, f"r{refinement}_farm_bench.txt"))
    row = {"refinement": refinement, "paired wall ratio min": ratio[0], "paired wall ratio median": ratio[1],
           "paired wall ratio max": ratio[2]}
    for s in sections + ["run"]:
        row[f"{s} before [s]"] = before[s]
        row[f"{s} after [s]"] = after[s]
    rows.append(row)

with open(os.path.join(os.path.dirname(here), f"{name}.csv"), "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
    writer.writeheader()
    writer.writerows(rows)

fig, axes = plt.subplots(1, len(rows), figsize=(4.4 * len(rows), 3.6), squeeze=False)
axes = axes[0]
for ax, row in zip(axes, rows):
    x = range(len(sections))
    ax.bar([i - 0.2 for i in x], [row[f"{s} before [s]"] for s in sections], 0.4, label=labels[name][0])
    ax.bar([i + 0.2 for i in x], [row[f"{s} after [s]"] for s in sections], 0.4, label=labels[name][1])
    ax.set_xticks(list(x))
    ax.set_xticklabels(sections)
    ax.set_ylabel("wall time of the section [s]")
    ax.set_title(f"refinement {row['refinement']}: paired run ratio {row['paired wall ratio median']:.3f}", fontsize=10)
    ax.legend(fontsize=8)
fig.suptitle("prm/prolate.prm windows, 2 ranks, alone: the last pair's split", fontsize=10)
fig.tight_layout()
fig.savefig(os.path.join(os.path.dirname(here), f"{name}.png"), dpi=120)
