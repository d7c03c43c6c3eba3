#!/usr/bin/env python3
"""High-precision references for stability-core's lifting-surface tests.

Writes stability-core/tests/data/lifting_surface/reference.json with
- I1(u1, k1) = int_{u1}^inf exp(-i k1 u) (1 + u^2)^(-3/2) du (the kernel
  integral of Landahl/Albano-Rodden) by mpmath.quadosc at 30 digits;
- Theodorsen's function C(k) = F + iG = H1(k)/(H1(k) + i H0(k)), H the Hankel
  functions of the second kind (T. Theodorsen, "General theory of aerodynamic
  instability and the mechanism of flutter", NACA Report 496, 1935), at the
  reduced frequencies k = omega b / V (b the semi-chord) the tests use.

Run: python3 -m venv /tmp/v && /tmp/v/bin/pip install mpmath &&
     /tmp/v/bin/python scripts/lifting_surface_reference.py
"""
import json
import os

import mpmath as mp

mp.mp.dps = 30


def i1(u, k):
    f = lambda v: mp.exp(-1j * k * v) * (1 + v * v) ** (-1.5)
    if k == 0:
        return mp.quad(f, [u, mp.inf])
    return mp.quadosc(f, [u, mp.inf], omega=k)


def theodorsen(k):
    h1 = mp.hankel2(1, k)
    h0 = mp.hankel2(0, k)
    return h1 / (h1 + 1j * h0)


def main():
    out = {"source": "scripts/lifting_surface_reference.py (mpmath, 30 digits)"}
    out["i1"] = [
        {"u1": u, "k1": k, "re": float(mp.re(v)), "im": float(mp.im(v))}
        for u in [0.0, 0.5, 2.0, 10.0, -1.5]
        for k in [0.0, 0.3, 2.0, 10.0]
        for v in [i1(u, k)]
    ]
    out["theodorsen"] = [
        {"k": k, "F": float(mp.re(c)), "G": float(mp.im(c))}
        for k in [0.1, 0.2, 0.5, 1.0]
        for c in [theodorsen(k)]
    ]
    path = os.path.join(
        os.path.dirname(__file__), "..", "stability-core", "tests", "data",
        "lifting_surface", "reference.json")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")
    print("wrote", os.path.normpath(path))


if __name__ == "__main__":
    main()
