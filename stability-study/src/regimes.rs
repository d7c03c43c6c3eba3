//! What the figures against Mach number show behind their curves: where a
//! curve is joined between theories (a shaded band, labelled in the
//! damping model's own words; the theories on either side named along the
//! top), and where each wing's leading edge turns sonic (a labelled dashed
//! line). Each is asked of the damping model
//! (`stability_core::aerodynamics::models::damping_model::DampingModel`),
//! where it is defined once:
//!
//! - the damping derivatives' joins (Figs 19–24): the model's regimes'
//!   joins ([`DampingModel::damping_joins`]: the default `faired`'s one
//!   join through the sonic point, from 0.99 to the Mach box's first Mach
//!   number);
//! - the coefficients' joins: as the study's results say their
//!   coefficients were had (`aero::Origin`) — a coefficient of a model's
//!   own theory has that model's joins ([`DampingModel::coefficient_joins`]),
//!   and on the coefficient figures (Figs 2–3, 5–12) the methods of
//!   `aero::defaults` are faired between `SUBSONIC_LIMIT` and
//!   `SUPERSONIC_LIMIT` (0.8 to 1.2);
//! - the figures built on both (the standard, the quartic, the margins,
//!   taper: Figs 25–36) shade the union of the damping joins and the
//!   model's own coefficients' joins (the drag methods' fairing enters them
//!   only through C_D in z_w, and is not a join of theories);
//! - the sonic leading edge, M = 1/cos Λ (`geometry::sonic_leading_edge_mach`:
//!   45°, √2; 60°, 2), where the supersonic theories change — the Mach box's
//!   edges in the default model, the lift slope's two forms in the methods.
//!
//! Not on the figures of one theory (13, 16–18: Figs 16–17 get the sonic
//! edge alone, where (36) ends), against aspect ratio (4, 14–15), edge
//! parameter (1) or time (37–38).

use super::Study;
use stability_core::aerodynamics::damping::Theory;
use stability_core::aerodynamics::models::aero::{Origin, OwnTheory, defaults};
use stability_core::aerodynamics::models::regime::{Regime, RegimeKind};
use stability_core::design::case::{CaseResult, DampingModel};
use stability_core::geometry::{Planform, Size, sonic_leading_edge_mach};
use stability_io::plot::{Band, Figure, VerticalLine};

/// What a figure's curves are built from, so which joins it shows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Basis {
    /// The coefficients and stiffness derivatives of §6.
    Coefficients,
    /// The damping derivatives of §7.
    Damping,
    /// Both: the standard, the quartic and what follows from it.
    Both,
}

/// The note's delta of leading-edge sweep `deg` (degrees), as the damping
/// model's regimes take it.
fn delta(deg: f64) -> Option<Planform> {
    Planform::new(deg.to_radians(), 0.0, Size::RootChord(1.0)).ok()
}

/// The default damping model's regimes of the delta of sweep `deg`.
fn regimes(deg: f64) -> Vec<Regime> {
    delta(deg).map_or_else(Vec::new, |p| DampingModel::default().regimes(&p))
}

/// The name of the markers in `docs/damping-theories.md` around
/// [`regimes_table`].
pub const REGIMES_MARKER: &str = "regimes";

/// The deltas of the note's study whose regimes [`regimes_table`] lists
/// (Figs 25–26 sweep 30° to 75°; the note's two wings are 45° and 60°).
const TABLE_SWEEPS: [f64; 4] = [30.0, 45.0, 60.0, 75.0];

/// The default model's regimes on the study's deltas, as a Markdown table
/// (Mach number from and to, in the model's own words): what
/// `docs/damping-theories.md` states of the model's bands, computed.
pub fn regimes_table() -> String {
    let mut s = String::from(
        "| delta | Mach number | the default `faired` model there |\n| --- | --- | --- |\n",
    );
    for deg in TABLE_SWEEPS {
        for r in regimes(deg).iter().filter(|r| r.to > r.from) {
            let range = if r.to.is_finite() {
                format!("{}–{}", mach(r.from), mach(r.to))
            } else {
                format!("above {}", mach(r.from))
            };
            s.push_str(&format!("| {deg}° | {range} | {} |\n", r.label));
        }
    }
    s
}

