#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Parameter fuzzer of fluid_surface (see README.md in this directory).

For every entry that `fluid_surface --print-parameters` lists, boundary and hostile values are derived from its
pattern and applied, one at a time, to short coarse runs of the scenes that use the entry (and to
`--equilibrium` for subsection equilibrium). Each case is classified:

  run       exit 0
  refused   exit 2, one message that names the entry
  stopped   exit 1, one line `fluid_surface: error: ...` (a valid run that stopped early, explained; for scene
            full the summary's first line is `status: stopped at t = ...`)
  timeout   still running after --timeout seconds (a valid but long run)
  FAIL      anything else: exit 2 without the entry's name, exit 1 with a multi-line message, a solver dump or
            a stack trace, a crash (signal), a summary missing after a stop

Usage: fuzz.py --binary build/fluid_surface --source . --work DIR --results results.csv [--timeout 30]
               [--only SUBSTRING] [--quick]
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import time

# ------------------------------------------------------------------ the entries


def read_entries(binary):
    """(path, default, pattern) of every entry of --print-parameters."""
    text = subprocess.run([binary, "--print-parameters"], capture_output=True, text=True, check=True).stdout
    entries, path, pattern = [], [], None
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("subsection "):
            path.append(s[len("subsection "):])
        elif s == "end":
            path.pop()
        elif s.startswith("# Pattern:"):
            pattern = s[len("# Pattern:"):].strip()
        elif s.startswith("#") and pattern is not None:
            pattern += " " + s[1:].strip()
        elif s.startswith("set "):
            name, _, value = s[4:].partition(" =")
            entries.append(("/".join(path + [name.strip()]), value.strip(), pattern))
            pattern = None
    return entries


# ------------------------------------------------------------------ values from a pattern

TINY, HUGE = "1e-300", "1e300"
HOSTILE_NUMBERS = ["0", "-1", TINY, HUGE, "-" + HUGE, "nan", "inf", "-inf", "", "abc", "1 2", "1e400"]


def fmt(x):
    return "%.10g" % x


def real_range(pattern):
    """(lower, lower_closed, upper, upper_closed) of a '[Finite number x with ...]' pattern."""
    inf = math.inf
    m = re.search(r"Finite number x with (.*)\]", pattern)
    if not m:
        return (-inf, False, inf, False)
    cond = m.group(1).replace("−", "-")
    m2 = re.fullmatch(r"(\S+) (<|≤) x (<|≤) (\S+)", cond)
    if m2:
        return (float(m2.group(1)), m2.group(2) == "≤", float(m2.group(4)), m2.group(3) == "≤")
    m2 = re.fullmatch(r"x (>|≥) (\S+)", cond)
    if m2:
        return (float(m2.group(2)), m2.group(1) == "≥", inf, False)
    m2 = re.fullmatch(r"x (<|≤) (\S+)", cond)
    if m2:
        return (-inf, False, float(m2.group(2)), m2.group(1) == "≤")
    raise ValueError("unknown range " + cond)


def outside(bound, direction):
    """A number just beyond @p bound (direction -1: below, +1: above)."""
    step = max(abs(bound) * 1e-6, 1e-9)
    return bound + direction * step


def real_values(pattern):
    lo, lo_closed, hi, hi_closed = real_range(pattern)
    values = list(HOSTILE_NUMBERS)
    if math.isfinite(lo):
        values += [fmt(lo), "%.10g" % outside(lo, -1)]
    if math.isfinite(hi):
        values += [fmt(hi), "%.10g" % outside(hi, +1)]
    return values


def integer_values(pattern):
    m = re.search(r"Integer range (-?\d+)\.\.\.(-?\d+)", pattern)
    lo, hi = int(m.group(1)), int(m.group(2))
    values = ["0", "-1", str(lo), str(lo - 1), str(hi), "1.5", "1e3", "nan", "", "abc", "99999999999999999999"]
    if hi < 2**31 - 1:
        values.append(str(hi + 1))
    return values


def list_values(pattern, default):
    m = re.search(r"List of <(.*)> of length (\d+)\.\.\.(\d+)", pattern)
    inner, n_min, n_max = m.group(1), int(m.group(2)), int(m.group(3))
    n = max(n_max, 1)
    items = [x.strip() for x in default.split(",") if x.strip()] or ["1"] * n
    if len(items) < n:
        items = (items * n)[:n]
    values = ["", "abc", ", ".join(items[:n]) + ", " + items[0] if n_max > 0 else "1"]
    if n_min > 0:
        values.append(", ".join(items[: n_min - 1]))          # one too few
    for v in real_values(inner) if "Finite" in inner else ["nan", "inf", "0", "-1"]:
        if v in ("", "1 2"):
            continue
        values.append(", ".join([v] * n))                     # every component
        if n > 1:
            values.append(", ".join([v] + items[1:n]))        # the first component only
    return values


def selection_values(pattern):
    options = [o.strip() for o in re.search(r"Selection (.*)\]", pattern).group(1).split("|")]
    return options + ["", "abc", options[0].upper()]


def quick_values(pattern, default, path):
    """--quick: at most two values per entry besides its default (which every entry runs first, to see whether the
    scene uses it): a range's lower bound and the value just below it (the upper bound and just above where there is
    no lower one; 0 and nan for a real without bounds), a selection's other options, a bool's other value, a list's
    first two values; file and directory names as in the full run."""
    if pattern.startswith("[Finite"):
        bounds = real_values(pattern)[len(HOSTILE_NUMBERS):]
        return bounds[:2] or ["0", "nan"]
    if pattern.startswith("[Integer"):
        return integer_values(pattern)[2:4]  # lo, lo − 1
    if pattern.startswith("[List"):
        return list_values(pattern, default)[:2]
    if pattern.startswith("[Selection"):
        return [o for o in selection_values(pattern)[:-3] if o != default]
    if pattern.startswith("[Bool"):
        return ["false" if default == "true" else "true"]
    return values_for(pattern, default, path)


def values_for(pattern, default, path):
    if pattern.startswith("[Finite"):
        return real_values(pattern)
    if pattern.startswith("[Integer"):
        return integer_values(pattern)
    if pattern.startswith("[List"):
        return list_values(pattern, default)
    if pattern.startswith("[Selection"):
        return selection_values(pattern)
    if pattern.startswith("[Bool"):
        return ["true", "false", "", "abc", "1", "yes"]
    if pattern.startswith("[FileName"):
        return ["", "does/not/exist.msh", "not_a_mesh.txt", ".", "no_such_dir/x.csv"]
    if pattern.startswith("[DirectoryName"):
        return ["", "output", "a_file/sub", "fuzz out dir"]
    return ["", "abc"]


# ------------------------------------------------------------------ the scenes

def base_scenes(source):
    out = {"output/overwrite": "true", "output/write vtu": "false", "output/report wall time": "false",
           "output/screen interval": "1000"}
    mesh = os.path.join(source, "meshes/ellipsoid.msh")
    full = {"model/scene": "full", "geometry/shape": "ellipsoid", "geometry/semi-axes": "0.61, 0.61, 2.02",
            "geometry/mesh file": mesh,
            "geometry/refinement": "1", "initial state/angular velocity": "4", "time stepping/end time": "0.03",
            "time stepping/time step": "0.01", **out}
    return {
        "geometry": {"model/scene": "geometry", "geometry/refinement": "1", "geometry/mesh file": mesh, **out},
        "geometry_mesh": {"model/scene": "geometry", "geometry/shape": "mesh file",
                          "geometry/mesh file": mesh,
                          "geometry/refinement": "0", **out},
        "fixed_stationary": {"model/scene": "fixed surface", "geometry/shape": "sphere",
                             "geometry/refinement": "1", **out},
        "fixed_decay": {"model/scene": "fixed surface", "geometry/shape": "sphere", "geometry/refinement": "1",
                        "fixed surface/problem": "decaying mode", "time stepping/end time": "0.04",
                        "time stepping/time step": "0.02", **out},
        "full": full,
        "full_stokes": {**full, "flow/inertia": "false", "initial state/angular velocity": "0",
                        "time stepping/end time": "0.02"},
        "full_equilibrium": {**full, "geometry/shape": "equilibrium", "equilibrium/area": "12.60350439",
                             "equilibrium/reduced volume": "0.7483226", "equilibrium/angular momentum": "13.77329728",
                             "initial state/equilibrium rotation": "true", "initial state/angular velocity": "0",
                             "flow/conserve momenta": "true", "diagnostics/reference equilibrium": "prolate",
                             "time stepping/end time": "0.02"},
        "equilibrium": {"equilibrium/area": "12.60350439", "equilibrium/reduced volume": "0.7483226",
                        "equilibrium/angular momentum": "13.77329728", "equilibrium/output file": "equilibrium.csv"},
    }


def scenes_of(path):
    """The scenes whose runs an entry is applied to (those that do not use it are skipped at run time)."""
    section = path.split("/")[0]
    if path in ("geometry/mesh file", "geometry/project onto ellipsoid"):
        return ["geometry_mesh"]
    if path == "model/scene":
        return ["geometry"]
    return {
        "geometry": ["geometry", "full"],
        "equilibrium": ["equilibrium", "full_equilibrium"],
        "flow": ["fixed_decay", "full", "full_stokes"],
        "fixed surface": ["fixed_stationary", "fixed_decay"],
        "fixed surface solver": ["fixed_stationary", "fixed_decay"],
        "linear solver": ["fixed_decay", "full"],
        "time stepping": ["fixed_decay", "full"],
        "output": ["geometry", "full"],
        "initial state": ["full", "full_equilibrium"] if path == "initial state/equilibrium rotation" else ["full"],
        "diagnostics": ["full_equilibrium"] if path == "diagnostics/reference equilibrium" else ["full"],
    }.get(section, ["full"])


def render(settings):
    """A parameter file setting every "subsection/entry" of @p settings."""
    by_section = {}
    for path, value in settings.items():
        section, _, name = path.rpartition("/")
        by_section.setdefault(section, []).append((name, value))
    lines = []
    for section, items in by_section.items():
        lines.append("subsection " + section)
        lines += ["  set %s = %s" % (name, value) for name, value in items]
        lines.append("end")
    return "\n".join(lines) + "\n"


# ------------------------------------------------------------------ one case

def run_case(binary, work, scene, settings, timeout):
    case_dir = os.path.join(work, "case")
    shutil.rmtree(case_dir, ignore_errors=True)
    os.makedirs(case_dir)
    with open(os.path.join(case_dir, "a_file"), "w") as f:
        f.write("a file, not a directory\n")
    with open(os.path.join(case_dir, "not_a_mesh.txt"), "w") as f:
        f.write("not a mesh\n")
    if scene != "equilibrium" and "output/output directory" not in settings:
        settings = {**settings, "output/output directory": "results_fuzz"}
    prm = os.path.join(case_dir, "case.prm")
    with open(prm, "w") as f:
        f.write(render(settings))
    command = ["nice", "-n", "10", binary] + (["--equilibrium"] if scene == "equilibrium" else []) + ["case.prm"]
    start = time.time()
    try:
        p = subprocess.run(command, cwd=case_dir, capture_output=True, text=True, timeout=timeout,
                           errors="replace")
        status, stdout, stderr = p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired as e:
        status, stdout, stderr = "timeout", "", (e.stderr.decode(errors="replace") if e.stderr else "")
    seconds = time.time() - start
    summary = None
    directory = settings.get("output/output directory", "results_fuzz")
    summary_file = os.path.join(case_dir, directory, "summary")
    if os.path.isfile(summary_file):
        with open(summary_file) as f:
            summary = f.readline().strip()
    return status, seconds, stdout, stderr, summary


def classify(path, scene, status, stderr, summary):
    lines = [l for l in stderr.splitlines() if l.strip()]
    first = lines[0] if lines else ""
    # Traces of a raw solver report or a deal.II exception with its stack trace.
    dump = any(k in stderr for k in ("Amesos_Mumps :", "Amesos_Klu :", "INFOG(", "Stacktrace", "--------",
                                     "An error occurred in line"))
    if status == "timeout":
        return "timeout"
    if status == 0:
        return "run" if not dump else "FAIL"
    if status == 2:
        name = path.split("/")[-1]
        names_entry = path in first or ("'%s'" % name) in first or \
            ("equilibrium/" in first and scene in ("equilibrium", "full_equilibrium") and path.startswith("equilibrium/"))
        if len(lines) != 1 or dump:
            return "FAIL"
        if names_entry:
            return "refused"
        # A relation: the message names the other entry of the pair (e.g. shape = mesh file and its mesh file).
        return "refused (names a related entry)" if re.search(r"entr(y|ies) '[^']+/[^']+'", first) else "FAIL"
    if status == 1:
        explained = len(lines) == 1 and first.startswith("fluid_surface: error: ") and not dump
        if scene.startswith("full"):  # scene full writes its summary also when it stops early
            explained = explained and (summary or "").startswith("status: stopped at t = ")
        return "stopped" if explained else "FAIL"
    return "FAIL"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--results", required=True)
    parser.add_argument("--timeout", type=float, default=30)
    parser.add_argument("--only", default="")
    parser.add_argument("--quick", action="store_true", help="the first scene of each entry only, with the values "
                        "of quick_values()")
    parser.add_argument("--replay", default="", help="run the cases of this results.csv with --binary (e.g. an "
                        "older build) and write them with its outcomes to --results, for a before/after comparison")
    args = parser.parse_args()
    binary, source = os.path.abspath(args.binary), os.path.abspath(args.source)
    os.makedirs(args.work, exist_ok=True)
    if args.replay:
        return replay(binary, source, args)

    entries = read_entries(binary)
    scenes = base_scenes(source)
    rows, counts, applicable, refused_by_pattern = [], {}, {}, set()
    print("%d entries" % len(entries), flush=True)
    for path, default, pattern in entries:
        if args.only and args.only not in path:
            continue
        for scene in scenes_of(path)[:1] if args.quick else scenes_of(path):
            if scene == "equilibrium" and not path.startswith("equilibrium/"):
                continue
            base = scenes[scene]
            # A scene that refuses the entry's default value does not use the entry: skip it.
            status, _, _, stderr, _ = run_case(binary, args.work, scene, {**base, path: base.get(path, default)},
                                               args.timeout)
            if status == 2 and "does not use it" in stderr:
                continue
            applicable.setdefault(path, []).append(scene)
            for value in (quick_values if args.quick else values_for)(pattern, default, path):
                if (path, value) in refused_by_pattern:
                    continue  # the pattern refuses it in every scene alike
                status, seconds, stdout, stderr, summary = run_case(binary, args.work, scene,
                                                                    {**base, path: value}, args.timeout)
                outcome = classify(path, scene, status, stderr, summary)
                first = next((l for l in stderr.splitlines() if l.strip()), "")
                if status == "timeout":
                    first = "(cut after %g s: a valid but long run)" % args.timeout
                elif not first and outcome == "run" and summary:
                    first = "(summary: %s)" % summary
                rows.append([scene, path, value, status, "%.1f" % seconds, outcome, first.replace("\n", " ")])
                if outcome == "refused" and ", line " in first and "expected [" in first:
                    refused_by_pattern.add((path, value))
                counts[outcome] = counts.get(outcome, 0) + 1
                if outcome in ("FAIL", "timeout", "stopped"):
                    print("%-8s %-17s %-45s %-22r exit %-7s %5.1fs %s" % (outcome, scene, path, value, status,
                                                                          seconds, first[:160]), flush=True)
    with open(args.results, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["scene", "entry", "value", "exit status", "seconds", "outcome", "first line of the message"])
        writer.writerows(rows)
    n_entries = len(applicable)
    print("entries fuzzed: %d of %d; cases: %d; %s" % (n_entries, len(entries), len(rows),
          ", ".join("%s %d" % kv for kv in sorted(counts.items()))))
    return 1 if counts.get("FAIL", 0) else 0


def replay(binary, source, args):
    """The cases of an earlier results.csv, run with @p binary; both outcomes side by side."""
    scenes = base_scenes(source)
    with open(args.replay) as f:
        rows = list(csv.reader(f))[1:]
    out = []
    for scene, path, value, status, seconds, outcome, message in rows:
        b_status, b_seconds, _, b_stderr, b_summary = run_case(binary, args.work, scene, {**scenes[scene], path: value},
                                                               args.timeout)
        b_outcome = classify(path, scene, b_status, b_stderr, b_summary)
        b_first = next((l for l in b_stderr.splitlines() if l.strip()), "")
        if b_status == "timeout":
            b_first = "(cut after %g s)" % args.timeout
        out.append([scene, path, value, b_status, "%.1f" % b_seconds, b_outcome, b_first, status, seconds, outcome,
                    message])
        if str(b_status) != str(status):
            print("%-17s %-45s %-22r before: exit %-7s %-8s after: exit %-7s %s" % (scene, path, value, b_status,
                                                                                    b_outcome, status, outcome),
                  flush=True)
    with open(args.results, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["scene", "entry", "value", "before: exit status", "before: seconds", "before: outcome",
                         "before: first line of the message", "exit status", "seconds", "outcome",
                         "first line of the message"])
        writer.writerows(out)
    changed = sum(1 for r in out if str(r[3]) != str(r[7]))
    print("cases replayed: %d; exit status changed in %d" % (len(out), changed))
    return 0


if __name__ == "__main__":
    sys.exit(main())
