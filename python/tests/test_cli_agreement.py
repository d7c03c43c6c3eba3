"""Each function against the command line's `--json` (or CSV) output on the
examples: the independent route is the program users run, through its own
parsing of its own output. Equality is exact: both serialize the library's
views, and the JSON's shortest round-trip numbers read back to the same
floats."""

import csv
import io
import json
import math

import numpy as np
import pytest

import delta_stability as ds
from conftest import EXAMPLES

DERIVATIVE_FILES = sorted(
    str(p.relative_to(EXAMPLES.parent))
    for p in [*EXAMPLES.glob("*.toml"), *EXAMPLES.glob("aircraft/*.toml")]
    if "notation" in p.read_text()
)
CONFIGS = ["examples/delta-45.toml", "examples/delta-60.toml"]


def test_the_examples_are_found():
    assert "examples/tailless-delta-45.toml" in DERIVATIVE_FILES
    assert "examples/boeing-747-american.toml" in DERIVATIVE_FILES
    assert len(DERIVATIVE_FILES) >= 8


def test_most_examples_are_read(cli):
    assert sum(_read_by_cli(cli, p) for p in DERIVATIVE_FILES) >= 4


def _read_by_cli(cli, path):
    return cli.run("quartic", path, "--json", check=False).returncode == 0


@pytest.mark.parametrize("path", DERIVATIVE_FILES)
def test_quartic_is_the_cli_json(cli, path):
    """The same JSON, or (for a file the command line refuses, such as one
    written for a reader still to come) the same error message."""
    if not _read_by_cli(cli, path):
        with pytest.raises(ds.InputError) as e:
            ds.quartic(path)
        assert str(e.value) == cli.error("quartic", path)
        return
    if _dimensional(path):
        return _dimensional_agrees(cli, path)
    q = ds.quartic(path)
    assert q.to_dict() == cli.json("quartic", path)


def _dimensional(path):
    return 'notation = "dimensional"' in (EXAMPLES.parent / path).read_text()


def _dimensional_agrees(cli, path):
    """notation = "dimensional": the command line analyses the general
    model (its own JSON); the package reads the set through the report's
    notation, which needs the [reference] quantities. Where they are given,
    its roots in 1/s are the command line's; where not, it says so."""
    j = cli.json("quartic", path)
    if j["report"] is None:
        with pytest.raises(ds.InputError) as e:
            ds.quartic(path)
        assert "[reference]" in e.value.message, e.value
        return
    q = ds.quartic(path)
    assert q.tau_s == pytest.approx(j["report"]["tau_s"], rel=1e-12)
    for name, value in j["report"]["derivatives"].items():
        assert getattr(q.derivatives, name) == pytest.approx(value, rel=1e-12, abs=1e-300), name
    if j["report"]["exact"]:
        ours = np.sort_complex(q.roots / q.tau_s)
        theirs = np.sort_complex([complex(r["re_s"], r["im_s"]) for r in j["roots"]])
        np.testing.assert_allclose(ours, theirs, rtol=1e-9)


@pytest.mark.parametrize("path", DERIVATIVE_FILES)
def test_quartic_attributes_are_the_json_values(cli, path):
    if not _read_by_cli(cli, path) or _dimensional(path):
        pytest.skip("refused by the command line, or its general (dimensional) model")
    q = ds.quartic(path)
    j = cli.json("quartic", path)
    assert list(q.coefficients) == [j["coefficients"][k] for k in "ABCDE"]
    assert list(q.roots) == [complex(r["re"], r["im"]) for r in j["roots"]]
    assert [m.to_dict() for m in q.modes] == j["modes"]
    assert q.criteria == j["criteria"]
    assert q.stable == j["stable"]
    assert q.warnings == j["warnings"]
    assert q.tau_s == j["tau_s"]
    assert q.routh["discriminant"] == j["routh_discriminant"]


