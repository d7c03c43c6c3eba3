//! `delta-stability size-tail CONFIG [--mach LO:HI:STEP] [--surface
//! tailplane|foreplane] [--max-area A] [--json]`: the smallest surface of
//! the config's shape that meets the §8 standard at every Mach number
//! ([`stability_core::design::sizing`]).

use crate::Failure;
use crate::args::ModelArgs;
use stability_core::design::sizing::{SCAN, Sizing, TOLERANCE, size_surface};
use stability_core::geometry::configuration::SurfaceKind;
use stability_core::numerics::display::sig;
use stability_io::config::overridden;
use stability_io::diag::InputError;
use stability_io::format::Format;
use stability_io::sweep::parse_machs;
use std::fmt::Write as _;

/// Which surface is sized.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum SurfaceArg {
    /// The config's `[tailplane]` table.
    Tailplane,
    /// The config's `[foreplane]` table.
    Foreplane,
}

/// The command's options.
#[derive(Debug, Clone, clap::Args)]
pub struct Args {
    /// The design-point config (TOML) with the surface to size.
    pub config: String,
    /// The Mach numbers the standard must hold at: A:B:STEP (inclusive) or
    /// a list A,B,….
    #[arg(long, default_value = "0.5:2.0:0.05", allow_hyphen_values = true)]
    pub mach: String,
    /// The surface sized.
    #[arg(long, value_enum, default_value = "tailplane")]
    pub surface: SurfaceArg,
    /// The largest area tried, in the config's length unit squared
    /// (default: the wing's area; at most 1e9, the largest size a config
    /// takes).
    #[arg(long, value_name = "A", value_parser = crate::args::positive)]
    pub max_area: Option<f64>,
    /// Print one JSON object: surface, area (null: none up to the limit),
    /// given_area, limit, volume, outcomes [{mach, verdict,
    /// cycles_to_half, error}].
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub model: ModelArgs,
}

pub fn run(o: &Args) -> Result<(), Failure> {
    let cfg = overridden(&o.config, &o.model.overrides())?;
    let bad = |m: String| Failure::Input(InputError::file(&o.config, m));
    let machs = parse_machs(&o.mach).map_err(&bad)?;
    // an area the config could give its surface (a size is at most 1e9)
    if let Some(a) = o.max_area {
        stability_io::limits::SIZE
            .check(a)
            .map_err(|e| bad(format!("--max-area: {e}")))?;
    }
    let kind = match o.surface {
        SurfaceArg::Tailplane => SurfaceKind::Tailplane,
        SurfaceArg::Foreplane => SurfaceKind::Foreplane,
    };
    let sized = crate::output::while_running(&format!("sizing the {}", kind.name()), || {
        size_surface(&cfg.case, kind, &machs, o.max_area)
    });
    let s = sized.map_err(|e| bad(e.to_string()))?;
    // the page too: every number finite
    crate::output::finite(&o.config, &s)?;
    let format = Format::printed(o.json);
    crate::output::print_as(format, &o.config, &s, || Ok(page(&o.config, &s)))
}

/// The answer in words, then the verdict at each Mach number.
pub fn page(path: &str, s: &Sizing) -> String {
    let name = s.surface.name();
    let mut p = format!(
        "Sizing the {name} of {path} (its sweep, taper, aspect ratio and apex fixed; area varied)\n"
    );
    let _ = match s.area {
        Some(0.0) => writeln!(
            p,
            "  no {name} is needed: the wing alone meets the §8 standard at every Mach number"
        ),
        Some(a) => writeln!(
            p,
            "  smallest area meeting the §8 standard at every Mach number: S = {} (yours: {}; ×{}), V̄ = S·l/(S_w·c̄) = {} (l from the c.g. to its M.A.C. quarter chord)",
            sig(a, 4),
            sig(s.given_area, 4),
            sig(a / s.given_area, 3),
            s.volume.map_or("—".into(), |v| sig(v, 4))
        ),
        None => writeln!(
            p,
            "  no area up to {} (--max-area) meets the §8 standard at every Mach number; the verdicts at that area:",
            sig(s.limit, 4)
        ),
    };
    let _ = writeln!(
        p,
        "  {:>8}  {:<10} {:>12}",
        "Mach", "verdict", "cycles to ½"
    );
    for m in &s.outcomes {
        let verdict = m
            .verdict
            .map_or("no result".to_string(), |v| format!("{v:?}").to_lowercase());
        let cycles = m.cycles_to_half.map_or("—".into(), |c| sig(c, 3));
        let _ = writeln!(p, "  {:>8}  {:<10} {:>12}", sig(m.mach, 4), verdict, cycles);
        if let Some(e) = &m.error {
            let _ = writeln!(p, "            {e}");
        }
    }
    let _ = writeln!(
        p,
        "  (search: the wing alone, then areas ×1.33 apart from 1/1000 of the limit or of the wing's area, whichever is smaller, to the limit ({SCAN} areas up to the wing's), then bisection to {} relative; a window of meeting areas narrower than one scan step can be missed)",
        sig(TOLERANCE, 1)
    );
    p
}
