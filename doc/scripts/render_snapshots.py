# SPDX-License-Identifier: LGPL-2.1-or-later
"""Render snapshots of a fluid_surface run as in panel [A] of the seed's
Figures 1-2 (Nestler & Voigt, section 3): the surface, its three principal
slices (planes x, y, z = const through the centre of the surface) as black
lines, the velocity as green arrows (Glyph of the point field 'velocity',
length proportional to the speed), the rotation axis as a red arrow pointing
in the direction of rotation (right-hand rule) and, if the statistics file
is found, the elongation axis as a blue line.  One PNG per requested time.

Usage
-----
    xvfb-run -a pvpython doc/scripts/render_snapshots.py RESULTS_DIR/solution.pvd \\
        --times 0 7.5 20 25 -o prefix [--statistics RESULTS_DIR/statistics] \\
        [--resolution 800 800] [--azimuth -60] [--elevation 20] \\
        [--colour-by H] [--arrow-scale S] [--arrows 150] \\
        [--arrow-sampling surface|points] \\
        [--rotation-axis vector|z] [--no-elongation-axis]

writes prefix_t0.png, prefix_t7.5.png, ...  Each requested time is rendered
at the nearest time step of the .pvd file (a note is printed when they
differ).  All snapshots share one camera scale (parallel projection, fitted
to everything drawn in all snapshots) and one arrow scale, so sizes and
speeds compare across the images; the arrow scale defaults to: longest arrow
over all snapshots = 0.2 x the largest extent of the surface.  The surface
is light grey, or coloured by a point field (--colour-by H: mean curvature)
with a colour bar and one colour range for all snapshots.

The statistics file (default: 'statistics' next to the .pvd) supplies, at
the row nearest to the snapshot time, the rotation axis ('rotation vector
x|y|z', Omega = I^-1 L, direction and sense; with --rotation-axis z or when
Omega = 0: the z axis with the sense of the sign of 'angular velocity') and
the 'elongation axis x|y|z'.  Without it the red arrow points to +z and no
blue line is drawn.  The blue line passes through the centre and ends a
little outside the surface; the red arrow starts just outside the surface,
or where the blue line ends when the two axes are (nearly) aligned, so that
they do not hide each other.

Tested with ParaView 5.11.0 (Debian 12 packages paraview, python3-paraview,
run offscreen through xvfb-run).  ColorBy(display, None) fails in 5.11
('invalid association string'), so solid colours clear ColorArrayName
instead; properties that differ between versions are set through a tolerant
helper.
"""

import argparse
import math
import os
import re
import sys

from paraview import servermanager
from paraview.simple import (  # noqa: F401  (pvpython provides these)
    CleantoGrid,
    ColorBy,
    Cone,
    Delete,
    ExtractSurface,
    ForceTime,
    GenerateSurfaceNormals,
    GetActiveViewOrCreate,
    GetColorTransferFunction,
    GetScalarBar,
    Glyph,
    Line,
    PVDReader,
    Render,
    SaveScreenshot,
    Show,
    Slice,
    Text,
)

PROG = "render_snapshots.py"

GREY = [0.85, 0.85, 0.85]
BLACK = [0.0, 0.0, 0.0]
GREEN = [0.0, 0.55, 0.0]
RED = [0.85, 0.0, 0.0]
BLUE = [0.0, 0.25, 0.95]


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


def solid_colour(display, rgb):
    """Colour a display uniformly (no scalar colouring).  ColorBy(display,
    None) raises 'invalid association string' in ParaView 5.11, so the
    colour array is cleared directly."""
    display.ColorArrayName = ["POINTS", ""]
    try_set(display, "DiffuseColor", list(rgb))
    try_set(display, "AmbientColor", list(rgb))


def read_statistics(path):
    """Minimal parser of the statistics file: {name: [floats]} by '# N: name'
    headers; malformed rows (e.g. a partial last line) are skipped, and when
    the time goes backwards (a resumed run appended to the file) the later
    rows replace the earlier ones from that time on."""
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
    it = columns["time"]
    kept = []
    for r in rows:
        while kept and kept[-1][it] >= r[it]:
            kept.pop()
        kept.append(r)
    return {name: [r[i] for r in kept] for name, i in columns.items()}


