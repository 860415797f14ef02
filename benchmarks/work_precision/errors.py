# SPDX-License-Identifier: LGPL-2.1-or-later
"""benchmarks/work_precision: errors of each variant against the reference run. Arguments: the work folder, the
end time, the reference's variant name, the variant names (the reference among them). One CSV row per variant."""
import os
import sys

from run_records import interpolate, statistics_columns, summary as read_summary

work, end, reference_name, variants = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4:]


def summary(name):
    return read_summary(os.path.join(work, name))


grid = [0.25 * k for k in range(1, int(round(end / 0.25)) + 1)]
reference = statistics_columns.read(os.path.join(work, reference_name, "statistics"))
ref_sum = summary(reference_name)
try:
    ref_tsym = float(ref_sum.get("t_sym_1e-2", "nan"))
except ValueError:
    ref_tsym = float("nan")
# The phases of the oblate: 1 the relaxation (t ≤ 1), 2 the rotating state while e(λ) grows (1 < t ≤ 2.5), 3 the
# symmetry breaking and the transformation (t > 2.5). e(λ) is compared in its linear phase only, 1 < t ≤ t_sym_1e-2 of the reference (later
# a small shift in time is a large relative difference of a quantity that changes by decades).
phases = [(0, 1), (1, 2.5), (2.5, end)]
quantities = [("F", "total energy"), ("omega", "angular velocity")]
header = ["variant", "status", "t reached", "steps", "rejected", "LU factorizations", "wall s"]
header += [f"error {key} phase {k + 1}" for key, _ in quantities for k in range(len(phases))]
header += ["error e linear phase", "t_sym_1e-2", "error t_sym_1e-2"]
print(",".join(header))
for v in variants:
    try:
        c = statistics_columns.read(os.path.join(work, v, "statistics"))
        s = summary(v)
    except OSError:
        print(f"{v},missing" + "," * (len(header) - 2))
        continue

    def worst(name, lo, hi, relative_to_self=False):
        w, scale = 0.0, max(abs(x) for x in reference[name])
        for g in grid:
            if not lo < g <= hi:
                continue
            a, b = interpolate(c["time"], c[name], g), interpolate(reference["time"], reference[name], g)
            if a is None or b is None:
                return float("nan")
            w = max(w, abs(a - b) / (abs(b) if relative_to_self else scale))
        return w

    errors = [worst(name, lo, hi) for _, name in quantities for lo, hi in phases]
    errors.append(worst("symmetry deviation", 1, ref_tsym, relative_to_self=True))
    tsym = s.get("t_sym_1e-2", "never")
    try:
        etsym = f"{abs(float(tsym) - ref_tsym) / ref_tsym:.3e}"
    except ValueError:
        etsym = ""
    print(f"{v},{s.get('status', '').split(':')[0]},{c['time'][-1]:.4g},{s.get('steps', '')},{s.get('rejected steps', '')},"
          f"{s.get('LU factorizations', '')},{float(s.get('wall time', 'nan')):.1f},"
          + ",".join(f"{e:.3e}" for e in errors) + f",{tsym},{etsym}")
