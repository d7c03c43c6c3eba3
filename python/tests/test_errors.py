"""Bad input raises InputError (a ValueError) with the command line's own
message — the same text `delta-stability` prints after `error: ` — and no
input, however garbled, crashes the interpreter (a small fuzz)."""

import math
import os
import random

import numpy as np
import pytest

import delta_stability as ds
from conftest import ROOT


def _write(tmp_path, name, text):
    p = tmp_path / name
    p.write_text(text)
    return os.path.relpath(p)


BAD_DERIVATIVES = {
    "misspelt": 'notation = "report"\n[derivatives]\nx_u = -0.03\nm_qq = 1\n',
    "nan": open("examples/tailless-delta-45.toml").read().replace("m_q = -0.6", "m_q = nan"),
    "notation": 'notation = "amercan"\n',
    "negative mu1": open("examples/tailless-delta-45.toml").read().replace("mu1 = 50.0",
                                                                            "mu1 = -5.0"),
    "syntax": 'notation = "report"\n[derivatives\n',
}


@pytest.mark.parametrize("case", sorted(BAD_DERIVATIVES))
def test_a_bad_derivative_file_raises_the_cli_message(cli, tmp_path, case):
    path = _write(tmp_path, f"{case.replace(' ', '-')}.toml", BAD_DERIVATIVES[case])
    message = cli.error("quartic", path)
    with pytest.raises(ValueError) as e:
        ds.quartic(path)
    assert isinstance(e.value, ds.InputError)
    assert str(e.value) == message
    assert e.value.file == path and e.value.line >= 1 and e.value.field in message


def test_the_error_names_the_line_and_field(tmp_path):
    path = _write(tmp_path, "nan.toml", BAD_DERIVATIVES["nan"])
    with pytest.raises(ds.InputError) as e:
        ds.quartic(path)
    text = open(path).read().splitlines()
    assert text[e.value.line - 1].startswith("m_q = nan")
    assert e.value.field == "[derivatives] m_q"
    assert "is not a finite number" in e.value.message


BAD_CONFIGS = {
    "mach": open("examples/delta-45.toml").read().replace("mach = 0.9", "mach = -2"),
    "damping": open("examples/delta-45.toml").read().replace('"faired"', '"fared"'),
    "two sizes": open("examples/delta-45.toml").read().replace("root_chord = 10.0",
                                                                "root_chord = 10.0\nspan = 3"),
    "sweep": open("examples/delta-45.toml").read().replace("sweep = 45.0", "sweep = 90.0"),
}


@pytest.mark.parametrize("case", sorted(BAD_CONFIGS))
def test_a_bad_config_raises_the_cli_message(cli, tmp_path, case):
    path = _write(tmp_path, f"{case.replace(' ', '-')}.toml", BAD_CONFIGS[case])
    message = cli.error("analyze", path)
    with pytest.raises(ds.InputError) as e:
        ds.analyze(path)
    assert str(e.value) == message
    with pytest.raises(ds.InputError) as e:
        ds.sweep(path, mach=0.9)
    assert str(e.value) == message


def test_overrides_and_theory_domains_raise_as_the_cli(cli):
    for flags, kwargs in [(["--mach", "0.9", "--damping", "supersonic"],
                           {"mach": 0.9, "damping": "supersonic"}),
                          (["--mach", "1000"], {"mach": 1000.0})]:
        message = cli.error("analyze", "examples/delta-45.toml", *flags)
        with pytest.raises(ds.InputError) as e:
            ds.analyze("examples/delta-45.toml", **kwargs)
        assert str(e.value) == message


def test_the_new_options_raise_as_the_cli(cli):
    """--omega-bar with a model that takes no frequency, --aero
    lifting-surface at M = 1: the command line's message, file and all;
    for sweep() too (its axes are the command line's flags)."""
    for flags, kwargs in [(["--omega-bar", "0.3", "--damping", "faired-slender"],
                           {"omega_bar": 0.3, "damping": "faired-slender"}),
                          (["--omega-bar", "0.3", "--damping", "slender"],
                           {"omega_bar": 0.3, "damping": "slender"}),
                          (["--omega-bar", "1e9", "--damping", "lifting-surface"],
                           {"omega_bar": 1e9, "damping": "lifting-surface"})]:
        message = cli.error("analyze", "examples/delta-45.toml", *flags)
        with pytest.raises(ds.InputError) as e:
            ds.analyze("examples/delta-45.toml", **kwargs)
        assert str(e.value) == message and e.value.file == "examples/delta-45.toml"
        assert "omega-bar" in message
        with pytest.raises(ds.InputError) as e:
            ds.sweep("examples/delta-45.toml", mach=[0.5, 0.9], **kwargs)
        assert str(e.value) == message
    # the lifting surface's steady solve is refused beyond M = 3 (at M = 1
    # its lift slope and aerodynamic centre are the join through the sonic
    # point: no error)
    ds.analyze("examples/delta-45.toml", mach=1.0, aero="lifting-surface")
    message = cli.error("analyze", "examples/delta-45.toml", "--mach", "3.5", "--aero",
                        "lifting-surface")
    with pytest.raises(ds.InputError) as e:
        ds.analyze("examples/delta-45.toml", mach=3.5, aero="lifting-surface")
    assert str(e.value) == message
    s = ds.sweep("examples/delta-45.toml", mach=[0.9, 3.5], aero="lifting-surface")
    assert s["error"][0] == "" and s["error"][1] and s["error"][1] in message
    with pytest.raises(ds.InputError) as e:
        ds.analyze("examples/delta-45.toml", aero="lifting-surfaces")
    assert e.value.field == "aero" and "default, lifting-surface" in e.value.message


