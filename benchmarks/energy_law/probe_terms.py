# SPDX-License-Identifier: LGPL-2.1-or-later
"""The terms of one accepted step's ΔF from one line of the probe's log (FS_ENERGY_LOG), for split.py and analyse.py.
Definitions in split.py's docstring and README.md."""


def terms(r):
    """The split of the step of log line @p r: a dict of ΔF, −τD, the projections, the constraint work, the bending
    and kinetic defects (with the kinetic parts), μ+mom+kin and ΔB."""
    tau, th, K0, W0, K1, W1, K2, W2, K3 = r[1:10]
    D, Pb, Ip, s, flux, Mk, Ku, Kh, Kd, gam = r[10:20]
    mu, ru = r[21:27], r[27:33]
    musum = sum(m * x for m, x in zip(mu, ru))
    C = -(Mk + D - s * Ip + gam * flux - Pb + musum)
    v = {"dF": (K3 + W2) - (K0 + W0), "-tauD": -tau * D, "solve": (K1 + W1) - (K0 + W0),
         "av": (K2 + W2) - (K1 + W1), "avK": K2 - K1, "avW": W2 - W1, "mom": K3 - K2,
         "cw_p": tau * s * Ip, "cw_g": -tau * gam * flux, "cw_mu": -tau * musum,
         "bend": (W1 - W0) + tau * Pb, "kin": (K1 - K0) - tau * (Mk + C), "kgeo": (K1 - K0) - (Ku - Kh),
         "kdiss": -Kd * tau / th, "kconv": -tau * C,
         # with τ̂ ≠ τ (BDF2) kin − (kgeo + kdiss + kconv) = (Ku − Kh)(1 − τ/τ̂)
         "kbdf": (Ku - Kh) * (1 - tau / th)}
    v["cwork"] = v["cw_p"] + v["cw_g"] + v["cw_mu"]
    v["mu"] = v["cwork"]
    v["mu+mom+kin"] = v["mu"] + v["mom"] + v["kin"]
    v["dB"] = v["dF"] - v["-tauD"]
    return v
