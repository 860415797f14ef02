#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/end_states: one row per run of run.sh from its statistics and summary.
    /usr/bin/python3 benchmarks/end_states/table.py WORK results.csv
Columns: v, L0 (nominal), start, F, W, omega, lambda1 ≤ lambda2 ≤ lambda3 (inertia eigenvalues), rigid fraction,
end time, shape, tilt angle (degrees between the rotation vector and the axis of least inertia: 90 for a body
rotating about a transverse axis), status (steady | plateau: F flat while the flow dissipates, held by the
discretization | not steady | stopped: …), L0 measured (|L| at t = 0), end dissipation (rel.) (∫D over the last
unit of time over |F|: a run that stopped "steady" with it ≥ 1e-6, the steady-state test's δ, is a plateau),
saddles left and end state class (the summary's lines of `steady state/saddle check`: minimum | saddle | 3D (scene
stability) | not classified; empty for a build before it or a run that did not end steady; a 3D end state that
spectra.sh analysed: minimum or saddle by its spectrum, see spectrum_class; the other start's row, if it ends in
the same state, "… (as the prolate start's state)").
shape, from the inertia eigenvalues with δ = 1e-2 relative to λ₃:
  sphere      λ₃ − λ₁ < δλ₃
  prolate     λ₃ − λ₂ < δλ₃: elongated, nearly a body of revolution about the axis of least inertia
  oblate      λ₂ − λ₁ < δλ₃: flattened, nearly a body of revolution about the axis of largest inertia
  triaxial    otherwise
