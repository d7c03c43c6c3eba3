#!/usr/bin/env python3
"""The reason for supersonic::transonic::LOW_FREQUENCY_LIMIT.

Linear supersonic theory to first order in frequency (the report's eq 36,
and stability_core::aerodynamics::supersonic) replaces the oscillatory kernel by its
low-frequency expansion.  For a two-dimensional flat plate the exact
oscillatory theory is known in closed form (I.E. Garrick and S.I. Rubinow,
NACA Rep. 846, 1946):

    Phi(x) = -(1/beta) * int_0^x w(xi) exp(-i lam (x - xi)) J0(mu (x - xi)) dxi,
    lam = omega M^2 / beta^2,  mu = omega M / beta^2   (V = c = 1),

and Delta C_p = 4 (i omega Phi + Phi_x).  This script plunges the plate
(w = -1) and compares the quadrature ("damping") part of the lift and of the
pitching moment about mid-chord, divided by omega, with the first-order
values z_wdot = 2/beta^3 and 1/(3 beta^3), as functions of the kernel phase
across the chord, kappa = omega c M^2 / beta^2.  The ratio depends on kappa
alone to within about 1 %; at kappa = 0.5 the lift is within 5 % and the
moment within 9 %.  The Rust test
`the_low_frequency_limit_is_where_the_exact_plate_says` (tests/it/supersonic.rs)
repeats the kappa = 0.5 row independently.

Usage: python3 scripts/supersonic_low_frequency.py   (numpy, scipy)
"""
import numpy as np
from scipy.integrate import quad
from scipy.special import j0


def plate(mach, omega):
    b2 = mach * mach - 1.0
    beta = np.sqrt(b2)
    lam, mu = omega * mach * mach / b2, omega * mach / b2
    kern = lambda x: np.exp(-1j * lam * x) * j0(mu * x) / beta

    def phi(x):
        re = quad(lambda s: kern(s).real, 0.0, x, limit=200)[0]
        im = quad(lambda s: kern(s).imag, 0.0, x, limit=200)[0]
        return re + 1j * im

    xs, ws = np.polynomial.legendre.leggauss(40)
    xs, ws = (xs + 1) / 2, ws / 2
    dcp = np.array([4 * (1j * omega * phi(x) + kern(x)) for x in xs])
    lift = np.sum(ws * dcp)
    moment_mid = -np.sum(ws * dcp * (xs - 0.5))
    return lift, moment_mid


def main():
    print("   M   kappa   omega   lift ratio   moment ratio (about mid-chord)")
    for mach in [1.05, 1.1, 1.2, 1.5, 2.0]:
        b = np.sqrt(mach * mach - 1.0)
        for kappa in [0.1, 0.25, 0.5, 0.75, 1.0]:
            omega = kappa * b * b / (mach * mach)
            lift, mom = plate(mach, omega)
            lq = -lift.imag / omega / (2 / b**3)
            mq = mom.imag / omega / (1 / (3 * b**3))
            print(f"{mach:5.2f} {kappa:6.2f} {omega:7.4f}   {lq:8.4f}     {mq:8.4f}")


if __name__ == "__main__":
    main()
