#!/usr/bin/env python3
"""Independent check of the published aircraft in examples/aircraft/.

For every stability-core/tests/data/aircraft/<name>.json this script

1. reads the TOML it names (the `notation = "dimensional"` shape of issue 12)
   and checks that its derivatives and flight condition are the JSON's, and
   that the JSON's derivatives are the printed values times the stated
   conversion factor;
2. builds the linear system of issue 12 item 1 in descriptor form E x' = A x,
   state (u, w, q, theta):
       u'     = X_u u + X_w w + X_wdot w' + (X_q - W0) q - g cos(theta0) theta
       w'     = Z_u u + Z_w w + Z_wdot w' + (Z_q + U0) q - g sin(theta0) theta
       q'     = M_u u + M_w w + M_wdot w' + M_q q
       theta' = q
   and takes the eigenvalues of E^-1 A with numpy;
3. prints them beside the published modes with the relative differences, and
   a rounding band: every printed input moved by half a unit in its last
   printed digit (one at a time, deviations summed, first order), plus half
   a unit of the published value itself;
4. rotates body-axis sets into stability axes (which brings in u' derivatives
   the issue's shape has no field for) and checks that the eigenvalues do not
   move; for the 747 it compares the rotated CR-2144 set with Etkin & Reid's;
5. for body-axis sets, a diagnostic "alpha-dot completion": Z_q, Z_wdot and
   M_wdot taken as flight-path (stability-axis) effects of q and alpha-dot,
   which in body axes brings X_q = -Z_q tan a0, X_wdot = -Z_wdot tan a0 and
   u' derivatives. It is printed, never written back into the data.

Needs Python >= 3.11 (tomllib) and numpy, e.g.
    python3 -m venv .venv && .venv/bin/pip install numpy && .venv/bin/python scripts/aircraft_check.py
Exit status 1 if a mode falls outside its band without a recorded
`known_discrepancy`, or if a file is inconsistent.
"""

from __future__ import annotations

import json
import math
import sys
import tomllib
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
DATA = ROOT / "stability-core" / "tests" / "data" / "aircraft"
FOOT = 0.3048
NAMES = ["X_u", "X_w", "X_wdot", "X_q", "Z_u", "Z_w", "Z_wdot", "Z_q", "M_u", "M_w", "M_wdot", "M_q"]


def half_unit(text: str) -> float:
    """Half a unit in the last printed digit of `text` (0 for a printed zero)."""
    value = float(text)
    if value == 0.0:
        return 0.0
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 0.5 * 10.0 ** (int(exponent or 0) - decimals)


