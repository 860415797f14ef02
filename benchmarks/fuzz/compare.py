#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Before/after comparison of the parameter fuzzer (see README.md here, section "Before and after").

Reads results.csv (the cases measured with the current code) and before_after.csv (the same cases replayed with
an older build by `fuzz.py --replay`) and prints, case by case:

  - the outcome counts before and after,
  - the changes grouped by (old outcome -> new outcome), where an old FAIL is split by its kind (stack trace,
    solver dump, crash, several lines, ...) and a case whose entry the old build does not declare is counted
    separately ("entry unknown to the old build"),
  - the notable cases (every old FAIL but deal.II's one-line pattern message, every stopped and timeout, every
    refused -> run, every case of flow/Re and time stepping/time step) with the old and the new first line.

Usage: compare.py [--results results.csv] [--before-after before_after.csv] [--old-binary OLD/build/fluid_surface]
                  [--list all|changed|notable] [--width 150]
With --old-binary, the entries unknown to the old build are taken from its --print-parameters; otherwise from the
old message (deal.II's "No entry with name ... was declared").
"""
import argparse
import collections
import csv
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fuzz  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))

# Cases named in issue 15's closing note (entry, value); every value of these entries is listed too.
NOTABLE = [("flow/Re", None), ("time stepping/time step", None), ("time stepping/end time", "0")]


def old_entries(binary):
    """The entry paths the binary's --print-parameters lists (fuzz.py's parser)."""
    return {path for path, _, _ in fuzz.read_entries(binary)}


def fail_kind(row):
    """A short name of what an old FAIL looked like (from its exit status and first message line)."""
    status, first = row["before: exit status"], row["before: first line of the message"]
    if status.startswith("-"):
        return "FAIL (signal %s)" % status[1:]
    if "An error occurred in line" in first or first.startswith("---") or "Exception" in first:
        return "FAIL (exit %s, deal.II exception)" % status
    if status == "2" and "for the entry named" in first:
        # deal.II's pattern message: one line with file and line, but the bare entry name (no subsection)
        return "FAIL (exit 2, pattern message, bare name)"
    if first.startswith("Amesos") or "INFOG(" in first:
        return "FAIL (exit %s, solver dump)" % status
    if status == "2":
        return "FAIL (exit 2, entry not named)"
    if status == "1" and first.startswith("fluid_surface: error: "):
        return "FAIL (exit 1, error line; no summary)"   # checked by hand: one line, no summary file
    if status == "0":
        return "FAIL (exit 0 with a dump)"
    return "FAIL (exit %s)" % status


def old_label(row, unknown):
    if row["entry"] in unknown:
        return "entry unknown to the old build"
    o = row["before: outcome"]
    return fail_kind(row) if o == "FAIL" else o


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--results", default=os.path.join(HERE, "results.csv"))
    p.add_argument("--before-after", default=os.path.join(HERE, "before_after.csv"))
    p.add_argument("--old-binary", default="")
    p.add_argument("--list", default="notable", choices=["all", "changed", "notable", "none"])
    p.add_argument("--width", type=int, default=150)
    args = p.parse_args()

    with open(args.results) as f:
        after = list(csv.DictReader(f))
    with open(args.before_after) as f:
        both = list(csv.DictReader(f))

    # Match by (scene, entry, value) and occurrence (a few values occur twice for one entry, e.g. 0 and a bound 0).
    def keyed(rows):
        seen, out = collections.Counter(), {}
        for r in rows:
            k = (r["scene"], r["entry"], r["value"])
            out[k + (seen[k],)] = r
            seen[k] += 1
        return out
    a, b = keyed(after), keyed(both)
    missing = [k for k in a if k not in b]
    for k, r in b.items():   # the new outcome of before_after.csv is a copy of results.csv's
        if k in a and a[k]["outcome"] != r["outcome"]:
            print("warning: %s: outcome %s in results.csv, %s in before_after.csv" % (k, a[k]["outcome"],
                                                                                      r["outcome"]))

    if args.old_binary:
        unknown = {r["entry"] for r in both} - old_entries(args.old_binary)
    else:
        unknown = {r["entry"] for r in both
                   if re.search(r"No entry with name|was not declared|is not declared|undeclared",
                                r["before: first line of the message"])}

    rows = [b[k] for k in a if k in b]
    print("cases in results.csv: %d; replayed: %d; not replayed: %d" % (len(a), len(rows), len(missing)))
    if unknown:
        n = sum(1 for r in rows if r["entry"] in unknown)
        print("entries unknown to the old build: %d (%d cases): %s" % (len(unknown), n, ", ".join(sorted(unknown))))

    before = collections.Counter(old_label(r, unknown) for r in rows)
    now = collections.Counter(r["outcome"] for r in rows)
    print("\noutcome counts (old build | current code), replayed cases only")
    for o in sorted(set(before) | set(now) | {"run", "refused"}, key=lambda s: (s.startswith("entry"), s)):
        print("  %-45s %5d | %5d" % (o, before.get(o, 0), now.get(o, 0)))
    n_fail = sum(v for k, v in before.items() if k.startswith("FAIL"))
    print("  %-45s %5d | %5d" % ("FAIL (all kinds)", n_fail, now.get("FAIL", 0)))

    trans = collections.Counter((old_label(r, unknown), r["outcome"]) for r in rows)
    changed = [r for r in rows if r["entry"] not in unknown and r["before: outcome"] != r["outcome"]]
    print("\nchanges (old -> new): %d of %d cases changed outcome (not counting %d with an entry unknown to the "
          "old build)" % (len(changed), len(rows) - sum(1 for r in rows if r["entry"] in unknown),
                          sum(1 for r in rows if r["entry"] in unknown)))
    for (o, n), c in sorted(trans.items(), key=lambda kv: (-kv[1], kv[0])):
        mark = "" if o.split(" (")[0] == n.split(" (")[0] and o == n else "  *"
        if o == "entry unknown to the old build":
            mark = "  (unknown)"
        elif o == n:
            mark = "  (unchanged)"
        print("  %-45s -> %-33s %5d%s" % (o, n, c, mark))

    print("\nchanged, by entry (old -> new: cases)")
    by_entry = collections.defaultdict(collections.Counter)
    for r in changed:
        by_entry[r["entry"]][(old_label(r, unknown), r["outcome"])] += 1
    for e in sorted(by_entry):
        print("  %-50s %s" % (e, "; ".join("%s -> %s: %d" % (o, n, c) for (o, n), c in sorted(by_entry[e].items()))))

    def hostile(r):
        return any(x.strip().lower() in ("nan", "inf", "-inf", "1e400") for x in r["value"].split(","))

    h = collections.Counter((old_label(r, unknown), r["outcome"]) for r in rows if hostile(r))
    print("\nvalues nan, inf, -inf, 1e400 (alone or as a list item): %s" % "; ".join(
        "%s -> %s: %d" % (o, n, c) for (o, n), c in sorted(h.items())))

    def notable(r):
        """Every old FAIL except deal.II's one-line pattern message, every old or new stopped/timeout, every
        refused -> run, and every case of the entries of NOTABLE."""
        if r["entry"] in unknown:
            return False
        old = old_label(r, unknown)
        if old not in ("run", "refused", "FAIL (exit 2, pattern message, bare name)"):
            return True
        if r["outcome"] not in ("run", "refused") or (old.startswith("refused") and r["outcome"] == "run"):
            return True
        return any(r["entry"] == e and (v is None or r["value"] == v) for e, v in NOTABLE)

    chosen = {"all": rows, "changed": changed, "notable": [r for r in rows if notable(r)], "none": []}[args.list]
    if chosen:
        print("\n%s cases: scene | entry = value | old: exit, outcome, first line | new: exit, outcome, first line"
              % args.list)
    w = args.width
    for r in chosen:
        print("- %s | %s = %r\n    old: exit %s, %s, %.1f s: %s\n    new: exit %s, %s: %s" % (
            r["scene"], r["entry"], r["value"], r["before: exit status"], old_label(r, unknown),
            float(r["before: seconds"]), r["before: first line of the message"][:w], r["exit status"], r["outcome"],
            r["first line of the message"][:w]))
    if missing:
        print("\nnot replayed (%d): %s" % (len(missing), "; ".join("%s %s = %r" % k[:3] for k in missing[:50])
                                          + (" ..." if len(missing) > 50 else "")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
