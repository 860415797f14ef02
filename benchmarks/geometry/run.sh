#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Work-precision benchmark of the surface geometry. Run from the repository root:
#   benchmarks/geometry/run.sh [--quick]
# Builds the driver in benchmarks/geometry/build (Release, JOBS=${JOBS:-1} compile jobs), runs it, writes
# benchmarks/geometry/results.csv and benchmarks/geometry/geometry.png. --quick runs only the coarser levels
# (k = 1: refinement 1..4, k = 2: 1..3, k = 3: 1..2) and writes the two files to benchmarks/geometry/quick/ (not
# committed). BUILD_LOCK=FILE: the driver's compile runs under flock FILE.
set -euo pipefail

here=benchmarks/geometry
if [[ ! -f $here/geometry_convergence.cc ]]; then
  echo "run.sh: run me from the repository root (benchmarks/geometry/run.sh)" >&2
  exit 2
fi

args=()
out=$here
for a in "$@"; do
  case $a in
    --quick) args+=(--quick); out=$here/quick ;;
    *) echo "usage: $here/run.sh [--quick]" >&2; exit 2 ;;
  esac
done

start=$(date +%s.%N)
mkdir -p $here/build $out
lock=(); [ -n "${BUILD_LOCK:-}" ] && lock=(flock "$BUILD_LOCK")
"${lock[@]}" cmake -S $here -B $here/build -DCMAKE_BUILD_TYPE=Release > $here/build/cmake.log
"${lock[@]}" cmake --build $here/build -j "${JOBS:-1}" > $here/build/make.log 2>&1 || { tail -40 $here/build/make.log >&2; exit 1; }

# CSV on stdout, progress (with signed errors) on stderr, kept in build/run.log.
$here/build/geometry_convergence "${args[@]}" > $out/results.csv.tmp 2> >(tee $here/build/run.log >&2)
mv $out/results.csv.tmp $out/results.csv

/usr/bin/python3 $here/plot.py $out/results.csv $out/geometry.png
end=$(date +%s.%N)
printf 'wrote %s/results.csv and %s/geometry.png; run.sh took %.1f s\n' $out $out "$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')"
