//! The p-method on the case with a closed form (issue 33's first check):
//! the incompressible typical section in plunge and pitch, its air forces
//! Theodorsen's at the root's own complex reduced frequency p̄ = sb/V
//! ([`stability_core::aerodynamics::theodorsen`]), each root found by the
//! secant method on the 2 × 2 determinant
//! ([`stability_core::numerics::complex_root`]). Against
//! `scripts/typical_section_p_method.py` (mpmath, 30 digits: the roots of
//! both branches at V/(bω_α) = 0.5–2.4, and the flutter point, which the
//! script found twice — by the p-method and by the classical real-k
//! solution — equal to 1e-12). The equations are the script's (Hodges &
//! Pierce 2011, §5.5; h down, α nose up, per unit mV²/b and mV²).

use num_complex::Complex64;
use stability_core::aerodynamics::theodorsen::theodorsen;
use stability_core::numerics::complex_root::secant;

const FIXTURE: &str = include_str!("../data/typical_section/p_method.json");

/// The section's parameters.
struct Section {
    a: f64,
    x_alpha: f64,
    r2: f64,
    sigma: f64,
    mu: f64,
}

impl Section {
    /// The determinant at p̄ and V̄ = V/(bω_α).
    fn det(&self, p: Complex64, vbar: f64) -> Option<Complex64> {
        let Section {
            a,
            x_alpha,
            r2,
            sigma,
            mu,
        } = *self;
        let c = theodorsen(p)?;
        let p2 = p * p;
        // the circulatory part's downwash at ¾ chord per unknown
        let wash_a = 1.0 + (0.5 - a) * p;
        let lift_h = (p2 + 2.0 * c * p) / mu;
        let lift_a = (p - a * p2 + 2.0 * c * wash_a) / mu;
        let mom_h = (a * p2 + 2.0 * (a + 0.5) * c * p) / mu;
        let mom_a = (-(0.5 - a) * p - (0.125 + a * a) * p2 + 2.0 * (a + 0.5) * c * wash_a) / mu;
        let m11 = p2 + (sigma / vbar).powi(2) + lift_h;
        let m12 = x_alpha * p2 + lift_a;
        let m21 = x_alpha * p2 - mom_h;
        let m22 = r2 * p2 + r2 / (vbar * vbar) - mom_a;
        Some(m11 * m22 - m12 * m21)
    }

    /// The root near `guess` at V̄.
    fn root(&self, guess: Complex64, vbar: f64) -> Complex64 {
        let nudge = guess * Complex64::new(1.0 + 1e-6, 1e-6);
        secant(|p| self.det(p, vbar), (guess, nudge), 1e-15, 100).expect("a root")
    }
}

fn fixture() -> serde_json::Value {
    serde_json::from_str(FIXTURE).unwrap()
}

fn section(v: &serde_json::Value) -> Section {
    let f = |k: &str| v["parameters"][k].as_f64().unwrap();
    Section {
        a: f("a"),
        x_alpha: f("x_alpha"),
        r2: f("r2"),
        sigma: f("sigma"),
        mu: f("mu"),
    }
}

/// Both branches followed from the structural frequencies (p̄ = iω b/V) at
/// V̄ = 0.5 in steps of 0.025, as the script follows them, and compared at
/// each V̄ it tabulates: within 1e-10 of |p̄|.
#[test]
fn the_roots_at_their_own_frequency_are_the_exact_ones() {
    let v = fixture();
    let s = section(&v);
    let table = v["roots_p_by_vbar"].as_object().unwrap();
    let mut roots = [
        Complex64::new(0.0, s.sigma / 0.5),
        Complex64::new(0.0, 1.0 / 0.5),
    ];
    let mut compared = 0;
    for k in 0..77 {
        let vbar = 0.5 + 0.025 * k as f64;
        roots = roots.map(|g| s.root(g, vbar));
        let tabulated = table
            .iter()
            .find(|(key, _)| (key.parse::<f64>().unwrap() - vbar).abs() < 1e-9);
        let Some((_, want)) = tabulated else {
            continue;
        };
        for (branch, got) in roots.iter().enumerate() {
            let w = &want[branch];
            let want = Complex64::new(w[0].as_f64().unwrap(), w[1].as_f64().unwrap());
            assert!(
                (got - want).norm() <= 1e-10 * want.norm(),
                "V̄ {vbar} branch {branch}: {got} against {want}"
            );
        }
        compared += 1;
    }
    assert_eq!(compared, table.len(), "every tabulated V̄ compared");
}

/// The flutter point: where the pitch branch's root crosses the imaginary
/// axis (secant in V̄ on Re p̄), at the script's V̄ and k (both routes'),
/// within 1e-9.
#[test]
fn the_root_crosses_the_axis_at_the_classical_flutter_point() {
    let v = fixture();
    let s = section(&v);
    let flutter = &v["flutter"];
    let (want_v, want_k) = (
        flutter["vbar_by_k_method"].as_f64().unwrap(),
        flutter["k"].as_f64().unwrap(),
    );
    // the pitch branch, followed to V̄ = 2.15 (stable there)
    let mut pitch = Complex64::new(0.0, 1.0 / 0.5);
    for k in 0..=66 {
        pitch = s.root(pitch, 0.5 + 0.025 * k as f64);
    }
    assert!(pitch.re < 0.0);
    let start = pitch;
    let crossing = |vbar: Complex64| Some(Complex64::new(s.root(start, vbar.re).re, 0.0));
    let vf = secant(
        crossing,
        (Complex64::new(2.15, 0.0), Complex64::new(2.2, 0.0)),
        1e-14,
        60,
    )
    .expect("the crossing")
    .re;
    let at = s.root(start, vf);
    assert!(
        (vf - want_v).abs() <= 1e-9 * want_v,
        "V̄_F {vf} against {want_v}"
    );
    assert!(
        (at.im - want_k).abs() <= 1e-9 * want_k,
        "k {} against {want_k}",
        at.im
    );
    assert!(at.re.abs() <= 1e-10, "{at}");
}
