#!/usr/bin/env python3
"""The exact short-period and phugoid roots of an aircraft whose wing is a
true delta with supersonic leading edges, its air forces taken at the root's
own complex frequency (the p-method), beside the k-method and the p-k
method's roots: the reference written to
stability-core/tests/data/supersonic_oscillatory/p_method.json.

The wing's loads (scripts/supersonic_oscillatory_reference.py): the
two-dimensional flat plate of I.E. Garrick and S.I. Rubinow (NACA Rep. 846,
1946), kernel g(u) = exp(-i sigma u) J0(nu u), sigma = kappa M^2/beta^2,
nu = kappa M/beta^2, Delta C_p = (4/beta)(i kappa Phi + dPhi/ds), carried to
the true delta by the reverse-flow theorem (H.J. Flax, J. Aero. Sci. 19,
1952): root chord 1, cbar = 2/3, xbar = 1/3, independent of the sweep while
beta cot(Lambda) > 1 (asserted per case).

Analytic continuation. Every one of those formulas is entire in kappa, so a
motion e^{pt} of complex p is the harmonic one with i kappa -> P = p/V per
unit root chord, kappa = -i P (then g(u) = exp(-P M^2 u/beta^2)
I0(P M u/beta^2), real for real P). With pbar = p cbar/V = P cbar:

  A_L(pbar), A_M(pbar)  C_L and C_m (nose up, about the M.A.C.'s leading
                        edge) for the normalwash w_F = 1 (incidence),
  R_L(pbar), R_M(pbar)  the same for w_F = (x - xbar)/cbar (unit rate).

The outer reverse-flow integral and the inner ones of Phi are exchanged, so
that each of the four is a polynomial combination of the moments
m_k(P) = int_0^1 u^k g(u) du, k = 0..4, taken by composite Gauss-Legendre
(20 points on pieces of at most two radians of |P| M (M + 1)/beta^2 u).

Checks (asserted; their values in the fixture's "verification"): a finer
rule (30 points, one radian); the steady C_L_alpha = 4/beta and h0 = 1/2;
the small-frequency limits by hand, l_adot(0) = -2/beta^3,
mu_adot(0) = 5/(4 beta^3); the script above's own nested mpmath quad at
pbar = 0.3 i (its real omega_bar 0.3) to 1e-12, and its load() taken at
complex kappa = -i P off the axis (pbar = -0.06 + 0.45 i and each case's
exact short-period root); every delta case of its reference.json to 1e-12;
conjugate symmetry on the axis; per case, the exact determinant equal to the
p-k one on the imaginary axis, and the same exact root from the p-k start.

The "six numbers" at the complex frequency w_c = -i pbar are the even and
odd parts of the transfer functions (exact continuations of the real-axis
l_a = Re A_L(i w), l_adot = Im A_L(i w)/w, ...):

  l_a  = [A_L(pbar) + A_L(-pbar)]/2,   l_adot  = [A_L(pbar) - A_L(-pbar)]/(2 pbar),
  mu_a = [A_M(pbar) + A_M(-pbar)]/2,   mu_adot = [A_M(pbar) - A_M(-pbar)]/(2 pbar),
  l_q  = [R_L(pbar) + R_L(-pbar)]/2,   mu_q    = [R_M(pbar) + R_M(-pbar)]/2
  (the rate response's odd part, a qdot derivative, neglected).

Steady: l_a0 = A_L(0) = 4/beta, mu_a0 = A_M(0), h0 = -mu_a0/l_a0 (= 1/2).

Equations of motion: W.B. McCarter (1953), eq (4), time unit tau, root lam,
pbar = lam/mu1 (stability-core/specs/quartic.toml, [determinant]):

  | lam - x_u      -(x_w + x_wdot/mu1 lam)          c_l - x_q/mu1 lam      |
  | -z_u           -(z_w + (z_wdot/mu1 - 1) lam)    -(z_q/mu1 + 1) lam     | = 0
  | -mu1/i_b m_u   -(mu1/i_b m_w + m_wdot/i_b lam)  lam^2 - m_q/i_b lam    |

with the wing's lifting terms only from the loads above (the others, x_u,
x_w, x_wdot, x_q, z_u, m_u, c_l, c_d, from the Rust program):

  z_q = -(l_q - h l_a),  m_q = mu_q - h mu_a - h^2 l_a + h l_q,

and three ways of taking them:
* exact (the p-method: H.J. Hassig, J. Aircraft 8(11), 1971; Edwards,
  Ashley & Breakwell, AIAA J. 17(4), 1979): the whole incidence response at
  the root, z_w + z_wdot pbar -> -(A_L(pbar) + c_d), m_w + m_wdot pbar ->
  A_M(pbar) + h A_L(pbar) + (h - h0) c_d, and z_q, m_q with the six numbers
  at w_c = -i pbar; det(lam) = 0 by the secant method (30 digits, to a
  relative step below 1e-20), short period and phugoid each at its own pbar,
  started from the k-method's quartic;
* k-method: steady z_w = -(l_a0 + c_d), m_w = (h - h0)(l_a0 + c_d);
  z_wdot = -l_adot(w), m_wdot = mu_adot(w) + h l_adot(w) and z_q, m_q at a
  real omega_bar w; the quartic's short-period root, w = Im(lam)/mu1 to a
  fixed point (secant on Im(lam(w))/mu1 - w);
* p-k: as the k-method, with also z_w = -(l_a(w) + c_d),
  m_w = mu_a(w) + h l_a(w) + (h - h0) c_d.

Per root: re, im (lam), omega_bar = Im(lam)/mu1, sigma_bar = Re(lam)/mu1,
cycles_to_half = ln2/(2 pi) |Im lam|/|Re lam| (null unless Re lam < 0 and
Im lam != 0). The k and p-k blocks add "phugoid_of_quartic", the phugoid of
the same quartic (derivatives at the short period's omega_bar), for scale;
the exact block a "convergence" record (secant steps, Newton's last step,
the loads at the root against the nested quad).

Continuation block per case (the case's Mach number), for the Rust unit test:
"axis": [l_a, mu_a, l_adot, mu_adot, l_q, mu_q] at omega_bar = 0, 0.025, ...,
1.5 (61 points; at 0 the limit: l_a0, mu_a0, l_q, mu_q at pbar = 0, and
l_adot, mu_adot the odd-part formula at pbar = 1e-12 with 15 more digits,
which is A'(0) to O(1e-24)); "complex": at pbar = sigma + i w, sigma in
{0, -0.05, -0.1, -0.2}, w in {0.2, 0.4, 0.6, 0.8}, the six numbers at w_c = -i pbar and A_L, A_M,
R_L, R_M at pbar, each complex as [re, im].

Input: stability-core/tests/data/supersonic_oscillatory/p_method_cases.json
({"cases": [{"name", "sweep_deg", "mach", "mu1", "i_b", "h", "c_l", "c_d",
"x_u", "x_w", "x_wdot", "x_q", "z_u", "m_u"}, ...]}); without it, one
made-up case (M = 2, sweep 45 deg).

  python3 scripts/supersonic_p_method_reference.py [cases.json]   (mpmath)
"""