def test_every_attribute_reads_a_key_the_json_has(cli):
    """The attributes read from the JSON (the package's table of names and
    key paths, _json_attributes) against the command line's --json: results
    that have every key (a physical flight condition: flight, damp, the
    short-period frequency requirement, the modes in seconds; a set with
    τ) have each attribute's key, and the attribute is its value there. A
    key renamed in the library without its attribute fails here; in use it
    is a RuntimeError, never a silent None. Where τ is unknown the keys in
    seconds are left out, and those attributes alone are None."""
    full = {
        "Analysis": [(ds.analyze("examples/delta-60-physical.toml"),
                      cli.json("analyze", "examples/delta-60-physical.toml"))],
        "Quartic": [(ds.quartic("examples/boeing-747-american.toml"),
                     cli.json("quartic", "examples/boeing-747-american.toml"))],
    }
    full["Mode"] = [(m, j) for o, d in full["Analysis"] + full["Quartic"]
                    for m, j in zip(o.modes, d["modes"])]
    bare = ds.quartic("examples/tailless-delta-45.toml")
    partial = {"Quartic": [bare], "Mode": bare.modes,
               "Analysis": [ds.analyze("examples/delta-45.toml")]}
    attributes = ds._native._json_attributes()
    assert {a[0] for a in attributes} == set(full)
    for cls, name, path, optional in attributes:
        for obj, j in full[cls]:
            for key in path:
                assert key in j, f"{cls}.{name}: the --json has no key {'.'.join(path)}"
                j = j[key]
            assert getattr(obj, name) == j, (cls, name)
        for obj in partial[cls]:
            # a key always there is read (else a RuntimeError), one that
            # needs τ or a physical condition is absent: None
            value = getattr(obj, name)
            assert optional is None or value is None, (cls, name, value)
    assert bare.tau_s is None and all(m.tau_s is None for m in bare.modes)
    m = full["Mode"][0][0]
    assert m.tau_s == full["Analysis"][0][0].tau_s > 0 and "tau_s" in dir(m)


def test_a_dict_and_keyword_arguments_read_as_the_file(cli):
    j = cli.json("quartic", "examples/boeing-747-american.toml")
    flat = {
        "C_xu": -0.1080, "C_xalpha": 0.2193, "C_xalphadot": 0.0, "C_xq": 0.0,
        "C_zu": -0.1060, "C_zalpha": -4.920, "C_zq": -5.921, "C_zalphadot": 5.896,
        "C_mu": 0.1043, "C_malpha": -1.023, "C_mq": -23.92, "C_malphadot": -6.314,
        "C_W0": 0.6540672, "mass": 288660.55, "I_y": 4.49e7, "rho": 0.3045, "V": 235.9,
        "S": 511.0, "chord": 8.324,
    }
    for q in [ds.quartic(flat, notation="american"), ds.quartic(notation="american", **flat)]:
        d = q.to_dict()
        assert d.pop("file") == "<dict>"
        j.pop("file", None)
        assert d == j
    nested = ds.quartic({
        "notation": "american",
        "derivatives": {k: v for k, v in flat.items() if k.startswith("C_") and k != "C_W0"},
        "flight": {"C_W0": 0.6540672},
        "dimensional": {k: flat[k] for k in ["mass", "I_y", "rho", "V", "S", "chord"]},
    })
    assert nested.to_dict()["coefficients"] == j["coefficients"]


def test_derivatives_round_trip(cli):
    q = ds.quartic("examples/tailless-delta-45.toml")
    d = q.derivatives
    assert ds.quartic(d).to_dict()["coefficients"] == q.to_dict()["coefficients"]
    assert list(d.quartic_coefficients()) == list(q.coefficients)
    assert ds.Derivatives(**d.to_dict()) == d
    assert ds.Derivatives.from_array(d.to_array()) == d
    assert d.replace(m_q=-1.0).m_q == -1.0 and d.m_q == -0.6
    assert ds.Derivatives.read("examples/tailless-delta-45.toml") == d


@pytest.mark.parametrize("path", CONFIGS)
@pytest.mark.parametrize(
    "overrides",
    [{}, {"mach": 1.2}, {"mach": 0.7, "cg": 0.3}, {"mach": 1.3, "damping": "supersonic"},
     {"mach": 1.0, "damping": "transonic-frequency"}, {"damping": "slender"}],
)
def test_analyze_is_the_cli_json(cli, path, overrides):
    flags = [x for k, v in overrides.items() for x in (f"--{k}", v)]
    j = cli.json("analyze", path, *flags)
    a = ds.analyze(path, **overrides)
    assert a.to_dict() == j
    assert a.criteria == j["criteria"]
    assert a.derivatives.to_dict() == j["derivatives"]
    assert list(a.coefficients) == [j["coefficients"][k] for k in "ABCDE"]
    assert [m.to_dict() for m in a.modes] == j["modes"]
    assert a.aerodynamics == j["aerodynamics"] and a.damping == j["damping"]
    assert a.case == j["case"]
    assert len(a.warnings) == len(j["warnings"])


