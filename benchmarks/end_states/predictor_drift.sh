#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/end_states/predictor_drift.sh: the map's row v = 0.95, L₀ = 20 from the oblate start (a spinning
# near-sphere) with the geometry's predictor and τ_max varied. Each case writes predictor_drift/<case>.summary and
# .statistics; predictor_drift.csv has the end state's F against the rotating equilibrium of the run's own A, V and L₀
# (`fluid_surface --equilibrium`), the least mesh quality and the steps.
#   benchmarks/end_states/predictor_drift.sh      from the repository root, after building
# Environment: CASES (default "r3:linear:0.1 r3:linear:0.025 r3:old surface:0.1 r3:old surface:0.025
# r3:quadratic normal:0.1 r4:linear:0.1"; refinement:predictor:τ_max), WORK (default benchmarks/end_states/work_drift), EXE.
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/end_states
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/$here/work_drift}
out=$here/predictor_drift
mkdir -p "$work" "$out"
cases=${CASES:-"r3:linear:0.1 r3:linear:0.025 r3:old surface:0.1 r3:old surface:0.025 r3:quadratic normal:0.1 r4:linear:0.1"}
echo "case,refinement,predictor,tau_max,status,steps,rejected,end time,F,F equilibrium,F rel. difference,min mesh quality"
IFS=$'\n'
for c in $(echo "$cases" | sed 's/ r\([0-9]\)/\nr\1/g'); do
  IFS=: read -r r predictor tau <<< "$c"
  name=${r}_$(echo "$predictor" | tr ' ' _)_tau$tau
  # The map's own prm for this row, written by run.sh without running it.
  EXE=/bin/true WORK=$work/$name.map VS=0.95 L0S=20 REFINEMENT=${r#r} $here/run.sh > /dev/null 2>&1
  sed -e "s#set output directory = .*#set output directory = $work/$name#" \
      -e "s#set maximum time step = .*#set maximum time step = $tau#" "$work/$name.map/v0.95_L20_oblate.prm" > "$work/$name.prm"
  printf 'subsection geometry iteration\n  set predictor = %s\nend\n' "$predictor" >> "$work/$name.prm"
  grep -q "^status: completed" "$work/$name/summary" 2>/dev/null || "$exe" "$work/$name.prm" > "$work/$name.log" 2>&1
  cp "$work/$name/summary" "$out/$name.summary"; cp "$work/$name/statistics" "$out/$name.statistics"
  # A, V (hence v) and L₀ of the discrete start.
  IFS=" " read -r area v L0 <<< "$(awk '!/^#/ { print $8, $10, $14; exit }' "$work/$name/statistics")"
  printf 'subsection equilibrium\n  set area = %s\n  set reduced volume = %s\n  set branch = oblate\n  set Be = 1\n  set angular momentum = %s\n  set output file = %s\nend\n' \
    "$area" "$v" "$L0" "$work/$name.curve.csv" > "$work/$name.equilibrium.prm"
  Feq=$("$exe" --equilibrium "$work/$name.equilibrium.prm" | awk -F': ' '/^total energy/ { print $2 }')
  awk -v name="$name" -v r="${r#r}" -v p="$predictor" -v tau="$tau" -v feq="$Feq" -F': ' '
    /^status/ { status = $2 } /^steps:/ { steps = $2 } /^rejected steps/ { rejected = $2 }
    /^final total energy/ { F = $2 }
    END { printf "%s,%s,%s,%s,%s,%s,%s,", name, r, p, tau, status, steps, rejected }' "$out/$name.summary"
  awk -v feq="$Feq" '!/^#/ { t = $2; F = $6; if (q == "" || $31 < q) q = $31 }
    END { printf "%.4f,%.8f,%.8f,%+.1e,%.3f\n", t, F, feq, F / feq - 1, q }' "$out/$name.statistics"
done