import importlib.util
import json
import os
import sys
import time

from mpmath import mp, mpf, mpc, besselj, exp, sqrt, cos, pi, tan, radians, log

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.normpath(os.path.join(HERE, "..", "stability-core", "tests", "data", "supersonic_oscillatory"))

mp.dps = 30

CBAR, XBAR = mpf(2) / 3, mpf(1) / 3


# --- polynomials in u: coefficient lists, lowest power first ----------------

def padd(a, b):
    n = max(len(a), len(b))
    return [(a[i] if i < len(a) else 0) + (b[i] if i < len(b) else 0) for i in range(n)]


def pmul(a, b):
    out = [mpf(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return out


def pscale(a, c):
    return [c * x for x in a]


def tail(f):
    """T(u) = int_u^1 f(s) ds."""
    anti = [mpf(0)] + [c / (k + 1) for k, c in enumerate(f)]
    return padd([sum(anti)], pscale(anti, -1))


# --- the wing's loads at complex P -------------------------------------------

def gauss(m):
    """m-point Gauss-Legendre nodes and weights on [0, 1] (Newton on P_m)."""
    out = []
    for k in range(1, m + 1):
        x = cos(pi * (k - mpf(1) / 4) / (m + mpf(1) / 2))
        for _ in range(100):
            p0, p1 = mpf(1), x
            for n in range(2, m + 1):
                p0, p1 = p1, ((2 * n - 1) * x * p1 - (n - 1) * p0) / n
            dp = m * (x * p1 - p0) / (x * x - 1)
            dx = p1 / dp
            x -= dx
            if abs(dx) < mpf(10) ** -(mp.dps + 2):
                break
        out.append(((1 - x) / 2, 1 / ((1 - x * x) * dp * dp)))
    return out


RULES = {}


def moments(mach, P, kmax=4, m=20, radians_per_piece=2):
    """m_k = int_0^1 u^k g(u) du, g(u) = exp(-i sigma u) J0(nu u) at kappa = -i P."""
    if m not in RULES:
        RULES[m] = gauss(m)
    rule = RULES[m]
    b2 = mach * mach - 1
    kappa = -1j * mpc(P)
    sigma, nu = kappa * mach * mach / b2, kappa * mach / b2
    rate = abs(P) * mach * (mach + 1) / b2
    pieces = int(mp.ceil(rate / radians_per_piece)) + 1
    out = [mpc(0)] * (kmax + 1)
    h = mpf(1) / pieces
    for j in range(pieces):
        for t, w in rule:
            u = h * (j + t)
            gu = exp(-1j * sigma * u) * besselj(0, nu * u) * w * h
            uk = mpf(1)
            for k in range(kmax + 1):
                out[k] += uk * gu
                uk *= u
    return out


def strip_integral(mom, beta, P, a, b, f):
    """int_0^1 f(s) Delta C_p(s) ds of the plate for wbar = a + b s, by
    Phi = a G0 + b (s G0 - G1), dPhi/ds = a g + b G0, G0 = int_0^s g,
    G1 = int_0^s u g, and int_0^1 f(s) G_j(s) ds = int_0^1 u^j g(u) T_f(u) du."""
    def against(poly):
        return sum(c * mom[k] for k, c in enumerate(poly))
    t_f, t_sf = tail(f), tail(pmul([0, 1], f))
    i_g = against(f)
    i_g0 = against(t_f)
    i_sg0 = against(t_sf)
    i_g1 = against(pmul([0, 1], t_f))
    phi = a * i_g0 + b * (i_sg0 - i_g1)
    dphi = a * i_g + b * i_g0
    return 4 / beta * (P * phi + dphi)


def loads(mach, pbar, **rule):
    """(A_L, A_M, R_L, R_M) at pbar for the true delta (reverse flow)."""
    mach = mpf(mach)
    beta = sqrt(mach * mach - 1)
    P = mpc(pbar) / CBAR
    mom = moments(mach, P, **rule)
    one_minus = [mpf(1), mpf(-1)]                                   # 1 - s
    rate = pscale(padd(one_minus, [-XBAR]), 1 / CBAR)               # w_F(1 - s)
    f1, fq = pscale(one_minus, 2), pscale(pmul(rate, one_minus), 2)
    a_l = strip_integral(mom, beta, P, 1, 0, f1)
    r_l = strip_integral(mom, beta, P, 1, 0, fq)
    a_m = -strip_integral(mom, beta, P, 1 - XBAR, -1, f1) / CBAR
    r_m = -strip_integral(mom, beta, P, 1 - XBAR, -1, fq) / CBAR
    return a_l, a_m, r_l, r_m


SMALL = mpf(10) ** -12


def six(mach, pbar):
    """[l_a, mu_a, l_adot, mu_adot, l_q, mu_q] at w_c = -i pbar (complex)."""
    pbar = mpc(pbar)
    if pbar == 0:
        a0 = loads(mach, 0)
        with mp.workdps(mp.dps + 15):           # the difference loses 12 digits
            odd = six(mach, SMALL)
        return [a0[0], a0[1], +odd[2], +odd[3], a0[2], a0[3]]
    plus, minus = loads(mach, pbar), loads(mach, -pbar)
    even = [(x + y) / 2 for x, y in zip(plus, minus)]
    odd = [(x - y) / (2 * pbar) for x, y in zip(plus, minus)]
    return [even[0], even[1], odd[0], odd[1], even[2], even[3]]


def real_six(mach, w):
    """The six numbers at a real omega_bar w (real-valued)."""
    return [x.real for x in six(mach, mpc(0, w))]


# --- equations of motion -----------------------------------------------------

def entries(c, lam, z_w, m_w, z_q, m_q):
    """McCarter eq (4) with the incidence responses z_w, m_w given as the
    whole coefficients of w (z_w + z_wdot pbar, m_w + m_wdot pbar)."""
    mu1, i_b = c["mu1"], c["i_b"]
    return [
        [lam - c["x_u"], -(c["x_w"] + c["x_wdot"] / mu1 * lam), c["c_l"] - c["x_q"] / mu1 * lam],
        [-c["z_u"], -(z_w - lam), -(z_q / mu1 + 1) * lam],
        [-mu1 / i_b * c["m_u"], -(mu1 / i_b * m_w), lam * lam - m_q / i_b * lam],
    ]


def det3(e):
    return (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1])
            - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0])
            + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]))


