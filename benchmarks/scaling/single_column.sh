#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/scaling/single_column.sh: the program's single-column products (source/linear_algebra/
# single_column_products.cc) against a build without them, paired (farm-bench: A B A B …), with the README's command
# (2 ranks): prm/prolate.prm to t = 0.5 at refinement 4 (3 pairs), to t = 0.2 at refinement 5 (2 pairs) and to t = 0.1
# at refinement 6 (2 pairs, no warm-up run; about 4 GB per rank).
#   BEFORE_EXE=… benchmarks/scaling/single_column.sh      # from the repository root, after building; about 50 minutes
# BEFORE_EXE: a fluid_surface built from commit 48ee798 (the same numerics without the file). Alone on the machine.
# Writes benchmarks/scaling/single_column/rN_farm_bench.txt and rN_{after,before}.timing (the last pair's split);
# then /usr/bin/python3 benchmarks/scaling/single_column.py draws single_column.csv and single_column.png.
set -eu
cd "$(dirname "$0")/../.."
before=${BEFORE_EXE:?"BEFORE_EXE: a fluid_surface built from commit 48ee798"}
work=${WORK:-$(mktemp -d)}
out=benchmarks/scaling/single_column
mkdir -p "$out"
for case in "4 0.5 3 1" "5 0.2 2 1" "6 0.1 2 0"; do
  set -- $case
  for side in a b; do
    cat > "$work/r$1$side.prm" <<PRM
include prm/prolate.prm
subsection geometry
  set refinement = $1
end
subsection time stepping
  set end time = $2
end
subsection output
  set output directory = $work/r$1$side
  set overwrite = true
  set output interval = 1000
end
PRM
  done
  farm-bench -n "$3" --warmup "$4" --timeout 3000 \
    --vs "mpirun --allow-run-as-root -np 2 $before $work/r$1b.prm" -- \
    mpirun --allow-run-as-root -np 2 ./build/fluid_surface "$work/r$1a.prm" |
    sed "s#$work/#WORK/#g; s#$before#BEFORE_EXE#g" > "$out/r$1_farm_bench.txt"
  cp "$work/r$1a/timing" "$out/r$1_after.timing"
  cp "$work/r$1b/timing" "$out/r$1_before.timing"
done
