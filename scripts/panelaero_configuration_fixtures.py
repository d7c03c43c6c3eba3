#!/usr/bin/env python3
"""Oscillatory solution of a wing + tailplane from panelaero (DLR's public
doublet-lattice code, `pip install panelaero`) for the configuration
lattice's test (stability-core/tests/it/configuration_lattice_panelaero.rs).

Writes stability-core/tests/fixtures/panelaero_configuration.json. The
note's 60 deg delta (root chord 1) with a tailplane (root 0.3, tip 0.15,
semi-span 0.35, 30 deg leading-edge sweep, apex at x = 1.3) 0.3 root
chords above the wing's plane, each cut as stability-core cuts it with
Extrapolation::None (8 chordwise boxes on 12 strips; the wing's strips
root-cosine, the tail's cosine; collocation at the strip's mid-angle, three
quarters of the local box chord; doublet line at the box's quarter chord),
both halves, panels left to right. panelaero's calc_Qjj(aerogrid, Ma, k,
method='quartic') -- Landahl's planar and non-planar kernel (K1, K2),
Rodden, Taylor & McIntosh's quartic, Desmarais' I1 -- with k = omega/V per
unit length = omega_bar / c_bar (the wing's M.A.C.), time factor
exp(i omega t), as scripts/panelaero_fixtures.py establishes.

Motions and loads as the configuration lattice's: unit incidence w = 1 and
unit rate w = (x - x_mac)/c_bar on every surface (x from the wing's apex);
C_L = sum dcp A / S, C_m = -sum dcp A (x_l - x_mac)/(S c_bar) with the
wing's S, c_bar and M.A.C. leading edge x_mac, for the total and for each
surface's panels.

Run: pip install panelaero; python3 scripts/panelaero_configuration_fixtures.py
"""
import json
import math
import os

import numpy as np
from panelaero import DLM


def station(spacing, t, s):
    if spacing == "Cosine":
        return 0.5 * s * (1.0 - math.cos(math.pi * t))
    if spacing == "RootCosine":
        return s * (1.0 - math.cos(0.5 * math.pi * t))
    raise ValueError(spacing)


def half_lattice(root, tip, s, sweep_deg, x0, z0, chordwise, spanwise, spacing):
    t = math.tan(math.radians(sweep_deg))
    chord = lambda y: root + (tip - root) * y / s
    le = lambda y: x0 + y * t
    edges = [station(spacing, k / spanwise, s) for k in range(spanwise + 1)]
    centres = [station(spacing, (k + 0.5) / spanwise, s) for k in range(spanwise)]
    boxes = []
    n = float(chordwise)
    for (y0, y1), yc in zip(zip(edges[:-1], edges[1:]), centres):
        ym = 0.5 * (y0 + y1)
        for k in range(chordwise):
            f, g = (k + 0.25) / n, (k + 0.75) / n
            boxes.append({
                "p1": (le(y0) + f * chord(y0), y0), "p3": (le(y1) + f * chord(y1), y1),
                "colloc": (le(yc) + g * chord(yc), yc), "chord": chord(ym) / n,
                "area": (y1 - y0) * (chord(y0) + chord(y1)) / (2.0 * n), "z": z0,
            })
    return boxes


def aerogrid(boxes):
    rows = []
    for b in boxes:
        (x1, y1), (x3, y3), (xc, yc) = b["p1"], b["p3"], b["colloc"]
        rows.append(((x1, y1), (x3, y3), (xc, yc), b["chord"], b["area"], b["z"]))
        rows.append(((x3, -y3), (x1, -y1), (xc, -yc), b["chord"], b["area"], b["z"]))
    n = len(rows)
    P1 = np.array([[r[0][0], r[0][1], r[5]] for r in rows])
    P3 = np.array([[r[1][0], r[1][1], r[5]] for r in rows])
    j = np.array([[r[2][0], r[2][1], r[5]] for r in rows])
    lpt = 0.5 * (P1 + P3)
    return {"offset_P1": P1, "offset_P3": P3, "offset_j": j, "offset_l": lpt, "offset_k": lpt,
            "N": np.tile([0.0, 0.0, 1.0], (n, 1)), "A": np.array([r[4] for r in rows]),
            "l": np.array([r[3] for r in rows]), "n": n}


WING = {"sweep_deg": 60.0}
TAIL = {"root_chord": 0.3, "tip_chord": 0.15, "semi_span": 0.35, "sweep_deg": 30.0, "x": 1.3,
        "z": 0.3}
CHORDWISE, SPANWISE = 8, 12
CASES = [(0.5, 0.3), (0.0, 0.6)]


def solve(mach, omega_bar):
    tw = math.tan(math.radians(WING["sweep_deg"]))
    s = 1.0 / tw
    area, mac, x_mac = s, 2.0 / 3.0, s / 3.0 * tw
    wing = half_lattice(1.0, 0.0, s, WING["sweep_deg"], 0.0, 0.0, CHORDWISE, SPANWISE,
                        "RootCosine")
    tail = half_lattice(TAIL["root_chord"], TAIL["tip_chord"], TAIL["semi_span"],
                        TAIL["sweep_deg"], TAIL["x"], TAIL["z"], CHORDWISE, SPANWISE, "Cosine")
    grid = aerogrid(wing + tail)
    nw = 2 * len(wing)
    q = DLM.calc_Qjj(grid, mach, omega_bar / mac, method="quartic")
    w_inc = np.ones(grid["n"], dtype=complex)
    w_rate = (grid["offset_j"][:, 0] - x_mac) / mac + 0j

    def loads(w, part):
        cp = (q @ w)[part]
        a, xl = grid["A"][part], grid["offset_l"][part, 0]
        return np.sum(cp * a) / area, -np.sum(cp * a * (xl - x_mac)) / (area * mac)

    out = {"mach": mach, "omega_bar": omega_bar}
    for name, part in [("total", slice(None)), ("wing", slice(0, nw)), ("tailplane", slice(nw, None))]:
        l1, m1 = loads(w_inc, part)
        l2, m2 = loads(w_rate, part)
        out[name] = {"lift_alpha": l1.real, "moment_alpha": m1.real,
                     "lift_alphadot": l1.imag / omega_bar, "moment_alphadot": m1.imag / omega_bar,
                     "lift_q": l2.real, "moment_q": m2.real}
    return out


def main():
    runs = [solve(m, w) for m, w in CASES]
    for r in runs:
        print(r["mach"], r["omega_bar"], {k: round(v, 5) for k, v in r["tailplane"].items()})
    out = {"source": "scripts/panelaero_configuration_fixtures.py (panelaero DLM.calc_Qjj, "
           "method='quartic')", "wing": WING, "tailplane": TAIL, "chordwise": CHORDWISE,
           "spanwise": SPANWISE, "runs": runs}
    path = os.path.join(os.path.dirname(__file__), "..", "stability-core", "tests", "fixtures",
                        "panelaero_configuration.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")
    print("wrote", os.path.normpath(path))


if __name__ == "__main__":
    main()
