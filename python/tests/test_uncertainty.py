"""uncertainty() against an independent plain-loop Monte Carlo over the
package's own analyze(), and against the command line."""

import math

import numpy as np
import pytest

import delta_stability as ds

from conftest import EXAMPLES

#: The 60° delta at M = 0.9 with the quasi-steady slender fairing (fast).
BASE = {
    "planform": {"sweep": 60.0, "taper": 0.0, "root_chord": 10.0},
    "flight": {"mach": 0.9, "cg": 0.25, "mu1": 50.0, "i_b": 0.08, "cl_m2": 0.05},
    "model": {"damping": "faired-slender"},
}


def _p(df, mach, quantity):
    row = df[(df["quantity"] == quantity) & np.isclose(df["mach"], mach)]
    assert len(row) == 1, (quantity, df)
    return row.iloc[0]


def test_the_probability_agrees_with_a_plain_loop_over_analyze():
    # μ₁ lognormal about 400 and the c.g. uniform: a case with both verdicts
    # at M = 1.5; the loop draws with numpy and calls analyze() per sample
    cfg = dict(BASE)
    cfg["flight"] = dict(BASE["flight"], mach=1.5)
    cfg["uncertainty"] = {
        "mu1": {"dist": "lognormal", "median": 300.0, "sigma": 0.5},
        "cg": {"dist": "uniform", "low": 0.2, "high": 0.4},
    }
    n = 1500
    df = ds.uncertainty(cfg, mach=1.5, samples=n, seed=7)
    p = _p(df, 1.5, "p_meets")
    rng = np.random.default_rng(2024)
    met = 0
    for _ in range(n):
        point = dict(BASE)
        point["flight"] = dict(
            BASE["flight"],
            mach=1.5,
            mu1=float(rng.lognormal(math.log(300.0), 0.5)),
            cg=float(rng.uniform(0.2, 0.4)),
        )
        # uncertainty judges each sample by its quartic (the k-method)
        met += ds.analyze(point, frequency_method="k").verdict == "meets"
    q = met / n
    assert 0.1 < q < 0.9, f"a case with both verdicts: {q}"
    se = math.sqrt(q * (1 - q) / n + p["value"] * (1 - p["value"]) / n)
    assert abs(p["value"] - q) < 3 * se, (p["value"], q)
    assert p["low"] < p["value"] < p["high"]


def test_the_package_gives_the_command_lines_numbers(cli):
    path = str(EXAMPLES / "delta-60-uncertain.toml")
    df = ds.uncertainty(path, mach="1.2:1.6:0.2", samples=500, seed=3, sobol=True)
    out = cli.json("uncertainty", path, "--mach", "1.2:1.6:0.2", "--samples", "500", "--seed", "3", "--sobol")
    assert df.attrs["results"]["results"] == out["results"]
    for r in out["results"]:
        assert _p(df, r["mach"], "p_meets")["value"] == pytest.approx(r["meets"]["p"], rel=1e-11)
    assert {"sobol_first_margin_mu1", "sobol_total_damping_ratio_model"} <= set(df["quantity"])


def test_a_bad_table_is_an_input_error_naming_its_field():
    cfg = dict(BASE, uncertainty={"i_b": {"dist": "normal", "sd": -1.0}})
    with pytest.raises(ds.InputError, match=r"\[uncertainty.i_b\] sd"):
        ds.uncertainty(cfg, mach=0.9, samples=10)


def test_sobol_sampling_is_the_command_lines_and_the_configs_by_default(cli):
    # the example says sampling = "sobol"; sampling="random" overrides it
    path = str(EXAMPLES / "delta-45-how-sure.toml")
    df = ds.uncertainty(path, mach="1.2,1.4", samples=256, seed=1953)
    assert df.attrs["results"]["sampling"] == "sobol"
    out = cli.json("uncertainty", path, "--mach", "1.2,1.4", "--samples", "256", "--seed", "1953")
    assert df.attrs["results"]["results"] == out["results"]
    random = ds.uncertainty(path, mach="1.2,1.4", samples=256, seed=1953, sampling="random")
    assert random.attrs["results"]["sampling"] == "random"
    with pytest.raises(ds.InputError, match="sampling"):
        ds.uncertainty(path, mach=1.2, samples=16, sampling="sobl")
