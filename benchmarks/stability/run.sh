#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Stability stress tests of scene full. Run from the repository root after building:
#   benchmarks/stability/run.sh [--quick] [PART ...]     PART = fixed | perturbed | elongated (default: all)
# fixed:     the rotating prolate (prm/prolate.prm) with a fixed τ (adaptive = false: a step whose energy rise
#            exceeds the tolerance stops the run) to t = 1, refinements FIXED_REFINEMENTS (default "2 3 4"),
#            τ = 0.1 … 0.0125.
# perturbed: the rotating oblate (prm/oblate.prm), refinement PERTURBED_REFINEMENT (3), adaptive τ, towards t = 50
#            with seeded shape or velocity noise (PERTURBED_CASES, default "shape:0.01 shape:0.05 velocity:0.1
#            velocity:0.5"); each run is cut after LIMIT s of wall time (default 600).
# elongated: a 1:5 spheroid [0.4, 0.4, 2] (refinements ELONGATED_REFINEMENTS, default "3 4") released from rest and
#            spun at ω0 = 2, adaptive τ, to t = 5.
# Each case writes a row to benchmarks/stability/cases/<name>.csv and keeps its statistics; results.csv and
# stability.png are rebuilt from all cases. --quick: one short case per part; its cases/, results.csv and stability.png
# go to benchmarks/stability/quick/ (not committed).
set -u
here=benchmarks/stability
exe=${FLUID_SURFACE:-./build/fluid_surface}
limit=${LIMIT:-600}
quick=0; out=$here; [ "${1:-}" = "--quick" ] && { quick=1; out=$here/quick; shift; }
parts="${*:-fixed perturbed elongated}"
work=$(mktemp -d)
mkdir -p $out/cases

# run NAME PRM-BODY: runs one case (base file and overrides) with the wall-time limit, records a row.
run() {
  local name=$1 base=$2 body=$3
  { echo "include $PWD/$base"; echo "$body"; cat <<PRM
subsection output
  set output directory = $work/$name
  set write vtu = false
  set screen interval = 100000
end
PRM
  } > $work/$name.prm
  local start=$(date +%s.%N)
  timeout $limit $exe $work/$name.prm > $work/$name.log 2>&1; local status=$?
  local stop=$(date +%s.%N)
  /usr/bin/python3 - "$work/$name" "$name" "$status" "$(echo "$stop - $start" | bc)" > $out/cases/$name.csv <<'PY'
import sys
d, name, status, wall = sys.argv[1:]
names, rows = [], []
for line in open(d + "/statistics"):
    if line.startswith("# "): names.append(line.split(": ", 1)[1].strip())
    elif line.strip(): rows.append([float(x) for x in line.split()])
col = {n: [r[i] for r in rows] for i, n in enumerate(names)}
F = col["total energy"]
rises = sum(1 for a, b in zip(F, F[1:]) if b > a)
taus = col["tau"][1:] or [0]
log = open(d + ".log").read().splitlines()
err = [l for l in log if "error:" in l]
outcome = "completed" if status == "0" else ("wall-time limit" if status == "124" else (err[-1].split("error: ", 1)[1] if err else f"exit {status}"))
summary = {}
try:
    for l in open(d + "/summary"):
        k, _, v = l.partition(": "); summary[k] = v.strip()
except OSError: pass
print(",".join([name, status, f"{col['time'][-1]:.6g}", str(len(rows) - 1), f"{max(taus):.3g}", f"{min(taus):.3g}",
                str(rises), f"{F[0]:.8g}", f"{F[-1]:.8g}", f"{min(col['mesh quality']):.3g}",
                f"{max(col['symmetry deviation']):.3g}", wall, '"' + outcome.replace('"', "'") + '"']))
PY
  cp $work/$name/statistics $out/cases/$name.statistics 2>/dev/null
}

for part in $parts; do
  case $part in
  fixed)
    refs=${FIXED_REFINEMENTS:-"2 3 4"}; taus="0.1 0.05 0.025 0.0125"; end=1
    [ $quick = 1 ] && { refs="2"; taus="0.05"; end=0.2; }
    for r in $refs; do for t in $taus; do
      run fixed_r${r}_tau$t prm/prolate.prm "subsection geometry
  set refinement = $r
end
subsection time stepping
  set adaptive = false
  set time step = $t
  set maximum time step = $t
  set end time = $end
end"
    done; done ;;
  perturbed)
    cases=${PERTURBED_CASES:-"shape:0.01 shape:0.05 velocity:0.1 velocity:0.5"}; end=50; pr=${PERTURBED_REFINEMENT:-3}
    [ $quick = 1 ] && { cases="shape:0.01"; end=0.2; }
    for c in $cases; do
      kind=${c%%:*}; a=${c##*:}
      run perturbed_r${pr}_${kind}_$a prm/oblate.prm "subsection geometry
  set refinement = $pr
end
subsection initial state
  set $kind perturbation = $a
end
subsection time stepping
  set end time = $end
end
subsection diagnostics
  set angular velocity window = 2, 3
end"
    done ;;
  elongated)
    refs=${ELONGATED_REFINEMENTS:-"3 4"}; end=5; [ $quick = 1 ] && { refs="2"; end=0.1; }
    for r in $refs; do for w in 0 2; do
      run elongated_r${r}_omega$w prm/prolate.prm "subsection geometry
  set semi-axes = 0.4, 0.4, 2
  set refinement = $r
end
subsection initial state
  set angular velocity = $w
end
subsection time stepping
  set end time = $end
end"
    done; done ;;
  esac
done
{ echo "case,exit,t_reached,steps,tau_max_used,tau_min_used,energy_rises,F0,F_end,min_mesh_quality,max_symmetry_deviation,wall_time_s,outcome"; cat $out/cases/*.csv; } > $out/results.csv
/usr/bin/python3 $here/plot.py $out
