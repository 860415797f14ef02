# SPDX-License-Identifier: LGPL-2.1-or-later
"""What the work–precision scripts read of a run: its summary and its statistics interpolated in time."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "phase3"))
import statistics_columns  # noqa: E402,F401  (re-exported: run_records.statistics_columns.read)


def summary(directory):
    """The `key: value` lines of <directory>/summary as a dict of strings."""
    values = {}
    for line in open(os.path.join(directory, "summary")):
        if ": " in line:
            key, value = line.split(": ", 1)
            values[key.strip()] = value.strip()
    return values


def interpolate(t, y, s):
    """y(s) by linear interpolation in the increasing times t; None beyond the last time."""
    for i in range(1, len(t)):
        if t[i] >= s:
            w = (s - t[i - 1]) / (t[i] - t[i - 1])
            return (1 - w) * y[i - 1] + w * y[i]
    return None
