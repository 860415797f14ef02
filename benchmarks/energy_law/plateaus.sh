#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/energy_law/plateaus.sh: the two plateaus of the grid (F flat while the flow dissipates; README.md,
# "The energy budget by term") split by term with `time stepping/energy budget` (budget.py): the body at rest
# (v = 0.65, L₀ = 0, oblate start; the parasitic current, t ∈ (5.5, 8]) and the fast spin (v = 0.95, L₀ = 40, oblate
# start; the multipliers' work, t ∈ (4, 6]), and the body at rest without the conservation projection; refinement 3,
# the map's step (benchmarks/end_states/run.sh's prms), `energy law = count` and no steady-state stop.
#   benchmarks/energy_law/plateaus.sh        from the repository root, after building; a few minutes
# Environment: EXE (default build/fluid_surface), WORK (default benchmarks/energy_law/work/plateaus, not committed),
# REFINEMENT (default 3).
set -eu
cd "$(dirname "$0")/../.."
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/benchmarks/energy_law/work/plateaus}
mkdir -p "$work"
case_run() {  # V L0 END [SUFFIX TEXT]: the oblate start of (V, L0) to t = END [with the prm TEXT appended]
  local v=$1 l0=$2 end=$3 name=v$1_L$2_oblate${4:-} text=${5:-}
  WORK=$work/prms EXE=/bin/true VS=$v L0S=$l0 END=$end ENERGY_LAW=count REFINEMENT=${REFINEMENT:-3} \
    bash benchmarks/end_states/run.sh > /dev/null
  sed -e "s|set output directory = .*|set output directory = $work/$name|" -e "s|set rate tolerance = .*|set rate tolerance = 0|" \
    "$work/prms/v${v}_L${l0}_oblate.prm" > "$work/$name.prm"
  printf 'subsection time stepping\n  set energy budget = true\nend\n%b' "$text" >> "$work/$name.prm"
  rm -rf "${work:?}/$name"
  "$exe" "$work/$name.prm" > "$work/$name.log" 2>&1 || echo "$name: exit $?"
}
case_run 0.65 0 8 &
case_run 0.95 40 6
wait
case_run 0.65 0 8 _no_projection 'subsection conservation projection\n  set enabled = false\nend\n'
for window in "v0.65_L0_oblate 5.5 8" "v0.65_L0_oblate_no_projection 5.5 8" "v0.95_L40_oblate 4 6"; do
  read -r name t0 t1 <<< "$window"
  echo "$name, t in ($t0, $t1]:"
  /usr/bin/python3 benchmarks/energy_law/budget.py "$work/$name" "$t0" "$t1"
done
