#!/usr/bin/env python3
"""The exact roots of the two-dimensional incompressible typical section in
plunge and pitch, its air forces at the root's own complex reduced frequency
(the p-method): the reference of issue 33's first check, written to
stability-core/tests/data/typical_section/p_method.json.

The section (Theodorsen, NACA Rep. 496, 1935; Bisplinghoff, Ashley &
Halfman, *Aeroelasticity*, 1955, §5-6; Hodges & Pierce, *Introduction to
Structural Dynamics and Aeroelasticity*, 2011, §5.5): semichord b, elastic
axis a·b aft of mid-chord, centre of mass x_a·b aft of the elastic axis,
radius of gyration r·b about it, uncoupled frequencies w_h (plunge) and w_a
(pitch), mass ratio mu = m/(pi rho b^2); plunge h positive down, pitch alpha
nose up, motion ~ e^{st}, p = s b / V the complex reduced frequency, Vbar =
V/(b w_a). Per unit m V^2/b and m V^2 (h/b = hh):

  p^2 hh + x_a p^2 alpha + (sig/Vbar)^2 hh = -L/(m V^2/b)
  x_a p^2 hh + r^2 p^2 alpha + (r/Vbar)^2 alpha = M/(m V^2)

  L/(m V^2/b) = [p^2 hh + p alpha - a p^2 alpha]/mu
                + (2/mu) C(p) [p hh + alpha + (1/2 - a) p alpha]
  M/(m V^2)   = [a p^2 hh - (1/2 - a) p alpha - (1/8 + a^2) p^2 alpha]/mu
                + (2/mu)(a + 1/2) C(p) [p hh + alpha + (1/2 - a) p alpha]

with Theodorsen's function continued to complex p (R.T. Jones; Edwards,
Ashley & Breakwell, AIAA J. 17(4), 1979): C(p) = K1(p)/(K0(p) + K1(p)),
which at p = ik is Theodorsen's H1(k)/(H1(k) + i H0(k)) (Hankel functions of
the second kind).

Two routes, independent of each other:
1. the p-method: for each Vbar, the two roots p of det = 0 by Newton
   (mpmath.findroot, 30 digits), followed in Vbar from the structural
   frequencies at Vbar small;
2. the classical flutter solution (the k-method at zero structural damping):
   real k and Vbar with det(ik; Vbar) = 0, solved directly.
At the flutter speed the p-method's root crosses the imaginary axis at
p = ik exactly there: the script checks that they agree and writes both.

Parameters: the case of Hodges & Pierce §5.5 (a = -1/5, x_a = 1/10,
r^2 = 6/25, sig = w_h/w_a = 2/5, mu = 20).

  python3 scripts/typical_section_p_method.py   (needs mpmath)
"""

import json
import os

import mpmath as mp

mp.mp.dps = 30

A, XA, R2, SIG, MU = mp.mpf(-1) / 5, mp.mpf(1) / 10, mp.mpf(6) / 25, mp.mpf(2) / 5, mp.mpf(20)


def theodorsen(p):
    """C(p) = K1(p)/(K0(p) + K1(p)), Theodorsen's function at complex p."""
    k0, k1 = mp.besselk(0, p), mp.besselk(1, p)
    return k1 / (k0 + k1)


def matrix(p, vbar):
    """The 2x2 matrix of the section's equations at p, Vbar (unknowns hh, alpha)."""
    c = theodorsen(p)
    # lift and moment per unit of each unknown
    lift_h = (p**2 + 2 * c * p) / MU
    lift_a = (p - A * p**2 + 2 * c * (1 + (mp.mpf(1) / 2 - A) * p)) / MU
    mom_h = (A * p**2 + 2 * (A + mp.mpf(1) / 2) * c * p) / MU
    mom_a = (
        -(mp.mpf(1) / 2 - A) * p
        - (mp.mpf(1) / 8 + A**2) * p**2
        + 2 * (A + mp.mpf(1) / 2) * c * (1 + (mp.mpf(1) / 2 - A) * p)
    ) / MU
    return [
        [p**2 + (SIG / vbar) ** 2 + lift_h, XA * p**2 + lift_a],
        [XA * p**2 - mom_h, R2 * p**2 + R2 / vbar**2 - mom_a],
    ]


