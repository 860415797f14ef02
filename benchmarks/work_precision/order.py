# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/work_precision/order.sh: the largest errors of each fixed-τ run on the times t0 + 0.1 k of its window
against the reference run, the measured orders between successive τ, and the plot order.png.
Arguments: the work folder, the window t0 t1, the reference run and the runs <scheme>_<τ>."""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from run_records import interpolate, statistics_columns, summary  # noqa: E402

work, t0, t1, reference_name, runs = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4], sys.argv[5:]
grid = [t0 + 0.1 * k for k in range(1, int(round((t1 - t0) / 0.1)) + 1)]
quantities = [("F", "total energy", True), ("kinetic", "kinetic energy", True), ("omega", "angular velocity", False),
              ("e", "symmetry deviation", False), ("lambda1", "inertia eigenvalue 1", False)]
reference = statistics_columns.read(os.path.join(work, reference_name, "statistics"))


def largest_error(c, name, relative):
    worst = 0.0
    for g in grid:
        a, b = interpolate(c["time"], c[name], g), interpolate(reference["time"], reference[name], g)
        if a is None or b is None:
            return float("nan")
        worst = max(worst, abs(a - b) / (abs(b) if relative else 1.0))
    return worst


table = {}
header = ["scheme", "tau", "status", "steps", "wall s"] + [f"error {q}" for q, _, _ in quantities]
header += [f"order {q}" for q, _, _ in quantities]
print(",".join(header))
for run in runs:
    scheme, tau = run.rsplit("_", 1)
    try:
        c = statistics_columns.read(os.path.join(work, run, "statistics"))
        s = summary(os.path.join(work, run))
    except OSError:
        continue
    # the window's own steps: the statistics start with the rows of the start run
    steps = sum(1 for t in c["time"] if t > t0 + 1e-9)
    errors = [largest_error(c, name, rel) for _, name, rel in quantities]
    previous = table.get(scheme, [])
    orders = ["" for _ in quantities]
    if previous:
        tau_p, errors_p = previous[-1]
        orders = [f"{math.log(ep / e) / math.log(tau_p / float(tau)):.2f}" if e > 0 and ep > 0 else ""
                  for e, ep in zip(errors, errors_p)]
    table.setdefault(scheme, []).append((float(tau), errors))
    print(",".join([scheme, tau, s.get("status", "").split(":")[0], str(steps), f"{float(s.get('wall time', 'nan')):.1f}"]
                   + [f"{e:.3e}" for e in errors] + orders))

fig, axes = plt.subplots(1, len(quantities), figsize=(3.4 * len(quantities), 3.6))
for ax, (key, name, relative) in zip(axes, quantities):
    k = [q for q, _, _ in quantities].index(key)
    for scheme, rows in table.items():
        taus = [t for t, _ in rows]
        ax.loglog(taus, [e[k] for _, e in rows], "o-", label=scheme.replace("_", " "))
    taus = sorted({t for rows in table.values() for t, _ in rows})
    if taus:
        for p, style in ((1, ":"), (2, "--")):
            ax.loglog(taus, [(t / taus[-1]) ** p * 1e-4 for t in taus], "k" + style, lw=0.8, label=f"τ^{p}")
    ax.set_xticks(taus)
    ax.set_xticklabels([f"{t:g}" for t in taus], fontsize=7, rotation=30)
    ax.minorticks_off()
    ax.set_xlabel("τ")
    ax.set_title(f"{name}{' (relative)' if relative else ''}", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
axes[0].legend(fontsize=7)
fig.suptitle(f"fixed τ over t ∈ [{t0:g}, {t1:g}]: largest error on t0 + 0.1k against {reference_name}", fontsize=9)
fig.tight_layout()
fig.savefig(os.path.join(os.path.dirname(__file__), "order.png"), dpi=120)
