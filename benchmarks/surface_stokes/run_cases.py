# SPDX-License-Identifier: LGPL-2.1-or-later
"""Runs the surface Stokes benchmark cases through the driver; writes results.csv and the PNG.
Called by run.sh: run_cases.py DRIVER OUTDIR [--quick] [--solvers] [--multiplier].
--solvers re-runs only the solver comparisons (sections 2, 2a, 2b, 6) and keeps the other rows of the
existing results.csv (convergence, penalty, Killing, decay: direct-solver accuracy studies).
--multiplier re-runs only the tangentiality multiplier cases (section 4b) and keeps the other rows."""
import csv, math, os, statistics, subprocess, sys, tempfile

driver, outdir = sys.argv[1], sys.argv[2]
quick = "--quick" in sys.argv[3:]
solvers_only = "--solvers" in sys.argv[3:]
multiplier_only = "--multiplier" in sys.argv[3:]
repeats = 1 if quick else 3
workdir = tempfile.mkdtemp(prefix="surface_stokes_")

# The driver's result lines (driver.cc); any other line on its stdout (a library's or MPI's message) is passed on to
# stderr and does not stop the run; a missing result line does, with the driver's whole output.
RESULT_KEYS = ("area", "dofs", "velocity", "tangential", "gradient", "pressure", "normal", "energy change",
               "measured rate", "exact rate", "steps", "total iterations", "max iterations", "factorizations",
               "assemble time", "solve time", "wall time")


def parse(out, args):
    r = {}
    for line in out.splitlines():
        key, sep, value = line.partition(": ")
        if sep and key in RESULT_KEYS:
            r[key] = value.strip()
        elif line.strip():
            print("driver:", line, file=sys.stderr)
    missing = [k for k in RESULT_KEYS if k not in r]
    if missing:
        sys.exit(f"run_cases.py: no {', '.join(missing)} in the output of {' '.join(args)}:\n{out}")
    return r


def run(settings, repeat=repeats, threads=None):
    """One case; settings: dict 'section/entry' -> value. Returns the driver's key: value dict
    with 'wall time' (and solve/assemble time) replaced by the median over `repeat` runs.
    threads: DEAL_II_NUM_THREADS for the run (default: deal.II's, all cores)."""
    env = dict(os.environ)
    if threads is not None:
        env["DEAL_II_NUM_THREADS"] = str(threads)
    args = [driver, "output/write vtu=false", f"output/output directory={workdir}", "output/overwrite=true"]
    args += [f"{k}={v}" for k, v in settings.items()]
    results = []
    for _ in range(repeat):
        out = subprocess.run(args, check=True, capture_output=True, text=True, env=env).stdout
        results.append(parse(out, args))
    r = dict(results[0])
    for key in ("wall time", "solve time", "assemble time"):
        r[key] = statistics.median(float(x[key]) for x in results)
    return r

columns = ["case", "problem", "shape", "k", "refinement", "dofs", "solver", "scheme", "convection", "Re",
           "penalty factor", "tau", "velocity L2", "tangential L2", "gradient L2", "pressure L2", "normal L2",
           "energy change", "measured rate", "exact rate", "steps", "total iterations", "max iterations",
           "factorizations", "assemble time", "solve time", "wall time", "threads", "aggregation threshold",
           "velocity AMG"]
rows = []

