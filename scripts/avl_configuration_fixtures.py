#!/usr/bin/env python3
"""Steady stability derivatives of wing + tailplane / foreplane layouts from
AVL (M. Drela & H. Youngren; the `optvl` package's Python interface) for the
configuration lattice's tests (stability-core/tests/configuration_lattice_avl.rs).

Writes stability-core/tests/fixtures/avl_configuration.json: for the note's
60 deg delta (root chord 1, pointed tip given a chord of 1e-4 as AVL needs
one) with a straight-tapered surface (root 0.3, tip 0.15, semi-span 0.35,
30 deg leading-edge sweep) in three layouts -- a coplanar tailplane, a
tailplane 0.3 root chords above the wing's plane, a foreplane 0.1 above it --
each at M = 0 and 0.5: CLa, Cma (per radian), CLq, Cmq (per AVL's
q-hat = q c/2V), about Xref = the wing M.A.C.'s leading edge, and the
neutral point Xnp. References: Sref = the wing's area, Cref = its M.A.C.,
Bref = its span (the configuration lattice's normalisation). Every surface
has a flat wake in its own plane, as the lattice's; the other surface's
strips are the wing's within its span (a section at its tip), so that the
wing's trailing legs lie on its strip edges (AVL's advice for a tail in a
wing's wake; the lattice does the same).

Run: pip install optvl; python3 scripts/avl_configuration_fixtures.py
"""
import json
import math
import os
import tempfile

from optvl import OVLSolver

WING_NCHORD = 16
SHARED_NSPAN, OUTER_NSPAN = 48, 36  # wing strips within and beyond the other surface's span
SURF_NCHORD = 16  # (AVL's array limit, 5000 vortices, bounds the density)
TIP = 1e-4
SWEEP = 60.0
SURFACE = {"root_chord": 0.3, "tip_chord": 0.15, "semi_span": 0.35, "sweep_deg": 30.0}
LAYOUTS = [
    ("coplanar tailplane", "tailplane", 1.3, 0.0),
    ("tailplane above", "tailplane", 1.3, 0.3),
    ("foreplane", "foreplane", -0.5, 0.1),
]


def wing():
    t = math.tan(math.radians(SWEEP))
    s = 1.0 / t
    return {"semi_span": s, "area": s, "mac": 2.0 / 3.0, "x_mac": s / 3.0 * t,
            "tip": (s * t * (1 - TIP), s * (1 - TIP), TIP)}


def surface_text(name, x, z, root, tip, s, sweep_deg, nchord, nspan):
    xt = x + s * math.tan(math.radians(sweep_deg))
    return f"""SURFACE
{name}
{nchord} 1.0
YDUPLICATE
0.0
SECTION
{x:.12f} 0.0 {z:.12f} {root:.12f} 0.0 {nspan} 1.0
SECTION
{xt:.12f} {s:.12f} {z:.12f} {tip:.12f} 0.0
"""


def avl_file(w, mach, layout, shared=SHARED_NSPAN, outer=OUTER_NSPAN):
    _, kind, x, z = layout
    xt, yt, ct = w["tip"]
    # a section at the other surface's tip, and the same cosine strips on
    # both within it: the wing's trailing legs on the other surface's strip
    # edges (AVL's advice for a tail in a wing's wake)
    t = math.tan(math.radians(SWEEP))
    ys = SURFACE["semi_span"]
    wing_text = f"""SURFACE
Wing
{WING_NCHORD} 1.0
YDUPLICATE
0.0
SECTION
0.0 0.0 0.0 1.0 0.0 {shared} 1.0
SECTION
{ys * t:.12f} {ys:.12f} 0.0 {1.0 - ys * t:.12f} 0.0 {outer} 1.0
SECTION
{xt:.12f} {yt:.12f} 0.0 {ct:.12f} 0.0
"""
    other = surface_text(kind.capitalize(), x, z, SURFACE["root_chord"], SURFACE["tip_chord"],
                         SURFACE["semi_span"], SURFACE["sweep_deg"], SURF_NCHORD, shared)
    return f"""{layout[0]}
{mach}
0 0 0.0
{w['area']:.12f} {w['mac']:.12f} {2 * w['semi_span']:.12f}
{w['x_mac']:.12f} 0.0 0.0
{wing_text}{other}"""


def run(w, mach, layout, shared=SHARED_NSPAN, outer=OUTER_NSPAN):
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "config.avl")
        with open(path, "w") as f:
            f.write(avl_file(w, mach, layout, shared, outer))
        s = OVLSolver(geo_file=path)
        s.set_parameter("Mach", mach)
        s.set_variable("alpha", 0.0)
        s.execute_run()
        st = s.get_stab_derivs()
    return {"mach": mach, "CLa": float(st["dCL/dalpha"]), "Cma": float(st["dCm/dalpha"]),
            "CLq": float(st["dCL/dq'"]), "Cmq": float(st["dCm/dq'"]),
            "Xnp": float(st["neutral point"])}


def main():
    w = wing()
    layouts = []
    for layout in LAYOUTS:
        runs = [run(w, m, layout) for m in (0.0, 0.5)]
        layouts.append({"name": layout[0], "kind": layout[1], "x": layout[2], "z": layout[3],
                        "runs": runs})
        print(layout[0], [(r["mach"], round(r["CLa"], 4), round(r["Xnp"], 4),
                           round(r["CLq"], 4), round(r["Cmq"], 4)) for r in runs])
    # the coplanar tail converges slowly in AVL: its C_La at 8 ... 48 strips
    convergence = [{"shared_nspan": n, "outer_nspan": 3 * n // 4,
                    **run(w, 0.0, LAYOUTS[0], n, 3 * n // 4)} for n in (8, 16, 32, 48)]
    print("coplanar convergence", [(c["shared_nspan"], round(c["CLa"], 4)) for c in convergence])
    out = {
        "source": "scripts/avl_configuration_fixtures.py (optvl, AVL vortex lattice, wing "
        f"{WING_NCHORD} x ({SHARED_NSPAN} + {OUTER_NSPAN}), other surface {SURF_NCHORD} x "
        f"{SHARED_NSPAN}, cosine, per half surface, spanwise strips aligned)",
        "rate_unit": "q c/2V, c = Cref = the wing's M.A.C.; moments about its leading edge",
        "wing": {"sweep_deg": SWEEP, "root_chord": 1.0, "semi_span": w["semi_span"],
                 "mac": w["mac"], "x_mac": w["x_mac"]},
        "surface": SURFACE,
        "layouts": layouts,
        "coplanar_convergence": convergence,
    }
    path = os.path.join(os.path.dirname(__file__), "..", "stability-core", "tests",
                        "fixtures", "avl_configuration.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")
    print("wrote", os.path.normpath(path))


if __name__ == "__main__":
    main()
