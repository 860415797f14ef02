#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Convergence of the rotating axisymmetric equilibrium solver in the number N of Chebyshev
# collocation intervals, the reproduction of the reference table, and the predicted equilibria of the seed runs.
#
# Usage, from the repository root:  benchmarks/equilibrium/run.sh [--quick]
# Needs the built library: $BUILD_DIR (default: build) must hold libfluid_surface_library.so. The small driver
# convergence.cc is compiled against it in $BUILD_DIR/benchmark_equilibrium (Release, -j1). Set
# EQUILIBRIUM_DRIVER=/path/to/convergence to use an already compiled driver instead.
# Writes benchmarks/equilibrium/results.csv, convergence.png and summary.md; --quick writes them to
# benchmarks/equilibrium/quick/ instead (not committed). BUILD_LOCK=FILE: the driver's compile runs under flock FILE.
set -euo pipefail

here=benchmarks/equilibrium
if [ ! -f "$here/convergence.cc" ]; then
  echo "run.sh: run this script from the repository root" >&2
  exit 1
fi
quick=""
for arg in "$@"; do
  case "$arg" in
    --quick) quick=--quick ;;
    *) echo "usage: $here/run.sh [--quick]" >&2; exit 1 ;;
  esac
done

out=$here; [ -n "$quick" ] && out=$here/quick
mkdir -p "$out"
lock=(); [ -n "${BUILD_LOCK:-}" ] && lock=(flock "$BUILD_LOCK")
driver="${EQUILIBRIUM_DRIVER:-}"
if [ -z "$driver" ]; then
  build_dir="$(cd "${BUILD_DIR:-build}" 2>/dev/null && pwd)" || {
    echo "run.sh: no build directory '${BUILD_DIR:-build}'; build the project first" >&2; exit 1; }
  if [ ! -f "$build_dir/libfluid_surface_library.so" ]; then
    echo "run.sh: $build_dir/libfluid_surface_library.so not found; build the project first" >&2
    exit 1
  fi
  work="$build_dir/benchmark_equilibrium"
  mkdir -p "$work"
  cat > "$work/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.13.4)
find_package(deal.II 9.4 REQUIRED HINTS /usr/share/cmake/deal.II)
deal_ii_initialize_cached_variables()
project(equilibrium_benchmark CXX)
add_executable(convergence $PWD/$here/convergence.cc)
target_include_directories(convergence PRIVATE $PWD/include)
target_link_libraries(convergence $build_dir/libfluid_surface_library.so)
deal_ii_setup_target(convergence)
CMAKE
  "${lock[@]}" cmake -S "$work" -B "$work/build" -DCMAKE_BUILD_TYPE=Release > /dev/null
  "${lock[@]}" cmake --build "$work/build" -j1 > /dev/null
  driver="$work/build/convergence"
fi

"$driver" $quick "$out/results.csv" | tee "$out/summary.md"

/usr/bin/python3 - "$out/results.csv" "$out/convergence.png" <<'PYTHON'
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
shapes = []
for row in rows:
    if row["shape"] not in shapes:
        shapes.append(row["shape"])
fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
for shape in shapes:
    data = [r for r in rows if r["shape"] == shape]
    N = [int(r["N"]) for r in data]
    eF = [max(float(r["error_bending_energy"]), 1e-16) for r in data]
    eI = [max(float(r["error_inertia_zz"]), 1e-16) for r in data]
    t = [float(r["wall_time_s"]) for r in data]
    line, = left.semilogy(N, eF, "o-", label=shape + r": $\frac{1}{2}\int H^2$")
    left.semilogy(N, eI, "s--", color=line.get_color(), label=shape + r": $I_{zz}$")
    right.loglog(t, eF, "o-", color=line.get_color(), label=shape)
left.set_xlabel("N (Chebyshev collocation intervals on the half curve)")
left.set_ylabel("relative error vs N = 128")
left.set_title("spectral convergence")
left.grid(True, which="both", alpha=0.3)
left.legend(fontsize=7)
right.set_xlabel("wall time of solve() [s]")
right.set_ylabel(r"relative error of $\frac{1}{2}\int H^2$")
right.set_title("error against run time")
right.grid(True, which="both", alpha=0.3)
right.legend(fontsize=7)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
print("wrote", sys.argv[1], "and", sys.argv[2])
PYTHON