/// A Mach number to four decimals, trailing zeros dropped.
fn mach(m: f64) -> String {
    let s = format!("{m:.4}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// The bands' label, the default model's own words.
pub(crate) fn faired_label() -> &'static str {
    regimes(45.0)
        .iter()
        .find(|r| r.kind == RegimeKind::Faired)
        .map_or("faired between theories", |r| r.label)
}

/// The default model's damping derivatives' joins for the wings of sweeps
/// `sweeps`.
pub(crate) fn damping_joins(sweeps: &[f64]) -> Vec<(f64, f64)> {
    sweeps
        .iter()
        .filter_map(|&deg| delta(deg))
        .flat_map(|p| DampingModel::default().damping_joins(&p))
        .collect()
}

/// The damping derivatives' joins of `model` on `planform` (none for a
/// single theory): [`DampingModel::damping_joins`].
pub fn model_damping_joins(model: DampingModel, planform: &Planform) -> Vec<(f64, f64)> {
    model.damping_joins(planform)
}

/// The coefficients' joins, as the results (of the wings `planforms`) had
/// them: a model's own theory's joins, and with `methods` the default
/// methods' band.
pub fn coefficient_joins<'a>(
    results: impl Iterator<Item = &'a CaseResult>,
    planforms: &[Planform],
    methods: bool,
) -> Vec<(f64, f64)> {
    let band = (defaults::SUBSONIC_LIMIT, defaults::SUPERSONIC_LIMIT);
    let of = |model: DampingModel| -> Vec<(f64, f64)> {
        planforms
            .iter()
            .flat_map(|p| model.coefficient_joins(p))
            .collect()
    };
    let mut out = Vec::new();
    for r in results {
        let o = r.coefficients.origin;
        for origin in [
            o.lift_slope,
            o.zero_lift_drag,
            o.drag_due_to_lift,
            o.aerodynamic_centre,
        ] {
            match origin {
                Origin::Method if methods => out.push(band),
                Origin::DampingModel(OwnTheory::Theory(Theory::LiftingSurface))
                | Origin::LiftingSurface => out.extend(of(DampingModel::Faired)),
                Origin::DampingModel(OwnTheory::Joined) => {
                    out.extend(of(DampingModel::FairedTheories))
                }
                _ => {}
            }
        }
    }
    out
}

/// The union of intervals, as disjoint intervals in order (touching ones
/// joined).
pub fn merged(mut joins: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    joins.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut out: Vec<(f64, f64)> = Vec::new();
    for (a, b) in joins {
        match out.last_mut() {
            Some(last) if a <= last.1 => last.1 = last.1.max(b),
            _ => out.push((a, b)),
        }
    }
    out
}

/// `fig` with the bands where its curves (built on `basis` for the wings of
/// `sweeps`) are faired between theories, the theories' regions named
/// along the top, and the wings' sonic leading edges.
pub fn faired(mut fig: Figure, study: &Study, sweeps: &[f64], basis: Basis) -> Figure {
    let mut joins = Vec::new();
    if basis != Basis::Damping {
        let planforms: Vec<Planform> = sweeps.iter().filter_map(|&d| delta(d)).collect();
        joins.extend(coefficient_joins(
            study.results.iter().flatten().flatten(),
            &planforms,
            basis == Basis::Coefficients,
        ));
    }
    if basis != Basis::Coefficients {
        joins.extend(damping_joins(sweeps));
    }
    let bands = merged(joins);
    fig = shaded(fig, &bands);
    if let (Some(first), Some(last)) = (bands.first(), bands.last()) {
        let region = |from, to, label: &str| Band {
            from,
            to,
            label: label.into(),
        };
        fig.regions = std::iter::once(region(f64::NEG_INFINITY, first.0, "subsonic theory"))
            .chain(bands.iter().map(|&(a, b)| region(a, b, "faired")))
            .chain(std::iter::once(region(
                last.1,
                f64::INFINITY,
                "supersonic theory",
            )))
            .collect();
    }
    sonic_edges(fig, sweeps)
}

/// `fig` with the bands `bands` shaded, where its curves are faired
/// between theories.
pub fn shaded(mut fig: Figure, bands: &[(f64, f64)]) -> Figure {
    let label = faired_label();
    fig.bands = bands
        .iter()
        .map(|&(from, to)| Band {
            from,
            to,
            label: label.into(),
        })
        .collect();
    fig
}

