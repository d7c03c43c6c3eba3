//! §9: the quartic's coefficients (Figs 27–31), the short period's ω̄
//! (32) and cycles to half amplitude (33), the static and manoeuvre
//! margins (34–35).

use super::regimes::{self, Basis};
use super::study::{WINGS, across, curve};
use super::{Plate, Study};
use stability_core::criteria::Margins;
use stability_core::design::case::{Case, CaseResult};

pub fn plates(study: &Study) -> Vec<Plate> {
    let mut out: Vec<Plate> = [
        ("27", "A"),
        ("28", "B"),
        ("29", "C"),
        ("30", "D"),
        ("31", "E"),
    ]
    .iter()
    .enumerate()
    .map(|(k, &(id, name))| {
        let title = format!("The coefficient {name} of the stability quartic");
        let fig = study.pair(id, &title, name, &|r| {
            Some(r.analysis.quartic.to_array()[k])
        });
        Plate::new(
            faired(fig, study),
            "Eq (6) corrected (docs/errata.md); μ₁ = 50.",
        )
    })
    .collect();
    out.push(fig32(study));
    out.push(fig33(study));
    out.extend(margins(study));
    out
}

/// A figure of the note's two wings with the regimes of the coefficients
/// and the damping derivatives both: the quartic is built on both.
fn faired(fig: stability_io::plot::Figure, study: &Study) -> stability_io::plot::Figure {
    regimes::faired(fig, study, &WINGS, Basis::Both)
}

fn fig32(study: &Study) -> Plate {
    let mut f = study.pair(
        "32",
        "The frequency parameter ω̄ of the short period",
        "ω̄ = 2πfc̄/V",
        &|r| {
            r.analysis
                .modes
                .short_period()
                .and_then(|m| m.frequency_parameter)
        },
    );
    for (k, &deg) in WINGS.iter().enumerate() {
        f = f.with(curve(
            &format!("{deg}°, √(−m_w/(μ₁i_B)) (§9)"),
            &study.ms,
            &study.results[k],
            |r| r.analysis.short_period_approximation.frequency_parameter,
        ));
    }
    Plate::new(
        faired(f, study),
        "The exact short period's ω̄ = s/μ₁ beside §9's first approximation √(−m_w/(μ₁i_B)); how close they are is among the conclusions.",
    )
}

/// Cycles to half amplitude of the short period (negative: cycles to
/// double); 0 where it does not oscillate.
pub fn cycles(r: &CaseResult) -> Option<f64> {
    match r.analysis.modes.short_period() {
        Some(m) => m.cycles_to_half.or(m.cycles_to_double.map(|c| -c)),
        None => Some(0.0),
    }
}

/// Fig 33, the figure README.md shows.
pub fn fig33(study: &Study) -> Plate {
    let mut f = study.pair(
        "33",
        "Cycles to damp to half amplitude",
        "cycles to half amplitude (negative: cycles to double)",
        &cycles,
    );
    for mu1 in [200.0, 400.0] {
        let rs = across(60.0, &study.ms, |c| Case { mu1, ..c });
        f = f.with(curve(
            &format!("60° delta, μ₁ = {mu1}"),
            &study.ms,
            &rs,
            cycles,
        ));
    }
    f.reference_lines.push((1.0, "one cycle (§8)".into()));
    // cycles to double (negative) only when some point diverges
    let diverges = f.series.iter().any(|s| s.points.iter().any(|p| p.1 < 0.0));
    f.y_range = Some((if diverges { -2.0 } else { 0.0 }, 6.0));
    Plate::new(
        faired(f, study),
        "Exact roots; 0 where the short period is not oscillatory. The report's Fig 33: serious instability of the 45° delta for 0.97 < M < 1.5; the 60° delta adequate for μ₁ below about 200.",
    )
}

fn margins(study: &Study) -> [Plate; 2] {
    let of = |r: &CaseResult| {
        Margins::of(
            &r.analysis.quartic,
            &r.derivatives,
            r.coefficients.lift_slope.value,
        )
    };
    [
        Plate::new(
            faired(
                study.pair(
                    "34",
                    "Contribution of the wing to the static margin",
                    "K_n (eq 42)",
                    &|r| of(r).static_margin,
                ),
                study,
            ),
            "From E by eq (42).",
        ),
        Plate::new(
            faired(
                study.pair(
                    "35",
                    "Contribution of the wing to the manoeuvre margin",
                    "H_m (§9)",
                    &|r| of(r).manoeuvre_margin,
                ),
                study,
            ),
            "From C by §9's relation C ≈ (μ₁/i_B)(∂C_L/∂α)H_m (sign corrected, see criteria.rs).",
        ),
    ]
}
