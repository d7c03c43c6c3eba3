//! The Mach box near M = 1 at the short period's frequencies, against the
//! exact reverse-flow solution (`tests/data/supersonic_oscillatory/reference.json`,
//! `scripts/supersonic_oscillatory_reference.py`): the 10° delta (leading
//! edge supersonic down to M = 1.016) at M = 1.03 and 1.05, ω̄ = 0.6 and 1,
//! h = ¼, on N = 16 … 128 strips (raw) and extrapolated (4X_N − X_{N/2})/3
//! ("R"). Errors: z_θ̇ on the larger of |z_θ̇|, |z_q|; m_θ̇ on m_q; C_Lα
//! relative; H₀ absolute. The table of `docs/supersonic-oscillatory.md`,
//! "Near M = 1".
//!
//! `cargo run --release -p stability-core --example supersonic_near_sonic_convergence`

use stability_core::aerodynamics::lifting_surface::Solution;
use stability_core::aerodynamics::lifting_surface::mach_box::{MachBoxSpec, solve};
use stability_core::geometry::{Planform, Size, Trapezoid};

fn main() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/supersonic_oscillatory/reference.json"
    ))
    .expect("the fixture");
    let v: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    let p = Planform::new(10f64.to_radians(), 0.0, Size::RootChord(1.0)).expect("a planform");
    let wing = Trapezoid::from(&p);
    println!("| M | ω̄ | N | z_θ̇ | m_θ̇ on m_q | C_Lα | H₀ |");
    println!("| --- | --- | --- | --- | --- | --- | --- |");
    for case in v["cases"].as_array().expect("cases") {
        let f = |k: &str| case[k].as_f64().expect("a number");
        if case["wing"] != "delta" || f("mach") > 1.2 {
            continue;
        }
        let r = Solution {
            mach: f("mach"),
            omega_bar: f("omega_bar"),
            lift_alpha: f("lift_alpha"),
            moment_alpha: f("moment_alpha"),
            lift_alphadot: f("lift_alphadot"),
            moment_alphadot: f("moment_alphadot"),
            lift_q: f("lift_q"),
            moment_q: f("moment_q"),
        };
        for (strips, richardson) in [
            (16, false),
            (32, false),
            (64, false),
            (128, false),
            (128, true),
        ] {
            let spec = MachBoxSpec { strips, richardson };
            let Ok(s) = solve(&wing, r.mach, r.omega_bar, spec) else {
                continue;
            };
            let (d, e) = (
                s.derivatives(0.25, 0.0).expect("finite"),
                r.derivatives(0.25, 0.0).expect("finite"),
            );
            let n = if richardson {
                format!("{strips} R")
            } else {
                strips.to_string()
            };
            println!(
                "| {} | {} | {n} | {:+.1e} | {:+.1e} | {:+.1e} | {:+.1e} |",
                r.mach,
                r.omega_bar,
                (d.z_thetadot - e.z_thetadot) / e.z_thetadot.abs().max(e.z_q.abs()),
                (d.m_thetadot - e.m_thetadot) / e.m_q.abs(),
                d.lift_slope / e.lift_slope - 1.0,
                d.aerodynamic_centre - e.aerodynamic_centre,
            );
        }
    }
}
