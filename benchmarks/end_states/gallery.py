#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/end_states: a gallery of the end shapes, one sheet per start (prolate, oblate), rows v, columns L₀.
Each cell is the run's last output, rendered by doc/scripts/render_snapshots.py (surface, its three principal
slices, the velocity as green arrows, the rotation axis in red, the elongation axis in blue), with its shape class
and F underneath. Every cell has its own camera scale and arrow scale.
    /usr/bin/python3 benchmarks/end_states/gallery.py WORK results.csv benchmarks/end_states/gallery
writes gallery_prolate.png and gallery_oblate.png. Needs pvpython and xvfb-run (Debian: paraview,
python3-paraview, xvfb); renders that exist already in WORK/renders are reused."""
import csv
import os
import re
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

work, table, prefix = sys.argv[1:4]
script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "doc", "scripts", "render_snapshots.py")
rows = list(csv.DictReader(open(table)))
renders = os.path.join(work, "renders")
os.makedirs(renders, exist_ok=True)


def last_output_time(pvd):
    times = re.findall(r'timestep="([^"]+)"', open(pvd).read())
    return float(times[-1]) if times else None


def render(row):
    name = f"v{row['v']}_L{row['L0']}_{row['start']}"
    pvd = os.path.join(work, name, "solution.pvd")
    if not row.get("F") or not os.path.exists(pvd):
        return None
    t = last_output_time(pvd)
    png = os.path.join(renders, f"{name}_t{t:g}.png")
    if not os.path.exists(png):
        for attempt in range(10):  # pvpython under xvfb aborts at start-up about every second time ("bad X server connection")
            subprocess.run(["xvfb-run", "-a", "pvpython", script, pvd, "--times", f"{t:g}", "-o",
                            os.path.join(renders, name), "--resolution", "500", "500", "--arrows", "60"],
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            if os.path.exists(png):
                break
    return png if os.path.exists(png) else None


vs = sorted({r["v"] for r in rows}, key=float)
l0s = sorted({r["L0"] for r in rows}, key=float)
for start in ("prolate", "oblate"):
    fig, axes = plt.subplots(len(vs), len(l0s), figsize=(2.6 * len(l0s), 2.8 * len(vs)), squeeze=False)
    for row in (r for r in rows if r["start"] == start):
        ax = axes[vs.index(row["v"])][l0s.index(row["L0"])]
        png = render(row)
        if png:
            ax.imshow(mpimg.imread(png))
        status = "" if row.get("status") == "steady" else f" ({row.get('status', 'not run')})"
        label = f"{row['shape']}, F = {float(row['F']):.3f}" if row.get("F") else "not run"
        ax.set_xlabel(label + status, fontsize=8)
    for k, ax in enumerate(axes.flat):
        ax.set_xticks([])
        ax.set_yticks([])
        if k < len(l0s):
            ax.set_title(f"L₀ = {l0s[k]}", fontsize=10)
        if k % len(l0s) == 0:
            ax.set_ylabel(f"v = {vs[k // len(l0s)]}", fontsize=10)
    fig.suptitle(f"End states from a {start} spheroid spinning about its symmetry axis (last output of each run)")
    fig.tight_layout()
    fig.savefig(f"{prefix}_{start}.png", dpi=80)
    print(f"wrote {prefix}_{start}.png")
