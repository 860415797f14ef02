#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/rotating_modes/exactness.sh (issue 33, item 1): a rotating axisymmetric equilibrium started at its own
# state (prm/seeded_mode_oblate.prm without the seed) for 100 steps of τ = 0.1 and 1000 steps of τ = 0.01 (t = 10)
# with each step (backward Euler or BDF2, one geometry correction; lab or Tisserand frame). How far it moves: the
# change of ω and of the L² distance to the equilibrium shape E(L²) from t = 0 to t = 10 (exactness.csv). The energy
# check is off (a fixed step; the discrete state relaxes from the collocated equilibrium).
#   benchmarks/rotating_modes/exactness.sh        from the repository root, after building
# Environment: REFINEMENT (default 2), SCHEMES (default "be bdf2"; bdf2: the linear predictor of the geometry, bdf2s:
# from S^m, bdf2n: quadratic normal), FRAMES (default "lab Tisserand"), OUT (default exactness.csv), WORK, EXE.
set -u
cd "$(dirname "$0")/../.."
here=benchmarks/rotating_modes
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/$here/work}/exactness
r=${REFINEMENT:-2}
mkdir -p "$work"
names=""
for s in ${SCHEMES:-be bdf2}; do for frame in ${FRAMES:-lab Tisserand}; do for tau in 0.1 0.01; do
  name=r${r}_${s}_${frame}_tau$tau; names="$names $name"
  cat > "$work/$name.prm" <<PRM
include $PWD/prm/seeded_mode_oblate.prm
subsection geometry
  set refinement = $r
end
subsection initial state
  set shape perturbation = 0
  set perturbation form = random
end
subsection time stepping
  set end time = 10
  set time step = $tau
  set maximum time step = $tau
  set adaptive = false
  set scheme = $([ $s = be ] && echo "backward Euler" || echo BDF2)
  set frame = $frame
  # a fixed step must not be stopped by the energy check: the discrete state is not a discrete equilibrium, and F
  # moves by its relaxation (about 6e-5 F in the first steps of τ = 0.01 at refinement 2)
  set energy tolerance = 1
end
subsection geometry iteration
  set predictor = $(case $s in bdf2s) echo "old surface";; bdf2n) echo "quadratic normal";; *) echo linear;; esac)
end
subsection output
  set output directory = $work/$name
  set overwrite = true
  set write vtu = false
  set screen interval = 100000
end
PRM
  start=$(date +%s.%N)
  "$exe" "$work/$name.prm" > "$work/$name.log" 2>&1; status=$?
  echo "$name exit $status, $(echo "$(date +%s.%N) - $start" | bc) s"
done; done; done
/usr/bin/python3 - "$work" $names > $here/${OUT:-exactness.csv} <<'PY'
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])) if sys.argv[0] != "-" else ".", "benchmarks", "phase3"))
import statistics_columns
work, names = sys.argv[1], sys.argv[2:]
print("run,steps,omega(0),omega(10),omega change,E(L2)(0),E(L2)(10),max E(L2),max |dA/A|,max |dV/V|")
for name in names:
    c = statistics_columns.read(os.path.join(work, name, "statistics"))
    w, e = c["angular velocity"], c["L2 distance to equilibrium"]
    print(f"{name},{len(w) - 1},{w[0]:.9f},{w[-1]:.9f},{w[-1] - w[0]:+.3e},{e[0]:.3e},{e[-1]:.3e},{max(e):.3e},"
          f"{max(abs(a / c['area'][0] - 1) for a in c['area']):.2e},{max(abs(v / c['volume'][0] - 1) for v in c['volume']):.2e}")
PY
cat $here/${OUT:-exactness.csv}
