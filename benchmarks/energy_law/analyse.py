# Issue 48 follow-up (e49probe): per-interval and per-step split of the probe log, with the av/mom projections split
# into their kinetic and bending parts and the probe's rms tangential/normal node moves.
# usage: python3 analyse.py RUN_DIR LOG t0 t1 [--steps]
import sys, os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "phase3"))
import statistics_columns

import probe_terms
run, logfile = sys.argv[1], sys.argv[2]
t0, t1 = float(sys.argv[3]), float(sys.argv[4])
steps = "--steps" in sys.argv
c = statistics_columns.read(os.path.join(run, "statistics"))
t, F = c["time"], c["total energy"]
rows = [list(map(float, l.split())) for l in open(logfile) if l.strip()]
assert len(rows) == len(t) - 1, (len(rows), len(t))
keys = ["dF", "-tauD", "mu", "bend", "kin", "kconv", "kgeo", "kbdf", "kdiss", "av", "avK", "avW", "mom",
        "mu+mom+kin", "dB"]
S = {k: 0.0 for k in keys}; n = 0; tmax = 0; tsum = 0; nsum = 0
if steps:
    print("t       " + " ".join(f"{k:>10s}" for k in keys) + "   |mu|    mu_z   tang.mv  norm.mv  sym.dev  quality")
for i, r in enumerate(rows):
    j = i + 1
    if not (t0 < t[j] <= t1 + 1e-12):
        continue
    mu = r[21:27]
    tm, nm = r[53], r[54]
    v = probe_terms.terms(r)
    assert abs(v["dF"] - (F[j] - F[j - 1])) < 1e-7, (t[j], v["dF"], F[j] - F[j - 1])
    chk = v["-tauD"] + v["mu"] + v["bend"] + v["kin"] + v["av"] + v["mom"] - v["dF"]
    assert abs(chk) < 1e-6 * max(1, abs(v["mu"])), chk
    for k in keys: S[k] += v[k]
    n += 1; tsum += tm; nsum += nm; tmax = max(tmax, tm)
    if steps:
        mun = sum(m * m for m in mu) ** 0.5
        print(f"{t[j]:.4f} " + " ".join(f"{v[k]:10.3e}" for k in keys) +
              f" {mun:7.2e} {mu[5]:8.1e} {tm:8.2e} {nm:8.2e} {c['symmetry deviation'][j]:8.2e} {c['mesh quality'][j]:.4f}")
print(f"({t0}, {t1}] n={n}: " + "  ".join(f"{k}={S[k]:+.3e}" for k in keys) +
      f"  mean tang.move={tsum/max(n,1):.2e} max={tmax:.2e} mean norm.move={nsum/max(n,1):.2e}")
