#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Restart stress test: a short scene-full run (rotating prolate, refinement 2, a checkpoint after every
# step) is killed with SIGKILL at random moments several times per trial and resumed each time
# (resume = auto) until it completes; its statistics, summary and solution.pvd must equal those of an
# uninterrupted run (wall time removed). Run from the repository root after building.
#   benchmarks/restart_stress/run.sh [--quick] [--trials N] [--kills K] [--np P] [--seed S] [--out DIR]
# Writes benchmarks/restart_stress/results.csv (one row per trial) and restart_stress.png (--quick: 5 trials, both in
# benchmarks/restart_stress/quick/, not committed).
exec /usr/bin/python3 "$(dirname "$0")/stress.py" "$@"
