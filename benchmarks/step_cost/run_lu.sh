#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# The LU's symbolic analysis kept across factorizations (AmesosFactorization): cost of a step before and after.
# The oblate of prm/oblate.prm for t ∈ [0, T] (T = 0.06: 3–4 steps, τ from 0.01 growing to 0.05; --quick: 0.02,
# refinement 3 only), refinements 3 and 4, `reuse factorization` as shipped, 3 repetitions, the two executables run
# in turn (before, after, before, after, ...) so that a drift of the shared machine's load hits both alike.
# Per run: the whole-process wall time and the split of the program's `timing` file, into results_lu.csv.
# Symbolic/LU is the analysis time spread over the run's factorizations (before: inside factorization/LU).
# Run from the repository root:
#   BEFORE=/path/to/old/fluid_surface AFTER=./build/fluid_surface benchmarks/step_cost/run_lu.sh [--quick]
# One run alone (appends one row to CSV; NP > 1: mpirun -np NP; environment: END_TIME, REUSE = false for a
# factorization at every step): benchmarks/step_cost/run_lu.sh --one EXE REFINEMENT LABEL CSV [NP]
# The README table from a CSV: benchmarks/step_cost/run_lu.sh --table [CSV]
set -uo pipefail
out=benchmarks/step_cost
end=${END_TIME:-0.06}

one_run() {
  local exe=$1 r=$2 label=$3 csv=$4 np=${5:-1}
  local work; work=$(mktemp -d)
  cat > $work/p.prm <<PRM
include $PWD/prm/oblate.prm
subsection geometry
  set refinement = $r
end
subsection time stepping
  set end time = $end
end
subsection linear solver
  set reuse factorization = ${REUSE:-true}
end
subsection output
  set output directory = $work/out
  set write vtu = false
  set screen interval = 1000
end
PRM
  local start; start=$(date +%s.%N)
  if [[ $np == 1 ]]; then $exe $work/p.prm > $work/log 2>&1
  else mpirun --allow-run-as-root -np $np $exe $work/p.prm > $work/log 2>&1; fi
  local wall; wall=$(awk -v a=$start -v b=$(date +%s.%N) 'BEGIN{print b-a}')
  /usr/bin/python3 - "$work" "$r" "$label" "$np" "$wall" >> $csv <<'PY'
import sys, re
d, r, label, np, wall = sys.argv[1:]
text = open(d + "/out/timing").read()
head = re.search(r"# run: ([\d.e+-]+) s, (\d+) accepted steps, (\d+) rejected, (\d+) LU", text)
total, steps, rejected, lu = float(head[1]), int(head[2]), int(head[3]), int(head[4])
sec, calls = {}, {}
for line in text.splitlines():
    if line.startswith('"'):
        name, n, w, share, per = line.rsplit(",", 4)
        sec[name.strip('"')] = float(w); calls[name.strip('"')] = int(n)
unknowns = re.search(r"(\d+) unknowns", open(d + "/log").read())[1]
num = sec.get("factorization", 0) - sec.get("symbolic factorization", 0)
print(",".join([r, unknowns, label, np, str(steps), str(rejected), str(lu), str(calls.get("symbolic factorization", 0)),
                f"{float(wall):.4g}", f"{total:.4g}", f"{total/steps:.4g}",
                f"{sec.get('assembly', 0)/steps:.4g}", f"{sec.get('factorization', 0)/max(lu, 1):.4g}",
                f"{sec.get('symbolic factorization', 0)/max(lu, 1):.4g}", f"{num/max(lu, 1):.4g}",
                f"{sec.get('linear solve', 0)/steps:.4g}"]))
PY
  rm -rf $work
}

header="refinement,unknowns,code,ranks,steps,rejected,factorizations,analyses,process_wall,run_wall,wall_per_step,assembly_per_step,factorization_per_lu,symbolic_per_lu,numeric_per_lu,linear_solve_per_step"
table() {  # medians per (refinement, code, ranks) of a results_lu.csv
  /usr/bin/python3 - "$1" <<'PY'
import sys, csv, statistics
rows = list(csv.DictReader(open(sys.argv[1])))
keys = sorted({(int(r["refinement"]), r["code"], r["ranks"]) for r in rows})
print("| refinement | unknowns | code | ranks | runs | s/step | assembly/step | LU/step | factorization/LU | symbolic/LU | numeric/LU | linear solve/step |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for ref, code, ranks in keys:
    sel = [r for r in rows if (int(r["refinement"]), r["code"], r["ranks"]) == (ref, code, ranks)]
    m = lambda k: statistics.median(float(r[k]) for r in sel)
    lu = statistics.median(int(r["factorizations"]) / int(r["steps"]) for r in sel)
    print(f"| {ref} | {sel[0]['unknowns']} | {code} | {ranks} | {len(sel)} | {m('wall_per_step'):.3g} | {m('assembly_per_step'):.3g} | "
          f"{lu:.2f} | {m('factorization_per_lu'):.3g} | {m('symbolic_per_lu'):.3g} | {m('numeric_per_lu'):.3g} | {m('linear_solve_per_step'):.3g} |")
PY
}

if [[ "${1:-}" == "--table" ]]; then table "${2:-$out/results_lu.csv}"; exit 0; fi
if [[ "${1:-}" == "--one" ]]; then
  [[ -s $5 ]] || echo "$header" > $5
  one_run "$2" "$3" "$4" "$5" "${6:-1}"; exit 0
fi
repeats=3; refinements="3 4"
if [[ "${1:-}" == "--quick" ]]; then end=0.02; repeats=1; refinements="3"; fi
csv=$(mktemp); echo "$header" > $csv
for run in $(seq 1 $repeats); do
  for r in $refinements; do
    one_run "$BEFORE" $r before $csv
    one_run "$AFTER" $r after $csv
  done
done
cp $csv $out/results_lu.csv
table $out/results_lu.csv