def row_at(stats, t):
    """Index of the statistics row nearest to time t."""
    times = stats["time"]
    return min(range(len(times)), key=lambda i: abs(times[i] - t))


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v] if n > 0 else None


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def fetch_at(source, t):
    """The output of source at time t on the client (ForceTime, so that the
    requested step is delivered whatever the pipeline time is)."""
    frozen = ForceTime(Input=source)
    frozen.ForcedTime = t
    frozen.IgnorePipelineTime = 1
    frozen.UpdatePipeline()
    data = servermanager.Fetch(frozen)
    Delete(frozen)
    return data


def points_of(data):
    points = data.GetPoints()
    return [points.GetPoint(i) for i in range(points.GetNumberOfPoints())] if points else []


class SurfaceAt:
    """The surface at one time: points (for extents along an axis), bounds,
    centre, speed and range of the colour field."""

    def __init__(self, source, t, colour_field):
        data = fetch_at(source, t)
        self.points = points_of(data)
        self.bounds = data.GetBounds()
        self.centre = [0.5 * (self.bounds[2 * k] + self.bounds[2 * k + 1]) for k in range(3)]
        self.extent = max(self.bounds[2 * k + 1] - self.bounds[2 * k] for k in range(3))
        self.speed = data.GetPointData().GetArray("velocity").GetRange(-1)[1]  # -1: magnitude
        self.colour_range = data.GetPointData().GetArray(colour_field).GetRange(-1) if colour_field else None

    def reach(self, direction):
        """Largest distance of the surface from the centre along direction."""
        return max(dot([p[k] - self.centre[k] for k in range(3)], direction) for p in self.points)


