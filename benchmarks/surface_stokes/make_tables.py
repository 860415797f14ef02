# SPDX-License-Identifier: LGPL-2.1-or-later
"""Prints the README tables (markdown) from results.csv: /usr/bin/python3 make_tables.py [results.csv]."""
import csv, math, os, sys

path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "results.csv")
rows = list(csv.DictReader(open(path)))
f = float

def rate(prev, cur):
    return f"{math.log2(f(prev) / f(cur)):.2f}" if prev is not None and f(cur) > 0 else ""

def table(header, lines):
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for line in lines:
        print("| " + " | ".join(str(x) for x in line) + " |")
    print()

for shape in ("sphere", "ellipsoid"):
    for k in ("2", "3"):
        sel = [r for r in rows if r["case"] == "convergence" and r["shape"] == shape and r["k"] == k]
        if not sel:
            continue
        print(f"**{shape}, k = {k}** (direct KLU)\n")
        lines, prev = [], None
        for r in sel:
            line = [r["refinement"], r["dofs"]]
            for key in ("velocity L2", "gradient L2", "pressure L2", "normal L2"):
                line += [f"{f(r[key]):.3e}", rate(prev[key] if prev else None, r[key])]
            line.append(f"{f(r['wall time']):.3g}")
            lines.append(line)
            prev = r
        table(["ref", "DoFs", "‖u−u_h‖", "rate", "‖∇_P(u−u_h)‖", "rate", "‖p−p_h‖", "rate", "‖u_h·ν‖", "rate",
               "wall [s]"], lines)

print("**Stationary solvers** (sphere; solver wall time incl. factorization or AMG setup, median of 3; block GMRES: "
      "default velocity AMG = Q2 operator in node frames; its = GMRES iterations)\n")
lines = []
def pick(case, solver, k, ref, amg=None):
    sel = [r for r in rows if r["case"] == case and solver in r["solver"] and r["k"] == k and r["refinement"] == ref
           and (amg is None or r.get("velocity AMG", "") == amg)]
    return sel[0] if sel else None
def timed(r):
    return [f"{f(r['solve time']):.3g}", r["total iterations"]] if r else ["", ""]
for k in ("2", "3"):
    for ref in sorted({r["refinement"] for r in rows if r["case"] == "stationary solver"}, key=int):
        klu, mumps, block = (pick("stationary solver", name, k, ref) for name in ("Klu", "Mumps", "block"))
        if not block:
            continue
        lines.append([k, ref, block["dofs"], f"{f(block['gradient L2']):.3e}",
                      f"{f(klu['solve time']):.3g}" if klu else "", f"{f(mumps['solve time']):.3g}" if mumps else ""]
                     + timed(block) + timed(pick("stationary solver amg", "block", k, ref, "Q2, Cartesian"))
                     + timed(pick("stationary solver amg", "block", k, ref, "low-order refined, node frames"))
                     + timed(pick("stationary solver amg", "block", k, ref, "low-order refined, Cartesian")))
table(["k", "ref", "DoFs", "‖∇_P(u−u_h)‖", "KLU [s]", "MUMPS [s]", "block, Q2 node frames [s]", "its",
       "Q2 Cartesian [s]", "its", "LOR node frames [s]", "its", "LOR Cartesian [s]", "its"], lines)

print("**Fastest stationary option per accuracy** (sphere; accuracy = ‖∇_P(u−u_h)‖ of the refinement; wall time "
      "of the whole run, median of 3)\n")
lines = []
for ref in sorted({r["refinement"] for r in rows if r["case"] == "stationary solver"}, key=int):
    cands = [r for r in rows if r["case"] == "stationary solver" and r["refinement"] == ref]
    best = min(cands, key=lambda r: f(r["wall time"]))
    ranking = ", ".join(f"{r['solver'].replace('direct ', '').replace('block preconditioned', 'block')} k={r['k']} "
                        f"{f(r['wall time']):.3g}" for r in sorted(cands, key=lambda r: f(r["wall time"])))
    lines.append([ref, best["dofs"], f"{f(best['gradient L2']):.2e}",
                  best["solver"].replace("direct ", "") + f", k = {best['k']}", ranking])
table(["ref", "DoFs", "accuracy", "fastest", "all options, wall [s]"], lines)

sel = [r for r in rows if r["case"] == "threads"]
if sel:
    print(f"**Assembly threads** (WorkStream; stationary sphere, refinement {sel[0]['refinement']}, "
          f"{sel[0]['dofs']} DoFs, median of 3)\n")
    table(["threads", "assembly [s]", "solve [s]", "wall [s]"],
          [[r["threads"], f"{f(r['assemble time']):.3g}", f"{f(r['solve time']):.3g}", f"{f(r['wall time']):.3g}"]
           for r in sel])

print("**Penalty variants** (sphere, k = 2; default: exact normal, β = 10, q = 3)\n")
lines = []
for r in rows:
    if r["case"].startswith("penalty"):
        lines.append([r["case"].replace("penalty ", ""), r["refinement"], f"{f(r['velocity L2']):.3e}",
                      f"{f(r['gradient L2']):.3e}", f"{f(r['pressure L2']):.3e}", f"{f(r['normal L2']):.3e}"])
