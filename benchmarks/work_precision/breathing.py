#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The breathing of the oblate's relaxation: frequency and decay of the oscillation of ω(t), against BDF2's.

    benchmarks/work_precision/breathing.py <name>=<run directory> ... > breathing.csv

For each run (a `statistics` file of scene full): the step τ (median over the window), the frequency ν of ω(t) on
t ∈ [0.5, 3.5] (the peak of a Hann-windowed Fourier sum, detrended), the peak-to-peak amplitude of ω on [1, 1.5),
[2, 2.5) and [3, 3.5), the decay rate of that amplitude from the first window to the last, and BDF2's own frequency
and damping rate for a mode of frequency NU (default 22.0, the finest run's) at that τ: the principal root r of
(3/2 − iντ) r² − 2r + 1/2 = 0, ν_BDF2 = arg(r)/τ, damping −ln|r|/τ. The measured decay minus BDF2's damping is the
mode's own decay if the step is the only other cause.
"""
import cmath
import math
import os
import sys

WINDOW = (0.5, 3.5)
AMPLITUDE_WINDOWS = [(1.0, 1.5), (2.0, 2.5), (3.0, 3.5)]
NU = float(os.environ.get("NU", "22.0"))


def read(path):
    rows = []
    for line in open(os.path.join(path, "statistics")):
        if not line.startswith("#") and line.strip():
            rows.append([float(x) for x in line.split()])
    return [(r[1], r[2], r[10]) for r in rows]  # time, τ, angular velocity


def frequency(samples):
    t = [s[0] for s in samples]
    y = [s[2] for s in samples]
    n = len(t)
    mt, my = sum(t) / n, sum(y) / n
    slope = sum((a - mt) * (b - my) for a, b in zip(t, y)) / sum((a - mt) ** 2 for a in t)
    y = [b - my - slope * (a - mt) for a, b in zip(t, y)]
    span = t[-1] - t[0]
    hann = [0.5 - 0.5 * math.cos(2 * math.pi * (a - t[0]) / span) for a in t]

    def power(nu):
        return abs(sum(h * b * cmath.exp(-1j * nu * a) for a, b, h in zip(t, y, hann)))

    best = max((power(0.25 * k), 0.25 * k) for k in range(8, 240))[1]
    lo, hi = best - 0.25, best + 0.25
    for _ in range(30):  # golden-section refinement of the peak
        m1, m2 = lo + 0.382 * (hi - lo), lo + 0.618 * (hi - lo)
        if power(m1) > power(m2):
            hi = m2
        else:
            lo = m1
    return 0.5 * (lo + hi)


def bdf2(nu, tau):
    z = 1j * nu * tau
    a = 1.5 - z
    root = max(((2 + s * cmath.sqrt(4 - 2 * a)) / (2 * a) for s in (1, -1)), key=abs)
    return cmath.phase(root) / tau, -math.log(abs(root)) / tau


print("run,tau,nu measured,nu BDF2,omega p2p [1 1.5),omega p2p [2 2.5),omega p2p [3 3.5),decay measured,"
      "BDF2 damping,decay minus BDF2 damping")
for argument in sys.argv[1:]:
    name, path = argument.split("=", 1)
    samples = [s for s in read(path) if WINDOW[0] < s[0] < WINDOW[1]]
    taus = sorted(s[1] for s in samples)
    tau = taus[len(taus) // 2]
    amplitudes = []
    for a, b in AMPLITUDE_WINDOWS:
        w = [s[2] for s in samples if a <= s[0] < b]
        amplitudes.append(max(w) - min(w))
    decay = math.log(amplitudes[0] / amplitudes[-1]) / (AMPLITUDE_WINDOWS[-1][0] - AMPLITUDE_WINDOWS[0][0])
    nu_bdf2, damping = bdf2(NU, tau)
    print(f"{name},{tau:.6g},{frequency(samples):.2f},{nu_bdf2:.2f},"
          + ",".join(f"{a:.4f}" for a in amplitudes)
          + f",{decay:.3f},{damping:.3f},{decay - damping:.3f}")
