# SPDX-License-Identifier: LGPL-2.1-or-later
"""The energy budget of runs of scene full: B(t) = F(t) + ∫₀ᵗ D, F the total energy, D the dissipation rate
(trapezoidal rule over the accepted steps). The continuous model has dB/dt = 0; a step that puts energy in raises B.

    /usr/bin/python3 benchmarks/end_states/energy_budget.py RUN_DIRECTORY [...]   # one CSV row per run

Columns: the run, its end time, F(0), F(end), the largest rise of B over any interval, max_{s<t} (B(t) − B(s)),
relative to |F(0)| and per unit time (the rise over the time it took), and the number of steps with B rising."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "phase3"))
import statistics_columns  # noqa: E402


def budget(path):
    c = statistics_columns.read(os.path.join(path, "statistics"))
    t, f, d = c["time"], c["total energy"], c["dissipation rate"]
    b, integral = [f[0]], 0.0
    for i in range(1, len(t)):
        integral += 0.5 * (d[i] + d[i - 1]) * (t[i] - t[i - 1])
        b.append(f[i] + integral)
    rise, rise_time, low, low_time = 0.0, 0.0, b[0], t[0]
    for ti, bi in zip(t, b):
        if bi - low > rise:
            rise, rise_time = bi - low, ti - low_time
        if bi < low:
            low, low_time = bi, ti
    rising = sum(1 for i in range(1, len(b)) if b[i] > b[i - 1])
    rate = rise / rise_time if rise_time > 0 else 0.0
    return t[-1], f[0], f[-1], rise / abs(f[0]), rate / abs(f[0]), rising


print("run,end time,F(0),F(end),max rise of F+int D (rel.),its rate per unit time (rel.),steps with F+int D rising")
for path in sys.argv[1:]:
    end, f0, f1, rise, rate, rising = budget(path)
    print(f"{os.path.basename(os.path.normpath(path))},{end:.4f},{f0:.6f},{f1:.6f},{rise:.2e},{rate:.2e},{rising}")
