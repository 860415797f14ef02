#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/end_states: where runs end (issue 23, item 4). A = 4π, reduced volume v ∈ {0.65, 0.75, 0.85, 0.95},
# L₀ ∈ {0, 5, 10, 20, 40}, each from a prolate and from an oblate spheroid spinning about its symmetry axis
# (ω₀ = L₀/I_zz, the shipped seed and step of prm/prolate_long.prm), carried to its steady state (subsection steady state,
# t ≤ 100) at refinement 3 with the long runs' mesh law. Each run checkpoints (resume = auto, `steps per run` if
# STEPS_PER_RUN is set): a queue cut off by the end of a session continues where it stopped when run again.
#   benchmarks/end_states/run.sh [--quick]      from the repository root, after building
#     (--quick: v = 0.75, L₀ = 10, both starts, refinement 2, t ≤ 5, in WORK/quick: results.csv there)
# Environment: WORK (default benchmarks/end_states/work, not committed), EXE, JOBS (runs at once, default 1),
# REFINEMENT (default 3), VS, L0S (override the grids), END (default 100: the last time a run may reach), STEPS_PER_RUN,
# TAU_MAX (default 0.1), MESH_LAW (membrane or conformal, default membrane), ENERGY_LAW (time stepping/energy law:
# retry, the default, count or stop; doc/scheme.md, "The discrete energy law"; set and empty: the entry is not written,
# for a build older than the entry), GRAD_DIV (flow/grad-div stabilization γ_gd; unset: the entry is not written).
# Then: /usr/bin/python3 benchmarks/end_states/table.py WORK benchmarks/end_states/results.csv
#       /usr/bin/python3 benchmarks/end_states/plot.py benchmarks/end_states/results.csv benchmarks/end_states/phase_diagram.png
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/end_states
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/$here/work}
vs=${VS:-"0.65 0.75 0.85 0.95"}; l0s=${L0S:-"0 5 10 20 40"}; refinement=${REFINEMENT:-3}; end=${END:-100}
if [ "${1:-}" = "--quick" ]; then vs=0.75; l0s=10; refinement=2; end=5; work=$work/quick; fi
mkdir -p "$work"
# The step of the shipped files (BDF2, co-rotating, one geometry correction, backward Euler after a rejection) at
# τ_max = 0.1 everywhere. With the lab-frame backward-Euler step the rows v = 0.95, L₀ = 20 needed τ_max = 0.025:
# at 0.1 both starts kept a non-rigid oscillation to t = 250 and F + ∫D rose by about 0.075 per unit time.
tau_max() { echo "${TAU_MAX:-0.1}"; }
# The mesh law: `membrane` (the default law `reference` with its membrane energy at full weight from the start,
# anchored at the mesh of the moment once the body rotates rigidly: `anchor non-rigid energy`) or
# `conformal` (BGN's conformal rows with the pull below quality 0.2 and the anchor at t = 4, the map's law before
# issue 48: its nodes creep along the conformal family and the creep raises F without work, benchmarks/energy_law).
mesh_law=${MESH_LAW:-membrane}
queue=$(for v in $vs; do for L0 in $l0s; do for start in prolate oblate; do
  name=v${v}_L${L0}_${start}
  read -r a c omega inertia <<< "$(/usr/bin/python3 $here/spheroid.py "$v" "$start" "$L0")"
  {
    echo "# $name: A = 4π, v = $v, L₀ = $L0 (I_zz = $inertia), from a $start spheroid"
    echo "subsection model"; echo "  set scene = full"; echo "end"
    echo "subsection geometry"; echo "  set shape = ellipsoid"; echo "  set semi-axes = $a, $a, $c"
    echo "  set refinement = $refinement"; echo "  set position degree = 2"; echo "end"
    echo "subsection flow"; echo "  set Re = 1"; echo "  set conserve momenta = true"
    [ -n "${GRAD_DIV:-}" ] && echo "  set grad-div stabilization = $GRAD_DIV"; echo "end"
    echo "subsection bending"; echo "  set Be = 1"; echo "end"
    echo "subsection initial state"; echo "  set angular velocity = $omega"; echo "  set rotation axis = 0, 0, 1"
    echo "  set shape perturbation = 1e-6"; echo "  set random seed = 1"; echo "end"
    echo "subsection time stepping"; echo "  set end time = $end"; echo "  set time step = 0.01"
    echo "  set maximum time step = $(tau_max "$v" "$L0")"; echo "  set scheme = BDF2"; echo "  set frame = Tisserand"
    echo "  set backward Euler steps after rejection = 20"
    [ -n "${ENERGY_LAW-retry}" ] && echo "  set energy law = ${ENERGY_LAW-retry}"; echo "end"
    echo "subsection geometry iteration"; echo "  set maximum iterations = 1"; echo "  set tolerance = 0"
    echo "  set apply = always"; echo "end"
    echo "subsection mesh redistribution"
    if [ "$mesh_law" = conformal ]; then
      echo "  set tangential law = conformal"; echo "  set pull onset quality = 0.2"; echo "  set full pull quality = 0.2"
      echo "  set anchor time = 4"
    else
      echo "  set anchor non-rigid energy = 1e-6"
    fi
    echo "end"
    echo "subsection output"; echo "  set output directory = $work/$name"; echo "  set output interval = 5"
    echo "  set screen interval = 1000"; echo "  set report wall time = false"; echo "  set overwrite = true"; echo "end"
    echo "subsection steady state"; echo "  set rate tolerance = 1e-6"; echo "  set window = 1"; echo "end"
    echo "subsection checkpoint"; echo "  set resume = auto"; echo "  set wall time between checkpoints = 300"
    [ -n "${STEPS_PER_RUN:-}" ] && echo "  set steps per run = $STEPS_PER_RUN"
    echo "end"
  } > "$work/$name.prm"
  echo "$name"
done; done; done)
# A run that reached its steady state, or finished at the end time, is not run again; one that ended unsteady at an
# earlier end time continues from its final checkpoint (END larger than before).
run_one() {
  local s=$work/$1/summary t_last
  if grep -q "steady state: reached" "$s" 2>/dev/null; then echo "$1 steady before"; return; fi
  t_last=$(tail -n 1 "$work/$1/statistics" 2>/dev/null | awk '{print $2}')
  if grep -q "^status: completed" "$s" 2>/dev/null && awk -v t="${t_last:-0}" -v e="$end" 'BEGIN { exit !(t >= e - 1e-9) }'; then
    echo "$1 done before"; return
  fi
  "$exe" "$work/$1.prm" >> "$work/$1.log" 2>&1; echo "$1 exit $?"
}
export -f run_one; export exe work end
echo "$queue" | xargs -P "${JOBS:-1}" -I{} bash -c 'run_one {}'
/usr/bin/python3 $here/table.py "$work" "$work/results.csv"
