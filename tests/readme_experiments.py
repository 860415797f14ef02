#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Checks the README's experiments table against the committed runs it links (ctest: readme_experiments).

The table under "## Experiments" in README.md has a column "key result" and a last column "numbers from" that links
the committed files the row's numbers come from. For every row that links a `.summary` file (`key: value` lines,
doc/output.md), each quantity of the "key result" column that RULES below recognizes by its label is compared with
the summary to the digits the README quotes: "7.8e-15" must be within 0.05e-15 of the summary's value, "3.294145"
within 5e-7, "393" exact. In the same rows:
* the summary's wall time must round to one of the times of the "wall time" column (outside parentheses);
* "F a → b": b is the final energy, a the first `total energy` of a linked `.statistics` file;
* "⟨ω⟩[t0, t1]": the window must be the `diagnostics/angular velocity window` of the row's prm file (if it links one);
* "within X of": X must be the absolute value of a number in a linked `.csv` file, to the digits quoted.
A row that links a summary but in which no rule matches is an error (the check would check nothing). Rows that link
no summary are listed as skipped. Numbers with other labels (the paper's, other runs') are not checked.

Usage: readme_experiments.py SOURCE_DIR
Prints one line per check and exits with status 1 if a number disagrees with its file, or the table cannot be read.
Uses only the Python standard library.
"""

import csv
import os
import re
import sys
from decimal import Decimal, InvalidOperation

NUMBER = r"([-+−]?\d+(?:\.\d+)?(?:[eE][-+−]?\d+)?)"
LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
PIPE = re.compile(r"(?<!\\)\|")


def steady_state_field(label):
    """A number of the summary's `steady state` line, e.g. `reached at t = 12.347964: …`."""
    pattern = re.compile(re.escape(label) + r"\s*=?\s*" + NUMBER)

    def get(summary):
        m = pattern.search(summary.get("steady state", ""))
        return m.group(1) if m else None
    return get


def key(name):
    return lambda summary: summary.get(name)


# (what, regular expression of the label in the "key result" column with one group per number, one getter per group)
RULES = [
    ("mean angular velocity", re.compile(r"⟨ω⟩\[[^\]]*\] = " + NUMBER), [key("mean angular velocity")]),
    ("reference equilibrium angular velocity", re.compile(r"\(equilibrium " + NUMBER),
     [key("reference equilibrium angular velocity")]),
    ("t_sym", re.compile(r"t_sym " + NUMBER + r" / " + NUMBER), [key("t_sym_1e-4"), key("t_sym_1e-2")]),
    ("min L2 distance", re.compile(r"min E\(L²\) " + NUMBER), [key("min L2 distance to equilibrium")]),
    ("angular momentum drift", re.compile(r"ΔL/L " + NUMBER), [key("max angular momentum drift")]),
    ("steps", re.compile(r"(?<![\w.])(\d+) steps\b"), [key("steps")]),
    ("rejected steps", re.compile(r"(?<![\w.])(\d+) rejected\b"), [key("rejected steps")]),
    ("LU factorizations", re.compile(r"(?<![\w.])(\d+) LU factorizations"), [key("LU factorizations")]),
    ("steady state time", re.compile(r"steady at t = " + NUMBER), [steady_state_field("reached at t")]),
    ("final total energy", re.compile(r"(?<![\w|])F = " + NUMBER), [key("final total energy")]),
    ("final total energy", re.compile(r"(?<![\w|])F " + NUMBER + r" → " + NUMBER), [None, key("final total energy")]),
    ("final angular velocity", re.compile(r"(?<![\w⟨|])ω = " + NUMBER), [key("final angular velocity")]),
    ("kinetic energy of the rigid rotation", re.compile(r"\(K − \|L\|²/\(2λ₃\)\)/\|F\| = " + NUMBER),
     [steady_state_field("(K − |L|²/(2λ₃))/|F|")]),
]
DRIFTS = re.compile(r"drifts ≤ " + NUMBER)
NO_ENERGY_RISE = re.compile(r"no accepted energy rise")
WITHIN = re.compile(r"within " + NUMBER + r" of")
INITIAL_ENERGY = re.compile(r"(?<![\w|])F " + NUMBER + r" → ")
WINDOW = re.compile(r"⟨ω⟩\[([^\]]*)\]")


def decimal(text):
    try:
        return Decimal(text.replace("−", "-"))
    except InvalidOperation:
        return None


def half_unit(quoted):
    """Half a unit in the last digit of @p quoted: 7.8e-15 → 5e-17, 393 → 0.5."""
    mantissa, _, exponent = quoted.replace("−", "-").lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return Decimal(5).scaleb(-decimals - 1 + (int(exponent) if exponent else 0))


def agrees(quoted, value):
    """Whether @p value (text) rounds to @p quoted (text) at the digits quoted."""
    q, v = decimal(quoted), decimal(value) if value is not None else None
    return q is not None and v is not None and abs(v - q) <= half_unit(quoted)


def cells(line):
    return [c.strip().replace("\\|", "|") for c in PIPE.split(line.strip())[1:-1]]


def experiments_table(text):
    """(header, rows) of the first table after the heading `## Experiments`; rows as (line number, cells)."""
    lines = text.split("\n")
    start = next((i for i, l in enumerate(lines) if l.strip() == "## Experiments"), None)
    if start is None:
        return None, []
    i = start + 1
    while i < len(lines) and not lines[i].lstrip().startswith("|"):
        if lines[i].startswith("## "):
            return None, []
        i += 1
    if i >= len(lines):
        return None, []
    header = cells(lines[i])
    rows = []
    for number in range(i + 2, len(lines)):
        if not lines[number].lstrip().startswith("|"):
            break
        rows.append((number + 1, cells(lines[number])))
    return header, rows


