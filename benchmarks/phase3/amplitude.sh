#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/phase3/amplitude.sh: when does the rotational symmetry break, against the amplitude of the seeded
# shape perturbation? prm/prolate.prm and prm/oblate.prm with `initial state/shape perturbation` = ε.
#   benchmarks/phase3/amplitude.sh [--quick]        from the repository root, after building
# Environment: SHAPES (default "oblate prolate"), AMPLITUDES (default "0 1e-8 1e-6 1e-4"), REFINEMENT (default 3),
# END_oblate (default 4), END_prolate (default 25), LIMIT (wall-time limit per case in s, default 3600), EXE.
# Each case writes amplitude/<shape>_r<r>_<ε>.statistics and .summary; amplitude.csv collects t_sym_1e-4 and
# t_sym_1e-2 (the first t with e(λ) ≥ 1e-4, 1e-2) and ⟨ω⟩ over each prm's window; amplitude_plot.py draws
# amplitude.png (e(λ) against t).
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/phase3
exe=${EXE:-./build/fluid_surface}
shapes=${SHAPES:-"oblate prolate"}; amplitudes=${AMPLITUDES:-"0 1e-8 1e-6 1e-4"}; r=${REFINEMENT:-3}
declare -A end=([oblate]=${END_oblate:-4} [prolate]=${END_prolate:-25}); limit=${LIMIT:-3600}
[ "${1:-}" = "--quick" ] && { r=2; end=([oblate]=0.3 [prolate]=0.3); limit=300; amplitudes="0 1e-4"; }
work=$(mktemp -d)
mkdir -p $here/amplitude
for shape in $shapes; do for eps in $amplitudes; do
  name=${shape}_r${r}_$eps
  cat > $work/$name.prm <<PRM
include $PWD/prm/$shape.prm
subsection geometry
  set refinement = $r
end
subsection initial state
  set shape perturbation = $eps
end
subsection time stepping
  set end time = ${end[$shape]}
end
subsection output
  set output directory = $work/$name
  set write vtu = false
  set screen interval = 100000
end
PRM
  timeout $limit $exe $work/$name.prm > $work/$name.log 2>&1
  echo "$name: exit $?"
  cp $work/$name/statistics $here/amplitude/$name.statistics 2>/dev/null
  cp $work/$name/summary $here/amplitude/$name.summary 2>/dev/null
done; done
/usr/bin/python3 $here/amplitude_plot.py $here/amplitude $here/amplitude.csv $here/amplitude.png
