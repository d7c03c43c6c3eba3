//! The supersonic-edge theory (stability_core::aerodynamics::supersonic) against its
//! independent routes: the direct source integral at every receiver
//! (`supersonic::source`), the closed forms (the true delta's strip
//! integrals, the cropped delta's lift slope), the limits — eq (36) at the
//! sonic leading edge, Ackeret's two-dimensional plate at large aspect
//! ratio — and the exact two-dimensional oscillatory theory.

use stability_core::aerodynamics::damping::mangler_k;
use stability_core::aerodynamics::supersonic::{
    self, Derivatives, EdgeRegime, PotentialIntegrals, SupersonicError, Wing, evvard, source,
    strip, transonic, wave_drag,
};
use std::f64::consts::PI;

fn wing(deg: f64, taper: f64) -> Wing {
    Wing::new(deg.to_radians(), taper).unwrap()
}

/// The Mach number at which β cot Λ = m.
fn mach_at(w: &Wing, m: f64) -> f64 {
    (1.0 + (m / w.cot()).powi(2)).sqrt()
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / (1.0 + b.abs())
}

fn worst(a: &Derivatives, b: &Derivatives) -> f64 {
    [
        rel(a.lift_slope, b.lift_slope),
        rel(a.aerodynamic_centre, b.aerodynamic_centre),
        rel(a.damping.z_q, b.damping.z_q),
        rel(a.damping.z_wdot, b.damping.z_wdot),
        rel(a.damping.m_q, b.damping.m_q),
        rel(a.damping.m_wdot, b.damping.m_wdot),
    ]
    .into_iter()
    .fold(0.0, f64::max)
}

fn fields(p: &PotentialIntegrals) -> [f64; 7] {
    [p.te0, p.te1, p.ar0, p.ar1, p.arx0, p.te_f, p.ar_f]
}

#[test]
fn true_delta_direct_source_integral_gives_the_strip_closed_form() {
    let mut max: f64 = 0.0;
    for (deg, m) in [(45.0, 1.0), (60.0, 1.3), (45.0, 2.5)] {
        let w = wing(deg, 0.0);
        let mach = mach_at(&w, m);
        let direct = source::integrals(&w, mach, 1e-10);
        let closed = strip::strip_integrals(&w, mach);
        for (a, b) in fields(&direct).into_iter().zip(fields(&closed)) {
            max = max.max(rel(a, b));
        }
        for h in [0.0, 0.25, 0.6] {
            let e = worst(
                &direct.derivatives(&w, mach, h),
                &strip::true_delta(mach, h),
            );
            max = max.max(e);
        }
    }
    println!("true delta: direct route vs closed form, worst relative error {max:.2e}");
    assert!(max < 1e-7, "{max}");
}

#[test]
fn cropped_delta_evvard_weights_against_the_direct_source_integral() {
    let mut max: f64 = 0.0;
    for (deg, taper, m) in [
        (45.0, 1.0 / 7.0, 1.0),
        (45.0, 1.0 / 7.0, 1.6),
        (60.0, 0.3, 1.2),
        (30.0, 0.5, 3.0),
        (45.0, 0.6, 1.5),
    ] {
        let w = wing(deg, taper);
        let mach = mach_at(&w, m);
        let a = evvard::integrals(&w, mach).unwrap();
        let b = source::integrals(&w, mach, 1e-10);
        for (x, y) in fields(&a).into_iter().zip(fields(&b)) {
            max = max.max(rel(x, y));
        }
        for h in [0.0, 0.25, 0.6] {
            max = max.max(worst(
                &a.derivatives(&w, mach, h),
                &b.derivatives(&w, mach, h),
            ));
        }
    }
    println!("cropped deltas: Evvard weights vs direct source integral, worst {max:.2e}");
    assert!(max < 1e-7, "{max}");
}

#[test]
fn cropped_delta_lift_slope_closed_form() {
    // βs ≥ c₀: the tip's reach stays on its own half-wing
    for (deg, taper, m) in [(45.0, 1.0 / 7.0, 2.0), (30.0, 0.5, 3.0), (20.0, 0.25, 1.8)] {
        let w = wing(deg, taper);
        let mach = mach_at(&w, m);
        let closed = evvard::lift_slope_closed(&w, mach).expect("in range");
        let a = supersonic::supersonic_edge(&w, mach, 0.25)
            .unwrap()
            .lift_slope;
        let b = source::integrals(&w, mach, 1e-10)
            .derivatives(&w, mach, 0.25)
            .lift_slope;
        println!(
            "{deg}° λ = {taper:.3} m = {m}: closed {closed:.10} weights {a:.10} direct {b:.10}"
        );
        assert!(rel(a, closed) < 1e-10 && rel(b, closed) < 1e-8);
        assert!(closed < 4.0 / (mach * mach - 1.0).sqrt());
    }
    // the rectangular wing's (4/β)(1 − 1/(2βA)) as λ → 1 with m → ∞
    let w = wing(0.05, 0.999);
    let mach = 1.5;
    let beta = (mach * mach - 1.0f64).sqrt();
    let rect = 4.0 / beta * (1.0 - 1.0 / (2.0 * beta * w.aspect_ratio()));
    let closed = evvard::lift_slope_closed(&w, mach).unwrap();
    assert!(rel(closed, rect) < 2e-3, "{closed} vs {rect}");
}

