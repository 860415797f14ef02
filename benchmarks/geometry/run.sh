#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Work-precision benchmark of the surface geometry. Run from the repository root:
#   benchmarks/geometry/run.sh [--quick]
# Builds the driver in benchmarks/geometry/build (Release, JOBS=${JOBS:-1} compile jobs), runs it, writes
# benchmarks/geometry/results.csv and benchmarks/geometry/geometry.png. --quick runs only the coarser levels
# (k = 1: refinement 1..4, k = 2: 1..3, k = 3: 1..2) and overwrites the same two files.
set -euo pipefail

here=benchmarks/geometry
if [[ ! -f $here/geometry_convergence.cc ]]; then
  echo "run.sh: run me from the repository root (benchmarks/geometry/run.sh)" >&2
  exit 2
fi

args=()
for a in "$@"; do
  case $a in
    --quick) args+=(--quick) ;;
    *) echo "usage: $here/run.sh [--quick]" >&2; exit 2 ;;
  esac
done

start=$(date +%s.%N)
mkdir -p $here/build
cmake -S $here -B $here/build -DCMAKE_BUILD_TYPE=Release > $here/build/cmake.log
cmake --build $here/build -j "${JOBS:-1}" > $here/build/make.log 2>&1 || { tail -40 $here/build/make.log >&2; exit 1; }

# CSV on stdout, progress (with signed errors) on stderr, kept in build/run.log.
$here/build/geometry_convergence "${args[@]}" > $here/results.csv.tmp 2> >(tee $here/build/run.log >&2)
mv $here/results.csv.tmp $here/results.csv

/usr/bin/python3 $here/plot.py $here/results.csv $here/geometry.png
end=$(date +%s.%N)
printf 'wrote %s/results.csv and %s/geometry.png; run.sh took %.1f s\n' $here $here "$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')"
