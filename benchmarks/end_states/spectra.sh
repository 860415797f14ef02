#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/end_states: the class of the end states that are not bodies of revolution (issue 49). For each named run
# of run.sh that ended steady or stopped at a plateau (a rigid rotation whose F the refinement-3 step holds: its
# class is that of the discrete model's state, not of an end state of the model), scene stability with `base state = checkpoint` on its last checkpoint: the mesh law
# anchored at the end state, one time unit of settling, the map over T = 0.3 with BDF2 steps of τ = 0.02, Arnoldi
# from all modes m ≤ 4 at once, the eight leading eigenvalues (doc/stability.md, "The end state of a run"). The
# geometry, flow and mesh law are the run's own (its prm). table.py reads WORK/NAME_stability/spectrum.csv.
#   WORK=… [EXE=…] [JOBS=1] benchmarks/end_states/spectra.sh NAME…      (NAME as v0.95_L10_prolate)
set -u
cd "$(dirname "$0")/../.."
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:?WORK: the work directory of run.sh}
[ $# -gt 0 ] || { echo "spectra.sh: name the runs (e.g. v0.95_L10_prolate)" >&2; exit 2; }
for name in "$@"; do
  prm=$work/$name.prm
  grep -qE "steady state: (reached|plateau)" "$work/$name/summary" 2>/dev/null || { echo "$name: neither steady nor at a plateau, skipped" >&2; continue; }
  # The run's prm without its scene, time control, steady state, checkpoint and output, and the stability entries.
  awk '/^subsection (steady state|checkpoint|output)$/ { skip = 1 } !skip { print } skip && /^end$/ { skip = 0 }' "$prm" |
    sed -e 's/set scene = full/set scene = stability/' -e 's/set time step = .*/set time step = 0.02/' \
        -e '/set end time/d' -e '/set maximum time step/d' -e '/set backward Euler steps/d' -e '/set energy law/d' \
    > "$work/${name}_stability.prm"
  {
    echo "subsection stability"; echo "  set base state = checkpoint"; echo "  set checkpoint directory = $work/$name"
    echo "  set anchor the end state = true"; echo "  set settling time = 1"; echo "  set map time = 0.3"
    echo "  set maximum Krylov dimension = 30"; echo "  set eigenvalues per wavenumber = 8"; echo "end"
    echo "subsection output"; echo "  set output directory = $work/${name}_stability"; echo "  set overwrite = true"
    echo "end"
  } >> "$work/${name}_stability.prm"
  echo "$name"
done | xargs -P "${JOBS:-1}" -I{} bash -c '"$0" "$1/{}_stability.prm" > "$1/{}_stability.log" 2>&1; echo "{} exit $?"' "$exe" "$work"