OPTIONS = [
    ("examples/delta-45.toml", {"mach": 0.7, "aero": "lifting-surface"}),
    ("examples/delta-45.toml", {"mach": 0.5, "aero": "lifting-surface",
                                "damping": "lifting-surface", "omega_bar": 0.3}),
    ("examples/delta-60.toml", {"mach": 0.8, "damping": "lifting-surface-frequency"}),
    ("examples/delta-60.toml", {"mach": 1.0, "damping": "transonic-frequency",
                                "omega_bar": 0.1}),
    ("examples/delta-60.toml", {"aero": "default", "cg": 0.3}),
    ("examples/delta-60-physical.toml", {}),
    ("examples/delta-60-physical.toml", {"mach": 1.5, "damping": "faired-slender"}),
    ("examples/delta-60-physical.toml", {"mach": 0.6, "aero": "lifting-surface"}),
    ("examples/delta-45.toml", {"mach": 1.3, "frequency_method": "p-k"}),
]


@pytest.mark.parametrize("path,options", OPTIONS)
def test_analyze_options_are_the_cli_flags(cli, path, options):
    """aero= and omega_bar= as --aero and --omega-bar; a physical flight
    condition; and the engineer's outputs (damp, mode_shapes,
    short_period_frequency) as the JSON's."""
    flags = [x for k, v in options.items() for x in (f"--{k.replace('_', '-')}", v)]
    j = cli.json("analyze", path, *flags)
    a = ds.analyze(path, **options)
    assert a.to_dict() == j
    assert a.mode_shapes == j["mode_shapes"] and len(a.mode_shapes) >= 2
    assert a.damp == j.get("damp") and a.flight == j.get("flight")
    assert a.short_period_frequency == j.get("short_period_frequency")
    assert [m.to_dict() for m in a.modes] == j["modes"]
    assert a.damping == j["damping"] and a.aerodynamics == j["aerodynamics"]
    physical = "physical" in path
    assert (a.tau_s is not None) == physical == (a.damp is not None)
    if physical:
        assert a.tau_s == j["flight"]["tau_s"]
        assert a.short_period.period_s == pytest.approx(a.short_period.period * a.tau_s)
        assert a.short_period_frequency["natural_frequency_rad_s"] == pytest.approx(
            abs(a.short_period.root) / a.tau_s, rel=1e-12)
    if "omega_bar" in options:  # not iterated
        f = a.damping["frequency"]
        assert f is None or (f["iterations"] == 0 and f["converged"] == options["omega_bar"])
    if "aero" in options and options["aero"] != "default":
        default = ds.analyze(path, **{**options, "aero": "default"}).aerodynamics
        if options.get("damping", "faired") == "faired":
            # the faired model's own coefficients below M = 0.9 are the lattice's
            assert default["lift_slope"] == a.aerodynamics["lift_slope"]
        else:
            assert a.aerodynamics != default


def test_analyze_a_dict_as_the_file(cli):
    j = cli.json("analyze", "examples/delta-45.toml", "--mach", "1.2")
    cfg = {
        "planform": {"sweep": 45.0, "taper": 0.0, "root_chord": 10.0},
        "flight": {"mach": 1.2, "cg": 0.25, "mu1": 50.0, "i_b": 0.08, "cl_m2": 0.05},
        "model": {"damping": "faired"},
    }
    d = ds.analyze(cfg).to_dict()
    assert d.pop("file") == "<dict>"
    j.pop("file")
    assert d == j


@pytest.mark.parametrize("to", ["american", "garner", "ribner", "perkins", "report"])
@pytest.mark.parametrize(
    "path", ["examples/tailless-delta-45.toml", "examples/boeing-747-american.toml"]
)
def test_convert_is_the_cli_json(cli, path, to):
    notation = ds.quartic(path).notation
    j = cli.json("convert", "--from", notation, "--to", to, path)
    assert ds.convert(path, to=to) == j


def _csv_columns(text):
    rows = list(csv.DictReader(io.StringIO(text)))
    return {k: np.array([float(r[k]) if r[k] != "" else math.nan for r in rows]) for k in rows[0]}


