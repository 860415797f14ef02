#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The stability chart of the rotating axisymmetric equilibria (issue 49, item 2) from `fluid_surface --equilibrium`'s
second variation (doc/stability.md): for each branch (oblate spinning about its short axis, prolate about its long
one) and reduced volume v, the lowest eigenvalue of the second variation over m = 0…4 and both parities at fixed A,
V, L (isolated) and at fixed A, V, ω (driven), on a grid of L, and the smallest L where it is negative, bisected.

    /usr/bin/python3 benchmarks/stability_chart/chart.py EXE OUT_DIRECTORY [--quick]

Writes OUT_DIRECTORY/scan.csv (every evaluation) and OUT_DIRECTORY/chart.csv (one row per branch and v: L_c, ω_c of
the isolated body at L_c, the class that turns negative there, and the same for the driven body). A = 4π, Be = 1.
"""
import csv
import os
import subprocess
import sys
import tempfile

exe, out = sys.argv[1], sys.argv[2]
quick = "--quick" in sys.argv
os.makedirs(out, exist_ok=True)
VS = [0.6, 0.65] if quick else [0.55, 0.6, 0.62, 0.64, 0.66, 0.7, 0.75, 0.8, 0.85, 0.9, 0.95, 0.99]
LS = [0, 1, 2, 5, 10, 20] if quick else [0, 0.5, 1, 2, 3, 5, 7.5, 10, 15, 20, 30, 40, 60]
BISECTIONS = 4 if quick else 10
REFINEMENTS = 30
scan = []
cache = {}


def evaluate(branch, v, L):
    """Lowest isolated and driven eigenvalue and their classes at (branch, v, L); None where no equilibrium."""
    if (branch, v, L) not in cache:
        cache[(branch, v, L)] = solve(branch, v, L)
    return cache[(branch, v, L)]


def solve(branch, v, L):
    with tempfile.TemporaryDirectory() as work:
        prm = os.path.join(work, "sv.prm")
        with open(prm, "w") as f:
            f.write(f"subsection equilibrium\n  set reduced volume = {v}\n  set branch = {branch}\n  set Be = 1\n"
                    f"  set angular momentum = {L}\n  set output file = {os.path.join(work, 'curve.csv')}\nend\n"
                    "subsection second variation\n  set modes = 0, 1, 2, 3, 4\n  set eigenvalues = 1\n"
                    "  set basis size = 24\nend\n")
        run = subprocess.run([exe, "--equilibrium", prm], capture_output=True, text=True)
    if run.returncode != 0:
        return None
    lowest = {"isolated": (float("inf"), ""), "driven": (float("inf"), "")}
    by_class = {"isolated": {}, "driven": {}}
    omega, bending = float("nan"), float("nan")
    for line in run.stdout.splitlines():
        if line.startswith("angular velocity:"):
            omega = float(line.split(":")[1])
        if line.startswith("bending energy:"):
            bending = float(line.split(":")[1])
        if line.startswith("second variation isolated m") or line.startswith("second variation driven m"):
            head, values = line.split(":")
            words = head.split()
            kind, cls = words[2], f"m = {words[4]} {words[5]}"
            value = float(values.split()[0])
            by_class[kind][cls] = value
            # the zero modes (a rigid tilt at rest) are not instabilities
            if value < lowest[kind][0] and abs(value) > 1e-7:
                lowest[kind] = (value, cls)
    row = dict(branch=branch, v=v, L=L, omega=omega, bending_energy=bending, isolated=lowest["isolated"][0],
               isolated_class=lowest["isolated"][1], driven=lowest["driven"][0], driven_class=lowest["driven"][1])
    scan.append(row)
    row = dict(row, by_class=by_class)
    return row


def crossing(branch, v, kind):
    """The smallest L of the grid interval in which the lowest `kind` eigenvalue turns negative, bisected."""
    previous = None
    for L in LS:
        row = evaluate(branch, v, L)
        if row is None:
            return dict(L="no equilibrium", omega="", cls="", at="beyond L = %g" % (previous["L"] if previous else 0))
        if row[kind] < 0:
            if previous is None:
                return dict(L=0.0, omega=row["omega"], cls=row[kind + "_class"], at="negative at rest")
            lo, hi, hi_row = previous["L"], L, row
            for _ in range(BISECTIONS):
                mid = 0.5 * (lo + hi)
                r = evaluate(branch, v, mid)
                if r is None:
                    break
                if r[kind] < 0:
                    hi, hi_row = mid, r
                else:
                    lo = mid
            cls = hi_row[kind + "_class"]
            if lo > 0:
                return refine(branch, v, kind, cls, lo, hi, hi_row)
            return dict(L=hi, omega=hi_row["omega"], cls=cls, at="bisected to %.1e" % (hi - lo))
        previous = row
    return dict(L="> %g" % LS[-1], omega="", cls="", at="positive on the grid")


def refine(branch, v, kind, cls, lo, hi, hi_row):
    """The zero of the class's lowest eigenvalue in [lo, hi] by regula falsi (Illinois): it is smooth in L."""
    value = lambda row: row["by_class"][kind][cls] if row else None
    f_lo, f_hi = value(evaluate(branch, v, lo)), value(hi_row)
    if f_lo is None or f_hi is None or not f_lo > 0 > f_hi:
        return dict(L=hi, omega=hi_row["omega"], cls=cls, at="bisected to %.1e" % (hi - lo))
    side, row = 0, hi_row
    for _ in range(REFINEMENTS):
        L = hi - f_hi * (hi - lo) / (f_hi - f_lo)
        row = evaluate(branch, v, L)
        f = value(row)
        if f is None:
            break
        if abs(f) < 1e-9 or hi - lo < 1e-9:
            return dict(L=L, omega=row["omega"], cls=cls, at="root: |lambda| = %.0e" % abs(f))
        if f < 0:
            hi, f_hi = L, f
            f_lo = f_lo / 2 if side == -1 else f_lo
            side = -1
        else:
            lo, f_lo = L, f
            f_hi = f_hi / 2 if side == 1 else f_hi
            side = 1
    return dict(L=hi, omega=row["omega"], cls=cls, at="bracketed to %.1e" % (hi - lo))


