# SPDX-License-Identifier: LGPL-2.1-or-later
"""results.csv of benchmarks/rotating_modes: one row per seeded run, the measured growth rate beside the linearized
rate σ (scene stability with the shipped step about the settled base state, benchmarks/spectrum/linearized_settled.csv,
else the co-rotating step's older linearized_tisserand.csv, else the lab frame's linearized.csv; extrapolated to τ → 0 from τ = 0.02 and 0.01 where both exist, second
order) and the one-mode prediction ln|z(λτ)|/τ of predict.py with λ = σ + iν_seen.

    table.py <work directory> <run name> ...
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "spectrum"))
sys.path.insert(0, os.path.join(here, "..", "phase3"))
import fit_modes  # noqa: E402
import predict  # noqa: E402
import statistics_columns  # noqa: E402


def linearized(shape, refinement, m, parity):
    rows = {}
    # the settled base state with the shipped step first, then the co-rotating step's older rows, then the lab's
    for name in ("linearized_settled.csv", "linearized_tisserand.csv", "linearized.csv"):
        path = os.path.join(here, "..", "spectrum", name)
        if not os.path.exists(path):
            continue
        with open(path) as f:
            header = f.readline().strip().split(",")
            for line in f:
                r = dict(zip(header, line.strip().split(",")))
                key = (r["shape"], int(r["refinement"]), float(r["tau"]), r["Re"], int(r["m"]), r["parity"])
                if key[3] == "1" and key not in rows:  # the first row of a case is its leading eigenvalue
                    rows[key] = (float(r["growth rate"]), float(r["frequency"]))
    coarse = rows.get((shape, refinement, 0.02, "1", m, parity))
    fine = rows.get((shape, refinement, 0.01, "1", m, parity))
    if coarse is None:
        return None
    if fine is None:
        return coarse[0], coarse[1], "tau 0.02"
    return fine[0] + (fine[0] - coarse[0]) / 3, fine[1] + (fine[1] - coarse[1]) / 3, "tau -> 0 from 0.02 and 0.01"


def main():
    work, names = sys.argv[1], sys.argv[2:]
    print("run,shape,m,parity,refinement,scheme,frame,tau,measured rate,linearized rate,linearized frequency,"
          "linearized from,mean angular velocity,seen frequency,predicted rate,measured vs linearized,"
          "predicted vs linearized,wall time [s],exit")
    for name in names:
        shape, mpart, parity, rpart, scheme, frame, taupart = name.split("_")
        m, refinement, tau = int(mpart[1:]), int(rpart[1:]), float(taupart[3:])
        run = os.path.join(work, name)
        exit_line = open(os.path.join(work, name + ".exit")).read().split()
        status, wall = int(exit_line[1]), float(exit_line[2])
        try:
            measured = fit_modes.fit(run, m, parity)["sigma"]
        except (Exception, SystemExit) as exc:  # a run that stopped before the window
            print(f"{name}: {exc}", file=sys.stderr)
            measured = float("nan")
        c = statistics_columns.read(os.path.join(run, "statistics"))
        omega = sum(c["angular velocity"]) / len(c["angular velocity"])
        ref = linearized(shape, refinement, m, parity)
        sigma, nu, origin = ref if ref else (float("nan"), float("nan"), "none")
        seen = nu + m * omega if frame == "lab" else nu
        rate = (predict.rate_bdf2 if scheme.startswith("bdf2") else
                predict.rate_sdirk2 if scheme.startswith("sdirk2") else predict.rate_be)
        predicted = rate(complex(sigma, seen), tau)
        print(f"{name},{shape},{m},{parity},{refinement},{scheme},{frame},{tau},{measured:.5f},{sigma:.5f},{nu:.4f},"
              f"{origin},{omega:.5f},{seen:.4f},{predicted:.5f},{(measured - sigma) / sigma:+.4f},"
              f"{(predicted - sigma) / sigma:+.4f},{wall:.1f},{status}")


if __name__ == "__main__":
    main()
