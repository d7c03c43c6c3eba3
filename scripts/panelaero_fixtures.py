#!/usr/bin/env python3
"""Oscillatory derivatives from panelaero (DLR's public doublet-lattice code,
`pip install panelaero`) for the lifting-surface tests.

Writes stability-core/tests/data/lifting_surface/panelaero.json. For each case
the wing (root chord 1, the note's Planform: unswept trailing edge) is cut into
the same lattice that stability-core builds with Extrapolation::None —
strips spaced as its Spacing says (edges at the spacing's equal steps,
collocation station at the step's mid-point), `chordwise` equal boxes per
strip, doublet line at the quarter chord of each box, collocation point at
three-quarters of the local box chord — here for the whole wing (both
halves, panels defined left to right as panelaero asks). panelaero's
calc_Qjj(aerogrid, Ma, k, method='quartic') (Rodden, Taylor & McIntosh's
quartic, Desmarais' I1) gives the pressures dcp = Qjj w for a normalwash w;
its k is omega/U per unit length (its docstring: "the classical definition,
not Nastran's"), so k = omega_bar / c_bar, and the time factor is
exp(i omega t) (Landahl's kernel).

Motions, as in stability-core's solve.rs: unit incidence w = 1 and unit rate
w = (x - x_mac)/c_bar; loads: C_L = sum dcp A / S, C_m about the M.A.C.'s
leading edge = -sum dcp A (x_l - x_mac) / (S c_bar), x_l the doublet line's
mid-point. The six numbers written are stability-core's Solution fields.

Run: /work/venv-lifting/bin/pip install panelaero
     /work/venv-lifting/bin/python scripts/panelaero_fixtures.py
"""
import json
import math
import os

import numpy as np
from panelaero import DLM


def station(spacing, t, s):
    if spacing == "Uniform":
        return s * t
    if spacing == "Cosine":
        return 0.5 * s * (1.0 - math.cos(math.pi * t))
    if spacing == "RootCosine":
        return s * (1.0 - math.cos(0.5 * math.pi * t))
    raise ValueError(spacing)


def half_lattice(sweep_deg, taper, chordwise, spanwise, spacing):
    t = math.tan(math.radians(sweep_deg))
    s = (1.0 - taper) / t
    chord = lambda y: 1.0 + (taper - 1.0) * y / s
    le = lambda y: y * t
    edges = [station(spacing, k / spanwise, s) for k in range(spanwise + 1)]
    centres = [station(spacing, (k + 0.5) / spanwise, s) for k in range(spanwise)]
    boxes = []
    n = float(chordwise)
    for (y0, y1), yc in zip(zip(edges[:-1], edges[1:]), centres):
        ym = 0.5 * (y0 + y1)
        for k in range(chordwise):
            f, g = (k + 0.25) / n, (k + 0.75) / n
            boxes.append({
                "p1": (le(y0) + f * chord(y0), y0),
                "p3": (le(y1) + f * chord(y1), y1),
                "colloc": (le(yc) + g * chord(yc), yc),
                "chord": chord(ym) / n,
                "area": (y1 - y0) * (chord(y0) + chord(y1)) / (2.0 * n),
            })
    lam = taper
    geom = {
        "semi_span": s,
        "area": s * (1.0 + taper),
        "mac": 2.0 / 3.0 * (1 + lam + lam * lam) / (1 + lam),
        "x_mac": s / 3.0 * (1 + 2 * lam) / (1 + lam) * t,
    }
    return boxes, geom


def aerogrid(boxes):
    """The whole wing: the half's boxes and their mirror images."""
    rows = []
    for b in boxes:
        (x1, y1), (x3, y3), (xc, yc) = b["p1"], b["p3"], b["colloc"]
        rows.append(((x1, y1), (x3, y3), (xc, yc), b["chord"], b["area"]))
        # mirror, still left to right
        rows.append(((x3, -y3), (x1, -y1), (xc, -yc), b["chord"], b["area"]))
    n = len(rows)
    P1 = np.array([[r[0][0], r[0][1], 0.0] for r in rows])
    P3 = np.array([[r[1][0], r[1][1], 0.0] for r in rows])
    j = np.array([[r[2][0], r[2][1], 0.0] for r in rows])
    lpt = 0.5 * (P1 + P3)
    return {
        "offset_P1": P1, "offset_P3": P3, "offset_j": j, "offset_l": lpt,
        "offset_k": lpt, "N": np.tile([0.0, 0.0, 1.0], (n, 1)),
        "A": np.array([r[4] for r in rows]), "l": np.array([r[3] for r in rows]),
        "n": n,
    }


def solve(case):
    boxes, geom = half_lattice(case["sweep_deg"], case["taper"], case["chordwise"],
                               case["spanwise"], case["spacing"])
    grid = aerogrid(boxes)
    mac, x_mac, area = geom["mac"], geom["x_mac"], geom["area"]
    k = case["omega_bar"] / mac
    q = DLM.calc_Qjj(grid, case["mach"], k, method="quartic")
    w_inc = np.ones(grid["n"], dtype=complex)
    w_rate = (grid["offset_j"][:, 0] - x_mac) / mac + 0j

    def loads(w):
        cp = q @ w
        lift = np.sum(cp * grid["A"]) / area
        moment = -np.sum(cp * grid["A"] * (grid["offset_l"][:, 0] - x_mac)) / (area * mac)
        return lift, moment

    l1, m1 = loads(w_inc)
    l2, m2 = loads(w_rate)
    if not l1.real > 0:
        raise SystemExit("panelaero's sign convention is not the one assumed: C_L < 0 for w = 1")
    wb = case["omega_bar"]
    return dict(case, semi_span=geom["semi_span"], first_collocation=list(boxes[0]["colloc"]),
                lift_alpha=l1.real, moment_alpha=m1.real,
                lift_alphadot=l1.imag / wb, moment_alphadot=m1.imag / wb,
                lift_q=l2.real, moment_q=m2.real)


CASES = [
    {"name": "delta 60", "sweep_deg": 60.0, "taper": 0.0, "mach": 0.5, "omega_bar": 0.5},
    {"name": "delta 45", "sweep_deg": 45.0, "taper": 0.0, "mach": 0.8, "omega_bar": 1.0},
    {"name": "cropped 60, taper 1/7", "sweep_deg": 60.0, "taper": 1.0 / 7.0, "mach": 0.0,
     "omega_bar": 0.3},
    {"name": "delta 60, low frequency", "sweep_deg": 60.0, "taper": 0.0, "mach": 0.0,
     "omega_bar": 0.05},
]


def main():
    out = {"source": "scripts/panelaero_fixtures.py (panelaero DLM.calc_Qjj, method='quartic')",
           "cases": []}
    for c in CASES:
        spacing = "RootCosine" if c["taper"] == 0.0 else "Cosine"
        for chordwise, spanwise in [(8, 12)]:
            case = dict(c, chordwise=chordwise, spanwise=spanwise, spacing=spacing)
            r = solve(case)
            out["cases"].append(r)
            print(r["name"], {k: round(r[k], 5) for k in
                              ("lift_alpha", "moment_alpha", "lift_alphadot", "moment_alphadot",
                               "lift_q", "moment_q")})
    path = os.path.join(os.path.dirname(__file__), "..", "stability-core", "tests", "data",
                        "lifting_surface", "panelaero.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")
    print("wrote", os.path.normpath(path))


if __name__ == "__main__":
    main()
