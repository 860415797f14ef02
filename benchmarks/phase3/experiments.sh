#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/phase3/experiments.sh: the shipped experiments through their symmetry breaking: prm/oblate.prm and
# prm/prolate.prm (refinement 4, to the oblate's steady end state and to t = 25) and prm/oblate_long.prm, prm/prolate_long.prm (refinement 3, to
# their steady state). Copies each run's statistics and summary to experiments/<name>.* and writes experiments.csv.
#   benchmarks/phase3/experiments.sh [NAMES]        from the repository root, after building
#   benchmarks/phase3/experiments.sh --table        only rebuild experiments.csv from experiments/
# NAMES (default "oblate prolate oblate_long prolate_long") selects prm files; EXE the binary; RANKS (default 1) the
# number of MPI processes (mpirun -np RANKS); the runs write to results/<name> as the prm files say (resume = auto
# in the long ones continues a stopped run).
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/phase3
exe=${EXE:-./build/fluid_surface}
ranks=${RANKS:-1}
[ "$ranks" -gt 1 ] && exe="mpirun --allow-run-as-root -np $ranks $exe"
mkdir -p $here/experiments
names=${1:-oblate prolate oblate_long prolate_long}; [ "$names" = --table ] && names=
for name in $names; do
  r=$(awk '/set refinement/ {print $4}' prm/$name.prm)
  $exe prm/$name.prm > $here/experiments/${name}_r$r.log 2>&1; echo "prm/$name.prm: exit $?"
  cp results/$name/statistics $here/experiments/${name}_r$r.statistics
  cp results/$name/summary $here/experiments/${name}_r$r.summary
  rm $here/experiments/${name}_r$r.log
done
{ echo "case,exit,t reached,steps,rejected,t_sym_1e-4,t_sym_1e-2,median tau,min tau,max rise/(tau F),min mesh quality,max |dA/A|,max |dV/V|,max |dL/L|,F end,bending end,omega end,rigid fraction end,tilt end,max e,wall s,outcome"
  for s in $here/experiments/*.summary; do
    case=$(basename $s .summary)
    status=$(awk -F': ' 'NR == 1 {print $2}' $s)
    /usr/bin/python3 $here/summarize.py ${s%.summary}.statistics "prm/${case%_r[0-9]}.prm (refinement ${case##*_r})" \
      $([ "$status" = completed ] && echo 0 || echo 1) "$(awk -F': ' '/^wall time/ {print $2}' $s)" \
      "$(awk -F': ' '/^steady state: reached/ {print "steady state"} /^steady state: plateau/ {print "plateau (not an end state)"}' $s)${status#completed}"
  done; } > $here/experiments.csv
