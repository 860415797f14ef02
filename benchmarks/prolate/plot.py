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
# Right: ⟨ω⟩ over the window [5, t_c] common to all cases that got past t = 6 (t_c ≤ 10), relative to the case with
# the finest (h, τ) among them, against the wall time each case took to reach t_c (statistics column "wall time").
def mean_between(d, a, b):
    t, w = d["time"], d["angular velocity"]
    s = T = 0.0
    for i in range(1, len(t)):
        x, y = max(t[i - 1], a), min(t[i], b)
        if y > x:
            s += 0.5 * (w[i - 1] + w[i]) * (y - x); T += y - x
    return s / T


runs = {f.split("/")[-1].replace(".statistics", ""): read(f) for f in sorted(glob.glob(here + "/cases/*.statistics"))}
runs = {k: d for k, d in runs.items() if d["time"][-1] > 6}
if len(runs) >= 2:
    tc = min(10.0, min(d["time"][-1] for d in runs.values()))
    key = lambda k: (int(k.split("_")[0][1:]), -float(k.split("tau")[1]))
    finest = max(runs, key=key)
    w_ref = mean_between(runs[finest], 5, tc)
    for k, d in runs.items():
        if k == finest:
            continue
        i = next(i for i, t in enumerate(d["time"]) if t >= tc - 1e-9)
        e = abs(mean_between(d, 5, tc) - w_ref) / w_ref
        ax[1].loglog(d["wall time"][i], e, "o", c="C0")
        ax[1].annotate(k, (d["wall time"][i], e), fontsize=8)
    ax[1].set_title(f"⟨ω⟩[5, {tc:.2f}]: relative difference to {finest} (its wall time to t = {tc:.2f}: "
                    f"{runs[finest]['wall time'][next(i for i, t in enumerate(runs[finest]['time']) if t >= tc - 1e-9)]:.0f} s)",
                    fontsize=8)
    ax[1].set_xlabel("wall time to reach the window's end [s] (2 shared cores)"); ax[1].set_ylabel("relative difference")
fig.tight_layout(); fig.savefig(here + "/prolate.png", dpi=110)
print("| ref. | unknowns | τ_max | completed | t reached | ⟨ω⟩[5,10] | F(10) | ΔL/L max | ΔA/A max | ΔV/V max | steps | rejected | LU | wall [s] |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    print(f"| {r['refinement']} | {r['unknowns']} | {r['tau_max']} | {'yes' if r['completed'] == '1' else 'no'} | {r['t_reached']} | "
          f"{r['mean_omega']} | {r['final_energy']} | {r['max_angular_momentum_drift']} | {r['max_area_drift']} | "
          f"{r['max_volume_drift']} | {r['steps']} | {r['rejected']} | {r['factorizations']} | {float(r['wall_time_s']):.0f} |")
