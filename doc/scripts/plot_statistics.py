#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Plot the diagnostics of a fluid_surface run as panels [B]-[F] of the seed's
Figures 1-2 (Nestler & Voigt, section 3) in one PNG.

Usage
-----
    /usr/bin/python3 doc/scripts/plot_statistics.py RESULTS_DIR/statistics \\
        [-o figure.png] [--summary RESULTS_DIR/summary] [--window t0 t1] \\
        [--marks t ...]

Needs python3-matplotlib (Debian: ``apt-get install -y python3-matplotlib``);
the Agg backend is used, so no display is required.

Input
-----
``statistics`` as written by the program (doc/output.md): ``# N: name``
header lines followed by whitespace-separated rows.  Columns are looked up by
*name*, never by position.  A partial last line (a run that is still writing)
and other malformed rows are skipped with a note on stderr.  If the time goes
backwards (a resumed run appended to the file) the later rows replace the
earlier ones from that time on.

Panels
------
[B] total energy F with F_kin and F_bend;
[C] angular velocity omega(t), F_kin scaled affinely onto omega's range, and
    <omega> as a horizontal line: taken from 'mean angular velocity' in the
    summary file if --summary is given (and holds a number), otherwise
    computed from the statistics over --window (default 5 10) by the
    program's rectangle rule (each step covers (t - tau, t]);
[D] inertia eigenvalues lambda_1 <= lambda_2 <= lambda_3 with F_bend scaled
    affinely onto the eigenvalues' range;
