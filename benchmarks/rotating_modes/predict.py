#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Predicted measured growth rate of a seeded mode lambda = sigma + i*nu_seen under backward Euler and constant-step
BDF2 (issue #33), stdlib only.

A mode that the mesh sees oscillating at nu_seen, with true rate sigma, is treated as the Dahlquist test equation
y' = lambda*y, lambda = sigma + i*nu_seen.  Per step the amplitude is multiplied by z:
  BE:   z = 1/(1 - lambda*tau)
  BDF2: (3/2 z^2 - 2 z + 1/2)/tau = lambda z^2  ->  (3 - 2 lambda tau) z^2 - 4 z + 1 = 0,
        principal root z = (2 + sqrt(1 + 2 lambda tau)) / (3 - 2 lambda tau)   (z -> 1 as tau -> 0)
  SDIRK2 (gamma = 1 - 1/sqrt(2)): z = (1 + (1 - 2 gamma) lambda tau) / (1 - gamma lambda tau)^2
and the measured rate is ln|z| / tau.

nu_seen:
  co-rotating frame (mesh turns with the body, or a frame at Omega): nu (the table's co-rotating frequency)
  lab frame, mesh at rest (law reference: R = 0 for an axisymmetric spin):
     '+'  nu + m*Omega   (fit_modes.py: frequency = d arg Q_m/dt - m<omega>, so the lab turning is nu + m<omega>;
                          physically consistent for both shapes: |nu| < m*Omega, the pattern lags the body)
     '-'  nu - m*Omega   (= m*Omega + |nu| here; the convention that reproduces the issue's *prolate* numbers)
"""
import cmath
import math

MODES = [  # name, m, sigma (linearized, r3, tau=0.02), co-rotating nu, Omega of the body
    ("oblate m=2 even", 2, 2.5714, -2.533, 4.034),
    ("prolate m=1 even", 1, 1.2114, -0.798, 3.2456),
    ("prolate m=2 even", 2, 0.6570, -1.419, 3.2456),
]
TAUS = [0.1, 0.05, 0.025, 0.0125]


def rate_be(lam, tau):
    return math.log(abs(1.0 / (1.0 - lam * tau))) / tau


def rate_bdf2(lam, tau):
    z = (2.0 + cmath.sqrt(1.0 + 2.0 * lam * tau)) / (3.0 - 2.0 * lam * tau)
    return math.log(abs(z)) / tau


def rate_sdirk2(lam, tau):
    # the two-stage L-stable SDIRK of order 2, gamma = 1 - 1/sqrt(2): z = (1 + (1 - 2 gamma) l t)/(1 - gamma l t)^2
    gamma = 1.0 - 1.0 / math.sqrt(2.0)
    z = (1.0 + (1.0 - 2.0 * gamma) * lam * tau) / (1.0 - gamma * lam * tau) ** 2
    return math.log(abs(z)) / tau


def table():
    print("predicted measured rate ln|z|/tau  [relative error vs sigma]")
    for name, m, sigma, nu, omega in MODES:
        print(f"\n{name}: sigma = {sigma}, nu (co-rotating) = {nu}, Omega = {omega}, "
              f"nu+m*Omega = {nu + m * omega:.4f}, nu-m*Omega = {nu - m * omega:.4f}")
        print(f"{'tau':>7} | {'frame':<14} | {'BE':>16} | {'BDF2':>16}")
        for tau in TAUS:
            for label, nus in (("co-rotating", nu), ("lab (+)", nu + m * omega), ("lab (-)", nu - m * omega)):
                lam = complex(sigma, nus)
                be, b2 = rate_be(lam, tau), rate_bdf2(lam, tau)
                print(f"{tau:7.4f} | {label:<14} | {be:7.3f} [{(be - sigma) / sigma:+7.1%}] |"
                      f" {b2:7.3f} [{(b2 - sigma) / sigma:+7.1%}]")


def leading_terms():
    # Small-tau expansions of the rate error (checked numerically against rate_be/rate_bdf2 at tau = 1e-3):
    # BE: ln|1/(1-l t)|/t = sigma + Re(l^2) t/2 + O(t^2),  Re(l^2) = sigma^2 - nu^2;
    # BDF2: ln|z|/t = sigma + Re(l^3) t^2/3 + O(t^3),  Re(l^3) = sigma^3 - 3 sigma nu^2.
    print("\nsmall-tau rate error:  BE  (sigma^2 - nu^2) tau / 2;   BDF2  Re(lambda^3) tau^2 / 3")
    for name, m, sigma, nu, omega in MODES:
        for label, nus in (("co-rotating", nu), ("lab (+)", nu + m * omega)):
            lam = complex(sigma, nus)
            print(f"  {name:<17} {label:<12} BE coeff {(sigma ** 2 - nus ** 2) / 2:+8.3f} * tau,"
                  f"  BDF2 coeff {(lam ** 3).real / 3:+8.3f} * tau^2")


def checks():
    print("\nchecks against the issue's quoted numbers (BE):")
    quoted = [("oblate m=2 lab", 2.5714, -2.533 + 2 * 4.034, [(0.05, 1.79), (0.025, 2.22), (0.0125, 2.41)]),
              ("oblate m=2 co-rot", 2.5714, -2.533, [(0.05, 2.54), (0.025, 2.57), (0.0125, 2.57)]),
              ("prolate m=1 lab (+)", 1.2114, -0.798 + 3.2456, [(0.1, 0.33)]),
              ("prolate m=1 lab (-)", 1.2114, -0.798 - 3.2456, [(0.1, 0.33)]),
              ("prolate m=1 co-rot", 1.2114, -0.798, [(0.1, 1.25)])]
    for name, sigma, nus, pts in quoted:
        got = ", ".join(f"tau={t}: {rate_be(complex(sigma, nus), t):.3f} (issue {q})" for t, q in pts)
        print(f"  {name:<20} {got}")
    print("  prolate m=2 lab, BE tau=0.1: (+) %.3f, (-) %.3f  (issue: 'decays')" %
          (rate_be(complex(0.657, -1.419 + 2 * 3.2456), 0.1), rate_be(complex(0.657, -1.419 - 2 * 3.2456), 0.1)))

    print("\nchecks against measured rates in the repository (lab frame, mesh at rest):")
    # benchmarks/step_limit/growth.csv: oblate r3, sigma of e(lambda) on t in [1.5, 2.5], tau_max = tau
    # (all1 = backward Euler with one geometry correction; bdf2 = BDF2 with one correction)
    lam = complex(2.5714, -2.533 + 2 * 4.034)
    for scheme, f, meas in (("all1 (BE)", rate_be, {0.05: 1.8149, 0.025: 2.1479, 0.0125: 2.3416}),
                            ("bdf2", rate_bdf2, {0.05: 2.5505, 0.025: 2.5622, 0.0125: 2.5372})):
        print("  oblate m=2, growth.csv %-9s " % scheme +
              ", ".join(f"tau={t}: measured {v:.3f} predicted {f(lam, t):.3f}" for t, v in meas.items()))
    # benchmarks/spectrum/seeded_modes.csv: BDF2 (one correction), tau_max 0.05 and 0.02, refinement 3
    for name, sigma, nu, m, meas in (("prolate m=1 even", 1.2114, -0.798, 1, {0.05: 1.18502, 0.02: 1.21326}),
                                     ("prolate m=1 odd", 0.5709, -2.375, 1, {0.05: 0.58354, 0.02: 0.57482}),
                                     ("prolate m=2 even", 0.6570, -1.419, 2, {0.05: 0.42528, 0.02: 0.64899})):
        for label, nus in (("(+)", nu + m * 3.2456), ("(-)", nu - m * 3.2456)):
            print(f"  {name}, seeded BDF2 {label} " + ", ".join(
                f"tau={t}: measured {v:.3f} predicted {rate_bdf2(complex(sigma, nus), t):.3f}" for t, v in meas.items()))


def frequency_bdf2(lam, tau):
    z = (2.0 + cmath.sqrt(1.0 + 2.0 * lam * tau)) / (3.0 - 2.0 * lam * tau)
    return cmath.phase(z) / tau


def frequencies():
    print("\npredicted measured co-rotating frequency (arg z / tau - m*Omega for the lab (+) frame), BDF2 and BE:")
    for name, m, sigma, nu, omega in MODES:
        lab = complex(sigma, nu + m * omega)
        row = ", ".join(f"tau={t}: BDF2 {frequency_bdf2(lab, t) - m * omega:+.3f}"
                        f" BE {cmath.phase(1 / (1 - lab * t)) / t - m * omega:+.3f}" for t in TAUS)
        print(f"  {name:<17} (true {nu}): {row}")
    print("  measured (seeded_modes.csv, BDF2 lab): prolate m=2 even tau_max 0.05 -> -1.987, 0.02 -> -1.440;"
          " prolate m=1 even 0.05 -> -0.827")


if __name__ == "__main__":
    table()
    leading_terms()
    checks()
    frequencies()