A steady state rotates about its axis of largest inertia: a steady prolate tumbles (tilt 90), a steady oblate
spins about its symmetry axis."""
import csv
import glob
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "phase3"))
import statistics_columns  # noqa: E402
from energy_budget import budget  # noqa: E402


def shape_class(l1, l2, l3, delta=1e-2):
    if l3 - l1 < delta * l3:
        return "sphere"
    if l3 - l2 < delta * l3:
        return "prolate"
    if l2 - l1 < delta * l3:
        return "oblate"
    return "triaxial"


def spectrum_class(directory, least_normal_share=0.05, least_symmetry_share=0.5, resolution=1e-3):
    """The class of a 3D end state from spectra.sh's scene stability (directory/spectrum.csv), None without one
    (doc/stability.md, "Which modes grow"). Rows that only slide the nodes (normal share below least_normal_share)
    and the neutral modes of the symmetries (the translations and the turn about the rotation axis: symmetry share
    at least least_symmetry_share) are set aside. Each other row has σ to within b = ln(1/(1 − r))/T (r its residual,
    T the map time): it grows if σ − b > 0 and decays if σ + b < 0. One grows: a saddle, with its directions (one
    for a real multiplier, two for a pair); all decay: a minimum; else undecided. A spectrum without the symmetry
    share column (a build before it) counts a row as growing if σ > resolution."""
    try:
        rows = list(csv.DictReader(open(os.path.join(directory, "spectrum.csv"))))
    except OSError:
        return None
    if not rows:
        return None
    prm = open(os.path.join(directory, "used_parameters.prm")).read()
    T = float(re.search(r"set map time\s*=\s*([0-9.eE+-]+)", prm).group(1))
    shape = [r for r in rows if float(r["normal share"]) >= least_normal_share]
    if "symmetry share" in rows[0]:
        neutral = [r for r in shape if float(r["symmetry share"]) >= least_symmetry_share]
        shape = [r for r in shape if float(r["symmetry share"]) < least_symmetry_share]
        bound = {id(r): -math.log(max(1e-300, 1 - min(float(r["residual"]), 0.999999))) / T for r in shape}
        growing = [r for r in shape if float(r["growth rate"]) - bound[id(r)] > 0]
        undecided = [r for r in shape if r not in growing and float(r["growth rate"]) + bound[id(r)] >= 0]
    else:
        neutral, undecided = [], []
        growing = [r for r in shape if float(r["growth rate"]) > resolution]
    symmetries = f"; symmetries |σ| ≤ {max(abs(float(r['growth rate'])) for r in neutral):.1e}" if neutral else ""
    leading = max((float(r["growth rate"]) for r in shape), default=float("nan"))
    if growing:
        directions = sum(1 if abs(float(r["multiplier argument"])) < 1e-9 else 2 for r in growing)
        return f"saddle (scene stability: {directions} growing directions; leading σ {leading:.2e}{symmetries})"
    if undecided:
        return f"undecided (scene stability: leading σ {leading:.1e} within its residual's bound{symmetries})"
    return f"minimum (scene stability: leading shape σ {leading:.2e}{symmetries})"


def run_row(run):
    """The columns of one run directory (statistics and summary) from F on; {"status": "not run"} without them."""
    try:
        c = statistics_columns.read(os.path.join(run, "statistics"))
        summary = open(os.path.join(run, "summary")).read() if os.path.exists(os.path.join(run, "summary")) else ""
    except (OSError, ValueError):
        c, summary = None, ""
    if not c or not c.get("time"):
        return {"status": "not run"}
    lam = sorted(c[f"inertia eigenvalue {k}"][-1] for k in (1, 2, 3))
    status = "not steady"
    if "steady state: reached" in summary:
        status = "steady"
    elif "steady state: plateau" in summary:
        status = "plateau"
    elif summary.startswith("status: stopped"):
        # Without the checkpoint's path: the run is named by its prm.
        status = "stopped: " + summary.splitlines()[0][len("status: "):].split("; checkpoint written to")[0].replace(",", ";")
    # The dissipation over the last unit of time (the steady-state window of run.sh) relative to |F|, as the steady
    # state's dissipation test takes it (Σ τD^{m+1}); a run of a build before that test that stopped "steady" with
    # it at or above δ = 1e-6 stopped at a plateau.
    t, D, tau = c["time"], c["dissipation rate"], c["tau"]
    window = [k for k in range(len(t)) if t[k] > t[-1] - 1]
    span = t[-1] - t[window[0] - 1] if window and window[0] > 0 else 0
    end_dissipation = sum(tau[k] * D[k] for k in window) / (span * abs(c["total energy"][-1])) if span > 0 else float("nan")
    if status == "steady" and not end_dissipation < 1e-6:
        status = "plateau"
    L0m = math.sqrt(sum(c[f"angular momentum {d}"][0] ** 2 for d in "xyz"))
    row = {
        "F": f"{c['total energy'][-1]:.8g}", "W": f"{c['bending energy'][-1]:.8g}",
        "omega": f"{c['angular velocity'][-1]:.6g}",
        "lambda1": f"{lam[0]:.6g}", "lambda2": f"{lam[1]:.6g}", "lambda3": f"{lam[2]:.6g}",
        "rigid fraction": f"{c['rigid fraction'][-1]:.6f}", "end time": f"{c['time'][-1]:.6g}",
        "shape": shape_class(*lam), "tilt angle": f"{c['tilt angle'][-1]:.3g}", "status": status, "L0 measured": f"{L0m:.6g}",
        "end dissipation (rel.)": f"{end_dissipation:.2e}"}
    # The program's own class of the end state (`steady state/saddle check`, builds from 2026-12-07 on).
    saddles = re.search(r"^saddles left: (\d+|none)", summary, re.M)
    row["saddles left"] = "" if not saddles else ("0" if saddles.group(1) == "none" else saddles.group(1))
    cls = re.search(r"^end state class: (.*)$", summary, re.M)
    row["end state class"] = "" if not cls else (
        "minimum" if ": a minimum" in cls.group(1) else
        "saddle" if ": a saddle" in cls.group(1) else
        "3D (scene stability)" if "scene stability" in cls.group(1) else "not classified")
    if row["end state class"] == "3D (scene stability)" or (status == "plateau" and row["end state class"] == ""):
        row["end state class"] = spectrum_class(run + "_stability") or row["end state class"]
    _, _, _, rise, _, _, breaking, _, excess = budget(run)
    row.update({"max rise of B (rel.)": f"{rise:.2e}", "steps breaking the law": breaking,
                "largest excess over the bound": f"{excess:.2e}"})
    return row


if __name__ == "__main__":
    rows = []
    for prm in sorted(glob.glob(os.path.join(sys.argv[1], "v*_L*_*.prm"))):
        name = os.path.basename(prm)[:-4]
        m = re.match(r"v([0-9.]+)_L([0-9.]+)_(prolate|oblate)$", name)
        if not m:
            continue
        v, L0, start = m.groups()
        rows.append({"v": v, "L0": L0, "start": start, **run_row(os.path.join(sys.argv[1], name))})

    # Both starts of a point that end steady in one state (the same shape, F within 1e-5 relative: the refinement-3
    # spread of one state reached from the two starts) share its class: spectra.sh analyses one of them.
    for r in rows:
        if r.get("status") != "steady" or r.get("end state class") != "3D (scene stability)":
            continue
        for o in rows:
            if (o["v"], o["L0"]) == (r["v"], r["L0"]) and o is not r and o.get("status") == "steady" \
                    and o["shape"] == r["shape"] and abs(float(o["F"]) - float(r["F"])) <= 1e-5 * abs(float(r["F"])) \
                    and o["end state class"].split(" (")[0] in ("minimum", "saddle"):
                r["end state class"] = f"{o['end state class'].split(' (')[0]} (as the {o['start']} start's state)"
    fields = ["v", "L0", "start", "F", "W", "omega", "lambda1", "lambda2", "lambda3", "rigid fraction", "end time",
              "shape", "tilt angle", "status", "L0 measured", "end dissipation (rel.)", "max rise of B (rel.)",
              "steps breaking the law", "largest excess over the bound", "saddles left", "end state class"]
    with open(sys.argv[2], "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for r in sorted(rows, key=lambda r: (float(r["v"]), float(r["L0"]), r["start"])):
            w.writerow(r)
    print(f"{len(rows)} rows, {sum(r.get('status') == 'steady' for r in rows)} steady -> {sys.argv[2]}")
