#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/rotating_modes (issue 33): the growth rate of a seeded azimuthal mode of a rotating equilibrium, measured
# in full nonlinear runs at a fixed τ, for the old step (the lab frame) and the co-rotating step
# (`time stepping/frame = Tisserand`), backward Euler and BDF2, against the linearized rate σ of scene stability and
# the one-mode prediction ln|z(λτ)|/τ (predict.py) with λ = σ + iν_seen, ν_seen = ν + mΩ (lab) or ν (co-rotating).
#   benchmarks/rotating_modes/run.sh [--quick]        from the repository root, after building
#     --quick: the oblate's m = 2 even at refinement 2, τ = 0.1 and 0.05 (8 runs, minutes), in WORK/quick; its table
#     is WORK/quick/results.csv (the committed results_quick.csv is an earlier quick run, not overwritten)
# Environment: WORK (default benchmarks/rotating_modes/work, not committed), EXE, JOBS (runs at once, default 1),
# REFINEMENT (default 3), TAUS (default "0.1 0.05 0.025"), CASES (default: the three modes below), SCHEMES
# (default "be bdf2"; bdf2 is the shipped BDF2 with the linear predictor of the geometry, bdf2s the one from S^m,
# bdf2q the quadratic one, bdf2n quadratic normal; sdirk2 the two-stage SDIRK with the linear predictor, sdirk2s from S^m), FRAMES (default "lab Tisserand"), OUT (default results.csv, results_quick.csv at REFINEMENT=2; with --quick
# WORK/quick/results.csv).
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/rotating_modes
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/$here/work}
refinement=${REFINEMENT:-3}; taus=${TAUS:-"0.1 0.05 0.025"}
cases=${CASES:-"oblate:2:even prolate:1:even prolate:2:even"}
end=3
out=$here/${OUT:-results$([ $refinement = 2 ] && echo _quick).csv}
if [ "${1:-}" = "--quick" ]; then
  refinement=2; taus="0.1 0.05"; cases="oblate:2:even"; end=2.5; work=$work/quick; out=$work/results.csv
  [ -n "${OUT:-}" ] && out=$here/$OUT
  shift
fi
mkdir -p "$work"
queue=""
for c in $cases; do
  IFS=: read -r shape m parity <<< "$c"
  for s in ${SCHEMES:-be bdf2}; do for frame in ${FRAMES:-lab Tisserand}; do for tau in $taus; do
    # bdf2: the shipped BDF2 (linear predictor of the geometry); bdf2s: from S^m (the step before); bdf2q: quadratic
    scheme=$(case $s in be) echo "backward Euler";; sdirk2*) echo SDIRK2;; *) echo BDF2;; esac)
    predictor=$(case $s in bdf2s|sdirk2s) echo "old surface";; bdf2q) echo quadratic;; bdf2n) echo "quadratic normal";; *) echo linear;; esac)
    name=${shape}_m${m}_${parity}_r${refinement}_${s}_${frame}_tau${tau}
    {
      echo "include $PWD/prm/seeded_mode_$shape.prm"
      echo "subsection geometry"; echo "  set refinement = $refinement"; echo "end"
      echo "subsection initial state"; echo "  set azimuthal wavenumber = $m"; echo "  set azimuthal parity = $parity"; echo "end"
      echo "subsection time stepping"; echo "  set end time = $end"; echo "  set time step = $tau"
      echo "  set maximum time step = $tau"; echo "  set scheme = $scheme"; echo "  set frame = $frame"; echo "end"
      # the predictor only where it is not the default (linear)
      [ "$predictor" != linear ] && { echo "subsection geometry iteration"; echo "  set predictor = $predictor"; echo "end"; }
      echo "subsection output"; echo "  set output directory = $work/$name"; echo "  set overwrite = true"
      echo "  set write vtu = false"; echo "  set screen interval = 100000"; echo "end"
    } > "$work/$name.prm"
    queue="$queue $name"
  done; done; done
done
run_one() {
  start=$(date +%s.%N)
  "$exe" "$work/$1.prm" > "$work/$1.log" 2>&1
  status=$?
  echo "$1 $status $(echo "$(date +%s.%N) - $start" | bc)" > "$work/$1.exit"
  echo "$1 exit $status"
}
export -f run_one; export exe work
echo $queue | tr ' ' '\n' | xargs -P "${JOBS:-1}" -I{} bash -c 'run_one {}'
/usr/bin/python3 $here/table.py "$work" $queue > "$out.tmp" || exit 1
mv "$out.tmp" "$out"
cat "$out"