#[test]
fn continuous_with_eq36_at_the_sonic_leading_edge() {
    // (36) with its own lift slope and aerodynamic centre, evaluated at the
    // sonic edge itself (E = π/2, H = ⅔ by Fig 18's series), against the
    // supersonic-edge theory at the same Mach number: every output
    let mut at_edge: f64 = 0.0;
    for deg in [45.0, 60.0, 70.0] {
        let w = wing(deg, 0.0);
        let sonic = w.sonic_mach();
        for h in [0.0, 0.25, 0.5, 0.8] {
            let eq36 = supersonic::eq36_with_own_aero(&w, sonic, h);
            let edge = supersonic::supersonic_edge(&w, sonic, h).unwrap();
            at_edge = at_edge.max(worst(&eq36, &edge));
            let chosen = supersonic::edge_theory(&w, sonic, h).unwrap();
            assert_eq!(chosen.regime, EdgeRegime::SonicEdge);
            assert!(worst(&chosen.derivatives, &edge) < 1e-15);
        }
    }
    println!(
        "sonic edge: (36) vs supersonic-edge theory at the same M, worst relative difference {at_edge:.2e}"
    );
    assert!(at_edge < 1e-12, "{at_edge}");
    // one-sided limits: the jump across M_sonic(1 ± ε) vanishes with ε
    let w = wing(45.0, 0.0);
    let jump = |eps: f64| {
        let s = w.sonic_mach();
        let below = supersonic::eq36_with_own_aero(&w, s * (1.0 - eps), 0.25);
        let above = supersonic::supersonic_edge(&w, s * (1.0 + eps), 0.25).unwrap();
        worst(&below, &above)
    };
    let (j6, j8) = (jump(1e-6), jump(1e-8));
    println!("jump across M_sonic(1 ± ε): ε = 1e-6: {j6:.2e}, ε = 1e-8: {j8:.2e}");
    assert!(j8 < j6 / 50.0 && j8 < 1e-6, "{j6} {j8}");
    // the 60° delta at exactly M = 2 (β cot Λ computes to 1.0000000000000002)
    let w = wing(60.0, 0.0);
    let r = supersonic::edge_theory(&w, 2.0, 0.25).unwrap();
    assert_eq!(r.regime, EdgeRegime::SonicEdge);
    assert!(rel(r.derivatives.lift_slope, 4.0 / 3f64.sqrt()) < 1e-12);
    // and the choice follows β cot Λ either side
    assert_eq!(
        supersonic::edge_theory(&w, 1.9, 0.25).unwrap().regime,
        EdgeRegime::SubsonicEdge
    );
    assert_eq!(
        supersonic::edge_theory(&w, 2.1, 0.25).unwrap().regime,
        EdgeRegime::SupersonicEdge
    );
}

#[test]
fn tends_to_ackeret_at_large_aspect_ratio() {
    // cropped delta, λ = 0.5, Λ → 0: every derivative → its strip integral
    // of the two-dimensional plate, the difference falling like 1/(βA)
    let mach = 1.5;
    let mut last = f64::INFINITY;
    for deg in [30.0, 10.0, 2.0] {
        let w = wing(deg, 0.5);
        let theory = supersonic::supersonic_edge(&w, mach, 0.25).unwrap();
        let strips = strip::strip_integrals(&w, mach).derivatives(&w, mach, 0.25);
        let e = worst(&theory, &strips);
        println!(
            "Λ = {deg}°, A = {:.1}: relative departure from strip theory {e:.2e}",
            w.aspect_ratio()
        );
        assert!(e < last);
        last = e;
    }
    assert!(last < 5e-3, "{last}");
    // nearly rectangular (λ → 1, A large): Ackeret's plate itself, with
    // a = 4/β, H₀ = ½, z_ẇ = 2/β³ (per chord; here c̄ → c₀)
    let w = wing(0.01, 0.99);
    let d = supersonic::supersonic_edge(&w, mach, 0.3).unwrap();
    let two_d = strip::two_dimensional(mach, 0.3);
    let e = worst(&d, &two_d);
    println!(
        "λ = 0.99, A = {:.0}: departure from the two-dimensional plate {e:.2e}",
        w.aspect_ratio()
    );
    assert!(e < 1e-2, "{e}");
}

/// The exact two-dimensional oscillating plate (Garrick & Rubinow, NACA
/// Rep. 846): Φ(x) = −(1/β) ∫₀ˣ w e^{−iλ(x−ξ)} J₀(μ(x − ξ)) dξ, λ = ωM²/β²,
/// μ = ωM/β² (V = c = 1), plunging with w = −1: the complex lift and the
/// moment about the leading edge, ΔC_p = 4(iωΦ + Φ_x); Φ by the trapezoid
/// rule on half steps, the chord by the midpoint rule, J₀ by its integral.
fn exact_plate(mach: f64, omega: f64) -> (f64, f64, f64, f64) {
    let b2 = mach * mach - 1.0;
    let (lam, mu) = (omega * mach * mach / b2, omega * mach / b2);
    let j0 = |z: f64| {
        (0..200)
            .map(|k| (((k as f64 + 0.5) * PI / 200.0).sin() * z).cos())
            .sum::<f64>()
            / 200.0
    };
    let beta = b2.sqrt();
    let kern = |x: f64| {
        let (a, j) = (-lam * x, j0(mu * x) / beta);
        (a.cos() * j, a.sin() * j)
    };
    let n = 400;
    let dx = 1.0 / n as f64;
    let (mut l, mut mo, mut phi) = ((0.0, 0.0), (0.0, 0.0), (0.0, 0.0));
    let step = |phi: &mut (f64, f64), a: (f64, f64), b: (f64, f64)| {
        phi.0 += 0.25 * dx * (a.0 + b.0);
        phi.1 += 0.25 * dx * (a.1 + b.1);
    };
    for i in 0..n {
        let x = (i as f64 + 0.5) * dx;
        let k = kern(x);
        step(&mut phi, kern(x - 0.5 * dx), k);
        let dcp = (4.0 * (k.0 - omega * phi.1), 4.0 * (k.1 + omega * phi.0));
        l = (l.0 + dcp.0 * dx, l.1 + dcp.1 * dx);
        mo = (mo.0 - dcp.0 * x * dx, mo.1 - dcp.1 * x * dx);
        step(&mut phi, k, kern(x + 0.5 * dx));
    }
    (l.0, l.1, mo.0, mo.1)
}