def rate_terms(h, s):
    l_a, mu_a, l_adot, mu_adot, l_q, mu_q = s
    return -(l_q - h * l_a), mu_q - h * mu_a - h * h * l_a + h * l_q


def det_exact(c, lam):
    mach, h, c_d = c["mach"], c["h"], c["c_d"]
    pbar = lam / c["mu1"]
    a_l, a_m, _, _ = loads(mach, pbar)
    z_q, m_q = rate_terms(h, six(mach, pbar))
    z_w = -(a_l + c_d)
    m_w = a_m + h * a_l + (h - c["h0"]) * c_d
    return det3(entries(c, lam, z_w, m_w, z_q, m_q))


def quartic_roots(c, z_w, z_wdot, m_w, m_wdot, z_q, m_q):
    """The four roots of eq (4) with constant derivatives: the determinant
    expanded as a polynomial (entries linear in lam, lam^2 in (3,3))."""
    mu1 = c["mu1"]
    # each entry, quadratic in lam, through lam = 0, 1, 2
    zero = entries(c, 0, z_w, m_w, z_q, m_q)
    one = entries(c, 1, z_w + z_wdot / mu1, m_w + m_wdot / mu1, z_q, m_q)
    two = entries(c, 2, z_w + 2 * z_wdot / mu1, m_w + 2 * m_wdot / mu1, z_q, m_q)
    poly = [[None] * 3 for _ in range(3)]
    for i in range(3):
        for j in range(3):
            f0, f1, f2 = zero[i][j], one[i][j], two[i][j]
            a2 = (f2 - 2 * f1 + f0) / 2
            a1 = f1 - f0 - a2
            poly[i][j] = [f0, a1, a2]

    def cof(a, b, cc, d):
        return padd(pmul(a, b), pscale(pmul(cc, d), -1))
    p = poly
    d = padd(padd(pmul(p[0][0], cof(p[1][1], p[2][2], p[1][2], p[2][1])),
                  pscale(pmul(p[0][1], cof(p[1][0], p[2][2], p[1][2], p[2][0])), -1)),
             pmul(p[0][2], cof(p[1][0], p[2][1], p[1][1], p[2][0])))
    while abs(d[-1]) < mpf(10) ** -(mp.dps - 5) * max(abs(x) for x in d):
        d.pop()
    roots = mp.polyroots(d[::-1], maxsteps=200, extraprec=60)
    # check against the determinant itself
    for r in roots:
        pb = r / mu1
        val = det3(entries(c, r, z_w + z_wdot * pb, m_w + m_wdot * pb, z_q, m_q))
        scale = max(1, abs(r)) ** 4
        assert abs(val) < mpf(10) ** -15 * scale, (r, val)
    return roots


