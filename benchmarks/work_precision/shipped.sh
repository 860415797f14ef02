#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/work_precision/shipped.sh (issue 33, item 3): are the shipped experiments converged in τ? prm/<shape>.prm
# as shipped (its scheme, frame, geometry iteration and mesh law) at one refinement, for each τ_max in TAUS, against
# the run at the last (smallest) τ_max in BDF2 (the reference; τ_max/8 of the shipped one). Each run's summary is
# copied to shipped/<shape>_r<r>_tau<τ_max>.summary; shipped_<shape>_r<r>.csv holds t_sym_1e-4, t_sym_1e-2, ⟨ω⟩ and
# the final F with their differences from the reference (times: relative; ⟨ω⟩, F: relative).
#   benchmarks/work_precision/shipped.sh [--quick]       from the repository root, after building
#     --quick: prm/oblate.prm at refinement 2 to t = 2, τ_max = 0.1 and 0.025
# Environment: SHAPE (oblate | prolate, default oblate), REFINEMENT (default 3), TAUS (default "0.1 0.05 0.025
# 0.0125"), EXTRA (prm lines appended to every run, e.g. another scheme), TAG (a name for that variant), WORK, EXE.
# A run is resumed from its checkpoint (`checkpoint/resume = auto`), so a script cut off goes on where it stopped;
# a run whose committed summary (shipped/<run>.summary) says completed is not rerun unless FORCE=1.
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/work_precision
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/$here/work}/shipped
shape=${SHAPE:-oblate}; r=${REFINEMENT:-3}; taus=${TAUS:-"0.1 0.05 0.025 0.0125"}; tag=${TAG:+_$TAG}
end=""; out=$here/shipped
if [ "${1:-}" = "--quick" ]; then r=2; taus="0.1 0.025"; end=2; out=$work/quick; fi
mkdir -p "$work" "$out"
reference=$(echo $taus | awk '{print $NF}')
names=""
for tau in $taus; do
  name=${shape}_r${r}${tag}_tau${tau}
  {
    echo "include $PWD/prm/$shape.prm"
    echo "subsection geometry"; echo "  set refinement = $r"; echo "end"
    echo "subsection time stepping"; echo "  set maximum time step = $tau"
    awk -v t=$tau 'BEGIN { if (t < 0.01) print "  set time step = " t }'
    [ -n "$end" ] && echo "  set end time = $end"
    echo "end"
    echo "subsection checkpoint"; echo "  set resume = auto"; echo "  set steps per run = ${STEPS_PER_RUN:-0}"; echo "end"
    echo "subsection output"; echo "  set output directory = $work/$name"; echo "  set write vtu = false"
    echo "  set screen interval = 100000"; echo "end"
    printf '%b\n' "${EXTRA:-}"
  } > "$work/$name.prm"
  if grep -q '^status: completed' "$work/$name/summary" 2>/dev/null; then echo "$name: completed before"
  elif [ -z "${FORCE:-}" ] && grep -q '^status: completed' "$out/$name.summary" 2>/dev/null; then
    echo "$name: its committed summary is kept (FORCE=1 reruns it)"
  else
    "$exe" "$work/$name.prm" > "$work/$name.log" 2>&1; echo "$name: exit $?"
  fi
  [ -f "$work/$name/summary" ] && cp "$work/$name/summary" "$out/$name.summary"
  names="$names $name"
done
/usr/bin/python3 $here/compare.py "$out" ${shape}_r${r}${tag}_tau$reference $names > "$out/../shipped_${shape}_r${r}${tag}.csv"
cat "$out/../shipped_${shape}_r${r}${tag}.csv"
