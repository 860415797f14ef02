#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The table and plot of grad_div.sh: per γ_gd, the two plateaus (the body at rest, v = 0.65, L₀ = 0, t ∈ (5.5, 8];
the fast spin, v = 0.95, L₀ = 40, t ∈ (4, 6]): the dissipation rate D at the window's end, the rate of B = F + ∫D
over the window relative to |F| (against the energy law's ε_L = 1e-6), the multipliers' work and the steps breaking
the law; and the relaxation of prm/prolate.prm (t ≤ ACCURACY_END) at refinement 3: the largest differences of F and
of ω from the refinement-4 run with γ_gd = 0 at t = 0.25, 0.5, …, relative, and the wall time (the runs of grad_div.sh
share the machine: a comparison, not a budget); at refinement 4 the largest γ_gd against γ_gd = 0 the same way.

    /usr/bin/python3 benchmarks/energy_law/grad_div.py WORK OUT.csv OUT.png"""
import glob
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "phase3"))
import budget  # noqa: E402
import statistics_columns  # noqa: E402

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

EPSILON_L = 1e-6
WINDOWS = {"rest": ("v0.65_L0_oblate", 5.5, 8.0), "spin": ("v0.95_L40_oblate", 4.0, 6.0)}


def statistics(run):
    """Columns of RUN/statistics by name."""
    return statistics_columns.read(f"{run}/statistics")


def summary(run):
    out = {}
    for line in open(f"{run}/summary"):
        if ":" in line:
            key, value = line.split(":", 1)
            out[key.strip()] = value.strip()
    return out


def at(s, name, t):
    """Column NAME of statistics S linearly interpolated at time t."""
    times, values = s["time"], s[name]
    for k in range(1, len(times)):
        if times[k] >= t:
            w = (t - times[k - 1]) / (times[k] - times[k - 1])
            return values[k - 1] + w * (values[k] - values[k - 1])
    return values[-1]


def plateau(work, case, gamma):
    name, t0, t1 = WINDOWS[case]
    run = f"{work}/{name}_g{gamma}"
    if not os.path.exists(f"{run}/summary"):
        return None
    s, b = statistics(run), budget.split(run, t0, t1)
    F = at(s, "total energy", t1)
    return {
        "D": s["dissipation rate"][-1],
        "rate": b["dB"] / (t1 - t0) / abs(F),
        "multiplier": b["multiplier work"] / (t1 - t0) / abs(F),
        "breaks": int(summary(run).get("steps breaking the energy law", "-1")),
        "F": F,
    }


def accuracy(work, gamma, reference, level=3):
    run = f"{work}/prolate_r{level}_g{gamma}"
    if not os.path.exists(f"{run}/summary") or reference is None:
        return None
    s = statistics(run)
    end = s["time"][-1]
    times = [0.25 * k for k in range(1, int(end / 0.25 + 1e-9) + 1)]
    error = max(abs(at(s, "total energy", t) - at(reference, "total energy", t)) / abs(at(reference, "total energy", t))
                for t in times)
    omega = max(abs(at(s, "angular velocity", t) - at(reference, "angular velocity", t)) / at(reference, "angular velocity", t)
                for t in times)
    return {"F error": error, "omega error": omega, "wall": float(summary(run)["wall time"]), "steps": len(s["time"]) - 1}


def main():
    work, out_csv, out_png = sys.argv[1:4]
    gammas = sorted({m.group(1) for p in glob.glob(f"{work}/v0.65_L0_oblate_g*")
                     if os.path.isdir(p) and (m := re.fullmatch(r".*_g([0-9.]+)", os.path.basename(p)))}, key=float)
    reference_run = f"{work}/prolate_r4_g0"
    reference = statistics(reference_run) if os.path.exists(f"{reference_run}/summary") else None
    rows = []
    for g in gammas:
        row = {"gamma_gd": g}
        for case in WINDOWS:
            p = plateau(work, case, g)
            if p:
                row.update({f"{case}_D": f"{p['D']:.3e}", f"{case}_B_rate_over_F": f"{p['rate']:.2e}",
                            f"{case}_multiplier_work_rate_over_F": f"{p['multiplier']:.2e}",
                            f"{case}_steps_breaking": p["breaks"], f"{case}_F": f"{p['F']:.8f}"})
        a = accuracy(work, g, reference)
        if a:
            row.update({"prolate_r3_F_error": f"{a['F error']:.2e}", "prolate_r3_omega_error": f"{a['omega error']:.2e}",
                        "prolate_r3_wall_s": f"{a['wall']:.1f}", "prolate_r3_steps": a["steps"]})
        for level in (4,):
            if os.path.exists(f"{work}/prolate_r{level}_g{g}/summary") and g != "0" and reference is not None:
                a4 = accuracy(work, g, reference, level)
                row.update({"prolate_r4_F_difference": f"{a4['F error']:.2e}", "prolate_r4_wall_s": f"{a4['wall']:.1f}"})
        rows.append(row)
    if reference is not None:
        rows.append({"gamma_gd": "0 (the reference: refinement 4)",
                     "prolate_r4_wall_s": f"{float(summary(reference_run)['wall time']):.1f}"})
    columns = []
    for r in rows:
        columns += [c for c in r if c not in columns]
    with open(out_csv, "w") as f:
        f.write(",".join(columns) + "\n")
        for r in rows:
            f.write(",".join(str(r.get(c, "")) for c in columns) + "\n")

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    x = [max(float(g), 0.1) for g in gammas]
    for case, label in (("rest", "at rest (0.65, 0)"), ("spin", "fast spin (0.95, 40)")):
        ys = [float(r.get(f"{case}_B_rate_over_F", "nan")) for r in rows[:len(gammas)]]
        left.loglog(x, [max(y, 1e-12) for y in ys], "o-", label=f"{label}: (ΔF + ∫D)/(Δt |F|)")
    left.axhline(EPSILON_L, color="k", ls="--", lw=0.8, label="ε_L = 1e-6 (the law's rounding bound)")
    left.set_xlabel("γ_gd (0 drawn at 0.1)")
    left.set_ylabel("rise rate of F + ∫D over the plateau / |F|")
    left.legend(fontsize=8)
    left.set_title("plateaus, refinement 3, τ_max 0.1")
    measured = [r for r in rows[:len(gammas)] if "prolate_r3_F_error" in r]
    xs = [max(float(r["gamma_gd"]), 0.1) for r in measured]
    right.loglog(xs, [float(r["prolate_r3_F_error"]) for r in measured], "o-", label="F")
    right.loglog(xs, [float(r["prolate_r3_omega_error"]) for r in measured], "s-", label="ω")
    for x, r in zip(xs, measured):
        right.annotate(f"{r['prolate_r3_steps']} steps, {float(r['prolate_r3_wall_s']):.0f} s", (x, float(r["prolate_r3_F_error"])),
                       fontsize=7)
    right.set_xlabel("γ_gd (0 drawn at 0.1); wall times loaded")
    right.set_ylabel("largest relative difference from refinement 4, t ≤ end")
    right.legend(fontsize=8)
    right.set_title("prm/prolate.prm relaxation at refinement 3")
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)


if __name__ == "__main__":
    main()