def pick(roots, which):
    """The short period (largest |lam|) or the phugoid (smallest), Im >= 0."""
    ordered = sorted(roots, key=lambda r: abs(r))
    r = ordered[-1] if which == "short" else ordered[0]
    return mpc(r.real, abs(r.imag))


def report(c, lam):
    mu1 = c["mu1"]
    lam = mpc(lam)
    cyc = None
    if lam.real < 0 and lam.imag != 0:
        cyc = float(log(2) / (2 * pi) * abs(lam.imag) / abs(lam.real))
    return {"re": float(lam.real), "im": float(lam.imag),
            "omega_bar": float(lam.imag / mu1), "sigma_bar": float(lam.real / mu1),
            "cycles_to_half": cyc}


def frequency_derivatives(c, w, pk):
    """(z_w, z_wdot, m_w, m_wdot, z_q, m_q) of the k-method (pk False) or
    the p-k method (pk True) at a real omega_bar w."""
    h, c_d = c["h"], c["c_d"]
    s = real_six(c["mach"], w)
    l_a, mu_a, l_adot, mu_adot, l_q, mu_q = s
    z_q, m_q = rate_terms(h, s)
    if pk:
        z_w = -(l_a + c_d)
        m_w = mu_a + h * l_a + (h - c["h0"]) * c_d
    else:
        z_w = -(c["l_a0"] + c_d)
        m_w = (h - c["h0"]) * (c["l_a0"] + c_d)
    return z_w, -l_adot, m_w, mu_adot + h * l_adot, z_q, m_q


