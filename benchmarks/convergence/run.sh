#!/usr/bin/env bash
# benchmarks/convergence: convergence in h of the full model's phase-2 figures (issue 22, item 3; first part).
# prm/prolate.prm to t = 10 (⟨ω⟩[5, 10] and min E(L²)) and prm/oblate.prm to t = 3 (⟨ω⟩[2, 3]) at refinements
# 2, 3, 4, for the mesh laws `experiments` (the prm files' law: conformal rows, the membrane pull below mesh
# quality 0.2), `membrane` (the law reference's membrane energy always, the earlier setting) and `bgn`, against the rotating equilibrium at L₀
# that each run's summary reports (`reference equilibrium angular velocity`). The τ check: refinement 3 again with
# τ_max halved (`_halfdt`).
#   benchmarks/convergence/run.sh [--quick]        from the repository root, after building (--quick: r2, r3)
# Environment: WORK (default benchmarks/convergence/work, not committed), EXE, REFINEMENTS, LAWS, LIMIT (s per run;
# a run that takes longer is stopped and listed as such: the law bgn collapses τ on the oblate at refinement 2).
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/convergence
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/$here/work}
refinements=${REFINEMENTS:-"2 3 4"}
laws=${LAWS:-"experiments membrane bgn"}
limit=${LIMIT:-3600}
out=$here
if [ "${1:-}" = "--quick" ]; then refinements="2 3"; work=$work/quick; out=$work; limit=${LIMIT:-180}; fi
mkdir -p "$work"
runs=""
for law in $laws; do for shape in prolate oblate; do for r in $refinements 3_halfdt; do
  case $r in 3_halfdt) level=3; half=1;; *) level=$r; half=0;; esac
  [ $half = 1 ] && ! echo " $refinements " | grep -q " 3 " && continue
  name=${shape}_${law}_r$r
  end=10; [ $shape = oblate ] && end=3
  tau_max=$(grep -m1 "maximum time step" prm/$shape.prm | awk '{print $NF}')
  [ $half = 1 ] && tau_max=$(awk -v t=$tau_max 'BEGIN { print t / 2 }')
  cat > $work/$name.prm.new <<PRM
include $PWD/prm/$shape.prm
subsection geometry
  set refinement = $level
end
subsection time stepping
  set end time = $end
  set maximum time step = $tau_max
end
subsection mesh redistribution
$(case $law in
  experiments) echo "  set law = reference";;
  membrane) printf '  set law = reference\n  set tangential law = membrane\n  set pull onset quality = 1\n  set full pull quality = 1';;
  *) echo "  set law = $law";;
esac)
end
subsection output
  set output directory = $work/$name
  set overwrite = true
  set write vtu = false
  set screen interval = 100000
end
PRM
  runs="$runs $name"
  if cmp -s $work/$name.prm.new $work/$name.prm && grep -q '^status: completed' $work/$name/summary 2>/dev/null; then
    rm $work/$name.prm.new; echo "$name: kept"; continue
  fi
  mv $work/$name.prm.new $work/$name.prm
  timeout $limit $exe $work/$name.prm > $work/$name.log 2>&1; status=$?
  if [ $status = 124 ]; then echo "$name stopped after $limit s"; else echo "$name exit $status"; fi
done; done; done
/usr/bin/python3 $here/table.py $work $out $runs