def test_every_named_option_suggests_the_nearest():
    with pytest.raises(ds.InputError, match="did you mean `phugoid`"):
        ds.sensitivity(ROOT / "examples/tailless-delta-45.toml", mode="phugiod")
    with pytest.raises(ds.InputError, match="did you mean `initial`"):
        ds.response(ROOT / "examples/tailless-delta-45.toml", until=1.0, input="inital")
    with pytest.raises(ds.InputError, match="did you mean `garner`"):
        ds.convert(ROOT / "examples/tailless-delta-45.toml", to="garnr")


def test_a_misspelt_model_name_suggests_the_nearest():
    with pytest.raises(ds.InputError, match="did you mean `lifting-surface`"):
        ds.analyze(ROOT / "examples/delta-45.toml", damping="liftingsurface")
    with pytest.raises(ds.InputError, match="did you mean `lifting-surface`"):
        ds.analyze(ROOT / "examples/delta-45.toml", aero="liftingsurface")
    with pytest.raises(ds.InputError, match="did you mean `slender`"):
        ds.damping_derivatives("slendr", sweep=45.0, mach=0.5)


def test_a_physical_config_s_errors(cli, tmp_path):
    """A physical flight condition fixes μ₁ and i_B (the sweep's mu1 and i_b
    axes are refused, as --mu1 and --ib are); a bad physical field names its
    line, as the command line does."""
    text = open("examples/delta-60-physical.toml").read()
    for name, flag in [("mu1", "--mu1"), ("i_b", "--ib")]:
        theirs = cli.error("sweep", "examples/delta-60-physical.toml", "--mach", "0.9", flag,
                           "50", "-o", tmp_path / "x.csv")
        with pytest.raises(ds.InputError) as e:
            ds.sweep("examples/delta-60-physical.toml", mach=0.9, **{name: 50.0})
        assert e.value.field == name and e.value.message in theirs
        assert "fixes μ₁ and i_B" in e.value.message
    both = _write(tmp_path, "both.toml", text.replace("mass = 12000.0", "mass = 12000.0\nmu1 = 50"))
    heavy = _write(tmp_path, "neg.toml", text.replace("mass = 12000.0", "mass = -12000.0"))
    for path in [both, heavy]:
        message = cli.error("analyze", path)
        with pytest.raises(ds.InputError) as e:
            ds.analyze(path)
        assert str(e.value) == message and e.value.line > 0
        with pytest.raises(ds.InputError) as e:
            ds.sweep(path, mach=[0.8, 0.9])
        assert str(e.value) == message


def test_a_dict_s_error_names_its_field():
    with pytest.raises(ds.InputError) as e:
        ds.quartic(x_u=-0.03, x_w=0.25, mu1=50.0)
    assert e.value.file == "<dict>" and "missing field" in e.value.message
    with pytest.raises(ds.InputError) as e:
        ds.analyze({"planform": {"sweep": 45, "root_chord": 1},
                    "flight": {"mach": 0.9, "cg": 0.25, "mu1": -1, "i_b": 0.08, "cl_m2": 0.05}})
    assert e.value.field == "[flight] mu1" and "positive" in e.value.message


def test_missing_files_and_wrong_types():
    with pytest.raises(FileNotFoundError, match="no-such.toml"):
        ds.quartic("no-such.toml")
    with pytest.raises(TypeError):
        ds.quartic(42)
    with pytest.raises(TypeError):
        ds.quartic()
    with pytest.raises(TypeError):
        ds.analyze({"planform": {"sweep": object()}})
    with pytest.raises(ds.InputError, match="unknown notation"):
        ds.convert("examples/tailless-delta-45.toml", to="klingon")
    with pytest.raises(ds.InputError, match="theory"):
        ds.damping_derivatives("nonesuch", sweep=45, mach=0.9)


