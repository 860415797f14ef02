#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/work_precision/order.sh: the temporal order of the full model's step, measured. prm/oblate.prm is run
# to t0 = 1 (past the initial relaxation, whose fast bending waves no τ here resolves); from its checkpoint each
# scheme runs the window [1, 1.8] at fixed τ (adaptive = false; the geometry iterated once, N_g = 1, ε_g = 0, so
# that only the time discretization differs). Errors: the largest difference on t = 1.1, 1.2, …, 1.8 from a
# reference run of BDF2 with τ = 1/1280 (--quick: 1/640) (the final time alone can sit near a zero of the oscillating error).
#   benchmarks/work_precision/order.sh [--quick]      from the repository root, after building
# Refinement 3 (--quick: 2, and two τ). Environment: WORK (default benchmarks/work_precision/work/order), EXE.
# Writes order.csv and order.png.
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/work_precision
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/$here/work/order}
refinement=3
taus="0.025 0.0125 0.00625 0.003125"
reference_tau=0.00078125
if [ "${1:-}" = "--quick" ]; then refinement=2; taus="0.0125 0.00625"; reference_tau=0.0015625; work=$work/quick; fi
t0=1
t1=1.8
mkdir -p "$work"

common() {
  printf 'include %s/prm/oblate.prm\nsubsection geometry\n  set refinement = %s\nend\n' "$PWD" $refinement
  printf 'subsection geometry iteration\n  set maximum iterations = 1\n  set tolerance = 0\n  set apply = always\nend\n'
}

start=$work/start
if ! grep -q '^status: completed' $start/summary 2>/dev/null; then
  { common; printf 'subsection time stepping\n  set end time = %s\nend\nsubsection output\n  set output directory = %s\n  set overwrite = true\n  set write vtu = false\n  set screen interval = 100000\nend\n' $t0 $start; } > $work/start.prm
  $exe $work/start.prm > $work/start.log 2>&1 || { echo "start run failed"; tail -3 $work/start.log; exit 1; }
fi

runs=""
reference=BDF2_$reference_tau
for name in $reference $(for t in $taus; do echo "backward_Euler_$t BDF2_$t"; done); do
  scheme=${name%_*}; tau=${name##*_}
  dir=$work/$name
  [ $name = $reference ] || runs="$runs $name"
  if grep -q '^status: completed' $dir/summary 2>/dev/null; then echo "$name: kept"; continue; fi
  rm -rf $dir; mkdir -p $dir
  cp -r $start/checkpoint $start/statistics $dir/
  { common; printf 'subsection time stepping\n  set end time = %s\n  set time step = %s\n  set adaptive = false\n  set scheme = %s\nend\n' $t1 $tau "${scheme/_/ }"
    printf 'subsection checkpoint\n  set resume = auto\nend\nsubsection output\n  set output directory = %s\n  set write vtu = false\n  set screen interval = 100000\nend\n' $dir; } > $work/$name.prm
  $exe $work/$name.prm > $work/$name.log 2>&1
  echo "$name exit $?"
done
/usr/bin/python3 $here/order.py $work $t0 $t1 $reference $runs | tee $here/order.csv
