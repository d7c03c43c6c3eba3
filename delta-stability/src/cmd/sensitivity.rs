//! `delta-stability sensitivity FILE [--json]`: how each mode's root moves
//! with each of the fifteen quartic inputs — the question of the report's
//! §7 conclusions, §8 and §10 (which derivative drives the short period's
//! damping), answered exactly by [`stability_core::sensitivity`].
//!
//! For a simple root λ = r + is of the quartic P(λ) and an input p,
//! dλ/dp = −(∂P/∂p)(λ)/P′(λ), with ∂P/∂p from the generated exact
//! gradient of the coefficients. Each mode's inputs are ranked by
//! |p·∂r/∂p|, the first-order change of r if p doubled.

use crate::Failure;
use crate::engineering::{aligned, mode_name};
use crate::fmt::sig;
use crate::input;
use crate::output::print;
use serde::Serialize;
use stability_core::analysis::Analysis;
use stability_core::modes::{ModeName, Origin};
use stability_core::sensitivity::{ModeSensitivity, mode_sensitivities};
use std::fmt::Write;

/// One input's sensitivities, with the rates also in 1/s when τ is known.
#[derive(Serialize)]
struct InputJson {
    #[serde(flatten)]
    s: ModeSensitivity,
    #[serde(skip_serializing_if = "Option::is_none")]
    d_re_s: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    d_im_s: Option<f64>,
}

#[derive(Serialize)]
struct ModeJson {
    mode: ModeName,
    origin: Option<Origin>,
    re: f64,
    im: f64,
    /// `None` at a multiple root, where λ is not differentiable.
    sensitivities: Option<Vec<InputJson>>,
}

#[derive(Serialize)]
struct SensitivityJson<'a> {
    file: &'a str,
    notation: &'a str,
    tau_s: Option<f64>,
    modes: Vec<ModeJson>,
}

pub fn run(file: &str, json: bool) -> Result<(), Failure> {
    let input = input::read(file)?;
    for w in &input.warnings {
        crate::output::warn(&format!("warning: {w}"));
    }
    let d = &input.derivatives;
    let analysis = Analysis::of(d)
        .map_err(|e| input.error_at(super::quartic::blame(&input, &e), e.to_string()))?;
    let tau = input.dimensional.map(|x| x.tau());
    let modes: Vec<ModeJson> = analysis
        .modes
        .iter()
        .map(|m| ModeJson {
            mode: m.name,
            origin: m.origin,
            re: m.re,
            im: m.im,
            sensitivities: mode_sensitivities(d, m).map(|v| {
                v.into_iter()
                    .map(|s| InputJson {
                        d_re_s: tau.map(|t| s.d_re / t),
                        d_im_s: tau.map(|t| s.d_im / t),
                        s,
                    })
                    .collect()
            }),
        })
        .collect();
    let finite = modes
        .iter()
        .flat_map(|m| m.sensitivities.iter().flatten())
        .all(|i| {
            [i.s.d_re, i.s.d_im, i.s.d_damping_ratio, i.s.damping_drive]
                .iter()
                .all(|v| v.is_finite())
        });
    if !finite {
        let m = "the sensitivities overflow f64: no result can be written";
        let at = super::quartic::most_extreme_input(&input);
        return Err(input.error_at(at, m).into());
    }
    let out = SensitivityJson {
        file,
        notation: &input.notation,
        tau_s: tau,
        modes,
    };
    if json {
        print(&format!(
            "{}\n",
            serde_json::to_string_pretty(&out).unwrap_or_default()
        ))
    } else {
        print(&page(&out))
    }
}

/// The tables, one per mode.
fn page(out: &SensitivityJson<'_>) -> String {
    let mut s = format!(
        "Sensitivity of each root to the quartic's inputs, {} (report notation, §3; dλ/dp = −(∂P/∂p)/P′(λ), exact)\n",
        out.file
    );
    let unit = if out.tau_s.is_some() {
        "1/τ; 1/s in brackets"
    } else {
        "1/τ"
    };
    for m in &out.modes {
        let root = if m.im > 0.0 {
            format!("{} ± {}i", sig(m.re, 5), sig(m.im, 5))
        } else {
            sig(m.re, 5)
        };
        let _ = writeln!(
            s,
            "\n{}, λ = {root} (1/τ); rates in {unit}; ranked by |p·∂r/∂p|:",
            mode_name(m.mode, m.origin)
        );
        let Some(rows) = &m.sensitivities else {
            let _ = writeln!(
                s,
                "  a multiple root: λ is not differentiable in the inputs"
            );
            continue;
        };
        let header = [
            "input",
            "value",
            "∂r/∂p",
            "∂s/∂p",
            "∂ζ/∂p",
            "∂(cycles ½)/∂p",
            "p·∂r/∂p",
        ];
        let mut table = vec![header.map(String::from).to_vec()];
        for i in rows {
            let rate = |x: f64, xs: Option<f64>| match xs {
                Some(v) => format!("{} ({})", sig(x, 4), sig(v, 3)),
                None => sig(x, 4),
            };
            table.push(vec![
                i.s.input.to_string(),
                sig(i.s.value, 4),
                rate(i.s.d_re, i.d_re_s),
                rate(i.s.d_im, i.d_im_s),
                sig(i.s.d_damping_ratio, 4),
                i.s.d_cycles_to_half.map_or("—".into(), |x| sig(x, 4)),
                sig(i.s.damping_drive, 4),
            ]);
        }
        s.push_str(&aligned(&table));
    }
    s
}
