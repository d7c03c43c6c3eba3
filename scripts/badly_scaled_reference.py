#!/usr/bin/env python3
"""Reference roots of badly scaled stability quartics (issue 10: fuzzing
found wrong roots with exit 0 for inputs beyond about 1e54 or below 1e-150).

Writes stability-core/tests/data/badly_scaled.csv in the format of
quartic_reference.csv (set, name, A..E, four roots re/im), for:
  inputs   the README's tailless delta (stability_core::design::examples::
           tailless_delta_45) with one input set to an extreme value
           (±1e60, ±1e250, ±1e-160, ±1e-300); the f64 coefficients come
           from the generated code, through
           `cargo run -p stability-core --example quartic_coefficients`;
  scaled   that aircraft's quartic under lambda -> rho*lambda and an overall
           factor sigma (powers of ten, so rounded), for rho, sigma across
           f64's range;
  wide     products of factors of widely different sizes.
The roots are of the f64 coefficients as given, by mpmath.polyroots at
high precision (each checked by its residual), printed to 25 digits.
Cases whose coefficients overflow, or whose roots leave f64's range, are
skipped (the solver reports those as errors; tests/it/badly_scaled.rs checks
that separately).

Run from the repository root:  python3 scripts/badly_scaled_reference.py
"""
import csv
import subprocess

import mpmath as mp

OUT = "stability-core/tests/data/badly_scaled.csv"
NAMES = ["x_u", "x_w", "x_wdot", "x_q", "z_u", "z_w", "z_wdot", "z_q",
         "m_u", "m_w", "m_wdot", "m_q", "c_l", "mu1", "i_b"]
BASE = [-0.03, 0.25, 0.0, 0.0, -0.62, -3.2, -0.6, -1.5,
        0.0, -0.55, -0.25, -0.6, 0.3, 50.0, 0.08]
EXTREMES = ["1e60", "-1e60", "1e250", "-1e250", "1e-160", "-1e-160", "1e-300", "-1e-300"]


def coefficients(sets):
    text = "\n".join(" ".join(repr(float(x)) for x in s) for s in sets) + "\n"
    out = subprocess.run(
        ["cargo", "run", "-q", "-p", "stability-core", "--example", "quartic_coefficients"],
        input=text, capture_output=True, text=True, check=True).stdout
    return [[float(x) for x in line.split()] for line in out.splitlines()]


def ref_roots(coeffs):
    """The eigenvalues of the companion matrix at 1600 digits (mpmath's QR;
    the digits cover any spread of f64 magnitudes), each polished by Newton
    steps and checked by its residual relative to sum |c_k||z|^(4-k)."""
    mp.mp.dps = 1600
    cs = [mp.mpf(x) for x in coeffs]
    a = mp.matrix(4, 4)
    for j in range(4):
        a[0, j] = -cs[j + 1] / cs[0]
    for i in range(1, 4):
        a[i, i - 1] = 1
    roots = []
    for z in mp.eig(a, left=False, right=False):
        for _ in range(8):
            d = mp.polyval(cs, z, derivative=True)
            if d[1] == 0:
                break
            z = z - d[0] / d[1]
        den = sum(abs(c) * abs(z) ** (4 - k) for k, c in enumerate(cs))
        if den != 0 and abs(mp.polyval(cs, z)) / den > mp.mpf(10) ** -200:
            raise RuntimeError(f"residual of {z} for {coeffs}")
        if abs(mp.im(z)) <= mp.mpf(10) ** -1000 * abs(z):
            z = mp.mpc(mp.re(z), 0)
        roots.append(z)
    return roots


def representable(z):
    m = max(abs(mp.re(z)), abs(mp.im(z)))
    return m == 0 or (mp.mpf("2.3e-308") <= m <= mp.mpf("1.7e308"))


def main():
    cases = []
    sets, names = [], []
    for i, n in enumerate(NAMES):
        for v in EXTREMES:
            if n in ("mu1", "i_b") and v.startswith("-"):
                continue
            s = list(BASE)
            s[i] = float(v)
            sets.append(s)
            names.append(f"{n} = {v}")
    for name, c in zip(names, coefficients(sets)):
        cases.append(("inputs", name, c))
    base = coefficients([BASE])[0]
    for rho in ["1e-150", "1e-75", "1e-30", "1e30", "1e75", "1e150"]:
        for sig in ["1e-280", "1e-150", "1", "1e150", "1e280"]:
            r, s = mp.mpf(rho), mp.mpf(sig)
            c = [float(mp.mpf(base[k]) * r ** (4 - k) * s) for k in range(5)]
            cases.append(("scaled", f"rho = {rho}, sigma = {sig}", c))
    wide = [
        ("1e160 beside 7 and 0.1", [mp.mpf("-1e160"), mp.mpf(-7), mp.mpf("-0.1"), mp.mpf(-2)]),
        ("1e200 pair beside a 1e-100 pair",
         [mp.mpc("-1e199", "1e200"), mp.mpc("-1e199", "-1e200"), mp.mpc("-1e-101", "1e-100"), mp.mpc("-1e-101", "-1e-100")]),
        ("1e150, 1, 1e-150, 2e-150", [mp.mpf("1e150"), mp.mpf(1), mp.mpf("-1e-150"), mp.mpf("2e-150")]),
        ("1e300 and three near 1", [mp.mpf("1e300"), mp.mpf(-1), mp.mpc(-1, 1), mp.mpc(-1, -1)]),
    ]
    for name, roots in wide:
        c = [mp.mpc(1)]
        for z in roots:
            c = [c[0]] + [c[i] - z * c[i - 1] for i in range(1, len(c))] + [-z * c[-1]]
        cases.append(("wide", name, [float(mp.re(x)) for x in c]))
    with open(OUT, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["set", "name", "A", "B", "C", "D", "E"] +
                   [f"{p}{k}" for k in range(1, 5) for p in ("re", "im")])
        kept = 0
        for set_, name, c in cases:
            if not all(mp.isfinite(x) for x in c) or c[0] == 0 or all(x == 0 for x in c[1:]):
                continue
            r = ref_roots(c)
            if not all(representable(z) for z in r):
                continue
            row = [set_, name] + [repr(x) for x in c]
            for z in r:
                row += [mp.nstr(mp.re(z), 25), mp.nstr(mp.im(z), 25)]
            w.writerow(row)
            kept += 1
    print(f"wrote {kept} cases to {OUT}")


if __name__ == "__main__":
    main()