table(["variant", "ref", "‖u−u_h‖", "‖∇_P(u−u_h)‖", "‖p−p_h‖", "‖u_h·ν‖"], lines)

print("**Killing field** u = e_z × x, Re = 10, BDF2, τ = 0.05, t ∈ [0, 1]\n")
lines, prev = [], None
for r in rows:
    if r["case"] == "killing":
        if prev is not None and prev["penalty factor"] != r["penalty factor"]:
            prev = None
        lines.append([r["penalty factor"], r["refinement"], r["dofs"], f"{f(r['energy change']):.3e}",
                      rate(prev["energy change"] if prev else None, r["energy change"]), f"{f(r['velocity L2']):.3e}",
                      f"{f(r['normal L2']):.3e}", r["factorizations"], r["total iterations"], f"{f(r['wall time']):.3g}"])
        prev = r
table(["β", "ref", "DoFs", "|F(1)−F(0)|/F(0)", "rate", "‖u(1)−u_h(1)‖", "‖u_h·ν‖", "LU", "GMRES its", "wall [s]"], lines)

sel = [r for r in rows if r["case"].startswith("multiplier")]
if sel:
    print("**Penalty vs Lagrange multiplier** (sphere, k = 2, direct KLU; stationary: manufactured solution, "
          "Re = 1; Killing: u = e_z × x, Re = 10, BDF2, τ = 0.05, t ∈ [0, 1]; penalty β = 10 unless stated)\n")
    lines = []
    for ref in sorted({r["refinement"] for r in sel}, key=int):
        pen = [r for r in rows if r["case"] == "convergence" and r["shape"] == "sphere" and r["k"] == "2"
               and r["refinement"] == ref]
        cands = [("penalty", pen[0] if pen else None)]
        cands += [(r["case"].split()[1] + " multiplier", r) for r in sel
                  if r["case"].endswith("stationary") and r["refinement"] == ref]
        for name, r in cands:
            if r:
                lines.append(["stationary", name, ref, r["dofs"], f"{f(r['velocity L2']):.3e}", f"{f(r['gradient L2']):.3e}",
                              f"{f(r['pressure L2']):.3e}", f"{f(r['normal L2']):.3e}", "", f"{f(r['wall time']):.3g}"])
    for ref in sorted({r["refinement"] for r in sel}, key=int):
        cands = [("penalty β = " + r["penalty factor"], r) for r in rows if r["case"] == "killing" and r["refinement"] == ref]
        cands += [(r["case"].split()[1] + " multiplier", r) for r in sel
                  if r["case"].endswith("killing") and r["refinement"] == ref]
        for name, r in cands:
            lines.append(["Killing", name, ref, r["dofs"], f"{f(r['velocity L2']):.3e}", "", "", f"{f(r['normal L2']):.3e}",
                          f"{f(r['energy change']):.3e}", f"{f(r['wall time']):.3g}"])
    table(["problem", "tangentiality", "ref", "DoFs", "‖u−u_h‖", "‖∇_P(u−u_h)‖", "‖p−p_h‖", "‖u_h·ν‖",
           "|F(1)−F(0)|/F(0)", "wall [s]"], lines)

for l in ("2", "3"):
    print(f"**Decaying mode l = {l}** (Navier–Stokes, Re = 10, exact rate λ = {f([r for r in rows if r['case'].startswith('decay l=' + l)][0]['exact rate']):.4f})\n")
    lines = []
    for r in rows:
        if r["case"] in (f"decay l={l} h", f"decay l={l} tau"):
            dev = f(r["measured rate"]) / f(r["exact rate"]) - 1
            lines.append([r["case"].split()[-1], r["scheme"], r["refinement"], r["dofs"], r["tau"],
                          f"{f(r['measured rate']):.6f}", f"{100 * dev:+.3f}%", f"{f(r['velocity L2']):.3e}",
                          f"{f(r['wall time']):.3g}"])
    table(["series", "scheme", "ref", "DoFs", "τ", "measured λ", "deviation", "‖u(1)−u_h(1)‖", "wall [s]"], lines)

print("**Time-dependent solvers** (decaying mode l = 2, Re = 10, BDF2, τ = 0.05, 20 steps; median of 3)\n")
lines = []
for r in rows:
    if r["case"].startswith("time solver"):
        name = (("NS" if r["convection"] == "true" else "Stokes") + ", " + r["solver"]
                + (f" ({r['velocity AMG']})" if r.get("velocity AMG") else "") + (" (no reuse)" if "no reuse" in r["case"] else ""))
        lines.append([name, r["refinement"], r["dofs"], r["factorizations"], r["total iterations"], r["max iterations"],
                      f"{f(r['assemble time']):.3g}", f"{f(r['solve time']):.3g}", f"{f(r['wall time']):.3g}",
                      f"{f(r['velocity L2']):.3e}"])
table(["method", "ref", "DoFs", "LU/AMG setups", "its total", "its max/step", "assembly [s]", "solve [s]", "wall [s]",
       "‖u(1)−u_h(1)‖"], lines)
