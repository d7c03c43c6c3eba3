//! The previous default, `faired-theories`: the §7 theories joined through
//! Mach number as the note built its Figs 19–24 — "with the aid of the
//! results of the various theories … the curves of Figs. 19 to 24 were
//! prepared" — each theory where the note trusts it, and between them a
//! stated join (docs/damping-theories.md, "The note's fairing"):
//!
//! | Mach number | damping derivatives | lift slope, aerodynamic centre |
//! | --- | --- | --- |
//! | M ≤ [`LIFTING_SURFACE_LIMIT`] (0.9) | lifting-surface theory at the short period's own ω̄ (the note: Multhopp–Garner "reliable … up to a Mach number of about 0.9") | the lattice's steady a, H₀ |
//! | 0.9 < M < 1 | faired: the lattice's values at 0.9 joined to Mangler's at M = 1 | faired: the lattice's at 0.9 joined to linear supersonic theory's at 1.2 |
//! | M = [`SONIC`] (1) | Mangler's transonic theory (38)–(40) at the short period's ω̄ ("claimed to be valid at M = 1.0") | (faired, as above) |
//! | 1 < M < 1.2 | faired: Mangler's at M = 1 joined to linear theory's at 1.2 | (faired, as above) |
//! | M ≥ [`SUPERSONIC_FROM`] (1.2) | linear supersonic theory: (36) while the leading edge is subsonic (a cropped wing: its potentials less the tips' corrections, `supersonic::subsonic_edge`), the supersonic-edge theory past it (`supersonic::edge_theory`; continuous at the sonic edge) | the same theory's |
//!
//! The bands are where the curve is a guess. Until the lifting surface through M = 1 became
//! the default `faired`, this was it; the default is now one lifting-surface theory through
//! M = 1 ([`super`]), and this model is kept for comparison and for the
//! note's own construction.

use super::super::increment::{Increment, Method, by_method, from_numbers, with_derivatives};
use super::super::regime::{Regime, RegimeKind};
use crate::aerodynamics::damping::{
    Damping, DampingError, Theory, WingInput, damping_derivatives_with, theory_coefficients,
};
use crate::aerodynamics::damping::{OwnTheory, TheoryCoefficients};
use crate::aerodynamics::lifting_surface::configuration::ConfigurationError;
use crate::aerodynamics::lifting_surface::{Contribution, Harmonic, store};
use crate::aerodynamics::warnings::{Warning, Warnings};
use crate::derivatives::DampingDerivatives;
use crate::geometry::configuration::{Configuration, Part};
use crate::geometry::{Planform, sonic_leading_edge_mach};
use crate::numerics::interpolation::{Value, hermite, monotone_slopes};

/// Up to this Mach number the faired model is lifting-surface theory (§7:
/// the Multhopp–Garner theory "provides what appears to be a reliable
/// prediction of the effects of compressibility up to a Mach number of
/// about 0.9").
pub const LIFTING_SURFACE_LIMIT: f64 = 0.9;

/// The Mach number of Mangler's transonic theory (38)–(40) ("claimed to be
/// valid at M = 1.0").
pub const SONIC: f64 = 1.0;

/// From this Mach number on the faired model is linear supersonic theory,
/// as the note applies (36) at M = 1.2 (§7, §10, Fig 17).
pub const SUPERSONIC_FROM: f64 = 1.2;

/// The two bands where the faired model joins one theory to the next:
/// [0.9, 1.0] (the lifting surface to Mangler's theory) and [1.0, 1.2]
/// (Mangler's theory to linear supersonic theory).
pub const JOINS: [(f64, f64); 2] = [(LIFTING_SURFACE_LIMIT, SONIC), (SONIC, SUPERSONIC_FROM)];

