# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/prolate: ω(t) of every case, and the error of ⟨ω⟩[5, 10] and F(10) against wall time, relative to the
rotating equilibrium at the run's initial angular momentum (results.csv, cases/*.statistics) → prolate.png; prints the
README table."""
import csv, glob, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = sys.argv[1] if len(sys.argv) > 1 else "benchmarks/prolate"  # the folder of results.csv and cases/


def read(f):
    names, rows = [], []
    for line in open(f):
        if line.startswith("# "):
            names.append(line.split(": ", 1)[1].strip())
        elif line.strip():
            try:
                rows.append([float(x) for x in line.split()])
            except ValueError:
                pass
    return {n: [r[i] for r in rows] for i, n in enumerate(names)}


rows = list(csv.DictReader(open(here + "/results.csv")))
done = [r for r in rows if r["completed"] == "1" and r["mean_omega"] not in ("", "n/a")]
fig, ax = plt.subplots(1, 2, figsize=(11, 4))
for f in sorted(glob.glob(here + "/cases/*.statistics")):
    d = read(f)
    ax[0].plot(d["time"], d["angular velocity"], label=f.split("/")[-1].replace(".statistics", ""))
ax[0].axhline(3.2455522821, ls=":", c="k", label="equilibrium at L0 (ω = 3.2456)")
ax[0].set_xlabel("t"); ax[0].set_ylabel("ω(t)"); ax[0].legend(fontsize=8)
# Right: the completed cases' errors against the rotating equilibrium with the run's A, v and L0 (the state a run that
# conserves L must approach, `fluid_surface --equilibrium prm/equilibrium_prolate.prm`), against their wall time.
omega_eq, energy_eq = 3.2455522821, 62.276217
for r in done:
    name = f"r{r['refinement']}_tau{r['tau_max']}"
    wall = float(r["wall_time_s"])
    e_omega = abs(float(r["mean_omega"]) - omega_eq) / omega_eq
    e_energy = abs(float(r["final_energy"]) - energy_eq) / energy_eq
    ax[1].loglog(wall, e_omega, "o", c="C0", label="|⟨ω⟩[5,10] − ω_eq| / ω_eq" if r is done[0] else None)
    ax[1].loglog(wall, e_energy, "s", c="C1", label="|F(10) − F_eq| / F_eq" if r is done[0] else None)
    ax[1].annotate(name, (wall, e_omega), fontsize=8)
ax[1].set_title("completed cases: error to the rotating equilibrium at L0", fontsize=9)
ax[1].set_xlabel("wall time to t = 10 [s] (2 cores, one other run beside)"); ax[1].set_ylabel("relative error")
if done:
    ax[1].legend(fontsize=8)
fig.tight_layout(); fig.savefig(here + "/prolate.png", dpi=110)
print("| ref. | unknowns | τ_max | completed | t reached | ⟨ω⟩[5,10] | F(10) | ΔL/L max | ΔA/A max | ΔV/V max | steps | rejected | LU | wall [s] |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    print(f"| {r['refinement']} | {r['unknowns']} | {r['tau_max']} | {'yes' if r['completed'] == '1' else 'no'} | {r['t_reached']} | "
          f"{r['mean_omega']} | {r['final_energy']} | {r['max_angular_momentum_drift']} | {r['max_area_drift']} | "
          f"{r['max_volume_drift']} | {r['steps']} | {r['rejected']} | {r['factorizations']} | {float(r['wall_time_s']):.0f} |")
