#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Cost of one step of scene full: wall time per step and its split (assembly, factorization, linear solve,
# curvature and energy, diagnostics, output) with the MUMPS factorization refactorized every step
# (`linear solver/reuse factorization = false`, the previous behaviour) and reused as the GMRES preconditioner.
# The rotating prolate of prm/prolate.prm, t ∈ [0, T] (T = 0.2; --quick: 0.05), refinements 2 and 3, 3 runs each.
# Run from the repository root: FLUID_SURFACE=./build/fluid_surface benchmarks/step_cost/run.sh [--quick]
# --quick writes results.csv and step_cost.png to benchmarks/step_cost/quick/ (not committed).
set -uo pipefail
exe=${FLUID_SURFACE:-./build/fluid_surface}
out=benchmarks/step_cost
work=$(mktemp -d)
end=0.2; repeats=3; refinements="2 3"
if [[ "${1:-}" == "--quick" ]]; then end=0.05; repeats=1; refinements="2"; out=$out/quick; mkdir -p $out; fi
echo "refinement,unknowns,reuse,run,steps,rejected,factorizations,wall_per_step,assembly,factorization,linear_solve,curvature_energy,diagnostics,output" > $work/results.csv
for run in $(seq 1 $repeats); do
  for r in $refinements; do
    for reuse in false true; do
      d=$work/r${r}_${reuse}_${run}
      cat > $work/p.prm <<PRM
include $PWD/prm/prolate.prm
subsection geometry
  set refinement = $r
end
subsection linear solver
  set reuse factorization = $reuse
end
subsection time stepping
  set end time = $end
end
subsection output
  set output directory = $d
  set write vtu = false
  set screen interval = 1000
end
PRM
      $exe $work/p.prm > $d.log 2>&1 || echo "exit status $? (kept: the timing file is written before the exit)" >> $d.log
      /usr/bin/python3 - "$d" "$r" "$reuse" "$run" >> $work/results.csv <<'PY'
import sys, re
d, r, reuse, run = sys.argv[1:]
text = open(d + "/timing").read()
head = re.search(r"# run: ([\d.e+-]+) s, (\d+) accepted steps, (\d+) rejected, (\d+) LU", text)
total, steps, rejected, lu = float(head[1]), int(head[2]), int(head[3]), int(head[4])
sec = {}
for line in text.splitlines():
    if line.startswith('"'):
        name, calls, wall, share, per = line.rsplit(",", 4)
        sec[name.strip('"')] = float(wall) / steps
unknowns = re.search(r"(\d+) unknowns", open(d + ".log").read())[1]
keys = ["assembly", "factorization", "linear solve", "curvature and energy", "diagnostics", "output"]
print(",".join([r, unknowns, reuse, run, str(steps), str(rejected), str(lu), f"{total/steps:.4g}"] +
               [f"{sec.get(k, 0):.4g}" for k in keys]))
PY
    done
  done
done
cp $work/results.csv $out/results.csv
/usr/bin/python3 benchmarks/step_cost/plot.py $out
