"""Render snapshots of a fluid_surface run as in panel [A] of the seed's
Figures 1-2 (Nestler & Voigt, section 3): the surface, its three principal
slices (planes x, y, z = const through the centre of the surface) as black
lines, the velocity as green arrows (Glyph of the point field 'velocity'),
the rotation axis (z) as a red arrow pointing in the direction of rotation
(sign of omega, right-hand rule) and, if the statistics file is found, the
elongation axis as a blue line.  One PNG per requested time.

Usage
-----
    xvfb-run -a pvpython doc/scripts/render_snapshots.py RESULTS_DIR/solution.pvd \\
        --times 0 7.5 20 25 -o prefix [--statistics RESULTS_DIR/statistics] \\
        [--resolution 900 900] [--azimuth -60] [--elevation 20] \\
        [--arrow-scale S] [--arrows 400] [--no-elongation-axis]

writes prefix_t0.png, prefix_t7.5.png, ...  Each requested time is rendered
at the nearest time step of the .pvd file (a note is printed when they
differ).  All snapshots share one camera distance (parallel projection) and
one arrow scale, so sizes and speeds compare across the images; the arrow
scale defaults to: longest arrow over all snapshots = 0.25 x the largest
extent of the surface.  The statistics file (default: 'statistics' next to
the .pvd) supplies the sign of 'angular velocity' and the 'elongation axis
x|y|z' at the snapshot time; without it the red arrow points to +z and no
blue line is drawn.

Written against the paraview.simple API of ParaView 5.9-5.12 (Glyph with
OrientationArray/ScaleArray/GlyphMode; properties that differ between
versions are set through a tolerant helper).

UNTESTED: pvpython is not installed on the development machine (and
python3-paraview conflicts with python3-vtk9 there), so this script has
been checked only for syntax, not run.  Expect small fixes on first use.
"""

import argparse
import math
import os
import re
import sys

from paraview.simple import (  # noqa: F401  (pvpython provides these)
    CleantoGrid,
    ColorBy,
    Cone,
    GetActiveViewOrCreate,
    Line,
    PVDReader,
    Render,
    SaveScreenshot,
    Show,
    Slice,
    Text,
    Glyph,
    GetAnimationScene,
)

PROG = "render_snapshots.py"


def fail(message):
    sys.exit("%s: error: %s" % (PROG, message))


def try_set(proxy, name, *values):
    """Set proxy.name to the first value this ParaView version accepts."""
    for value in values:
        try:
            setattr(proxy, name, value)
            return True
        except (AttributeError, ValueError, TypeError):
            continue
    return False


def read_statistics(path):
    """Minimal parser of the statistics file: {name: [floats]} by '# N: name'
    headers; malformed rows (e.g. a partial last line) are skipped."""
    columns, rows = {}, []
    header = re.compile(r"^#\s*(\d+)\s*:\s*(.*?)\s*$")
    with open(path, "r") as f:
        for line in f:
            s = line.strip()
            if not s:
                continue
            if s.startswith("#"):
                m = header.match(s)
                if m:
                    columns[m.group(2)] = int(m.group(1)) - 1
                continue
            if not line.endswith("\n"):
                continue  # partial last line
            fields = s.split()
            if columns and len(fields) != max(columns.values()) + 1:
                continue
            try:
                rows.append([float(x) for x in fields])
            except ValueError:
                continue
    if "time" not in columns or not rows:
        return None
    return {name: [r[i] for r in rows] for name, i in columns.items()}


def row_at(stats, t):
    """Index of the statistics row nearest to time t."""
    times = stats["time"]
    return min(range(len(times)), key=lambda i: abs(times[i] - t))


def bounds_at(source, t):
    source.UpdatePipeline(t)
    return source.GetDataInformation().GetBounds()


def max_speed_at(reader, t):
    reader.UpdatePipeline(t)
    array = reader.PointData["velocity"]
    return array.GetRange(-1)[1]  # component -1: magnitude