def read_summary(path):
    summary = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            name, sep, value = line.rstrip("\n").partition(": ")
            if sep:
                summary[name] = value
    return summary


def first_total_energy(path):
    column = None
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("#"):
                m = re.match(r"#\s*(\d+):\s*(.*?)\s*$", line)
                if m and m.group(2) == "total energy":
                    column = int(m.group(1)) - 1
            elif line.strip() and column is not None:
                return line.split()[column]
    return None


def csv_numbers(path):
    numbers = []
    with open(path, encoding="utf-8", newline="") as f:
        for row in csv.reader(f):
            for cell in row:
                value = decimal(cell.strip())
                if value is not None:
                    numbers.append(cell.strip().lstrip("+-−"))
    return numbers


def prm_window(path):
    with open(path, encoding="utf-8") as f:
        for line in f:
            m = re.match(r"\s*set angular velocity window\s*=\s*(.*?)\s*(#.*)?$", line)
            if m:
                return [decimal(x) for x in m.group(1).split(",")]
    return None


def check_row(root, cols, row):
    """(problems, checks that passed, number of checks) of one row; None if the row links no summary."""
    paths = [os.path.join(root, l.split("#")[0]) for l in LINK.findall(row[cols["numbers from"]])]
    summaries = [p for p in paths if p.endswith(".summary")]
    if not summaries:
        return None
    summary = read_summary(summaries[0])
    name = os.path.relpath(summaries[0], root)
    result = row[cols["key result"]]
    problems, passed = [], []

    def check(ok, what, problem):
        (passed if ok else problems).append(what if ok else what + ": " + problem)

    def compare(what, quoted, value, source):
        check(agrees(quoted, value), "%s %s" % (what, quoted), "%s has %s" % (source, value))

    for what, pattern, getters in RULES:
        for m in pattern.finditer(result):
            for group, get in enumerate(getters, 1):
                if get is not None:
                    compare(what, m.group(group), get(summary), name)
    for m in DRIFTS.finditer(result):
        drifts = [summary.get(d, "nan") for d in ("max area drift", "max volume drift", "max angular momentum drift")]
        values = [decimal(d) for d in drifts]
        check(all(v is not None and not v.is_nan() and v <= decimal(m.group(1)) for v in values),
              "drifts ≤ " + m.group(1), "%s has area, volume, angular momentum drift %s" % (name, ", ".join(drifts)))
    if NO_ENERGY_RISE.search(result):
        check(summary.get("energy rises accepted") == "0", "no accepted energy rise",
              "%s has energy rises accepted = %s" % (name, summary.get("energy rises accepted")))
    statistics = [p for p in paths if p.endswith(".statistics")]
    for m in INITIAL_ENERGY.finditer(result):
        if statistics:
            compare("initial total energy", m.group(1), first_total_energy(statistics[0]),
                    os.path.relpath(statistics[0], root))
    tables = [p for p in paths if p.endswith(".csv")]
    for m in WITHIN.finditer(result):
        if tables:
            check(any(agrees(m.group(1), n) for t in tables for n in csv_numbers(t)), "within " + m.group(1),
                  "no number of %s rounds to it" % ", ".join(os.path.relpath(t, root) for t in tables))
    prms = [os.path.join(root, l) for l in LINK.findall(row[0]) if l.endswith(".prm")]
    for m in WINDOW.finditer(result):
        if len(prms) == 1:
            window = prm_window(prms[0])
            check([decimal(x) for x in m.group(1).split(",")] == window, "window [%s]" % m.group(1),
                  "%s sets angular velocity window = %s"
                  % (os.path.relpath(prms[0], root), ", ".join(str(w) for w in window or [])))
    if "wall time" in cols:
        times = re.sub(r"\([^)]*\)", "", row[cols["wall time"]])
        if " s" in times and summary.get("wall time"):
            quoted = re.findall(NUMBER, times.split(" s")[0])
            check(any(agrees(q, summary["wall time"]) for q in quoted), "wall time %s s" % " / ".join(quoted),
                  "%s has %s" % (name, summary["wall time"]))
    if not problems and not passed:
        problems.append("links %s, but no number of its key result is one this check recognizes" % name)
    return problems, passed, len(problems) + len(passed)


def main(argv):
    if len(argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    root = os.path.abspath(argv[1])
    with open(os.path.join(root, "README.md"), encoding="utf-8") as f:
        header, rows = experiments_table(f.read())
    cols = {}
    for index, title in enumerate(header or []):
        for name in ("key result", "numbers from", "wall time"):
            if title.startswith(name):
                cols[name] = index
    if "key result" not in cols or "numbers from" not in cols:
        print("readme_experiments: README.md has no table with columns 'key result' and 'numbers from' under "
              "'## Experiments'")
        return 1
    failed, checked = 0, 0
    for number, row in rows:
        if len(row) != len(header):
            print("README.md line %d: %d cells, the header has %d" % (number, len(row), len(header)))
            failed += 1
            continue
        outcome = check_row(root, cols, row)
        label = LINK.sub(lambda m: m.group(0)[1:m.group(0).index("]")], row[0])
        if outcome is None:
            print("README.md line %d (%s): skipped, links no .summary" % (number, label))
            continue
        problems, passed, checks = outcome
        checked += 1
        print("README.md line %d (%s): %d checks, %s" % (number, label, checks,
                                                      "OK" if not problems else "%d wrong" % len(problems)))
        for problem in problems:
            print("  wrong: " + problem)
        if passed:
            print("  agree: " + "; ".join(passed))
        failed += bool(problems)
    if checked == 0:
        print("readme_experiments: no row of the experiments table links a .summary file")
        return 1
    print("OK" if not failed else "%d row(s) disagree with their files" % failed)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
