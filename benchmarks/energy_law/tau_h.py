#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Issue 48, item 3: do the end states depend on τ or h? One row per run, then per case the differences.
    /usr/bin/python3 benchmarks/energy_law/tau_h.py OUT.csv "CASE|CONFIG|RUN_DIR" ...
CONFIG is "r3 tau0.1", "r3 tau0.05" or "r4 tau0.1" (refinement, τ_max). RUN_DIR holds a run's statistics and
summary (end_states/table.py's columns). With `--from-csv OUT.csv` the table is printed from a written OUT.csv.
Printed (markdown), per case: the end of each run and
  ΔF_τ = (F(r3, τ_max 0.05) − F(r3, τ_max 0.1)) / |F|,
  ΔF_h = (F(r4) − F(r3) − ω (L(r4) − L(r3))) / |F|   (F moved to the same L by dF/dL = ω: the two meshes' L₀ of
         the same ω₀ differ)."""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "end_states"))
from table import run_row  # noqa: E402

FIELDS = ["case", "config", "status", "end time", "F", "omega", "L0 measured", "lambda1", "lambda2", "lambda3",
          "shape", "steps breaking the law", "largest excess over the bound"]


def write(out, specs):
    rows = []
    for spec in specs:
        case, config, run = spec.split("|")
        row = run_row(run)
        rows.append({"case": case, "config": config, **{k: row.get(k, "") for k in FIELDS[2:]}})
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        w.writerows(rows)
    return rows


def relative(a, b, F):
    return f"{(a - b) / abs(F):+.1e}"


def print_table(rows):
    print("| case | run | end | F | ω | λ₁, λ₂, λ₃ | steps breaking the law | ΔF_τ | ΔF_h |")
    print("|---|---|---|---|---|---|---|---|---|")
    cases = []
    for r in rows:
        if r["case"] not in cases:
            cases.append(r["case"])
    for case in cases:
        runs = {r["config"]: r for r in rows if r["case"] == case}
        ok = {k: r for k, r in runs.items() if r["F"]}
        dtau = dh = "—"
        if "r3 tau0.1" in ok and "r3 tau0.05" in ok:
            dtau = relative(float(ok["r3 tau0.05"]["F"]), float(ok["r3 tau0.1"]["F"]), float(ok["r3 tau0.1"]["F"]))
        if "r3 tau0.1" in ok and "r4 tau0.1" in ok:
            a, b = ok["r4 tau0.1"], ok["r3 tau0.1"]
            moved = float(b["F"]) + float(b["omega"]) * (float(a["L0 measured"]) - float(b["L0 measured"]))
            dh = relative(float(a["F"]), moved, float(b["F"]))
        for k, (config, r) in enumerate(runs.items()):
            end = f"{r['status']} at t = {r['end time']}" if r["F"] else r["status"]
            lam = f"{r['lambda1']}, {r['lambda2']}, {r['lambda3']}" if r["F"] else ""
            print(f"| {case if k == 0 else ''} | {config} | {end} | {r['F']} | {r['omega']} | {lam} | "
                  f"{r['steps breaking the law']} | {dtau if k == 0 else ''} | {dh if k == 0 else ''} |")


if __name__ == "__main__":
    if sys.argv[1] == "--from-csv":
        print_table(list(csv.DictReader(open(sys.argv[2]))))
    else:
        print_table(write(sys.argv[1], sys.argv[2:]))
