"""sweep against a Python loop over analyze (the same design points one by
one through the per-point route), and the GIL released while it runs."""

import threading
import time

import numpy as np
import pytest

import delta_stability as ds

BASE = "examples/delta-60.toml"


def same(column_value, value):
    """A column's value is the attribute's (NaN where it is None)."""
    if value is None:
        return bool(np.isnan(column_value))
    return column_value == value


def test_a_sweep_is_a_loop_over_analyze():
    grid = dict(mach=[0.6, 0.95, 1.1, 1.3, 1.9], sweep=[45.0, 60.0, 70.0], cg=[0.2, 0.3],
                mu1=[50.0, 400.0], i_b=[0.08, 0.1])
    s = ds.sweep(BASE, **grid)
    assert s.shape == (5, 3, 2, 2, 2) and len(s["mach"]) == 120
    i = 0
    for mach in grid["mach"]:
        for sweep in grid["sweep"]:
            for cg in grid["cg"]:
                for mu1 in grid["mu1"]:
                    for i_b in grid["i_b"]:
                        cfg = {
                            "planform": {"sweep": sweep, "taper": 0.0, "root_chord": 10.0},
                            "flight": {"mach": mach, "cg": cg, "mu1": mu1, "i_b": i_b,
                                       "cl_m2": 0.05},
                            "model": {"damping": "faired"},
                        }
                        assert (s["mach"][i], s["sweep_deg"][i], s["cg"][i], s["mu1"][i],
                                s["i_b"][i]) == (mach, sweep, cg, mu1, i_b)
                        try:
                            a = ds.analyze(cfg)
                        except ValueError as e:
                            assert s["error"][i] and s["error"][i] in str(e), (i, e)
                            assert s["verdict"][i] == "" and np.isnan(s["sp_re"][i])
                            i += 1
                            continue
                        assert s["error"][i] == ""
                        assert s["verdict"][i] == a.verdict and s["stable"][i] == a.stable
                        sp, ph = a.short_period, a.phugoid
                        if sp is None:  # split into two real roots
                            assert np.isnan(s["sp_re"][i]) and np.isnan(s["sp_cycles_to_half"][i])
                            i += 1
                            continue
                        assert s["sp_re"][i] == sp.re and s["sp_im"][i] == sp.im
                        assert same(s["sp_cycles_to_half"][i], sp.cycles_to_half)
                        assert same(s["sp_damping_ratio"][i], sp.damping_ratio)
                        assert same(s["sp_omega_bar"][i], sp.frequency_parameter)
                        if ph is not None:
                            assert (s["ph_re"][i], s["ph_im"][i]) == (ph.re, ph.im)
                        ds_ = a.criteria["damping_standard"]
                        assert s["m_thetadot"][i] == ds_["m_thetadot"]
                        assert same(s["delta_m_thetadot"][i], ds_["margin"])
                        i += 1
    assert i == 120


def test_axes_take_strings_numbers_and_arrays():
    a = ds.sweep(BASE, mach="0.5:1:0.25", mu1=np.array([50.0, 100.0]))
    b = ds.sweep(BASE, mach=[0.5, 0.75, 1.0], mu1=(50, 100))
    for k in a:
        np.testing.assert_array_equal(a[k], b[k])
    c = ds.sweep(BASE, mach=0.9)
    assert c.shape == (1, 1, 1, 1, 1) and c["mu1"][0] == 50.0


def test_damping_override_and_derivative_columns():
    s = ds.sweep(BASE, mach=[0.9, 1.5], damping="supersonic", derivatives=True)
    assert s["error"][0].startswith("damping theory: supersonic theory (36) needs M > 1")
    assert s["error"][1] == "" and s["verdict"][1] in ("meets", "fails", "divergent")
    a = ds.analyze(BASE, mach=1.5, damping="supersonic")
    for name in ds.Derivatives.NAMES:
        assert s[name][1] == getattr(a.derivatives, name)


def test_to_pandas():
    pd = pytest.importorskip("pandas")
    df = ds.sweep(BASE, mach="0.5:2:0.5", cg=[0.2, 0.25]).to_pandas()
    assert isinstance(df, pd.DataFrame) and df.shape[0] == 8
    assert list(df.columns[:5]) == ["mach", "sweep_deg", "cg", "mu1", "i_b"]
    assert df["verdict"].isin(["meets", "fails", "divergent", ""]).all()


def test_bad_axes_raise_input_errors():
    with pytest.raises(ds.InputError, match="mach: the Mach number must lie in"):
        ds.sweep(BASE, mach=[0.5, -1.0])
    with pytest.raises(ds.InputError, match="mu1: the step must be positive"):
        ds.sweep(BASE, mach=0.9, mu1="50:100:0")
    with pytest.raises(ds.InputError, match="sweep"):
        ds.sweep(BASE, mach=0.9, sweep=[95.0])
    with pytest.raises(ds.InputError, match="damping"):
        ds.sweep(BASE, mach=0.9, damping="nonesuch")
    with pytest.raises(ds.InputError, match="the axis has no values"):
        ds.sweep(BASE, mach=[])


def test_the_gil_is_released_during_a_sweep():
    """A Python thread counts while the sweep runs in the main thread: with
    the GIL held for the sweep's whole second it could not count at all."""
    counts = {"n": 0}
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counts["n"] += 1

    args = dict(mach="0.5:2:0.001", cg="0.2:0.3:0.01", mu1="50:450:50")  # 1501·11·9 points
    t0 = time.perf_counter()
    ds.sweep(BASE, **args)
    alone = time.perf_counter() - t0
    thread = threading.Thread(target=count)
    thread.start()
    time.sleep(0.05)
    before = counts["n"]
    t0 = time.perf_counter()
    ds.sweep(BASE, **args)
    during = time.perf_counter() - t0
    after = counts["n"]
    stop.set()
    thread.join()
    progress = after - before
    # the thread ran for most of the sweep: at least 1000 iterations per
    # 10 ms of the sweep (a pure-Python loop makes ~10⁶–10⁷ a second)
    assert during > 0.05, f"the sweep took {during:.3f} s: too short to tell"
    assert progress > 1000 * during / 0.01, (progress, during, alone)
