#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/energy_law: the tumbling start of tests/energy_law_tumbling (a prolate spinning about an axis 17° from
# its symmetry axis, the map's step) with one setting changed, and its energy budget (end_states/energy_budget.py).
#   benchmarks/energy_law/tumbling.sh NAME [ENTRY=VALUE ...]     from the repository root, after building
# e.g.  tumbling.sh r3 refinement=3        tumbling.sh r2_lab frame=lab        tumbling.sh r2_t4 "end time=4"
# ENTRY is the name of an entry of the test's file (the first line `set ENTRY = …` is replaced). The test itself runs
# with `energy law = retry`; the rows of tumbling.csv were run with `energy law = count` unless named `retry`.
# Environment: EXE (default build/fluid_surface), WORK (default benchmarks/energy_law/work/tumbling, not committed).
set -eu
cd "$(dirname "$0")/../.."
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/benchmarks/energy_law/work/tumbling}
name=$1; shift
mkdir -p "$work"
prm=$work/$name.prm
sed "s|set output directory = results|set output directory = $work/$name|" tests/energy_law_tumbling.prm > "$prm"
for setting in "$@"; do
  entry=${setting%%=*}; value=${setting#*=}
  grep -q "set $entry = " "$prm" || { echo "tumbling.sh: no entry '$entry' in tests/energy_law_tumbling.prm" >&2; exit 1; }
  sed -i "0,/set $entry = .*/s||set $entry = $value|" "$prm"
done
"$exe" "$prm" > "$work/$name.log" 2>&1
/usr/bin/python3 benchmarks/end_states/energy_budget.py "$work/$name" | tail -n 1