def det_frequency(c, w, pk, lam):
    z_w, z_wdot, m_w, m_wdot, z_q, m_q = frequency_derivatives(c, w, pk)
    pbar = lam / c["mu1"]
    return det3(entries(c, lam, z_w + z_wdot * pbar, m_w + m_wdot * pbar, z_q, m_q))


def frequency_method(c, pk):
    """k-method (pk False) or p-k (pk True): derivatives at real omega_bar w,
    w = Im(lam_sp)/mu1 by the secant method."""
    mu1 = c["mu1"]

    def root(w):
        return quartic_roots(c, *frequency_derivatives(c, w, pk))

    w0 = pick(root(mpf("0.3")), "short").imag / mu1
    w1 = pick(root(w0), "short").imag / mu1
    f0 = w0 - mpf("0.3")
    f1 = w1 - w0
    x0, x1 = w0, w1
    steps = 0
    while abs(x1 - x0) > mpf(10) ** -22 * abs(x1):
        steps += 1
        assert steps < 60
        x2 = x1 - f1 * (x1 - x0) / (f1 - f0)
        roots = root(x2)
        f0, x0 = f1, x1
        x1 = x2
        f1 = pick(roots, "short").imag / mu1 - x1
    roots = root(x1)
    sp, ph = pick(roots, "short"), pick(roots, "phugoid")
    assert abs(sp.imag / mu1 - x1) < mpf(10) ** -20
    return sp, ph, x1


def secant(f, x0, x1, tol=mpf(10) ** -20, maxit=60):
    f0, f1 = f(x0), f(x1)
    hist = []
    for it in range(maxit):
        x2 = x1 - f1 * (x1 - x0) / (f1 - f0)
        step = abs(x2 - x1) / abs(x2)
        hist.append(float(step))
        x0, f0, x1 = x1, f1, x2
        f1 = f(x1)
        if step < tol:
            return x1, hist, f1
    raise RuntimeError("secant did not converge: %s" % hist)


