# Markdown rows of the per-interval split (same formulas as split.py; see analyse.py) for FINDINGS.md.
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "phase3"))
import statistics_columns
def rows_for(run, ivs, label):
    c = statistics_columns.read(run + "/statistics"); t, F = c["time"], c["total energy"]
    L = [list(map(float, l.split())) for l in open(run + ".elog")]
    out = []
    for a, b in ivs:
        S = dict.fromkeys("dF tD mu bend kin kconv kgeo kbdf kdiss av avK avW mom".split(), 0.0); tm = []; mu = []
        J = [j for j in range(1, len(t)) if a < t[j] <= b + 1e-12]
        for j in J:
            r = L[j - 1]
            tau, th, K0, W0, K1, W1, K2, W2, K3 = r[1:10]
            D, Pb, Ip, s, flux, Mk, Ku, Kh, Kd, gam, vval = r[10:21]
            musum = sum(x * y for x, y in zip(r[21:27], r[27:33]))
            C = -(Mk + D - s * Ip + gam * flux - Pb + musum)
            S["dF"] += K3 + W2 - K0 - W0; S["tD"] += -tau * D
            S["mu"] += -tau * musum + tau * s * Ip - tau * gam * flux
            S["bend"] += W1 - W0 + tau * Pb; S["kin"] += K1 - K0 - tau * (Mk + C)
            S["kconv"] += -tau * C; S["kgeo"] += K1 - K0 - (Ku - Kh); S["kbdf"] += (Ku - Kh) * (1 - tau / th)
            S["kdiss"] += -Kd * tau / th; S["av"] += K2 + W2 - K1 - W1; S["avK"] += K2 - K1; S["avW"] += W2 - W1
            S["mom"] += K3 - K2; tm.append(r[53]); mu.append(sum(x * x for x in r[21:27]) ** 0.5)
        e = lambda x: f"{x:+.2e}"
        chain = S["mu"] + S["kin"] + S["mom"]
        out.append(f"| {label} | ({a}, {b}] | {len(J)} | {e(S['dF'])} | {e(S['tD'])} | **{e(S['dF']-S['tD'])}** | {e(S['mu'])} | "
                   f"{e(S['bend'])} | {e(S['kin'])} ({e(S['kconv'])} / {e(S['kgeo'])} / {e(S['kbdf'])} / {e(S['kdiss'])}) | "
                   f"{e(S['av'])} ({e(S['avK'])} / {e(S['avW'])}) | {e(S['mom'])} | {e(chain)} | {e(S['bend']+S['avW'])} | "
                   f"{e(chain+S['avK'])} | {sum(tm)/len(tm):.1e} / {max(tm):.1e} | {max(mu):.2g} | "
                   f"{c['mesh quality'][J[0]-1]:.3f}→{c['mesh quality'][J[-1]]:.3f} | {c['symmetry deviation'][J[0]-1]:.1e}→{c['symmetry deviation'][J[-1]]:.1e} |")
    return out
hdr = ("| run | t | steps | ΔF | −∫D | ΔB | μ work | bending defect | kinetic defect (conv / geo / bdf / diss) | "
       "area/vol proj. (K / W part) | mom. proj. | μ+kin+mom | W side (bend+avW) | K side (μ+kin+avK+mom) | "
       "tang. move per step mean / max | max abs(μ) | mesh quality | symmetry dev. |")
print(hdr); print("|" + "---|" * 18)
for r in rows_for("v0.95_L40_prolate", [(2, 4.9), (4.9, 6.1), (6.1, 7.3), (7.3, 8)], "0.95 τ0.1"): print(r)
for r in rows_for("v0.75_L40_prolate", [(1.5, 2.0), (2.0, 2.35), (2.35, 3)], "0.75 τ0.1"): print(r)
print(); print(hdr); print("|" + "---|" * 18)
for run, lab in [("v0.95_L40_prolate_tau0.05", "0.95 τ_max 0.05"), ("v0.95_L40_prolate_nomom", "0.95 conserve momenta = false"),
                 ("v0.95_L40_prolate_noproj", "0.95 conservation projection off")]:
    for r in rows_for(run, [(2, 4.9), (4.9, 6.1), (6.1, 7.3), (7.3, 8)], lab): print(r)