@pytest.mark.parametrize(
    "path,flags,kwargs",
    [
        ("examples/tailless-delta-45.toml", ["--until", "20"], {"until": 20.0}),
        ("examples/tailless-delta-60-dimensional.toml", ["--until", "10", "--steps", "50",
         "--neglect-zq-zwdot"], {"until": 10.0, "steps": 50, "neglect_zq_zwdot": True}),
        ("examples/tailless-delta-45.toml", ["--until", "5", "--input", "initial", "--w0",
         "0.02", "--neglect-u"], {"until": 5.0, "input": "initial", "w0": 0.02,
                                  "neglect_u": True}),
    ],
)
def test_response_is_the_cli_csv(cli, path, flags, kwargs):
    theirs = _csv_columns(cli.run("response", path, *flags).stdout)
    ours = ds.response(path, **kwargs)
    for k, v in theirs.items():
        if np.all(np.isnan(v)):
            assert k not in ours or np.all(np.isnan(ours[k]))
            continue
        # the command line's CSV carries 12 significant digits (plot::num)
        np.testing.assert_allclose(ours[k], v, rtol=5e-12, atol=0, err_msg=k)


def test_response_in_seconds_and_degrees_is_the_cli_csv(cli, tmp_path):
    """until_s and elevator_deg (--until-s, --elevator-deg) on a set with τ
    and a [control] (the physical design point's derivative file): the
    command line's CSV; and where they cannot apply, the command line's
    reasons in Python's words."""
    f = tmp_path / "point.toml"
    ds.analyze("examples/delta-60-physical.toml").write_derivatives(f)
    flags = ["--until-s", "6", "--elevator-deg", "-1", "--steps", "60"]
    theirs = _csv_columns(cli.run("response", f, *flags).stdout)
    ours = ds.response(f, until_s=6.0, elevator_deg=-1.0, steps=60)
    assert ours["t_s"][-1] == pytest.approx(6.0, rel=1e-14)
    for k, v in theirs.items():
        if np.all(np.isnan(v)):  # eq (45) is the moment step's alone
            assert k not in ours
            continue
        np.testing.assert_allclose(ours[k], v, rtol=5e-12, atol=0, err_msg=k)
    no_tau = "examples/tailless-delta-45.toml"
    for path, cli_flags, kwargs, words in [
        (no_tau, ["--until-s", "5"], {"until_s": 5.0}, "until_s=5: times in seconds need τ"),
        (no_tau, ["--until", "5", "--elevator-deg", "1"], {"until": 5.0, "elevator_deg": 1.0},
         "elevator_deg=1: the file has no [control] table"),
        (f, ["--until", "5", "--input", "initial", "--m0", "1"],
         {"until": 5.0, "input": "initial", "m0": 1.0},
         "m0 is the moment step of input=step: it does nothing with input=initial"),
    ]:
        message = cli.error("response", path, *cli_flags)
        with pytest.raises(ds.InputError) as e:
            ds.response(path, **kwargs)
        assert words in str(e.value), str(e.value)
        # the same sentence, in the command line's words
        cli_words = (words.replace("until_s=", "--until-s ").replace("elevator_deg=", "--elevator-deg ")
                     .replace("m0 is", "--m0 is").replace("input=", "--input "))
        assert cli_words in message, message


@pytest.mark.parametrize("theory,mach", [("slender", 0.9), ("garrick", 0.5),
                                         ("supersonic", 1.3), ("transonic", 1.0)])
def test_damping_derivatives_are_analyze_s(cli, theory, mach):
    j = cli.json("analyze", "examples/delta-45.toml", "--mach", mach, "--damping", theory)
    d = ds.damping_derivatives(theory, sweep=45.0, mach=mach, cg=0.25)
    assert d["theory"] == j["damping"]["theory"] and d["equations"] == j["damping"]["equations"]
    assert d["z_thetadot"] == j["damping"]["z_thetadot"]
    assert d["m_thetadot"] == j["damping"]["m_thetadot"]
    assert d["z_wdot"] == j["derivatives"]["z_wdot"] and d["m_q"] == j["derivatives"]["m_q"]
    assert d["fig18"] == j["damping"]["fig18"]


