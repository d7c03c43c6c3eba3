#!/usr/bin/env python3
"""Reference roots for the quartic solver's accuracy tests.

Writes stability-core/tests/data/quartic_reference.csv: for each case, the
f64 coefficients A..E actually given to the solver (as exact Python float
reprs) and the four roots *of those rounded coefficients* computed with
mpmath at 60 significant digits (mpmath.polyroots, Durand-Kerner with
extra precision; each checked by its residual), printed to 25 digits.

Test sets, after Orellana & De Michele, ACM TOMS Algorithm 1010 (2020), and
Flocke, ACM TOMS Algorithm 954 (2015):
  hard       fixed hard cases in the style of their lists: roots spread
             1e9...1 and 1e53...1e47, nearly equal roots 1.000...1.003, a
             quadruple root at 1000, a double complex pair, close complex
             pairs, a zero root, a typical stability quartic, ...
  real4      four real roots, uniform in [-1, 1]
  pair_real2 one complex pair and two real roots, parts uniform in [-1, 1]
  pairs2     two complex pairs, parts uniform in [-1, 1]
  real4_s, pair_real2_s, pairs2_s
             the same, each root (pair) multiplied by 10**u, u uniform in
             [0, 6]: magnitudes spread over six decades
  stability  two complex pairs shaped like aircraft modes: short period
             |lambda| in [1, 20], phugoid |lambda| in [0.005, 0.2]

Deterministic (seeded). Run from the repository root:
  python3 scripts/quartic_reference.py
"""
import csv
import random

import mpmath as mp

mp.mp.dps = 60
OUT = "stability-core/tests/data/quartic_reference.csv"
N_RANDOM = 400


def coeffs_from_roots(roots):
    """Monic coefficients [1, B, C, D, E] in high precision."""
    c = [mp.mpc(1)]
    for r in roots:
        c = [c[0]] + [c[i] - r * c[i - 1] for i in range(1, len(c))] + [-r * c[-1]]
    return [mp.re(x) for x in c]


def ref_roots(coeffs):
    """Roots of the float coefficients, at 60 digits."""
    cs = [mp.mpf(x) for x in coeffs]
    for extra in (200, 800, 3000):
        try:
            roots, err = mp.polyroots(cs, maxsteps=2000, extraprec=extra, error=True)
        except mp.libmp.libhyper.NoConvergence:
            continue
        if err < mp.mpf(10) ** -40:
            return roots
    raise RuntimeError("no convergence for %r" % (coeffs,))


def rand_real(rng):
    return mp.mpf(rng.uniform(-1, 1))


def rand_pair(rng):
    z = mp.mpc(rng.uniform(-1, 1), abs(rng.uniform(-1, 1)) or 0.5)
    return [z, mp.conj(z)]


def scale(rng, roots, spread):
    if not spread:
        return roots
    k = mp.mpf(10) ** mp.mpf(rng.uniform(0, 6))
    return [r * k for r in roots]


def case_real4(rng, spread):
    return sum((scale(rng, [rand_real(rng)], spread) for _ in range(4)), [])


def case_pair_real2(rng, spread):
    return scale(rng, rand_pair(rng), spread) + scale(rng, [rand_real(rng)], spread) + scale(rng, [rand_real(rng)], spread)


def case_pairs2(rng, spread):
    return scale(rng, rand_pair(rng), spread) + scale(rng, rand_pair(rng), spread)


def case_stability(rng):
    def pair(lo, hi):
        mod = mp.mpf(10) ** mp.mpf(rng.uniform(mp.log10(lo), mp.log10(hi)))
        zeta = mp.mpf(rng.uniform(-0.2, 0.9))
        z = mod * mp.mpc(-zeta, mp.sqrt(1 - zeta * zeta))
        return [z, mp.conj(z)]
    return pair(1, 20) + pair(0.005, 0.2)