/// The note's fairing's regimes for a planform, in Mach order: subsonic to
/// 0.9, the two joins, then (36) up to the Mach number where the leading
/// edge turns sonic, 1/cos Λ (`geometry::sonic_leading_edge_mach`), and the
/// supersonic-edge theory beyond. (Where the leading edge is already sonic
/// below 1.2 — sweep under 33.6° — the (36) regime is empty and left out.)
pub fn regimes(planform: &Planform) -> Vec<Regime> {
    let sonic_edge = sonic_leading_edge_mach(planform.sweep_le).max(SUPERSONIC_FROM);
    let all = [
        Regime {
            from: 0.0,
            to: LIFTING_SURFACE_LIMIT,
            kind: RegimeKind::Subsonic,
            label: "lifting surface",
        },
        Regime {
            from: JOINS[0].0,
            to: JOINS[0].1,
            kind: RegimeKind::Faired,
            label: "faired between theories",
        },
        Regime {
            from: JOINS[1].0,
            to: JOINS[1].1,
            kind: RegimeKind::Faired,
            label: "faired between theories",
        },
        Regime {
            from: SUPERSONIC_FROM,
            to: sonic_edge,
            kind: RegimeKind::SubsonicEdge,
            label: "(36), subsonic leading edge",
        },
        Regime {
            from: sonic_edge,
            to: f64::INFINITY,
            kind: RegimeKind::SupersonicEdge,
            label: "supersonic leading edge",
        },
    ];
    all.into_iter().filter(|r| r.to > r.from).collect()
}

/// The Mach step of the lattice's slope at [`LIFTING_SURFACE_LIMIT`] (a
/// backward difference: the lattice is not used above 0.9).
pub const LATTICE_SLOPE_STEP: f64 = 0.02;

/// The Mach step of linear supersonic theory's slope at
/// [`SUPERSONIC_FROM`] (a central difference of its closed forms).
pub const SUPERSONIC_SLOPE_STEP: f64 = 1e-4;

/// One end of a join: a theory's derivatives at the band's end, and their
/// rate of change with Mach number there.
struct End {
    mach: f64,
    damping: Damping,
    slope: DampingDerivatives,
}

/// The faired model's damping derivatives of the wing at c.g. `h`, Mach
/// `mach` and frequency parameter ω̄ (`omega_bar`: the short period's, which
/// the lifting surface and Mangler's theory need; linear supersonic theory
/// checks its low-frequency rule at it), the lattice's harmonic solutions
/// had as `harmonic` says. In a join ([`JOINS`]) each derivative is the
/// cubic through both ends' values and Mach slopes (the lattice's by a
/// backward difference at 0.9, Mangler's zero — his theory has no Mach
/// number — linear theory's by a central difference at 1.2), its slopes
/// limited as Fritsch and Carlson's (`aero::monotone_slopes`) so that the
/// join does not overshoot the ends: the draftsman's fairing, C¹, stated.
/// The result carries the ends' warnings and [`Warning::Faired`]; its
/// `theory` is the nearer end's.
pub fn damping(
    wing: &WingInput,
    h: f64,
    mach: f64,
    omega_bar: Option<f64>,
    harmonic: Harmonic,
) -> Result<Damping, DampingError> {
    let at =
        |theory: Theory, m: f64| damping_derivatives_with(theory, wing, h, m, omega_bar, harmonic);
    if !mach.is_finite() || mach <= LIFTING_SURFACE_LIMIT {
        // (non-finite: the theory says so)
        return at(Theory::LiftingSurfaceFrequency, mach);
    }
    if mach >= SUPERSONIC_FROM {
        return at(Theory::Supersonic, mach);
    }
    if mach == SONIC {
        return at(Theory::TransonicFrequency, SONIC);
    }
    let mangler = || -> Result<End, DampingError> {
        let d = at(Theory::TransonicFrequency, SONIC)?;
        Ok(End {
            mach: SONIC,
            damping: d,
            slope: DampingDerivatives::default(),
        })
    };
    let (lower, upper) = if mach < SONIC {
        let lattice = at(Theory::LiftingSurfaceFrequency, LIFTING_SURFACE_LIMIT)?;
        let before = at(
            Theory::LiftingSurfaceFrequency,
            LIFTING_SURFACE_LIMIT - LATTICE_SLOPE_STEP,
        )?;
        let slope = difference(
            &before.derivatives,
            &lattice.derivatives,
            LATTICE_SLOPE_STEP,
        );
        let lower = End {
            mach: LIFTING_SURFACE_LIMIT,
            damping: lattice,
            slope,
        };
        (lower, mangler()?)
    } else {
        let step = SUPERSONIC_SLOPE_STEP;
        let below = at(Theory::Supersonic, SUPERSONIC_FROM - step)?;
        let above = at(Theory::Supersonic, SUPERSONIC_FROM + step)?;
        let upper = End {
            mach: SUPERSONIC_FROM,
            damping: at(Theory::Supersonic, SUPERSONIC_FROM)?,
            slope: difference(&below.derivatives, &above.derivatives, 2.0 * step),
        };
        (mangler()?, upper)
    };
    Ok(join(&lower, &upper, mach))
}

