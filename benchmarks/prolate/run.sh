#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# The seed's rotating prolate to t = 10 at several (h, τ): wall time, ⟨ω⟩ over [5, 10], F(10), drifts, step cost.
# Run from the repository root after building (./build/fluid_surface):
#   [REPEAT=n] benchmarks/prolate/run.sh [--quick] [CASE ...]   CASE = refinement:τ_max (default: 2:0.05 3:0.05 3:0.025 4:0.05)
# REPEAT=n runs each case n times and records the median wall time (all of them in cases/<case>.walls).
# --quick: refinement 2 only, to t = 2. Each case writes benchmarks/prolate/cases/r<ref>_tau<τ_max>.{csv,statistics,timing}
# (cases may run in parallel, one invocation each); results.csv and prolate.png are then rebuilt from all cases.
# --quick writes cases/, results.csv and prolate.png to benchmarks/prolate/quick/ (not committed).
set -u
here=benchmarks/prolate
exe=${FLUID_SURFACE:-./build/fluid_surface}
end=10; cases="2:0.05 3:0.05 3:0.025 4:0.05"
out=$here
[ "${1:-}" = "--quick" ] && { cases="2:0.05"; end=2; out=$here/quick; shift; }
[ $# -gt 0 ] && cases="$*"
work=$(mktemp -d)
mkdir -p $out/cases
header="refinement,unknowns,tau_max,end_time,completed,t_reached,mean_omega,final_energy,max_area_drift,max_volume_drift,max_angular_momentum_drift,steps,rejected,energy_rises_accepted,factorizations,wall_time_s"
for c in $cases; do
  r=${c%%:*}; tau=${c##*:}; name=r${r}_tau${tau}
  sed -e "s/refinement = [0-9]*/refinement = $r/; s/end time = 25/end time = $end/; s#results/prolate#$work/$name#; s/output interval = 0.25/output interval = 1/; s/maximum time step = [0-9.]*/maximum time step = $tau/; s/time step = 0.01/time step = $(/usr/bin/python3 -c "print(min(0.01, $tau))")/" prm/prolate.prm > $work/$name.prm
  # REPEAT runs of the case (the wall time is their median; the runs are deterministic on one rank).
  walls=""
  for k in $(seq ${REPEAT:-1}); do
    rm -rf $work/$name
    start=$(date +%s.%N)
    $exe $work/$name.prm > $work/$name.log 2>&1; status=$?
    stop=$(date +%s.%N)
    walls="$walls $(echo "$stop - $start" | bc)"
  done
  wall=$(echo $walls | tr ' ' '\n' | sort -g | awk '{a[NR]=$1} END{print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}')
  unknowns=$(grep -o '[0-9]* unknowns' $work/$name.log | cut -d' ' -f1)
  t_reached=$(awk '!/^#/{t=$2} END{print t}' $work/$name/statistics)
  get() { grep "^$1:" $work/$name/summary 2>/dev/null | sed "s/^$1: //; s/ .*//" ; }
  completed=$([ $status -eq 0 ] && echo 1 || echo 0)
  echo "$r,$unknowns,$tau,$end,$completed,$t_reached,$(get 'mean angular velocity'),$(get 'final total energy'),$(get 'max area drift'),$(get 'max volume drift'),$(get 'max angular momentum drift'),$(get steps),$(get 'rejected steps'),$(get 'energy rises accepted'),$(get 'LU factorizations'),$wall" > $out/cases/$name.csv
  echo "$walls" > $out/cases/$name.walls
  cp $work/$name/statistics $out/cases/$name.statistics 2>/dev/null
  cp $work/$name/timing $out/cases/$name.timing 2>/dev/null
  tail -n 3 $work/$name.log > $out/cases/$name.tail
done
{ echo "$header"; cat $out/cases/*.csv; } > $out/results.csv
/usr/bin/python3 $here/plot.py $out || exit 1
cat $out/results.csv
