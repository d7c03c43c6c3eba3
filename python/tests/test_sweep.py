"""sweep against a Python loop over analyze (the same design points one by
one through the per-point route), and the GIL released while it runs."""

import itertools
import threading

import numpy as np
import pytest

import delta_stability as ds

BASE = "examples/delta-60.toml"
PHYSICAL = "examples/delta-60-physical.toml"
#: The sweep's short-period roots against analyze's where the point iterates
#: its frequency parameter: the sweep interpolates in the wing's table of
#: solved frequencies (the near-sonic lattice's, and the Mach box's in Mach
#: number too: within 2.5e-3 of C_Lα), analyze solves at every iterate
#: (measured: 1.2e-3 in m_θ̇ at M = 0.95).
INTERPOLATED = 3e-3


def same(column_value, value, scale=0.0):
    """A column's value is the attribute's (NaN where it is None): exactly,
    or within `scale` when one is given."""
    if value is None:
        return bool(np.isnan(column_value))
    if scale == 0.0:
        return column_value == value
    return abs(column_value - value) <= scale


def assert_point(s, i, a, what):
    """Point i of the sweep s is the analysis a: exactly, or within
    INTERPOLATED (of each root's modulus, of m_θ̇) where a iterated its
    frequency parameter (the sweep interpolating in the lattice's frequency
    table, analyze solving at each iterate)."""
    assert s["error"][i] == "", (what, s["error"][i])
    assert s["verdict"][i] == a.verdict and s["stable"][i] == a.stable, what
    f = a.damping["frequency"]
    rel = INTERPOLATED if f is not None and f["iterations"] > 0 else 0.0
    sp, ph = a.short_period, a.phugoid
    if sp is None:  # split into two real roots
        assert np.isnan(s["sp_re"][i]) and np.isnan(s["sp_cycles_to_half"][i]), what
    else:
        lam = rel * abs(sp.root)
        assert same(s["sp_re"][i], sp.re, lam) and same(s["sp_im"][i], sp.im, lam), what
        cycles = (sp.cycles_to_half or 0.0) * lam / abs(sp.re)
        assert same(s["sp_cycles_to_half"][i], sp.cycles_to_half, 2 * cycles), what
        assert same(s["sp_damping_ratio"][i], sp.damping_ratio, 2 * rel), what
        assert same(s["sp_omega_bar"][i], sp.frequency_parameter,
                    lam / s["mu1"][i]), what
    if ph is not None:
        lam = 10 * rel * abs(ph.root)
        assert same(s["ph_re"][i], ph.re, lam) and same(s["ph_im"][i], ph.im, lam), what
    d = a.criteria["damping_standard"]
    # on the scale of the lift slope where m_θ̇ is small (the tables' error
    # is stated on C_Lα's scale: a heavy wing's small ω̄ near M = 1)
    m = rel * max(abs(d["m_thetadot"]), 1.0)
    assert same(s["m_thetadot"][i], d["m_thetadot"], m), what
    assert same(s["delta_m_thetadot"][i], d["margin"], m), what
    return rel


def loop(s, grid, config, **options):
    """Each point of the grid through analyze, against the sweep's columns;
    how many were compared exactly and how many within INTERPOLATED."""
    names = ["mach", "sweep", "cg", "mu1", "i_b"]
    counts = {"exact": 0, "interpolated": 0, "error": 0}
    points = list(itertools.product(*(grid[k] for k in names)))
    assert len(points) == len(s["mach"])
    for i, (mach, sweep, cg, mu1, i_b) in enumerate(points):
        assert (s["mach"][i], s["sweep_deg"][i], s["cg"][i], s["mu1"][i],
                s["i_b"][i]) == (mach, sweep, cg, mu1, i_b)
        try:
            a = ds.analyze(config(sweep, mach, cg, mu1, i_b), **options)
        except ValueError as e:
            assert s["error"][i] and s["error"][i] in str(e), (i, e)
            assert s["verdict"][i] == "" and np.isnan(s["sp_re"][i])
            counts["error"] += 1
            continue
        rel = assert_point(s, i, a, (i, mach, sweep, cg, mu1, i_b))
        counts["interpolated" if rel else "exact"] += 1
    return counts


