#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/scaling/paired.sh: this build against an earlier one, paired (farm-bench: A B A B …), with the README's
# command (2 ranks): prm/prolate.prm to t = 0.5 at refinement 4 (3 pairs), to t = 0.2 at refinement 5 (2 pairs) and to
# t = 0.1 at refinement 6 (2 pairs, no warm-up run; about 4 GB per rank).
#   BEFORE_EXE=… benchmarks/scaling/paired.sh NAME     # from the repository root, after building; about 50 minutes
# NAME: the change measured, the folder benchmarks/scaling/NAME: single_column (the single-column products,
# BEFORE_EXE a build of 48ee798), in_place (the in-place insertion of commit f1b1b2a, not kept: ./build a build of
# f1b1b2a, BEFORE_EXE a build of 37fdd10).
# CASES: the windows, "REFINEMENT END_TIME PAIRS WARMUP ..." (default "4 0.5 3 1 5 0.2 2 1 6 0.1 2 0"). Alone on the
# machine. Writes benchmarks/scaling/NAME/rN_farm_bench.txt and rN_{after,before}.timing (the last pair's split);
# then /usr/bin/python3 benchmarks/scaling/paired.py NAME draws NAME.csv and NAME.png.
set -eu
cd "$(dirname "$0")/../.."
name=${1:?"usage: BEFORE_EXE=… paired.sh NAME"}
before=${BEFORE_EXE:?"BEFORE_EXE: a fluid_surface built from the commit before the change"}
work=${WORK:-$(mktemp -d)}
out=benchmarks/scaling/$name
mkdir -p "$out"
set -- ${CASES:-4 0.5 3 1 5 0.2 2 1 6 0.1 2 0}
while [ $# -ge 4 ]; do
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
  shift 4
done
