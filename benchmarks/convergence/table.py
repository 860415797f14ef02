"""benchmarks/convergence: results.csv and convergence.png from the runs of run.sh (arguments: the work folder, the
output folder, the run names <shape>_<law>_r<refinement>[_halfdt])."""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "work_precision"))
from run_records import summary  # noqa: E402

work, out, runs = sys.argv[1], sys.argv[2], sys.argv[3:]
rows = []
print_rows = ["shape,law,refinement,tau check,status,steps,wall s,mean omega,equilibrium omega,relative error omega,"
              "min L2 distance,order omega"]
previous = {}
for run in runs:
    shape, law, level = run.split("_", 2)
    halfdt = level.endswith("_halfdt")
    r = int(level[1:].split("_")[0])
    try:
        s = summary(os.path.join(work, run))
    except OSError:
        continue
    try:
        omega, eq = float(s["mean angular velocity"]), float(s["reference equilibrium angular velocity"])
        err = abs(omega - eq) / eq
    except (KeyError, ValueError):
        omega, eq, err = float("nan"), float("nan"), float("nan")
    order = ""
    key = (shape, law)
    if not halfdt and key in previous and err > 0 and previous[key] > 0:
        order = f"{math.log2(previous[key] / err):.2f}"
    if not halfdt:
        previous[key] = err
        rows.append((shape, law, r, err))
    print_rows.append(",".join([shape, law, str(r), "halved" if halfdt else "", s.get("status", "").split(":")[0],
                                s.get("steps", ""), f"{float(s.get('wall time', 'nan')):.0f}", f"{omega:.6f}",
                                f"{eq:.6f}", f"{err:.3e}", s.get("min L2 distance to equilibrium", ""), order]))
open(os.path.join(out, "results.csv"), "w").write("\n".join(print_rows) + "\n")
print("\n".join(print_rows))
fig, ax = plt.subplots(figsize=(5, 4))
for shape in ("prolate", "oblate"):
    for law, style in (("experiments", "o-"), ("membrane", "d:"), ("bgn", "s--")):
        pts = sorted((r, e) for sh, lw, r, e in rows if sh == shape and lw == law and e > 0)
        if pts:
            ax.semilogy([p[0] for p in pts], [p[1] for p in pts], style, label=f"{shape}, law {law}")
ax.set_xlabel("refinement")
ax.set_ylabel("|⟨ω⟩ − ω_eq(L₀)| / ω_eq")
ax.set_title("phase-2 angular velocity against the rotating equilibrium", fontsize=9)
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(out, "convergence.png"), dpi=120)
