#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Every parameter entry earns its place (ctest: entries_in_use).

Each entry that `fluid_surface --print-parameters` lists must be set by a shipped experiment file (prm/*.prm) or by
a test: a `set NAME =` line in prm/*.prm, tests/*.prm or tests/*.prm.in, or the entry's name as a string in a test
source (tests/*.cc, tests/*.h: "subsection/NAME" or "NAME" in a parameter list). An entry no file sets is untested
or unused: give it a test or remove it (issue 47, item 5).

Usage: entries_in_use.py SOURCE_DIR FLUID_SURFACE_EXECUTABLE
Prints the count, and one line per entry that nothing sets; exits with status 1 if there is any.
Uses only the Python standard library.
"""

import glob
import os
import re
import subprocess
import sys


def declared_entries(executable):
    """(subsection path, name) of every entry, from --print-parameters."""
    listing = subprocess.run([executable, "--print-parameters"], capture_output=True, text=True, check=True).stdout
    entries, path = [], []
    for line in listing.splitlines():
        text = line.strip()
        if text.startswith("subsection "):
            path.append(text[len("subsection "):])
        elif text == "end":
            path.pop()
        else:
            match = re.match(r"set (.+?)\s*=", text)
            if match:
                entries.append(("/".join(path), match.group(1)))
    return entries


def main():
    root, executable = sys.argv[1], sys.argv[2]
    parameter_files = [f for pattern in ("prm/*.prm", "tests/*.prm", "tests/*.prm.in")
                       for f in glob.glob(os.path.join(root, pattern))]
    sources = [f for pattern in ("tests/*.cc", "tests/*.h") for f in glob.glob(os.path.join(root, pattern))]
    parameter_text = [open(f, encoding="utf-8", errors="replace").read() for f in parameter_files]
    source_text = [open(f, encoding="utf-8", errors="replace").read() for f in sources]
    entries = declared_entries(executable)
    unset = []
    for subsection, name in entries:
        in_prm = re.compile(r"^\s*set\s+" + re.escape(name) + r"\s*=", re.MULTILINE)
        in_source = re.compile(r"[\"/]" + re.escape(name) + r"\"|set\s+" + re.escape(name) + r"\s*=")
        if not any(in_prm.search(t) for t in parameter_text) and not any(in_source.search(t) for t in source_text):
            unset.append(subsection + "/" + name)
    print(f"{len(entries)} entries, {len(entries) - len(unset)} set by a shipped prm file or a test")
    for entry in unset:
        print(f"set by no prm file and no test: {entry}")
    return 1 if unset else 0


if __name__ == "__main__":
    sys.exit(main())
