#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/stability_chart: L_c(v) of the spinning oblate and prolate from --equilibrium's second variation.
#   benchmarks/stability_chart/run.sh [--quick]     from the repository root, after building (about 10 minutes on
#   one core; --quick: v = 0.6, 0.65, a coarse L grid, in WORK, a minute)
# Environment: EXE (default build/fluid_surface), WORK (for --quick; default benchmarks/stability_chart/work/quick, not committed).
set -eu
cd "$(dirname "$0")/../.."
exe=${EXE:-$PWD/build/fluid_surface}
if [ "${1:-}" = "--quick" ]; then
  out=${WORK:-benchmarks/stability_chart/work/quick}
  /usr/bin/python3 benchmarks/stability_chart/chart.py "$exe" "$out" --quick
else
  out=benchmarks/stability_chart
  /usr/bin/python3 benchmarks/stability_chart/chart.py "$exe" "$out"
fi
/usr/bin/python3 benchmarks/stability_chart/plot.py "$out"
