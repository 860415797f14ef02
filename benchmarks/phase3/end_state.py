# SPDX-License-Identifier: LGPL-2.1-or-later
"""The end state of a run from its statistics file (python3 end_state.py STATISTICS): F, bending energy W, ω, the
inertia eigenvalues, rigid fraction, the angle between the rotation vector Ω = I⁻¹L and L (zero iff Ω is a
principal axis), the inertia I_Ω = |L|²/(L·Ω) about it, and the identity of a rigid rotation about the axis of
largest inertia, F = W + |L₀|²/(2 I_max)."""
import math
import sys

import statistics_columns

c = statistics_columns.read(sys.argv[1])
end = -1
L = [c[f"angular momentum {d}"][end] for d in "xyz"]
L0 = [c[f"angular momentum {d}"][0] for d in "xyz"]
W = [c[f"rotation vector {d}"][end] for d in "xyz"]
norm = lambda v: math.sqrt(sum(x * x for x in v))
dot = lambda a, b: sum(x * y for x, y in zip(a, b))
I = sorted(c[f"inertia eigenvalue {k}"][end] for k in (1, 2, 3))
F, Wb = c["total energy"][end], c["bending energy"][end]
angle = math.degrees(math.acos(max(-1.0, min(1.0, dot(L, W) / (norm(L) * norm(W))))))
print(f"t = {c['time'][end]:.6g}")
print(f"F = {F:.8g}, bending energy W = {Wb:.8g}, kinetic = {c['kinetic energy'][end]:.8g}")
print(f"omega = {c['angular velocity'][end]:.6g}, rigid fraction = {c['rigid fraction'][end]:.6f}, tilt = {c['tilt angle'][end]:.4g}")
print(f"inertia eigenvalues = {I[0]:.6g}, {I[1]:.6g}, {I[2]:.6g}; e = {c['symmetry deviation'][end]:.4g}")
print(f"angle(L, Omega) = {angle:.4g} deg; I about Omega = |L|^2/(L.Omega) = {dot(L, L) / dot(L, W):.6g}")
print(f"|L0| = {norm(L0):.8g}, |L| = {norm(L):.8g}, relative drift {abs(norm(L) - norm(L0)) / norm(L0):.2e}")
print(f"W + |L0|^2/(2 I_max) = {Wb + dot(L0, L0) / (2 * I[2]):.8g} against F = {F:.8g} (difference {F - Wb - dot(L0, L0) / (2 * I[2]):.3e})")
if len(c["time"]) > 2:
    dF = (c["total energy"][-1] - c["total energy"][-2]) / (c["time"][-1] - c["time"][-2])
    print(f"dF/dt at the end = {dF:.3e} (|dF/dt|/|F| = {abs(dF) / abs(F):.2e})")
