//! `delta-stability`: the longitudinal (pitch-plane) dynamic stability of
//! aircraft after W.B. McCarter, *Note on the longitudinal stability
//! characteristics and damping in pitch of delta wings at subsonic,
//! transonic and supersonic speeds*, College of Aeronautics, 1953.

use clap::{Parser, Subcommand};
use std::process::ExitCode;

use delta_stability::{Failure, cmd};

/// Longitudinal dynamic stability of aircraft, after McCarter (1953).
///
/// Equation numbers refer to the report. Derivatives are in the report's
/// notation (§3): forces and moments made non-dimensional on ½ρSV, ½ρSVc̄,
/// ½ρSc̄ …; time in units of τ = m/(½ρSV); relative density μ₁ = m/(½ρSc̄);
/// pitching inertia i_B = B/(mc̄²).
#[derive(Parser)]
#[command(name = "delta-stability", version, about, long_about = None, propagate_version = true)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// The stability quartic A λ⁴ + B λ³ + C λ² + D λ + E = 0 of a derivative set (eqs 4–6).
    ///
    /// FILE is TOML in the report's notation:
    ///
    ///   notation = "report"
    ///   [derivatives]   # x_u x_w x_wdot x_q z_u z_w z_wdot z_q m_u m_w m_wdot m_q
    ///   x_u = -0.05
    ///   ...
    ///   [flight]
    ///   c_l = 0.3       # lift coefficient of the level flight, eq (24)
    ///   mu1 = 50.0      # relative density m/(½ρSc̄)
    ///   i_b = 0.08      # pitching inertia B/(mc̄²)
    ///
    /// The coefficients are the exact expansion of the determinant of eq (4);
    /// the report's printed eq (6) has three misprints, corrected here (see
    /// docs/errata.md). Examples: examples/*.toml.
    #[command(verbatim_doc_comment)]
    Quartic {
        /// The derivative file (TOML).
        file: String,
        /// Print one JSON object (key `coefficients`: A B C D E) instead of a table.
        #[arg(long)]
        json: bool,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Quartic { file, json } => cmd::quartic::run(&file, json),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Input(e)) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
