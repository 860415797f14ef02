#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/step_limit/growth.sh: does a step scheme keep the growth rate of the oblate's symmetry breaking?
# prm/oblate.prm at refinement 3 to t = 2.6 with the maximum time step τ (adaptive otherwise: the step reaches τ by
# t ≈ 1), for each scheme of run.sh; σ is the growth rate of the symmetry deviation e(λ) over t ∈ [1.5, 2.5]
# (the linear phase; the lagged step gives σ ≈ 2.5 at every τ from 0.005 to 0.09). Rows to growth.csv.
#   benchmarks/step_limit/growth.sh [--quick]        from the repository root, after building
# Environment: SCHEMES (default "lagged normal1 all1 mid1"), TAUS (default "0.05 0.025 0.0125"), WORK, EXE.
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/step_limit
exe=${EXE:-$PWD/build/fluid_surface}
schemes=${SCHEMES:-"lagged normal1 all1 mid1"}
taus=${TAUS:-"0.05 0.025 0.0125"}
work=${WORK:-$PWD/benchmarks/step_limit/work}
[ "${1:-}" = "--quick" ] && { schemes="lagged normal1"; taus="0.05"; }
mkdir -p "$work" $here/growth
source <(sed -n '/^scheme_lines()/,/^}/p' $here/run.sh)
iterations=10
for s in $schemes; do for tau in $taus; do
  name=growth_${s}_tau$tau
  (
    cat > $work/$name.prm <<PRM
include $PWD/prm/oblate.prm
subsection geometry
  set refinement = 3
end
subsection time stepping
  set end time = 2.6
  set maximum time step = $tau
end
subsection output
  set output directory = $work/$name
  set overwrite = true
  set write vtu = false
  set screen interval = 100000
end
$(scheme_lines $s)
PRM
    begin=$(date +%s.%N)
    $exe $work/$name.prm > $work/$name.log 2>&1; status=$?
    wall=$(echo "$(date +%s.%N) - $begin" | bc)
    /usr/bin/python3 - "$work/$name/statistics" "$s" "$tau" "$status" "$wall" > $here/growth/$name.csv <<'PY'
import math, sys
sys.path.insert(0, "benchmarks/phase3")
import statistics_columns
path, scheme, tau, status, wall = sys.argv[1:]
c = statistics_columns.read(path)
t, e = c["time"], c["symmetry deviation"]
def at(T):
    i = min(range(len(t)), key=lambda k: abs(t[k] - T))
    return t[i], e[i]
(t0, e0), (t1, e1) = at(1.5), at(2.5)
sigma = math.log(e1 / e0) / (t1 - t0) if e0 > 0 and e1 > 0 else float("nan")
print(f"{scheme},{tau},{status},{t[-1]:.4g},{len(t) - 1},{e0:.4e},{e1:.4e},{sigma:.4f},{float(wall):.1f}")
PY
    cat $here/growth/$name.csv
  )
done; done
{ echo "scheme,tau max,exit,t reached,steps,e(1.5),e(2.5),growth rate,wall s"; cat $here/growth/*.csv; } > $here/growth.csv
