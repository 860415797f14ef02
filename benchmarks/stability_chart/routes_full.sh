#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/stability_chart/routes_full.sh: route (c) of issue 49, item 3. Full runs (scene full, the map's step of
# benchmarks/end_states/run.sh: BDF2, co-rotating, τ_max 0.1, membrane law anchored once the flow is rigid) from the
# spinning equilibrium of the chart's branch and v at L just below and just above the second variation's L_c,
# displaced by one azimuthal mode (default m = 2 even, amplitude 1e-3), carried to their steady state or END. Below
# L_c the mode must decay and the run stay axisymmetric; above it the mode grows and the run ends off the
# axisymmetric branch. Q_m of the mode is in each run's statistics (fit its rate with
# benchmarks/spectrum/fit_modes.py); the end states with benchmarks/end_states/table.py WORK OUT.csv.
#   benchmarks/stability_chart/routes_full.sh [--quick]     from the repository root, after building
#     (--quick: t ≤ 0.3, a minute; refinement 2 is below what these shapes need)
# Environment: EXE, WORK (default benchmarks/stability_chart/work/full, not committed), BRANCH (oblate), V (0.66),
# LS (default "11.8 13.1"), REFINEMENT (3), TAU_MAX (0.1), END (200), AMPLITUDE (1e-3), MODE (2), PARITY (even),
# JOBS (1). Runs resume from their checkpoints when the script is run again.
set -u
cd "$(dirname "$0")/../.."
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/benchmarks/stability_chart/work/full}
branch=${BRANCH:-oblate}; v=${V:-0.66}; ls=${LS:-"11.8 13.1"}; refinement=${REFINEMENT:-3}; end=${END:-200}
if [ "${1:-}" = "--quick" ]; then end=0.3; work=$work/quick; fi
mkdir -p "$work"
queue=$(for L in $ls; do
  name=full_${branch}_v${v}_L${L}_r${refinement}_m${MODE:-2}${PARITY:-even}
  {
    echo "subsection model"; echo "  set scene = full"; echo "end"
    echo "subsection geometry"; echo "  set shape = equilibrium"; echo "  set refinement = $refinement"
    echo "  set position degree = 2"; echo "end"
    echo "subsection equilibrium"; echo "  set area = 12.566370614359172"; echo "  set reduced volume = $v"
    echo "  set branch = $branch"; echo "  set Be = 1"; echo "  set angular momentum = $L"; echo "end"
    echo "subsection flow"; echo "  set Re = 1"; echo "  set conserve momenta = true"; echo "end"
    echo "subsection bending"; echo "  set Be = 1"; echo "end"
    echo "subsection initial state"; echo "  set equilibrium rotation = true"
    echo "  set shape perturbation = ${AMPLITUDE:-1e-3}"; echo "  set perturbation form = azimuthal"
    echo "  set azimuthal wavenumber = ${MODE:-2}"; echo "  set azimuthal parity = ${PARITY:-even}"; echo "end"
    echo "subsection time stepping"; echo "  set end time = $end"; echo "  set time step = 0.01"
    echo "  set maximum time step = ${TAU_MAX:-0.1}"; echo "  set scheme = BDF2"; echo "  set frame = Tisserand"
    echo "  set backward Euler steps after rejection = 20"; echo "  set energy law = retry"; echo "end"
    echo "subsection geometry iteration"; echo "  set maximum iterations = 1"; echo "  set tolerance = 0"
    echo "  set apply = always"; echo "end"
    echo "subsection mesh redistribution"; echo "  set anchor non-rigid energy = 1e-6"; echo "end"
    echo "subsection diagnostics"; echo "  set reference equilibrium = $branch"; echo "  set azimuthal modes = 1, 2, 3, 4"; echo "end"
    echo "subsection output"; echo "  set output directory = $work/$name"; echo "  set output interval = 10"
    echo "  set screen interval = 1000"; echo "  set report wall time = false"; echo "  set overwrite = true"; echo "end"
    echo "subsection steady state"; echo "  set rate tolerance = 1e-6"; echo "  set window = 1"; echo "end"
    echo "subsection checkpoint"; echo "  set resume = auto"; echo "  set wall time between checkpoints = 300"; echo "end"
  } > "$work/$name.prm"
  echo "$name"
done)
run_one() { grep -q "steady state: reached" "$work/$1/summary" 2>/dev/null || "$exe" "$work/$1.prm" >> "$work/$1.log" 2>&1; echo "$1 exit $?"; }
export -f run_one; export exe work
echo "$queue" | xargs -P "${JOBS:-1}" -I{} bash -c 'run_one {}'