/// `fig` with a dashed line where the leading edge of each wing of
/// `sweeps` turns sonic, "45° edge sonic".
pub fn sonic_edges(mut fig: Figure, sweeps: &[f64]) -> Figure {
    for &deg in sweeps {
        let x = sonic_leading_edge_mach(deg.to_radians());
        if !fig.markers.iter().any(|m| m.x == x) {
            fig.markers.push(VerticalLine {
                x,
                label: format!("{deg}° edge sonic"),
            });
        }
    }
    fig
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sonic_edge_is_where_the_faired_model_changes_theory() {
        for (deg, edge) in [(45.0, 2f64.sqrt()), (60.0, 2.0)] {
            let x = sonic_leading_edge_mach(f64::to_radians(deg));
            assert!((x - edge).abs() < 1e-12, "{deg}°: {x}");
            let r = regimes(deg);
            let sup = r
                .iter()
                .find(|r| r.kind == RegimeKind::MachBoxSupersonicEdge)
                .unwrap();
            assert_eq!(sup.from, x, "{deg}°");
            let p = delta(deg).unwrap();
            let old = DampingModel::FairedTheories.regimes(&p);
            let sup = old
                .iter()
                .find(|r| r.kind == RegimeKind::SupersonicEdge)
                .unwrap();
            assert_eq!(sup.from, x, "{deg}°");
        }
    }

    /// The band of a coefficient figure is where its curve is faired: with
    /// the methods' coefficients (`faired-slender`), below it the lift
    /// slope (Fig 5) is the subsonic method's, above it the supersonic
    /// method's, inside it neither. (Under the default `faired` model the
    /// lift slope is the lifting surface's, joined from 0.99 to the Mach
    /// box's first Mach number, C_D0 the method's: the band is the
    /// methods', 0.8 to 1.2, which holds the join.)
    #[test]
    fn the_coefficients_band_is_where_the_lift_slope_is_neither_method() {
        use stability_core::design::case::{Case, DampingModel, evaluate};
        use stability_core::design::study::{grid, report_wing};
        let ms = grid(0.5, 2.0, 0.02);
        let at = |m: f64, damping| {
            evaluate(&Case {
                damping,
                ..report_wing(45.0, m)
            })
            .ok()
        };
        let results: Vec<(f64, CaseResult)> = ms
            .iter()
            .filter_map(|&m| at(m, DampingModel::FairedSlender).map(|r| (m, r)))
            .collect();
        let faired: Vec<CaseResult> = [0.6, 0.95, 1.5]
            .iter()
            .filter_map(|&m| at(m, DampingModel::Faired))
            .collect();
        let p45 = [delta(45.0).unwrap()];
        assert_eq!(
            merged(coefficient_joins(faired.iter(), &p45, true)),
            vec![(0.8, 1.2)]
        );
        assert_eq!(results.len(), ms.len());
        let bands = merged(coefficient_joins(
            results.iter().map(|(_, r)| r),
            &p45,
            true,
        ));
        let [(from, to)] = bands[..] else {
            panic!("{bands:?}")
        };
        let p = delta(45.0).unwrap();
        for (m, r) in &results {
            let a = r.coefficients.lift_slope.value;
            let sub = defaults::lift_slope_subsonic(&p, *m).value;
            let sup = defaults::lift_slope_supersonic(&p, *m).value;
            let same = |b: f64| (a - b).abs() < 1e-9 * b.abs();
            if *m <= from {
                assert!(same(sub), "M = {m}: {a} vs {sub}");
            } else if *m >= to {
                assert!(same(sup), "M = {m}: {a} vs {sup}");
            } else {
                assert!(!same(sub) && !same(sup), "M = {m}: {a}");
            }
        }
    }

    #[test]
    fn joins_merge_into_disjoint_bands() {
        assert_eq!(
            merged(vec![(1.0, 1.2), (0.8, 1.2), (0.9, 1.0), (1.5, 1.6)]),
            vec![(0.8, 1.2), (1.5, 1.6)]
        );
        // the default model's one join on each wing, from 0.99 to the
        // Mach box's first Mach number (1.0055 on the 45° delta, 1.0164 on
        // the 60°): one band, within 0.03 of M = 1
        let [(from, to)] = merged(damping_joins(&[45.0, 60.0]))[..] else {
            panic!()
        };
        assert_eq!(
            from,
            stability_core::aerodynamics::models::faired::SONIC_JOIN
        );
        assert!((to - 1.0164).abs() < 1e-3 && to < 1.03, "{to}");
        // the note's fairing's two joins touch at M = 1: 0.9 to 1.2
        let p = delta(45.0).unwrap();
        assert_eq!(
            merged(model_damping_joins(DampingModel::FairedTheories, &p)),
            vec![(0.9, 1.2)]
        );
    }

    /// The docs' table: on each delta the regimes tile M 0 to the last,
    /// one row each, the join from 0.99 among them.
    #[test]
    fn the_regimes_table_lists_each_deltas_regimes_in_order() {
        let table = regimes_table();
        for deg in TABLE_SWEEPS {
            let rows: Vec<&str> = table
                .lines()
                .filter(|l| l.starts_with(&format!("| {deg}° |")))
                .collect();
            assert!(rows[0].contains("| 0–0.9 |"), "{rows:?}");
            assert!(rows.last().unwrap().contains("above "), "{rows:?}");
            assert!(
                rows.iter()
                    .any(|r| r.contains("| 0.99–1.")
                        && r.ends_with(&format!("{} |", faired_label()))),
                "{rows:?}"
            );
        }
        assert_eq!(mach(1.0055), "1.0055");
        assert_eq!(mach(0.9), "0.9");
        assert_eq!(mach(3.0), "3");
    }
}