SWEEPS = {
    "derivatives": ("examples/delta-60.toml",
                    dict(mach="0.5:2:0.25", cg="0.2:0.3:0.05", mu1="50:450:400",
                         sweep="45:75:15", derivatives=True)),
    "the config's sweep, faired-slender": ("examples/delta-45.toml",
                                           dict(mach="0.6:1.6:0.2", i_b="0.06:0.1:0.02",
                                                damping="faired-slender")),
    "the lattice at a fixed frequency": ("examples/delta-45.toml",
                                         dict(mach="0.4:0.8:0.2", mu1="50:450:400",
                                              damping="lifting-surface",
                                              aero="lifting-surface", omega_bar=0.25)),
    "the lattice's frequency iterated": ("examples/delta-60.toml",
                                         dict(mach="0.5:0.9:0.2", mu1="40:200:160",
                                              sweep="55:65:10",
                                              damping="lifting-surface-frequency")),
    "errors: supersonic theory below M = 1": ("examples/delta-60.toml",
                                              dict(mach="0.8:1.4:0.2", damping="supersonic")),
    "a DATCOM output": ("examples/delta-60.toml",
                        dict(mach="0.5:2:0.25", cg="0.1:0.3:0.1", derivatives=True,
                             datcom="stability-io/tests/fixtures/datcom/delta60_h0.0.out")),
    "a physical flight condition": ("examples/delta-60-physical.toml",
                                    dict(mach="0.6:1.5:0.9", sweep="70",
                                         cg="0.2:0.3:0.1", derivatives=True)),
    "a physical flight condition's own axes": ("examples/delta-60-physical.toml",
                                               dict(mach="0.6", altitude="0:11000:11000",
                                                    mass="10000:14000:4000", I_y="70000")),
}


def _flags(kwargs):
    """The command line's flags for sweep()'s keyword arguments."""
    names = {"i_b": "--ib", "omega_bar": "--omega-bar", "derivatives": "--derivatives",
             "I_y": "--iy"}
    out = []
    for k, v in kwargs.items():
        flag = names.get(k, f"--{k}")
        out += [flag] if v is True else [flag, v]
    return out


@pytest.mark.parametrize("case", sorted(SWEEPS))
def test_sweep_is_the_cli_csv(cli, tmp_path, case):
    """Column for column and value for value: the CSV's columns, in its
    order, and each cell (empty: NaN; a number: the same float)."""
    path, kwargs = SWEEPS[case]
    out = tmp_path / "sweep.csv"
    cli.run("sweep", path, *_flags(kwargs), "-o", out)
    with out.open(newline="") as f:
        header, *rows = list(csv.reader(f))
    ours = ds.sweep(path, **kwargs)
    # the CSV repeats mu1 and i_b among the quartic inputs, and with a
    # physical flight condition c_l (the flight point's C_L, eq 24, then the
    # quartic input, computed apart: equal to rounding): a dict holds each
    # name once, its first column, and every repetition must be that column
    assert list(ours) == list(dict.fromkeys(header)), (list(ours), header)
    # and the docs list them, from the same table
    assert all(f"\n      {k}" in ds.SweepResult.__doc__ for k in header)
    assert len(ours["mach"]) == len(rows) == int(np.prod(ours.shape)) > 1
    error = header.index("error")
    assert any(r[error] == "" for r in rows)
    assert any(r[error] != "" for r in rows) == case.startswith("errors")
    for j, k in enumerate(header):
        col = ours[k]
        for i, row in enumerate(rows):
            if k in ("verdict", "error"):
                assert col[i] == row[j], (k, i)
            elif k == "stable":
                assert (row[j] == "true") == bool(col[i]), (k, i)
            elif row[j] == "":
                assert math.isnan(col[i]), (k, i)
            elif header.index(k) < j:  # a repetition
                assert col[i] == pytest.approx(float(row[j]), rel=1e-15), (k, j, i)
            else:
                assert col[i] == float(row[j]), (k, j, i, col[i], row[j])


def test_report_writes_the_command_line_s_summary_and_figures(cli_report, tmp_path):
    """report(): summary.json byte for byte the command line's (the same
    library writes both), returned as the file's dict; each figure's SVG and
    CSV the command line's, and every figure the command line draws."""
    out = tmp_path / "report"
    summary = ds.report(out)
    ours = (out / "summary.json").read_bytes()
    assert ours == (cli_report / "summary.json").read_bytes()
    assert summary == json.loads(ours)
    assert list(summary) == list(json.loads(ours))
    figures = sorted(p.name for p in out.iterdir() if p.suffix in (".svg", ".csv"))
    theirs = sorted(p.name for p in cli_report.iterdir() if p.suffix in (".svg", ".csv"))
    assert figures == theirs and len(figures) >= 80
    for name in figures:
        assert (out / name).read_bytes() == (cli_report / name).read_bytes(), name
    assert sorted(p.name for p in out.iterdir()) == sorted(figures + ["summary.json"])


