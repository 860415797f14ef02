#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/phase3/snapshots.sh: the seed's panel [A] (snapshots before, during and after the symmetry breaking
# and the end state) and an animation of a run, from its VTU output (doc/scripts/render_snapshots.py, ParaView's
# pvpython under xvfb-run; ffmpeg).
#   benchmarks/phase3/snapshots.sh RESULTS_DIR NAME "T1 T2 T3 T4" [FRAME_STEP]
# writes benchmarks/phase3/NAME_panel.png and, with FRAME_STEP (every FRAME_STEP-th output time), NAME.mp4.
# Needs: apt-get install paraview python3-paraview xvfb xauth ffmpeg python3-matplotlib
set -eu
cd "$(dirname "$0")/../.."
here=benchmarks/phase3
dir=$1; name=$2; times=$3; frame_step=${4:-0}
work=$(mktemp -d)
# pvpython sometimes aborts with "bad X server connection" when xvfb-run's server is not up yet: try three times.
render() {
  for attempt in 1 2 3; do
    xvfb-run -a pvpython doc/scripts/render_snapshots.py "$dir/solution.pvd" --statistics "$dir/statistics" \
      --resolution 480 480 "$@" 2> $work/render.err && return 0
    sleep 3
  done
  tail -3 $work/render.err >&2; return 1
}
# The panel coloured by H; the animation grey (its colour range would span the short-lived curvature ripples of
# the fast transformation, H up to +15 at t ≈ 5.03 in the oblate at refinement 3, and wash out every other frame).
render --times $times -o $work/panel --colour-by H
/usr/bin/python3 - "$work" "$here/${name}_panel.png" $times <<'PY'
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.image as image
import matplotlib.pyplot as plt
work, out, times = sys.argv[1], sys.argv[2], sys.argv[3:]
fig, axes = plt.subplots(1, len(times), figsize=(3.2 * len(times), 3.4))
for ax, t in zip(axes, times):
    ax.imshow(image.imread(f"{work}/panel_t{float(t):g}.png"))
    ax.axis("off")
fig.tight_layout()
fig.savefig(out, dpi=110)
PY
echo "wrote $here/${name}_panel.png"
if [ "$frame_step" -gt 0 ]; then
  all=$(grep -o 'timestep="[^"]*"' "$dir/solution.pvd" | cut -d'"' -f2 | awk -v s=$frame_step 'NR % s == 1 || s == 1')
  render --times $all -o $work/frame > /dev/null
  n=0
  for t in $all; do
    ln -s "$work/frame_t$(/usr/bin/python3 -c "print('%g' % float('$t'))").png" "$work/seq_$(printf %04d $n).png"; n=$((n + 1))
  done
  ffmpeg -loglevel error -y -framerate 8 -i "$work/seq_%04d.png" -vf "scale=480:-2" -pix_fmt yuv420p "$here/$name.mp4"
  echo "wrote $here/$name.mp4 ($n frames)"
fi
