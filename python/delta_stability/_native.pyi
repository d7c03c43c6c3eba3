"""Type stubs of the extension module ``delta_stability._native`` (Rust,
PyO3). The docstrings at run time are the Rust functions' own; these stubs
give the signatures and, briefly, what each returns. Equation numbers are
McCarter (1953)'s."""

from __future__ import annotations

import os
from typing import Any, ClassVar, Literal, Mapping, Optional, Sequence, Union, overload

import numpy as np
import numpy.typing as npt

PathLike = Union[str, os.PathLike]
#: A derivative set: a path to a TOML file, a dict of the same shape (or a
#: flat one, quantities by name beside ``notation``), or a Derivatives.
DerivativeSource = Union[PathLike, Mapping[str, Any], "Derivatives"]
#: A design-point config: a path to a TOML file, or a dict of the same shape.
ConfigSource = Union[PathLike, Mapping[str, Any]]
Axis = Union[None, float, Sequence[float], npt.ArrayLike, str]

__version__: str

class InputError(ValueError):
    """Bad input, with the command line's message (``file:line:column:
    field: message`` and the offending line)."""

    file: str
    line: int
    column: int
    field: str
    message: str

class Derivatives:
    """A derivative set in the report's notation (§3, eqs 2–4): x_u x_w
    x_wdot x_q z_u z_w z_wdot z_q m_u m_w m_wdot m_q (eqs 9–20), c_l
    (eq 24), mu1 = m/(½ρSc̄), i_b = B/(mc̄²). Frozen."""

    NAMES: ClassVar[list[str]]
    x_u: float
    x_w: float
    x_wdot: float
    x_q: float
    z_u: float
    z_w: float
    z_wdot: float
    z_q: float
    m_u: float
    m_w: float
    m_wdot: float
    m_q: float
    c_l: float
    mu1: float
    i_b: float
    def __init__(
        self,
        *,
        x_u: float,
        x_w: float,
        x_wdot: float,
        x_q: float,
        z_u: float,
        z_w: float,
        z_wdot: float,
        z_q: float,
        m_u: float,
        m_w: float,
        m_wdot: float,
        m_q: float,
        c_l: float,
        mu1: float,
        i_b: float,
    ) -> None: ...
    @staticmethod
    def read(
        source: Optional[DerivativeSource] = None, /, *, notation: Optional[str] = None, **quantities: float
    ) -> Derivatives:
        """Read a derivative set in any notation (converted to the report's)."""
    @staticmethod
    def from_array(values: Sequence[float]) -> Derivatives: ...
    def to_array(self) -> npt.NDArray[np.float64]: ...
    def to_dict(self) -> dict[str, float]: ...
    def replace(self, **quantities: float) -> Derivatives: ...
    def quartic_coefficients(self) -> npt.NDArray[np.float64]:
        """[A, B, C, D, E] of eq (5), the exact expansion of eq (4)."""

class Mode:
    """One mode (§4, eq 8), in units of τ; None where undefined."""

    name: str
    origin: Optional[str]
    re: float
    im: float
    root: complex
    period: Optional[float]
    time_to_half: Optional[float]
    time_to_double: Optional[float]
    cycles_to_half: Optional[float]
    cycles_to_double: Optional[float]
    damping_ratio: Optional[float]
    natural_frequency: float
    frequency_parameter: Optional[float]
    tau_s: Optional[float]
    period_s: Optional[float]
    time_to_half_s: Optional[float]
    time_to_double_s: Optional[float]
    def to_dict(self) -> dict[str, Any]: ...

class Quartic:
    """A derivative set's stability quartic (eqs 4–6), roots, modes (eq 8),
    Routh (§4) and criteria (§8): ``delta-stability quartic``'s result."""

    coefficients: npt.NDArray[np.float64]
    routh: dict[str, Any]
    stable: bool
    roots: npt.NDArray[np.complex128]
    modes: list[Mode]
    short_period: Optional[Mode]
    phugoid: Optional[Mode]
    verdict: str
    verdict_reasons: list[str]
    criteria: dict[str, Any]
    classical: Optional[dict[str, Any]]
    warnings: list[str]
    derivatives: Derivatives
    tau_s: Optional[float]
    notation: str
    roots_s: Optional[npt.NDArray[np.complex128]]
    """The roots in 1/s (``roots`` over τ), where τ is known."""
    mode_shapes: list[dict[str, Any]]
    """Each mode's eigenvector (u/V, α, q, θ) of eqs (2)–(3), θ = 1."""
    damp: Optional[list[dict[str, Any]]]
    """The modes in seconds (``damp``), when τ is known."""
    short_period_frequency: Optional[dict[str, Any]]
    """MIL-F-8785C §3.2.2.1.1: ω_sp against n/α, the CAP and the levels,
    when τ is known and the short period oscillates."""
    def state_space(self) -> dict[str, Any]:
        """As ``quartic FILE --state-space OUT.json`` exports it: ``A``,
        ``B``, ``C``, ``D`` (2-D arrays; ``B``, ``D`` None without a
        control), the states', inputs' and outputs' names and units,
        ``time_unit``, ``eigenvalues`` and the scripts (``python_control``,
        ``matlab``)."""
    def to_dict(self) -> dict[str, Any]:
        """As ``delta-stability quartic FILE --json``."""