def resting_limit(branch, v_stable, v_unstable, cls):
    """The v between two of the grid where the resting equilibrium's class eigenvalue is zero (L_c reaches 0), by
    the secant method at L = 0."""
    def value(v):
        row = evaluate(branch, v, 0.0)
        return row["by_class"]["isolated"].get(cls) if row else None

    v0, v1, f0, f1 = v_stable, v_unstable, value(v_stable), value(v_unstable)
    for _ in range(REFINEMENTS):
        if f0 is None or f1 is None:
            return None, None
        if abs(f1) < 1e-9 or abs(v1 - v0) < 1e-12:
            break
        v0, v1, f0 = v1, v1 - f1 * (v1 - v0) / (f1 - f0), f1
        f1 = value(v1)
    return dict(L=0.0, omega=0.0, cls=cls, at="L_c reaches 0 here: |lambda| = %.0e at rest" % abs(f1)), v1


rows = []
for branch in ["oblate", "prolate"]:
    for v in VS:
        iso = crossing(branch, v, "isolated")
        drv = crossing(branch, v, "driven")
        if (rows and rows[-1][0] == branch and rows[-1][5].startswith("root") and iso["at"] == "negative at rest"
                and rows[-1][4] == iso["cls"]):
            limit, v_limit = resting_limit(branch, rows[-1][1], v, iso["cls"])
        else:
            limit = None
        if limit:
            rows.append([branch, v_limit, 0.0, 0.0, limit["cls"], limit["at"], 0.0, 0.0, limit["cls"], limit["at"]])
            print(branch, v_limit, limit, flush=True)
        rows.append([branch, v, iso["L"], iso["omega"], iso["cls"], iso["at"], drv["L"], drv["omega"], drv["cls"], drv["at"]])
        print(branch, v, iso, drv, flush=True)
with open(os.path.join(out, "chart.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["branch", "v", "L_c isolated", "omega at L_c isolated", "class isolated", "how isolated",
                "L_c driven", "omega_c driven", "class driven", "how driven"])
    w.writerows(rows)
with open(os.path.join(out, "scan.csv"), "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(scan[0].keys()), extrasaction="ignore")
    w.writeheader()
    w.writerows(sorted(scan, key=lambda r: (r["branch"], r["v"], r["L"])))
