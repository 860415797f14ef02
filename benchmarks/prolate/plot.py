"""benchmarks/prolate: ω(t) of every case, and the error of ⟨ω⟩[5, 10] and F(10) against wall time, relative to the
finest completed case (results.csv, cases/*.statistics) → prolate.png; prints the README table."""
import csv, glob
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = "benchmarks/prolate"


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
ref = max(done, key=lambda r: (int(r["refinement"]), -float(r["tau_max"]))) if done else None
fig, ax = plt.subplots(1, 2, figsize=(11, 4))
for f in sorted(glob.glob(here + "/cases/*.statistics")):
    d = read(f)
    ax[0].plot(d["time"], d["angular velocity"], label=f.split("/")[-1].replace(".statistics", ""))
ax[0].axhline(3.2455522821, ls=":", c="k", label="equilibrium at L0 (ω = 3.2456)")
ax[0].set_xlabel("t"); ax[0].set_ylabel("ω(t)"); ax[0].legend(fontsize=8)
if ref:
    for r in done:
        if r is ref:
            continue
        w = float(r["wall_time_s"])
        ax[1].loglog(w, abs(float(r["mean_omega"]) - float(ref["mean_omega"])) / float(ref["mean_omega"]), "o", c="C0")
        ax[1].loglog(w, abs(float(r["final_energy"]) - float(ref["final_energy"])) / float(ref["final_energy"]), "s", c="C1")
        ax[1].annotate(f"r{r['refinement']} τ≤{r['tau_max']}", (w, abs(float(r["mean_omega"]) - float(ref["mean_omega"])) / float(ref["mean_omega"])), fontsize=8)
    ax[1].plot([], [], "o", c="C0", label="⟨ω⟩[5,10]"); ax[1].plot([], [], "s", c="C1", label="F(10)")
    ax[1].set_title(f"relative difference to r{ref['refinement']} τ≤{ref['tau_max']}", fontsize=9)
    ax[1].set_xlabel("wall time [s] (2 shared cores)"); ax[1].set_ylabel("relative difference"); ax[1].legend()
fig.tight_layout(); fig.savefig(here + "/prolate.png", dpi=110)
print("| ref. | unknowns | τ_max | completed | t reached | ⟨ω⟩[5,10] | F(10) | ΔL/L max | ΔA/A max | ΔV/V max | steps | rejected | LU | wall [s] |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    print(f"| {r['refinement']} | {r['unknowns']} | {r['tau_max']} | {'yes' if r['completed'] == '1' else 'no'} | {r['t_reached']} | "
          f"{r['mean_omega']} | {r['final_energy']} | {r['max_angular_momentum_drift']} | {r['max_area_drift']} | "
          f"{r['max_volume_drift']} | {r['steps']} | {r['rejected']} | {r['factorizations']} | {float(r['wall_time_s']):.0f} |")
