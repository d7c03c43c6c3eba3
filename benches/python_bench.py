"""The Python package's speed against the Python routes a user would take,
side by side in one run (figures are ratios measured here, never absolute
claims):

1. ``delta_stability.batch_roots`` on 10⁶ random quartics, against
   ``numpy.roots`` called in a loop (timed on a subset, extrapolated per
   quartic: the loop would take minutes) and against numpy's batched
   ``linalg.eigvals`` of the (10⁶, 4, 4) companion matrices;
2. ``delta_stability.sweep`` over the grid of ``cargo xtask bench``
   (benches/sweep-grid.json, 1 051 050 design points, planform to modes),
   against python-control's ``ss`` + ``damp`` per point and numpy's
   ``eigvals`` per point (both on the grid's first ``pointwise`` points,
   extrapolated) and numpy's batched ``eigvals`` on all of them. The Python
   routes are handed our derivatives (``sweep(…, derivatives=True)``) and
   only find the roots and the short period: they are spared the
   planform → derivatives part that ``sweep`` does.

   The damping model is pinned to the quasi-steady ``faired-slender`` (the
   grid file's ``options`` when it gives them, else here): the default
   ``faired`` iterates each subsonic point's frequency parameter through the
   doublet lattice (solved once per planform and Mach number, then
   interpolated), work the python-control route does not do, so timing it
   would compare unlike things.

Usage, with the package installed (``pip install ./python``) and numpy and
python-control in the same environment::

    python benches/python_bench.py [--quick]

Prints a Markdown table and writes target/bench/python-bench.json.
"""

import argparse
import json
import os
import pathlib
import sys
import time

import numpy as np

import delta_stability as ds

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benches"))
import sweep_baseline as baseline  # noqa: E402  (the xtask bench's baselines)


CPU = {}


def best_of(n, f, key=None):
    """The shortest wall-clock time of n calls, and the last result; the CPU
    time of that call (all threads) is kept in CPU[key]."""
    times, out = [], None
    for _ in range(n):
        c0, t0 = time.process_time(), time.perf_counter()
        out = f()
        times.append((time.perf_counter() - t0, time.process_time() - c0))
    wall, cpu = min(times)
    if key:
        CPU[key] = cpu
    return wall, out


def companion_eigvals(c):
    """numpy's batched route: the companion matrix of each monic quartic."""
    monic = c[:, 1:] / c[:, :1]
    m = np.zeros((len(c), 4, 4))
    m[:, 0, :] = -monic
    m[:, 1, 0] = m[:, 2, 1] = m[:, 3, 2] = 1.0
    return np.linalg.eigvals(m)


def nearest_gap(ours, theirs):
    """The largest |ours − theirs| / |ours| over a row, each of ours paired
    with the nearest of theirs."""
    d = np.abs(ours[:, :, None] - theirs[:, None, :]).min(axis=2)
    return float(np.max(d / np.maximum(np.abs(ours), 1e-300)))


def roots_bench(n, subset, repeats):
    rng = np.random.default_rng(2024)
    c = rng.normal(size=(n, 5))
    t_ours, ours = best_of(repeats, lambda: ds.batch_roots(c), "roots")
    t_batched, theirs = best_of(repeats, lambda: companion_eigvals(c))
    t0 = time.perf_counter()
    loop = [np.roots(row) for row in c[:subset]]
    t_loop = (time.perf_counter() - t0) * n / subset
    k = min(n, 20000)
    return {
        "quartics": n,
        "ours_s": t_ours,
        "ours_cpu_s": CPU["roots"],
        "numpy_batched_eigvals_s": t_batched,
        "numpy_roots_loop_s_extrapolated": t_loop,
        "numpy_roots_loop_subset": subset,
        "worst_relative_gap_batched": nearest_gap(ours[:k], theirs[:k]),
        "worst_relative_gap_loop": nearest_gap(ours[:subset], np.array(loop)),
    }


