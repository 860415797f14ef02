#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The velocity at the mesh vertices along the meridian y = 0, x ≥ 0 of a body of revolution about z, from one VTU
file of a run (doc/scheme.md, "The plateau at rest": the parasitic current is a two-cell zigzag).
    /usr/bin/python3 benchmarks/energy_law/meridian.py RUN/solution-NNNNN.vtu
Prints per vertex, from the south pole to the north pole: the polar angle atan2(z, x), x, z, the meridional velocity
u·(e_y × n), the normal velocity u·n, the azimuthal velocity u_y and the bending scalar y; then the largest and rms
speed and the largest |u·n| over all vertices."""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tests"))
from output_hdf5 import read_vtu  # noqa: E402


def main(name):
    points, _, fields = read_vtu(name)
    u, n = fields["velocity"], fields["normal"]
    on_meridian = (np.abs(points[:, 1]) < 1e-4) & (points[:, 0] > -1e-9)
    seen = set()
    print("angle x z u_meridional u_normal u_azimuthal y")
    for k in sorted(np.flatnonzero(on_meridian), key=lambda k: math.atan2(points[k, 2], points[k, 0])):
        angle = math.atan2(points[k, 2], points[k, 0])
        if round(angle, 5) in seen:
            continue
        seen.add(round(angle, 5))
        tangent = np.cross([0.0, 1.0, 0.0], n[k])
        print(f"{angle:+.3f} {points[k, 0]:.3f} {points[k, 2]:+.3f} {u[k] @ tangent:+.3e} {u[k] @ n[k]:+.2e} "
              f"{u[k, 1]:+.1e} {fields['bending_scalar'][k, 0]:+.4f}")
    speed = np.linalg.norm(u, axis=1)
    print(f"max speed {speed.max():.3e}, rms {math.sqrt((speed ** 2).mean()):.3e}, "
          f"max |u.n| {np.abs((u * n).sum(axis=1)).max():.3e}")


if __name__ == "__main__":
    main(sys.argv[1])