def record(case, settings, r):
    s = dict(settings)
    row = {"case": case, "problem": s.get("fixed surface/problem", "manufactured sphere"),
           "shape": s.get("geometry/shape", "sphere"), "k": s.get("geometry/position degree", "2"),
           "refinement": s["geometry/refinement"], "dofs": r["dofs"],
           "solver": s.get("fixed surface solver/linear solver", "direct") + ("" if s.get("fixed surface solver/linear solver", "direct") != "direct"
                                                             else " " + s.get("linear solver/direct solver", "Amesos_Klu")),
           "scheme": s.get("fixed surface solver/time scheme", "BDF2"), "convection": s.get("flow/convection", "true"),
           "Re": s.get("flow/Re", "1"),
           "penalty factor": "" if s.get("fixed surface solver/tangentiality") == "multiplier" else s.get("fixed surface solver/penalty factor", "10"),
           "tau": s.get("time stepping/time step", ""), "threads": s.get("threads", ""),
           "aggregation threshold": s.get("fixed surface solver/velocity AMG aggregation threshold", ""),
           "velocity AMG": "" if s.get("fixed surface solver/linear solver", "direct") == "direct" else
                           s.get("fixed surface solver/velocity AMG operator", "Q2") + ", " +
                           ("node frames" if s.get("fixed surface solver/velocity AMG node frames", "true") == "true" else "Cartesian")}
    for key, name in [("velocity", "velocity L2"), ("tangential", "tangential L2"), ("gradient", "gradient L2"),
                      ("pressure", "pressure L2"), ("normal", "normal L2")]:
        row[name] = r[key]
    for key in ["energy change", "measured rate", "exact rate", "steps", "total iterations", "max iterations",
                "factorizations", "assemble time", "solve time", "wall time"]:
        row[key] = r[key]
    rows.append(row)
    print(case, {k: row[k] for k in ("shape", "k", "refinement", "solver", "tau", "gradient L2", "measured rate",
                                       "energy change", "max iterations", "wall time")}, flush=True)

max_ref = 3 if quick else 5
# "stationary solver theta" (θ = 0.02, Cartesian AMG) is not rerun by --solvers: its rows are kept from the
# session that compared the aggregation thresholds.
solver_cases = ("stationary solver", "stationary solver amg", "threads", "time solver", "time solver no reuse")
multiplier_cases = ("multiplier Q1 stationary", "multiplier Q2 stationary", "multiplier Q1 killing", "multiplier Q2 killing")
if solvers_only or multiplier_only:
    rerun = solver_cases if solvers_only else multiplier_cases
    with open(os.path.join(outdir, "results.csv")) as f:
        rows = [dict(r) for r in csv.DictReader(f) if r["case"] not in rerun]
        for r in rows:
            for c in columns:
                r.setdefault(c, "")
# 1. Manufactured stationary Stokes: convergence for k = 2, 3 on sphere and ellipsoid (direct solver).
for shape in ("sphere", "ellipsoid") if not (solvers_only or multiplier_only) else ():
    for k in (2, 3):
        for ref in range(1, max_ref + 1):
            s = {"geometry/shape": shape, "geometry/refinement": ref, "geometry/position degree": k}
            if shape == "ellipsoid":
                s.update({"geometry/semi-axes": "1.27,1.27,0.47", "fixed surface/problem": "manufactured ellipsoid"})
            record("convergence", s, run(s))
# 2. Solvers on the stationary problem (sphere, k = 2 and 3): KLU, MUMPS and the block preconditioner
#    (default aggregation threshold 1e-4; k = 2 also with the former 0.02), all in one session.
for k in (2, 3) if not multiplier_only else ():
    for solver in (("direct", "Amesos_Klu"), ("direct", "Amesos_Mumps"), ("block preconditioned", None)):
        for ref in range(1, max_ref + 1):
            s = {"geometry/shape": "sphere", "geometry/refinement": ref, "geometry/position degree": k,
                 "fixed surface solver/linear solver": solver[0]}
            if solver[1]:
                s["linear solver/direct solver"] = solver[1]
            record("stationary solver", s, run(s))
for ref in range(1, max_ref + 1) if not (solvers_only or multiplier_only) else ():
    s = {"geometry/shape": "sphere", "geometry/refinement": ref, "fixed surface solver/linear solver": "block preconditioned",
         "fixed surface solver/velocity AMG aggregation threshold": 0.02, "fixed surface solver/velocity AMG node frames": "false"}
    record("stationary solver theta", s, run(s, 1 if ref == 5 else repeats))
# 2a. Velocity AMG variants of the block preconditioner (the default, Q2 in node frames, is in section 2):
#     Q2 in Cartesian components (the former default), and the low-order-refined operator in node frames
#     and in Cartesian components; k = 3 only the former default.
for k, variants in ((2, (("Q2", "false"), ("low-order refined", "true"), ("low-order refined", "false"))),
                    (3, (("Q2", "false"),))) if not multiplier_only else ():
    for operator, frames in variants:
        for ref in range(1, max_ref + 1):
            s = {"geometry/shape": "sphere", "geometry/refinement": ref, "geometry/position degree": k,
                 "fixed surface solver/linear solver": "block preconditioned", "fixed surface solver/velocity AMG operator": operator,
                 "fixed surface solver/velocity AMG node frames": frames}
            record("stationary solver amg", s, run(s))
