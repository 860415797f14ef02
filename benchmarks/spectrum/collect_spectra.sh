#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/spectrum/collect_spectra.sh: the spectrum.csv of several scene-stability runs in one table, each row
# prefixed with the run's settings read from its name. Used by spectrum/linearized.sh and stability_chart/routes.sh.
#   collect_spectra.sh WORK OUT COLUMNS SED NAME...
# COLUMNS: the settings' column names ("shape,refinement"); SED: a sed expression that turns a run's NAME into
# its comma-separated settings; each run's table is WORK/NAME/spectrum.csv.
set -u
work=$1 out=$2 columns=$3 expression=$4
shift 4
head -n 1 "$work/$1/spectrum.csv" 2>/dev/null | sed "s/^/$columns,/" > "$out"
for name in "$@"; do
  [ -f "$work/$name/spectrum.csv" ] || { echo "$name: no spectrum.csv"; continue; }
  settings=$(echo "$name" | sed "$expression")
  tail -n +2 "$work/$name/spectrum.csv" | sed "s/^/$settings,/" >> "$out"
done
cat "$out"
