# SPDX-License-Identifier: LGPL-2.1-or-later
"""The energy budget of runs of scene full: B(t) = F(t) + ∫₀ᵗ D, F the total energy, D the dissipation rate
(trapezoidal rule over the accepted steps). The continuous model has dB/dt = 0; a step that puts energy in raises B.

    /usr/bin/python3 benchmarks/end_states/energy_budget.py RUN_DIRECTORY [...]   # one CSV row per run

Columns: the run, its end time, F(0), F(end), the largest rise of B over any interval, max_{s<t} (B(t) − B(s)),
relative to |F(0)| and per unit time (the rise over the time it took), and the number of steps with B rising.
Then the per-step law of the program's summary (`steps breaking the energy law`, time stepping/energy law tolerance):
r_m = F^{m+1} − F^m + τD^{m+1} with the step's own D against 2τ|D^{m+1} − D^m| + (ε_L τ + 1e-9)|F^m| (ε_L = 1e-6 unless
--law-tolerance is given): the steps above it, those after t = 1.5 (past the relaxation of the map's spins), and the
largest excess r_m − bound."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "phase3"))
import statistics_columns  # noqa: E402


LAW_TOLERANCE = 1e-6


def budget(path, law_tolerance=LAW_TOLERANCE):
    """(end time, F(0), F(end), largest rise of B relative to |F(0)|, its rate per unit time, steps with B rising,
    steps breaking the per-step law, of them after t = 1.5, the largest excess over the law's bound)."""
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
    tau = c["tau"]
    breaking, late, excess = 0, 0, 0.0
    for i in range(1, len(t)):
        law = f[i] - f[i - 1] + tau[i] * d[i]
        bound = 2 * tau[i] * abs(d[i] - d[i - 1]) + (law_tolerance * tau[i] + 1e-9) * abs(f[i - 1])
        if law > bound:
            breaking += 1
            late += t[i] > 1.5
            excess = max(excess, law - bound)
    return t[-1], f[0], f[-1], rise / abs(f[0]), rate / abs(f[0]), rising, breaking, late, excess


def main(arguments):
    law_tolerance = LAW_TOLERANCE
    if "--law-tolerance" in arguments:
        k = arguments.index("--law-tolerance")
        law_tolerance = float(arguments[k + 1])
        del arguments[k:k + 2]
    print("run,end time,F(0),F(end),max rise of F+int D (rel.),its rate per unit time (rel.),steps with F+int D rising,"
          "steps breaking the law,of them after t = 1.5,largest excess over the bound")
    for path in arguments:
        end, f0, f1, rise, rate, rising, breaking, late, excess = budget(path, law_tolerance)
        print(f"{os.path.basename(os.path.normpath(path))},{end:.4f},{f0:.6f},{f1:.6f},{rise:.2e},{rate:.2e},{rising},"
              f"{breaking},{late},{excess:.2e}")


if __name__ == "__main__":
    main(sys.argv[1:])