#[test]
fn the_low_frequency_limit_is_where_the_exact_plate_says() {
    // at κ = ωcM²/β² = LOW_FREQUENCY_LIMIT the first-order damping lift is
    // within 5 % and the moment about mid-chord within 9 % of the exact
    // oscillatory plate, whatever the Mach number
    for mach in [1.1, 1.5, 2.0] {
        let b2 = mach * mach - 1.0f64;
        let omega = transonic::LOW_FREQUENCY_LIMIT * b2 / (mach * mach);
        let (_, li, _, mi) = exact_plate(mach, omega);
        let d = strip::two_dimensional(mach, 0.0).damping;
        let lift = -li / omega / d.z_wdot;
        let mid = (mi + 0.5 * li) / omega / (d.m_wdot - 0.5 * d.z_wdot);
        println!(
            "M = {mach}, κ = 0.5: damping lift {lift:.4}, moment about mid-chord {mid:.4} of first order"
        );
        assert!((0.95..1.0).contains(&lift), "{lift}");
        assert!((0.91..1.0).contains(&mid), "{mid}");
    }
}

#[test]
fn two_dimensional_acceleration_derivatives_are_the_exact_theory_at_low_frequency() {
    // the quadrature part of the exact lift and moment, divided by ω, at
    // ω → 0 is −∂C_L/∂(α̇c/V) = z_ẇ and m_ẇ about the leading edge
    for mach in [1.2, 1.5, 2.5] {
        let omega = 1e-3;
        let (_, li, _, mi) = exact_plate(mach, omega);
        let d = strip::two_dimensional(mach, 0.0).damping;
        println!(
            "M = {mach}: −Im C_L/ω = {:.6} (z_ẇ = {:.6}), Im C_m/ω = {:.6} (m_ẇ = {:.6})",
            -li / omega,
            d.z_wdot,
            mi / omega,
            d.m_wdot
        );
        assert!(rel(-li / omega, d.z_wdot) < 1e-3);
        assert!(rel(mi / omega, d.m_wdot) < 1e-3);
        // Garrick & Rubinow's pitch damping about the leading edge
        let beta = (mach * mach - 1.0f64).sqrt();
        let m_theta = d.m_q + d.m_wdot;
        assert!(
            rel(
                m_theta,
                -4.0 / (3.0 * beta) * (mach * mach - 2.0) / (mach * mach - 1.0)
            ) < 1e-14
        );
    }
}

#[test]
fn eq36_acceleration_derivatives_grow_like_ln_one_over_beta() {
    let w = wing(45.0, 0.0);
    let mut prev = 0.0;
    for beta in [1e-2, 1e-3, 1e-4] {
        let mach = (1.0f64 + beta * beta).sqrt();
        let z = supersonic::eq36_with_own_aero(&w, mach, 0.25)
            .damping
            .z_wdot;
        let asym = transonic::z_wdot_eq36_near_sonic(&w, mach);
        println!("β = {beta:e}: (36) z_ẇ = {z:.6}, asymptote {asym:.6}");
        assert!(
            (z - asym).abs() < 200.0 * beta * beta * (1.0 / beta).ln() + 1e-9,
            "{z} vs {asym}"
        );
        // each decade of β adds 3 cot²Λ ln 10 · πA/4 = 3π ln 10 (A = 4)
        if prev != 0.0 {
            assert!(rel(z - prev, 3.0 * PI * 10f64.ln()) < 5e-3);
        }
        prev = z;
    }
}

#[test]
fn the_transonic_rule() {
    let w = wing(45.0, 0.0);
    for omega in [0.05, 0.1, 0.2] {
        let m_star = transonic::validity_mach(&w, omega).unwrap();
        let at = transonic::eq36_validity(&w, m_star, omega).unwrap();
        assert!((at.kappa - transonic::LOW_FREQUENCY_LIMIT).abs() < 1e-12);
        assert!(
            transonic::eq36_validity(&w, m_star * 1.01, omega)
                .unwrap()
                .valid
        );
        assert!(
            !transonic::eq36_validity(&w, m_star * 0.99, omega)
                .unwrap()
                .valid
        );
        let m_match = transonic::matching_mach(omega).unwrap();
        assert!(m_match < m_star);
        println!(
            "ω̄ = {omega}: (36) valid above M = {m_star:.4}; matches Mangler at M = {m_match:.4}"
        );
    }
    // at the matching point (36)'s near-sonic z_ẇ is Mangler's (39)–(40)
    for deg in [45.0, 60.0] {
        let w = wing(deg, 0.0);
        let omega = 0.02;
        let m = transonic::matching_mach(omega).unwrap();
        let (k, _) = mangler_k(omega, w.sweep_le);
        let mangler = -PI * w.aspect_ratio() / 4.0 * k;
        assert!(rel(transonic::z_wdot_eq36_near_sonic(&w, m), mangler) < 1e-6);
    }
    // ω̄c₀/c̄ at or above the limit: no Mach number will do
    assert!(matches!(
        transonic::validity_mach(&w, 0.4),
        Err(SupersonicError::FrequencyTooHigh { .. })
    ));
    assert!(matches!(
        transonic::eq36_validity(&w, 1.5, -1.0),
        Err(SupersonicError::Frequency(_))
    ));
}

