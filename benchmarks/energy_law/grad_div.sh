#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/energy_law/grad_div.sh: the grad-div term γ_gd(div_P u − s, div_P v) (`flow/grad-div stabilization`)
# against the two plateaus of the grid and against the relaxation's accuracy (issue 48).
#   plateaus: plateaus.sh's body at rest (v = 0.65, L₀ = 0, oblate start, t ≤ 8) and fast spin (v = 0.95, L₀ = 40,
#             oblate start, t ≤ 6), the map's step with `energy budget`, for each γ_gd;
#   accuracy: prm/prolate.prm to t = 4 (its relaxation; τ_max 0.025 there) at REFINEMENT for each γ_gd, against the
#             same file at REFERENCE_REFINEMENT with γ_gd = 0 and with the largest γ_gd.
#   benchmarks/energy_law/grad_div.sh         from the repository root, after building; about an hour on one core
# Then: /usr/bin/python3 benchmarks/energy_law/grad_div.py WORK benchmarks/energy_law/grad_div.csv benchmarks/energy_law/grad_div.png
# Environment: EXE (default build/fluid_surface), WORK (default benchmarks/energy_law/work/grad_div, not committed),
# GAMMAS (default "0 1 10 100"), REFINEMENT (3), REFERENCE_REFINEMENT (4), ACCURACY_END (4), JOBS (1).
set -eu
cd "$(dirname "$0")/../.."
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/benchmarks/energy_law/work/grad_div}
gammas=${GAMMAS:-"0 1 10 100"}
refinement=${REFINEMENT:-3}
reference=${REFERENCE_REFINEMENT:-4}
end=${ACCURACY_END:-4}
mkdir -p "$work"

# plateau V L0 END GAMMA: the oblate start of (V, L0) to t = END with γ_gd = GAMMA (plateaus.sh's case)
plateau() {
  local v=$1 l0=$2 t_end=$3 gamma=$4 name=v$1_L$2_oblate_g$4
  [ -f "$work/$name/summary" ] && return
  WORK=$work/prms_g$gamma EXE=/bin/true VS=$v L0S=$l0 END=$t_end ENERGY_LAW=count REFINEMENT=$refinement \
    GRAD_DIV=$gamma bash benchmarks/end_states/run.sh > /dev/null
  sed -e "s|set output directory = .*|set output directory = $work/$name|" -e "s|set rate tolerance = .*|set rate tolerance = 0|" \
    -e "s|set report wall time = false|set report wall time = true|" \
    "$work/prms_g$gamma/v${v}_L${l0}_oblate.prm" > "$work/$name.prm"
  printf 'subsection time stepping\n  set energy budget = true\nend\n' >> "$work/$name.prm"
  "$exe" "$work/$name.prm" > "$work/$name.log" 2>&1 || echo "$name: exit $?"
}

# accuracy LEVEL GAMMA: prm/prolate.prm at refinement LEVEL to t = ACCURACY_END with γ_gd = GAMMA
accuracy() {
  local level=$1 gamma=$2 name=prolate_r$1_g$2
  [ -f "$work/$name/summary" ] && return
  {
    echo "include $PWD/prm/prolate.prm"
    echo "subsection geometry"; echo "  set refinement = $level"; echo "end"
    echo "subsection flow"; echo "  set grad-div stabilization = $gamma"; echo "end"
    echo "subsection time stepping"; echo "  set end time = $end"; echo "end"
    echo "subsection output"; echo "  set output directory = $work/$name"; echo "  set write vtu = false"
    echo "  set screen interval = 1000"; echo "  set overwrite = true"; echo "end"
  } > "$work/$name.prm"
  "$exe" "$work/$name.prm" > "$work/$name.log" 2>&1 || echo "$name: exit $?"
}
export -f plateau accuracy; export exe work refinement end

largest=$(echo "$gammas" | tr ' ' '\n' | sort -g | tail -n 1)
{
  for g in $gammas; do
    echo "plateau 0.65 0 8 $g"; echo "plateau 0.95 40 6 $g"; echo "accuracy $refinement $g"
  done
  echo "accuracy $reference 0"; echo "accuracy $reference $largest"
} | xargs -P "${JOBS:-1}" -I{} bash -c '{}'
