"""Longitudinal (pitch-plane) dynamic stability of aircraft after W.B. McCarter,
*Note on the longitudinal stability characteristics and damping in pitch of
delta wings at subsonic, transonic and supersonic speeds* (College of
Aeronautics, Cranfield, 1953): the Rust library ``stability-core`` with numpy
arrays in and out. Equation numbers are the note's.

- :func:`quartic` — a derivative set (any notation) → the stability quartic
  (eqs 4–6), its roots and modes (eqs 7–8), Routh's test (§4), the §8
  criteria;
- :func:`analyze` — a planform at a flight condition (non-dimensional, or
  physical: altitude, mass, I_y, eq 24) → coefficients (§6), derivatives
  (§5–7), and the same, with the engineer's outputs (mode shapes, ``damp``,
  the short-period frequency requirement); ``mach``, ``cg``, ``damping``,
  ``aero`` and ``omega_bar`` are the command line's overrides;
- :func:`sweep` — a Cartesian grid of design points, in parallel, as columns
  (the library's sweep, as ``delta-stability sweep`` evaluates it);
- :func:`batch_roots` — the quartic solver on an (N, 5) array;
- :func:`response` (§11), :func:`convert` (the appendix's notations),
  :func:`sensitivity` (§10), :func:`damping_derivatives` (§7's theories),
  :func:`lifting_surface` (the doublet-lattice method);
- :func:`uncertainty` — the probability of meeting the §8 standard, of each
  MIL-F-8785C level and of a divergence when the inputs are uncertain, with
  Sobol indices (``delta-stability uncertainty``), as a pandas DataFrame;
- :func:`report` — the note's whole study (``delta-stability report``): its
  ``summary.json`` and figures written into a folder, the summary returned.

Inputs are read by the command line's own readers: a path to a TOML file or
a dict of the same shape, and errors are :class:`InputError` (a
``ValueError``) with the command line's message: file, line and field.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Optional

import numpy as _np

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

    from ._native import Axis, ConfigSource, PathLike

from . import _native
from ._native import (
    Analysis,
    Derivatives,
    InputError,
    Mode,
    Quartic,
    __version__,
    aero_models,
    analyze,
    convert,
    damping_derivatives,
    damping_models,
    lifting_surface,
    notations,
    quartic,
    response,
    sensitivity,
    size_tail,
    theories,
)

__all__ = [
    "Analysis",
    "Derivatives",
    "InputError",
    "Mode",
    "Quartic",
    "SweepResult",
    "aero_models",
    "analyze",
    "batch_roots",
    "convert",
    "damping_derivatives",
    "damping_models",
    "lifting_surface",
    "notations",
    "quartic",
    "report",
    "response",
    "sensitivity",
    "size_tail",
    "sweep",
    "theories",
    "uncertainty",
]

class SweepResult(dict):
    """The columns of a sweep, one numpy array each (a ``dict``), named,
    ordered and computed as ``delta-stability sweep``'s CSV (one table of
    columns, listed below): the grid values, then each point's results —
    Routh's test, the overall verdict (``meets``, ``fails``, ``divergent``,
    or ``""`` where the point has no result), the modes, m_θ̇ and its margin
    (eq 41), the MIL-F-8785C levels, the roots, K_n (eq 42), the neutral
    point and the static margin — at a physical flight condition the
    point's altitude, mass and I_y and the modes in seconds, with
    ``derivatives=True`` the quartic's inputs, and last ``error`` (``""``
    or why the point has no result, e.g. outside a theory's validity).
    Numbers that are undefined (a short period that does not oscillate)
    are NaN. Roots are in 1/τ, τ = m/(½ρSV).

    ``shape`` is the grid's shape (mach, sweep, cg, mu1, i_b):
    ``r["sp_cycles_to_half"].reshape(r.shape)`` indexes by axis.

    Columns (name [unit]: meaning), in order:

"""

    shape: "tuple[int, ...]"

    def to_pandas(self):  # -> pandas.DataFrame
        """The columns as a ``pandas.DataFrame`` (needs pandas)."""
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("SweepResult.to_pandas needs pandas: pip install pandas") from e
        return pd.DataFrame({k: v for k, v in self.items()})

    def __repr__(self):
        n = len(self["mach"]) if "mach" in self else 0
        return f"SweepResult({n} points, grid {self.shape}, columns {list(self)})"


# the column list, from the table the command line's columns come from
SweepResult.__doc__ += "".join("    " + line for line in _native.sweep_columns_doc().splitlines(True))


def sweep(
    config: ConfigSource,
    *,
    mach: Axis = None,
    sweep: Axis = None,
    cg: Axis = None,
    mu1: Axis = None,
    i_b: Axis = None,
    altitude: Axis = None,
    mass: Axis = None,
    I_y: Axis = None,
    damping: Optional[str] = None,
    aero: Optional[str] = None,
    omega_bar: Optional[float] = None,
    derivatives: bool = False,
    datcom: Optional[str] = None,
    iy: Axis = None,
    frequency_method: Optional[str] = None,
) -> SweepResult:
    """Design points over a Cartesian grid of Mach number, leading-edge sweep
    (degrees), c.g. position h, relative density μ₁ and pitching inertia i_B:
    what ``delta-stability sweep`` computes — the same library grid
    (``stability_core::design::sweep``), evaluated in Rust in parallel with the GIL
    released — returned as columns of numpy arrays (:class:`SweepResult`,
    with ``to_pandas()``), no CSV in between.

    ``config`` is a path to a TOML file or a dict of the same shape (see
    :func:`analyze`): the base design point. Each axis is None (the config's
    value), a number, a sequence or 1-D array, or the command line's
    ``"A:B:STEP"``. Each point goes planform → coefficients (§6) →
    derivatives (§5–7) → quartic (eqs 4–6) → roots → modes (eq 8) → Routh (§4)
    → the §8 standard and eq (41)'s margin. Points are in grid order, the last
    axis (i_B) varying fastest.

    ``damping``, ``aero``, ``omega_bar``, ``datcom`` and ``frequency_method``
    override the config's model as the command line's ``--damping``,
    ``--aero``, ``--omega-bar``, ``--datcom`` and ``--frequency-method`` do
    (see :func:`analyze`). The aerodynamics are shared by the
    points that differ only in μ₁ and i_B unless the damping theory iterates
    ω̄ (eqs 39–40, the lattice's), the doublet lattice is solved once per
    planform and Mach number, and a point's frequency iteration interpolates in that wing's
    table of solved frequencies (stability-core's tests hold the short
    period's roots within 2·10⁻⁴ of ``analyze``'s, which solves the lattice at
    every iterate). With a physical flight condition in the config (``[flight]
    altitude``, ``mass``, ``I_y``) each planform's μ₁, i_B and C_L·M² (eq 24)
    follow from it — the ``mu1`` and ``i_b`` axes may then not be given — and
    the columns carry the modes in seconds. Its own quantities are axes too,
    as the command line's ``--altitude``, ``--mass`` and ``--iy``:
    ``altitude`` (pressure altitudes), ``mass`` and ``I_y`` (``iy`` is the
    same), in the config's units; given any of them, the grid's shape has
    eight dimensions (those three last, each one value where not given).

    Raises :class:`InputError` for a bad config, option or axis value; a point
    outside a theory's validity is not an error but has its ``error`` column
    set.
    """
    raw = _native.sweep_columns(
        config,
        mach=mach,
        sweep=sweep,
        cg=cg,
        mu1=mu1,
        i_b=i_b,
        altitude=altitude,
        mass=mass,
        i_y=_one_of("I_y", I_y, "iy", iy),
        damping=damping,
        aero=aero,
        omega_bar=omega_bar,
        derivatives=derivatives,
        datcom=datcom,
        frequency_method=frequency_method,
    )
    decode = {k: _np.array(list(v)) for k, v in raw["words"].items()}
    decode["error"] = _np.array(list(raw["messages"]) + [""], dtype=object)
    out = SweepResult()
    for k in raw["columns"]:
        out[k] = decode[k][raw[k]] if k in decode else raw[k]
    out.shape = tuple(raw["shape"])
    return out


def uncertainty(
    config: ConfigSource,
    *,
    mach: Axis,
    samples: int = 10_000,
    seed: int = 1,
    sobol: bool = False,
    damping: Optional[str] = None,
    aero: Optional[str] = None,
    omega_bar: Optional[float] = None,
    sampling: Optional[str] = None,
    datcom: Optional[str] = None,
    frequency_method: Optional[str] = None,
):  # -> pandas.DataFrame
    """The config's ``[uncertainty]`` study at each Mach number: what
    ``delta-stability uncertainty`` computes (docs/uncertainty.md), by the
    same library (``stability_core::uncertainty``) with the GIL released.

    ``config`` is a path or a dict with an ``uncertainty`` table, e.g.
    ``{"uncertainty": {"i_b": {"dist": "normal", "relative_sd": 0.1},
    "m_q": {"error": "multiplicative", "dist": "uniform", "low": 0.8,
    "high": 1.2}, "model": {"damping": ["faired", "faired-slender"],
    "weights": [3, 1]}}}`` beside ``planform`` and ``flight``. ``mach`` is a
    number, a list or ``"A:B:STEP"``; ``samples`` Monte Carlo samples a Mach
    number; the same ``seed`` gives the same numbers on any thread count;
    ``sobol=True`` adds the first-order and total Sobol indices (Saltelli et
    al. 2010; Jansen 1999) for the margin Δm_θ̇ (eq 41) and for ζ;
    ``sampling="sobol"`` draws Owen-scrambled Sobol′ points (Burley 2020)
    instead of random ones (default: the config's ``sampling``, else
    ``"random"``), an error nearer 1/N than 1/√N. ``damping``, ``aero``,
    ``omega_bar``, ``datcom`` and ``frequency_method`` override the config's
    model as for :func:`analyze`.

    Returns a ``pandas.DataFrame`` in long form, one row per Mach number and
    quantity: columns ``mach``, ``quantity`` (``p_standard_met``,
    ``p_meets``, ``p_fails``, ``p_divergent``, ``p_sp_level_a_1`` …,
    ``cycles_to_half_q50`` …, ``sobol_first_margin_i_b`` …), ``value``,
    ``low``, ``high`` (95 % intervals; NaN where none). The whole result as
    ``delta-stability uncertainty --json`` gives it is in
    ``df.attrs["results"]``. Raises :class:`InputError` for a bad table.
    """
    import io
    import json

    try:
        import pandas as pd
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError("uncertainty() needs pandas: pip install pandas") from e
    text, csv = _native.uncertainty_run(
        config,
        mach=mach,
        samples=samples,
        seed=seed,
        sobol=sobol,
        damping=damping,
        aero=aero,
        omega_bar=omega_bar,
        sampling=sampling,
        datcom=datcom,
        frequency_method=frequency_method,
    )
    df = pd.read_csv(io.StringIO(csv))
    df.attrs["results"] = json.loads(text)
    return df


def report(out: Optional[PathLike] = "report", *, figures: bool = True) -> dict:
    """The note's whole study on its built-in cases: what ``delta-stability
    report`` computes (``stability-study``, the same library), with the GIL
    released — the 45° and 60° deltas across Mach number, the note's
    figures, the findings, the note's ten conclusions judged and swept over
    the unstated inputs, how sure the two headlines are, and the tail the
    45° delta needs; it takes as long as the command does.

    With ``out`` (a folder, made if missing) it writes ``summary.json`` —
    byte for byte the command line's — and, with ``figures``, each figure's
    ``figNN.svg`` and ``figNN.csv`` (``how-sure``, ``tail-needed``) as the
    command line draws them; files of those names are replaced, nothing else
    in the folder is touched. The page ``index.html`` and the replacement of
    the whole folder at once are the command line's. ``out=None`` writes
    nothing.

    Returns ``summary.json`` as a dict (its keys in the file's order):
    ``assumptions``, ``conclusions`` (each with ``claim``, ``section``,
    ``ours``, ``reproduced``, ``id`` …), ``delta_45`` and ``delta_60``
    (``unstable_mach``, ``fails_one_cycle_mach``, ``max_mu1_one_cycle`` …),
    ``how_sure`` and ``tail_needed``. Raises ``OSError`` naming the file
    that cannot be written.
    """
    import json

    return json.loads(_native.report_run(out, figures=figures))


def _one_of(name: str, value, alias: str, alias_value):
    """The value of an argument given by its name or its alias, not both."""
    if value is not None and alias_value is not None:
        raise TypeError(f"give {name} or {alias}, not both (the same axis)")
    return alias_value if value is None else value


def _argument_error(field: str, message: str) -> InputError:
    """An InputError about an argument, as the native functions raise them."""
    e = InputError(f"<arguments>: {field}: {message}")
    e.file, e.line, e.column, e.field, e.message = "<arguments>", 0, 0, field, message
    return e


def batch_roots(coefficients: npt.ArrayLike, *, errors: str = "raise") -> npt.NDArray[np.complex128]:
    """The four roots of each quartic Aλ⁴ + Bλ³ + Cλ² + Dλ + E (eq 5): for an
    array of shape (..., 5) of [A, B, C, D, E], a complex array of shape
    (..., 4), each row by descending modulus with a complex pair adjacent
    (positive imaginary part first). The solver of ``delta-stability quartic``
    (exact power-of-two scaling; Ferrari's resolvent cubic polished by Newton,
    or Aberth–Ehrlich where the coefficients span too many decades; every
    root's backward error checked), in parallel with the GIL released.

    ``errors="raise"``: :class:`InputError` naming the first row without roots
    (A = 0, a coefficient not finite, roots beyond float64's range);
    ``errors="nan"``: NaN in such rows.
    """
    if errors not in ("raise", "nan"):
        raise ValueError(f"errors must be 'raise' or 'nan', not {errors!r}")
    c = _np.asarray(coefficients, dtype=_np.float64)
    if c.ndim == 0 or c.shape[-1] != 5:
        raise _argument_error(
            "coefficients",
            f"expected an array of shape (..., 5) of [A, B, C, D, E], not {c.shape}",
        )
    lead = c.shape[:-1]
    roots = _native.batch_roots(_np.ascontiguousarray(c.reshape(-1, 5)), nan=(errors == "nan"))
    return roots.reshape(lead + (4,))