#[test]
fn errors_are_typed() {
    let w = wing(45.0, 0.0);
    assert!(matches!(
        supersonic::supersonic_edge(&w, 1.2, 0.25),
        Err(SupersonicError::SubsonicLeadingEdge { .. })
    ));
    assert!(matches!(
        supersonic::edge_theory(&w, 1.0, 0.25),
        Err(SupersonicError::SubsonicMach(_))
    ));
    assert!(matches!(
        supersonic::edge_theory(&w, f64::NAN, 0.25),
        Err(SupersonicError::Invalid(_))
    ));
    assert!(matches!(
        Wing::new(0.0, 0.0),
        Err(SupersonicError::Sweep(_))
    ));
    assert!(matches!(
        Wing::new(0.5, 1.0),
        Err(SupersonicError::Taper(_))
    ));
    // 2βs < c₀: one reflection per tip is not enough
    let w = wing(45.0, 0.9);
    assert!(matches!(
        supersonic::supersonic_edge(&w, 2f64.sqrt(), 0.25),
        Err(SupersonicError::TipsInteract { limit: 1.0, .. })
    ));
    // subsonic edges, 2βs < c_t: a tip's Mach wave reaches the other tip
    // ahead of the trailing edge (60°, λ = 0.5: 2βs = 0.38 at M = 1.2)
    let w = wing(60.0, 0.5);
    let e = supersonic::edge_theory(&w, 1.2, 0.25).unwrap_err();
    assert!(
        matches!(e, SupersonicError::TipsInteract { limit: 0.5, .. }),
        "{e:?}"
    );
    assert!(e.to_string().contains("< 0.5"), "{e}");
    assert!(supersonic::edge_theory(&w, 1.4, 0.25).is_ok());
}

#[test]
fn wave_drag_limits_and_the_existing_blend() {
    let f = wave_drag::NOTE_RIDGE;
    let two_d = 1.0 / (f * (1.0 - f));
    let far = wave_drag::scaled_wave_drag(40.0, f).unwrap();
    println!("m = 40: C_D β/τ² = {far:.4} (two-dimensional {two_d:.4})");
    assert!(rel(far, two_d) < 0.05);
    // slender limit: an unswept trailing edge closes the area distribution
    // with S′(c₀) ≠ 0, and slender-body theory's drag grows like
    // (S′(c₀)²/2π) ln(1/(β·span)): C_D β/τ² ≈ m[a + (2/(π(1 − f)²)) ln(1/m)]
    assert!(matches!(
        wave_drag::scaled_wave_drag(1.0, 1.0),
        Err(SupersonicError::Ridge(_))
    ));
    // C_Dw itself: (τ²/β)·F at τ = 0.06, the 45° delta at M = √2 (m = 1)
    let cdw = wave_drag::wave_drag(PI / 4.0, 2f64.sqrt()).unwrap();
    assert!(rel(cdw, 0.0036 * wave_drag::scaled_wave_drag(1.0, f).unwrap()) < 1e-9);
    let g = |m: f64| wave_drag::scaled_wave_drag(m, f).unwrap() / m;
    let slope = (g(0.003125) - g(0.00625)) / 2f64.ln();
    let slender = 2.0 / (PI * (1.0 - f) * (1.0 - f));
    println!("slender ln(1/m) coefficient {slope:.4} (slender-body theory {slender:.4})");
    assert!(rel(slope, slender) < 0.02, "{slope} vs {slender}");
    for m in [0.3, 0.6, 0.9, 1.2, 2.0, 4.0] {
        let t = wave_drag::scaled_wave_drag(m, f).unwrap();
        println!(
            "m = {m}: linear theory {t:.4}, blend (biconvex) {:.4}",
            16.0 / 3.0 * m / (1.0 + m * m).sqrt()
        );
    }
}

#[test]
fn a_shift_of_the_pitch_axis_obeys_the_kinematics() {
    // about h rather than 0 (lengths in c̄): z_q(h) = z_q(0) − h z_w,
    // m_q(h) = m_q(0) − h(z_q(0) + m_w(0)) + h² z_w, m_ẇ(h) = m_ẇ(0) − h z_ẇ,
    // with z_w = −a and m_w(0) = −aH₀ — the assembly of the derivatives
    // checked apart from the integrals
    let w = wing(45.0, 1.0 / 7.0);
    let mach = 1.8;
    let d0 = supersonic::supersonic_edge(&w, mach, 0.0).unwrap();
    let a = d0.lift_slope;
    let (zq0, mq0, mw0) = (d0.damping.z_q, d0.damping.m_q, -a * d0.aerodynamic_centre);
    for h in [0.3, 0.7] {
        let d = supersonic::supersonic_edge(&w, mach, h).unwrap();
        assert!(rel(d.damping.z_q, zq0 + h * a) < 1e-13);
        assert!(rel(d.damping.m_q, mq0 - h * (zq0 + mw0) - h * h * a) < 1e-13);
        assert!(rel(d.damping.m_wdot, d0.damping.m_wdot - h * d0.damping.z_wdot) < 1e-13);
        assert_eq!(d.damping.z_wdot, d0.damping.z_wdot);
        assert_eq!(d.aerodynamic_centre, d0.aerodynamic_centre);
    }
    // the tips move the aerodynamic centre forward of the true delta's ½
    assert!(
        d0.aerodynamic_centre < 0.5 && d0.aerodynamic_centre > 0.4,
        "{}",
        d0.aerodynamic_centre
    );
}

