#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/step_cost/mpi.sh NP: one window of the oblate's transformation at refinement 4 on NP MPI ranks, for
# `farm-bench --vs` (one rank against two). prm/oblate.prm as shipped, resumed from a checkpoint at t = 4.75 (made
# once by benchmarks/step_limit/run.sh, CASES=oblate:4) to t = 5.0; the checkpoint is copied for each run, so every
# run does the same steps.
#   farm-bench -n 2 --timeout 1200 -- benchmarks/step_cost/mpi.sh 2 --vs 'benchmarks/step_cost/mpi.sh 1'
set -eu
cd "$(dirname "$0")/../.."
np=$1
start=${START:-$PWD/benchmarks/step_limit/work/start_oblate_r4}
[ -f $start/checkpoint/last ] || { echo "no start checkpoint $start (run benchmarks/step_limit/run.sh with CASES=oblate:4)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf $work' EXIT
mkdir -p $work/run
cp -r $start/checkpoint $start/statistics $work/run/
cat > $work/window.prm <<PRM
include $PWD/prm/oblate.prm
subsection time stepping
  set end time = 5.0
end
subsection checkpoint
  set resume = true
end
subsection output
  set output directory = $work/run
  set write vtu = false
  set screen interval = 100000
end
PRM
mpirun --allow-run-as-root --oversubscribe -np $np $PWD/build/fluid_surface $work/window.prm > $work/log 2>&1 || { tail -3 $work/log >&2; exit 1; }
grep -E "^(steps|rejected steps|LU factorizations|wall time):" $work/run/summary >&2
