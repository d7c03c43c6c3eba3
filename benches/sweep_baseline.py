"""The baselines of `cargo xtask bench`: the stability of the same design
points through python-control point by point, and through numpy's batched
eigenvalues.

Input: a CSV written by `delta-stability sweep --derivatives` (the fifteen
quartic inputs of each point, report notation, and our short-period root).
Each baseline starts from those derivatives -- it is spared the planform ->
coefficients -> derivatives part of the work that `delta-stability sweep`
does -- and finds the four roots of each point, picks the short period (the
complex pair of largest modulus) and its cycles to half amplitude, eq (8).
The roots are checked against ours.

The state matrix is that of eqs (2) in units of tau (stability-core's
response::StateSpace): with A = 1 - z_wdot/mu1 and the w-equation solved
for w',
    w' = (z_u u + z_w w + (1 + z_q/mu1) q) / A
    u' = x_u u + x_w w + x_q/mu1 q - c_l theta + x_wdot/mu1 w'
    q' = mu1/i_b (m_u u + m_w w) + m_q/i_b q + m_wdot/i_b w'
    theta' = q
Its eigenvalues are the roots of the quartic (4)-(6).

The design points are those of benches/sweep-grid.json (the grid is
defined there once); the point-by-point routes take its first `pointwise`.

Usage: python sweep_baseline.py GRID.json POINTS.csv > result.json
"""

import csv
import json
import sys
import time

import control
import numpy as np

NAMES = ["x_u", "x_w", "x_wdot", "x_q", "z_u", "z_w", "z_wdot", "z_q",
         "m_u", "m_w", "m_wdot", "m_q", "c_l", "mu1", "i_b"]


def read(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["error"] == "" and r["sp_re"] != ""]
    d = np.array([[float(r[n]) for n in NAMES] for r in rows])
    sp = np.array([complex(float(r["sp_re"]), float(r["sp_im"])) for r in rows])
    return d, sp


def state_matrices(d):
    """The (N, 4, 4) state matrices of eqs (2), vectorised."""
    (x_u, x_w, x_wdot, x_q, z_u, z_w, z_wdot, z_q,
     m_u, m_w, m_wdot, m_q, c_l, mu1, i_b) = d.T
    a = 1.0 - z_wdot / mu1
    w = np.stack([z_u / a, z_w / a, (1.0 + z_q / mu1) / a, np.zeros_like(a)], axis=1)
    xw = (x_wdot / mu1)[:, None]
    mw = (m_wdot / i_b)[:, None]
    m = np.zeros((len(d), 4, 4))
    m[:, 0, :] = np.stack([x_u, x_w, x_q / mu1, -c_l], axis=1) + xw * w
    m[:, 1, :] = w
    m[:, 2, :] = np.stack([mu1 / i_b * m_u, mu1 / i_b * m_w, m_q / i_b,
                           np.zeros_like(a)], axis=1) + mw * w
    m[:, 3, 2] = 1.0
    return m


def short_period(poles):
    """The complex root of largest modulus with s > 0, and its cycles to
    half amplitude, eq (8): 0.11032 s/(-r)."""
    upper = [p for p in poles if p.imag > 0]
    sp = max(upper, key=abs) if upper else complex("nan")
    cycles = 0.11032 * sp.imag / -sp.real if sp.real < 0 else float("inf")
    return sp, cycles


def python_control(mats, n):
    """Point by point: a state-space system per point and its modes by
    control.damp (natural frequencies, damping ratios, poles: what our sweep
    reports), then the short period (what a python-control user writes in a
    loop)."""
    b = np.zeros((4, 1))
    b[2, 0] = 1.0
    c = np.eye(4)
    dd = np.zeros((4, 1))
    out = []
    t0 = time.perf_counter()
    for k in range(n):
        sys_ = control.ss(mats[k], b, c, dd)
        _wn, _zeta, poles = control.damp(sys_, doprint=False)
        out.append(short_period(poles))
    return time.perf_counter() - t0, out


def numpy_pointwise(mats, n):
    out = []
    t0 = time.perf_counter()
    for k in range(n):
        out.append(short_period(np.linalg.eigvals(mats[k])))
    return time.perf_counter() - t0, out


def numpy_batched(d):
    """All points at once: build the stack, batched eigvals, vectorised
    mode picking."""
    t0 = time.perf_counter()
    mats = state_matrices(d)
    ev = np.linalg.eigvals(mats)
    key = np.where(ev.imag > 0, np.abs(ev), -1.0)
    sp = np.take_along_axis(ev, key.argmax(axis=1)[:, None], axis=1)[:, 0]
    with np.errstate(divide="ignore", invalid="ignore"):
        cycles = np.where(sp.real < 0, 0.11032 * sp.imag / -sp.real, np.inf)
    return time.perf_counter() - t0, sp, cycles


def worst(ours, theirs):
    return float(np.max(np.abs(np.asarray(theirs) - ours) / np.abs(ours)))


def main():
    grid_path, path = sys.argv[1], sys.argv[2]
    with open(grid_path) as f:
        max_pointwise = int(json.load(f)["pointwise"])
    d, ours = read(path)
    n = len(d)
    k = min(n, max_pointwise)
    mats = state_matrices(d)
    t_ctl, r_ctl = python_control(mats, k)
    t_np1, r_np1 = numpy_pointwise(mats, k)
    t_np, sp_np, _ = numpy_batched(d)
    print(json.dumps({
        "points": n,
        "python_control": {"points": k, "seconds": t_ctl, "points_per_second": k / t_ctl,
                           "worst_relative_difference": worst(ours[:k], [s for s, _ in r_ctl])},
        "numpy_pointwise": {"points": k, "seconds": t_np1, "points_per_second": k / t_np1,
                            "worst_relative_difference": worst(ours[:k], [s for s, _ in r_np1])},
        "numpy_batched": {"points": n, "seconds": t_np, "points_per_second": n / t_np,
                          "worst_relative_difference": worst(ours, sp_np)},
        "versions": {"python": sys.version.split()[0], "numpy": np.__version__,
                     "control": control.__version__},
    }, indent=2))


if __name__ == "__main__":
    main()
