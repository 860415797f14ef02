# SPDX-License-Identifier: LGPL-2.1-or-later
"""phase3.png: F, mesh quality, τ and the drifts against t for every case of benchmarks/phase3 (python3 plot.py DIR OUT)."""
import glob
import os
import sys

import statistics_columns

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

directory, out = sys.argv[1:3]
fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
for path in sorted(glob.glob(os.path.join(directory, "*.statistics"))):
    c = statistics_columns.read(path)
    label = os.path.basename(path).replace(".statistics", "")
    t = c["time"]
    axes[0][0].plot(t, c["total energy"], label=label)
    axes[0][1].plot(t, c["mesh quality"], label=label)
    axes[1][0].semilogy(t[1:], c["tau"][1:], ".", ms=2, label=label)
    A0, V0 = c["area"][0], c["volume"][0]
    axes[1][1].semilogy(t, [abs(a - A0) / A0 + 1e-16 for a in c["area"]], label=label + " ΔA/A")
axes[0][0].set_ylabel("F")
axes[0][1].set_ylabel("mesh quality (min σ_min/σ_max)")
axes[1][0].set_ylabel("τ")
axes[1][1].set_ylabel("|ΔA|/A")
for a in axes[1]:
    a.set_xlabel("t")
axes[0][0].legend(fontsize=7)
fig.suptitle("perturbed oblate (prm/oblate.prm, shape perturbation 0.01): mesh laws bgn and reference")
fig.tight_layout()
fig.savefig(out, dpi=110)
