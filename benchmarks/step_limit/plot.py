# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/step_limit: completed (stable) and failed fixed-τ windows against τ, per case and scheme."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

rows = list(csv.DictReader(open(sys.argv[1])))
pairs = sorted({(r["shape"], r["refinement"], r["scheme"]) for r in rows})
fig, ax = plt.subplots(figsize=(7, 1 + 0.4 * len(pairs)))
labels = []
for y, (shape, ref, scheme) in enumerate(pairs):
    labels.append(f"{shape} r{ref}, {scheme}")
    for r in rows:
        if (r["shape"], r["refinement"], r["scheme"]) != (shape, ref, scheme):
            continue
        ok = r["completed"] == "1"
        ax.plot(float(r["tau"]), y, "o" if ok else "x", color="tab:green" if ok else "tab:red", ms=9)
ax.set_xscale("log")
ax.set_yticks(range(len(labels)))
ax.set_yticklabels(labels)
ax.set_xlabel("fixed time step τ")
ax.set_title("Fixed τ in the transformation: o completed, x energy rise or no convergence\n"
             "prm/prolate_long.prm from t = 20, prm/oblate_long.prm from t = 4.75", fontsize=9)
ax.grid(True, axis="x", alpha=0.3)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
