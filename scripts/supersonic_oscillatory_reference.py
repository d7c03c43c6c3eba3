#!/usr/bin/env python3
"""Exact oscillatory supersonic loads for the Mach box tests
(stability_core::supersonic::oscillatory, tests/supersonic_oscillatory.rs).

Two-dimensional flat plate (I.E. Garrick and S.I. Rubinow, NACA Rep. 846,
1946), normalwash wbar(s) (positive down, per unit V), s from the leading
edge, harmonic e^{i omega t}:

    Phi(s) = beta * phi/V = int_0^s wbar(s - u) g(u) du,
    g(u) = exp(-i sigma u) J0(nu u),
    sigma = kappa M^2/beta^2, nu = kappa M/beta^2, kappa = omega/V,
    Delta C_p = (4/beta) (i kappa Phi + dPhi/ds).

True delta with supersonic leading edges (beta cot Lambda > 1), root chord 1,
by the reverse-flow theorem (H.J. Flax, J. Aero. Sci. 19, 1952): the lift
and moment of the forward wing's normalwash w_F are
int int Delta C_p^R[w_R] w_F dS with the reversed wing's loads for w_R = 1
and w_R = x - xbar; in reversed flow every chordwise strip is the 2-D plate
above with s = 1 - x (the forward Mach cone of a reversed-flow point stays
on the wing), so with the span 2 cot(Lambda) (1 - s) at s and S = cot(Lambda)
everything is a 1-D integral, independent of the sweep:

    C_L[w_F] = 2 int_0^1 DCp^R[1](s) w_F(1 - s) (1 - s) ds,
    C_m[w_F] = -(2/cbar) int_0^1 DCp^R[(1 - xbar) - s](s) w_F(1 - s) (1 - s) ds,

cbar = 2/3, xbar = 1/3 (the M.A.C. and its leading edge), w_F = 1
(incidence) and (x - xbar)/cbar (unit rate); moments nose up about the
M.A.C.'s leading edge, as stability_core::lifting_surface::Solution.

The plate (chord 1, cbar = 1, xbar = 0) directly, and its reverse-flow value
as a check of the theorem's use (asserted below).

Output: tests/data/supersonic_oscillatory/reference.json, per case the six
numbers of a Solution: lift_alpha = Re C_L[1], lift_alphadot =
Im C_L[1]/omega_bar, moment_alpha, moment_alphadot likewise, lift_q =
Re C_L[rate], moment_q = Re C_m[rate].

Usage: python3 scripts/supersonic_oscillatory_reference.py   (mpmath)
"""
import json
import os
from mpmath import mp, mpf, quad, besselj, exp, mpc, sqrt

mp.dps = 20


def kernel(mach, kappa):
    b2 = mach * mach - 1
    sigma, nu = kappa * mach * mach / b2, kappa * mach / b2
    return lambda u: exp(-1j * sigma * u) * besselj(0, nu * u)


def load(mach, kappa, a, b):
    """Delta C_p(s) of the plate for wbar = a + b s."""
    beta = sqrt(mach * mach - 1)
    g = kernel(mach, kappa)

    def dcp(s):
        if s == 0:
            return 4 / beta * (a * g(0))
        g0 = quad(g, [0, s])
        g1 = quad(lambda u: u * g(u), [0, s])
        phi = a * g0 + b * (s * g0 - g1)
        dphi = a * g(s) + b * g0
        return 4 / beta * (1j * kappa * phi + dphi)

    return dcp


def solution(cl, cm, omega_bar):
    return {
        "lift_alpha": float(cl[0].real),
        "lift_alphadot": float(cl[0].imag / omega_bar),
        "moment_alpha": float(cm[0].real),
        "moment_alphadot": float(cm[0].imag / omega_bar),
        "lift_q": float(cl[1].real),
        "moment_q": float(cm[1].real),
    }


def delta(mach, omega_bar):
    cbar, xbar = mpf(2) / 3, mpf(1) / 3
    kappa = omega_bar / cbar
    lift = load(mach, kappa, 1, 0)
    pitch = load(mach, kappa, 1 - xbar, -1)
    forward = [lambda s: 1, lambda s: ((1 - s) - xbar) / cbar]
    cl = [2 * quad(lambda s: lift(s) * w(s) * (1 - s), [0, 1]) for w in forward]
    cm = [-2 / cbar * quad(lambda s: pitch(s) * w(s) * (1 - s), [0, 1]) for w in forward]
    return solution(cl, cm, omega_bar)


def plate(mach, omega_bar):
    kappa = mpf(omega_bar)
    cl, cm = [], []
    for a, b in [(1, 0), (0, 1)]:
        p = load(mach, kappa, a, b)
        cl.append(quad(p, [0, 1]))
        cm.append(-quad(lambda s: s * p(s), [0, 1]))
    # reverse flow: C_L for wbar = s equals int DCp^R[1](1 - s) s ds
    lift = load(mach, kappa, 1, 0)
    reverse = quad(lambda r: lift(r) * (1 - r), [0, 1])
    assert abs(reverse - cl[1]) < mpf(10) ** -12, (reverse, cl[1])
    return solution(cl, cm, omega_bar)


def main():
    cases = []
    for mach in [1.6, 2.5]:
        for omega_bar in [0.01, 0.25, 0.5, 1.0]:
            cases.append({"wing": "delta", "mach": mach, "omega_bar": omega_bar,
                          **delta(mpf(mach), mpf(omega_bar))})
            print(cases[-1])
    for mach in [2.5]:
        for omega_bar in [0.25, 1.0]:
            cases.append({"wing": "plate", "mach": mach, "omega_bar": omega_bar,
                          **plate(mpf(mach), mpf(omega_bar))})
            print(cases[-1])
    here = os.path.dirname(os.path.abspath(__file__))
    out = os.path.join(here, "..", "stability-core", "tests", "data",
                       "supersonic_oscillatory", "reference.json")
    with open(out, "w") as f:
        json.dump({"source": "scripts/supersonic_oscillatory_reference.py",
                   "cases": cases}, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
