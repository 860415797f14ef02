#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/work_precision: run time against error of the full model, prm/oblate.prm at refinement 3 to t = 7.
# Each variant (a time-step setting of a scheme) runs once; its errors in F(t), ω(t) and e(λ)(t) on the grid
# t = 0.25, 0.5, …, 7 and in t_sym_1e-2 are measured against a reference run (REFERENCE, default bdf2_0.0025: BDF2
# with τ_max = τ₀ = 2.5e-3; same mesh, so only the time discretization is measured). `reference` is the earlier
# reference, the lagged step with τ_max = 2.5e-3 and energy tolerance 1e-4.
#   benchmarks/work_precision/run.sh [--quick]      from the repository root, after building
# A completed run whose prm is unchanged is kept (FORCE=1: run it again).
# Environment: VARIANTS (names below), WORK (default benchmarks/work_precision/work, not committed), EXE.
# results.csv holds the errors of every variant; plot.py draws work_precision.png (--quick: both in the work folder).
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/work_precision
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/$here/work}
end=7
reference=${REFERENCE:-bdf2_0.0025}
variants=${VARIANTS:-"bdf2_0.0025 reference lagged_0.1 lagged_0.05 lagged_0.025 lagged_0.0125 lagged_0.05_e1e-4 normal1_0.05 normal1_0.025 normal1_0.0125 all1_0.05 all1_0.025 after1_0.05 after1_0.025 bdf2_0.1 bdf2_0.05 bdf2_0.025 lagged_0.05_s0.0025 bdf2_0.05_s0.0025 after1_0.05_s0.0025"}
out=$here
if [ "${1:-}" = "--quick" ]; then reference=bdf2_0.005; variants="bdf2_0.005 lagged_0.05 bdf2_0.05"; end=1; work=$work/quick; out=$work; fi
mkdir -p "$work"

# <scheme>_<τ_max>[_e<energy tolerance>][_s<τ₀>] (τ₀ = min(τ_max, 0.01) unless named); reference: lagged, τ_max = 2.5e-3, energy tolerance 1e-4. Schemes: lagged;
# normal1, all1: the predictor–corrector step (one re-assembly with ñ and c, or all geometry, of the predicted
# surface); after1: lagged until the energy check rejects a step, then all1 for the retry and the next 20 steps;
# bdf2: all1 with time stepping/scheme = BDF2 (second order).
variant_lines() {
  local v=$1 scheme tau energy=1e-3 start relax
  [ $v = reference ] && v=lagged_0.0025_e1e-4
  scheme=${v%%_*}; tau=${v#*_}; tau=${tau%%_*}
  start=$(awk -v t=$tau 'BEGIN { print (t < 0.01 ? t : 0.01) }')
  case $v in *_e*) energy=${v##*_e}; energy=${energy%%_*};; esac
  case $v in *_s*) start=${v##*_s}; start=${start%%_*};; esac
  # the relaxation phase's τ cap of prm/oblate.prm, at most τ_max (the program refuses a larger one); every variant but
  # bdf2 is the backward-Euler step it was measured with (prm/oblate.prm now sets SDIRK2, which the program refuses
  # with the lagged geometry)
  relax=$(awk '/^ *set relaxation maximum time step *=/ { print $NF; exit }' prm/oblate.prm)
  printf 'subsection time stepping\n  set time step = %s\n  set maximum time step = %s\n  set energy tolerance = %s\n' \
    $start $tau $energy
  [ -n "$relax" ] && printf '  set relaxation maximum time step = %s\n' "$(awk -v r="$relax" -v t=$tau 'BEGIN { print (r < t ? r : t) }')"
  [ $scheme != bdf2 ] && printf '  set scheme = backward Euler\n'
  printf 'end\n'
  case $scheme in
    lagged) printf 'subsection geometry iteration\n  set maximum iterations = 0\n  set apply = always\nend\n' ;;
    # implicit only where it is not the default (all): all1 runs also with a program without the entry
    normal1|all1) printf 'subsection geometry iteration\n  set maximum iterations = 1\n  set tolerance = 0\n'
      [ $scheme = normal1 ] && printf '  set implicit = normal\n'
      printf '  set apply = always\nend\n' ;;
    after1) printf 'subsection geometry iteration\n  set maximum iterations = 1\n  set tolerance = 0\n  set apply = after rejection\nend\n' ;;
    bdf2) printf 'subsection geometry iteration\n  set maximum iterations = 1\n  set tolerance = 0\n  set apply = always\nend\nsubsection time stepping\n  set scheme = BDF2\nend\n' ;;
  esac
}

for v in $variants; do
  dir=$work/$v
  # a completed run of the same prm is kept (FORCE=1 runs it again)
  (
    cat > $work/$v.prm.new <<PRM
include $PWD/prm/oblate.prm
subsection geometry
  set refinement = 3
end
subsection time stepping
  set end time = $end
end
subsection output
  set output directory = $dir
  set overwrite = true
  set write vtu = false
  set screen interval = 100000
end
$(variant_lines $v)
PRM
    if [ -z "${FORCE:-}" ] && cmp -s $work/$v.prm.new $work/$v.prm && grep -q '^status: completed' $dir/summary 2>/dev/null; then
      echo "$v: kept"; rm $work/$v.prm.new; exit 0
    fi
    mv $work/$v.prm.new $work/$v.prm
    $exe $work/$v.prm > $work/$v.log 2>&1
    echo "$v exit $?"
  )
done
# a table that cannot be made (a run without statistics) ends the script with exit 1 and leaves results.csv as it was
/usr/bin/python3 $here/errors.py "$work" $end $reference $variants > $out/results.csv.tmp || exit 1
mv $out/results.csv.tmp $out/results.csv
/usr/bin/python3 $here/plot.py $out/results.csv $out/work_precision.png $reference || exit 1
cat $out/results.csv
