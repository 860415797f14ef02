#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The map's axisymmetric end states against the rotating equilibrium of the same v and L (issue 33's independent check).

    /usr/bin/python3 benchmarks/end_states/variational.py <fluid_surface> <results.csv> ... > variational.csv

For every steady row of the given results files whose shape is `oblate` and whose L0 > 0 (a body of revolution
spinning about its symmetry axis), `fluid_surface --equilibrium` computes the critical point of
W + L²/(2 I_zz) on the oblate branch at the row's v and measured L₀ (A = 4π, Be = 1; Chebyshev collocation of the
generating curve, independent of the surface mesh and of the time stepping). Columns: the row's v, L0, start, its F,
W and ω, the equilibrium's, and the relative differences.
"""
import csv
import os
import subprocess
import sys
import tempfile


def equilibrium(exe, v, L, directory):
    prm = os.path.join(directory, "equilibrium.prm")
    with open(prm, "w") as f:
        f.write("subsection equilibrium\n  set reduced volume = %s\n  set branch = oblate\n  set Be = 1\n"
                "  set angular momentum = %s\n  set output file = %s\nend\n"
                % (v, L, os.path.join(directory, "curve.csv")))
    out = subprocess.run([exe, "--equilibrium", prm], capture_output=True, text=True, check=True).stdout
    values = {}
    for line in out.splitlines():
        if ": " in line:
            key, value = line.split(": ", 1)
            values[key.strip()] = value.strip()
    return float(values["total energy"]), float(values["bending energy"]), float(values["angular velocity"])


exe, files = sys.argv[1], sys.argv[2:]
writer = csv.writer(sys.stdout, lineterminator="\n")
writer.writerow(["file", "v", "L0", "start", "F", "W", "omega", "F equilibrium", "W equilibrium",
                 "omega equilibrium", "F rel. difference", "W rel. difference", "omega rel. difference"])
with tempfile.TemporaryDirectory() as directory:
    for name in files:
        for row in csv.DictReader(open(name)):
            if row["shape"] != "oblate" or float(row["L0"]) <= 0 or row["status"] != "steady":
                continue
            F, W, omega = (float(row[k]) for k in ("F", "W", "omega"))
            Fe, We, omegae = equilibrium(exe, row["v"], row["L0 measured"], directory)
            writer.writerow([os.path.relpath(name), row["v"], row["L0"], row["start"], F, W, omega,
                             "%.9f" % Fe, "%.9f" % We, "%.9f" % omegae, "%+.1e" % (F / Fe - 1),
                             "%+.1e" % (W / We - 1), "%+.1e" % (omega / omegae - 1)])
