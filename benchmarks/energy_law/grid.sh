#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/energy_law/grid.sh: the energy law over the map's grid (issue 48, item 4). Runs benchmarks/end_states/run.sh
# (v ∈ {0.65, 0.75, 0.85, 0.95}, L₀ ∈ {0, 5, 10, 20, 40}, prolate and oblate starts) with one step and writes its table,
# with the law's columns of end_states/table.py (largest rise of B = F + ∫D, steps breaking the per-step law, the largest
# excess over its bound), to benchmarks/energy_law/grid/STEP_rREFINEMENT_tauTAU_MAX_tEND.csv.
#   benchmarks/energy_law/grid.sh after [--quick]    # the map's step of this commit (EXE, default build/fluid_surface;
#                                                    # ENERGY_LAW, default retry: end_states/run.sh)
#   benchmarks/energy_law/grid.sh before [--quick]   # the step of issue 48's report: BEFORE_EXE = a build of f0c166e,
#                                                    # with the map's mesh law of then (MESH_LAW=conformal), counting
# Environment: REFINEMENT (3), TAU_MAX (0.1), END (40), JOBS (1), VS, L0S, GRAD_DIV (flow/grad-div stabilization of
# the step after; the name gets _graddivGRAD_DIV), WORK (default benchmarks/energy_law/work/STEP_rREFINEMENT_tauTAU_MAX_tEND,
# not committed). The runs resume from their checkpoints when the script is run again.
# --quick: end_states/run.sh --quick (v = 0.75, L₀ = 10, refinement 2, t ≤ 5), its table printed, nothing written here.
# Then: /usr/bin/python3 benchmarks/energy_law/grid_plot.py   (grid/*.csv → grid.md, grid.png)
set -eu
cd "$(dirname "$0")/../.."
step=${1:?"usage: grid.sh after|before [--quick]"}
case "$step" in
  after) export EXE=${EXE:-$PWD/build/fluid_surface} MESH_LAW=membrane ;;
  before) export EXE=${BEFORE_EXE:?"BEFORE_EXE: the fluid_surface of a build of commit f0c166e"} MESH_LAW=conformal \
    ENERGY_LAW= ;;
  *) echo "grid.sh: the step is 'after' or 'before', not '$step'" >&2; exit 2 ;;
esac
export REFINEMENT=${REFINEMENT:-3} TAU_MAX=${TAU_MAX:-0.1} END=${END:-40}
name=${step}_r${REFINEMENT}_tau${TAU_MAX}_t${END}
[ "$step" = after ] && [ "${ENERGY_LAW:-retry}" != retry ] && name=${name}_$ENERGY_LAW
[ "$step" = after ] && [ -n "${GRAD_DIV:-}" ] && name=${name}_graddiv$GRAD_DIV
export WORK=${WORK:-$PWD/benchmarks/energy_law/work/$name}
if [ "${2:-}" = "--quick" ]; then
  bash benchmarks/end_states/run.sh --quick
  cat "$WORK/quick/results.csv"
  exit 0
fi
bash benchmarks/end_states/run.sh
mkdir -p benchmarks/energy_law/grid
cp "$WORK/results.csv" "benchmarks/energy_law/grid/$name.csv"
echo "benchmarks/energy_law/grid/$name.csv"
