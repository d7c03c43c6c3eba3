#!/usr/bin/env python3
"""Fixtures for the state-space export, from python-control (an independent
implementation: LAPACK's eigenvalues and eigenvectors through numpy, and
python-control's own damp()).

For each case below the script runs the program with `--state-space`, runs
the python-control script it wrote (OUT.py) as it is, and records what
python-control and numpy make of that system: damp()'s natural frequencies,
damping ratios and poles, and numpy's eigenvectors of A scaled so that
theta = 1. `delta-stability/tests/it/engineering.rs` compares the program's own
damp table and mode shapes (its quartic's roots, its cofactor eigenvectors)
with these. CI does not run this script; run it after a change to the
export, with a venv holding python-control:

    python3 -m venv /work/venv-engineering
    /work/venv-engineering/bin/pip install control numpy scipy
    cargo build -p delta-stability
    /work/venv-engineering/bin/python scripts/state_space_fixtures.py
"""

import json
import pathlib
import runpy
import subprocess
import sys
import tempfile

import control as ct
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parent.parent
BIN = ROOT / "target" / "debug" / "delta-stability"
OUT = ROOT / "delta-stability" / "tests" / "data" / "state_space"

CASES = [
    ("boeing-747-american", ["quartic", "examples/boeing-747-american.toml"]),
    ("tailless-delta-60-dimensional", ["quartic", "examples/tailless-delta-60-dimensional.toml"]),
    ("tailless-delta-45-tau", ["quartic", "examples/tailless-delta-45.toml"]),
    ("delta-60-physical", ["analyze", "examples/delta-60-physical.toml"]),
]


def shapes(a):
    """numpy's eigenvectors of A, theta = 1, for the roots with im >= 0."""
    w, v = np.linalg.eig(a)
    out = []
    for k in np.argsort(-np.abs(w)):
        if w[k].imag < 0:
            continue
        vec = v[:, k] / v[3, k]
        out.append({
            "re": float(w[k].real),
            "im": float(w[k].imag),
            "magnitude": [float(abs(z)) for z in vec],
            "phase_deg": [float(np.degrees(np.angle(z))) for z in vec],
        })
    return out


def fixture(name, args):
    with tempfile.TemporaryDirectory() as tmp:
        out = pathlib.Path(tmp) / f"{name}.json"
        subprocess.run([str(BIN), *args, "--state-space", str(out)], cwd=ROOT, check=True,
                       stdout=subprocess.DEVNULL)
        exported = json.loads(out.read_text())
        # the script exactly as written, as a user would run it
        ns = runpy.run_path(str(out.with_suffix(".py")), run_name="fixture")
    sys_ = ns["sys"]
    wn, zeta, poles = ct.damp(sys_, doprint=False)
    order = np.argsort(-np.abs(poles))
    return {
        "generated_by": "scripts/state_space_fixtures.py",
        "python_control": ct.__version__,
        "numpy": np.__version__,
        "command": ["delta-stability", *args, "--state-space", "OUT.json"],
        "time_unit": exported["time_unit"],
        "A": np.asarray(sys_.A).tolist(),
        "B": np.asarray(sys_.B).tolist(),
        "damp": [
            {"re": float(poles[k].real), "im": float(poles[k].imag),
             "natural_frequency": float(wn[k]), "damping_ratio": float(zeta[k])}
            for k in order
        ],
        "mode_shapes": shapes(np.asarray(sys_.A)),
    }


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    for name, args in CASES:
        path = OUT / f"{name}.json"
        path.write_text(json.dumps(fixture(name, args), indent=1) + "\n")
        print(f"wrote {path.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
