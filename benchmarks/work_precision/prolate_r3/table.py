# SPDX-License-Identifier: LGPL-2.1-or-later
"""One CSV row per run of benchmarks/work_precision/prolate_r3/run.sh, from its summary, statistics and screen log.

    table.py <work directory> <run> ...     (wall times as measured: say in the file name whether loaded)
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "phase3"))
import statistics_columns  # noqa: E402


def summary(path):
    values = {}
    for line in open(path):
        if ": " in line:
            key, value = line.rstrip("\n").split(": ", 1)
            values.setdefault(key, value)
    return values


work, runs = sys.argv[1], sys.argv[2:]
print("run,status,t_end,t_sym_1e-4,t_sym_1e-2,mean omega window 4..6,F at t_end,steps,rejected steps,"
      "energy rises accepted,min mesh quality,anchored at (t),LU factorizations,wall s")
for run in runs:
    s = summary(os.path.join(work, run, "summary"))
    c = statistics_columns.read(os.path.join(work, run, "statistics"))
    log = open(os.path.join(work, run + ".log")).read()
    anchored = re.search(r"mesh law anchored at t = ([0-9.e+-]+)", log)
    print(",".join([run, s["status"].split(" ")[0], f"{c['time'][-1]:g}", s["t_sym_1e-4"], s["t_sym_1e-2"],
                    s["mean angular velocity"], s["final total energy"], s["steps"], s["rejected steps"],
                    s["energy rises accepted"], f"{min(c['mesh quality']):.4f}",
                    anchored.group(1) if anchored else "none", s["LU factorizations"],
                    f"{float(s['wall time']):.0f}"]))
