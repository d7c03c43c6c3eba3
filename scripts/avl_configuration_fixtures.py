#!/usr/bin/env python3
"""Steady stability derivatives of wing + tailplane / foreplane layouts from
AVL (M. Drela & H. Youngren; the `optvl` package's Python interface) for the
configuration lattice's tests (stability-core/tests/it/configuration_lattice_avl.rs).

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

Vortex cores: AVL gives every horseshoe acting on another *component*
(each surface is its own unless told) a finite core of radius
VRCOREW x its strip width (VRCOREW = 2 by default; within a component
1e-4 x the width: AVL 3.36, aic.f, VVOR). A coplanar tail in the wing's
wake sits half a strip from the wing's trailing legs, well inside those
cores, so the wing's downwash there is smeared and AVL converges slowly
(like 1/sqrt(N) in the strips) to the singular lattice's answer. Here the
surfaces are one COMPONENT (the singular kernel, as the configuration
lattice's); the default-core series of the coplanar layout is kept as
`coplanar_default_core` (the evidence). `coplanar_study` is the coplanar
layout's convergence with one component: 4, 8 and 16 chordwise on each
surface times 12, 24 and 48 shared strips (AVL's limits: 500 strips,
5000 vortices, on the whole configuration), Richardson-extrapolated first
in the strips (1/N_span, at the order observed on the three densities)
and then chordwise (1/N_chord, likewise); plus equal strips (SPACE 0) at
4 chordwise as a check of the spacing.

`tailed_45` (issue 30): the program's 45 deg delta (root chord 10) with a
coplanar tailplane as a config gives it -- [tailplane] sweep = 45,
taper = 0.3, root_chord = 3, x = 11, z = 0: straight-tapered with an
unswept trailing edge, so tip chord 0.9 and semi-span
3 x 0.7/tan 45 deg = 2.1 -- studied as `coplanar_study` at M = 0.05 and
0.5 (the same densities; the wing's strips section at y = 2.1). Its
extrapolation is also given in the note's notation (`program`) about the
c.g. h = 0 and 0.25 (fractions of the wing's M.A.C. aft of its leading
edge): z_w = -C_La, m_w = C_ma + h C_La, z_q and m_q per q c/V (half
AVL's per q c/2V), the lift and the rotation moved to the c.g.
(`program_notation`); `about_cg` is AVL's densest lattice with its
reference at h = 0.25, against which the script checks that transfer.

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


def wing(sweep=SWEEP, root=1.0):
    """A pointed delta of leading-edge sweep `sweep` (degrees) and root
    chord `root`, its tip given a chord of TIP x the root's."""
    t = math.tan(math.radians(sweep))
    s = root / t
    return {"sweep": sweep, "root": root, "semi_span": s, "area": root * s,
            "mac": 2.0 * root / 3.0, "x_mac": s / 3.0 * t,
            "tip": (s * t * (1 - TIP), s * (1 - TIP), root * TIP)}


KEYS = ("CLa", "Cma", "CLq", "Cmq", "Xnp")


def surface_text(name, x, z, root, tip, s, sweep_deg, nchord, nspan, space=1.0):
    xt = x + s * math.tan(math.radians(sweep_deg))
    return f"""SURFACE
{name}
{nchord} 1.0
COMPONENT
1
YDUPLICATE
0.0
SECTION
{x:.12f} 0.0 {z:.12f} {root:.12f} 0.0 {nspan} {space}
SECTION
{xt:.12f} {s:.12f} {z:.12f} {tip:.12f} 0.0
"""


def avl_file(w, mach, layout, shared=SHARED_NSPAN, outer=OUTER_NSPAN, nchord=None,
             space=1.0, one_component=True, surface=SURFACE, h=0.0):
    """The AVL input: both surfaces one COMPONENT unless `one_component` is
    false (then AVL's default finite cores act between them); moments and
    the pitch rate about the c.g. `h` (a fraction of the wing's M.A.C. aft
    of its leading edge)."""
    wn = WING_NCHORD if nchord is None else nchord
    sn = SURF_NCHORD if nchord is None else nchord
    _, kind, x, z = layout
    xt, yt, ct = w["tip"]
    # a section at the other surface's tip, and the same cosine strips on
    # both within it: the wing's trailing legs on the other surface's strip
    # edges (AVL's advice for a tail in a wing's wake)
    t = math.tan(math.radians(w["sweep"]))
    ys = surface["semi_span"]
    wing_text = f"""SURFACE
Wing
{wn} 1.0
COMPONENT
1
YDUPLICATE
0.0
SECTION
0.0 0.0 0.0 {w['root']} 0.0 {shared} {space}
SECTION
{ys * t:.12f} {ys:.12f} 0.0 {w['root'] - ys * t:.12f} 0.0 {outer} {space}
SECTION
{xt:.12f} {yt:.12f} 0.0 {ct:.12f} 0.0
"""
    other = surface_text(kind.capitalize(), x, z, surface["root_chord"], surface["tip_chord"],
                         surface["semi_span"], surface["sweep_deg"], sn, shared, space)
    text = f"""{layout[0]}
{mach}
0 0 0.0
{w['area']:.12f} {w['mac']:.12f} {2 * w['semi_span']:.12f}
{w['x_mac'] + h * w['mac']:.12f} 0.0 0.0
{wing_text}{other}"""
    return text if one_component else text.replace("COMPONENT\n1\n", "")


