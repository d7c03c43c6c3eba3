//! The doublet lattice (`stability_core::aerodynamics::lifting_surface`) against routes
//! independent of it: slender-wing theory (eq 37) as A → 0, the
//! two-dimensional flat plate (thin-aerofoil theory, Theodorsen's function
//! by mpmath) as A → ∞, the Prandtl–Glauert rule, the exact kernel by
//! quadrature as ω̄ → 0, the kinematics of moving the axis, and its own
//! errors. AVL, panelaero and the convergence table have their own files.

use serde_json::Value;
use stability_core::aerodynamics::lifting_surface::{
    Extrapolation, I1Approximation, Lattice, LatticeSpec, LiftingSurfaceError, Spacing,
};
use stability_core::geometry::{Planform, Size, Trapezoid};
use std::f64::consts::PI;

fn delta(aspect_ratio: f64) -> Trapezoid {
    Trapezoid::from_aspect_ratio(aspect_ratio, 0.0, (4.0 / aspect_ratio).atan(), 1.0).unwrap()
}

fn reference() -> Value {
    serde_json::from_str(include_str!("../data/lifting_surface/reference.json")).unwrap()
}

#[test]
fn the_slender_limit_is_eq_37() {
    // (37), Ribner: C_Lα = πA/2, H₀ = ½, z_ẇ = −πA/4, m_ẇ = z_ẇ(5/8 − h),
    // z_q = −(πA/2)(1 − h), m_q = −(πA/4)(2h² − 3h + 11/8). Each error on
    // the scale πA/4 must shrink with A and be small at A = 0.05.
    let mut previous = f64::INFINITY;
    for a in [0.4, 0.2, 0.1, 0.05] {
        let lattice = Lattice::new(&delta(a), LatticeSpec::default()).unwrap();
        let mut worst: f64 = 0.0;
        for mach in [0.0, 0.8] {
            let s = lattice.solve(mach, 0.0).unwrap();
            for h in [0.0, 0.25, 0.5] {
                let d = s.derivatives(h, 0.0).unwrap();
                let scale = PI * a / 4.0;
                let pairs = [
                    (d.lift_slope, PI * a / 2.0),
                    (d.aerodynamic_centre * scale, 0.5 * scale),
                    (d.z_wdot, -PI * a / 4.0),
                    (d.m_wdot, -PI * a / 4.0 * (5.0 / 8.0 - h)),
                    (d.z_q, -PI * a / 2.0 * (1.0 - h)),
                    (d.m_q, -PI * a / 4.0 * (2.0 * h * h - 3.0 * h + 11.0 / 8.0)),
                ];
                for (k, (lattice, slender)) in pairs.into_iter().enumerate() {
                    worst = worst.max((lattice - slender).abs() / scale);
                    assert!(
                        (lattice - slender).abs() < 0.8 * a * scale,
                        "A = {a}, M = {mach}, h = {h}, #{k}: {lattice} vs (37) {slender}"
                    );
                }
            }
        }
        assert!(worst < previous, "A = {a}: {worst} ≥ {previous}");
        previous = worst;
    }
    assert!(previous < 0.03, "{previous}");
}

/// X(A) = X∞ + a/A + b/A² through three aspect ratios: X∞.
fn extrapolate(a: [f64; 3], x: [f64; 3]) -> f64 {
    // Lagrange in t = 1/A, evaluated at t = 0
    let t = a.map(|v| 1.0 / v);
    let mut sum = 0.0;
    for i in 0..3 {
        let mut l = 1.0;
        for j in 0..3 {
            if j != i {
                l *= t[j] / (t[j] - t[i]);
            }
        }
        sum += l * x[i];
    }
    sum
}

#[test]
fn a_rectangle_of_large_aspect_ratio_tends_to_the_flat_plate() {
    // Thin-aerofoil theory about the quarter chord, with Prandtl–Glauert:
    // C_Lα = 2π/β, H₀ = ¼, z_q = −π/β (the ¾-chord point sees qc/2V),
    // m_q = −π/(8β) (the linear "camber" of the rotation).
    let aspect = [20.0, 40.0, 80.0];
    for mach in [0.0f64, 0.5] {
        let beta = f64::sqrt(1.0 - mach * mach);
        let mut rows = Vec::new();
        for a in aspect {
            let l = Lattice::new(
                &Trapezoid::rectangle(a, 1.0).unwrap(),
                LatticeSpec::default(),
            );
            rows.push(
                l.unwrap()
                    .solve(mach, 0.0)
                    .unwrap()
                    .derivatives(0.25, 0.0)
                    .unwrap(),
            );
        }
        let lim =
            |f: fn(
                &stability_core::aerodynamics::lifting_surface::LiftingSurfaceDerivatives,
            ) -> f64| { extrapolate(aspect, [f(&rows[0]), f(&rows[1]), f(&rows[2])]) };
        let a = lim(|d| d.lift_slope);
        assert!(
            (a * beta / (2.0 * PI) - 1.0).abs() < 0.012,
            "M {mach}: C_Lα → {a}"
        );
        let zq = lim(|d| d.z_q);
        assert!(
            (zq * beta / -PI - 1.0).abs() < 0.012,
            "M {mach}: z_q → {zq}"
        );
        let mq = lim(|d| d.m_q);
        assert!(
            (mq * 8.0 * beta / -PI - 1.0).abs() < 0.003,
            "M {mach}: m_q → {mq}"
        );
        // at A = 80 already: the centre at the quarter chord, and the ¾-chord
        // rule z_q = −C_Lα/2 about it
        let d = rows[2];
        assert!((d.aerodynamic_centre - 0.25).abs() < 0.002, "{d:?}");
        assert!((d.z_q / d.lift_slope + 0.5).abs() < 0.002, "{d:?}");
        // and every step in A moves towards the plate
        for w in rows.windows(2) {
            assert!(w[1].lift_slope > w[0].lift_slope && w[1].z_q < w[0].z_q);
        }
    }
}

