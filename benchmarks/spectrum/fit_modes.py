# SPDX-License-Identifier: LGPL-2.1-or-later
"""Growth rate and frequency of one azimuthal wavenumber from a seeded run's `statistics` (the columns
`mode <m> <parity> amplitude` and `… phase` of diagnostics/azimuthal modes).

    fit_modes.py <run directory> <m> <even|odd> [t0 t1] [--baseline <unperturbed run directory>]

The window defaults to the second half of the span in which |Q_m| stays below 1e3 times its first value (the
linear regime, after the seed's other eigen-components of wavenumber m have decayed). Prints one CSV row:
m, parity, growth rate, frequency, t0, t1, growth rate first half, growth rate second half, where the growth rate
is the least-squares slope of log|Q_m|, and the frequency that of the unwrapped arg Q_m minus m⟨ω⟩ (the pattern's
turning relative to the body, in the co-rotating frame; > 0: it runs ahead). The two half-window rates show
whether one mode dominates (they agree) or several still compete. With --baseline, the moment of the unperturbed
run from the same equilibrium (interpolated in time) is subtracted first: the mesh's own content (m = 4 on the
cube-sphere mesh) and its evolution as the discrete equilibrium settles are not the seeded mode's."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "phase3"))
import statistics_columns  # noqa: E402


def slope(t, y):
    n = len(t)
    mt, my = sum(t) / n, sum(y) / n
    return sum((a - mt) * (b - my) for a, b in zip(t, y)) / sum((a - mt) ** 2 for a in t)


def unwrap(phases):
    out = [phases[0]]
    for p in phases[1:]:
        d = p - out[-1]
        out.append(out[-1] + d - 2 * math.pi * round(d / (2 * math.pi)))
    return out


def moment(columns, name):
    return [a * complex(math.cos(p), math.sin(p)) for a, p in zip(columns[name + " amplitude"], columns[name + " phase"])]


def interpolate(t, y, s):
    for i in range(1, len(t)):
        if t[i] >= s:
            w = (s - t[i - 1]) / (t[i] - t[i - 1])
            return (1 - w) * y[i - 1] + w * y[i]
    return y[-1]


def fit(run, m, parity, window=None, baseline=None):
    c = statistics_columns.read(os.path.join(run, "statistics"))
    name = f"mode {m} {parity}"
    t, omega = c["time"], c["angular velocity"]
    q = moment(c, name)
    if baseline:
        b = statistics_columns.read(os.path.join(baseline, "statistics"))
        qb = moment(b, name)
        q = [v - interpolate(b["time"], qb, s) for v, s in zip(q, t)]
    amp, phase = [abs(v) for v in q], [math.atan2(v.imag, v.real) for v in q]
    if window is None:
        end = next((i for i, a in enumerate(amp) if a > 1e3 * amp[0]), len(t) - 1)
        window = (0.5 * (t[0] + t[end]), t[end])
    idx = [i for i in range(len(t)) if window[0] <= t[i] <= window[1] and amp[i] > 0]
    if len(idx) < 6:
        raise SystemExit(f"{run}: fewer than 6 samples of {name} in [{window[0]}, {window[1]}]")
    ts = [t[i] for i in idx]
    logs = [math.log(amp[i]) for i in idx]
    sigma = slope(ts, logs)
    turning = slope(ts, unwrap([phase[i] for i in idx]))
    mean_omega = sum(omega[i] for i in idx) / len(idx)
    h = len(idx) // 2
    return dict(m=m, parity=parity, sigma=sigma, frequency=turning - m * mean_omega, t0=window[0], t1=window[1],
                sigma_first=slope(ts[:h], logs[:h]), sigma_second=slope(ts[h:], logs[h:]))


if __name__ == "__main__":
    args = sys.argv[1:]
    base = None
    if "--baseline" in args:
        i = args.index("--baseline")
        base = args[i + 1]
        del args[i:i + 2]
    run, m, parity = args[0], int(args[1]), args[2]
    window = (float(args[3]), float(args[4])) if len(args) > 4 else None
    r = fit(run, m, parity, window, base)
    print(f"{r['m']},{r['parity']},{r['sigma']:.5f},{r['frequency']:.5f},{r['t0']:.3f},{r['t1']:.3f},"
          f"{r['sigma_first']:.5f},{r['sigma_second']:.5f}")