def det(p, vbar):
    m = matrix(p, vbar)
    return m[0][0] * m[1][1] - m[0][1] * m[1][0]


def roots_along(vbars):
    """The two branches' roots p (upper half plane) at each Vbar, followed
    from the structural frequencies (p = i w b/V) at the first."""
    guesses = [1j * SIG / vbars[0], 1j / vbars[0]]
    out = []
    for v in vbars:
        found = [mp.findroot(lambda p: det(p, v), g, tol=mp.mpf(10) ** -25) for g in guesses]
        out.append(found)
        guesses = found
    return out


def flutter_by_k():
    """Real k and Vbar with det(ik; Vbar) = 0: the classical flutter point."""

    def f(k, v):
        d = det(1j * k, v)
        return [mp.re(d), mp.im(d)]

    k, v = mp.findroot(f, (mp.mpf("0.3"), mp.mpf("2.2")), tol=mp.mpf(10) ** -25)
    return k, v


def flutter_by_p(branch, grid, table):
    """Vbar where the p-method's `branch` root has Re p = 0: secant in Vbar,
    each root followed from the nearest tabulated one below it in steps of
    at most 0.005."""

    def root_at(v):
        k = max(i for i, g in enumerate(grid) if g <= v)
        steps = int(mp.ceil((v - grid[k]) / mp.mpf("0.005"))) or 1
        vs = [grid[k] + (v - grid[k]) * j / steps for j in range(1, steps + 1)]
        guesses = [table[k][branch]]
        for vj in vs:
            guesses = [mp.findroot(lambda p: det(p, vj), guesses[0], tol=mp.mpf(10) ** -25)]
        return guesses[0]

    # the bracket: the last tabulated Vbar with Re p < 0 and the next
    k = next(i for i in range(len(grid)) if mp.re(table[i][branch]) > 0)
    v = mp.findroot(lambda v: mp.re(root_at(v)), (grid[k - 1], grid[k]), solver="secant", tol=mp.mpf(10) ** -24)
    return v, root_at(v)


def main():
    # Vbar 0.5-2.4 (beyond it the plunge branch, heavily damped, nears the
    # other: followed further it can jump onto it)
    grid = [mp.mpf("0.5") + k * mp.mpf("0.025") for k in range(0, 77)]
    table = roots_along(grid)
    assert all(abs(r[0] - r[1]) > mp.mpf("0.01") for r in table), "a branch jumped"
    by_v = {}
    for k in range(0, 77, 4):
        by_v[mp.nstr(grid[k], 6)] = [[float(mp.re(p)), float(mp.im(p))] for p in table[k]]
    # the branch that crosses: the one with Re p > 0 at the last Vbar
    branch = 0 if mp.re(table[-1][0]) > 0 else 1
    k_f, v_k = flutter_by_k()
    v_p, p_f = flutter_by_p(branch, grid, table)
    assert abs(v_p - v_k) < mp.mpf(10) ** -12, (v_p, v_k)
    assert abs(mp.im(p_f) - k_f) < mp.mpf(10) ** -12, (p_f, k_f)
    out = {
        "source": "scripts/typical_section_p_method.py (mpmath, 30 digits)",
        "case": "Hodges & Pierce (2011) section 5.5: a = -1/5, x_a = 1/10, r^2 = 6/25, w_h/w_a = 2/5, mu = 20",
        "parameters": {"a": -0.2, "x_alpha": 0.1, "r2": 0.24, "sigma": 0.4, "mu": 20.0},
        "roots_p_by_vbar": by_v,
        "flutter": {
            "vbar_by_p_method": float(v_p),
            "vbar_by_k_method": float(v_k),
            "k": float(k_f),
            "omega_over_omega_alpha": float(k_f * v_k),
        },
        "note": "Vbar = V/(b w_alpha); p = s b / V; each Vbar: the plunge and the pitch branch (upper half plane), [re, im]; the pitch branch flutters",
    }
    path = os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "stability-core", "tests", "data", "typical_section", "p_method.json"
    )
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")
    print(json.dumps(out["flutter"], indent=1))


if __name__ == "__main__":
    main()
