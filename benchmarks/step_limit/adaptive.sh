#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/step_limit/adaptive.sh: the same windows as run.sh (from its start checkpoints, which must exist), with
# adaptive τ: today's default (lagged step, τ grown by the growth factor, the energy check) against the implicit
# geometry with the step from the local error estimate at several tolerances. A row per run in adaptive.csv:
# steps, rejected steps, geometry iterations, wall time and F at the end of the window (compare with the smallest
# fixed τ of results.csv).
#   benchmarks/step_limit/adaptive.sh [--quick]
# Environment: CASES (default "oblate:3 prolate:3"), TOLERANCES (default "1e-2 1e-3 1e-4"), WINDOW, WORK, EXE.
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/step_limit
exe=${EXE:-$PWD/build/fluid_surface}
cases=${CASES:-"oblate:3 prolate:3"}
tolerances=${TOLERANCES:-"1e-2 1e-3 1e-4"}
window=${WINDOW:-0.5}
work=${WORK:-$PWD/benchmarks/step_limit/work}
[ "${1:-}" = "--quick" ] && { cases="oblate:3"; tolerances="1e-2"; window=0.1; }
mkdir -p $here/adaptive
for c in $cases; do
  shape=${c%%:*}; r=${c##*:}
  case $shape:$r in prolate:3) t0=20;; prolate:*) t0=18;; oblate:*) t0=4.75;; esac
  start=$work/start_${shape}_r$r
  [ -f $start/checkpoint/last ] || { echo "no start checkpoint $start: run run.sh first"; continue; }
  for variant in default $(for e in $tolerances; do echo implicit_$e; done); do
    name=${shape}_r${r}_adaptive_$variant
    dir=$work/$name
    rm -rf $dir; mkdir -p $dir
    cp -r $start/checkpoint $start/statistics $dir/
    if [ $variant = default ]; then
      lines=""
    else
      lines=$(printf 'subsection geometry iteration\n  set maximum iterations = 20\n  set tolerance = 1e-3\nend\nsubsection time stepping\n  set error tolerance = %s\nend\n' "${variant#implicit_}")
    fi
    cat > $work/$name.prm <<PRM
include $PWD/prm/${shape}_long.prm
subsection geometry
  set refinement = $r
end
subsection time stepping
  set end time = $(echo "$t0 + $window" | bc -l)
end
subsection output
  set output directory = $dir
  set write vtu = false
  set screen interval = 100000
end
subsection checkpoint
  set resume = true
  set wall time between checkpoints = 0
end
$lines
PRM
    begin=$(date +%s.%N)
    $exe $work/$name.prm > $work/$name.log 2>&1; status=$?
    wall=$(echo "$(date +%s.%N) - $begin" | bc)
    /usr/bin/python3 - "$dir/statistics" "$shape" "$r" "$variant" "$t0" "$status" "$wall" > $here/adaptive/$name.csv <<'PY'
import sys
sys.path.insert(0, "benchmarks/phase3")
import statistics_columns
path, shape, r, variant, t0, status, wall = sys.argv[1:]
s = statistics_columns.read(path)
rows = [i for i, t in enumerate(s["time"]) if t > float(t0) + 1e-9]
taus = sorted(s["tau"][i] for i in rows)
it = [s["geometry iterations"][i] for i in rows]
print(",".join(str(x) for x in [shape, r, variant, status, f"{s['time'][rows[-1]]:.6g}", len(rows),
      f"{taus[len(taus) // 2]:.3g}", f"{s['total energy'][rows[-1]]:.10g}", f"{sum(it) / len(it):.3g}",
      int(sum(s["factorized"][i] for i in rows)), f"{float(wall):.1f}"]))
PY
    cat $here/adaptive/$name.csv
  done
done
{ echo "shape,refinement,variant,exit,t reached,steps,median tau,F end,geometry iterations mean,factorizations,wall s"
  cat $here/adaptive/*.csv; } > $here/adaptive.csv