[E] symmetry deviation e(lambda) (log axis), thresholds 1e-4 (solid) and
    1e-2 (dashed), first crossing times (first row with e > threshold, the
    program's rule) marked by vertical lines;
[F] 'L2 distance to equilibrium' (log axis) if the column exists, otherwise
    the rigid fraction (left axis) and the tilt angle in degrees (right axis).
A sixth cell lists the final values.  --marks t ... puts red diamonds at
these times on every panel (the seed marks its snapshot times so).

Without -o the figure is written next to the statistics file as
``statistics.png``.  The title is --title, else the run's name: the results
directory relative to the working directory (e.g. ``results/prolate``), or its
last two path components when it lies elsewhere; never an absolute path.
"""

import argparse
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

PROG = os.path.basename(sys.argv[0]) if sys.argv and sys.argv[0] else "plot_statistics.py"
HEADER = re.compile(r"^#\s*(\d+)\s*:\s*(.*?)\s*$")

T_KIN = "kinetic energy"
T_BEND = "bending energy"
T_TOTAL = "total energy"
OMEGA = "angular velocity"
EIGEN = ["inertia eigenvalue 1", "inertia eigenvalue 2", "inertia eigenvalue 3"]
SYM = "symmetry deviation"
L2 = "L2 distance to equilibrium"
RIGID = "rigid fraction"
TILT = "tilt angle"


def fail(message):
    sys.exit("%s: error: %s" % (PROG, message))


def note(message):
    print("%s: %s" % (PROG, message), file=sys.stderr)


def read_statistics(path):
    """Return ({name: np.array}, n_skipped, last_line_partial)."""
    if not os.path.isfile(path):
        fail("statistics file '%s' not found" % path)
    with open(path, "r", encoding="utf-8", errors="replace") as f:
        text = f.read()
    lines = text.split("\n")
    # A file that does not end in a newline is being written: its last line
    # may be cut anywhere.
    last_partial = not text.endswith("\n") and lines[-1].strip() != ""
    if text.endswith("\n"):
        lines = lines[:-1]

    columns = {}
    rows = []
    skipped = 0
    for number, line in enumerate(lines):
        stripped = line.strip()
        if not stripped:
            continue
        if stripped.startswith("#"):
            m = HEADER.match(stripped)
            if m:
                columns[m.group(2)] = int(m.group(1)) - 1
            continue
        is_last = number == len(lines) - 1
        if is_last and last_partial:
            skipped += 1
            continue
        fields = stripped.split()
        if columns and len(fields) != max(columns.values()) + 1:
            skipped += 1
            continue
        try:
            rows.append([float(x) for x in fields])
        except ValueError:
            skipped += 1
    if not columns:
        fail("'%s' has no '# N: name' header lines; is it a fluid_surface statistics file?" % path)
    if "time" not in columns:
        fail("'%s' has no column named 'time'" % path)
    if not rows:
        fail("'%s' has no complete data rows (yet)" % path)

    data = np.array(rows)
    # A resumed run appends rows starting again at an earlier time: keep the
    # later rows, drop earlier ones from that time on.
    t = data[:, columns["time"]]
    keep = np.ones(len(t), dtype=bool)
    for i in range(1, len(t)):
        if t[i] < t[i - 1]:
            keep[:i] &= t[:i] < t[i]
    data = data[keep]
    return {name: data[:, index] for name, index in columns.items()}, skipped, last_partial


def read_summary(path):
    """Return {key: value string} of a 'key: value' summary file."""
    if not os.path.isfile(path):
        fail("summary file '%s' not found" % path)
    values = {}
    with open(path, "r", encoding="utf-8", errors="replace") as f:
        for line in f:
            if ":" in line:
                key, value = line.split(":", 1)
                values[key.strip()] = value.strip()
    return values


def to_float(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def window_mean(stats, t0, t1):
    """<omega> over [t0, t1] by the program's rectangle rule; None if no overlap."""
    t = stats["time"]
    omega = stats[OMEGA]
    if "tau" in stats:
        tau = stats["tau"]
    else:
        tau = np.concatenate(([0.0], np.diff(t)))
    start = np.maximum(t - tau, t0)
    end = np.minimum(t, t1)
    overlap = np.where((tau > 0) & (end > start), end - start, 0.0)
    total = overlap.sum()
    if total <= 0:
        return None
    return float((omega * overlap).sum() / total)


def first_crossing(t, e, threshold):
    above = np.nonzero(e > threshold)[0]
    return float(t[above[0]]) if len(above) else None


def positive(values):
    """Values for a log axis: non-positive entries become gaps."""
    return np.where(values > 0, values, np.nan)


def scale_onto(values, target):
    """Affine map of values onto [min(target), max(target)]."""
    lo, hi = np.nanmin(values), np.nanmax(values)
    tlo, thi = np.nanmin(target), np.nanmax(target)
    if hi > lo and thi > tlo:
        return tlo + (values - lo) * (thi - tlo) / (hi - lo)
    if hi > 0:  # constant data: proportional scaling onto the target's maximum
        return values * (thi / hi)
    return values


def missing(ax, names):
    ax.text(0.5, 0.5, "column(s) not in file:\n" + "\n".join("'%s'" % n for n in names),
            ha="center", va="center", transform=ax.transAxes, color="0.4")


def mark(ax, t, y, marks, log=False):
    """Red diamonds at the --marks times, interpolated in the curve (t, y)."""
    for tm in marks:
        if t[0] <= tm <= t[-1]:
            ym = np.interp(tm, t, np.log(y) if log else y)
            ax.plot(tm, math.exp(ym) if log else ym, "D", color="red", ms=6, zorder=5)


def run_name(statistics_path):
    """The run's name for the title: the directory of the statistics file relative to the working
    directory (e.g. 'results/prolate'); the directory's own name when it is the working directory; its
    last two components when it lies outside the working directory."""
    directory = os.path.dirname(os.path.abspath(statistics_path))
    relative = os.path.relpath(directory)
    if relative == ".":
        return os.path.basename(directory) or "statistics"
    if relative == ".." or relative.startswith(".." + os.sep):
        return os.path.join(*directory.split(os.sep)[-2:]) or "statistics"
    return relative


def fmt(x):
    return "n/a" if x is None or not np.isfinite(x) else "%.6g" % x


def main():
    parser = argparse.ArgumentParser(
        description="Plot a fluid_surface statistics file as the seed's panels [B]-[F].")
    parser.add_argument("statistics", help="RESULTS_DIR/statistics")
    parser.add_argument("-o", "--output", help="PNG to write (default: next to the statistics file)")
    parser.add_argument("--summary", help="RESULTS_DIR/summary; its 'mean angular velocity' is used for <omega>")
    parser.add_argument("--window", nargs=2, type=float, metavar=("T0", "T1"), default=None,
                        help="window of <omega> computed from the statistics (default 5 10)")
    parser.add_argument("--marks", nargs="+", type=float, default=[], metavar="T",
                        help="times marked by red diamonds (e.g. the snapshot times)")
    parser.add_argument("--title", help="figure title (default: the run's name, the results directory "
                        "relative to the working directory)")
    args = parser.parse_args()

    stats, skipped, last_partial = read_statistics(args.statistics)
    t = stats["time"]
    n = len(t)
    if skipped:
        note("skipped %d incomplete or malformed row(s)%s" %
             (skipped, " (the last line is partial: live run?)" if last_partial else ""))

    # <omega>: summary if given and numeric, else computed over the window.
    window = tuple(args.window) if args.window else (5.0, 10.0)
    mean_omega, mean_source = None, None
    if args.summary:
        summary = read_summary(args.summary)
        mean_omega = to_float(summary.get("mean angular velocity"))
        if mean_omega is not None:
            mean_source = "summary"
            if args.window:
                note("--summary given: <omega> is taken from it, --window is ignored")
        else:
            note("summary has no numeric 'mean angular velocity' (%s); computing it over [%g, %g]"
                 % (summary.get("mean angular velocity", "missing"), window[0], window[1]))
    if mean_omega is None and OMEGA in stats:
        mean_omega = window_mean(stats, *window)
        mean_source = "window"

    fig, axes = plt.subplots(2, 3, figsize=(16, 9.5))
    axB, axC, axD, axE, axF, axS = axes.ravel()
    for ax in (axB, axC, axD, axE, axF):
        ax.set_xlabel("time $t$")
        ax.grid(True, which="major", alpha=0.3)
        ax.set_xlim(t[0], t[-1] if t[-1] > t[0] else t[0] + 1)

    # [B] energies
    axB.set_title("[B] free energy")
    have = [c for c in (T_TOTAL, T_KIN, T_BEND) if c in stats]
    if have:
        style = {T_TOTAL: ("k", "$F = F_\\mathrm{kin} + F_\\mathrm{bend}$", 2.0),
                 T_KIN: ("tab:blue", "$F_\\mathrm{kin}$", 1.3),
                 T_BEND: ("tab:orange", "$F_\\mathrm{bend}$", 1.3)}
        for c in have:
            color, label, lw = style[c]
            axB.plot(t, stats[c], color=color, lw=lw, label=label)
        if T_TOTAL in stats:
            mark(axB, t, stats[T_TOTAL], args.marks)
        axB.set_ylabel("energy")
        axB.legend(loc="best", fontsize=9)
    if len(have) < 3:
        missing(axB, [c for c in (T_TOTAL, T_KIN, T_BEND) if c not in stats])

    # [C] angular velocity
    axC.set_title("[C] angular velocity about $z$")
    if OMEGA in stats:
        omega = stats[OMEGA]
        axC.plot(t, omega, color="tab:blue", lw=1.8, label="$\\omega(t)$")
        if T_KIN in stats:
            axC.plot(t, scale_onto(stats[T_KIN], omega), color="k", lw=1.0,
                     label="$F_\\mathrm{kin}$ (scaled to the range of $\\omega$)")
        if mean_omega is not None:
            where = ("summary" if mean_source == "summary"
                     else "$t \\in [%g, %g]$" % window)
            axC.axhline(mean_omega, color="tab:green", ls="--", lw=1.3,
                        label="$\\langle\\omega\\rangle = %.4g$ (%s)" % (mean_omega, where))
            if mean_source == "window":
                axC.axvspan(max(window[0], t[0]), min(window[1], t[-1]), color="tab:green", alpha=0.08)
        else:
            axC.plot([], [], " ", label="$\\langle\\omega\\rangle$: n/a (run ends before $t = %g$)" % window[0])
        mark(axC, t, omega, args.marks)
        axC.set_ylabel("$\\omega$")
        axC.legend(loc="best", fontsize=9)
    else:
        missing(axC, [OMEGA])

    # [D] inertia eigenvalues
    axD.set_title("[D] eigenvalues of the inertia tensor")
    if all(c in stats for c in EIGEN):
        lam = np.vstack([stats[c] for c in EIGEN])
        # lambda_2 = lambda_3 (or lambda_1 = lambda_2) for an axisymmetric
        # surface: draw lambda_2 wide and lambda_3 dashed so both stay visible
        for i, (c, ls, lw) in enumerate((("tab:blue", "-", 1.6), ("tab:orange", "-", 3.2),
                                         ("tab:green", "--", 1.6))):
            axD.plot(t, lam[i], color=c, ls=ls, lw=lw, label="$\\lambda_%d$" % (i + 1))
            mark(axD, t, lam[i], args.marks)
        if T_BEND in stats:
            axD.plot(t, scale_onto(stats[T_BEND], lam), color="k", lw=1.0,
                     label="$F_\\mathrm{bend}$ (scaled to the range of $\\lambda$)")
        axD.set_ylabel("$\\lambda_1 \\leq \\lambda_2 \\leq \\lambda_3$")
        axD.legend(loc="best", fontsize=9)
    else:
        missing(axD, [c for c in EIGEN if c not in stats])

    # [E] symmetry deviation
    axE.set_title("[E] deviation from rotational symmetry")
    crossings = {}
    if SYM in stats:
        e = stats[SYM]
        axE.semilogy(t, positive(e), color="tab:blue", lw=1.6, label="$e(\\lambda)$")
        for threshold, ls in ((1e-4, "-"), (1e-2, "--")):
            tc = first_crossing(t, e, threshold)
            crossings[threshold] = tc
            name = "t_{10^{%d}}" % round(math.log10(threshold))
            text = ("$%s = %.4g$" % (name, tc)) if tc is not None else ("$%s$: not crossed" % name)
            axE.axhline(threshold, color="k", ls=ls, lw=1.0,
                        label="$e = 10^{%d}$,  %s" % (round(math.log10(threshold)), text))
            if tc is not None:
                axE.axvline(tc, color="tab:red", ls=ls, lw=0.9)
        # keep both thresholds in view
        finite = e[e > 0]
        lo = min(np.nanmin(finite) if len(finite) else 1e-5, 1e-5)
        hi = max(np.nanmax(finite) if len(finite) else 1e-1, 1e-1)
        axE.set_ylim(lo / 3, hi * 3)
        mark(axE, t, np.where(e > 0, e, lo), args.marks, log=True)
        axE.set_ylabel("$e(\\lambda) = |\\lambda_a - \\lambda_b| / \\langle\\lambda\\rangle$")
        axE.legend(loc="best", fontsize=9)
    else:
        missing(axE, [SYM])

    # [F] L2 distance, or rigid fraction and tilt angle
    if L2 in stats and np.any(stats[L2] > 0):
        axF.set_title("[F] $L^2$ distance to the rotating equilibrium")
        axF.semilogy(t, positive(stats[L2]), color="tab:blue", lw=1.6, label="$E(L^2)$")
        mark(axF, t, np.where(stats[L2] > 0, stats[L2], np.nan), args.marks, log=True)
        axF.set_ylabel("$E(L^2)$")
        axF.legend(loc="best", fontsize=9)
    else:
        axF.set_title("[F] rigid fraction and tilt angle (no $E(L^2)$ column)")
        if RIGID in stats:
            axF.plot(t, stats[RIGID], color="tab:blue", lw=1.6,
                     label="rigid fraction $\\frac{1}{2}\\Omega\\cdot L / F_\\mathrm{kin}$")
            mark(axF, t, stats[RIGID], args.marks)
            axF.set_ylabel("rigid fraction $\\frac{1}{2}\\Omega\\cdot L / F_\\mathrm{kin}$", color="tab:blue")
            axF.set_ylim(min(0.0, np.nanmin(stats[RIGID])), max(1.05, np.nanmax(stats[RIGID]) * 1.05))
        if TILT in stats:
            axT = axF.twinx()
            axT.plot(t, stats[TILT], color="tab:red", lw=1.3,
                     label="tilt angle $\\angle(\\Omega, \\mathrm{elongation\\ axis})$")
            axT.set_ylabel("tilt angle $\\angle(\\Omega, \\mathbf{a})$ [deg]", color="tab:red")
            axT.set_ylim(-3, 95)
            axT.set_yticks([0, 15, 30, 45, 60, 75, 90])
            h1, l1 = axF.get_legend_handles_labels()
            h2, l2 = axT.get_legend_handles_labels()
            axF.legend(h1 + h2, l1 + l2, loc="center right", fontsize=9)
        elif RIGID in stats:
            axF.legend(loc="best", fontsize=9)
        if RIGID not in stats and TILT not in stats:
            missing(axF, [L2, RIGID, TILT])

    # summary cell
    axS.axis("off")
    last = n - 1

    def final(name):
        return fmt(stats[name][last]) if name in stats else "n/a"

    lines = ["final row: step %s,  $t$ = %s%s" % (final("time step"), fmt(t[last]),
                                                 "  (live run: partial last line skipped)" if last_partial else ""),
             "$F$ = %s   ($F_\\mathrm{kin}$ = %s,  $F_\\mathrm{bend}$ = %s)" % (final(T_TOTAL), final(T_KIN), final(T_BEND)),
             "$\\omega$ = %s,   $\\langle\\omega\\rangle$ = %s %s" % (
                 final(OMEGA), fmt(mean_omega),
                 "(summary)" if mean_source == "summary" else "over $t \\in [%g, %g]$" % window),
             "$\\lambda_{1,2,3}$ = %s, %s, %s" % tuple(final(c) for c in EIGEN),
             "$e(\\lambda)$ = %s;   $t_{10^{-4}}$ = %s,   $t_{10^{-2}}$ = %s" % (
                 final(SYM), fmt(crossings.get(1e-4)) if 1e-4 in crossings else "n/a",
                 fmt(crossings.get(1e-2)) if 1e-2 in crossings else "n/a"),
             "rigid fraction = %s,   tilt angle = %s deg" % (final(RIGID), final(TILT))]
    if SYM in stats:
        lines[4] = lines[4].replace("= n/a", "= never")
    if L2 in stats:
        lines.append("$E(L^2)$ = %s" % final(L2))
    for name, label in (("reduced volume", "reduced volume"), ("mesh quality", "mesh quality")):
        if name in stats:
            lines.append("%s = %s" % (label, final(name)))
    lines.append("%d rows, $t \\in$ [%s, %s]" % (n, fmt(t[0]), fmt(t[last])))
    axS.text(0.0, 0.95, "\n".join(lines), va="top", ha="left", fontsize=10.5,
             transform=axS.transAxes, linespacing=1.7)

    title = args.title or run_name(args.statistics)
    fig.suptitle(title, fontsize=12)
    fig.tight_layout(rect=(0, 0, 1, 0.97))

    output = args.output or os.path.join(os.path.dirname(os.path.abspath(args.statistics)), "statistics.png")
    directory = os.path.dirname(os.path.abspath(output))
    if not os.path.isdir(directory):
        fail("output directory '%s' does not exist" % directory)
    fig.savefig(output, dpi=110)
    print("wrote %s (%d rows, t in [%g, %g])" % (output, n, t[0], t[last]))


if __name__ == "__main__":
    main()