/// (b − a)/dx, derivative by derivative.
fn difference(a: &DampingDerivatives, b: &DampingDerivatives, dx: f64) -> DampingDerivatives {
    DampingDerivatives {
        z_q: (b.z_q - a.z_q) / dx,
        z_wdot: (b.z_wdot - a.z_wdot) / dx,
        m_q: (b.m_q - a.m_q) / dx,
        m_wdot: (b.m_wdot - a.m_wdot) / dx,
    }
}

/// The monotone cubic through (x₀, y₀, d₀) and (x₁, y₁, d₁) at x.
fn fair((x0, y0, d0): (f64, f64, f64), (x1, y1, d1): (f64, f64, f64), x: f64) -> Value {
    let (d0, d1) = monotone_slopes((y1 - y0) / (x1 - x0), d0, d1);
    hermite((x0, y0, d0), (x1, y1, d1), x)
}

/// The derivatives between the ends `a` (lower Mach) and `b` at `mach`.
fn join(a: &End, b: &End, mach: f64) -> Damping {
    let (p, q) = (&a.damping.derivatives, &b.damping.derivatives);
    let each = |f: fn(&DampingDerivatives) -> f64| {
        fair(
            (a.mach, f(p), f(&a.slope)),
            (b.mach, f(q), f(&b.slope)),
            mach,
        )
        .value
    };
    let derivatives = DampingDerivatives {
        z_q: each(|d| d.z_q),
        z_wdot: each(|d| d.z_wdot),
        m_q: each(|d| d.m_q),
        m_wdot: each(|d| d.m_wdot),
    };
    let mut warnings = Warnings::default();
    warnings.push(Warning::Faired {
        mach,
        lower: a.damping.theory,
        lower_mach: a.mach,
        upper: b.damping.theory,
        upper_mach: b.mach,
    });
    warnings.extend(&a.damping.warnings);
    warnings.extend(&b.damping.warnings);
    let nearer = if mach - a.mach <= b.mach - mach { a } else { b };
    Damping {
        theory: nearer.damping.theory,
        derivatives,
        // a fairing between theories has no in-phase change of its own
        in_phase: Default::default(),
        fig18: nearer.damping.fig18,
        warnings,
    }
}