def run(w, mach, layout, shared=SHARED_NSPAN, outer=OUTER_NSPAN, **kw):
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "config.avl")
        with open(path, "w") as f:
            f.write(avl_file(w, mach, layout, shared, outer, **kw))
        s = OVLSolver(geo_file=path)
        s.set_parameter("Mach", mach)
        s.set_variable("alpha", 0.0)
        s.execute_run()
        st = s.get_stab_derivs()
    return {"mach": mach, "CLa": float(st["dCL/dalpha"]), "Cma": float(st["dCm/dalpha"]),
            "CLq": float(st["dCL/dq'"]), "Cmq": float(st["dCm/dq'"]),
            "Xnp": float(st["neutral point"])}


STUDY_NCHORD = (4, 8, 16)
STUDY_NSPAN = (12, 24, 48)


def richardson(f):
    """Richardson's extrapolation of f at densities N, 2N, 4N (error ~ N^-p)
    at the order p observed on the three: (order, extrapolated value). The
    order is None (and the value the densest's) if the differences do not
    shrink with one sign."""
    d1, d2 = f[1] - f[0], f[2] - f[1]
    if d1 == 0.0 or d2 / d1 <= 0.0 or abs(d2) >= abs(d1):
        return None, f[2]
    p = math.log2(d1 / d2)
    return p, f[2] + d2 / (2.0**p - 1.0)


