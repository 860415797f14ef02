#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/stability_chart/routes.sh: route (b) of issue 49, item 3. Scene stability's leading growth rate σ of
# one class (default m = 2 even) at the spinning equilibria of the chart's branch and v for several L around the
# second variation's L_c, over refinements and time steps; collected into WORK/routes_stability.csv. Then
#   /usr/bin/python3 benchmarks/stability_chart/routes.py WORK/routes_stability.csv    # L_c of each (refinement, τ)
#   benchmarks/stability_chart/routes.sh [--quick]     from the repository root, after building
#     (--quick: refinement 2, two L, a minute or two)
# Environment: EXE (default build/fluid_surface), WORK (default benchmarks/stability_chart/work, not committed),
# BRANCH (oblate), V (0.66), LS (default "11.8 12.44 13.1"), REFINEMENTS ("3"), TAUS ("0.02"), MODE (2),
# PARITY (even), JOBS (1). Each run about 2.5 minutes at refinement 3 (one core), four times that at 4.
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/stability_chart
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/$here/work}
branch=${BRANCH:-oblate}; v=${V:-0.66}; ls=${LS:-"11.8 12.44 13.1"}
refinements=${REFINEMENTS:-3}; taus=${TAUS:-0.02}; mode=${MODE:-2}; parity=${PARITY:-even}
if [ "${1:-}" = "--quick" ]; then refinements=2; ls="11.8 13.1"; work=$work/quick; fi
mkdir -p "$work"
queue=$(for r in $refinements; do for tau in $taus; do for L in $ls; do
  name=route_${branch}_v${v}_L${L}_r${r}_tau${tau}_m${mode}${parity}
  {
    echo "include $PWD/$here/route_stability.prm"
    echo "subsection geometry"; echo "  set refinement = $r"; echo "end"
    echo "subsection equilibrium"; echo "  set reduced volume = $v"; echo "  set branch = $branch"
    echo "  set angular momentum = $L"; echo "end"
    echo "subsection time stepping"; echo "  set time step = $tau"; echo "end"
    echo "subsection stability"; echo "  set wavenumbers = $mode"; echo "  set parities = $parity"; echo "end"
    echo "subsection output"; echo "  set output directory = $work/$name"; echo "  set overwrite = true"; echo "end"
  } > "$work/$name.prm"
  echo "$name"
done; done; done)
run_one() { [ -f "$work/$1/spectrum.csv" ] || "$exe" "$work/$1.prm" > "$work/$1.log" 2>&1; echo "$1 exit $?"; }
export -f run_one; export exe work
echo "$queue" | xargs -P "${JOBS:-1}" -I{} bash -c 'run_one {}'
# shellcheck disable=SC2086
bash benchmarks/spectrum/collect_spectra.sh "$work" "$work/routes_stability.csv" branch,v,L,refinement,tau \
  's/^route_\([a-z]*\)_v\([0-9.]*\)_L\([0-9.]*\)_r\([0-9]*\)_tau\([0-9.e-]*\)_.*$/\1,\2,\3,\4,\5/' $queue
