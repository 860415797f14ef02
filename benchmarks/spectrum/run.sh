#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/spectrum: both routes of README.md in one command, linearized.sh (scene stability, Arnoldi on the
# time-T map) and then seeded_modes.sh (seeded nonlinear runs, fit_modes.py), then the figures from their tables.
#   benchmarks/spectrum/run.sh [--quick] [shape ...]     from the repository root, after building
#     (shapes: oblate prolate; --quick: linearized.sh --quick, the oblate's m = 2 even at refinement 2, and
#     seeded_modes.sh --quick, m = 2 even to t = 2 with its baseline, for both shapes)
# Environment: as linearized.sh and seeded_modes.sh (WORK, EXE, JOBS, ...). WORK defaults to benchmarks/spectrum/work,
# with --quick to benchmarks/spectrum/work/quick (neither committed). Writes WORK/linearized.csv,
# WORK/seeded_modes.csv, WORK/spectrum.png and WORK/seeded_modes.png; the committed tables and figures of this folder
# (README.md) are not touched: they collect runs of several settings (REFINEMENTS, TAUS, FRAMES, ...).
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/spectrum
quick=""; [ "${1:-}" = "--quick" ] && { quick=--quick; shift; }
shapes=${*:-"oblate prolate"}
work=${WORK:-$PWD/$here/work$([ -n "$quick" ] && echo /quick)}
export WORK=$work
mkdir -p "$work"
status=0
# linearized.sh --quick runs the oblate only, whatever the shapes
$here/linearized.sh $quick $shapes || status=1
$here/seeded_modes.sh $quick $shapes || status=1
/usr/bin/python3 $here/plot_linearized.py "$work/linearized.csv" "$work/seeded_modes.csv" "$work/spectrum.png" \
  > "$work/spectrum_tables.md" || status=1
/usr/bin/python3 $here/plot.py "$work" "$work/seeded_modes.png" $shapes || status=1
echo "wrote $work/linearized.csv, seeded_modes.csv, spectrum.png, seeded_modes.png"
exit $status