def system(d: dict, U0: float, W0: float, theta0_deg: float, g: float, udot=(0.0, 0.0, 0.0)):
    """E and A of the descriptor system; `udot` = (X_udot, Z_udot, M_udot) for rotated sets."""
    th = math.radians(theta0_deg)
    xud, zud, mud = udot
    E = np.array([
        [1.0 - xud, -d["X_wdot"], 0.0, 0.0],
        [-zud, 1.0 - d["Z_wdot"], 0.0, 0.0],
        [-mud, -d["M_wdot"], 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ])
    A = np.array([
        [d["X_u"], d["X_w"], d["X_q"] - W0, -g * math.cos(th)],
        [d["Z_u"], d["Z_w"], d["Z_q"] + U0, -g * math.sin(th)],
        [d["M_u"], d["M_w"], d["M_q"], 0.0],
        [0.0, 0.0, 1.0, 0.0],
    ])
    return E, A


def eigenvalues(E, A) -> np.ndarray:
    return np.linalg.eigvals(np.linalg.solve(E, A))


def modes(lam: np.ndarray) -> dict:
    """Phugoid and short period: the upper roots of the two conjugate pairs, slow one first."""
    upper = sorted((x for x in lam if x.imag > 0), key=abs)
    if len(upper) != 2:
        raise ValueError(f"expected two oscillatory pairs, got {lam}")
    return {"phugoid": upper[0], "short period": upper[1]}


def quantities(root: complex) -> dict:
    wn = abs(root)
    return {"re": root.real, "im": root.imag, "omega_n": wn, "zeta": -root.real / wn}


def inputs(js: dict) -> dict:
    """The printed inputs: derivatives, V and alpha0 as (value, half unit)."""
    out = {}
    for name, p in js["printed"].items():
        out[name] = (float(p["text"]) * p["factor"], half_unit(p["text"]) * abs(p["factor"]))
    fp = js["flight_printed"]
    out["V"] = (float(fp["V"]) * fp["V_factor"], half_unit(fp["V"]) * fp["V_factor"])
    out["alpha0_deg"] = (float(fp["alpha0_deg"]), half_unit(fp["alpha0_deg"]))
    out["gamma0_deg"] = (float(fp["gamma0_deg"]), 0.0)
    return out


def model_from_inputs(values: dict, g: float):
    d = {n: values.get(n, 0.0) for n in NAMES}
    a = math.radians(values["alpha0_deg"])
    V = values["V"]
    return system(d, V * math.cos(a), V * math.sin(a), values["alpha0_deg"] + values["gamma0_deg"], g)


def band(js: dict, g: float) -> dict:
    """First-order spread of each modal quantity over the inputs' printed rounding."""
    printed = inputs(js)
    nominal = {k: v[0] for k, v in printed.items()}
    base = {m: quantities(r) for m, r in modes(eigenvalues(*model_from_inputs(nominal, g))).items()}
    spread = {m: {q: 0.0 for q in base[m]} for m in base}
    for name, (value, step) in printed.items():
        if step == 0.0:
            continue
        worst = {m: {q: 0.0 for q in base[m]} for m in base}
        for sign in (1.0, -1.0):
            moved = dict(nominal, **{name: value + sign * step})
            got = {m: quantities(r) for m, r in modes(eigenvalues(*model_from_inputs(moved, g))).items()}
            for m in base:
                for q in base[m]:
                    worst[m][q] = max(worst[m][q], abs(got[m][q] - base[m][q]))
        for m in base:
            for q in base[m]:
                spread[m][q] += worst[m][q]
    return spread


def check_files(js: dict, toml: dict) -> list[str]:
    problems = []
    if toml.get("notation") != "dimensional" or toml.get("axes") != js["axes"] or toml.get("units") != js["units"]:
        problems.append("notation/axes/units differ between TOML and JSON")
    for n in NAMES:
        t, j = toml["derivatives"].get(n, 0.0), js["derivatives"][n]
        if abs(t - j) > 1e-9 * abs(j):
            problems.append(f"{n}: TOML {t} against JSON {j}")
        if n in js["printed"]:
            p = js["printed"][n]
            if abs(float(p["text"]) * p["factor"] - j) > 1e-9 * abs(j) + 1e-15:
                problems.append(f"{n}: JSON {j} is not printed {p['text']} x {p['factor']}")
        elif j != 0.0 or n not in js["assumed_zero"]:
            problems.append(f"{n}: not printed, yet not recorded as assumed zero")
    f, jf = toml["flight"], js["flight"]
    for key, jkey in (("U0", "U0"), ("W0", "W0"), ("theta0", "theta0_deg"), ("g", "g")):
        if f[key] != jf[jkey]:
            problems.append(f"[flight] {key}: TOML {f[key]} against JSON {jf[jkey]}")
    v = inputs(js)
    a = math.radians(v["alpha0_deg"][0])
    if abs(f["U0"] - v["V"][0] * math.cos(a)) > 1e-3 or abs(f["W0"] - v["V"][0] * math.sin(a)) > 1e-3:
        problems.append("U0, W0 are not V cos(alpha0), V sin(alpha0)")
    if abs(f["theta0"] - (v["alpha0_deg"][0] + v["gamma0_deg"][0])) > 1e-12:
        problems.append("theta0 is not alpha0 + gamma0")
    return problems


def to_stability_axes(d: dict, U0: float, W0: float, theta0_deg: float):
    """A body-axis set in stability axes: v_b = C v_s, C = [[c, -s], [s, c]], alpha0 = atan(W0/U0).

    Returns the rotated derivatives, the u' derivatives (X_udot, Z_udot, M_udot)
    that the rotation of the w' terms brings in, and the stability-axis flight
    condition (V, 0, gamma0).
    """
    alpha = math.atan2(W0, U0)
    c, s = math.cos(alpha), math.sin(alpha)
    C = np.array([[c, -s], [s, c]])
    D = C.T @ np.array([[d["X_u"], d["X_w"]], [d["Z_u"], d["Z_w"]]]) @ C
    Ed = C.T @ np.array([[0.0, d["X_wdot"]], [0.0, d["Z_wdot"]]]) @ C
    Q = C.T @ np.array([d["X_q"], d["Z_q"]])
    Mv = np.array([d["M_u"], d["M_w"]]) @ C
    r = {"X_u": D[0, 0], "X_w": D[0, 1], "Z_u": D[1, 0], "Z_w": D[1, 1],
         "X_wdot": Ed[0, 1], "Z_wdot": Ed[1, 1], "X_q": Q[0], "Z_q": Q[1],
         "M_u": Mv[0], "M_w": Mv[1], "M_wdot": c * d["M_wdot"], "M_q": d["M_q"]}
    udot = (Ed[0, 0], Ed[1, 0], s * d["M_wdot"])
    return r, udot, (math.hypot(U0, W0), 0.0, theta0_deg - math.degrees(alpha))


def alpha_dot_completion(d: dict, U0: float, W0: float):
    """The body-axis set whose q and w' derivatives act along the stability axes.

    A stability-axis set has Z_q,s, Z_wdot,s, M_wdot,s acting on q and on
    w'_s = -s u'_b + c w'_b (alpha-dot), with no X_q, X_wdot or u' terms. In
    body axes (v_b = C v_s) that is X_q = -s Z_q,s, Z_q = c Z_q,s,
    X_udot = s^2 Z_wdot,s, X_wdot = Z_udot = -s c Z_wdot,s, Z_wdot = c^2 Z_wdot,s,
    M_udot = -s M_wdot,s, M_wdot = c M_wdot,s; solved here for the tabulated
    body-axis Z_q, Z_wdot, M_wdot. Returns (derivatives, (X_udot, Z_udot, M_udot)).
    """
    t = W0 / U0
    r = dict(d)
    r["X_q"] = d["X_q"] - t * d["Z_q"]
    r["X_wdot"] = d["X_wdot"] - t * d["Z_wdot"]
    udot = (t * t * d["Z_wdot"], -t * d["Z_wdot"], -t * d["M_wdot"])
    return r, udot


def fmt(x: complex) -> str:
    return f"{x.real:+.6f} {x.imag:+.6f}i"


def report(js: dict, toml: dict) -> tuple[bool, dict]:
    d = {n: toml["derivatives"].get(n, 0.0) for n in NAMES}
    f = toml["flight"]
    lam = eigenvalues(*system(d, f["U0"], f["W0"], f["theta0"], f["g"]))
    ours = modes(lam)
    spread = band(js, f["g"])
    print(f"\n== {js['name']}: {js['aircraft']} ({js['axes']} axes, {js['units']}, theta0 = {f['theta0']} deg)")
    print("   " + js["source"]["citation"][:100])
    print("   eigenvalues: " + ", ".join(fmt(x) for x in sorted(lam, key=lambda z: (abs(z), z.imag))))
    ok = True
    rows = []
    for pm in js["published_modes"]:
        q = quantities(ours[pm["mode"]])
        label = pm["mode"] + (f" [{pm['source']}]" if "source" in pm else "")
        keys = ("omega_n", "zeta") if pm["form"] == "omega_zeta" else ("re", "im")
        known = {k["quantity"]: k for k in pm.get("known_discrepancies", [])}
        for k in keys:
            pub = float(pm[k])
            diff = q[k] - pub
            allowed = spread[pm["mode"]][k] + half_unit(pm[k])
            inside = abs(diff) <= allowed
            if inside:
                verdict = "within rounding"
            elif k in known and abs(diff / pub) <= known[k]["bound"]:
                verdict = "KNOWN DISCREPANCY"
            else:
                verdict = "OUTSIDE"
                ok = False
            print(f"   {label:<44} {k:<8} ours {q[k]:+.6g}  published {pm[k]:>9}  "
                  f"rel {diff / abs(pub):+.2e}  band ±{allowed:.2g}  {verdict}")
            rows.append({"mode": label, "quantity": k, "ours": q[k], "published": pm[k],
                         "relative": diff / abs(pub), "band": allowed, "verdict": verdict})
        if pm["form"] == "root":
            pub = complex(float(pm["re"]), float(pm["im"]))
            print(f"   {'':<44} |Δλ|/|λ| = {abs(ours[pm['mode']] - pub) / abs(pub):.2e}")
        else:
            wn, z = float(pm["omega_n"]), float(pm["zeta"])
            pub = complex(-z * wn, wn * math.sqrt(1.0 - z * z))
            print(f"   {'':<44} published root {fmt(pub)}, |Δλ|/|λ| = {abs(ours[pm['mode']] - pub) / abs(pub):.2e}")
    if js["axes"] == "body":
        r, udot, (V, W0s, gamma) = to_stability_axes(d, f["U0"], f["W0"], f["theta0"])
        lam_s = eigenvalues(*system(r, V, W0s, gamma, f["g"], udot))
        moved = max(min(abs(x - y) for y in lam_s) for x in lam)
        print(f"   in stability axes (alpha0 = {math.degrees(math.atan2(f['W0'], f['U0'])):.4f} deg, "
              f"V = {V:.4f}, theta0 = {gamma:.4f} deg): eigenvalues move by {moved:.1e}")
        print("   stability-axis set: " + ", ".join(f"{k} = {v:.6g}" for k, v in r.items()))
        print(f"   u' terms the rotation adds: X_udot = {udot[0]:.3g}, Z_udot = {udot[1]:.3g}, M_udot = {udot[2]:.3g}")
        if moved > 1e-9 * max(abs(x) for x in lam):
            ok = False
            print("   ROTATION CHANGED THE EIGENVALUES")
        completed, cud = alpha_dot_completion(d, f["U0"], f["W0"])
        comp = modes(eigenvalues(*system(completed, f["U0"], f["W0"], f["theta0"], f["g"], cud)))
        print(f"   alpha-dot completion (X_q = {completed['X_q']:.4g}, X_wdot = {completed['X_wdot']:.3g}, "
              f"X_udot = {cud[0]:.3g}, Z_udot = {cud[1]:.3g}, M_udot = {cud[2]:.3g}): "
              + ", ".join(f"{m} zeta {quantities(x)['zeta']:.5f} omega_n {abs(x):.5f}" for m, x in comp.items()))
        for pm in js["published_modes"]:
            if pm["form"] == "omega_zeta" and "source" not in pm:
                cq = quantities(comp[pm["mode"]])
                print(f"      {pm['mode']:<13} against published: omega_n rel {(cq['omega_n'] - float(pm['omega_n'])) / float(pm['omega_n']):+.2e}"
                      f", zeta rel {(cq['zeta'] - float(pm['zeta'])) / float(pm['zeta']):+.2e}")
        naive = modes(eigenvalues(*system(d, math.hypot(f["U0"], f["W0"]), 0.0, 0.0, f["g"])))
        print("   read as stability axes instead (W0 = 0, theta0 = 0): "
              + ", ".join(f"{m} zeta {quantities(x)['zeta']:+.4f} omega_n {abs(x):.4f}" for m, x in naive.items()))
    return ok, {"name": js["name"], "eigenvalues": lam, "modes": ours, "rows": rows, "d": d, "flight": f}


def compare_747(results: dict) -> None:
    """CR-2144 F/C 9 rotated into stability axes, in SI, beside Etkin & Reid's set."""
    if "boeing-747-cr2144-fc9" not in results or "boeing-747-etkin-reid" not in results:
        return
    b, e = results["boeing-747-cr2144-fc9"], results["boeing-747-etkin-reid"]
    r, udot, _ = to_stability_axes(b["d"], b["flight"]["U0"], b["flight"]["W0"], b["flight"]["theta0"])
    per_ft = {"M_u": 1 / FOOT, "M_w": 1 / FOOT, "M_wdot": 1 / FOOT, "Z_q": FOOT, "X_q": FOOT}
    print("\n== the 747 at 40 000 ft, M 0.8: CR-2144 F/C 9 (body axes) rotated to stability axes, in SI,"
          " against Etkin & Reid")
    for k in NAMES:
        ours = r[k] * per_ft.get(k, 1.0)
        theirs = e["d"][k]
        rel = (ours - theirs) / abs(theirs) if theirs else float("nan")
        print(f"   {k:<7} CR-2144 rotated {ours:+.5g}   Etkin & Reid {theirs:+.5g}   rel {rel:+.2%}")
    for m in ("phugoid", "short period"):
        x, y = b["modes"][m], e["modes"][m]
        print(f"   {m:<12} CR-2144 body {fmt(x)}   Etkin & Reid {fmt(y)}   |Δλ|/|λ| {abs(x - y) / abs(y):.2e}")


def main() -> int:
    ok = True
    results = {}
    for path in sorted(DATA.glob("*.json")):
        js = json.loads(path.read_text())
        toml = tomllib.loads((ROOT / js["toml"]).read_text())
        problems = check_files(js, toml)
        for p in problems:
            print(f"{path.name}: {p}")
        good, res = report(js, toml)
        ok &= good and not problems
        results[js["name"]] = res
    compare_747(results)
    print("\nall published modes within rounding or recorded" if ok else "\nFAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