def report_wing(sweep, mach, cg, mu1, i_b, damping="faired"):
    return {
        "planform": {"sweep": sweep, "taper": 0.0, "root_chord": 10.0},
        "flight": {"mach": mach, "cg": cg, "mu1": mu1, "i_b": i_b, "cl_m2": 0.05},
        "model": {"damping": damping},
    }


@pytest.mark.parametrize("damping", [None, "faired-slender"])
def test_a_sweep_is_a_loop_over_analyze(damping):
    """The default model (faired) and the quasi-steady faired-slender, at
    subsonic, transonic and supersonic points."""
    # (analyze solves each point's lifting surface at its own frequency:
    # three Mach numbers, two sweeps, the extremes of μ₁, which moves the
    # frequency most; every axis's whole grid is the library's
    # stability-core/tests/it/sweep.rs)
    grid = dict(mach=[0.6, 0.95, 1.3], sweep=[45.0, 70.0], cg=[0.3],
                mu1=[50.0, 400.0], i_b=[0.08])
    # (the k-method: the interpolated tables' accuracy is stated for its
    # roots; stability-core's tests/it/p_method.rs holds the p-method's
    # interpolated roots to the direct ones within 0.01 cycles)
    s = ds.sweep(BASE, damping=damping, frequency_method="k", **grid)
    assert s.shape == (3, 2, 1, 2, 1) and len(s["mach"]) == 12
    c = loop(s, grid, report_wing, damping=damping, frequency_method="k")
    assert c["exact"] + c["interpolated"] + c["error"] == 12, c
    assert c["error"] <= 2, c
    if damping == "faired-slender":
        assert c["interpolated"] == 0, c


def test_lattice_options_are_analyze_s():
    """aero= and omega_bar=: the lattice's lift slope and aerodynamic centre
    and its damping at a fixed ω̄ (a direct solve per planform and Mach
    number, exactly analyze's); and the iterated lifting-surface-frequency,
    whose sweep interpolates its frequency table."""
    grid = dict(mach=[0.5, 0.8], sweep=[45.0, 60.0], cg=[0.25], mu1=[50.0, 200.0], i_b=[0.08])
    kw = dict(damping="lifting-surface", aero="lifting-surface", omega_bar=0.2)
    s = ds.sweep(BASE, **kw, **grid)
    assert loop(s, grid, report_wing, **kw) == {"exact": 8, "interpolated": 0, "error": 0}
    kw = dict(damping="lifting-surface-frequency", aero="lifting-surface", frequency_method="k")
    s = ds.sweep(BASE, **kw, **grid)
    assert loop(s, grid, report_wing, **kw) == {"exact": 0, "interpolated": 8, "error": 0}


def physical_wing(sweep, mach, cg):
    """examples/delta-60-physical.toml with another sweep, as a dict: its
    root chord and physical flight condition kept."""
    return {
        "planform": {"sweep": sweep, "taper": 0.0, "root_chord": 12.0},
        "flight": {"mach": mach, "cg": cg, "units": "si", "altitude": 11000.0,
                   "mass": 12000.0, "I_y": 70000.0},
    }


