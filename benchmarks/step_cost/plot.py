# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/step_cost: stacked wall time per step by section (median of the runs in results.csv) → step_cost.png;
prints the README table."""
import sys, csv, statistics
import matplotlib; matplotlib.use("Agg"); import matplotlib.pyplot as plt
out = sys.argv[1] if len(sys.argv) > 1 else "benchmarks/step_cost"
rows = list(csv.DictReader(open(out + "/results.csv")))
keys = ["assembly", "factorization", "linear_solve", "curvature_energy", "diagnostics", "output"]
groups = sorted({(int(r["refinement"]), r["reuse"]) for r in rows})
fig, ax = plt.subplots(figsize=(7, 4))
labels = []
for g, (ref, reuse) in enumerate(groups):
    sel = [r for r in rows if int(r["refinement"]) == ref and r["reuse"] == reuse]
    bottom = 0
    for k, key in enumerate(keys):
        v = statistics.median(float(r[key]) for r in sel)
        ax.bar(g, v, bottom=bottom, color=f"C{k}", label=key if g == 0 else None)
        bottom += v
    labels.append(f"ref {ref}\n{'reuse' if reuse == 'true' else 'refactor'}\n{statistics.median(float(r['wall_per_step']) for r in sel):.3g} s")
ax.set_xticks(range(len(groups))); ax.set_xticklabels(labels)
ax.set_ylabel("wall time per accepted step [s] (median)"); ax.legend(fontsize=8)
ax.set_title("scene full, rotating prolate: cost of a step")
fig.tight_layout(); fig.savefig(out + "/step_cost.png", dpi=120)
print("| refinement | unknowns | factorization | s/step (median) | assembly | factorization | linear solve | curvature+energy | LU per step |")
print("|---|---|---|---|---|---|---|---|---|")
for ref, reuse in groups:
    sel = [r for r in rows if int(r["refinement"]) == ref and r["reuse"] == reuse]
    m = lambda k: statistics.median(float(r[k]) for r in sel)
    print(f"| {ref} | {sel[0]['unknowns']} | {'reused' if reuse == 'true' else 'every step'} | {m('wall_per_step'):.3g} | "
          f"{m('assembly'):.3g} | {m('factorization'):.3g} | {m('linear_solve'):.3g} | {m('curvature_energy'):.3g} | "
          f"{statistics.median(int(r['factorizations'])/int(r['steps']) for r in sel):.2f} |")
