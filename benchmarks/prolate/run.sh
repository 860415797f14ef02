#!/usr/bin/env bash
# The seed's rotating prolate to t = 10 at several refinements: wall time, ⟨ω⟩ over [5, 10], F(10), drifts.
# Run from the repository root after building (./build/fluid_surface). --quick: refinement 2 only, to t = 2.
# Writes benchmarks/prolate/results.csv and benchmarks/prolate/prolate.png.
set -u
here=benchmarks/prolate
exe=${FLUID_SURFACE:-./build/fluid_surface}
refinements="2 3"; end=10
[ "${1:-}" = "--quick" ] && { refinements="2"; end=2; }
work=$(mktemp -d)
echo "refinement,unknowns,end_time,completed,t_reached,mean_omega,final_energy,max_area_drift,max_volume_drift,max_angular_momentum_drift,steps,rejected,energy_rises_accepted,wall_time_s" > $here/results.csv
for r in $refinements; do
  sed -e "s/refinement = 3/refinement = $r/; s/end time = 25/end time = $end/; s#results/prolate#$work/r$r#; s/output interval = 0.25/output interval = 1/" prm/prolate.prm > $work/r$r.prm
  start=$(date +%s.%N)
  $exe $work/r$r.prm > $work/r$r.log 2>&1; status=$?
  stop=$(date +%s.%N)
  unknowns=$(grep -o '[0-9]* unknowns' $work/r$r.log | cut -d' ' -f1)
  t_reached=$(awk '!/^#/{t=$2} END{print t}' $work/r$r/statistics)
  get() { grep "^$1:" $work/r$r/summary 2>/dev/null | sed "s/^$1: //; s/ .*//" ; }
  completed=$([ $status -eq 0 ] && echo 1 || echo 0)
  echo "$r,$unknowns,$end,$completed,$t_reached,$(get 'mean angular velocity'),$(get 'final total energy'),$(get 'max area drift'),$(get 'max volume drift'),$(get 'max angular momentum drift'),$(get steps),$(get 'rejected steps'),$(get 'energy rises accepted'),$(echo "$stop - $start" | bc)" >> $here/results.csv
  cp $work/r$r/statistics $here/statistics_r$r 2>/dev/null
done
/usr/bin/python3 - <<'PY'
import csv, matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
def read(f):
    names, rows = [], []
    for line in open(f):
        if line.startswith("# "): names.append(line.split(": ", 1)[1].strip())
        elif line.strip():
            try: rows.append([float(x) for x in line.split()])
            except ValueError: pass
    return {n: [r[i] for r in rows] for i, n in enumerate(names)}
import glob
fig, ax = plt.subplots(1, 2, figsize=(11, 4))
for f in sorted(glob.glob("benchmarks/prolate/statistics_r*")):
    d = read(f); lab = "refinement " + f[-1]
    ax[0].plot(d["time"], d["angular velocity"], label=lab)
    ax[1].plot(d["wall time"], d["total energy"], label=lab)
ax[0].axhline(3.2455522821, ls=":", c="k", label="equilibrium at L0 (ω = 3.2456)")
ax[0].set_xlabel("t"); ax[0].set_ylabel("ω(t)"); ax[0].legend()
ax[1].set_xlabel("wall time [s]"); ax[1].set_ylabel("total energy F"); ax[1].legend()
fig.tight_layout(); fig.savefig("benchmarks/prolate/prolate.png", dpi=110)
PY
cat $here/results.csv
