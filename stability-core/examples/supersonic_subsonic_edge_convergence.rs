//! The Mach box at ω̄ → 0 on deltas with subsonic leading edges against
//! eq (36) (`supersonic::edge_theory`), h = ¼: relative errors of C_Lα,
//! H₀ (absolute), z_θ̇, m_θ̇ at N = 32, 64, 128 strips and extrapolated
//! (4X₁₂₈ − X₆₄)/3, and m_θ̇'s error on m_q — the table of
//! `docs/supersonic-oscillatory.md` (`PARTS=1`: z_q, m_q, z_ẇ, m_ẇ's
//! errors on stderr; `TAPER=0.2`: cropped deltas, against the same theory
//! with Evvard's tip corrections).
//! `cargo run --release -p stability-core --example supersonic_subsonic_edge_convergence [sweep mach]...`

use stability_core::aerodynamics::lifting_surface::mach_box::{MachBoxError, MachBoxSpec, solve};
use stability_core::aerodynamics::supersonic::{Wing, edge_theory};
use stability_core::geometry::{Planform, Size, Trapezoid};

fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let cases: Vec<(f64, f64)> = if args.len() >= 2 {
        args.chunks(2).map(|c| (c[0], c[1])).collect()
    } else {
        vec![(45.0, 1.2), (45.0, 1.3), (60.0, 1.6)]
    };
    println!("| wing | β cot Λ | N | C_Lα | H₀ | z_θ̇ | m_θ̇ | m_θ̇ on m_q |");
    println!("| --- | --- | --- | --- | --- | --- | --- | --- |");
    for (sweep, mach) in cases {
        let taper: f64 = std::env::var("TAPER")
            .ok()
            .and_then(|t| t.parse().ok())
            .unwrap_or(0.0);
        let p = Planform::new(f64::to_radians(sweep), taper, Size::RootChord(1.0)).unwrap();
        let wing = Trapezoid::from(&p);
        let beta_cot = (mach * mach - 1.0f64).sqrt() / f64::to_radians(sweep).tan();
        let e = edge_theory(
            &Wing::new(f64::to_radians(sweep), taper).unwrap(),
            mach,
            0.25,
        )
        .unwrap()
        .derivatives;
        for (label, strips, richardson) in [
            ("32", 32, false),
            ("64", 64, false),
            ("128", 128, false),
            ("128 R", 128, true),
        ] {
            let spec = MachBoxSpec { strips, richardson };
            let row = match solve(&wing, mach, 0.01, spec) {
                Ok(s) => row(&s, &e, sweep, mach, strips),
                Err(MachBoxError::TooManyRows { rows, .. }) => {
                    format!("({rows} rows: over the limit) | | | |")
                }
                Err(err) => format!("{err}"),
            };
            println!("| {sweep}°, M {mach} | {beta_cot:.3} | {label} | {row} |");
        }
    }
}

/// One table row's cells: the errors of C_Lα, H₀ (absolute), z_θ̇, m_θ̇ and
/// m_θ̇ on m_q against eq (36)'s `e`.
fn row(
    s: &stability_core::aerodynamics::lifting_surface::Solution,
    e: &stability_core::aerodynamics::supersonic::Derivatives,
    sweep: f64,
    mach: f64,
    strips: usize,
) -> String {
    let want = [
        e.lift_slope,
        e.aerodynamic_centre,
        e.damping.z_q + e.damping.z_wdot,
        e.damping.m_q + e.damping.m_wdot,
    ];
    let d = s.derivatives(0.25, 0.0).unwrap();
    let got = [
        d.lift_slope,
        d.aerodynamic_centre,
        d.z_thetadot,
        d.m_thetadot,
    ];
    if std::env::var("PARTS").is_ok() {
        eprintln!(
            "{sweep} {mach} {strips}: z_q {:+.2e} m_q {:+.2e} z_wdot {:+.2e} m_wdot {:+.2e} (m_q {:.4} m_thetadot {:.4})",
            d.z_q / e.damping.z_q - 1.0,
            d.m_q / e.damping.m_q - 1.0,
            d.z_wdot / e.damping.z_wdot - 1.0,
            d.m_wdot / e.damping.m_wdot - 1.0,
            e.damping.m_q,
            e.damping.m_q + e.damping.m_wdot
        );
    }
    let mut cells: Vec<String> = got
        .iter()
        .zip(want)
        .enumerate()
        .map(|(k, (g, w))| {
            let err = if k == 1 { g - w } else { (g - w) / w.abs() };
            format!("{err:+.1e}")
        })
        .collect();
    let scaled = (got[3] - want[3]) / e.damping.m_q.abs();
    cells.push(format!("{scaled:+.1e}"));
    cells.join(" | ")
}