def exact_root(c, guess):
    lam, hist, res = secant(lambda l: det_exact(c, l), guess, guess * (1 + mpf("1e-3")))
    assert hist[-1] < 1e-12
    # Newton's step from the residual: the root's relative error
    eps = mpf(10) ** -10
    slope = (det_exact(c, lam * (1 + eps)) - res) / (eps * lam)
    return lam, {"iterations": len(hist), "relative_steps": hist,
                 "newton_step_relative": float(abs(res / slope) / abs(lam))}


# --- checks ------------------------------------------------------------------

_EXISTING = []


def existing_module():
    if _EXISTING:
        return _EXISTING[0]
    spec = importlib.util.spec_from_file_location(
        "supersonic_oscillatory_reference", os.path.join(HERE, "supersonic_oscillatory_reference.py"))
    mod = importlib.util.module_from_spec(spec)
    dps = mp.dps
    spec.loader.exec_module(mod)          # it sets mp.dps = 20
    mp.dps = dps
    _EXISTING.append(mod)
    return mod


NAMES = ["lift_alpha", "moment_alpha", "lift_alphadot", "moment_alphadot", "lift_q", "moment_q"]


def checks(machs):
    out = {}
    # the quadrature: a finer rule at a complex pbar of each Mach number
    worst = 0
    for mach in machs:
        for pbar in [mpc("-0.2", "0.8"), mpc("0", "1.5"), mpc("0.1", "-0.5"), mpc("-0.05", "0.01")]:
            a = loads(mach, pbar)
            b = loads(mach, pbar, m=30, radians_per_piece=1)
            worst = max(worst, max(abs(x - y) / abs(y) for x, y in zip(a, b)))
    assert worst < 1e-25, worst
    out["quadrature_vs_finer_rule"] = float(worst)
    # steady lift slope 4/beta, aerodynamic centre 1/2
    worst = 0
    for mach in machs:
        beta = sqrt(mpf(mach) ** 2 - 1)
        a_l, a_m, _, _ = loads(mach, 0)
        worst = max(worst, abs(a_l - 4 / beta) * beta / 4, abs(-a_m / a_l - mpf(1) / 2))
    assert worst < 1e-25, worst
    out["steady_lift_slope_vs_4_over_beta"] = float(worst)
    # the existing script's nested quad, at pbar = 0.3 i (its kappa real)
    mod = existing_module()
    worst = 0
    for mach in machs:
        with mp.workdps(20):
            ref = mod.delta(mpf(mach), mpf("0.3"))
        mine = real_six(mach, mpf("0.3"))
        worst = max(worst, max(abs(mine[i] - ref[n]) / (1 + abs(ref[n])) for i, n in enumerate(NAMES)))
    assert worst < 1e-12, worst
    out["existing_nested_quad_at_pbar_0.3i"] = float(worst)
    # every delta case of reference.json
    with open(os.path.join(DATA, "reference.json")) as f:
        ref = json.load(f)
    worst = 0
    n = 0
    for case in ref["cases"]:
        if case["wing"] != "delta":
            continue
        mine = real_six(case["mach"], mpf(case["omega_bar"]))
        worst = max(worst, max(abs(mine[i] - case[k]) / (1 + abs(case[k])) for i, k in enumerate(NAMES)))
        n += 1
    assert worst < 1e-12, worst
    out["reference_json_delta_cases"] = {"count": n, "worst": float(worst)}
    # the small-frequency limits, by hand from g(u) = 1 - P M^2 u/beta^2 + O(P^2):
    # A_L = (4/beta)(1 - P/(3 beta^2)), A_M = -(4/beta)(1/2 - 5 P/(24 beta^2)),
    # R_L(0) = (4/beta)/2, R_M(0) = -(4/beta)(3/8); so l_adot(0) = -2/beta^3,
    # mu_adot(0) = 5/(4 beta^3)
    worst = 0
    for mach in machs:
        beta = sqrt(mpf(mach) ** 2 - 1)
        s = real_six(mach, 0)
        exact = [4 / beta, -2 / beta, -2 / beta**3, 5 / (4 * beta**3), 2 / beta, -3 / (2 * beta)]
        worst = max(worst, max(abs(x - y) / abs(y) for x, y in zip(s, exact)))
    assert worst < 1e-20, worst
    out["small_frequency_limits"] = float(worst)
    # conjugate symmetry on the axis
    worst = 0
    for mach in machs:
        w = mpf("0.45")
        a = loads(mach, mpc(0, w))
        b = loads(mach, mpc(0, -w))
        worst = max(worst, max(abs(x - y.conjugate()) for x, y in zip(a, b)))
    assert worst < 1e-25, worst
    out["conjugate_symmetry"] = float(worst)
    # the continuation against the existing script's own nested quad
    # (load() at complex kappa = -i P, outer quad as its delta()), off the axis
    worst = 0
    for mach in machs:
        worst = max(worst, nested_quad_check(mod, mach, mpc("-0.06", "0.45")))
    assert worst < 1e-15, worst
    out["existing_nested_quad_at_pbar_-0.06+0.45i"] = float(worst)
    return out