/// The Mach derivative of `f` by the five-point rule, central or (where
/// `forward`) one-sided.
fn five_point(f: impl Fn(f64) -> f64, m: f64, h: f64, forward: bool) -> f64 {
    if forward {
        let y: Vec<f64> = (0..5).map(|k| f(m + k as f64 * h)).collect();
        (-25.0 * y[0] + 48.0 * y[1] - 36.0 * y[2] + 16.0 * y[3] - 3.0 * y[4]) / (12.0 * h)
    } else {
        (f(m - 2.0 * h) - 8.0 * f(m - h) + 8.0 * f(m + h) - f(m + 2.0 * h)) / (12.0 * h)
    }
}

/// The Mach derivatives of `f` by the five-point rule at h and h/2 and
/// Richardson's extrapolation, (16D(h/2) − D(h))/15, which removes the
/// rule's h⁴ term (nine evaluations).
fn richardson(f: impl Fn(f64) -> [f64; 2], m: f64, h: f64, forward: bool) -> [f64; 2] {
    let offsets: Vec<i32> = if forward {
        (0..9).collect()
    } else {
        (-4..=4).collect()
    };
    let pts: Vec<[f64; 2]> = offsets
        .iter()
        .map(|&k| f(m + f64::from(k) * h / 2.0))
        .collect();
    let at = |j: i32, i: usize| pts[(j - offsets[0]) as usize][i];
    std::array::from_fn(|i| {
        let rule = |s: i32, hh: f64| {
            if forward {
                (-25.0 * at(0, i) + 48.0 * at(s, i) - 36.0 * at(2 * s, i) + 16.0 * at(3 * s, i)
                    - 3.0 * at(4 * s, i))
                    / (12.0 * hh)
            } else {
                (at(-2 * s, i) - 8.0 * at(-s, i) + 8.0 * at(s, i) - at(2 * s, i)) / (12.0 * hh)
            }
        };
        (16.0 * rule(1, h / 2.0) - rule(2, h)) / 15.0
    })
}

#[test]
fn edge_coefficients_are_edge_theorys_with_their_mach_derivatives() {
    // closed forms: (36)'s πA/(2E) and the true delta's 4/β, against a
    // central difference of edge_theory's own values
    let mut worst_d: f64 = 0.0;
    for deg in [45.0, 60.0] {
        let w = wing(deg, 0.0);
        for m in [0.1, 0.5, 0.9, 0.999, 1.001, 1.5, 3.0] {
            let mach = mach_at(&w, m);
            let c = supersonic::edge_coefficients(&w, mach).unwrap();
            let t = supersonic::edge_theory(&w, mach, 0.25).unwrap().derivatives;
            assert_eq!(c.lift_slope.value, t.lift_slope);
            assert_eq!(c.aerodynamic_centre.value, t.aerodynamic_centre);
            let a = |x: f64| {
                supersonic::edge_theory(&w, x, 0.25)
                    .unwrap()
                    .derivatives
                    .lift_slope
            };
            let fd = five_point(a, mach, 1e-5 * (mach - 1.0).min(1e-1), false);
            worst_d = worst_d.max(rel(c.lift_slope.d_mach, fd));
            assert_eq!(c.aerodynamic_centre.d_mach, 0.0);
        }
    }
    println!("true deltas: da/dM against a central difference, worst {worst_d:.2e}");
    assert!(worst_d < 1e-7, "{worst_d}");
    // the kink at the sonic edge: da/dM = −2M/β³ below, −4M/β³ above
    let w = wing(45.0, 0.0);
    let s = w.sonic_mach();
    let below = supersonic::edge_coefficients(&w, s * (1.0 - 1e-9)).unwrap();
    let above = supersonic::edge_coefficients(&w, s * (1.0 + 1e-9)).unwrap();
    assert!(rel(below.lift_slope.d_mach, -2.0 * s) < 1e-6, "{below:?}");
    assert!(rel(above.lift_slope.d_mach, -4.0 * s) < 1e-6, "{above:?}");
}

