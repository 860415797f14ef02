#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/work_precision/relaxation.sh: the oblate's relaxation (prm/oblate.prm at refinement 3) with the linear
# and the quadratic normal predictor, at τ_max 0.1 and 0.025 to t = 3 and at a fixed τ = 0.00625 to t = 1.2 (the
# reference); oblate_relaxation_r3.csv holds the total energy F and the mesh quality at t = 0.1, 0.2, …, 3
# (linear interpolation between steps).
#   benchmarks/work_precision/relaxation.sh [--table]     from the repository root, after building
#     --table: only tabulate the runs in WORK
# Environment: WORK (default benchmarks/work_precision/work/relaxation, not committed), EXE.
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/work_precision
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/$here/work/relaxation}
mkdir -p "$work"
runs="linear_0.1 qn_0.1 linear_0.025 qn_0.025 linear_fixed0.00625 qn_fixed0.00625"
if [ "${1:-}" != "--table" ]; then
  for run in $runs; do
    predictor=$(case $run in qn*) echo "quadratic normal";; *) echo linear;; esac)
    tau=${run#*_}; fixed=""; end=3
    case $tau in fixed*) tau=${tau#fixed}; fixed=1; end=1.2;; esac
    {
      echo "include $PWD/prm/oblate.prm"
      echo "subsection geometry"; echo "  set refinement = 3"; echo "end"
      echo "subsection time stepping"; echo "  set end time = $end"; echo "  set maximum time step = $tau"
      [ -n "$fixed" ] && echo "  set time step = $tau"
      echo "end"
      echo "subsection geometry iteration"; echo "  set predictor = $predictor"; echo "end"
      echo "subsection output"; echo "  set output directory = $work/$run"; echo "  set overwrite = true"
      echo "  set write vtu = false"; echo "  set screen interval = 100000"; echo "end"
    } > "$work/$run.prm"
    "$exe" "$work/$run.prm" > "$work/$run.log" 2>&1; echo "$run: exit $?"
  done
fi
/usr/bin/python3 - "$work" $runs > "$here/oblate_relaxation_r3.csv" <<'PY'
import os, sys
sys.path.insert(0, os.path.join("benchmarks", "phase3"))
import statistics_columns
work, runs = sys.argv[1], sys.argv[2:]
columns = {run: statistics_columns.read(os.path.join(work, run, "statistics")) for run in runs}
def at(c, key, t):
    ts, vs = c["time"], c[key]
    for i in range(1, len(ts)):
        if ts[i] >= t - 1e-12:
            w = (t - ts[i - 1]) / (ts[i] - ts[i - 1])
            return f"{(1 - w) * vs[i - 1] + w * vs[i]:.4f}"
    return ""
print("t," + ",".join(f"F {r},mesh quality {r}" for r in runs))
for k in range(1, 31):
    t = k / 10
    print(f"{t:g}," + ",".join(at(columns[r], "total energy", t) + "," + at(columns[r], "mesh quality", t) for r in runs))
PY
cat "$here/oblate_relaxation_r3.csv"
