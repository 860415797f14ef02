#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Surface Stokes / Navier–Stokes on a fixed surface: convergence, dynamics and work–precision.
# Usage (from the repository root): benchmarks/surface_stokes/run.sh [--quick] [--solvers] [--multiplier]
#   --solvers re-runs only the solver comparisons and keeps the accuracy rows of results.csv;
#   --multiplier re-runs only the Lagrange-multiplier tangentiality cases and keeps the other rows.
#   BUILD_DIR (default: build) is a Release build directory of the project; the library is built
#   there if missing, the driver in $BUILD_DIR/benchmark-surface-stokes.
# Writes benchmarks/surface_stokes/results.csv and work_precision.png; --quick writes them to
# benchmarks/surface_stokes/quick/ (not committed). BUILD_LOCK=FILE: the compiles run under flock FILE.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(cd "${BUILD_DIR:-$root/build}" 2>/dev/null && pwd || true)"
if [ -z "$build" ]; then
  build="$root/build"; mkdir -p "$build"
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
fi
lock=(); [ -n "${BUILD_LOCK:-}" ] && lock=(flock "$BUILD_LOCK")
[ -f "$build/libfluid_surface_library.so" ] || "${lock[@]}" make -C "$build" -j1 fluid_surface_library
"${lock[@]}" cmake -S "$here" -B "$build/benchmark-surface-stokes" -DCMAKE_BUILD_TYPE=Release \
      -DFLUID_SURFACE_BUILD_DIR="$build" > /dev/null
"${lock[@]}" make -C "$build/benchmark-surface-stokes" -j1 > /dev/null
out=$here
for a in "$@"; do [ "$a" = --quick ] && out=$here/quick; done
mkdir -p "$out"
/usr/bin/python3 "$here/run_cases.py" "$build/benchmark-surface-stokes/surface_stokes_driver" "$out" "$@"
