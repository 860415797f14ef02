#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/spectrum: the leading growth rates of scene stability (linearized.csv) against the seeded nonlinear
runs (seeded_modes.csv), and σ(Re).
    /usr/bin/python3 benchmarks/spectrum/plot_linearized.py linearized.csv seeded_modes.csv spectrum.png
Prints the tables of benchmarks/spectrum/README.md: the leading eigenvalue per (m, parity) at refinement 3,
τ = 0.02, Re = 1 beside the seeded fit; its convergence in h and τ; σ against Re."""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def leading(rows):
    """The leading row (largest growth rate) of each (shape, refinement, tau, Re, seed m, seed parity)."""
    best = {}
    for r in rows:
        key = (r["shape"], int(r["refinement"]), float(r["tau"]), float(r["Re"]), int(r["seed m"]), r["seed parity"])
        if key not in best or float(r["growth rate"]) > float(best[key]["growth rate"]):
            best[key] = r
    return best


linearized, seeded = read(sys.argv[1]), read(sys.argv[2])
best = leading(linearized)
seeded_by = {}
for r in seeded:
    shape = r["run"].split("_")[0]
    tau = 0.02 if shape == "oblate" or "tau0.02" in r["run"] else 0.05
    seeded_by.setdefault((shape, int(r["m"]), r["parity"]), []).append((tau, r))

print("| shape | m, parity | σ (linearized) | frequency | residual | normal share | σ (seeded, τ_max) | frequency | σ difference |")
print("|---|---|---|---|---|---|---|---|---|")
for key in sorted(best):
    shape, ref, tau, re, m, parity = key
    if (ref, tau, re) != (3, 0.02, 1.0):
        continue
    r = best[key]
    line = (f"| {shape} | {m} {parity} | {float(r['growth rate']):.4f} | {float(r['frequency']):.3f} | "
            f"{float(r['residual']):.1e} | {float(r['normal share']):.2f} |")
    fits = sorted(seeded_by.get((shape, m, parity), []), key=lambda x: x[0])
    if fits:
        t, s = fits[0]
        diff = float(r["growth rate"]) - float(s["growth rate"])
        line += f" {float(s['growth rate']):.4f} ({t}) | {float(s['frequency']):.3f} | {diff:+.4f} |"
    else:
        line += " | | |"
    print(line)

print("\n| shape | m, parity | refinement | τ | σ | frequency |")
print("|---|---|---|---|---|---|")
for key in sorted(best, key=lambda k: (k[0], k[4], k[5], k[1], -k[2])):
    shape, ref, tau, re, m, parity = key
    if re != 1.0:
        continue
    r = best[key]
    print(f"| {shape} | {m} {parity} | {ref} | {tau} | {float(r['growth rate']):.4f} | {float(r['frequency']):.3f} |")

print("\n| shape | m, parity | refinement | Re | σ | frequency | σ/Re |")
print("|---|---|---|---|---|---|---|")
re_series = {}
for key in sorted(best, key=lambda k: (k[0], k[4], k[5], k[1], k[3])):
    shape, ref, tau, re, m, parity = key
    if ref != 2 or tau != 0.02:
        continue
    r = best[key]
    sigma = float(r["growth rate"])
    re_series.setdefault((shape, m, parity), []).append((re, sigma))
    print(f"| {shape} | {m} {parity} | {ref} | {re:g} | {sigma:.4f} | {float(r['frequency']):.3f} | {sigma / re:.4f} |")
re_series = {k: v for k, v in re_series.items() if len(v) > 1}

fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
for ax, shape in zip(axes[:2], ("oblate", "prolate")):
    for parity, dx, colour in (("even", -0.08, "C0"), ("odd", 0.08, "C3")):
        lin = [(m + dx, float(best[k]["growth rate"])) for k in best for m in [k[4]]
               if k[0] == shape and k[1:4] == (3, 0.02, 1.0) and k[5] == parity]
        seed = [(int(m) + dx, float(fits[0][1]["growth rate"])) for (s, m, p), fits in
                ((k, sorted(v, key=lambda x: x[0])) for k, v in seeded_by.items()) if s == shape and p == parity]
        if lin:
            ax.plot(*zip(*sorted(lin)), "o", color=colour, label=f"{parity}: linearized (scene stability)")
        if seed:
            ax.plot(*zip(*sorted(seed)), "x", color=colour, markersize=10, label=f"{parity}: seeded nonlinear run")
    ax.axhline(0, color="grey", lw=0.8)
    ax.set_xlabel("azimuthal wavenumber m")
    ax.set_ylabel("leading growth rate σ")
    ax.set_title(f"{shape} rotating equilibrium, refinement 3")
    ax.legend(fontsize=8)
ax = axes[2]
for (shape, m, parity), points in sorted(re_series.items()):
    res, sigmas = zip(*sorted(points))
    ax.plot(res, sigmas, "o-", label=f"{shape}, m = {m} {parity}")
ax.set_xscale("log")
ax.axhline(0, color="grey", lw=0.8)
ax.set_xlabel("Re")
ax.set_ylabel("leading growth rate σ")
ax.set_title("σ against Re (refinement 2)")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[3], dpi=110)
