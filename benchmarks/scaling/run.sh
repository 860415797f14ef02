#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/scaling: the cost model of a step of prm/prolate.prm against its size (issue 50, item 2). The shipped
# prolate, t ∈ [0, END] (0.5: 29 steps at every refinement; refinement 6: END6, default 0.1), refinements 2–6, on
# 1 and 2 MPI ranks; per run the program's `timing` file (TimerOutput sections: assembly, factorization, linear
# solve, curvature and energy, diagnostics, output), the linear iterations from `statistics` and the peak resident
# memory of every rank (/usr/bin/time). Run from the repository root, alone on the machine:
#   benchmarks/scaling/run.sh [--quick]
#   (--quick: refinements 2 and 3, one rank, END = 0.1; results in benchmarks/scaling/quick/, not committed)
# Environment: EXE (default ./build/fluid_surface), REFINEMENTS, NPS (default "1 2"), REPEATS (runs per case at
# refinements ≤ 4, default 3; one run above), END, END6, WORK (default: a temporary folder).
# Then: /usr/bin/python3 benchmarks/scaling/analyze.py benchmarks/scaling/results.csv benchmarks/scaling
set -uo pipefail
cd "$(dirname "$0")/../.."
exe=${EXE:-$PWD/build/fluid_surface}
out=benchmarks/scaling
refinements=${REFINEMENTS:-"2 3 4 5 6"}; nps=${NPS:-"1 2"}; repeats=${REPEATS:-3}; end=${END:-0.5}; end6=${END6:-0.1}
if [[ "${1:-}" == "--quick" ]]; then refinements="2 3"; nps=1; repeats=1; end=0.1; out=$out/quick; fi
mkdir -p "$out"
work=${WORK:-$(mktemp -d)}
mkdir -p "$work"
results=$out/results.csv
header="refinement,unknowns,ranks,run,end_time,steps,rejected,factorizations,wall,assembly,assembly_calls,factorization,factorization_calls,linear_solve,solve_calls,curvature_energy,diagnostics,output,linear_iterations,peak_memory_rank_max_mb,peak_memory_total_mb"
[ -f "$results" ] || echo "$header" > "$results"
for r in $refinements; do
  n=$repeats; [ "$r" -gt 4 ] && n=1
  t_end=$end; [ "$r" -ge 6 ] && t_end=$end6
  for np in $nps; do
    for run in $(seq 1 "$n"); do
      if grep -q "^$r,[0-9]*,$np,$run,$t_end," "$results"; then echo "r$r np$np run $run: in $results"; continue; fi
      d=$work/r${r}_np${np}_${run}
      rm -rf "$d"
      cat > "$work/r${r}.prm" <<PRM
include $PWD/prm/prolate.prm
subsection geometry
  set refinement = $r
end
subsection time stepping
  set end time = $t_end
end
subsection output
  set output directory = $d
  set screen interval = 1000
end
PRM
      echo "r$r np$np run $run: $(date +%T)"
      if ! mpirun --allow-run-as-root --oversubscribe -np "$np" /usr/bin/time -f "peak memory kB %M" \
           "$exe" "$work/r${r}.prm" > "$d.log" 2>&1; then
        echo "r$r np$np run $run failed: $(tail -n 3 "$d.log")"; continue
      fi
      /usr/bin/python3 - "$d" "$r" "$np" "$run" "$t_end" >> "$results" <<'PY'
import re, sys
d, r, np, run, t_end = sys.argv[1:]
text = open(d + "/timing").read()
head = re.search(r"# run: ([\d.e+-]+) s, (\d+) accepted steps, (\d+) rejected, (\d+) LU", text)
wall, steps, rejected, lu = float(head[1]), int(head[2]), int(head[3]), int(head[4])
sections = {}
for line in text.splitlines():
    if line.startswith('"'):
        name, calls, seconds, share, per_step = line.rsplit(",", 4)
        sections[name.strip('"')] = (float(seconds), int(calls))
def seconds(*names):
    return sum(sections.get(k, (0, 0))[0] for k in names)
def calls(name):
    return sections.get(name, (0, 0))[1]
log = open(d + ".log").read()
unknowns = re.search(r"(\d+) unknowns", log)[1]
memory = [int(m) / 1024 for m in re.findall(r"peak memory kB (\d+)", log)]
columns = None
iterations = 0
for line in open(d + "/statistics"):
    if line.startswith("#"):
        m = re.match(r"# (\d+): linear iterations", line)
        if m: columns = int(m[1]) - 1
    elif columns is not None and line.strip():
        iterations += float(line.split()[columns])
print(",".join([r, unknowns, np, run, t_end, str(steps), str(rejected), str(lu), f"{wall:.4g}",
                f"{seconds('assembly'):.4g}", str(calls("assembly")),
                f"{seconds('factorization', 'symbolic factorization'):.4g}", str(calls("factorization")),
                f"{seconds('linear solve'):.4g}", str(calls("linear solve")),
                f"{seconds('curvature and energy'):.4g}", f"{seconds('diagnostics'):.4g}", f"{seconds('output'):.4g}",
                f"{iterations:.0f}", f"{max(memory):.0f}", f"{sum(memory):.0f}"]))
PY
      tail -n 1 "$results"
    done
  done
done
/usr/bin/python3 benchmarks/scaling/analyze.py "$results" "$out"
