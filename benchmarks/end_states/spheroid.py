#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Semi-axes (a, a, c) of the spheroid of area 4π and reduced volume v (prolate: c > a, oblate: c < a), its
surface moment of inertia I_zz = ∫(x² + y²) dA about the symmetry axis, and ω₀ = L₀/I_zz.
    python3 spheroid.py v prolate|oblate L0     prints: a c omega0 Izz"""
import math
import sys


def area(a, c):
    if abs(a - c) < 1e-12:
        return 4 * math.pi * a * a
    if c > a:
        e = math.sqrt(1 - a * a / (c * c))
        return 2 * math.pi * a * a * (1 + c / (a * e) * math.asin(e))
    e = math.sqrt(1 - c * c / (a * a))
    return 2 * math.pi * a * a * (1 + (1 - e * e) / e * math.atanh(e))


def scaled(k):
    """(a, c) with c/a = k and area 4π."""
    s = math.sqrt(4 * math.pi / area(1.0, k))
    return s, s * k


def reduced_volume(k):
    a, c = scaled(k)
    return a * a * c  # V/(4π/3) with A = 4π


def semi_axes(v, kind):
    # v(k) rises from 0 to 1 as k goes to 1 from either side: bisection in log k
    lo, hi = (0.0, 8.0) if kind == "prolate" else (-8.0, 0.0)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        below = reduced_volume(math.exp(mid)) < v
        if kind == "prolate":
            lo, hi = (lo, mid) if below else (mid, hi)
        else:
            lo, hi = (mid, hi) if below else (lo, mid)
    return scaled(math.exp(0.5 * (lo + hi)))


def inertia_zz(a, c, n=20000):
    total = 0.0
    for i in range(n):
        t = math.pi * (i + 0.5) / n
        s, co = math.sin(t), math.cos(t)
        total += a * a * s * s * a * s * math.sqrt(a * a * co * co + c * c * s * s)
    return 2 * math.pi * total * math.pi / n


if __name__ == "__main__":
    v, kind, L0 = float(sys.argv[1]), sys.argv[2], float(sys.argv[3])
    a, c = semi_axes(v, kind)
    I = inertia_zz(a, c)
    print(f"{a:.10f} {c:.10f} {L0 / I:.10f} {I:.10f}")
