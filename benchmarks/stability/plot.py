# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/stability: F(t) and τ(t) of every case (cases/*.statistics) → stability.png; prints the README table."""
import csv, glob, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = sys.argv[1] if len(sys.argv) > 1 else "benchmarks/stability"  # the folder of results.csv and cases/


def read(f):
    names, rows = [], []
    for line in open(f):
        if line.startswith("# "):
            names.append(line.split(": ", 1)[1].strip())
        elif line.strip():
            rows.append([float(x) for x in line.split()])
    return {n: [r[i] for r in rows] for i, n in enumerate(names)}


groups = ["fixed", "perturbed", "elongated"]
fig, ax = plt.subplots(2, 3, figsize=(15, 7))
for g, group in enumerate(groups):
    for f in sorted(glob.glob(f"{here}/cases/{group}_*.statistics")):
        d = read(f)
        lab = f.split("/")[-1].replace(".statistics", "").replace(group + "_", "")
        F0 = d["total energy"][0]
        ax[0][g].plot(d["time"], [x / F0 for x in d["total energy"]], label=lab)
        ax[1][g].semilogy(d["time"][1:], d["tau"][1:], label=lab)
    ax[0][g].set_title(group); ax[0][g].set_ylabel("F / F(0)"); ax[0][g].legend(fontsize=7)
    ax[1][g].set_xlabel("t"); ax[1][g].set_ylabel("τ")
fig.tight_layout(); fig.savefig(here + "/stability.png", dpi=100)
rows = list(csv.DictReader(open(here + "/results.csv")))
print("| case | t reached | steps | τ used (max/min) | F rises | F(0) → F(end) | min mesh quality | max e(λ) | wall [s] | outcome |")
print("|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    print(f"| {r['case']} | {r['t_reached']} | {r['steps']} | {r['tau_max_used']} / {r['tau_min_used']} | {r['energy_rises']} | "
          f"{r['F0']} → {r['F_end']} | {r['min_mesh_quality']} | {r['max_symmetry_deviation']} | {float(r['wall_time_s']):.0f} | {r['outcome']} |")
