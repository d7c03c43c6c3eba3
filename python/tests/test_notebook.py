"""The example notebook (python/examples/note-study.ipynb) runs from top to
bottom: it recomputes the note's Fig 33 and checks it against the report's
docs/figures/fig33.csv, so it cannot rot. Needs nbclient, nbformat,
ipykernel and matplotlib (.ci/run installs them and sets
DELTA_STABILITY_REQUIRE_NOTEBOOK=1, so that there a missing one fails rather
than skips)."""

import os

import pytest

from conftest import ROOT


def _need(module):
    if os.environ.get("DELTA_STABILITY_REQUIRE_NOTEBOOK") == "1":
        return __import__(module)
    return pytest.importorskip(module)


def test_the_note_study_notebook_executes():
    nbformat = _need("nbformat")
    nbclient = _need("nbclient")
    _need("matplotlib")
    _need("ipykernel")
    os.environ.setdefault("MPLBACKEND", "Agg")
    path = ROOT / "python" / "examples" / "note-study.ipynb"
    nb = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(
        nb, timeout=600, kernel_name="python3",
        resources={"metadata": {"path": str(path.parent)}},
    )
    client.execute()
    text = "".join(
        o.get("text", "") for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
    )
    assert "Fig 33 agrees with the report's CSV at 119 Mach numbers on 4 curves" in text
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
              if o.output_type == "error"]
    assert not errors, errors
