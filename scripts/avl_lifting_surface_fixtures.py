#!/usr/bin/env python3
"""Steady stability derivatives from AVL (M. Drela & H. Youngren; the `optvl`
package's Python interface) for the lifting-surface tests.

Writes stability-core/tests/data/lifting_surface/avl.json: for the note's two
true deltas (45 and 60 deg leading-edge sweep) and two cropped deltas (taper
1/7, the note's Fig 36), each at M = 0, 0.5, 0.8:
CLa, Cma (per radian), CLq, Cmq (per AVL's q-hat = q c/2V, c = Cref = the
M.A.C.), about Xref = the c.g. at h = 0.25 of the M.A.C., and the neutral
point Xnp — stability axes at alpha = 0, so they are body axes.

AVL is a vortex lattice too (horseshoes, Prandtl-Glauert), with its own
lattice: NCHORD chordwise (cosine), NSPAN spanwise (cosine) per half wing.
A true delta's pointed tip is given a chord of 1e-4 c0 (AVL needs a chord).
The Mach number is set both in the file header and in the run case.

Run: python3 -m venv /work/venv-lifting && /work/venv-lifting/bin/pip install optvl
     /work/venv-lifting/bin/python scripts/avl_lifting_surface_fixtures.py
"""
import json
import math
import os
import tempfile

from optvl import OVLSolver

NCHORD, NSPAN = 24, 48
TIP = 1e-4  # chord of a "pointed" tip, in root chords


def wing(sweep_deg, taper):
    """A delta of root chord 1, unswept trailing edge, as the note's Planform."""
    t = math.tan(math.radians(sweep_deg))
    s = (1.0 - taper) / t
    ct = max(taper, TIP)
    # the tip section's leading edge sits on the straight leading edge
    lam = taper
    mac = 2.0 / 3.0 * (1 + lam + lam * lam) / (1 + lam)
    y_mac = s / 3.0 * (1 + 2 * lam) / (1 + lam)
    return {
        "name": f"delta {sweep_deg:g} deg, taper {taper:.6g}",
        "sweep_deg": sweep_deg,
        "taper": taper,
        "root_chord": 1.0,
        "semi_span": s,
        "area": s * (1 + taper),
        "mac": mac,
        "x_mac": y_mac * t,
        "tip": (s * t * (1.0 - TIP) if taper == 0 else s * t, s * (1.0 - TIP) if taper == 0 else s, ct),
    }


def avl_file(w, mach, xref):
    xt, yt, ct = w["tip"]
    return f"""{w['name']}
{mach}
0 0 0.0
{w['area']:.12f} {w['mac']:.12f} {2 * w['semi_span']:.12f}
{xref:.12f} 0.0 0.0
SURFACE
Wing
{NCHORD} 1.0 {NSPAN} 1.0
YDUPLICATE
0.0
SECTION
0.0 0.0 0.0 1.0 0.0
SECTION
{xt:.12f} {yt:.12f} 0.0 {ct:.12f} 0.0
"""


def run(w, mach, h=0.25):
    xref = w["x_mac"] + h * w["mac"]
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "wing.avl")
        with open(path, "w") as f:
            f.write(avl_file(w, mach, xref))
        s = OVLSolver(geo_file=path)
        s.set_parameter("Mach", mach)
        s.set_variable("alpha", 0.0)
        s.execute_run()
        st = s.get_stab_derivs()
    return {
        "mach": mach,
        "h": h,
        "xref": xref,
        "CLa": float(st["dCL/dalpha"]),
        "Cma": float(st["dCm/dalpha"]),
        "CLq": float(st["dCL/dq'"]),
        "Cmq": float(st["dCm/dq'"]),
        "Xnp": float(st["neutral point"]),
    }


def main():
    cases = []
    for sweep, taper in [(45.0, 0.0), (60.0, 0.0), (45.0, 1.0 / 7.0), (60.0, 1.0 / 7.0)]:
        w = wing(sweep, taper)
        w["runs"] = [run(w, m) for m in (0.0, 0.5, 0.8)]
        w.pop("tip")
        cases.append(w)
        print(w["name"], [(r["mach"], round(r["CLa"], 4), round(r["Xnp"], 4)) for r in w["runs"]])
    out = {
        "source": "scripts/avl_lifting_surface_fixtures.py (optvl, AVL "
        f"vortex lattice, {NCHORD} x {NSPAN} cosine per half wing)",
        "rate_unit": "q c/2V, c = Cref = M.A.C.",
        "wings": cases,
    }
    path = os.path.join(os.path.dirname(__file__), "..", "stability-core", "tests",
                        "data", "lifting_surface", "avl.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")
    print("wrote", os.path.normpath(path))


if __name__ == "__main__":
    main()