class Analysis:
    """A design point's analysis: ``delta-stability analyze``'s result —
    coefficients (§6), derivatives (§5–7), the quartic (eqs 4–6), modes
    (eq 8), Routh (§4), the §8–9 criteria, and the engineer's outputs of
    ``analyze --json`` (mode shapes; with a physical flight condition the
    modes in seconds, ``damp`` and the MIL-F-8785C short-period frequency)."""

    derivatives: Derivatives
    coefficients: npt.NDArray[np.float64]
    routh: dict[str, Any]
    stable: bool
    roots: npt.NDArray[np.complex128]
    modes: list[Mode]
    short_period: Optional[Mode]
    phugoid: Optional[Mode]
    verdict: str
    verdict_reasons: list[str]
    criteria: dict[str, Any]
    classical: Optional[dict[str, Any]]
    aerodynamics: dict[str, Any]
    damping: dict[str, Any]
    case: dict[str, Any]
    warnings: list[str]
    tau_s: Optional[float]
    """τ = m/(½ρSV) in seconds, at a physical flight condition."""
    flight: Optional[dict[str, Any]]
    """The physical flight condition at the point's Mach number (ρ, a, V,
    μ₁, i_B, C_L·M² of eq 24, C_L, τ), or None."""
    mode_shapes: list[dict[str, Any]]
    """Each mode's eigenvector (u/V, α, q, θ) of eqs (2)–(3), θ = 1."""
    damp: Optional[list[dict[str, Any]]]
    """The modes in seconds (``damp``), when τ is known."""
    short_period_frequency: Optional[dict[str, Any]]
    """MIL-F-8785C §3.2.2.1.1: ω_sp against n/α, the CAP and the levels,
    when τ is known and the short period oscillates."""
    roots_s: Optional[npt.NDArray[np.complex128]]
    """The roots in 1/s (``roots`` over τ), at a physical flight condition."""
    def state_space(self) -> dict[str, Any]:
        """As ``analyze CONFIG --state-space OUT.json`` exports it (see
        ``Quartic.state_space``)."""
    def write_derivatives(self, path: PathLike) -> None:
        """Writes the design point as a derivative file, as ``analyze CONFIG
        --write-derivatives OUT.toml`` does."""
    def to_dict(self) -> dict[str, Any]:
        """As ``delta-stability analyze CONFIG --json``."""

def quartic(
    source: Optional[DerivativeSource] = None, /, *, notation: Optional[str] = None, **quantities: Any
) -> Quartic:
    """The stability quartic (eqs 4–6) of a derivative set in any notation."""

def analyze(
    config: ConfigSource,
    /,
    *,
    mach: Optional[float] = None,
    cg: Optional[float] = None,
    damping: Optional[str] = None,
    aero: Optional[str] = None,
    omega_bar: Optional[float] = None,
    datcom: Optional[str] = None,
    frequency_method: Optional[str] = None,
) -> Analysis:
    """A design point through §5–8: ``delta-stability analyze``, the keywords
    its ``--mach``, ``--cg``, ``--damping``, ``--aero`` (``default`` or
    ``lifting-surface``), ``--omega-bar``, ``--datcom`` and
    ``--frequency-method`` (``p``, ``p-k`` or ``k``)."""

def uncertainty_run(
    config: ConfigSource,
    /,
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
) -> tuple[str, str]:
    """The raw result of ``delta_stability.uncertainty``: the JSON of
    ``delta-stability uncertainty --json`` and its long CSV."""

def report_run(out: Optional[PathLike], /, *, figures: bool = True) -> str:
    """The raw result of ``delta_stability.report``: ``summary.json``'s text
    (written into ``out`` with, given ``figures``, each figure's SVG and
    CSV)."""