def coplanar_study(w, mach, layout=LAYOUTS[0], surface=SURFACE):
    """The coplanar layout's AVL convergence at `mach` with one component:
    every (chordwise, strips) of the study, the strips' extrapolation at
    each chordwise count and then the chordwise one."""
    grid = [{"nchord": nc, "shared_nspan": n,
             **run(w, mach, layout, n, 3 * n // 4, nchord=nc, surface=surface)}
            for nc in STUDY_NCHORD for n in STUDY_NSPAN]
    equal = [{"nchord": STUDY_NCHORD[0], "shared_nspan": n,
              **run(w, mach, layout, n, 3 * n // 4, nchord=STUDY_NCHORD[0], space=0.0,
                    surface=surface)}
             for n in STUDY_NSPAN]
    spanwise = []
    for nc in STUDY_NCHORD:
        rows = [g for g in grid if g["nchord"] == nc]
        ext = {k: richardson([r[k] for r in rows]) for k in KEYS}
        spanwise.append({"nchord": nc, "order": {k: ext[k][0] for k in KEYS},
                         **{k: ext[k][1] for k in KEYS}})
    ext = {k: richardson([s[k] for s in spanwise]) for k in KEYS}
    extrapolated = {"order": {k: ext[k][0] for k in KEYS}, **{k: ext[k][1] for k in KEYS}}
    equal_ext = {k: richardson([r[k] for r in equal]) for k in KEYS}
    print(f"{layout[0]} study M = {mach}: spanwise orders",
          [{k: s["order"][k] and round(s["order"][k], 2) for k in KEYS} for s in spanwise])
    print("  chordwise orders", {k: v and round(v, 2) for k, v in extrapolated["order"].items()})
    print("  extrapolated", {k: round(extrapolated[k], 5) for k in KEYS})
    print("  equal strips at", STUDY_NCHORD[0], {k: (equal_ext[k][0] and round(equal_ext[k][0], 2),
                                                   round(equal_ext[k][1], 5)) for k in KEYS})
    return {"mach": mach, "grid": grid, "equal_strips": equal,
            "equal_strips_extrapolated": {"order": {k: equal_ext[k][0] for k in KEYS},
                                          **{k: equal_ext[k][1] for k in KEYS}},
            "spanwise_extrapolated": spanwise, "extrapolated": extrapolated}


# Issue 30's case: the 45 deg delta of root chord 10 with a coplanar 45 deg
# tailplane as the program's config gives it ([tailplane] sweep = 45,
# taper = 0.3, root_chord = 3, x = 11, z = 0: a straight taper with an
# unswept trailing edge, so its semi-span c0 (1 - taper)/tan(sweep) = 2.1)
TAILED45_SWEEP, TAILED45_ROOT = 45.0, 10.0
TAILED45_TAIL = {"sweep_deg": 45.0, "taper": 0.3, "root_chord": 3.0}
TAILED45_LAYOUT = ("45 deg delta, coplanar tailplane", "tailplane", 11.0, 0.0)
TAILED45_MACH = (0.05, 0.5)
TAILED45_CG = (0.0, 0.25)


def tailed45_surface():
    """The tailplane's trapezoid as the program builds it from its keys."""
    t = TAILED45_TAIL
    root, taper = t["root_chord"], t["taper"]
    return {"root_chord": root, "tip_chord": taper * root,
            "semi_span": root * (1.0 - taper) / math.tan(math.radians(t["sweep_deg"])),
            "sweep_deg": t["sweep_deg"]}


def program_notation(avl, w, h):
    """AVL's CLa, Cma, CLq, Cmq (per radian and per q c/2V about the wing
    M.A.C.'s leading edge) in the note's notation about the c.g. h: the
    pitch rate q c/V (half AVL's derivative), z = -lift, moments and the
    rotation moved aft by h c (Cm' = Cm + h CL; a pitch rate about the c.g.
    is one about the leading edge less a plunge q h c/V)."""
    a, cma = avl["CLa"], avl["Cma"]
    lq, mq = avl["CLq"] / 2.0, avl["Cmq"] / 2.0
    return {"h": h, "lift_slope": a, "aerodynamic_centre": (avl["Xnp"] - w["x_mac"]) / w["mac"],
            "z_w": -a, "m_w": cma + h * a, "z_q": -(lq - h * a),
            "m_q": mq - h * cma + h * (lq - h * a)}


def tailed45():
    """Issue 30's case: the convergence study at each Mach number, its
    extrapolation in the note's notation at each c.g., and a check of the
    axis transfer: AVL's densest lattice with its reference at the last
    c.g. against the transfer of its run about the leading edge."""
    w = wing(TAILED45_SWEEP, TAILED45_ROOT)
    surface = tailed45_surface()
    out = []
    for mach in TAILED45_MACH:
        study = coplanar_study(w, mach, TAILED45_LAYOUT, surface)
        n, h = STUDY_NSPAN[-1], TAILED45_CG[-1]
        moved = run(w, mach, TAILED45_LAYOUT, n, 3 * n // 4, nchord=STUDY_NCHORD[-1],
                    surface=surface, h=h)
        transferred = program_notation(study["grid"][-1], w, h)
        direct = program_notation(moved, w, 0.0)
        for k in ("z_w", "m_w", "z_q", "m_q"):
            assert abs(transferred[k] - direct[k]) < 1e-6 * abs(direct[k]), (k, transferred, direct)
        study["about_cg"] = {"h": h, **moved}
        study["program"] = [program_notation(study["extrapolated"], w, h) for h in TAILED45_CG]
        print(f"  M = {mach}, the note's notation:",
              [{k: round(v, 4) for k, v in p.items()} for p in study["program"]])
        out.append(study)
    return {"wing": {"sweep_deg": TAILED45_SWEEP, "root_chord": TAILED45_ROOT,
                     "semi_span": w["semi_span"], "mac": w["mac"], "x_mac": w["x_mac"]},
            "tailplane_keys": TAILED45_TAIL, "surface": surface,
            "name": TAILED45_LAYOUT[0], "kind": TAILED45_LAYOUT[1], "x": TAILED45_LAYOUT[2],
            "z": TAILED45_LAYOUT[3], "cg": list(TAILED45_CG), "study": out}


def main():
    w = wing()
    layouts = []
    for layout in LAYOUTS:
        runs = [run(w, m, layout) for m in (0.0, 0.5)]
        layouts.append({"name": layout[0], "kind": layout[1], "x": layout[2], "z": layout[3],
                        "runs": runs})
        print(layout[0], [(r["mach"], round(r["CLa"], 4), round(r["Xnp"], 4),
                           round(r["CLq"], 4), round(r["Cmq"], 4)) for r in runs])
    # AVL's default cores between the surfaces: the slow series (16 chordwise)
    default_core = [{"shared_nspan": n, "outer_nspan": 3 * n // 4,
                     **run(w, 0.0, LAYOUTS[0], n, 3 * n // 4, one_component=False)}
                    for n in (8, 16, 32, 48)]
    print("coplanar, default cores", [(c["shared_nspan"], round(c["CLa"], 4))
                                      for c in default_core])
    study = [coplanar_study(w, m) for m in (0.0, 0.5)]
    out = {
        "source": "scripts/avl_configuration_fixtures.py (optvl, AVL vortex lattice, one component, wing "
        f"{WING_NCHORD} x ({SHARED_NSPAN} + {OUTER_NSPAN}), other surface {SURF_NCHORD} x "
        f"{SHARED_NSPAN}, cosine, per half surface, spanwise strips aligned)",
        "rate_unit": "q c/2V, c = Cref = the wing's M.A.C.; moments about its leading edge",
        "wing": {"sweep_deg": SWEEP, "root_chord": 1.0, "semi_span": w["semi_span"],
                 "mac": w["mac"], "x_mac": w["x_mac"]},
        "surface": SURFACE,
        "layouts": layouts,
        "coplanar_default_core": default_core,
        "coplanar_study": study,
        "tailed_45": tailed45(),
    }
    path = os.path.join(os.path.dirname(__file__), "..", "stability-core", "tests",
                        "fixtures", "avl_configuration.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")
    print("wrote", os.path.normpath(path))


if __name__ == "__main__":
    main()
