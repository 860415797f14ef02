#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Parameter fuzzer: every entry of `fluid_surface --print-parameters` with boundary and hostile values derived
# from its pattern, on short coarse runs of each scene and on --equilibrium (see README.md here).
#   benchmarks/fuzz/run.sh [--quick] [--only SUBSTRING] [--timeout SECONDS]     (from the repository root)
# --quick: each entry on its first scene only, with at most two values besides its default (fuzz.py, quick_values; the
# whole set of values took over 30 minutes). Writes benchmarks/fuzz/results.csv and run.log (--quick: quick/results.csv
# and quick/run.log, not committed);
# exit status 1 if a case failed (a solver exit 1 with a dump, a crash, a refusal that does not name the entry).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
binary=${BINARY:-$root/build/fluid_surface}
work=${WORK:-/tmp/fluid_surface_fuzz_$$}
results=$here/results.csv
log=$here/run.log
args=()
for a in "$@"; do
  [[ "$a" == "--quick" ]] && { mkdir -p "$here/quick"; results=$here/quick/results.csv; log=$here/quick/run.log; }
  args+=("$a")
done
mkdir -p "$work"
status=0
/usr/bin/python3 "$here/fuzz.py" --binary "$binary" --source "$root" --work "$work" --results "$results" \
  --timeout 30 "${args[@]}" | tee "$log" || status=$?
rm -rf "$work"
exit $status
