#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The class of each end state of the map (issue 49, item 5): minimum, or saddle with its count of growing directions.

    /usr/bin/python3 benchmarks/end_states/classify.py RESULTS_CSV OUT_CSV [EXE]     # EXE: build/fluid_surface

An end state that spins about its axis of symmetry (an oblate about its short axis, tilt 90; a prolate about its long
axis, tilt 0; either at rest) is the rotating axisymmetric equilibrium of its v and L (L the run's own |L|, A = 4π,
Be = 1). `EXE --equilibrium` computes that equilibrium and the second variation at fixed A, V and L per azimuthal
number m ≤ 4 and parity (doc/stability.md); a negative eigenvalue of m = 0 is one direction in which the energy falls,
one of m ≥ 1 two (cos mφ, sin mφ); |λ| ≤ 1e-7 (the rigid tilt at rest) is not counted. Columns added to the map's:
  branch          oblate, prolate, or "3D" for an end state that is not axisymmetric about its rotation axis
  F equilibrium   the energy of that equilibrium
  F - F_eq        the run's F minus it (the spatial error of the run at its refinement, if it is that state)
  negative        the negative eigenvalues as m/parity:λ
  class           minimum | saddle (k directions) | "scene stability" (3D: not classified here) | not steady;
                  "plateau at a …" for a run that stopped at a plateau (F flat while the flow dissipates: held by
                  the discretization, not an end state of the model; doc/scheme.md, "Steady state")
"""
import csv
import os
import re
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
exe = sys.argv[3] if len(sys.argv) > 3 else os.path.join(here, "..", "..", "build", "fluid_surface")


def branch_of(row):
    if row.get("status") not in ("steady", "plateau"):
        return None
    tilt = float(row["tilt angle"])
    if row["shape"] == "oblate" and (tilt > 80 or float(row["L0"]) == 0):
        return "oblate"
    if row["shape"] == "prolate" and (tilt < 10 or float(row["L0"]) == 0):
        return "prolate"
    if row["shape"] == "sphere":
        return "oblate"
    return "3D"


def second_variation(v, branch, L):
    prm = (f"subsection equilibrium\n  set reduced volume = {v}\n  set branch = {branch}\n  set Be = 1\n"
           f"  set angular momentum = {L}\nend\nsubsection second variation\n  set modes = 0, 1, 2, 3, 4\n"
           "  set eigenvalues = 3\n  set basis size = 24\nend\n")
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, "sv.prm"), "w") as f:
            f.write(prm)
        out = subprocess.run([exe, "--equilibrium", "sv.prm"], cwd=work, capture_output=True, text=True)
    if out.returncode != 0:
        return None, [], out.stderr.strip().splitlines()[-1:] or ["failed"]
    energy = float(re.search(r"^total energy: (\S+)", out.stdout, re.M).group(1))
    negative = []
    for m, parity, values in re.findall(r"^second variation isolated m (\d+) (even|odd): (.*)$", out.stdout, re.M):
        for value in map(float, values.split()):
            if value < -1e-7:
                negative.append((int(m), parity, value))
    return energy, negative, None


rows = list(csv.DictReader(open(sys.argv[1])))
for row in rows:
    branch = branch_of(row)
    row.update({"branch": branch or "", "F equilibrium": "", "F - F_eq": "", "negative": ""})
    if branch is None:
        row["class"] = "not steady" if row.get("F") else "not run"
        continue
    if branch == "3D":
        row["class"] = "scene stability"
        continue
    L = float(row["L0 measured"])
    energy, negative, error = second_variation(row["v"], branch, L)
    if energy is None:
        row["class"] = "equilibrium failed: " + error[0].replace(",", ";")
        continue
    directions = sum(1 if m == 0 else 2 for m, _, _ in negative)
    row["F equilibrium"] = f"{energy:.8g}"
    row["F - F_eq"] = f"{float(row['F']) - energy:.2e}"
    row["negative"] = " ".join(f"{m}/{p}:{value:.4g}" for m, p, value in negative)
    row["class"] = "minimum" if directions == 0 else f"saddle ({directions} directions)"

for row in rows:
    # The state a plateau holds is classified too, but it is not an end state of the model at this refinement.
    if row.get("status") == "plateau":
        row["class"] = "plateau at a " + row["class"].replace("scene stability", "3D state (scene stability)")

fields = list(rows[0].keys())
with open(sys.argv[2], "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=fields)
    w.writeheader()
    w.writerows(rows)
counts = {}
for row in rows:
    key = row["class"].split(" (")[0]
    counts[key] = counts.get(key, 0) + 1
print(", ".join(f"{n} {k}" for k, n in sorted(counts.items())), "->", sys.argv[2])