#[test]
fn a_rectangle_of_large_aspect_ratio_oscillates_as_theodorsens_plate() {
    // Theodorsen (NACA Rep. 496, 1935), about the quarter chord, with
    // k = ωb/V = ω̄/2 (b the semi-chord, c̄ = 2b), C(k) = F + iG:
    // incidence: C_L = 2πC(k)α + (π/2)(α̇c/V) → C_Lα = 2πF,
    //   z_ẇ = −(π/2 + πG/k); pitch less incidence: z_q = −πF;
    // moments about c/4: the circulatory lift acts there, so H₀ = ¼ and
    // m_ẇ = m_q = −π/8 (apparent mass and the rotation's "camber").
    let k = 0.5;
    let theo = reference()["theodorsen"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["k"].as_f64() == Some(k))
        .cloned()
        .unwrap();
    let (f, g) = (theo["F"].as_f64().unwrap(), theo["G"].as_f64().unwrap());
    // the published table (Theodorsen 1935; Bisplinghoff, Ashley & Halfman
    // 1955, table 5-1): F(0.5) = 0.5979, G(0.5) = −0.1507
    assert!((f - 0.5979).abs() < 1e-4 && (g + 0.1507).abs() < 1e-4);
    let spec = LatticeSpec::new(8, 64, Spacing::Auto).with_extrapolation(Extrapolation::Chordwise);
    let lattice = Lattice::new(&Trapezoid::rectangle(40.0, 1.0).unwrap(), spec).unwrap();
    let d = lattice
        .solve(0.0, 2.0 * k)
        .unwrap()
        .derivatives(0.25, 0.0)
        .unwrap();
    let close = |x: f64, y: f64, tol: f64, what: &str| {
        assert!(
            (x / y - 1.0).abs() < tol,
            "{what}: lattice {x}, Theodorsen {y}"
        );
    };
    close(d.lift_slope, 2.0 * PI * f, 0.015, "C_Lα");
    close(d.z_q, -PI * f, 0.015, "z_q");
    close(d.z_wdot, -(PI / 2.0 + PI * g / k), 0.03, "z_ẇ");
    close(d.m_wdot, -PI / 8.0, 0.015, "m_ẇ");
    close(d.m_q, -PI / 8.0, 0.015, "m_q");
    assert!(
        (d.aerodynamic_centre - 0.25).abs() < 0.003,
        "H₀ {}",
        d.aerodynamic_centre
    );
}

#[test]
fn prandtl_glauert_maps_a_wing_at_m_onto_its_affine_wing_at_rest() {
    // Göthert's rule: the wing at M equals the wing of spans scaled by β at
    // M = 0, with the steady coefficients divided by β (chords, the M.A.C.
    // and its position unchanged).
    for (wing, mach) in [
        (delta(4.0), 0.6f64),
        (Trapezoid::new(1.0, 1.0 / 7.0, 0.7, 0.9).unwrap(), 0.8),
    ] {
        let beta = f64::sqrt(1.0 - mach * mach);
        let spec = LatticeSpec::new(8, 12, Spacing::Auto);
        let at_m = Lattice::new(&wing, spec).unwrap().solve(mach, 0.0).unwrap();
        let affine = wing.affine(beta).unwrap();
        assert!((affine.mac() - wing.mac()).abs() < 1e-14);
        assert!((affine.x_mac() - wing.x_mac()).abs() < 1e-14);
        let at_0 = Lattice::new(&affine, spec)
            .unwrap()
            .solve(0.0, 0.0)
            .unwrap();
        for (x, y) in [
            (at_m.lift_alpha, at_0.lift_alpha),
            (at_m.moment_alpha, at_0.moment_alpha),
            (at_m.lift_q, at_0.lift_q),
            (at_m.moment_q, at_0.moment_q),
        ] {
            assert!((x * beta - y).abs() < 1e-10 * y.abs(), "{x} β vs {y}");
        }
    }
}

