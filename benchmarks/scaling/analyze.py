#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/scaling: the cost model from results.csv (benchmarks/scaling/run.sh).

    analyze.py RESULTS.csv OUT_DIR

Writes OUT_DIR/table.md (medians per refinement and rank count: time per step by part, time per call of the LU and
the solve, iterations per solve, peak memory; the fitted exponent p of cost ∝ N^p between neighbouring refinements, and the model of a whole run of
prm/prolate.prm: the window's cost per step, per LU and per solve with the whole run's 393 steps and 72 LU)
and OUT_DIR/scaling.png."""
import csv
import math
import statistics
import sys
from collections import defaultdict

PARTS = ["assembly", "factorization", "linear_solve", "curvature_energy", "diagnostics", "output", "other"]
# The whole of prm/prolate.prm at refinement 4 (benchmarks/phase3/experiments/prolate_r4.summary): 393 steps, 72 LU.
WHOLE_RUN_STEPS, WHOLE_RUN_LU = 393, 72


def load(path):
    groups = defaultdict(list)
    with open(path) as f:
        for row in csv.DictReader(f):
            groups[(int(row["refinement"]), int(row["ranks"]))].append(row)
    cases = {}
    for key, rows in sorted(groups.items()):
        def med(fn):
            return statistics.median(fn(r) for r in rows)
        steps = lambda r: float(r["steps"])
        case = {"unknowns": int(rows[0]["unknowns"]), "runs": len(rows), "end_time": float(rows[0]["end_time"]),
                "steps": med(steps), "factorizations": med(lambda r: float(r["factorizations"])),
                "per_step": med(lambda r: float(r["wall"]) / steps(r)),
                "per_lu": med(lambda r: float(r["factorization"]) / max(1.0, float(r["factorization_calls"]))),
                "per_solve": med(lambda r: float(r["linear_solve"]) / max(1.0, float(r["solve_calls"]))),
                "per_assembly": med(lambda r: float(r["assembly"]) / max(1.0, float(r["assembly_calls"]))),
                "iterations_per_solve": med(lambda r: float(r["linear_iterations"]) / max(1.0, float(r["solve_calls"]))),
                "memory_rank": med(lambda r: float(r["peak_memory_rank_max_mb"])),
                "memory_total": med(lambda r: float(r["peak_memory_total_mb"]))}
        for part in PARTS[:-1]:
            case[part] = med(lambda r: float(r[part]) / steps(r))
        case["other"] = max(0.0, case["per_step"] - sum(case[p] for p in PARTS[:-1]))
        case["solves_per_step"] = med(lambda r: float(r["solve_calls"]) / steps(r))
        # The model of a whole run: every step's parts but the LU and the solves as in the window, the LU and the
        # solves per call times the whole run's counts (the window's solves per step).
        fixed = sum(case[p] for p in PARTS if p not in ("factorization", "linear_solve"))
        case["whole_run"] = WHOLE_RUN_STEPS * (fixed + case["solves_per_step"] * case["per_solve"]) + \
            WHOLE_RUN_LU * case["per_lu"]
        cases[key] = case
    return cases


def exponent(a, b, name):
    if a[name] <= 0 or b[name] <= 0:
        return float("nan")
    return math.log(b[name] / a[name]) / math.log(b["unknowns"] / a["unknowns"])


def table(cases):
    lines = ["| refinement | unknowns | ranks | runs | t_end | steps | LU | s/step | " +
             " | ".join(p.replace("_", " ") + "/step" for p in PARTS) +
             " | s/LU | s/solve | s/assembly | iterations/solve | peak MB (largest rank) | peak MB (all ranks) |"
             " model: whole run [min] |",
             "|" + "---|" * (24 - 1 + 1)]
    lines[1] = "|" + "---|" * (len(lines[0].split("|")) - 2)
    for (r, np), c in cases.items():
        lines.append(f"| {r} | {c['unknowns']} | {np} | {c['runs']} | {c['end_time']:g} | {c['steps']:g} | "
                     f"{c['factorizations']:g} | {c['per_step']:.3g} | " +
                     " | ".join(f"{c[p]:.3g}" for p in PARTS) +
                     f" | {c['per_lu']:.3g} | {c['per_solve']:.3g} | {c['per_assembly']:.3g} | "
                     f"{c['iterations_per_solve']:.3g} | {c['memory_rank']:.0f} | {c['memory_total']:.0f} | "
                     f"{c['whole_run'] / 60:.3g} |")
    lines += ["", "Exponent p of cost ∝ N^p between neighbouring refinements (medians above):", "",
              "| ranks | refinements | s/step | assembly/step | s/LU | s/solve | curvature/step | peak MB |",
              "|---|---|---|---|---|---|---|---|"]
    for np in sorted({k[1] for k in cases}):
        rs = sorted(r for (r, n) in cases if n == np)
        for r0, r1 in zip(rs, rs[1:]):
            a, b = cases[(r0, np)], cases[(r1, np)]
            lines.append(f"| {np} | {r0}→{r1} | " + " | ".join(
                f"{exponent(a, b, k):.2f}" for k in
                ["per_step", "assembly", "per_lu", "per_solve", "curvature_energy", "memory_rank"]) + " |")
    return "\n".join(lines) + "\n"


def plot(cases, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, am) = plt.subplots(1, 2, figsize=(11, 4.5))
    for np, style in [(1, "-"), (2, "--"), (4, ":")]:
        keys = sorted(k for k in cases if k[1] == np)
        if not keys:
            continue
        n = [cases[k]["unknowns"] for k in keys]
        for i, part in enumerate(["per_step", "assembly", "factorization", "linear_solve", "curvature_energy"]):
            ax.loglog(n, [cases[k][part] for k in keys], style, marker="o", color=f"C{i}",
                      label=f"{part.replace('_', ' ')}" if np == 1 else None)
        am.loglog(n, [cases[k]["memory_rank"] / 1024 for k in keys], style, marker="o", color="C0",
                  label=f"np {np}, largest rank")
    ax.set_xlabel("unknowns N")
    ax.set_ylabel("wall time per step [s] (solid: 1 rank, dashed: 2)")
    ax.legend(fontsize=8)
    ax.set_title("prm/prolate.prm, first steps, by part")
    am.set_xlabel("unknowns N")
    am.set_ylabel("peak resident memory [GB]")
    am.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    results, out = sys.argv[1], sys.argv[2]
    cases = load(results)
    text = table(cases)
    open(f"{out}/table.md", "w").write(text)
    print(text)
    plot(cases, f"{out}/scaling.png")


if __name__ == "__main__":
    main()
