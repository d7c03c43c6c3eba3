"""Shared by the tests: the repository's root, and the command-line program
(`delta-stability`, release build) whose output the package must reproduce.
The binary is found at $DELTA_STABILITY_BIN, else target/release/ (built
there by `cargo build --release -p delta-stability` when missing)."""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


def _binary():
    path = os.environ.get("DELTA_STABILITY_BIN")
    if path:
        return pathlib.Path(path)
    path = ROOT / "target" / "release" / "delta-stability"
    if not path.exists():
        subprocess.run(
            ["cargo", "build", "--release", "-q", "-p", "delta-stability"], cwd=ROOT, check=True
        )
    return path


class Cli:
    """Runs the command line in the repository's root."""

    def __init__(self, binary):
        self.binary = binary

    def run(self, *args, check=True):
        r = subprocess.run(
            [str(self.binary), *map(str, args)], cwd=ROOT, capture_output=True, text=True
        )
        if check and r.returncode != 0:
            raise AssertionError(f"delta-stability {' '.join(map(str, args))}: {r.stderr}")
        return r

    def json(self, *args):
        return json.loads(self.run(*args, "--json").stdout)

    def error(self, *args):
        """The message the command line prints after `error: ` (exit 2)."""
        r = self.run(*args, check=False)
        assert r.returncode == 2, (r.returncode, r.stderr)
        lines = [l for l in r.stderr.splitlines() if not l.startswith("warning: ")]
        text = "\n".join(lines)
        assert text.startswith("error: "), text
        return text[len("error: "):]


@pytest.fixture(scope="session")
def cli():
    return Cli(_binary())


@pytest.fixture(scope="session")
def cli_report(cli, tmp_path_factory):
    """The folder of `delta-stability report`: CI's run before the tests
    (target/ci-report, .ci/run) when it is there and newer than the binary,
    else one run of the binary, once for the session."""
    ci = ROOT / "target" / "ci-report"
    summary = ci / "summary.json"
    if (
        "DELTA_STABILITY_BIN" not in os.environ
        and summary.exists()
        and summary.stat().st_mtime >= cli.binary.stat().st_mtime
    ):
        return ci
    out = tmp_path_factory.mktemp("cli") / "report"
    cli.run("report", "--out", out)
    return out


@pytest.fixture(autouse=True)
def _in_root(monkeypatch):
    """Paths in the tests are relative to the repository's root, as in the
    command line's runs (its JSON names the file as given)."""
    monkeypatch.chdir(ROOT)
