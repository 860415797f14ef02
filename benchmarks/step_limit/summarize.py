# SPDX-License-Identifier: LGPL-2.1-or-later
"""One row of benchmarks/step_limit/results.csv from a case's statistics (the rows after the start time t0)."""
import sys

sys.path.insert(0, __file__.rsplit("/", 2)[0] + "/phase3")
import statistics_columns  # noqa: E402

path, shape, r, scheme, tau, t0, window, status, wall, reason = sys.argv[1:11]
t0, window, tau, wall = float(t0), float(window), float(tau), float(wall)
try:
    s = statistics_columns.read(path)
except OSError:
    s = {}
time = s.get("time", [])
rows = [i for i, t in enumerate(time) if t > t0 + 1e-9]
F = s.get("total energy", [])
rises = [(F[i] - F[i - 1]) / (s["tau"][i] * abs(F[i - 1])) for i in rows if i > 0]
iters = [s["geometry iterations"][i] for i in rows] if "geometry iterations" in s else []
fact = sum(s["factorized"][i] for i in rows) if "factorized" in s else 0
reached = time[rows[-1]] if rows else t0
completed = reached >= t0 + window - 1e-9
steps = len(rows)
print(",".join(str(x) for x in [
    shape, r, scheme, tau, t0, window, status, f"{reached:.6g}", int(completed), steps,
    f"{F[rows[-1]]:.10g}" if rows else "", f"{max(rises):.3g}" if rises else "",
    f"{sum(iters) / len(iters):.3g}" if iters else "", int(max(iters)) if iters else "", int(fact),
    f"{wall:.1f}", f"{wall / steps:.3g}" if steps else "", '"' + reason.replace('"', "'") + '"']))
