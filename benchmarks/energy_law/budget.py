#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The energy budget of a run of scene full by term, from its file `energy_budget` (`time stepping/energy budget =
true`; doc/output.md). Per accepted step, ΔB = ΔF + τD (> 0: the step put energy in) splits exactly into

    bending defect     ΔW of the solve + τP      (W changed by more than the bending force's work P took from the fluid)
    multiplier work    τP_μ                      (the volume and momentum multipliers' forces on the fluid)
    transport defect   ΔK of the solve − τP − τP_μ + τD (inertia on the moving surface, convection, frame, pressure)
    area/volume proj.  ΔW + ΔK of the area and volume projection (nodes moved along ñ; u unchanged)
    momentum proj.     ΔK of the momentum projection

    /usr/bin/python3 benchmarks/energy_law/budget.py RUN_DIR [t0 t1] [--steps]

prints the sums over the accepted steps ending in (t0, t1] (default: the whole run), and with --steps every step."""
import sys

TERMS = ["bending defect", "multiplier work", "transport defect", "area/volume projection", "momentum projection"]


def rows(run):
    """The rows of RUN/energy_budget by step number (a resumed run may repeat a step: its later row counts)."""
    by_step = {}
    for line in open(f"{run}/energy_budget"):
        if line.startswith("#") or not line.strip():
            continue
        v = [float(x) for x in line.split()]
        (step, t, tau, D, W0, K0, P, Pm, Ws, Ks, Kav, W, K) = v
        by_step[int(step)] = {
            "step": int(step), "time": t, "tau": tau, "D": D,
            "dB": W + K - W0 - K0 + tau * D,
            "bending defect": Ws - W0 + tau * P,
            "multiplier work": tau * Pm,
            "transport defect": Ks - K0 - tau * P - tau * Pm + tau * D,
            "area/volume projection": W - Ws + Kav - Ks,
            "momentum projection": K - Kav,
        }
    return [by_step[k] for k in sorted(by_step)]


def split(run, t0=-1e300, t1=1e300):
    """The sums of ΔB and of its terms over the steps ending in (t0, t1], with the count of steps."""
    steps = [r for r in rows(run) if t0 < r["time"] <= t1 + 1e-12]
    total = {name: sum(r[name] for r in steps) for name in ["dB"] + TERMS}
    total["steps"] = len(steps)
    return total


def main():
    args = [a for a in sys.argv[1:] if a != "--steps"]
    run = args[0]
    t0, t1 = (float(args[1]), float(args[2])) if len(args) >= 3 else (-1e300, 1e300)
    header = "| steps | ΔB | " + " | ".join(TERMS) + " |"
    print(header)
    print("|" + "---|" * (header.count("|") - 1))
    s = split(run, t0, t1)
    print(f"| {s['steps']} | {s['dB']:+.4g} | " + " | ".join(f"{s[n]:+.4g}" for n in TERMS) + " |")
    if "--steps" in sys.argv:
        print()
        print("| step | t | τ | D | ΔB | " + " | ".join(TERMS) + " |")
        print("|" + "---|" * (5 + len(TERMS)))
        for r in rows(run):
            if t0 < r["time"] <= t1 + 1e-12:
                print(f"| {r['step']} | {r['time']:.6g} | {r['tau']:.3g} | {r['D']:.4g} | {r['dB']:+.3e} | "
                      + " | ".join(f"{r[n]:+.3e}" for n in TERMS) + " |")


if __name__ == "__main__":
    main()
