#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/phase3: the perturbed rotating oblate of prm/oblate.prm through its symmetry breaking (the paper's
# phase 3), with the mesh law `bgn` (the earlier default) and `reference`, at refinements 3 and 4.
#   benchmarks/phase3/run.sh [--quick]        from the repository root, after building
# Environment: REFINEMENTS (default "3 4"), LAWS (default "bgn reference"), END (default 7), LIMIT (wall-time
# limit per case in s, default 3600), EXTRA (prm lines appended to every case, e.g. time stepping entries).
# Each case writes cases/<case>.statistics and a row of results.csv; plot.py draws phase3.png. --quick (refinement 2
# to t = 0.3) writes cases/, results.csv and phase3.png to benchmarks/phase3/quick/ (not committed).
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/phase3
exe=${EXE:-./build/fluid_surface}
refinements=${REFINEMENTS:-"3 4"}; laws=${LAWS:-"bgn reference"}; end=${END:-7}; limit=${LIMIT:-3600}
out=$here
[ "${1:-}" = "--quick" ] && { refinements=2; end=0.3; limit=300; out=$here/quick; }
work=$(mktemp -d)
mkdir -p $out/cases
for r in $refinements; do for law in $laws; do
  name=oblate_r${r}_$law
  cat > $work/$name.prm <<PRM
include $PWD/prm/oblate.prm
subsection geometry
  set refinement = $r
end
subsection initial state
  set shape perturbation = 0.01
end
subsection mesh redistribution
  set law = $law
end
subsection time stepping
  set end time = $end
end
subsection output
  set output directory = $work/$name
  set write vtu = false
  set screen interval = 100000
end
${EXTRA:-}
PRM
  start=$(date +%s.%N)
  timeout $limit $exe $work/$name.prm > $work/$name.log 2>&1; status=$?
  wall=$(echo "$(date +%s.%N) - $start" | bc)
  cp $work/$name/statistics $out/cases/$name.statistics 2>/dev/null
  cp $work/$name/summary $out/cases/$name.summary 2>/dev/null
  /usr/bin/python3 $here/summarize.py $out/cases/$name.statistics $name $status $wall "$(grep -h 'error:' $work/$name.log | tail -1)" > $out/cases/$name.csv
done; done
{ echo "case,exit,t reached,steps,rejected,t_sym_1e-4,t_sym_1e-2,median tau,min tau,max rise/(tau F),min mesh quality,max |dA/A|,max |dV/V|,max |dL/L|,F end,bending end,omega end,rigid fraction end,tilt end,max e,wall s,outcome"
  cat $out/cases/*.csv; } > $out/results.csv
/usr/bin/python3 $here/plot.py $out/cases $out/phase3.png
