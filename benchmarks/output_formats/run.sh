#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Output formats: wall time of one output step (OutputWriter::write: build_patches with curved sub-cells, then the
# file and the time series) and its bytes on disk, VTU (.vtu + its share of solution.pvd) against HDF5 (.h5 + its
# share of solution.xdmf), on the ellipsoid [0.61, 0.61, 2.02] (Q2 geometry, 2×2 sub-cells per cell, 14 field
# components as in scene full), refinements 4 and 5, 1 and 2 MPI ranks; WRITES (default 7) writes per case,
# the median reported. --quick: refinement 3 only, 3 writes; its results.csv and plot go to
# benchmarks/output_formats/quick/ (not committed).
# Usage (from the repository root): benchmarks/output_formats/run.sh [--quick]
#   BUILD_DIR (default: build) is a Release build directory of the project; the library is built there if missing,
#   the driver in $BUILD_DIR/benchmark-output-formats. Writes benchmarks/output_formats/results.csv.
#   BUILD_LOCK=FILE: the compiles run under flock FILE.
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
"${lock[@]}" cmake -S "$here" -B "$build/benchmark-output-formats" -DCMAKE_BUILD_TYPE=Release \
      -DFLUID_SURFACE_BUILD_DIR="$build" > /dev/null
"${lock[@]}" make -C "$build/benchmark-output-formats" -j1 > /dev/null
driver="$build/benchmark-output-formats/output_formats_driver"

writes=${WRITES:-7}; refinements="4 5"; out=$here
if [[ "${1:-}" == "--quick" ]]; then writes=3; refinements="3"; out=$here/quick; mkdir -p "$out"; fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "refinement,ranks,format,cells,writes,median_s,min_s,max_s,file_bytes,series_bytes_per_step,bytes_per_step" \
  > "$work/results.csv"
for r in $refinements; do
  for np in 1 2; do
    for format in vtu hdf5; do
      d="$work/r${r}_np${np}_${format}"
      mpirun --allow-run-as-root -np $np "$driver" $writes geometry/shape=ellipsoid \
        "geometry/semi-axes=0.61, 0.61, 2.02" geometry/refinement=$r output/format=$format \
        "output/output directory=$d" > "$d.log"
      /usr/bin/python3 - "$d.log" "$r" "$np" "$format" "$writes" >> "$work/results.csv" <<'PY'
import re, statistics, sys
log, r, np, fmt, writes = sys.argv[1:]
text = open(log).read()
times = [float(t) for t in re.findall(r"write \d+: ([\d.e+-]+) s", text)]
files = {name: int(size) for name, size in re.findall(r"file (\S+): (\d+) bytes", text)}
steps = [size for name, size in files.items() if name.startswith("solution-")]
series = files["solution.pvd" if fmt == "vtu" else "solution.xdmf"] / len(steps)
cells = re.search(r"cells: (\d+)", text)[1]
print(f"{r},{np},{fmt},{cells},{len(times)},{statistics.median(times):.4f},{min(times):.4f},{max(times):.4f},"
      f"{max(steps)},{series:.0f},{max(steps) + series:.0f}")
PY
      tail -1 "$work/results.csv"
    done
  done
done
cp "$work/results.csv" "$out/results.csv"
/usr/bin/python3 "$here/plot.py" "$out"