def nested_quad_check(mod, mach, pbar):
    """Largest relative difference of (A_L, A_M, R_L, R_M) at a complex pbar
    between loads() and the existing script's nested mpmath quad (20 digits)."""
    mine = loads(mach, pbar)
    with mp.workdps(20):
        mach = mpf(mach)
        kappa = -1j * mpc(pbar) / CBAR
        lift = mod.load(mach, kappa, 1, 0)
        pitch = mod.load(mach, kappa, 1 - XBAR, -1)
        forward = [lambda s: 1, lambda s: ((1 - s) - XBAR) / CBAR]
        cl = [2 * mp.quad(lambda s: lift(s) * w(s) * (1 - s), [0, 1]) for w in forward]
        cm = [-2 / CBAR * mp.quad(lambda s: pitch(s) * w(s) * (1 - s), [0, 1]) for w in forward]
    return max(abs(x - y) / abs(y) for x, y in zip(mine, [cl[0], cm[0], cl[1], cm[1]]))


# --- the fixture -------------------------------------------------------------

def pair(z):
    z = mpc(z)
    return [float(z.real), float(z.imag)]


def continuation(mach):
    axis = []
    for k in range(61):
        w = mpf(k) / 40
        axis.append({"omega_bar": float(w), "six": [float(x) for x in real_six(mach, w)]})
    complex_ = []
    for sig in ["0", "-0.05", "-0.1", "-0.2"]:
        for w in ["0.2", "0.4", "0.6", "0.8"]:
            pbar = mpc(sig, w)
            a = loads(mach, pbar)
            complex_.append({"pbar": pair(pbar),
                             "six": [pair(x) for x in six(mach, pbar)],
                             "A_L": pair(a[0]), "A_M": pair(a[1]),
                             "R_L": pair(a[2]), "R_M": pair(a[3])})
    return {"order": ["l_a", "mu_a", "l_adot", "mu_adot", "l_q", "mu_q"],
            "axis_note": "omega_bar 0 is the limit: l_a0, mu_a0, l_q, mu_q at pbar = 0; "
                         "l_adot, mu_adot by the odd-part formula at pbar = 1e-12 (A'(0) to O(1e-24)), "
                         "which are -2/beta^3 and 5/(4 beta^3)",
            "axis": axis, "complex": complex_}


KEYS = ["mu1", "i_b", "h", "c_l", "c_d", "x_u", "x_w", "x_wdot", "x_q", "z_u", "m_u"]