def sweep_bench(grid_file, subset, repeats):
    grid = json.loads(grid_file.read_text())
    axes = {name: value for name, value in grid["axes"]}
    kwargs = dict(mach=axes["mach"], cg=axes["cg"], mu1=axes["mu1"], sweep=axes["sweep"])
    # the quasi-steady fairing: see the module's docstring
    kwargs.update(dict(grid.get("options", [])))
    kwargs.setdefault("damping", "faired-slender")
    base = str(ROOT / grid["base"])
    t_ours, s = best_of(repeats, lambda: ds.sweep(base, **kwargs), "sweep")
    t_deriv, sd = best_of(1, lambda: ds.sweep(base, derivatives=True, **kwargs))
    ok = (sd["error"] == "") & ~np.isnan(sd["sp_re"])
    d = np.stack([sd[name][ok] for name in baseline.NAMES], axis=1)
    sp = (sd["sp_re"] + 1j * sd["sp_im"])[ok]
    k = min(subset, len(d))
    mats = baseline.state_matrices(d)
    t_ctl, r_ctl = baseline.python_control(mats, k)
    t_np1, r_np1 = baseline.numpy_pointwise(mats, k)
    t_npb, sp_np, _ = baseline.numpy_batched(d)
    n = len(s["mach"])
    return {
        "points": n,
        "damping": kwargs["damping"],
        "points_with_roots": int(ok.sum()),
        "ours_s": t_ours,
        "ours_cpu_s": CPU["sweep"],
        "ours_with_derivatives_s": t_deriv,
        "python_control_s_extrapolated": t_ctl * n / k,
        "numpy_pointwise_s_extrapolated": t_np1 * n / k,
        "pointwise_subset": k,
        "numpy_batched_s": t_npb * n / len(d),
        "worst_relative_gap_python_control": baseline.worst(sp[:k], [z for z, _ in r_ctl]),
        "worst_relative_gap_numpy_batched": baseline.worst(sp, sp_np),
    }


def table(r, s):
    """Wall-clock seconds and the speed-up over each route; and the speed-up
    per CPU second (ours runs on every core, each baseline on one: on a
    loaded machine the wall-clock figure understates ours)."""
    rows = [
        (f"batch_roots, {r['quartics']} quartics", r["ours_s"], r["ours_cpu_s"], None),
        ("  numpy.roots in a loop (extrapolated from "
         f"{r['numpy_roots_loop_subset']})", r["numpy_roots_loop_s_extrapolated"], None,
         r["worst_relative_gap_loop"]),
        ("  numpy batched companion eigvals", r["numpy_batched_eigvals_s"], None,
         r["worst_relative_gap_batched"]),
        (f"sweep, {s['points']} design points (planform → modes, {s['damping']})", s["ours_s"],
         s["ours_cpu_s"], None),
        (f"  python-control ss + damp per point (extrapolated from {s['pointwise_subset']})",
         s["python_control_s_extrapolated"], None, s["worst_relative_gap_python_control"]),
        (f"  numpy eigvals per point (extrapolated from {s['pointwise_subset']})",
         s["numpy_pointwise_s_extrapolated"], None, None),
        ("  numpy batched eigvals (derivatives given)", s["numpy_batched_s"], None,
         s["worst_relative_gap_numpy_batched"]),
    ]
    out = ["| route | wall s | ours ÷ route, wall | per CPU second | roots vs ours (worst rel.) |",
           "|---|---:|---:|---:|---:|"]
    ours = ours_cpu = None
    for name, t, cpu, gap in rows:
        if not name.startswith("  "):
            ours, ours_cpu = t, cpu
            out.append(f"| **{name}** | {t:.3f} (CPU {cpu:.3f}) | 1 | 1 | — |")
        else:
            g = "—" if gap is None else f"{gap:.1e}"
            out.append(f"| {name.strip()} | {t:.2f} | {t / ours:.0f}× | {t / ours_cpu:.0f}× | {g} |")
    return "\n".join(out)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--quick", action="store_true", help="10⁵ quartics and smaller subsets")
    a = p.parse_args()
    n = 100_000 if a.quick else 1_000_000
    roots = roots_bench(n, subset=2_000 if a.quick else 20_000, repeats=3)
    sweep = sweep_bench(ROOT / "benches/sweep-grid.json", subset=2_000 if a.quick else 20_000,
                        repeats=1 if a.quick else 3)
    import control
    versions = {"python": sys.version.split()[0], "numpy": np.__version__,
                "control": control.__version__, "delta_stability": ds.__version__,
                "cores": os.cpu_count()}
    print(f"Python routes against delta_stability, {versions}\n")
    print(table(roots, sweep))
    out = ROOT / "target" / "bench"
    out.mkdir(parents=True, exist_ok=True)
    (out / "python-bench.json").write_text(
        json.dumps({"versions": versions, "batch_roots": roots, "sweep": sweep}, indent=2))
    print("\nwrote target/bench/python-bench.json")


if __name__ == "__main__":
    main()