/// The faired model's lift slope and aerodynamic centre, with their Mach
/// derivatives (eqs 27–29 need them), so that z_w, m_w come from the
/// theories z_q, m_q come from: the lattice's steady values (exact Mach
/// derivatives) up to [`LIFTING_SURFACE_LIMIT`], linear supersonic
/// theory's from [`SUPERSONIC_FROM`] (`supersonic::edge_coefficients`), and
/// between them the monotone cubic through both ends' values and exact
/// slopes. (One join, 0.9 to 1.2: Mangler's (38) has the slender lift slope
/// πA/2, which the note's Fig 5, "based on evidence", does not reach for
/// these aspect ratios.)
pub fn coefficients(
    planform: &Planform,
    mach: f64,
) -> Result<Option<TheoryCoefficients>, DampingError> {
    if !mach.is_finite() {
        return Ok(None);
    }
    if mach >= SUPERSONIC_FROM {
        return theory_coefficients(Theory::Supersonic, planform, mach);
    }
    let lattice = lattice_coefficients(planform, mach.min(LIFTING_SURFACE_LIMIT))?;
    if mach <= LIFTING_SURFACE_LIMIT {
        return Ok(Some(lattice));
    }
    let Some(sup) = theory_coefficients(Theory::Supersonic, planform, SUPERSONIC_FROM)? else {
        return Ok(None);
    };
    let each = |f: fn(&TheoryCoefficients) -> Value| {
        let (a, b) = (f(&lattice), f(&sup));
        fair(
            (LIFTING_SURFACE_LIMIT, a.value, a.d_mach),
            (SUPERSONIC_FROM, b.value, b.d_mach),
            mach,
        )
    };
    Ok(Some(TheoryCoefficients {
        model: OwnTheory::Joined,
        lift_slope: each(|c| c.lift_slope),
        aerodynamic_centre: each(|c| c.aerodynamic_centre),
    }))
}

/// The lattice's steady lift slope and aerodynamic centre at `mach` < 1.
fn lattice_coefficients(
    planform: &Planform,
    mach: f64,
) -> Result<TheoryCoefficients, DampingError> {
    let shape = store::unit_wing(planform.aspect_ratio(), planform.taper, planform.sweep_le)?;
    let steady = store::lattice_steady(&shape, mach)?;
    let ((a, da), (h0, dh0)) = (steady.lift_slope(), steady.aerodynamic_centre());
    Ok(TheoryCoefficients {
        model: OwnTheory::Theory(Theory::LiftingSurface),
        lift_slope: Value::new(a, da),
        aerodynamic_centre: Value::new(h0, dh0),
    })
}

/// From this Mach number the note's model's damping is quasi-steady
/// (linear supersonic theory); below it the short period's ω̄ is iterated.
pub fn iterates_frequency_at(mach: f64) -> bool {
    mach < SUPERSONIC_FROM
}

/// Where the note's model joins its own lift slope and aerodynamic centre:
/// the lattice's at 0.9 to linear supersonic theory's at 1.2 (one cubic).
pub const COEFFICIENT_JOIN: (f64, f64) = (LIFTING_SURFACE_LIMIT, SUPERSONIC_FROM);

/// A configuration's increment over its wing in the note's bands (the
/// increment of `faired-theories` and of the classical theories, which
/// have no lifting surface of their own near M = 1):
///
/// | Mach number | the increment |
/// | --- | --- |
/// | M ≤ 0.9 | the multi-surface doublet lattice |
/// | 0.9 < M < 1.2 | each part's every number the monotone cubic (Fritsch–Carlson slopes) through the lattice's value at 0.9 (slope: backward difference over [`LATTICE_SLOPE_STEP`]) and the supersonic theory's at 1.2 (slope: central difference over [`SUPERSONIC_SLOPE_STEP`]) |
/// | M ≥ 1.2 | each surface by linear supersonic theory, the wing's downwash at the tailplane |
pub fn increment(
    config: &Configuration,
    mach: f64,
    omega_bar: f64,
    harmonic: Harmonic,
    mach_derivatives: bool,
) -> Result<Increment, ConfigurationError> {
    if !mach.is_finite() || mach < 0.0 {
        return Err(ConfigurationError::Geometry(format!(
            "the Mach number must be finite and ≥ 0, not {mach}"
        )));
    }
    if mach > LIFTING_SURFACE_LIMIT && mach < SUPERSONIC_FROM {
        return faired(config, mach, omega_bar, harmonic);
    }
    let (method, lo) = if mach >= SUPERSONIC_FROM {
        (Method::Supersonic, SUPERSONIC_FROM)
    } else {
        (Method::Lattice, 0.0)
    };
    with_derivatives(
        config,
        mach,
        omega_bar,
        method,
        harmonic,
        mach_derivatives,
        lo,
    )
}

