//! `delta-stability sensitivity FILE [--json]`: how each mode's root moves
//! with each of the fifteen quartic inputs — the question of the report's
//! §7 conclusions, §8 and §10 (which derivative drives the short period's
//! damping), answered exactly by [`stability_core::dynamics::sensitivity`].
//!
//! For a simple root λ = r + is of the quartic P(λ) and an input p,
//! dλ/dp = −(∂P/∂p)(λ)/P′(λ), with ∂P/∂p from the generated exact
//! gradient of the coefficients. Each mode's inputs are ranked by
//! |p·∂r/∂p|, the first-order change of r if p doubled.

use crate::Failure;
use crate::output::print_as;
use crate::page::{aligned, root};
use stability_core::numerics::display::sig;
use stability_io::format::Format;
use stability_io::views::SensitivityJson;
use std::fmt::Write;

/// The command's options.
#[derive(Debug, Clone, clap::Args)]
pub struct Args {
    /// The derivative file (TOML), or a design-point config (its design point as `analyze` computes it).
    pub file: String,
    /// Print one JSON object (keys file, notation, tau_s, modes[].sensitivities[] with input, value, d_re, d_im, d_damping_ratio, d_cycles_to_half, damping_drive, and d_re_s, d_im_s when τ is known).
    #[arg(long)]
    pub json: bool,
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let (input, _) = stability_io::design_point::read_set(&args.file, None)?;
    crate::output::warn_all(&input.warnings);
    let analysis = input.analysis()?;
    let out = SensitivityJson::new(&input, &analysis);
    if !out.is_finite() {
        let m = "the sensitivities overflow f64: no result can be written";
        return Err(input.error_at(input.most_extreme_input(), m).into());
    }
    print_as(Format::printed(args.json), &args.file, &out, || {
        Ok(page(&out))
    })
}

/// The tables, one per mode.
fn page(out: &SensitivityJson<'_>) -> String {
    let mut s = format!(
        "Sensitivity of each root to the quartic's inputs, {} (report notation, §3; dλ/dp = −(∂P/∂p)/P′(λ), exact)\n\
         Each root is λ = r + is: r its real part (the damping: the mode decays where r < 0), s its imaginary part (the\n\
         frequency); ∂r/∂p and ∂s/∂p are their rates of change with the input p, ∂ζ/∂p that of the damping ratio\n\
         ζ = −r/|λ|, and p·∂r/∂p the change of r if p doubled, by which the inputs are ranked.\n",
        out.file
    );
    let unit = if out.tau_s.is_some() {
        "1/τ; 1/s in brackets"
    } else {
        "1/τ"
    };
    for m in &out.modes {
        let root = root(m.re, m.im);
        let _ = writeln!(
            s,
            "\n{}, λ = {root} (1/τ); rates in {unit}; ranked by |p·∂r/∂p|:",
            m.mode.label(m.origin)
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