#[test]
fn cropped_mach_derivatives_against_independent_routes() {
    // the lift slope: the closed form (βs ≥ c₀), differenced
    let mut worst_a: f64 = 0.0;
    for (deg, taper, mach) in [
        (45.0, 1.0 / 7.0, 2.0),
        (45.0, 1.0 / 7.0, 2.5),
        (30.0, 0.3, 2.0),
    ] {
        let w = wing(deg, taper);
        let c = supersonic::edge_coefficients(&w, mach).unwrap();
        let closed = |x: f64| evvard::lift_slope_closed(&w, x).unwrap();
        let fd = five_point(closed, mach, 1e-3, false);
        worst_a = worst_a.max(rel(c.lift_slope.d_mach, fd));
    }
    println!("cropped: da/dM against the closed form's, worst {worst_a:.2e}");
    assert!(worst_a < 1e-8, "{worst_a}");
    // both, against the direct source integral differenced (Richardson's
    // extrapolation of the five-point rule at h and h/2 removes its h⁴
    // term) — centrally inside the domain, one-sided at the sonic edge
    // (60°, M = 2); and the step: halving it moves the derivative by < 1e-9
    let mut worst: [f64; 3] = [0.0; 3];
    for (deg, taper, mach, forward) in [(45.0, 1.0 / 7.0, 1.5, false), (60.0, 1.0 / 7.0, 2.0, true)]
    {
        let w = wing(deg, taper);
        let c = supersonic::edge_coefficients(&w, mach).unwrap();
        assert_eq!(c.regime == EdgeRegime::SupersonicEdge, !forward);
        let direct = |x: f64| {
            let d = source::integrals(&w, x, 1e-10).derivatives(&w, x, 0.0);
            [d.lift_slope, d.aerodynamic_centre]
        };
        let [da, dh] = richardson(direct, mach, 1e-2, forward);
        println!(
            "{deg}° λ = {taper:.3} M = {mach}: da/dM {:.10} (direct {da:.10}), dH₀/dM {:.10} (direct {dh:.10})",
            c.lift_slope.d_mach, c.aerodynamic_centre.d_mach
        );
        worst[0] = worst[0].max(rel(c.lift_slope.d_mach, da));
        worst[1] = worst[1].max((c.aerodynamic_centre.d_mach - dh).abs());
        let ev = |x: f64| {
            supersonic::edge_coefficients(&w, x)
                .unwrap()
                .aerodynamic_centre
                .value
        };
        let halved = five_point(ev, mach, supersonic::coefficients::STEP / 2.0, forward);
        worst[2] = worst[2].max((c.aerodynamic_centre.d_mach - halved).abs());
    }
    println!(
        "cropped against the direct route: da/dM {:.2e} (relative), dH₀/dM {:.2e} (absolute); step halved: dH₀/dM moves {:.2e}",
        worst[0], worst[1], worst[2]
    );
    assert!(
        worst[0] < 1e-7 && worst[1] < 1e-7 && worst[2] < 1e-9,
        "{worst:?}"
    );
}

// ---------------------------------------------------------------------------
// The cropped delta with subsonic leading edges (issue 19, item 3): the
// true delta's potentials corrected behind the tips (`subsonic_edge`),
// continuous with the supersonic-edge theory at the sonic edge.

/// The wing's outline in characteristic coordinates U = x − βy, V = x + βy
/// (c₀ = 1), for the source solution of a potential sheet.
struct Outline {
    beta: f64,
    /// (1 − m)/(1 + m): the leading edges are U = ρV and V = ρU.
    rho: f64,
    /// βs (the tips are U = V − 2βs and U = V + 2βs).
    bs: f64,
    /// The right corner's Mach line V = v_corner, the left one's U = v_corner.
    v_corner: f64,
}

impl Outline {
    fn new(w: &Wing, mach: f64, cropped: bool) -> Outline {
        let beta = (mach * mach - 1.0).sqrt();
        let m = beta * w.cot();
        let bs = if cropped { beta * w.semi_span() } else { 1e6 };
        Outline {
            beta,
            rho: (1.0 - m) / (1.0 + m),
            bs,
            v_corner: if cropped { 1.0 - w.taper + bs } else { 2e6 },
        }
    }

    /// ψ(P) = −(1/π)∫∫ Φ dξ dη/R = −(2/(πβ))∫∫ Φ dσ dτ (U = U_P − σ²,
    /// V = V_P − τ²): the source solution of density Φ in the plane, so
    /// that φ = ψ_z has φ(z = 0⁺) = Φ everywhere and the downwash
    /// φ_z = ψ_zz = β²ψ_xx − ψ_yy = 4β²ψ_UV. Φ's support (the leading edges,
    /// the tips) and its kinks (the corners' Mach lines) split the ranges.
    fn psi(&self, phi: &dyn Fn(f64, f64) -> f64, up: f64, vp: f64) -> f64 {
        let (rho, bs) = (self.rho, self.bs);
        let lo = |v: f64| (v * rho).max(v - 2.0 * bs);
        let hi = |v: f64| up.min(v / rho).min(v + 2.0 * bs);
        let mut vb = vec![0.0, vp];
        for c in [self.v_corner, rho * up, up - 2.0 * bs] {
            if c > 0.0 && c < vp {
                vb.push(c);
            }
        }
        vb.sort_by(f64::total_cmp);
        let mut total = 0.0;
        for w in vb.windows(2) {
            let [part] = supersonic::quadrature::tanh_sinh(
                |tau| {
                    let v = vp - tau * tau;
                    let (a, b) = (lo(v), hi(v));
                    if b <= a {
                        return [0.0];
                    }
                    let mut sb = vec![(up - b).max(0.0).sqrt(), (up - a).sqrt()];
                    if self.v_corner > a && self.v_corner < b {
                        sb.insert(1, (up - self.v_corner).sqrt());
                    }
                    let mut acc = 0.0;
                    for s in sb.windows(2) {
                        let [p] = supersonic::quadrature::tanh_sinh(
                            |sig| [phi(up - sig * sig, v)],
                            s[0],
                            s[1],
                            10,
                        );
                        acc += p;
                    }
                    [acc]
                },
                (vp - w[1]).sqrt(),
                (vp - w[0]).sqrt(),
                10,
            );
            total += part;
        }
        -2.0 / (PI * self.beta) * total
    }

    /// The downwash 4β²ψ_UV at (x, y) of the sheet Φ(x, y), by the
    /// four-point mixed difference at steps h and h/2 and Richardson's
    /// extrapolation.
    fn downwash(&self, phi: &dyn Fn(f64, f64) -> f64, x: f64, y: f64, h: f64) -> f64 {
        let (u, v) = (x - self.beta * y, x + self.beta * y);
        let at = |u: f64, v: f64| {
            self.psi(
                &|uu, vv| phi(0.5 * (uu + vv), 0.5 * (vv - uu) / self.beta),
                u,
                v,
            )
        };
        let d = |h: f64| {
            (at(u + h, v + h) - at(u + h, v - h) - at(u - h, v + h) + at(u - h, v - h))
                / (4.0 * h * h)
        };
        4.0 * self.beta * self.beta * (4.0 * d(0.5 * h) - d(h)) / 3.0
    }
}