def main():
    parser = argparse.ArgumentParser(description="Render snapshots of a fluid_surface run (seed panel [A]).")
    parser.add_argument("pvd", help="RESULTS_DIR/solution.pvd")
    parser.add_argument("--times", nargs="+", type=float, required=True, help="snapshot times")
    parser.add_argument("-o", "--output", default="snapshot", help="prefix of the PNG files (default 'snapshot')")
    parser.add_argument("--statistics", help="statistics file (default: next to the .pvd)")
    parser.add_argument("--resolution", nargs=2, type=int, default=[900, 900], metavar=("W", "H"))
    parser.add_argument("--azimuth", type=float, default=-60.0, help="camera azimuth about z in degrees")
    parser.add_argument("--elevation", type=float, default=20.0, help="camera elevation above the xy plane in degrees")
    parser.add_argument("--arrow-scale", type=float, help="length of an arrow per unit speed")
    parser.add_argument("--arrows", type=int, default=400, help="(maximum) number of velocity arrows")
    parser.add_argument("--no-elongation-axis", action="store_true", help="do not draw the blue elongation axis")
    args = parser.parse_args()

    if not os.path.isfile(args.pvd):
        fail("'%s' not found" % args.pvd)
    stats_path = args.statistics or os.path.join(os.path.dirname(os.path.abspath(args.pvd)), "statistics")
    stats = read_statistics(stats_path) if os.path.isfile(stats_path) else None
    if stats is None:
        print("%s: no usable statistics at '%s': red arrow points to +z, no elongation axis" % (PROG, stats_path))

    reader = PVDReader(FileName=os.path.abspath(args.pvd))
    values = reader.TimestepValues  # a scalar when the file has one time step
    if values is None or (hasattr(values, "__len__") and len(values) == 0):
        available = [0.0]
    elif hasattr(values, "__len__"):
        available = [float(v) for v in values]
    else:
        available = [float(values)]
    reader.UpdatePipeline(available[0])
    if "velocity" not in reader.PointData.keys():
        fail("'%s' has no point field 'velocity' (fields: %s)" % (args.pvd, ", ".join(reader.PointData.keys())))

    # deal.II writes every cell with its own copy of its vertices: merge them
    # so that glyph sampling and shading see one connected surface.
    surface = CleantoGrid(Input=reader)

    snapshots = []
    for requested in args.times:
        t = min(available, key=lambda a: abs(a - requested))
        if abs(t - requested) > 1e-8 * max(1.0, abs(requested)):
            print("%s: t = %g requested, rendering the nearest output time t = %g" % (PROG, requested, t))
        snapshots.append((requested, t))

    # Common camera scale and arrow scale over all snapshots.
    extent, speed = 0.0, 0.0
    for _, t in snapshots:
        b = bounds_at(surface, t)
        extent = max(extent, b[1] - b[0], b[3] - b[2], b[5] - b[4])
        speed = max(speed, max_speed_at(reader, t))
    if extent <= 0:
        fail("the surface in '%s' is empty" % args.pvd)
    arrow_scale = args.arrow_scale if args.arrow_scale else (0.25 * extent / speed if speed > 0 else 1.0)

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = list(args.resolution)
    try_set(view, "OrientationAxesVisibility", 0)
    try_set(view, "UseColorPaletteForBackground", 0)
    try_set(view, "BackgroundColorMode", "Single Color")
    try_set(view, "Background", [1.0, 1.0, 1.0])
    try_set(view, "CameraParallelProjection", 1)

    # surface
    surface_display = Show(surface, view)
    ColorBy(surface_display, None)
    surface_display.Representation = "Surface"
    try_set(surface_display, "DiffuseColor", [0.85, 0.85, 0.85])
    try_set(surface_display, "AmbientColor", [0.85, 0.85, 0.85])
    try_set(surface_display, "Interpolation", "Gouraud")

    # principal slices
    slices = []
    for normal in ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]):
        s = Slice(Input=surface)
        s.SliceType = "Plane"
        s.SliceType.Normal = normal
        try_set(s, "Triangulatetheslice", 0)
        d = Show(s, view)
        ColorBy(d, None)
        try_set(d, "DiffuseColor", [0.0, 0.0, 0.0])
        try_set(d, "AmbientColor", [0.0, 0.0, 0.0])
        try_set(d, "LineWidth", 3.0)
        try_set(d, "RenderLinesAsTubes", 1)
        slices.append(s)

    # velocity arrows
    glyph = Glyph(Input=surface, GlyphType="Arrow")
    glyph.OrientationArray = ["POINTS", "velocity"]
    glyph.ScaleArray = ["POINTS", "velocity"]
    glyph.ScaleFactor = arrow_scale
    if not try_set(glyph, "GlyphMode", "Uniform Spatial Distribution (Surface Sampling)",
                   "Uniform Spatial Distribution (Bounds Based)", "Uniform Spatial Distribution"):
        try_set(glyph, "GlyphMode", "Every Nth Point")
    try_set(glyph, "MaximumNumberOfSamplePoints", args.arrows)
    glyph_display = Show(glyph, view)
    ColorBy(glyph_display, None)
    try_set(glyph_display, "DiffuseColor", [0.0, 0.6, 0.0])
    try_set(glyph_display, "AmbientColor", [0.0, 0.6, 0.0])

    # rotation axis: red line along z through the centre, cone at the end
    # that points in the direction of rotation (right-hand rule)
    axis_line = Line()
    axis_display = Show(axis_line, view)
    try_set(axis_display, "DiffuseColor", [0.85, 0.0, 0.0])
    try_set(axis_display, "AmbientColor", [0.85, 0.0, 0.0])
    try_set(axis_display, "LineWidth", 4.0)
    try_set(axis_display, "RenderLinesAsTubes", 1)
    axis_tip = Cone()
    try_set(axis_tip, "Resolution", 24)
    tip_display = Show(axis_tip, view)
    try_set(tip_display, "DiffuseColor", [0.85, 0.0, 0.0])
    try_set(tip_display, "AmbientColor", [0.85, 0.0, 0.0])

    # elongation axis: blue line through the centre
    elongation = None
    if stats is not None and not args.no_elongation_axis and all(
            "elongation axis " + c in stats for c in "xyz"):
        elongation = Line()
        el_display = Show(elongation, view)
        try_set(el_display, "DiffuseColor", [0.0, 0.2, 0.9])
        try_set(el_display, "AmbientColor", [0.0, 0.2, 0.9])
        try_set(el_display, "LineWidth", 3.0)
        try_set(el_display, "RenderLinesAsTubes", 1)

    label = Text()
    label_display = Show(label, view)
    try_set(label_display, "WindowLocation", "Upper Left Corner", "UpperLeftCorner")
    try_set(label_display, "FontSize", 28)
    try_set(label_display, "Color", [0.0, 0.0, 0.0])

    az, el = math.radians(args.azimuth), math.radians(args.elevation)
    direction = [math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)]

    try:
        scene = GetAnimationScene()
        scene.UpdateAnimationUsingDataTimeSteps()
    except Exception:  # the view time alone also selects the data time
        scene = None

    written = []
    for requested, t in snapshots:
        b = bounds_at(surface, t)
        centre = [0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])]
        for s in slices:
            s.SliceType.Origin = centre

        sign, axis = 1.0, None
        if stats is not None:
            i = row_at(stats, t)
            if "angular velocity" in stats and stats["angular velocity"][i] < 0:
                sign = -1.0
            if elongation is not None:
                axis = [stats["elongation axis " + c][i] for c in "xyz"]

        # red axis: from below the surface to beyond it in the direction of
        # rotation; 0.5 height + margin + tip <= 0.75 extent fits the view
        margin = 0.15 * extent
        low, high = (b[4] - 0.3 * margin, b[5] + margin) if sign > 0 else (b[5] + 0.3 * margin, b[4] - margin)
        axis_line.Point1 = [centre[0], centre[1], low]
        axis_line.Point2 = [centre[0], centre[1], high]
        tip_height = 0.1 * extent
        axis_tip.Height = tip_height
        axis_tip.Radius = 0.04 * extent
        axis_tip.Direction = [0.0, 0.0, sign]
        axis_tip.Center = [centre[0], centre[1], high + 0.5 * sign * tip_height]

        if elongation is not None and axis is not None:
            half = 0.6 * extent
            elongation.Point1 = [centre[k] - half * axis[k] for k in range(3)]
            elongation.Point2 = [centre[k] + half * axis[k] for k in range(3)]

        label.Text = "t = %g" % t

        distance = 4.0 * extent
        view.CameraFocalPoint = centre
        view.CameraPosition = [centre[k] + distance * direction[k] for k in range(3)]
        view.CameraViewUp = [0.0, 0.0, 1.0]
        view.CameraParallelScale = 0.8 * extent
        view.ViewTime = t
        if scene is not None:
            scene.AnimationTime = t

        Render(view)
        filename = "%s_t%g.png" % (args.output, requested)
        SaveScreenshot(filename, view, ImageResolution=list(args.resolution))
        written.append(filename)
        print("%s: wrote %s (t = %g)" % (PROG, filename, t))

    return written


if __name__ == "__main__":
    main()
