#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# benchmarks/work_precision/prolate_r3/run.sh: prm/prolate.prm at refinement 3, τ_max = 0.1, 0.05, 0.025, 0.0125 to
# t = 25 (the τ-convergence of the shipped file, issue 33), and the hypothesis runs to t = 11–14: first step 0.0025
# (s0.0025), the pull latched early (pull onset quality 0.22: q22), the anchor at t = 1 (a1), the anchor at t = 1
# without the tangential relaxation (a1_r0), the predictor `quadratic normal` (qn; to t = 25 unless END is given).
# Each run's summary goes to WORK/<run>/summary; the committed CSV files were tabulated from them
# (prolate_r3_tau.csv, prolate_r3_hypotheses.csv, prolate_r3_linear.csv, prolate_r3_predictor.csv).
#   benchmarks/work_precision/prolate_r3/run.sh [RUN ...]     from the repository root, after building
# Environment: WORK (default benchmarks/work_precision/prolate_r3/work, not committed), EXE, END (the end time of
# the hypothesis runs, default 14). Runs resume from their checkpoints.
set -u
cd "$(dirname "$0")/../../.."
exe=${EXE:-$PWD/build/fluid_surface}
work=${WORK:-$PWD/benchmarks/work_precision/prolate_r3/work}
mkdir -p "$work"
runs=${*:-"tau0.1 tau0.05 tau0.025 tau0.0125 tau0.1_s0.0025 tau0.1_q22 tau0.1_a1 tau0.05_a1 tau0.025_a1 tau0.0125_a1 tau0.1_a1_r0 tau0.025_a1_r0"}
for run in $runs; do
  tau=${run#tau}; tau=${tau%%_*}; variant=${run#tau$tau}
  end=25; [ -n "${variant%_qn}" ] && end=${END:-14}; [ "$variant" = _qn ] && end=${END:-25}
  {
    echo "include $PWD/prm/prolate.prm"
    echo "subsection geometry"; echo "  set refinement = 3"; echo "end"
    echo "subsection time stepping"; echo "  set maximum time step = $tau"; echo "  set end time = $end"
    case $variant in *s0.0025*) echo "  set time step = 0.0025";; esac
    echo "end"
    echo "subsection mesh redistribution"
    case $variant in *q22*) echo "  set pull onset quality = 0.22"; echo "  set full pull quality = 0.22";; esac
    case $variant in *a1*) echo "  set anchor time = 1";; esac
    case $variant in *r0*) echo "  set relaxation time = 0";; esac
    echo "end"
    case $variant in *qn*) echo "subsection geometry iteration"; echo "  set predictor = quadratic normal"; echo "end";; esac
    echo "subsection checkpoint"; echo "  set resume = auto"; echo "end"
    echo "subsection output"; echo "  set output directory = $work/$run"; echo "  set write vtu = false"
    echo "  set screen interval = 100000"; echo "end"
  } > "$work/$run.prm"
  "$exe" "$work/$run.prm" > "$work/$run.log" 2>&1; echo "$run: exit $?"
done