def test_roots_in_seconds_damp_and_mode_shapes_are_the_cli_s(cli):
    """Quartic.roots_s, damp and mode_shapes: the command line's re_s/im_s,
    damp table and mode shapes (Etkin's 747, τ known); where τ is not
    known, roots_s and damp are None."""
    path = "examples/boeing-747-american.toml"
    q, j = ds.quartic(path), cli.json("quartic", path)
    theirs = [complex(r["re_s"], r["im_s"]) for r in j["roots"]]
    np.testing.assert_allclose(q.roots_s, theirs, rtol=1e-15)
    np.testing.assert_allclose(q.roots_s * q.tau_s, q.roots, rtol=1e-15)
    assert q.damp == j["damp"] and q.mode_shapes == j["mode_shapes"]
    assert q.short_period_frequency == j.get("short_period_frequency")
    n = ds.quartic("examples/tailless-delta-45.toml")
    assert n.tau_s is None and n.roots_s is None and n.damp is None


def _exported(cli, tmp_path, *args):
    out = tmp_path / "ss.json"
    cli.run(*args, "--state-space", out)
    return json.loads(out.read_text())


def test_state_space_is_the_cli_export_and_its_eigenvalues_are_the_roots(cli, tmp_path):
    """state_space(): the matrices and names `--state-space` writes, as
    arrays; the eigenvalues of A (numpy's, an independent route from the
    quartic's roots) are the roots in the model's unit of time; with a
    [control] table B and D are there."""
    # the exported model is the derivatives' (constant): its eigenvalues are
    # the k-method's roots (by default analyze's are each at its own
    # complex frequency, the p-method)
    k = ["--frequency-method", "k"]
    for command, path, call, extra in [
        ("quartic", "examples/boeing-747-american.toml", ds.quartic, []),
        ("quartic", "examples/tailless-delta-45.toml", ds.quartic, []),
        ("analyze", "examples/delta-60-physical.toml",
         lambda p: ds.analyze(p, frequency_method="k"), k),
    ]:
        r = call(path)
        ours, theirs = r.state_space(), _exported(cli, tmp_path, command, path, *extra)
        assert set(ours) == set(theirs), path
        for k in ["A", "B", "C", "D"]:
            if theirs[k] is None:
                assert ours[k] is None, (path, k)
            else:
                assert ours[k].tolist() == theirs[k], (path, k)
        for k in ["states", "inputs", "outputs", "time_unit", "python_control", "matlab"]:
            assert ours[k] == theirs[k], (path, k)
        roots = r.roots if r.roots_s is None else r.roots_s
        assert ours["time_unit"] == ("tau" if r.roots_s is None else "s"), path
        eig = np.sort_complex(np.linalg.eigvals(ours["A"]))
        np.testing.assert_allclose(eig, np.sort_complex(roots), rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(np.sort_complex(ours["eigenvalues"]), np.sort_complex(roots),
                                   rtol=1e-15)
    # examples/delta-60-physical.toml has a [control]: the elevon's column
    assert ours["B"] is not None and ours["B"].shape == (4, 1)


def test_write_derivatives_is_the_cli_s_file_and_reads_back(cli, tmp_path):
    """Analysis.write_derivatives: the file `analyze --write-derivatives`
    writes (but the line naming what wrote it), whose quartic is the design
    point's; never over the config it came from."""
    config = "examples/delta-60-physical.toml"
    # the k-method: the file's constant derivatives give its roots
    a = ds.analyze(config, frequency_method="k")
    ours, theirs = tmp_path / "ours.toml", tmp_path / "theirs.toml"
    a.write_derivatives(ours)
    cli.run("analyze", config, "--frequency-method", "k", "--write-derivatives", theirs)

    def kept(p):
        return [l for l in p.read_text().splitlines() if not l.startswith("# Written by")]

    assert kept(ours) == kept(theirs)
    assert "delta_stability.analyze(" in ours.read_text()
    q = ds.quartic(ours)
    assert q.derivatives == a.derivatives
    np.testing.assert_allclose(q.roots, a.roots, rtol=1e-15)
    copy = tmp_path / "config.toml"
    copy.write_text((EXAMPLES / "delta-60-physical.toml").read_text())
    b = ds.analyze(str(copy))
    with pytest.raises(ds.InputError) as e:
        b.write_derivatives(copy)
    assert "config" in str(e.value)
    assert copy.read_text() == (EXAMPLES / "delta-60-physical.toml").read_text()
