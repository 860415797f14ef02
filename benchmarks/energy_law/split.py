# SPDX-License-Identifier: LGPL-2.1-or-later
"""Issue 48: the per-step energy split written by the probe in SurfaceStep (FS_ENERGY_LOG=file).

    /usr/bin/python3 benchmarks/energy_law/split.py RUN_DIR LOG [t0 t1] [--steps]

Joins the log's accepted lines with RUN_DIR/statistics (row i of the log = accepted step i) and prints, summed over
the steps ending in (t0, t1]: ΔF of the step and its parts, against −τD.
  solve   = F(u, Y) − F^m (before the conservation projection)
  av      = ΔF of the area/volume node projection, mom = ΔF of the momentum projection
  cwork   = τ[s∫p − γ∫u·ñ − Σμ_k(r_k, u)] the work of the constraint forces (drift corrections and multipliers)
  bend    = ΔW_solve + τ(1/Be)(yñ, u): bending energy change minus the work the bending force took from the fluid
  kin     = ΔK_solve − τ(Mk + C): kinetic change minus what the momentum rows give it; C (convection + mesh motion
            power) is the remainder of the momentum rows tested with u, so kin = [ΔK − (K_u − K_û)] − K_d − τC
            split as kgeo = ΔK − (K_u − K_û), kdiss = −K_d·τ/τ̂, kconv = −τC, kbdf = (K_u − K_û)(1 − τ/τ̂)
            (BDF2's start; 0 for backward Euler)
  check: solve = −τD + cwork + bend + kin (identity)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "phase3"))
import statistics_columns  # noqa: E402

run, logfile = sys.argv[1], sys.argv[2]
args = [a for a in sys.argv[3:] if not a.startswith("--")]
t0, t1 = (float(args[0]), float(args[1])) if len(args) >= 2 else (-1e9, 1e9)
per_step = "--steps" in sys.argv
c = statistics_columns.read(os.path.join(run, "statistics"))
t, F = c["time"], c["total energy"]
rows = [list(map(float, l.split())) for l in open(logfile) if l.strip()]
# A resumed run restarts the counter; the statistics rows after the first are the accepted steps in order.
n = min(len(rows), len(t) - 1)
off = len(t) - 1 - len(rows) if len(rows) < len(t) - 1 else 0
keys = ["dF", "dFstat", "-tauD", "solve", "av", "mom", "cwork", "cw_p", "cw_g", "cw_mu", "bend", "kin", "kgeo",
        "kdiss", "kconv", "kbdf"]
sums = {k: 0.0 for k in keys}
if per_step:
    print("t tau " + " ".join(keys) + " |mu| mesh_quality")
for i in range(n):
    r = rows[i]
    tau, th, K0, W0, K1, W1, K2, W2, K3 = r[1:10]
    D, Pb, Ip, s, flux, Mk, Ku, Kh, Kd, gam, vval = r[10:21]
    mu = r[21:27]
    ru = r[27:33]
    j = i + 1 + off
    ti = t[j]
    if not (t0 < ti <= t1 + 1e-12):
        continue
    musum = sum(m * x for m, x in zip(mu, ru))
    C = -(Mk + D - s * Ip + gam * flux - Pb + musum)
    v = {}
    v["dF"] = (K3 + W2) - (K0 + W0)
    v["dFstat"] = F[j] - F[j - 1]
    v["-tauD"] = -tau * D
    v["solve"] = (K1 + W1) - (K0 + W0)
    v["av"] = (K2 + W2) - (K1 + W1)
    v["mom"] = K3 - K2
    v["cw_p"] = tau * s * Ip
    v["cw_g"] = -tau * gam * flux
    v["cw_mu"] = -tau * musum
    v["cwork"] = v["cw_p"] + v["cw_g"] + v["cw_mu"]
    v["bend"] = (W1 - W0) + tau * Pb
    v["kin"] = (K1 - K0) - tau * (Mk + C)
    v["kgeo"] = (K1 - K0) - (Ku - Kh)
    v["kdiss"] = -Kd * tau / th
    v["kconv"] = -tau * C
    v["kbdf"] = (Ku - Kh) * (1 - tau / th)
    # with τ̂ ≠ τ (BDF2) kin − (kgeo + kdiss + kconv) = (Ku − Kh)(1 − τ/τ̂)
    for k in keys:
        sums[k] += v[k]
    if per_step:
        q = c["mesh quality"][j]
        print(f"{ti:.4f} {tau:.4f} " + " ".join(f"{v[k]:.3e}" for k in keys) +
              f" {sum(m*m for m in mu)**0.5:.2e} {q:.4f}")
print(f"sum over t in ({t0}, {t1}]: " + "  ".join(f"{k}={sums[k]:.4e}" for k in keys))
