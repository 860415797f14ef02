#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/spectrum: growth rates and frequencies of the rotating equilibria by azimuthal wavenumber, from seeded
# runs of the full nonlinear model (issue 23, the second route): prm/seeded_mode_<shape>.prm with one mode h_m
# (m = 1..4, even and odd) at amplitude 1e-5, the moment Q_m, less that of an unperturbed run from the same
# equilibrium, fitted by fit_modes.py.
#   benchmarks/spectrum/seeded_modes.sh [--quick] [shape ...]     from the repository root, after building
#     (shapes: oblate prolate; --quick: m = 2 even only, to t = 2)
# Environment: WORK (default benchmarks/spectrum/work, not committed), EXE, JOBS (runs at once, default 1),
# REFINEMENT (default: the prm's), TAU_MAX (default: the prm's), MODES (default "1 2 3 4"), PARITIES (default
# "even odd").
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/spectrum
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/$here/work}
modes=${MODES:-"1 2 3 4"}; parities=${PARITIES:-"even odd"}; end=""
if [ "${1:-}" = "--quick" ]; then modes=2; parities=even; end=2; shift; fi
shapes=${*:-"oblate prolate"}
mkdir -p "$work"
suffix=${REFINEMENT:+_r$REFINEMENT}${TAU_MAX:+_tau$TAU_MAX}
# One unperturbed run per shape first (m = 0 stands for it): fit_modes.py subtracts its moments.
queue=$(for shape in $shapes; do for m in baseline $modes; do for p in $parities; do
  [ $m = baseline ] && [ $p != even ] && continue
  name=${shape}_m${m}_${p}$suffix; [ $m = baseline ] && name=${shape}_baseline$suffix
  {
    echo "include $PWD/prm/seeded_mode_$shape.prm"
    if [ $m = baseline ]; then
      echo "subsection initial state"; echo "  set shape perturbation = 0"; echo "  set perturbation form = random"; echo "end"
    else
      echo "subsection initial state"; echo "  set azimuthal wavenumber = $m"; echo "  set azimuthal parity = $p"; echo "end"
    fi
    echo "subsection time stepping"
    [ -n "$end" ] && echo "  set end time = $end"
    [ -n "${TAU_MAX:-}" ] && echo "  set maximum time step = $TAU_MAX"
    echo "end"
    [ -n "${REFINEMENT:-}" ] && { echo "subsection geometry"; echo "  set refinement = $REFINEMENT"; echo "end"; }
    echo "subsection output"; echo "  set output directory = $work/$name"; echo "  set overwrite = true"
    echo "  set write vtu = false"; echo "  set screen interval = 100000"; echo "end"
  } > "$work/$name.prm"
  echo "$name"
done; done; done)
run_one() { "$exe" "$work/$1.prm" > "$work/$1.log" 2>&1; echo "$1 exit $?"; }
export -f run_one; export exe work
echo "$queue" | xargs -P "${JOBS:-1}" -I{} bash -c 'run_one {}'
echo "run,m,parity,growth rate,frequency,t0,t1,growth rate first half,growth rate second half" > "$work/seeded_modes.csv"
for name in $queue; do
  case $name in *_baseline*) continue;; esac
  shape=${name%%_m*}; m=$(echo $name | sed 's/.*_m\([0-9]*\)_.*/\1/'); p=$(echo $name | sed 's/.*_m[0-9]*_\([a-z]*\).*/\1/')
  row=$(/usr/bin/python3 $here/fit_modes.py "$work/$name" $m $p --baseline "$work/${shape}_baseline$suffix" 2>&1) \
    && echo "$name,$row" >> "$work/seeded_modes.csv" || echo "$name: $row"
done
cat "$work/seeded_modes.csv"
