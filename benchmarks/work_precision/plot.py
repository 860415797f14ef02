# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/work_precision: the errors of results.csv against wall time, one panel per quantity."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["variant"] != sys.argv[3] and r["status"] == "completed"]
panels = [("error F phase 1", "F, t ≤ 1: max |F − F_ref| / max F_ref"),
          ("error F phase 2", "F, 1 < t ≤ 2.5"), ("error F phase 3", "F, t > 2.5"),
          ("error e linear phase", "e(λ), 1 < t ≤ t_sym: max |e/e_ref − 1|"),
          ("error t_sym_1e-2", "|t_sym − t_sym,ref| / t_sym,ref")]
markers = {"lagged": "o", "normal1": "s", "all1": "^", "after1": "D", "bdf2": "*", "reference": "P"}
fig, axes = plt.subplots(1, len(panels), figsize=(3.6 * len(panels), 4))
for ax, (key, label) in zip(axes, panels):
    for r in rows:
        if not r[key]:
            continue
        scheme = r["variant"].split("_")[0]
        ax.loglog(float(r["wall s"]), max(float(r[key]), 1e-12), markers.get(scheme, "x"),
                  color={"lagged": "tab:blue", "normal1": "tab:red", "all1": "tab:green", "after1": "tab:purple",
                         "bdf2": "tab:orange"}.get(scheme, "k"))
        ax.annotate(r["variant"], (float(r["wall s"]), max(float(r[key]), 1e-12)), fontsize=6)
    ax.set_xlabel("wall time (s)")
    ax.set_title(label, fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
fig.suptitle(f"prm/oblate.prm at refinement 3, t ≤ 7: error against {sys.argv[3]} (o lagged, □ predictor–corrector "
             "normal, △ all, ◇ corrected after a rejection, ★ BDF2, + the lagged reference)", fontsize=9)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
