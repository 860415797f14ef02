# F rises per interval from the statistics file alone (F = total energy, D = dissipation rate of the step's row).
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "phase3"))
import statistics_columns
run = sys.argv[1]; ivs = [tuple(map(float, a.split(","))) for a in sys.argv[2:]]
c = statistics_columns.read(run + "/statistics")
t, F, D, tau = c["time"], c["total energy"], c["dissipation rate"], c["tau"]
q, s, mu = c["mesh quality"], c["symmetry deviation"], c["rigid multiplier"]
for a, b in ivs:
    J = [j for j in range(1, len(t)) if a < t[j] <= b + 1e-12]
    dF = F[J[-1]] - F[J[0] - 1]; iD = sum(tau[j] * D[j] for j in J)
    up = sum(1 for j in J if F[j] > F[j - 1]); jm = max(J, key=lambda j: F[j])
    print(f"{run} ({a},{b}] steps={len(J)} F {F[J[0]-1]:.6f}->{F[J[-1]]:.6f} dF={dF:+.4e} intD={iD:.4e} dB={dF+iD:+.4e} "
          f"rising={up} maxF={F[jm]:.6f}@{t[jm]:.3f} maxstepdF={max(F[j]-F[j-1] for j in J):+.2e} "
          f"quality {q[J[0]-1]:.3f}->{q[J[-1]]:.3f} symdev {s[J[0]-1]:.1e}->{s[J[-1]]:.1e} max|mu|={max(mu[j] for j in J):.2f}")