def test_report_names_a_folder_it_cannot_make(tmp_path):
    """report() into a path through a file: an OSError naming the folder,
    raised before the study is computed."""
    plain = tmp_path / "plain"
    plain.write_text("mine")
    with pytest.raises(OSError) as e:
        ds.report(plain / "out")
    assert "plain/out" in str(e.value), e.value
    assert plain.read_text() == "mine"


def _garbage(rng):
    """A random value: numbers of every size and kind, strings, containers."""
    kind = rng.randrange(9)
    if kind == 0:
        return rng.choice([math.nan, math.inf, -math.inf, 0.0, -0.0, 1e308, -1e-308, 5e-324])
    if kind == 1:
        return rng.uniform(-1e6, 1e6) * 10.0 ** rng.randrange(-300, 300)
    if kind == 2:
        return rng.randrange(-10**30, 10**30)
    if kind == 3:
        return "".join(chr(rng.randrange(1, 0x2FFF)) for _ in range(rng.randrange(0, 40)))
    if kind == 4:
        return [rng.uniform(-5, 5) for _ in range(rng.randrange(0, 4))]
    if kind == 5:
        return {"x": rng.random()}
    if kind == 6:
        return rng.choice([True, False, None])
    if kind == 7:
        return rng.choice(["report", "american", "avl", "garner", "faired", "supersonic"])
    return rng.uniform(-2, 2)


NAMES = list(ds.Derivatives.NAMES) + ["notation", "C_xu", "C_W0", "mass", "rho", "V", "I_y",
                                      "st_file", "lt", "derivatives", "flight", "zz"]
CONFIG_KEYS = {"planform": ["sweep", "taper", "root_chord", "span", "area", "xx"],
               "flight": ["mach", "cg", "mu1", "i_b", "cl_m2"],
               "model": ["damping", "omega_bar", "iterate_frequency", "tables"]}


def test_garbage_never_crashes_the_interpreter():
    """Every call either returns or raises an ordinary exception (ValueError,
    TypeError, OSError): no RuntimeError (a caught Rust panic), no crash."""
    rng = random.Random(13)
    base = ds.Derivatives.read("examples/tailless-delta-45.toml").to_dict()
    outcomes = {"ok": 0, "error": 0}

    def attempt(f, *a, **k):
        try:
            f(*a, **k)
            outcomes["ok"] += 1
        except (ValueError, TypeError, OSError):
            outcomes["error"] += 1

    for _ in range(200):
        d = dict(base)
        for _ in range(rng.randrange(1, 4)):
            d[rng.choice(NAMES)] = _garbage(rng)
        attempt(ds.quartic, d)
        attempt(ds.sensitivity, d)
        attempt(ds.convert, d, to=rng.choice(["american", "garner", "report"]))
        attempt(ds.response, d, until=rng.choice([1.0, 1e9, 1e-9]), steps=rng.choice([1, 10]))
        cfg = {"planform": {"sweep": 45.0, "taper": 0.0, "root_chord": 10.0},
               "flight": {"mach": 0.9, "cg": 0.25, "mu1": 50.0, "i_b": 0.08, "cl_m2": 0.05}}
        for _ in range(rng.randrange(1, 3)):
            table = rng.choice(list(CONFIG_KEYS))
            cfg.setdefault(table, {})[rng.choice(CONFIG_KEYS[table])] = _garbage(rng)
        attempt(ds.analyze, cfg)
        attempt(ds.sweep, cfg, mach=[_garbage(rng), 0.9])
        attempt(ds.damping_derivatives, rng.choice(ds.theories()), sweep=_garbage(rng),
                mach=_garbage(rng), cg=_garbage(rng), omega_bar=rng.choice([None, 0.1, -1.0]))
    special = [math.nan, math.inf, -math.inf, 0.0, 1e308, -1e308, 5e-324, 1e-300]
    c = np.array([[rng.choice(special) if rng.random() < 0.2 else rng.uniform(-1, 1)
                   for _ in range(5)] for _ in range(500)])
    c[rng.randrange(500), 2] = 1e308
    attempt(ds.batch_roots, c)
    attempt(ds.batch_roots, c, errors="nan")
    assert outcomes["ok"] > 0 and outcomes["error"] > 0, outcomes


def test_a_rust_panic_is_a_runtime_error_not_a_crash():
    """The guard around every native function turns a panic (here a
    deliberate one, in a thread without the GIL) into RuntimeError, which
    `except Exception` catches (pyo3's PanicException would not be)."""
    with pytest.raises(RuntimeError, match="internal error in delta_stability"):
        ds._native._panic_for_tests()
    assert ds.quartic("examples/tailless-delta-45.toml").stable  # still alive
