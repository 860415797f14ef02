# SPDX-License-Identifier: LGPL-2.1-or-later
"""One results.csv row from a statistics file: python3 summarize.py STATISTICS NAME EXIT WALL MESSAGE."""
import statistics
import sys

import statistics_columns

path, name, status, wall, message = sys.argv[1:6]
col = statistics_columns.read(path)
F, t, tau = col["total energy"], col["time"], col["tau"][1:] or [0]
rises = [(b - a) / (s * abs(a)) for a, b, s in zip(F, F[1:], tau) if b > a]
L = [sum(col[f"angular momentum {d}"][k] ** 2 for d in "xyz") ** 0.5 for k in range(len(F))]
drift = lambda c: max(abs(x - c[0]) / abs(c[0]) for x in c)
summary = {}
try:
    for line in open(path.replace(".statistics", ".summary")):
        key, _, value = line.partition(": ")
        summary[key.strip()] = value.strip()
except OSError:
    pass
outcome = (message or "completed") if status == "0" else ("wall-time limit" if status == "124" else (message.split("error: ", 1)[-1] or f"exit {status}"))
print(",".join([name, status, f"{t[-1]:.6g}", str(len(t) - 1), summary.get("rejected steps", "?"), summary.get("t_sym_1e-4", "?"), summary.get("t_sym_1e-2", "?"), f"{statistics.median(tau):.3g}",
                f"{min(tau):.3g}", f"{max(rises, default=0):.3g}", f"{min(col['mesh quality']):.3g}",
                summary.get("max area drift", f"{drift(col['area']):.2e}"), summary.get("max volume drift", f"{drift(col['volume']):.2e}"),
                summary.get("max angular momentum drift", f"{drift(L):.2e}"), f"{F[-1]:.8g}",
                f"{col['bending energy'][-1]:.8g}", f"{col['angular velocity'][-1]:.6g}", f"{col['rigid fraction'][-1]:.4f}",
                f"{col['tilt angle'][-1]:.4g}", f"{max(col['symmetry deviation']):.3g}", f"{float(wall):.0f}",
                '"' + outcome.replace('"', "'") + '"']))
