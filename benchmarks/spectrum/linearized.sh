#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/spectrum: the first route of issue 23, scene stability (prm/stability_<shape>.prm): the leading
# eigenvalues of the rotating equilibria by azimuthal wavenumber and parity from Arnoldi on the linearized time-T
# map, over refinements, time steps and Reynolds numbers; each run's spectrum.csv is collected into
# work/linearized.csv with its settings.
#   benchmarks/spectrum/linearized.sh [--quick] [shape ...]     from the repository root, after building
#     (shapes: oblate prolate; --quick: the oblate's m = 2 even at refinement 2)
# Environment: WORK (default benchmarks/spectrum/work, not committed), EXE, JOBS (runs at once, default 1),
# REFINEMENTS (default "3"), TAUS (default "0.02"), RES (Reynolds numbers, default "1"), MODES (default "0 1 2 3 4"),
# PARITIES (default "even odd"), FRAMES (default "Tisserand": the co-rotating step; "lab" the old one), SETTLE (the
# settling time, default that of the prm file), OUT (default work/linearized.csv); each run computes all MODES ×
# PARITIES.
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/spectrum
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/$here/work}
refinements=${REFINEMENTS:-3}; taus=${TAUS:-0.02}; res=${RES:-1}; frames=${FRAMES:-Tisserand}
modes=${MODES:-"0 1 2 3 4"}; parities=${PARITIES:-"even odd"}
if [ "${1:-}" = "--quick" ]; then refinements=2; modes=2; parities=even; shift; set -- oblate; fi
shapes=${*:-"oblate prolate"}
mkdir -p "$work"
queue=$(for shape in $shapes; do for r in $refinements; do for tau in $taus; do for re in $res; do for frame in $frames; do
  name=stability_${shape}_r${r}_tau${tau}_Re${re}_${frame}
  {
    echo "include $PWD/prm/stability_$shape.prm"
    echo "subsection geometry"; echo "  set refinement = $r"; echo "end"
    echo "subsection flow"; echo "  set Re = $re"; echo "end"
    echo "subsection time stepping"; echo "  set time step = $tau"; echo "  set frame = $frame"; echo "end"
    echo "subsection stability"; echo "  set wavenumbers = $(echo $modes | sed 's/ /, /g')"
    echo "  set parities = $(echo $parities | sed 's/ /, /g')"
    # the settling time of the prm, in steps of the new τ
    settle=${SETTLE:-$(sed -n 's/^ *set settling time = *//p' "prm/stability_$shape.prm")}
    [ -n "$settle" ] && echo "  set settling time = $settle"
    echo "end"
    echo "subsection output"; echo "  set output directory = $work/$name"; echo "  set overwrite = true"; echo "end"
  } > "$work/$name.prm"
  echo "$name"
done; done; done; done; done)
run_one() { "$exe" "$work/$1.prm" > "$work/$1.log" 2>&1; echo "$1 exit $?"; }
export -f run_one; export exe work
echo "$queue" | xargs -P "${JOBS:-1}" -I{} bash -c 'run_one {}'
out=${OUT:-$work/linearized.csv}
# shellcheck disable=SC2086
bash $here/collect_spectra.sh "$work" "$out" shape,refinement,tau,Re,frame \
  's/^stability_\([a-z]*\)_r\([0-9]*\)_tau\([0-9.e-]*\)_Re\([0-9.]*\)_\([A-Za-z]*\)$/\1,\2,\3,\4,\5/' $queue