# 2b. Threads in assembly (WorkStream): the same stationary problem with 1 and 2 threads.
for threads in (1, 2) if not multiplier_only else ():
    s = {"geometry/shape": "sphere", "geometry/refinement": max_ref - 1}
    r = run(s, threads=threads)
    record("threads", {**s, "threads": threads}, r)
# 3. Penalty choices (sphere, k = 2): exponent 2 vs 3, and the normal used.
for ref in range(2, max_ref + 1) if not (solvers_only or multiplier_only) else ():
    for extra in ({"fixed surface solver/penalty exponent": 2}, {"fixed surface solver/penalty normal": "continuous"}, {"fixed surface solver/penalty normal": "cell"},
                  {"fixed surface solver/penalty factor": 1000}):
        s = {"geometry/shape": "sphere", "geometry/refinement": ref, **extra}
        r = run(s, 1)
        record("penalty " + ",".join(f"{k.split('/')[1]}={v}" for k, v in extra.items()), s, r)
# 4. Killing field, t in [0, 1], Re = 10, penalty factor 1000 and 10.
for beta in (1000, 10) if not (solvers_only or multiplier_only) else ():
    for ref in range(2, (4 if quick else 5) + 1):
        s = {"geometry/shape": "sphere", "geometry/refinement": ref, "fixed surface/problem": "killing",
             "flow/Re": 10, "fixed surface solver/penalty factor": beta, "time stepping/time step": 0.05, "time stepping/end time": 1}
        record("killing", s, run(s, 1))
# 4b. Tangentiality by a Lagrange multiplier λ ∈ Q1 or Q2 instead of the penalty (direct solver): stationary
#     manufactured sphere (errors) and the Killing field (energy drift), k = 2.
for d in (1, 2) if not solvers_only else ():
    for ref in range(2, max_ref + 1):
        s = {"geometry/shape": "sphere", "geometry/refinement": ref, "fixed surface solver/tangentiality": "multiplier",
             "fixed surface solver/multiplier degree": d}
        record(f"multiplier Q{d} stationary", s, run(s, 1))
    for ref in range(2, (4 if quick else 5) + 1):
        s = {"geometry/shape": "sphere", "geometry/refinement": ref, "fixed surface/problem": "killing",
             "flow/Re": 10, "fixed surface solver/tangentiality": "multiplier", "fixed surface solver/multiplier degree": d,
             "time stepping/time step": 0.05, "time stepping/end time": 1}
        record(f"multiplier Q{d} killing", s, run(s, 1))
# 5. Decaying modes l = 2, 3 with convection, Re = 10: h-convergence at tau = 0.0125, tau-convergence at ref 4.
for l in (2, 3) if not (solvers_only or multiplier_only) else ():
    for ref in range(2, (3 if quick else 4) + 1):
        s = {"geometry/shape": "sphere", "geometry/refinement": ref, "fixed surface/problem": "decaying mode",
             "fixed surface/mode number": l, "flow/Re": 10, "time stepping/time step": 0.0125,
             "time stepping/end time": 1}
        record(f"decay l={l} h", s, run(s, 1))
    for scheme in ("BDF1", "BDF2"):
        for tau in (0.1, 0.05, 0.025) if not quick else (0.1, 0.05):
            s = {"geometry/shape": "sphere", "geometry/refinement": 3 if quick else 4,
                 "fixed surface/problem": "decaying mode", "fixed surface/mode number": l, "flow/Re": 10,
                 "fixed surface solver/time scheme": scheme, "time stepping/time step": tau, "time stepping/end time": 1}
            record(f"decay l={l} tau", s, run(s, 1))
# 6. Time-dependent solvers (decaying mode l = 2, BDF2, tau = 0.05): direct with reuse, direct without, block.
for ref in range(2, (3 if quick else 4) + 1) if not multiplier_only else ():
    block = {"fixed surface solver/linear solver": "block preconditioned"}
    cartesian = {**block, "fixed surface solver/velocity AMG node frames": "false"}
    lor = {**block, "fixed surface solver/velocity AMG operator": "low-order refined"}
    stokes = {"flow/convection": "false"}
    for extra in ({}, {"linear solver/reuse factorization": "false"}, block, cartesian, lor,
                  stokes, {**stokes, **block}, {**stokes, **cartesian}, {**stokes, **lor}):
        s = {"geometry/shape": "sphere", "geometry/refinement": ref, "fixed surface/problem": "decaying mode",
             "flow/Re": 10, "time stepping/time step": 0.05, "time stepping/end time": 1, **extra}
        tag = "time solver" + ("" if "linear solver/reuse factorization" not in extra else " no reuse")
        record(tag, s, run(s))

