# SPDX-License-Identifier: LGPL-2.1-or-later
"""The columns of a fluid_surface `statistics` file (`# N: name` headers) as a dict name -> list of floats."""


def read(path):
    names, rows = [], []
    for line in open(path):
        if line.startswith("# "):
            names.append(line.split(": ", 1)[1].strip())
        elif line.strip():
            rows.append([float(x) for x in line.split()])
    return {n: [r[i] for r in rows] for i, n in enumerate(names)}
