#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/step_limit: the largest fixed τ at which the step stays stable inside the fast shape change (the
# symmetry-breaking transformation) of the seed's prolate and oblate, for the lagged step and the step with
# implicit geometry (subsection geometry iteration).
#   benchmarks/step_limit/run.sh [--quick]        from the repository root, after building
# 1. A start checkpoint per case inside the fastest part of its transformation: prm/prolate_long.prm to t = 20
#    (refinement 3) or 18 (refinement 4), prm/oblate_long.prm to t = 4.75, at the case's refinement (kept in
#    $WORK and reused).
# 2. From it, a window of WINDOW time units at each fixed τ (adaptive = false, so that one rejected step, an
#    energy rise above 'energy tolerance', ends the case) for each scheme.
# Environment: CASES (default "prolate:3 oblate:3"), TAUS, SCHEMES (default "lagged anderson"; also aitken, normal, metric), WINDOW (0.5),
# WORK (default benchmarks/step_limit/work, not committed), ITERATIONS (N_g of the iterated schemes, default 10), LIMIT (s/case).
# Rows go to cases/<case>.csv, results.csv collects them; plot.py draws step_limit.png. --quick: the oblate at
# refinement 3, τ = 0.05 and 0.0125, a window of 0.1, lagged and anderson; its cases/, results.csv and step_limit.png go
# to benchmarks/step_limit/quick/ (not committed), its runs to WORK/quick (the start checkpoint is WORK's, shared).
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/step_limit
exe=${EXE:-$PWD/build/fluid_surface}
cases=${CASES:-"prolate:3 oblate:3"}
taus=${TAUS-"0.1 0.05 0.025 0.0125 0.00625 0.003125"}
schemes=${SCHEMES:-"lagged anderson"}
window=${WINDOW:-0.5}
iterations=${ITERATIONS:-10}
limit=${LIMIT:-3600}
work=${WORK:-$PWD/benchmarks/step_limit/work}
out=$here; runs=$work
if [ "${1:-}" = "--quick" ]; then cases="oblate:3"; taus="0.05 0.0125"; window=0.1; out=$here/quick; runs=$work/quick; fi
mkdir -p "$work" "$runs" $out/cases

# lagged: one solve on S^m. aitken, anderson: the implicit geometry with that relaxation. normal, metric: only ñ (with
# c) or only the metric from the iterate (which lagged quantity sets the limit), Anderson's mixing. all1, normal1:
# one re-assembly whatever its change (tolerance 0: a predictor–corrector step of two solves); mid1: all1 on the
# midpoint surface (time level ½); metric1: one re-assembly with only the metric from the predicted surface; bdf2:
# all1 with time stepping/scheme = BDF2 (second order). relaxation, implicit and time level are written only where they
# differ from their defaults (anderson, all, 1), which are also what a program without these entries does: lagged,
# anderson, all1 and bdf2 run with either; aitken, normal, metric, normal1, mid1 and metric1 need the entries (a
# program that does not declare them refuses the case, exit 2).
scheme_lines() {
  iterate() {
    printf 'subsection geometry iteration\n  set maximum iterations = %s\n  set tolerance = %s\n' "$1" "$2"
    [ "$3" != anderson ] && printf '  set relaxation = %s\n' "$3"
    [ "$4" != all ] && printf '  set implicit = %s\n' "$4"
    [ "${5:-1}" != 1 ] && printf '  set time level = %s\n' "$5"
    printf '  set apply = always\nend\n'
  }
  case $1 in
    lagged) printf 'subsection geometry iteration\n  set maximum iterations = 0\nend\n' ;;
    aitken) iterate $iterations 1e-3 aitken all ;;
    anderson) iterate $iterations 1e-3 anderson all ;;
    normal|metric) iterate $iterations 1e-3 anderson $1 ;;
    all1) iterate 1 0 anderson all ;;
    normal1) iterate 1 0 anderson normal ;;
    mid1) iterate 1 0 anderson all 0.5 ;;
    metric1) iterate 1 0 anderson metric ;;
    bdf2) iterate 1 0 anderson all; printf 'subsection time stepping\n  set scheme = BDF2\nend\n' ;;
  esac
  # every other scheme is the backward-Euler step it was measured with: the _long prm files now step with BDF2, which
  # the program refuses with the lagged geometry (maximum iterations = 0)
  [ "$1" != bdf2 ] && printf 'subsection time stepping\n  set scheme = backward Euler\nend\n'
}

for c in $cases; do
  shape=${c%%:*}; r=${c##*:}
  # inside the fastest part of the transformation (benchmarks/phase3/experiments: the τ of the adaptive runs)
  case $shape:$r in prolate:3) t0=20;; prolate:*) t0=18;; oblate:*) t0=4.75;; esac
  start=$work/start_${shape}_r$r
  if [ ! -f $start/checkpoint/last ] || ! grep -q "status: completed" $start/summary 2>/dev/null; then
    cat > $work/start_${shape}_r$r.prm <<PRM
include $PWD/prm/${shape}_long.prm
subsection geometry
  set refinement = $r
end
subsection time stepping
  set end time = $t0
end
subsection output
  set output directory = $start
  set write vtu = false
  set screen interval = 100000
end
subsection checkpoint
  set resume = auto
end
PRM
    echo "start checkpoint $shape r$r (t = $t0)"
    $exe $work/start_${shape}_r$r.prm > $work/start_${shape}_r$r.log 2>&1 || { echo "start run failed"; tail -3 $work/start_${shape}_r$r.log; continue; }
  fi
  for s in $schemes; do for tau in $taus; do
    name=${shape}_r${r}_${s}_tau$tau
    dir=$runs/$name
    rm -rf $dir; mkdir -p $dir
    cp -r $start/checkpoint $start/statistics $dir/
    cat > $runs/$name.prm <<PRM
include $PWD/prm/${shape}_long.prm
subsection geometry
  set refinement = $r
end
subsection time stepping
  set end time = $(echo "$t0 + $window" | bc -l)
  set adaptive = false
  set time step = $tau
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
$(scheme_lines $s)
PRM
    begin=$(date +%s.%N)
    timeout $limit $exe $runs/$name.prm > $runs/$name.log 2>&1; status=$?
    wall=$(echo "$(date +%s.%N) - $begin" | bc)
    /usr/bin/python3 $here/summarize.py $dir/statistics "$shape" "$r" "$s" "$tau" "$t0" "$window" "$status" "$wall" \
      "$(grep -h -m1 'rejected at' $runs/$name.log | head -c 300)" > $out/cases/$name.csv
    tail -1 $out/cases/$name.csv
  done; done
done
{ echo "shape,refinement,scheme,tau,t0,window,exit,t reached,completed,steps,F end,max rise/(tau F),geometry iterations mean,geometry iterations max,factorizations,wall s,s per step,reason"
  cat $out/cases/*.csv; } > $out/results.csv
/usr/bin/python3 $here/plot.py $out/results.csv $out/step_limit.png