def main():
    parser = argparse.ArgumentParser(description="Render snapshots of a fluid_surface run (seed panel [A]).")
    parser.add_argument("pvd", help="RESULTS_DIR/solution.pvd")
    parser.add_argument("--times", nargs="+", type=float, required=True, help="snapshot times")
    parser.add_argument("-o", "--output", default="snapshot", help="prefix of the PNG files (default 'snapshot')")
    parser.add_argument("--statistics", help="statistics file (default: next to the .pvd)")
    parser.add_argument("--resolution", nargs=2, type=int, default=[800, 800], metavar=("W", "H"))
    parser.add_argument("--azimuth", type=float, default=-60.0, help="camera azimuth about z in degrees")
    parser.add_argument("--elevation", type=float, default=20.0, help="camera elevation above the xy plane in degrees")
    parser.add_argument("--colour-by", metavar="FIELD",
                        help="colour the surface by this point field (e.g. H) with a colour bar; default light grey")
    parser.add_argument("--arrow-scale", type=float, help="length of an arrow per unit speed")
    parser.add_argument("--arrows", type=int, default=150, help="(maximum) number of velocity arrows")
    parser.add_argument("--arrow-sampling", choices=["surface", "points"], default="surface",
                        help="arrows at random points uniform in area (default) or at every n-th mesh vertex")
    parser.add_argument("--rotation-axis", choices=["vector", "z"], default="vector",
                        help="red arrow along the statistics' rotation vector (default) or along z")
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
    fields = reader.PointData.keys()
    if "velocity" not in fields:
        fail("'%s' has no point field 'velocity' (fields: %s)" % (args.pvd, ", ".join(fields)))
    if args.colour_by and args.colour_by not in fields:
        fail("--colour-by: '%s' has no point field '%s' (fields: %s)" % (args.pvd, args.colour_by, ", ".join(fields)))

    # deal.II writes every cell with its own copy of its vertices: merge them
    # so that glyph sampling, slices and the shading normals see one
    # connected surface.
    merged = CleantoGrid(Input=reader)
    polygons = ExtractSurface(Input=merged)
    surface = GenerateSurfaceNormals(Input=polygons)
    try_set(surface, "FeatureAngle", 180.0)
    try_set(surface, "Splitting", 0)
    try_set(surface, "ComputeCellNormals", 0)

    snapshots = []
    for requested in args.times:
        t = min(available, key=lambda a: abs(a - requested))
        if abs(t - requested) > 1e-8 * max(1.0, abs(requested)):
            print("%s: t = %g requested, rendering the nearest output time t = %g" % (PROG, requested, t))
        snapshots.append((requested, t, SurfaceAt(surface, t, args.colour_by)))

    # one arrow scale and one colour range over all snapshots
    extent = max(f.extent for _, _, f in snapshots)
    speed = max(f.speed for _, _, f in snapshots)
    if extent <= 0:
        fail("the surface in '%s' is empty" % args.pvd)
    arrow_scale = args.arrow_scale if args.arrow_scale else (0.2 * extent / speed if speed > 0 else 1.0)

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = list(args.resolution)
    try_set(view, "OrientationAxesVisibility", 0)
    try_set(view, "UseColorPaletteForBackground", 0)
    try_set(view, "BackgroundColorMode", "Single Color")
    try_set(view, "Background", [1.0, 1.0, 1.0])
    try_set(view, "CameraParallelProjection", 1)

    # surface
    surface_display = Show(surface, view)
    surface_display.Representation = "Surface"
    try_set(surface_display, "Interpolation", "Gouraud")
    try_set(surface_display, "Ambient", 0.15)
    try_set(surface_display, "Specular", 0.2)
    if args.colour_by:
        low = min(f.colour_range[0] for _, _, f in snapshots)
        high = max(f.colour_range[1] for _, _, f in snapshots)
        ColorBy(surface_display, ("POINTS", args.colour_by))
        lut = GetColorTransferFunction(args.colour_by)
        try_set(lut, "AutomaticRescaleRangeMode", "Never")
        lut.ApplyPreset("Oranges", True)
        lut.RescaleTransferFunction(low, high if high > low else low + 1.0)
        bar = GetScalarBar(lut, view)
        bar.Title = args.colour_by
        try_set(bar, "ComponentTitle", "")
        try_set(bar, "TitleColor", BLACK)
        try_set(bar, "LabelColor", BLACK)
        try_set(bar, "TitleFontSize", 20)
        try_set(bar, "LabelFontSize", 16)
        try_set(bar, "HorizontalTitle", 1)
        try_set(bar, "RangeLabelFormat", "%-#.3g")
        try_set(bar, "WindowLocation", "Lower Right Corner", "LowerRightCorner")
        surface_display.SetScalarBarVisibility(view, True)
    else:
        solid_colour(surface_display, GREY)

    # principal slices
    slices = []
    for normal in ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]):
        s = Slice(Input=surface)
        s.SliceType = "Plane"
        s.SliceType.Normal = normal
        try_set(s, "Triangulatetheslice", 0)
        d = Show(s, view)
        solid_colour(d, BLACK)
        try_set(d, "LineWidth", 3.0)
        try_set(d, "RenderLinesAsTubes", 1)
        slices.append(s)

    # velocity arrows: tail at a surface point, along u, length |u| x scale
    glyph = Glyph(Input=surface, GlyphType="Arrow")
    glyph.OrientationArray = ["POINTS", "velocity"]
    glyph.ScaleArray = ["POINTS", "velocity"]
    glyph.ScaleFactor = arrow_scale
    try_set(glyph.GlyphType, "TipResolution", 16)
    try_set(glyph.GlyphType, "TipRadius", 0.06)
    try_set(glyph.GlyphType, "TipLength", 0.25)
    try_set(glyph.GlyphType, "ShaftResolution", 8)
    try_set(glyph.GlyphType, "ShaftRadius", 0.018)
    if args.arrow_sampling == "surface" and try_set(
            glyph, "GlyphMode", "Uniform Spatial Distribution (Surface Sampling)",
            "Uniform Spatial Distribution (Bounds Based)", "Uniform Spatial Distribution"):
        try_set(glyph, "MaximumNumberOfSamplePoints", args.arrows)
    else:
        glyph.GlyphMode = "Every Nth Point"
        glyph.Stride = max(1, len(snapshots[0][2].points) // max(1, args.arrows))
    glyph_display = Show(glyph, view)
    solid_colour(glyph_display, GREEN)

    # rotation axis: red shaft and cone outside the surface, pointing in the
    # direction of rotation (right-hand rule)
    axis_line = Line()
    axis_display = Show(axis_line, view)
    solid_colour(axis_display, RED)
    try_set(axis_display, "LineWidth", 5.0)
    try_set(axis_display, "RenderLinesAsTubes", 1)
    axis_tip = Cone()
    try_set(axis_tip, "Resolution", 32)
    tip_display = Show(axis_tip, view)
    solid_colour(tip_display, RED)

    # elongation axis: blue line through the centre
    elongation = None
    if stats is not None and not args.no_elongation_axis and all(
            "elongation axis " + c in stats for c in "xyz"):
        elongation = Line()
        el_display = Show(elongation, view)
        solid_colour(el_display, BLUE)
        try_set(el_display, "LineWidth", 4.0)
        try_set(el_display, "RenderLinesAsTubes", 1)

    label = Text()
    label_display = Show(label, view)
    try_set(label_display, "WindowLocation", "Upper Left Corner", "UpperLeftCorner")
    try_set(label_display, "FontSize", 28)
    try_set(label_display, "FontFamily", "Times")
    try_set(label_display, "Color", BLACK)

    az, el = math.radians(args.azimuth), math.radians(args.elevation)
    direction = [math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)]
    up = [0.0, 0.0, 1.0]
    screen_x = unit(cross(up, direction))
    screen_y = cross(direction, screen_x)

    overhang = 0.08 * extent  # blue line beyond the surface (and gap before an aligned red arrow)
    shaft, tip_height = 0.15 * extent, 0.08 * extent

    # Place the axes for every snapshot first, so that one camera scale can
    # be fitted to everything that is drawn in any of them.
    placed = []
    for requested, t, f in snapshots:
        rotation, along = [0.0, 0.0, 1.0], None
        if stats is not None:
            i = row_at(stats, t)
            omega = None
            if args.rotation_axis == "vector" and all("rotation vector " + c in stats for c in "xyz"):
                omega = unit([stats["rotation vector " + c][i] for c in "xyz"])
            if omega is None and "angular velocity" in stats and stats["angular velocity"][i] < 0:
                omega = [0.0, 0.0, -1.0]
            if omega is not None:
                rotation = omega
            if elongation is not None:
                along = unit([stats["elongation axis " + c][i] for c in "xyz"])
        c = f.centre
        aligned = along is not None and abs(dot(along, rotation)) > 0.9
        start = f.reach(rotation) + (overhang if aligned else 0.02 * extent)
        axis_points = [[c[k] + start * rotation[k] for k in range(3)],
                       [c[k] + (start + shaft) * rotation[k] for k in range(3)],
                       [c[k] + (start + shaft + tip_height) * rotation[k] for k in range(3)]]
        el_points = None
        if along is not None:
            el_points = [[c[k] - (f.reach([-a for a in along]) + overhang) * along[k] for k in range(3)],
                         [c[k] + (f.reach(along) + overhang) * along[k] for k in range(3)]]
        placed.append((requested, t, f, rotation, axis_points, el_points))

    # per snapshot: the view centre is the middle of everything drawn, seen
    # on the screen; one scale for all snapshots fits the largest of them
    aspect = float(args.resolution[0]) / float(args.resolution[1])
    half_height, focal_points = 0.0, []
    for requested, t, f, rotation, axis_points, el_points in placed:
        drawn = f.points + points_of(fetch_at(glyph, t)) + axis_points + (el_points or [])
        lo, hi = [float("inf")] * 2, [float("-inf")] * 2
        for p in drawn:
            d = [p[k] - f.centre[k] for k in range(3)]
            for j, e in enumerate((screen_x, screen_y)):
                lo[j], hi[j] = min(lo[j], dot(d, e)), max(hi[j], dot(d, e))
        half_height = max(half_height, 0.5 * (hi[1] - lo[1]), 0.5 * (hi[0] - lo[0]) / aspect)
        mid = [0.5 * (lo[j] + hi[j]) for j in range(2)]
        focal_points.append([f.centre[k] + mid[0] * screen_x[k] + mid[1] * screen_y[k] for k in range(3)])
    parallel_scale = 1.08 * half_height

    # paraview.simple.Render resets the camera on its first call: have that
    # happen before the camera is placed
    Render(view)

    written = []
    for (requested, t, f, rotation, axis_points, el_points), focal in zip(placed, focal_points):
        for s in slices:
            s.SliceType.Origin = f.centre

        axis_line.Point1 = axis_points[0]
        axis_line.Point2 = axis_points[1]
        axis_tip.Height = tip_height
        axis_tip.Radius = 0.035 * extent
        axis_tip.Direction = rotation
        axis_tip.Center = [axis_points[1][k] + 0.5 * tip_height * rotation[k] for k in range(3)]

        if elongation is not None:
            if el_points is not None:
                elongation.Point1, elongation.Point2 = el_points
            else:
                elongation.Point1 = elongation.Point2 = f.centre

        label.Text = "t = %.4g" % t

        view.CameraFocalPoint = focal
        view.CameraPosition = [focal[k] + 4.0 * extent * direction[k] for k in range(3)]
        view.CameraViewUp = up
        view.CameraParallelScale = parallel_scale
        view.ViewTime = t

        Render(view)
        filename = "%s_t%g.png" % (args.output, requested)
        SaveScreenshot(filename, view, ImageResolution=list(args.resolution))
        written.append(filename)
        print("%s: wrote %s (t = %g)" % (PROG, filename, t))

    return written


if __name__ == "__main__":
    main()