def sweep_columns(
    config: ConfigSource,
    *,
    mach: Axis = None,
    sweep: Axis = None,
    cg: Axis = None,
    mu1: Axis = None,
    i_b: Axis = None,
    altitude: Axis = None,
    mass: Axis = None,
    i_y: Axis = None,
    damping: Optional[str] = None,
    aero: Optional[str] = None,
    omega_bar: Optional[float] = None,
    derivatives: bool = False,
    datcom: Optional[str] = None,
    frequency_method: Optional[str] = None,
) -> dict[str, Any]:
    """The raw columns of ``delta_stability.sweep`` (the library's grid,
    ``stability_core::design::sweep``): ``columns`` (the CSV's names, in order), each
    column (a word column such as ``verdict`` as codes into its list in
    ``words`` — ``verdict``'s also as ``verdicts``, the older key —
    ``error`` as codes into ``messages``, −1 for none) and ``shape``."""

def sweep_columns_doc() -> str:
    """The sweep's columns, one line each (name [unit]: meaning), from the
    table the command line's columns come from."""

def batch_roots(
    coefficients: npt.NDArray[np.float64], *, nan: bool = False
) -> npt.NDArray[np.complex128]:
    """The roots of an (N, 5) array of quartics: (N, 4) complex."""

def response(
    source: Optional[DerivativeSource] = None,
    /,
    *,
    until: Optional[float] = None,
    input: str = "step",
    steps: int = 400,
    m0: Optional[float] = None,
    w0: Optional[float] = None,
    neglect_zq_zwdot: bool = False,
    neglect_u: bool = False,
    notation: Optional[str] = None,
    until_s: Optional[float] = None,
    elevator_deg: Optional[float] = None,
    **quantities: Any,
) -> dict[str, npt.NDArray[np.float64]]:
    """The response of §11 (exact; eqs 44–45 beside it for a step)."""

def convert(
    source: Optional[DerivativeSource] = None,
    /,
    *,
    to: str,
    notation: Optional[str] = None,
    **quantities: Any,
) -> dict[str, Any]:
    """A derivative set in another notation (the appendix): ``convert --json``."""

def notations() -> list[str]:
    """The notations a derivative set may be written in."""

def sensitivity(
    source: Optional[DerivativeSource] = None,
    /,
    *,
    mode: str = "short_period",
    notation: Optional[str] = None,
    **quantities: Any,
) -> dict[str, Any]:
    """dλ/dp of a mode for each quartic input, ranked (§10)."""

def size_tail(
    config: ConfigSource,
    /,
    *,
    mach: Optional[Sequence[float]] = None,
    surface: str = "tailplane",
    max_area: Optional[float] = None,
    damping: Optional[str] = None,
    aero: Optional[str] = None,
    omega_bar: Optional[float] = None,
    datcom: Optional[str] = None,
    frequency_method: Optional[str] = None,
) -> dict[str, Any]:
    """The smallest tailplane (or foreplane) of the config's shape meeting the
    §8 standard at every Mach number (``delta-stability size-tail``)."""

def damping_derivatives(
    theory: str,
    *,
    sweep: float,
    mach: float,
    cg: float = 0.25,
    taper: float = 0.0,
    omega_bar: Optional[float] = None,
) -> dict[str, Any]:
    """The damping derivatives of a §7 theory (eqs 32–40)."""

#: A row of the library's registry of models: name, equations, summary,
#: validity, supplies, source.
ModelRow = dict[str, str]

@overload
def theories(*, details: Literal[False] = ...) -> list[str]: ...
@overload
def theories(*, details: Literal[True]) -> list[ModelRow]: ...
def theories(*, details: bool = False) -> Union[list[str], list[ModelRow]]:
    """The §7 damping theories (with ``details=True``, their registry rows)."""

@overload
def damping_models(*, details: Literal[False] = ...) -> list[str]: ...
@overload
def damping_models(*, details: Literal[True]) -> list[ModelRow]: ...
def damping_models(*, details: bool = False) -> Union[list[str], list[ModelRow]]:
    """``faired``, ``faired-slender`` and the theories (with ``details=True``, their registry rows)."""

@overload
def aero_models(*, details: Literal[False] = ...) -> list[str]: ...
@overload
def aero_models(*, details: Literal[True]) -> list[ModelRow]: ...
def aero_models(*, details: bool = False) -> Union[list[str], list[ModelRow]]:
    """The aerodynamic models of ``analyze(aero=…)`` (with ``details=True``, their registry rows)."""

def lifting_surface(
    *,
    sweep: float,
    mach: float,
    taper: float = 0.0,
    omega_bar: float = 0.0,
    cg: Union[None, float, Sequence[float], npt.ArrayLike] = None,
    c_d: float = 0.0,
) -> dict[str, Any]:
    """The doublet-lattice lifting surface's derivatives at each c.g."""