#[test]
fn the_true_deltas_subsonic_edge_potentials_satisfy_their_boundary_condition() {
    // Φ₀[1] = −r/E and Φ₀[x] = −G x r (r = √(x²cot²Λ − y²); Ribner &
    // Malvestuto's, eq (36)'s) must have the downwash 1 and x on the wing:
    // the sheet's downwash by its source solution, independently of (36)
    let mut worst_err: f64 = 0.0;
    for (deg, m) in [(45.0, 0.3), (45.0, 0.6), (60.0, 0.9)] {
        let w = wing(deg, 0.0);
        let mach = mach_at(&w, m);
        let f = supersonic::eq36::Fig18::at(m);
        let o = Outline::new(&w, mach, false);
        let cot = w.cot();
        let r = move |x: f64, y: f64| ((cot * x).powi(2) - y * y).max(0.0).sqrt();
        for (x, eta) in [(1.0, 0.0), (0.8, 0.5)] {
            let y = eta * cot * x;
            let one = o.downwash(&|x, y| -r(x, y) / f.e, x, y, 0.02);
            let lin = o.downwash(&|x, y| -f.g * x * r(x, y), x, y, 0.02);
            println!("{deg}°, m = {m}, ({x}, {y:.3}): w = {one:.9} (1), {lin:.9} ({x})");
            worst_err = worst_err.max((one - 1.0).abs()).max((lin - x).abs());
        }
    }
    println!("true delta, subsonic edges: worst downwash error {worst_err:.1e}");
    assert!(worst_err < 1e-6, "{worst_err}");
}

#[test]
fn the_cropped_deltas_subsonic_edge_potential_satisfies_its_boundary_condition() {
    // Behind a tip the potential is the true delta's corrected by Evvard's
    // theorem along the Mach line (subsonic_edge's module doc): its sheet's
    // downwash must still be 1 (and x) on the wing there
    let mut worst_err: f64 = 0.0;
    for (deg, taper, m) in [(45.0, 0.3, 0.7), (60.0, 1.0 / 7.0, 0.5), (55.0, 0.5, 0.9)] {
        let w = wing(deg, taper);
        let mach = mach_at(&w, m);
        let o = Outline::new(&w, mach, true);
        let pot = |i: usize| {
            move |x: f64, y: f64| supersonic::subsonic_edge::potentials(&w, mach, x, y).unwrap()[i]
        };
        // midway between the corner's Mach line and the tip, near the
        // trailing edge
        let x = 0.97;
        let y = w.semi_span() - 0.5 * (x - (1.0 - taper)) / o.beta;
        let one = o.downwash(&pot(0), x, y, 0.01);
        let lin = o.downwash(&pot(1), x, y, 0.01);
        println!(
            "{deg}°, λ = {taper:.3}, m = {m}, ({x}, {y:.4}) behind the tip: w = {one:.9} (1), {lin:.9} ({x})"
        );
        worst_err = worst_err.max((one - 1.0).abs()).max((lin - x).abs());
        // and the correction is not nothing there
        let delta = supersonic::subsonic_edge::potentials(&wing(deg, 0.0), mach, x, y).unwrap();
        assert!((pot(0)(x, y) - delta[0]).abs() > 1e-2 * delta[0].abs());
    }
    println!("cropped delta behind the tips: worst downwash error {worst_err:.1e}");
    assert!(worst_err < 1e-5, "{worst_err}");
}

const SWEEPS: [f64; 3] = [45.0, 55.0, 60.0];
const TAPERS: [f64; 4] = [0.0, 1.0 / 7.0, 0.3, 0.5];

#[test]
fn at_the_sonic_edge_the_subsonic_edge_route_is_evvards_and_the_source_integrals() {
    // At β cot Λ = 1 both theories apply: the subsonic-edge potentials are
    // the source integral in closed form there (E = π/2, G = 4/(3π)), and
    // the tips' corrections, taken along the Mach line, must be Evvard's
    // reduced area taken source by source (evvard) and receiver by receiver
    // (source) — all seven integrals
    let mut worst_ev: f64 = 0.0;
    let mut worst_src: f64 = 0.0;
    for deg in SWEEPS {
        for taper in &TAPERS[1..] {
            let w = wing(deg, *taper);
            let mach = mach_at(&w, 1.0);
            let sub = supersonic::subsonic_edge::integrals(&w, mach).unwrap();
            let ev = evvard::integrals(&w, mach).unwrap();
            for (x, y) in fields(&sub).into_iter().zip(fields(&ev)) {
                worst_ev = worst_ev.max(rel(x, y));
            }
            if deg == 55.0 {
                let src = source::integrals(&w, mach, 1e-11);
                for (x, y) in fields(&sub).into_iter().zip(fields(&src)) {
                    worst_src = worst_src.max(rel(x, y));
                }
            }
        }
    }
    println!(
        "sonic edge: subsonic-edge route vs Evvard's weights {worst_ev:.2e}, vs the direct source integral {worst_src:.2e}"
    );
    assert!(
        worst_ev < 1e-9 && worst_src < 1e-8,
        "{worst_ev} {worst_src}"
    );
}

