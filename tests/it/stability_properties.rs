//! Properties of the analysis over random derivative sets (proptest):
//! Routh's test (§4) agrees with the signs of the roots' real parts; every
//! root satisfies the quartic; the sensitivities dλ/dp agree with finite
//! differences; the state-space form of eqs (2) has the quartic's roots.

use nalgebra::DMatrix;
use num_complex::Complex64;
use proptest::prelude::*;
use stability_core::analysis::Analysis;
use stability_core::design::examples::tailless_delta_45;
use stability_core::dynamics::modes::ModeName;
use stability_core::dynamics::response::{Simplifications, StateSpace};
use stability_core::dynamics::sensitivity::{mode_sensitivities, root_sensitivities};
use stability_core::{Derivatives, Quartic, QuarticGradient};
use workspace_tests::{SplitMix64, random_derivatives};

fn derivatives_strategy() -> impl Strategy<Value = Derivatives> {
    any::<u64>().prop_map(|seed| random_derivatives(&mut SplitMix64(seed)))
}

/// |P(λ)| / Σ|cₖ||λ|^(4−k): the backward error of a root.
fn relative_residual(q: &Quartic, z: Complex64) -> f64 {
    let n = z.norm();
    let scale = q.to_array().iter().fold(0.0, |acc, c| acc * n + c.abs());
    q.eval(z).norm() / scale
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn routh_agrees_with_the_roots(d in derivatives_strategy()) {
        let Ok(a) = Analysis::of(&d) else { return Ok(()) };
        let max_re = a.roots.iter().map(|z| z.re).fold(f64::NEG_INFINITY, f64::max);
        // Skip the marginal cases where rounding decides (a root on the axis).
        let scale = a.roots.iter().map(|z| z.norm()).fold(0.0, f64::max);
        prop_assume!(max_re.abs() > 1e-9 * scale.max(1e-300));
        prop_assert_eq!(a.routh.stable, max_re < 0.0, "R = {}, roots {:?}", a.routh.discriminant, a.roots);
    }

    #[test]
    fn every_root_satisfies_the_quartic(d in derivatives_strategy()) {
        let Ok(a) = Analysis::of(&d) else { return Ok(()) };
        for z in a.roots {
            prop_assert!(z.re.is_finite() && z.im.is_finite());
            let r = relative_residual(&a.quartic, z);
            prop_assert!(r <= 1e-12, "residual {r:e} at {z}");
        }
        // and the modes account for all four roots
        let n: usize = a.modes.iter().map(|m| if m.im > 0.0 { 2 } else { 1 }).sum();
        prop_assert_eq!(n, 4);
    }

    #[test]
    fn the_state_space_form_has_the_quartics_roots(d in derivatives_strategy()) {
        let Ok(a) = Analysis::of(&d) else { return Ok(()) };
        let ss = StateSpace::new(&d, Simplifications::default()).expect("state space");
        let ev = DMatrix::from(ss.a.clone()).complex_eigenvalues();
        // Match each quartic root to the nearest eigenvalue.
        let scale = a.roots.iter().map(|z| z.norm()).fold(0.0, f64::max);
        for z in a.roots {
            let nearest = ev.iter().map(|e| (e - z).norm()).fold(f64::INFINITY, f64::min);
            prop_assert!(nearest <= 1e-6 * scale, "root {z} vs eigenvalues {ev:?}");
        }
    }
}

/// dλ/dp from the generated gradient against central differences of the
/// roots themselves, for every input, on the short period and the phugoid.
#[test]
fn sensitivities_agree_with_finite_differences() {
    let mut rng = SplitMix64(99);
    let mut checked = 0;
    while checked < 40 {
        let d = random_derivatives(&mut rng);
        let Ok(a) = Analysis::of(&d) else { continue };
        let q = a.quartic;
        let g = QuarticGradient::of(&d);
        for &lam in a.roots.iter().filter(|z| z.im >= 0.0) {
            let Some(dl) = root_sensitivities(&q, &g, lam) else {
                continue;
            };
            let values = d.quartic_input_values();
            for i in 0..15 {
                let h = 1e-6 * values[i].abs().max(1e-3);
                let shifted = |sign: f64| {
                    let mut v = values;
                    v[i] += sign * h;
                    let a = Analysis::of(&Derivatives::from_quartic_input_values(v)).ok()?;
                    // the root of the shifted quartic nearest λ
                    a.roots
                        .iter()
                        .copied()
                        .min_by(|x, y| (x - lam).norm().total_cmp(&(y - lam).norm()))
                };
                let (Some(up), Some(down)) = (shifted(1.0), shifted(-1.0)) else {
                    continue;
                };
                let fd = (up - down) / (2.0 * h);
                let tol = 1e-4 * (dl[i].norm() + lam.norm() / values[i].abs().max(1e-3) * 1e-3);
                assert!(
                    (fd - dl[i]).norm() <= tol.max(1e-7 * lam.norm()),
                    "∂λ/∂{} at λ = {lam}: analytic {} vs finite difference {fd}",
                    Derivatives::QUARTIC_INPUTS[i],
                    dl[i]
                );
            }
        }
        checked += 1;
    }
}

/// The report's question: what drives the short period's damping? For a
/// tailless delta the damping-in-pitch derivatives and z_w must rank high;
/// x_u and the phugoid-only terms must not.
#[test]
fn the_short_period_damping_is_driven_by_m_q_and_z_w() {
    let d = tailless_delta_45();
    let a = Analysis::of(&d).expect("analysis");
    let sp = a
        .modes
        .iter()
        .find(|m| m.name == ModeName::ShortPeriod)
        .expect("short period");
    let s = mode_sensitivities(&d, sp).expect("simple root");
    let top: Vec<&str> = s.iter().take(4).map(|x| x.input).collect();
    assert!(
        top.contains(&"m_q") && top.contains(&"z_w") && top.contains(&"i_b"),
        "{top:?}"
    );
    // By hand, from the short-period approximation: r ≈ −B/2 = (z_w + m_θ̇/i_B)/2,
    // so ∂r/∂m_q ≈ 1/(2 i_B) = 6.25 and ∂r/∂z_w ≈ 0.5.
    let by = |n: &str| s.iter().find(|x| x.input == n).expect(n);
    assert!(
        (by("m_q").d_re - 6.25).abs() < 0.1 * 6.25,
        "{}",
        by("m_q").d_re
    );
    assert!((by("z_w").d_re - 0.5).abs() < 0.1, "{}", by("z_w").d_re);
}
