# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/convergence: the tables and the plot from the runs of run.sh (arguments: the work folder, the output
folder). Every run in the work folder counts: <shape>_<law>_r<N>[_halfdt] (phase 2) and <shape>_long_r<N> (end
states). Writes results.csv (phase 2), end_states.csv and convergence.png to the output folder."""
import glob
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "work_precision"))
from run_records import statistics_columns, summary  # noqa: E402

GROWTH_WINDOW = (1.2, 2.5)
END_STATE = [("total energy", "F"), ("bending energy", "W"), ("inertia eigenvalue 1", "lambda1"),
             ("inertia eigenvalue 2", "lambda2"), ("inertia eigenvalue 3", "lambda3"), ("angular velocity", "omega")]


def growth_rate(columns, window):
    """Least-squares slope of log e(λ) against t on the window: the growth rate of the symmetry deviation."""
    pts = [(t, math.log(e)) for t, e in zip(columns["time"], columns["symmetry deviation"])
           if window[0] <= t <= window[1] and e > 0]
    if len(pts) < 3:
        return float("nan")
    n = len(pts)
    mt, my = sum(p[0] for p in pts) / n, sum(p[1] for p in pts) / n
    return sum((p[0] - mt) * (p[1] - my) for p in pts) / sum((p[0] - mt) ** 2 for p in pts)


def observed_order(coarse, middle, fine):
    """log2 of the ratio of successive differences; None when they do not shrink monotonically."""
    d1, d2 = middle - coarse, fine - middle
    if d1 == 0 or d2 == 0 or d1 * d2 < 0 or abs(d2) >= abs(d1):
        return None
    return math.log2(abs(d1) / abs(d2))


def fmt(x, spec):
    return "" if x is None or (isinstance(x, float) and math.isnan(x)) else format(x, spec)


work, out = sys.argv[1], sys.argv[2]
runs = sorted(os.path.basename(p)[:-4] for p in glob.glob(os.path.join(work, "*.prm")))

# Phase 2.
phase2 = []
for run in runs:
    m = re.fullmatch(r"(prolate|oblate)_(experiments|membrane|bgn)_r(\d)(_halfdt)?", run)
    if not m or not os.path.exists(os.path.join(work, run, "summary")):
        continue
    s = summary(os.path.join(work, run))
    row = dict(shape=m[1], law=m[2], r=int(m[3]), halved=bool(m[4]), status=s.get("status", "").split(":")[0],
               steps=s.get("steps", ""), rejected=s.get("rejected steps", ""),
               wall=float(s.get("wall time", "nan")), emin=float(s.get("min L2 distance to equilibrium", "nan")))
    try:
        row["omega"], row["eq"] = float(s["mean angular velocity"]), float(s["reference equilibrium angular velocity"])
        row["err"] = abs(row["omega"] - row["eq"]) / row["eq"]
    except (KeyError, ValueError):
        row["omega"] = row["eq"] = row["err"] = float("nan")
    stats = os.path.join(work, run, "statistics")
    row["sigma"] = growth_rate(statistics_columns.read(stats), GROWTH_WINDOW) if m[1] == "oblate" else float("nan")
    phase2.append(row)
phase2.sort(key=lambda x: (x["shape"], x["law"], x["r"], x["halved"]))
lines = ["shape,law,refinement,tau_max,status,steps,rejected,wall s,mean omega,equilibrium omega,relative error omega,"
         "order omega,min L2 distance,growth rate e(lambda) [1.2, 2.5]"]
for row in phase2:
    prev = [p for p in phase2 if (p["shape"], p["law"], p["r"], p["halved"]) ==
            (row["shape"], row["law"], row["r"] - 1, False)]
    order = None
    if not row["halved"] and prev and prev[0]["err"] > 0 and row["err"] > 0:
        order = math.log2(prev[0]["err"] / row["err"])
    lines.append(",".join([row["shape"], row["law"], str(row["r"]), "halved" if row["halved"] else "shipped",
                           row["status"], row["steps"], row["rejected"], fmt(row["wall"], ".0f"),
                           fmt(row["omega"], ".6f"), fmt(row["eq"], ".6f"), fmt(row["err"], ".2e"),
                           fmt(order, ".2f"), fmt(row["emin"], ".2e"), fmt(row["sigma"], ".4f")]))
open(os.path.join(out, "results.csv"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))

# End states, against Richardson extrapolation of the finest three levels.
ends = {}
for run in runs:
    m = re.fullmatch(r"(prolate|oblate)_long_r(\d)", run)
    if not m or not os.path.exists(os.path.join(work, run, "summary")):
        continue
    s = summary(os.path.join(work, run))
    c = statistics_columns.read(os.path.join(work, run, "statistics"))
    values = {key: c[col][-1] for col, key in END_STATE}
    values.update(status=s.get("status", "").split(":")[0], end_time=c["time"][-1],
                  rigid=c["rigid fraction"][-1], rises=s.get("energy rises accepted", ""),
                  quality=min(c["mesh quality"]), wall=float(s.get("wall time", "nan")))
    ends.setdefault(m[1], {})[int(m[2])] = values
lines = ["shape,quantity,refinement,value,observed order,extrapolated,relative error,relative change to the next level"]
extrapolated = {}
for shape, levels in sorted(ends.items()):
    rs = sorted(levels)
    for _, key in END_STATE:
        order, limit = None, None
        if len(rs) >= 3:
            order = observed_order(*(levels[r][key] for r in rs[-3:]))
            if order is not None:
                f1, f2 = levels[rs[-2]][key], levels[rs[-1]][key]
                limit = f2 + (f2 - f1) / (2 ** order - 1)
        extrapolated[(shape, key)] = limit
        for r in rs:
            err = abs(levels[r][key] - limit) / abs(limit) if limit else None
            change = abs(levels[r + 1][key] - levels[r][key]) / abs(levels[r + 1][key]) if r + 1 in levels else None
            lines.append(",".join([shape, key, str(r), f"{levels[r][key]:.8g}", fmt(order, ".2f"),
                                   fmt(limit, ".8g"), fmt(err, ".2e"), fmt(change, ".2e")]))
    for r in rs:
        v = levels[r]
        lines.append(",".join([shape, "run", str(r), f"status {v['status']}; end time {v['end_time']:.2f}; rigid "
                               f"fraction {v['rigid']:.6f}; accepted rises {v['rises']}; min quality "
                               f"{v['quality']:.3f}; wall {v['wall']:.0f} s", "", "", "", ""]))
open(os.path.join(out, "end_states.csv"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))

fig, axes = plt.subplots(1, 3, figsize=(13, 4))
for shape, colour in (("prolate", "C0"), ("oblate", "C1")):
    for law, style in (("experiments", "o-"), ("membrane", "d:"), ("bgn", "s--")):
        pts = sorted((p["r"], p["err"], p["emin"]) for p in phase2
                     if (p["shape"], p["law"], p["halved"]) == (shape, law, False) and p["err"] > 0)
        half = sorted((p["r"], p["err"], p["emin"]) for p in phase2
                      if (p["shape"], p["law"], p["halved"]) == (shape, law, True) and p["err"] > 0)
        filled = "none" if law == "bgn" else colour
        if pts:
            axes[0].semilogy([p[0] for p in pts], [p[1] for p in pts], style, color=colour, mfc=filled,
                             label=f"{shape}, {law}")
        if half:
            axes[0].semilogy([p[0] for p in half], [p[1] for p in half], "x", color=colour, ms=8,
                             label=f"{shape}, {law}, τ_max halved")
        if pts and shape == "prolate":
            axes[1].semilogy([p[0] for p in pts], [p[2] for p in pts], style, color=colour, mfc=filled,
                             label=f"{shape}, {law}")
for shape, levels in sorted(ends.items()):
    for (_, key), marker in zip(END_STATE, "os^v<>"):
        limit = extrapolated.get((shape, key))
        pts = [(r, abs(levels[r][key] - limit) / abs(limit)) for r in sorted(levels)] if limit else []
        if pts:
            axes[2].semilogy(*zip(*pts), marker + ("-" if shape == "prolate" else "--"), label=f"{shape}_long {key}")
axes[0].set_ylabel("|⟨ω⟩ − ω_eq(L₀)| / ω_eq")
axes[1].set_ylabel("min E(L²), prolate")
axes[2].set_ylabel("end state: relative distance to the Richardson limit")
for ax, title in zip(axes, ("phase-2 angular velocity", "distance to the equilibrium shape", "end states of the long runs")):
    ax.set_xlabel("refinement r (h ∝ 2⁻ʳ: a log–log plot)")
    ax.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
    ax.set_title(title, fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=6)
fig.tight_layout()
fig.savefig(os.path.join(out, "convergence.png"), dpi=120)
