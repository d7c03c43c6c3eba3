#!/usr/bin/env python3
"""Exact oscillatory supersonic loads for the Mach box tests
(stability_core::aerodynamics::lifting_surface::mach_box, tests/it/supersonic_oscillatory.rs).

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
M.A.C.'s leading edge, as stability_core::aerodynamics::lifting_surface::Solution.

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


def gauss(m):
    """m-point Gauss-Legendre nodes and weights on [0, 1] (Newton on P_m)."""
    out = []
    for k in range(1, m + 1):
        x = mp.cos(mp.pi * (k - mpf(1) / 4) / (m + mpf(1) / 2))
        for _ in range(100):
            p0, p1 = mpf(1), x
            for n in range(2, m + 1):
                p0, p1 = p1, ((2 * n - 1) * x * p1 - (n - 1) * p0) / n
            dp = m * (x * p1 - p0) / (x * x - 1)
            dx = p1 / dp
            x -= dx
            if abs(dx) < mpf(10) ** -(mp.dps + 2):
                break
        out.append(((1 - x) / 2, 1 / ((1 - x * x) * dp * dp)))
    return out


def delta_near_sonic(mach, omega_bar, m=12):
    """delta() for kernels of many radians along the chord (near M = 1):
    the same integrals by composite Gauss-Legendre on pieces of at most one
    radian of (sigma + nu) s, the inner integrals g0, g1 carried along the
    pieces (each outer node's by its own Gauss rule from the piece's start).
    Checked against delta() where both apply (main)."""
    cbar, xbar = mpf(2) / 3, mpf(1) / 3
    kappa = omega_bar / cbar
    beta = sqrt(mach * mach - 1)
    g = kernel(mach, kappa)
    rate = kappa * mach * (mach + 1) / beta**2
    pieces = int(mp.ceil(rate)) + 4
    rule = gauss(m)
    forward = [lambda s: 1, lambda s: ((1 - s) - xbar) / cbar]
    cl, cm = [mpc(0), mpc(0)], [mpc(0), mpc(0)]
    G0, G1 = mpc(0), mpc(0)

    def dcp(a, b, s, g0, g1):
        phi = a * g0 + b * (s * g0 - g1)
        return 4 / beta * (1j * kappa * phi + a * g(s) + b * g0)

    for k in range(pieces):
        l, h = mpf(k) / pieces, mpf(1) / pieces
        for t, w in rule:
            s = l + h * t
            # g0, g1 from l to s
            d0 = sum(wi * g(l + h * t * ti) for ti, wi in rule) * h * t
            d1 = sum(wi * (l + h * t * ti) * g(l + h * t * ti) for ti, wi in rule) * h * t
            g0, g1 = G0 + d0, G1 + d1
            lift = dcp(1, 0, s, g0, g1)
            pitch = dcp(1 - xbar, -1, s, g0, g1)
            for i, wf in enumerate(forward):
                cl[i] += 2 * lift * wf(s) * (1 - s) * w * h
                cm[i] += -2 / cbar * pitch * wf(s) * (1 - s) * w * h
        G0 += sum(wi * g(l + h * ti) for ti, wi in rule) * h
        G1 += sum(wi * (l + h * ti) * g(l + h * ti) for ti, wi in rule) * h
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
    # near M = 1 at the short period's frequencies, where the kernel turns
    # through 10-30 radians along the chord (a delta of sweep under 17
    # degrees keeps its leading edge supersonic at M = 1.03); the composite
    # rule first checked against delta() at M = 1.6, omega_bar = 1
    a, b = delta(mpf(1.6), mpf(1.0)), delta_near_sonic(mpf(1.6), mpf(1.0))
    assert all(abs(a[k] - b[k]) < 1e-12 * (1 + abs(a[k])) for k in a), (a, b)
    for mach in ["1.03", "1.05"]:
        for omega_bar in ["0.6", "1.0"]:
            cases.append({"wing": "delta", "mach": float(mach), "omega_bar": float(omega_bar),
                          **delta_near_sonic(mpf(mach), mpf(omega_bar))})
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