with open(os.path.join(outdir, "results.csv"), "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=columns)
    w.writeheader()
    w.writerows(rows)

# Work–precision figure.
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
ax = axes[0]
def series(filter_fn):
    pts = [(float(r["wall time"]), float(r["gradient L2"])) for r in rows if filter_fn(r)]
    return zip(*sorted(pts)) if pts else ([], [])
for label, fn, style in [
        ("direct KLU, k=2", lambda r: r["case"] == "stationary solver" and "Klu" in r["solver"] and str(r["k"]) == "2", "o-"),
        ("direct KLU, k=3", lambda r: r["case"] == "stationary solver" and "Klu" in r["solver"] and str(r["k"]) == "3", "s--"),
        ("direct MUMPS, k=2", lambda r: r["case"] == "stationary solver" and "Mumps" in r["solver"] and str(r["k"]) == "2", "^-"),
        ("direct MUMPS, k=3", lambda r: r["case"] == "stationary solver" and "Mumps" in r["solver"] and str(r["k"]) == "3", "v--"),
        ("GMRES + block AMG (node frames), k=2", lambda r: r["case"] == "stationary solver" and r["solver"].startswith("block") and str(r["k"]) == "2", "d-"),
        ("GMRES + block AMG (node frames), k=3", lambda r: r["case"] == "stationary solver" and r["solver"].startswith("block") and str(r["k"]) == "3", "D--"),
        ("GMRES + block AMG (Cartesian), k=2", lambda r: r["case"] == "stationary solver amg" and r["velocity AMG"] == "Q2, Cartesian" and str(r["k"]) == "2", "x:"),
        ("GMRES + LOR AMG (node frames), k=2", lambda r: r["case"] == "stationary solver amg" and r["velocity AMG"] == "low-order refined, node frames", "+:")]:
    x, y = series(fn)
    ax.loglog(list(x), list(y), style, label=label)
ax.set_xlabel("wall time [s] (median of %d)" % repeats)
ax.set_ylabel(r"$\|\nabla_P(u-u_h)\|_{L^2}$")
ax.set_title("stationary Stokes, manufactured solution, unit sphere")
ax.grid(True, which="both", alpha=0.3)
ax.legend()
ax = axes[1]
for label, fn, style in [
        ("NS, direct + reuse", lambda r: r["case"] == "time solver" and r["convection"] == "true" and r["solver"].startswith("direct"), "o-"),
        ("NS, direct, no reuse", lambda r: r["case"] == "time solver no reuse", "x--"),
        ("NS, block AMG (node frames)", lambda r: r["case"] == "time solver" and r["convection"] == "true" and r["velocity AMG"] == "Q2, node frames", "d-"),
        ("Stokes, direct", lambda r: r["case"] == "time solver" and r["convection"] == "false" and r["solver"].startswith("direct"), "s-"),
        ("Stokes, block AMG (node frames)", lambda r: r["case"] == "time solver" and r["convection"] == "false" and r["velocity AMG"] == "Q2, node frames", "^-")]:
    pts = sorted((float(r["wall time"]), float(r["velocity L2"])) for r in rows if fn(r))
    if pts:
        x, y = zip(*pts)
        ax.loglog(x, y, style, label=label)
ax.set_xlabel("wall time [s] for t in [0, 1], 20 BDF2 steps")
ax.set_ylabel(r"$\|u(1)-u_h(1)\|_{L^2}$")
ax.set_title(r"decaying mode curl$_S Y_2^0$, Re = 10, refinements 2..")
ax.grid(True, which="both", alpha=0.3)
ax.legend()
fig.tight_layout()
fig.savefig(os.path.join(outdir, "work_precision.png"), dpi=120)
print("wrote", os.path.join(outdir, "results.csv"), "and work_precision.png")
