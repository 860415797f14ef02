#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Checks the documentation against the repository (ctest: documentation_links).

1. Every relative link and image in README.md, CHANGELOG.md, doc/*.md and benchmarks/*/README.md points to an
   existing file or directory; a link to a heading of a Markdown file (file.md#heading) names an existing heading.
2. Every prm file named in README.md passes `fluid_surface --validate FILE`, run from the repository root; the
   listing doc/parameters.prm, which sets every entry of every scene, may fail only by the scene rule (no scene
   reads every subsection), so each of its entries is declared and its default passes its pattern.

Usage: documentation_links.py SOURCE_DIR [FLUID_SURFACE_EXECUTABLE]
Without the executable only part 1 runs. Prints one line per problem and exits with status 1 if there is any.
Uses only the Python standard library (python3 comes with python3-h5py, which the README installs).
"""

import glob
import os
import re
import subprocess
import sys

LINK = re.compile(r"!?\[(?:[^\]\\]|\\.)*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HTML_SOURCE = re.compile(r"<(?:img|a)\s[^>]*(?:src|href)=\"([^\"]+)\"", re.IGNORECASE)
INLINE_CODE = re.compile(r"`[^`]*`")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
LISTING = "doc/parameters.prm"
PRM = re.compile(r"(?<![\w./-])((?:prm|tests|benchmarks|doc)/[\w./-]*\.prm)(?![\w.-])")


def documentation_files(root):
    files = [os.path.join(root, "README.md"), os.path.join(root, "CHANGELOG.md")]
    files += sorted(glob.glob(os.path.join(root, "doc", "*.md")))
    files += sorted(glob.glob(os.path.join(root, "benchmarks", "*", "README.md")))
    return [f for f in files if os.path.isfile(f)]


def prose_lines(text):
    """(line number, line) outside fenced code blocks, with inline code removed."""
    fenced = False
    for number, line in enumerate(text.split("\n"), 1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if not fenced:
            yield number, INLINE_CODE.sub("", line)


def slug(heading):
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    heading = re.sub(r"[`*_]|\[([^\]]*)\]\([^)]*\)", lambda m: m.group(1) or "", heading)
    return re.sub(r"[^\w\- ]", "", heading.lower()).replace(" ", "-")


def anchors(path):
    found, seen = set(), {}
    with open(path, encoding="utf-8") as f:
        for _, line in prose_lines(f.read()):
            m = HEADING.match(line)
            if m:
                base = slug(m.group(2))
                n = seen.get(base, 0)
                seen[base] = n + 1
                found.add(base if n == 0 else "%s-%d" % (base, n))
    return found


def check_links(root):
    problems = []
    for path in documentation_files(root):
        name = os.path.relpath(path, root)
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for number, line in prose_lines(text):
            for target in LINK.findall(line) + HTML_SOURCE.findall(line):
                if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.IGNORECASE):
                    continue  # http:, https:, mailto:
                file_part, _, anchor = target.partition("#")
                resolved = path if not file_part else os.path.normpath(os.path.join(os.path.dirname(path), file_part))
                if file_part and not os.path.exists(resolved):
                    problems.append("%s:%d: link to '%s': no such file" % (name, number, target))
                elif file_part.startswith("/") or os.path.relpath(resolved, root).startswith(".."):
                    problems.append("%s:%d: link to '%s' leaves the repository" % (name, number, target))
                elif anchor and resolved.endswith(".md") and anchor not in anchors(resolved):
                    problems.append("%s:%d: link to '%s': no heading with anchor '#%s' in %s"
                                    % (name, number, target, anchor, os.path.relpath(resolved, root)))
    return problems


def check_prm_files(root, executable):
    problems = []
    with open(os.path.join(root, "README.md"), encoding="utf-8") as f:
        named = sorted(set(PRM.findall(f.read())))
    if not named:
        problems.append("README.md names no prm file")
    for prm in named:
        if not os.path.isfile(os.path.join(root, prm)):
            problems.append("README.md names '%s': no such file" % prm)
            continue
        run = subprocess.run([executable, "--validate", prm], cwd=root, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, universal_newlines=True)
        refused_by_scene_rule = run.returncode == 2 and "is set, but scene" in run.stdout
        if run.returncode != 0 and not (prm == LISTING and refused_by_scene_rule):
            problems.append("README.md names '%s': --validate failed (exit %d): %s"
                            % (prm, run.returncode, run.stdout.strip()))
    return problems, named


def main(argv):
    if len(argv) not in (2, 3):
        sys.stderr.write(__doc__)
        return 2
    root = os.path.abspath(argv[1])
    problems = check_links(root)
    print("links: %d documentation files checked" % len(documentation_files(root)))
    if len(argv) == 3:
        prm_problems, named = check_prm_files(root, argv[2])
        problems += prm_problems
        print("prm files named in README.md: %s" % ", ".join(named))
    for problem in problems:
        print("documentation_links: " + problem)
    print("OK" if not problems else "%d problem(s)" % len(problems))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
