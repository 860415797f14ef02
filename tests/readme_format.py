#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Checks the shape of README.md (ctest: readme_format).

README.md is a user's guide: at most 200 lines, and no line longer than 200 characters outside fenced code
blocks (``` ... ```) and table rows (lines starting with `|`). Lengths are counted in characters (UTF-8), not bytes.

Usage: readme_format.py SOURCE_DIR
Prints one line per problem, naming the line numbers, and exits with status 1 if there is any.
Uses only the Python standard library.
"""

import os
import sys

MAX_LINES = 200
MAX_LINE_LENGTH = 200


def problems_of(text, name="README.md"):
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()  # the newline that ends the last line
    problems = []
    if len(lines) > MAX_LINES:
        problems.append("%s has %d lines, more than %d (lines %d-%d are over)"
                        % (name, len(lines), MAX_LINES, MAX_LINES + 1, len(lines)))
    fenced = False
    long_lines = []
    for number, line in enumerate(lines, 1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if fenced or line.lstrip().startswith("|"):
            continue
        if len(line) > MAX_LINE_LENGTH:
            long_lines.append((number, len(line)))
    if long_lines:
        problems.append("%s has %d line(s) over %d characters outside code blocks and tables: %s"
                        % (name, len(long_lines), MAX_LINE_LENGTH,
                           ", ".join("line %d (%d)" % (n, length) for n, length in long_lines)))
    return problems


def main(argv):
    if len(argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    path = os.path.join(os.path.abspath(argv[1]), "README.md")
    with open(path, encoding="utf-8") as f:
        text = f.read()
    problems = problems_of(text)
    for problem in problems:
        print("readme_format: " + problem)
    print("OK" if not problems else "%d problem(s)" % len(problems))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
