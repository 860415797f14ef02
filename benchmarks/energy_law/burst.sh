#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/energy_law/burst.sh: the burst of the map's (0.75, 20) prolate start (refinement 3, τ_max 0.1, the map's
# step) near t = 5, where F + ∫D rose by about 1 in 0.1 time units: the run to t = 4.7 once, then from its checkpoint
# to t = 5.3 with `energy law = count` (and its energy budget, budget.py) and one change each (README.md, "The mesh law's tangential speed"), and the
# budget of (4.7, 5.3] (burst.py).
#   benchmarks/energy_law/burst.sh        from the repository root, after building; about 10 minutes alone
#   benchmarks/energy_law/burst.sh rate   the burst's growth rate against T_r and τ_max, and without the convection
#                                         (README.md, "What sets the burst's rate")
# Environment: EXE (default build/fluid_surface), WORK (default benchmarks/energy_law/work/burst, not committed).
set -eu
cd "$(dirname "$0")/../.."
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/benchmarks/energy_law/work/burst}
mkdir -p "$work"
WORK=$work/map EXE=/bin/true VS=0.75 L0S=20 bash benchmarks/end_states/run.sh > /dev/null
template=$work/map/v0.75_L20_prolate.prm
base=$work/base
sed -e "s|set output directory = .*|set output directory = $base|" -e "s|set end time = .*|set end time = 4.7|" \
  -e "s|set rate tolerance = .*|set rate tolerance = 0|" "$template" > "$base.prm"
[ -f "$base/summary" ] || "$exe" "$base.prm" > "$base.log" 2>&1
variant() {  # NAME, then the prm text appended (a later `set` of an entry wins)
  local name=$1 text=$2
  rm -rf "${work:?}/$name"; cp -r "$base" "$work/$name"
  sed -e "s|$base|$work/$name|" -e "s|set end time = 4.7|set end time = 5.3|" "$base.prm" > "$work/$name.prm"
  printf 'subsection time stepping\n  set energy law = count\n  set energy budget = true\nend\n%b' "$text" >> "$work/$name.prm"
  "$exe" "$work/$name.prm" > "$work/$name.log" 2>&1 || echo "$name: exit $?"
}
if [ "${1:-}" = rate ]; then
  variant shipped ''
  for tr in 0.1 0.2; do
    variant "T_r_$tr" "subsection mesh redistribution\n  set relaxation time = $tr\nend\n"
  done
  variant tau_max_0.01 'subsection time stepping\n  set maximum time step = 0.01\nend\n'
  variant no_convection 'subsection flow\n  set convection = false\nend\n'
  /usr/bin/python3 benchmarks/energy_law/burst.py 4.7 5.3 "$work"/{shipped,T_r_0.1,T_r_0.2,tau_max_0.01,no_convection}
  exit
fi
variant shipped ''
variant no_momenta 'subsection flow\n  set conserve momenta = false\nend\n'
variant no_projection 'subsection conservation projection\n  set enabled = false\nend\n'
for tr in 0.5 5 50; do
  variant "T_r_$tr" "subsection mesh redistribution\n  set relaxation time = $tr\nend\n"
done
/usr/bin/python3 benchmarks/energy_law/burst.py 4.7 5.3 "$work"/{shipped,no_momenta,no_projection,T_r_0.5,T_r_5,T_r_50}