def test_a_physical_flight_condition_is_analyze_s():
    """examples/delta-60-physical.toml (12 000 kg at 11 000 m): each
    planform's μ₁ and i_B follow from its area and M.A.C. at the fixed root
    chord, and the columns in seconds are analyze's flight condition and
    modes in seconds."""
    grid = dict(mach=[0.7, 1.3, 1.8], sweep=[50.0, 60.0], cg=[0.25])
    s = ds.sweep(PHYSICAL, damping="faired-slender", **grid)
    assert s.shape == (3, 2, 1, 1, 1) and len(set(s["mu1"])) == 2
    for i, (mach, sweep) in enumerate(itertools.product(grid["mach"], grid["sweep"])):
        a = ds.analyze(physical_wing(sweep, mach, 0.25), damping="faired-slender")
        if sweep == 60.0:
            assert ds.analyze(PHYSICAL, mach=mach, damping="faired-slender").roots.tolist() \
                == a.roots.tolist()
        f, sp = a.flight, a.short_period
        assert (s["mu1"][i], s["i_b"][i]) == (f["mu1"], f["i_b"]) == (a.case["mu1"],
                                                                       a.case["i_b"])
        assert_point(s, i, a, (mach, sweep))
        assert s["tau_s"][i] == a.tau_s == f["tau_s"]
        assert s["v_m_s"][i] == f["speed_m_s"] and s["c_l"][i] == f["c_l"]
        assert s["sp_re_s"][i] == sp.re / a.tau_s and s["sp_im_s"][i] == sp.im / a.tau_s
        assert s["sp_period_s"][i] == pytest.approx(sp.period_s, rel=1e-14)
        assert s["sp_natural_frequency_rad_s"][i] == pytest.approx(
            sp.natural_frequency / a.tau_s, rel=1e-14)
        ph = a.phugoid
        if ph is not None:
            assert (s["ph_re_s"][i], s["ph_im_s"][i]) == (ph.re / a.tau_s, ph.im / a.tau_s)


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
    """The main thread runs Python while a sweep runs in another thread.
    With the GIL held for the whole sweep it could not run between the
    thread's entering the sweep and its return; so the loop turns it sees
    while the thread says it is inside are counted (no clock: on a loaded
    machine the sweep only lasts longer)."""
    state = {"inside": False, "seen": 0, "error": None}
    # 1501·11·9 points; the quasi-steady fairing, whose cost does not
    # depend on how many lattice solves the default model needs
    args = dict(mach="0.5:2:0.001", cg="0.2:0.3:0.01", mu1="50:450:50",
                damping="faired-slender")

    def run():
        state["inside"] = True
        try:
            ds.sweep(BASE, **args)
        except Exception as e:  # reported by the main thread
            state["error"] = e
        state["inside"] = False

    thread = threading.Thread(target=run)
    thread.start()
    while thread.is_alive():
        if state["inside"]:
            state["seen"] += 1
    thread.join()
    assert state["error"] is None, state["error"]
    assert state["seen"] > 0, "the main thread never ran while the sweep did"


def test_a_physical_flight_condition_s_own_axes_shape_the_grid():
    """altitude, mass and I_y (iy, the command line's --iy, is the same) as
    axes: three more dimensions of the grid, last; each point's condition
    is its altitude's, mass's and I_y's (the columns say so); a config
    without a physical flight condition refuses them, naming the axis."""
    path = "examples/delta-60-physical.toml"
    s = ds.sweep(path, mach=0.6, altitude=[0.0, 11000.0], mass=[10000.0, 14000.0])
    assert s.shape == (1, 1, 1, 1, 1, 2, 2, 1)
    assert list(s["altitude"]) == [0.0, 0.0, 11000.0, 11000.0]
    assert list(s["mass"]) == [10000.0, 14000.0, 10000.0, 14000.0]
    # a heavier aircraft at the same altitude: a larger μ₁
    assert s["mu1"][1] > s["mu1"][0] and s["mu1"][3] > s["mu1"][2]
    a = ds.sweep(path, mach=0.6, I_y=[60000.0, 80000.0])
    b = ds.sweep(path, mach=0.6, iy="60000:80000:20000")
    assert a.shape == b.shape == (1, 1, 1, 1, 1, 1, 1, 2)
    assert np.array_equal(a["sp_re"], b["sp_re"]) and a["i_b"][1] > a["i_b"][0]
    with pytest.raises(TypeError):
        ds.sweep(path, mach=0.6, I_y=1.0, iy=1.0)
    with pytest.raises(ds.InputError) as e:
        ds.sweep("examples/delta-60.toml", mach=0.6, altitude=[0.0, 1000.0])
    assert "altitude" in str(e.value)
