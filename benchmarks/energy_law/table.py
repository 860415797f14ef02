# SPDX-License-Identifier: LGPL-2.1-or-later
"""Issue 48: the energy-split table of benchmarks/energy_law (results.md).

    /usr/bin/python3 benchmarks/energy_law/table.py RUNS_DIR [--csv OUT]   from the runs of run.sh
    /usr/bin/python3 benchmarks/energy_law/table.py --from-csv results.csv  the committed table (results.md)

RUNS_DIR holds NAME/ (output directory, with its statistics) and NAME.elog (FS_ENERGY_LOG) for each run; rows whose
run is missing are left out. Each row sums split.py's per-step terms over the accepted steps ending in (t0, t1].
The table is printed in Markdown; --csv also writes it as CSV (one row per case, one column per term)."""
import csv
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# (case, run, t0, t1): the rows of results.md, then the runs named only in its text, then run.sh --quick's run.
ROWS = [("a r3 τ0.1 (shipped, anchor 4)", "a_base", "2", "4"), ("a r3 τ0.1 (shipped)", "a_base", "3.5", "4"),
        ("a r3 τ0.05", "a_t05", "2", "4"), ("a r3 τ0.1 anchored at 2", "a_anc2", "2", "4"),
        ("a r3 τ0.1 anchored at 2", "a_anc2", "3.5", "4"), ("a r3 τ0.05 anchored at 2", "a_anc2_t05", "3.5", "4"),
        ("a r3 τ0.1 anchored 2, lab frame", "a_anc2_lab", "3.5", "4"),
        ("a r3 τ0.1 anchored 2, backward Euler", "a_anc2_be", "3.5", "4"),
        ("a r3 τ0.1 no momenta", "a_nomom", "2", "4"),
        ("a r3 τ0.1 no momenta, anchored 2", "a_nomom_anc2", "3.5", "4"),
        ("a r3 τ0.1 projection off", "a_noproj", "2", "4"),
        ("a r4 τ0.1 (shipped)", "r4_base", "2", "4"), ("a r4 τ0.1 (shipped)", "r4_base", "3.5", "4"),
        ("a r4 τ0.1 anchored 2", "r4_anc2", "3.5", "4"),
        ("a r4 τ0.1 no momenta, anchored 2", "r4_nomom_anc2", "3.5", "4"),
        ("b r3 τ0.1 oblate (shipped)", "b_r3", "1", "3"), ("b r3 τ0.1 oblate (shipped)", "b_r3", "3", "4.2"),
        ("b r3 τ0.1 oblate (shipped)", "b_r3", "4.2", "5.4"),
        ("c r2 τ0.1 (stalled)", "c_r2", "0.4729", "0.5"),
        ("a r3 τ0.1 anchored 2, geometry iteration converged", "a_anc2_iter", "3.5", "4"),
        ("b r3 τ0.1 oblate anchored at 1", "b_anc1", "1", "4.2"),
        ("L₀ = 10 r3 τ0.1 anchored 2 (from t = 0)", "L10_anc2", "3.5", "4"),
        ("L₀ = 20 r3 τ0.1 anchored 2 (from t = 0)", "L20_anc2", "3.5", "4"),
        ("a r3 τ0.1 (shipped, from t = 0; --quick)", "a_quick", "0", "2"),
        ("a r3 τ0.1 (shipped, from t = 0; --quick)", "a_quick", "2", "2.5")]
COLUMNS = ["case", "run", "t0", "t1", "dF", "minus_int_D", "dB", "solve", "area_volume_proj", "momentum_proj",
           "mu_work", "s_gamma_work", "bending_defect", "kinetic_defect", "kin_conv", "kin_geo", "kin_bdf", "kin_diss"]
HEADER = ("| case | t | ΔF | −∫D | ΔB | solve | area/vol proj. | mom. proj. | μ work | s,γ work | bending defect "
          "| kinetic defect (conv / geo / bdf / diss) |")


def from_runs(runs_dir):
    """The table's rows (dicts of strings) from the runs present in runs_dir."""
    rows = []
    for case, run, t0, t1 in ROWS:
        log = os.path.join(runs_dir, run + ".elog")
        if not (os.path.isfile(log) and os.path.isfile(os.path.join(runs_dir, run, "statistics"))):
            continue
        out = subprocess.run([sys.executable, os.path.join(HERE, "split.py"), os.path.join(runs_dir, run), log,
                              t0, t1], capture_output=True, text=True, check=True).stdout
        d = {kv.split("=")[0]: float(kv.split("=")[1]) for kv in out.split(": ", 1)[1].split()}
        vals = [d["dF"], d["-tauD"], d["dF"] - d["-tauD"], d["solve"], d["av"], d["mom"], d["cw_mu"],
                d["cw_p"] + d["cw_g"], d["bend"], d["kin"], d["kconv"], d["kgeo"], d["kbdf"], d["kdiss"]]
        rows.append(dict(zip(COLUMNS, [case, run, t0, t1] + [f"{x:+.2e}" for x in vals])))
    return rows


def markdown(rows):
    print(HEADER)
    print("|" + "---|" * 12)
    for r in rows:
        dB = f"**{r['dB']}**" if r["dB"].startswith("-") else r["dB"]  # B falls: the energy law holds
        print(f"| {r['case']} | ({r['t0']}, {r['t1']}] | {r['dF']} | {r['minus_int_D']} | {dB} | {r['solve']} | "
              f"{r['area_volume_proj']} | {r['momentum_proj']} | {r['mu_work']} | {r['s_gamma_work']} | "
              f"{r['bending_defect']} | {r['kinetic_defect']} ({r['kin_conv']} / {r['kin_geo']} / {r['kin_bdf']} / "
              f"{r['kin_diss']}) |")


if __name__ == "__main__":
    args = sys.argv[1:]
    if not args or args[0] in ("-h", "--help"):
        sys.exit(__doc__)
    if args[0] == "--from-csv":
        with open(args[1], newline="") as f:
            markdown(list(csv.DictReader(f)))
        sys.exit(0)
    rows = from_runs(args[0])
    if not rows:
        sys.exit(f"table.py: no run with a .elog and statistics in {args[0]}")
    markdown(rows)
    if "--csv" in args:
        with open(args[args.index("--csv") + 1], "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=COLUMNS, lineterminator="\n")
            w.writeheader()
            w.writerows(rows)