/// The six outputs' largest jump across M_sonic(1 ± ε), c.g. at `h`.
fn sonic_jump(w: &Wing, eps: f64, h: f64) -> f64 {
    let s = w.sonic_mach();
    let below = supersonic::edge_theory(w, s * (1.0 - eps), h).unwrap();
    let above = supersonic::edge_theory(w, s * (1.0 + eps), h).unwrap();
    assert_eq!(below.regime, EdgeRegime::SubsonicEdge);
    assert_eq!(above.regime, EdgeRegime::SupersonicEdge);
    worst(&below.derivatives, &above.derivatives)
}

#[test]
fn every_taper_is_continuous_across_the_sonic_edge() {
    // The issue: 45°, λ = 1/7 jumped from (36)'s a = πA/(2E) = 3.00 to the
    // cropped wing's 3.72 at M = √2. Now the six outputs are continuous for
    // every taper — the jump is the slope's, 2εM times it, and shrinks with
    // ε — and at the edge they are the true delta's strip values less the
    // tips' (for λ = 0, exactly (36)'s and the strip values)
    for deg in SWEEPS {
        for taper in TAPERS {
            let w = wing(deg, taper);
            for h in [0.25, 0.6] {
                let (j6, j8) = (sonic_jump(&w, 1e-6, h), sonic_jump(&w, 1e-8, h));
                println!(
                    "{deg}°, λ = {taper:.3}, h = {h}: jump {j6:.2e} (ε = 1e-6), {j8:.2e} (ε = 1e-8)"
                );
                assert!(
                    j6 < 1e-4 && j8 < 1e-6 && j8 < j6 / 20.0,
                    "{deg} {taper}: {j6} {j8}"
                );
            }
        }
    }
    // the case, at the edge: the cropped wing's own values, below
    // the true delta's 4/β (and far from (36)'s 3.00 on the cropped A = 3)
    let w = wing(45.0, 1.0 / 7.0);
    let s = w.sonic_mach();
    let below = supersonic::edge_theory(&w, s * (1.0 - 1e-9), 0.25).unwrap();
    let ev = evvard::integrals(&w, s).unwrap().derivatives(&w, s, 0.25);
    assert!(worst(&below.derivatives, &ev) < 1e-8);
    assert!(below.derivatives.lift_slope > 3.7 && below.derivatives.lift_slope < 4.0);
}

#[test]
fn the_subsonic_edge_route_tends_to_the_true_delta_as_the_taper_vanishes() {
    // taper 0 through the cropped route is (36) (the true delta's
    // potentials integrated numerically against its closed forms); a small
    // taper differs from it by O(λ)
    for deg in SWEEPS {
        for m in [0.2, 0.6, 0.95] {
            let w0 = wing(deg, 0.0);
            let mach = mach_at(&w0, m);
            let eq36 = supersonic::eq36_with_own_aero(&w0, mach, 0.25);
            let route = supersonic::subsonic_edge::integrals(&w0, mach)
                .unwrap()
                .derivatives(&w0, mach, 0.25);
            assert!(worst(&route, &eq36) < 1e-10, "{deg} {m}");
            let mut last = f64::INFINITY;
            for taper in [1e-2, 1e-3, 1e-4] {
                let w = wing(deg, taper);
                let e = worst(
                    &supersonic::edge_theory(&w, mach, 0.25).unwrap().derivatives,
                    &eq36,
                );
                assert!(e < 30.0 * taper && e < last, "{deg} {m} {taper}: {e}");
                last = e;
            }
        }
    }
}

#[test]
fn cropped_subsonic_edge_mach_derivatives() {
    // a and H₀'s Mach derivatives on the subsonic side against a Richardson
    // extrapolated difference of edge_theory's values: centrally, and
    // backward at the sonic edge's subsonic side (the kink is not crossed)
    let mut worst_d: [f64; 2] = [0.0; 2];
    for (deg, taper, m) in [
        (45.0, 1.0 / 7.0, 0.7),
        (60.0, 0.3, 0.95),
        (55.0, 0.5, 0.999_999),
    ] {
        let w = wing(deg, taper);
        let mach = mach_at(&w, m);
        let c = supersonic::edge_coefficients(&w, mach).unwrap();
        assert_eq!(c.regime, EdgeRegime::SubsonicEdge);
        let values = |x: f64| {
            let d = supersonic::edge_theory(&w, x, 0.0).unwrap().derivatives;
            [d.lift_slope, d.aerodynamic_centre]
        };
        let backward = m > 0.99;
        let [da, dh] = if backward {
            // the forward rule on the mirrored function
            let [a, b] = richardson(|t| values(2.0 * mach - t), mach, 2e-3, true);
            [-a, -b]
        } else {
            richardson(values, mach, 1e-2, false)
        };
        println!(
            "{deg}° λ = {taper:.3} m = {m}: da/dM {:.8} ({da:.8}), dH₀/dM {:.8} ({dh:.8})",
            c.lift_slope.d_mach, c.aerodynamic_centre.d_mach
        );
        worst_d[0] = worst_d[0].max(rel(c.lift_slope.d_mach, da));
        worst_d[1] = worst_d[1].max((c.aerodynamic_centre.d_mach - dh).abs());
    }
    assert!(worst_d[0] < 1e-6 && worst_d[1] < 1e-6, "{worst_d:?}");
    // the kink: the slopes either side of the sonic edge differ
    let w = wing(45.0, 1.0 / 7.0);
    let s = w.sonic_mach();
    let below = supersonic::edge_coefficients(&w, s * (1.0 - 1e-9)).unwrap();
    let above = supersonic::edge_coefficients(&w, s * (1.0 + 1e-9)).unwrap();
    assert!((below.lift_slope.value - above.lift_slope.value).abs() < 1e-7);
    assert!((below.lift_slope.d_mach - above.lift_slope.d_mach).abs() > 0.1);
}