def hard_cases():
    j = mp.mpc(0, 1)
    cases = [
        ("spread 1e9..1", [1e9, 1e6, 1e3, 1]),
        ("spread 1e53..1e47", [1e53, 1e50, 1e49, 1e47]),
        ("1e14, 2, 1, -1", [1e14, 2, 1, -1]),
        ("-2e7, 1e7, 1, -1", [-2e7, 1e7, 1, -1]),
        ("-7, -4, -1e6, -1e-6", [-7, -4, -1e6, mp.mpf("-1e-6")]),
        ("nearly equal 1.000..1.003", [1, mp.mpf("1.001"), mp.mpf("1.002"), mp.mpf("1.003")]),
        ("nearly equal 2.000..2.003", [2, mp.mpf("2.001"), mp.mpf("2.002"), mp.mpf("2.003")]),
        ("quadruple root 1000", [1000, 1000, 1000, 1000]),
        ("double complex pair 1+i", [1 + j, 1 - j, 1 + j, 1 - j]),
        ("close complex pairs", [1 + j, 1 - j, mp.mpf("1.0001") + j, mp.mpf("1.0001") - j]),
        ("pairs 1e3 +- i and 1e-3 +- i", [1000 + j, 1000 - j, mp.mpf("1e-3") + j, mp.mpf("1e-3") - j]),
        ("pairs far apart 1e5(1 +- i), 1e-5(1 +- i)", [mp.mpf(1e5) * (1 + j), mp.mpf(1e5) * (1 - j), mp.mpf("1e-5") * (1 + j), mp.mpf("1e-5") * (1 - j)]),
        ("pure imaginary pairs +-i, +-2i", [j, -j, 2 * j, -2 * j]),
        ("zero root", [0, 1, 2, 3]),
        ("two zero roots", [0, 0, -1 + 2 * j, -1 - 2 * j]),
        ("tailless delta, mu1 = 50", [mp.mpc(-6.84, 17.4), mp.mpc(-6.84, -17.4), mp.mpc(-0.0031, 0.18), mp.mpc(-0.0031, -0.18)]),
        ("divergent short period", [mp.mpc(0.3, 9), mp.mpc(0.3, -9), mp.mpc(-0.01, 0.1), mp.mpc(-0.01, -0.1)]),
        ("split phugoid", [mp.mpc(-2, 8), mp.mpc(-2, -8), mp.mpf("0.002"), mp.mpf("-0.04")]),
        ("biquadratic x^4 - 5x^2 + 4", [1, -1, 2, -2]),
        ("tiny imaginary parts 1 +- 1e-7 i, 3 +- 1e-7 i", [1 + mp.mpf("1e-7") * j, 1 - mp.mpf("1e-7") * j, 3 + mp.mpf("1e-7") * j, 3 - mp.mpf("1e-7") * j]),
        ("large real part, small imaginary 1e6 +- i", [mp.mpf(1e6) + j, mp.mpf(1e6) - j, -1, -2]),
        ("roots 1e-8 apart near 1 (pair of doubles)", [1, 1 + mp.mpf("1e-8"), 5, 5 + mp.mpf("1e-8")]),
        ("x^4 - 1", [1, -1, j, -j]),
        ("scaled 1e-30", [mp.mpf("1e-30"), mp.mpf("2e-30"), mp.mpf("3e-30"), mp.mpf("4e-30")]),
    ]
    return [(name, [mp.mpc(r) for r in roots]) for name, roots in cases]


def main():
    rng = random.Random(20261123)
    rows = []
    for name, roots in hard_cases():
        rows.append(("hard", name, roots))
    for set_name, gen in [
        ("real4", lambda: case_real4(rng, False)),
        ("pair_real2", lambda: case_pair_real2(rng, False)),
        ("pairs2", lambda: case_pairs2(rng, False)),
        ("real4_s", lambda: case_real4(rng, True)),
        ("pair_real2_s", lambda: case_pair_real2(rng, True)),
        ("pairs2_s", lambda: case_pairs2(rng, True)),
        ("stability", lambda: case_stability(rng)),
    ]:
        for i in range(N_RANDOM):
            rows.append((set_name, str(i), gen()))

    with open(OUT, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["set", "case", "A", "B", "C", "D", "E"] + [f"r{k}{p}" for k in range(1, 5) for p in ("re", "im")])
        for set_name, case, roots in rows:
            a = rng.choice([1.0, 2.5, -0.75]) if set_name != "hard" else 1.0
            cs = [float(a * x) for x in coeffs_from_roots(roots)]
            ref = ref_roots(cs)
            ref = sorted(ref, key=lambda z: (-abs(z), mp.re(z), -mp.im(z)))
            w.writerow([set_name, case] + [repr(x) for x in cs] + sum(([mp.nstr(mp.re(z), 25), mp.nstr(mp.im(z), 25)] for z in ref), []))
    print("wrote", OUT, len(rows), "cases")


if __name__ == "__main__":
    main()