/// The faired band: each part's every number the monotone cubic
/// between the lattice at 0.9 and the supersonic theory at 1.2, with
/// the ends' slopes; the increment is their sum (so the parts sum to
/// it, and its Mach derivative is theirs).
fn faired(
    config: &Configuration,
    mach: f64,
    omega_bar: f64,
    harmonic: Harmonic,
) -> Result<Increment, ConfigurationError> {
    let (m0, m1, st) = (
        LIFTING_SURFACE_LIMIT,
        SUPERSONIC_FROM,
        SUPERSONIC_SLOPE_STEP,
    );
    let ends = [
        by_method(config, m0, omega_bar, Method::Lattice, harmonic)?.1,
        by_method(
            config,
            m0 - LATTICE_SLOPE_STEP,
            omega_bar,
            Method::Lattice,
            harmonic,
        )?
        .1,
        by_method(config, m1, omega_bar, Method::Supersonic, harmonic)?.1,
        by_method(config, m1 - st, omega_bar, Method::Supersonic, harmonic)?.1,
        by_method(config, m1 + st, omega_bar, Method::Supersonic, harmonic)?.1,
    ];
    let of = |i: usize, part: Part| {
        ends[i]
            .iter()
            .find(|c| c.part == part)
            .map_or([0.0; 6], |c| c.solution.numbers())
    };
    let mut order: Vec<Part> = Vec::new();
    for c in ends[0].iter().chain(ends[2].iter()) {
        if !order.contains(&c.part) {
            order.push(c.part);
        }
    }
    let mut parts = Vec::new();
    let (mut total, mut d) = ([0.0; 6], [0.0; 2]);
    for part in order {
        let (y0, b0, y1, c1, a1) = (
            of(0, part),
            of(1, part),
            of(2, part),
            of(3, part),
            of(4, part),
        );
        let v: [crate::numerics::interpolation::Value; 6] = std::array::from_fn(|i| {
            let s0 = (y0[i] - b0[i]) / LATTICE_SLOPE_STEP;
            let s1 = (a1[i] - c1[i]) / (2.0 * st);
            let (e0, e1) = monotone_slopes((y1[i] - y0[i]) / (m1 - m0), s0, s1);
            hermite((m0, y0[i], e0), (m1, y1[i], e1), mach)
        });
        for i in 0..6 {
            total[i] += v[i].value;
        }
        d[0] += v[0].d_mach;
        d[1] += v[1].d_mach;
        parts.push(Contribution {
            part,
            solution: from_numbers(v.map(|x| x.value), mach, omega_bar),
        });
    }
    Ok(Increment {
        solution: from_numbers(total, mach, omega_bar),
        parts,
        d_lift_alpha: Some(d[0]),
        d_moment_alpha: Some(d[1]),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Size;

    #[test]
    fn the_regimes_tile_the_mach_axis_and_the_sonic_edge_is_where_beta_cot_is_one() {
        for deg in [45.0_f64, 60.0, 30.0] {
            let p = Planform::new(deg.to_radians(), 0.0, Size::RootChord(10.0)).unwrap();
            let r = regimes(&p);
            assert_eq!(r[0].from, 0.0);
            assert!(r.windows(2).all(|w| w[0].to == w[1].from));
            assert_eq!(r.last().unwrap().to, f64::INFINITY);
            let edge = r.last().unwrap().from;
            if deg > 35.0 {
                // β cot Λ = 1 there
                let beta = (edge * edge - 1.0).sqrt();
                assert!((beta / deg.to_radians().tan() - 1.0).abs() < 1e-12);
            } else {
                assert_eq!(edge, SUPERSONIC_FROM);
            }
        }
    }
}