#[test]
fn the_quasi_steady_limit_is_the_harmonic_one_as_the_frequency_vanishes() {
    // The harmonic solution with the exact kernel (I₁ by quadrature) tends
    // to the quasi-steady one (first-order kernel) as O(ω̄ ln ω̄); with
    // Desmarais' approximation it stops within its error (about 1 % of the
    // α̇ derivatives, see the docs).
    let spec = LatticeSpec::new(4, 6, Spacing::Auto);
    let wing = delta(2.0);
    let qs = Lattice::new(&wing, spec).unwrap().solve(0.5, 0.0).unwrap();
    let exact = Lattice::new(&wing, spec.with_kernel(I1Approximation::Quadrature)).unwrap();
    let gaps: Vec<f64> = [1e-2, 1e-3]
        .iter()
        .map(|&w| {
            let s = exact.solve(0.5, w).unwrap();
            let d = (s.lift_alphadot - qs.lift_alphadot).abs() / qs.lift_alphadot.abs();
            let m = (s.moment_alphadot - qs.moment_alphadot).abs() / qs.moment_alphadot.abs();
            assert!((s.lift_alpha - qs.lift_alpha).abs() < 1e-3 * qs.lift_alpha);
            d.max(m)
        })
        .collect();
    assert!(gaps[1] < gaps[0] && gaps[1] < 3e-3, "{gaps:?}");
    let desmarais = Lattice::new(&wing, spec).unwrap().solve(0.5, 1e-3).unwrap();
    let gap = (desmarais.lift_alphadot / qs.lift_alphadot - 1.0).abs();
    assert!(gap < 0.02, "{gap}");
}

#[test]
fn moving_the_axis_obeys_the_kinematics() {
    // Independently of the solution's algebra (derivatives.rs): with C_D = 0,
    // about h against h = 0 (docs/damping-theories.md, eq 36's evidence 2):
    // z_q(h) = z_q(0) − h z_w, m_ẇ(h) = m_ẇ(0) − h z_ẇ,
    // m_q(h) = m_q(0) − h(z_q(0) + m_w(0)) + h² z_w, m_w(h) = m_w(0) − h z_w.
    let p = Planform::new(45f64.to_radians(), 1.0 / 7.0, Size::RootChord(1.0)).unwrap();
    let lattice = Lattice::new(&Trapezoid::from(&p), LatticeSpec::new(4, 8, Spacing::Auto));
    let s = lattice.unwrap().solve(0.7, 0.3).unwrap();
    let d0 = s.derivatives(0.0, 0.0).unwrap();
    for h in [-0.3, 0.25, 0.6, 1.2] {
        let d = s.derivatives(h, 0.0).unwrap();
        let near =
            |x: f64, y: f64| assert!((x - y).abs() < 1e-12 * (1.0 + y.abs()), "{h}: {x} {y}");
        near(d.z_q, d0.z_q - h * d0.z_w);
        near(d.m_wdot, d0.m_wdot - h * d0.z_wdot);
        near(d.m_q, d0.m_q - h * (d0.z_q + d0.m_w) + h * h * d0.z_w);
        near(d.m_w, d0.m_w - h * d0.z_w);
        near(d.z_thetadot, d.z_q + d.z_wdot);
        near(d.m_thetadot, d.m_q + d.m_wdot);
    }
}

#[test]
fn bad_input_is_an_error_not_a_number() {
    let lattice = Lattice::new(&delta(2.0), LatticeSpec::new(4, 4, Spacing::Auto)).unwrap();
    for m in [1.0, 1.5, -0.1, f64::NAN] {
        assert!(matches!(
            lattice.solve(m, 0.0),
            Err(LiftingSurfaceError::Mach(_))
        ));
    }
    for w in [-1.0, f64::INFINITY, f64::NAN] {
        assert!(matches!(
            lattice.solve(0.5, w),
            Err(LiftingSurfaceError::Frequency(_))
        ));
    }
    let s = lattice.solve(0.5, 0.2).unwrap();
    assert!(matches!(
        s.derivatives(f64::NAN, 0.0),
        Err(LiftingSurfaceError::Invalid(_))
    ));
    assert!(matches!(
        s.derivatives(0.2, f64::INFINITY),
        Err(LiftingSurfaceError::Invalid(_))
    ));
    // the report's wings through `Planform`
    let p = Planform::new(60f64.to_radians(), 0.0, Size::Span(10.0)).unwrap();
    assert!(Lattice::new(&Trapezoid::from(&p), LatticeSpec::default()).is_ok());
    let e = Lattice::new(
        &delta(2.0),
        LatticeSpec::default()
            .scaled(0)
            .with_extrapolation(Extrapolation::None),
    );
    assert!(matches!(e, Err(LiftingSurfaceError::Lattice { .. })));
    assert!(e.unwrap_err().to_string().contains("multiple"));
}