def solve_case(case):
    c = {k: mpf(case[k]) for k in KEYS}
    c["mach"] = mpf(case["mach"])
    beta = sqrt(c["mach"] ** 2 - 1)
    sweep = radians(mpf(case["sweep_deg"]))
    assert beta / tan(sweep) > 1, "subsonic leading edge: beta cot(sweep) = %s" % (beta / tan(sweep))
    a_l0, a_m0, _, _ = loads(c["mach"], 0)
    a_l0, a_m0 = a_l0.real, a_m0.real
    c["l_a0"], c["h0"] = a_l0, -a_m0 / a_l0
    k_sp, k_ph, k_w = frequency_method(c, pk=False)
    pk_sp, pk_ph, pk_w = frequency_method(c, pk=True)
    sp, sp_conv = exact_root(c, k_sp)
    ph, ph_conv = exact_root(c, k_ph)
    # the same short-period root from the p-k root
    again, _ = exact_root(c, pk_sp)
    assert abs(again - sp) < mpf(10) ** -20 * abs(sp), (again, sp)
    # on the imaginary axis the exact determinant is the p-k one at that w
    w = mpf("0.4")
    lam = mpc(0, w * c["mu1"])
    pk_det = det_frequency(c, w, True, lam)
    assert abs(det_exact(c, lam) - pk_det) < mpf(10) ** -22 * abs(pk_det)
    # the loads at the root's own pbar against the existing nested quad
    sp_conv["loads_vs_existing_nested_quad"] = float(
        nested_quad_check(existing_module(), c["mach"], sp / c["mu1"]))
    assert sp_conv["loads_vs_existing_nested_quad"] < 1e-15
    out = {k: case[k] for k in case}
    out["steady"] = {"l_a0": float(a_l0), "mu_a0": float(a_m0), "h0": float(c["h0"]),
                     "four_over_beta": float(4 / beta)}
    out["exact"] = {"short_period": report(c, sp), "phugoid": report(c, ph),
                    "convergence": {"short_period": sp_conv, "phugoid": ph_conv}}
    out["k_method"] = {"short_period": report(c, k_sp), "omega_bar": float(k_w),
                       "phugoid_of_quartic": report(c, k_ph)}
    out["p_k"] = {"short_period": report(c, pk_sp), "omega_bar": float(pk_w),
                  "phugoid_of_quartic": report(c, pk_ph)}
    out["continuation"] = continuation(c["mach"])
    return out


DEFAULT = {"cases": [{"name": "made-up", "sweep_deg": 45.0, "mach": 2.0, "mu1": 50.0, "i_b": 0.08,
                      "h": 0.25, "c_l": 0.02, "c_d": 0.01, "x_u": -0.02, "x_w": 0.05,
                      "x_wdot": 0.0, "x_q": 0.0, "z_u": -0.1, "m_u": 0.0}]}


def main():
    start = time.time()
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(DATA, "p_method_cases.json")
    if os.path.exists(path):
        with open(path) as f:
            inp = json.load(f)
        src = os.path.relpath(path, os.path.join(HERE, ".."))
    else:
        inp, src = DEFAULT, "made-up case (no %s)" % path
    machs = sorted({mpf(c["mach"]) for c in inp["cases"]})
    verification = checks(machs)
    print("checks:", verification, flush=True)
    cases = []
    for case in inp["cases"]:
        t = time.time()
        cases.append(solve_case(case))
        r = cases[-1]
        print(case["name"], "cycles to half: exact %s, k %s, p-k %s (%.1f s)" % (
            r["exact"]["short_period"]["cycles_to_half"], r["k_method"]["short_period"]["cycles_to_half"],
            r["p_k"]["short_period"]["cycles_to_half"], time.time() - t), flush=True)
    out = os.path.join(DATA, "p_method.json")
    with open(out, "w") as f:
        json.dump({"source": "scripts/supersonic_p_method_reference.py", "input": src,
                   "verification": verification, "cases": cases}, f, indent=1)
        f.write("\n")
    print("wrote %s in %.1f s" % (out, time.time() - start))


if __name__ == "__main__":
    main()
