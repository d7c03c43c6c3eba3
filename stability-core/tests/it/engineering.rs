//! The engineer's outputs of the library against independent routes: the
//! physical flight condition by hand and against the 1976 table, the mode
//! shapes against nalgebra's SVD null vector of A − λI, the `damp()` table
//! by hand, the MIL-F-8785C frequency requirement at its boundaries.

use nalgebra::{Complex, Matrix4};
use num_complex::Complex64;
use stability_core::analysis::engineering::Engineering;
use stability_core::analysis::{Analysis, STANDARD_GRAVITY};
use stability_core::criteria::cap::{
    AirplaneClass, ShortPeriodFrequency, frequency_level, n_alpha, n_alpha_dimensional, regions,
};
use stability_core::criteria::{Category, Level};
use stability_core::design::atmosphere::{FOOT, KG_PER_SLUG, NEWTON_PER_LBF};
use stability_core::design::examples::{
    tailless_delta_45_coupled, tailless_delta_60, tailless_delta_60_flight,
};
use stability_core::design::flight::{Air, Altitude, FlightCondition, Mass, Units};
use stability_core::dynamics::linear::{Control, LinearModel, TimeUnit};
use stability_core::dynamics::mode_shape::{ModeShape, eigenvector};
use stability_core::geometry::{Planform, Size};

fn delta_60() -> Planform {
    Planform::new(60f64.to_radians(), 0.0, Size::RootChord(12.0)).unwrap()
}

fn at_11_km() -> FlightCondition {
    FlightCondition {
        units: Units::Si,
        air: Air::Standard(Altitude::Pressure(11_000.0)),
        mass: Mass::Mass(12_000.0),
        pitch_inertia: 70_000.0,
    }
}

#[test]
fn the_air_at_11_km_is_the_standards() {
    // The 1976 standard at H = 11 km′ (the tropopause, its Table 4 layer
    // base): T = 216.65 K, P = 22 632 Pa, ρ = 0.36392 kg/m³, a = 295.07 m/s.
    let f = at_11_km().for_planform(&delta_60()).unwrap();
    assert!((f.density - 0.36392).abs() < 5e-6, "{}", f.density);
    assert!(
        (f.speed_of_sound - 295.07).abs() < 5e-3,
        "{}",
        f.speed_of_sound
    );
    // a geometric 11 km is a geopotential 10 981 m′: denser air
    let g = FlightCondition {
        air: Air::Standard(Altitude::Geometric(11_000.0)),
        ..at_11_km()
    }
    .for_planform(&delta_60())
    .unwrap();
    assert!(g.density > f.density * 1.002 && g.density < f.density * 1.004);
    // and 40 000 ft (pressure altitude, ft units): the standard's density
    // ratio σ = 0.2462 there (ρ = 5.851e-4 slug/ft³)
    let ft = FlightCondition {
        units: Units::Ft,
        air: Air::Standard(Altitude::Pressure(40_000.0)),
        mass: Mass::Weight(636_636.0),
        pitch_inertia: 0.331e8,
    }
    .resolve(5_500.0, 27.31)
    .unwrap();
    let sigma = ft.atmosphere.unwrap().density_ratio();
    assert!((sigma - 0.2462).abs() < 5e-5, "{sigma}");
    let slug_ft3 = ft.density / Units::Ft.density();
    assert!((slug_ft3 - 5.851e-4).abs() < 5e-8, "{slug_ft3}");
}

#[test]
fn the_flight_parameters_by_hand() {
    let p = delta_60();
    // the planform: span 2·12/tan 60°, S = ½·b·c₀, M.A.C. (2/3)c₀
    let b = 24.0 / 3f64.sqrt();
    let (s, c) = (0.5 * b * 12.0, 8.0);
    let f = at_11_km().for_planform(&p).unwrap();
    assert!((f.area - s).abs() < 1e-12 && (f.chord - c).abs() < 1e-12);
    let (rho, a) = (f.density, f.speed_of_sound);
    let mu1 = 12_000.0 / (0.5 * rho * s * c);
    let i_b = 70_000.0 / (12_000.0 * c * c);
    let cl_m2 = 12_000.0 * 9.80665 / (0.5 * rho * a * a * s);
    assert!((f.mu1() - mu1).abs() < 1e-12 * mu1);
    assert!((f.i_b() - i_b).abs() < 1e-15);
    assert!((f.cl_m2() - cl_m2).abs() < 1e-14 * cl_m2);
    // the example's printed values
    assert!((mu1 - 99.155).abs() < 5e-3 && (cl_m2 - 0.08935).abs() < 5e-5);
    let pt = f.at_mach(0.9).unwrap();
    let v = 0.9 * a;
    assert!((pt.speed - v).abs() < 1e-12);
    assert!((pt.tau - 12_000.0 / (0.5 * rho * s * v)).abs() < 1e-12);
    // and the same through analysis::Dimensional, which the quartic uses
    let d = f.dimensional(&pt);
    assert!((d.tau() - pt.tau).abs() < 1e-12 && (d.mu1() - mu1).abs() < 1e-9);
    assert!((d.c_l() - pt.c_l).abs() < 1e-14);
}

#[test]
fn over_mach_c_l_m2_stays_and_c_l_and_tau_follow() {
    // eq (24): at a fixed altitude and weight C_L·M² is constant, so
    // C_L = (C_L·M²)/M² and τ·M is constant too.
    let f = at_11_km().for_planform(&delta_60()).unwrap();
    let first = f.at_mach(0.5).unwrap();
    for m in [0.6, 0.9, 1.2, 2.0] {
        let p = f.at_mach(m).unwrap();
        assert!((p.c_l * m * m - f.cl_m2()).abs() < 1e-14);
        assert!((p.tau * m - first.tau * 0.5).abs() < 1e-12);
        assert!((p.speed - m * f.speed_of_sound).abs() < 1e-12);
    }
}

#[test]
fn si_and_ft_give_one_aircraft() {
    // A 747-like condition (CR-2144 F/C 9's weight, inertia and wing; the
    // air as given) in ft–slug, and the same numbers converted by hand into
    // SI: μ₁, i_B, C_L·M² and τ agree.
    let ft = FlightCondition {
        units: Units::Ft,
        air: Air::Given {
            density: 5.8727e-4,
            speed_of_sound: 968.08,
        },
        mass: Mass::Weight(636_636.0),
        pitch_inertia: 0.331e8,
    }
    .resolve(5_500.0, 27.31)
    .unwrap();
    let si = FlightCondition {
        units: Units::Si,
        air: Air::Given {
            density: 5.8727e-4 * KG_PER_SLUG / FOOT.powi(3),
            speed_of_sound: 968.08 * FOOT,
        },
        mass: Mass::Mass(636_636.0 * NEWTON_PER_LBF / STANDARD_GRAVITY),
        pitch_inertia: 0.331e8 * KG_PER_SLUG * FOOT * FOOT,
    }
    .resolve(5_500.0 * FOOT * FOOT, 27.31 * FOOT)
    .unwrap();
    for (a, b) in [
        (ft.mu1(), si.mu1()),
        (ft.i_b(), si.i_b()),
        (ft.cl_m2(), si.cl_m2()),
        (ft.at_mach(0.8).unwrap().tau, si.at_mach(0.8).unwrap().tau),
    ] {
        assert!((a - b).abs() < 1e-12 * a.abs(), "{a} vs {b}");
    }
    // C_L at M 0.8 by hand in ft–lbf: W/(½ρV²S)
    let v = 0.8 * 968.08;
    let c_l = 636_636.0 / (0.5 * 5.8727e-4 * v * v * 5_500.0);
    assert!((ft.at_mach(0.8).unwrap().c_l - c_l).abs() < 1e-12);
}

/// The null vector of A − λI by nalgebra's SVD (the right singular vector
/// of the smallest singular value), θ = 1: an independent eigenvector.
fn svd_null_vector(a: &Matrix4<f64>, lam: Complex64) -> [Complex64; 4] {
    let m = a.map(|x| Complex::new(x, 0.0)) - Matrix4::<Complex<f64>>::identity() * lam;
    let svd = m.svd(false, true);
    let v_t = svd.v_t.unwrap();
    let k = (0..4)
        .min_by(|&i, &j| svd.singular_values[i].total_cmp(&svd.singular_values[j]))
        .unwrap();
    let row: [Complex64; 4] = std::array::from_fn(|j| v_t[(k, j)].conj());
    row.map(|z| z / row[3])
}

#[test]
fn mode_shapes_are_the_svd_null_vectors() {
    for d in [tailless_delta_45_coupled(), tailless_delta_60()] {
        let a = Analysis::of(&d).unwrap();
        let model = LinearModel::of_report(&d, None).unwrap();
        for taus in [None, Some(3.455)] {
            let e = Engineering::of_report(&d, &a, taus, None, Some(AirplaneClass::IV)).unwrap();
            assert_eq!(e.mode_shapes.len(), a.modes.len());
            let m = match taus {
                Some(t) => model.in_seconds(t),
                None => model.clone(),
            };
            for s in &e.mode_shapes {
                let svd = svd_null_vector(&m.a, s.lambda);
                for (k, (ours, theirs)) in s.vector.iter().zip(svd).enumerate() {
                    let err = (ours - theirs).norm();
                    assert!(
                        err < 1e-9 * (1.0 + theirs.norm()),
                        "{:?} {k}: {err}",
                        s.name
                    );
                }
                // and A v = λ v
                let av: Vec<Complex64> = (0..4)
                    .map(|i| (0..4).map(|j| s.vector[j] * m.a[(i, j)]).sum())
                    .collect();
                for (avk, vk) in av.iter().zip(s.vector) {
                    assert!((avk - s.lambda * vk).norm() < 1e-9 * (1.0 + s.lambda.norm()));
                }
                // θ is the reference and q/θ = λ in the model's own time
                assert_eq!(s.reference, 3);
                assert!((s.vector[2] - s.lambda).norm() < 1e-9 * s.lambda.norm());
            }
        }
    }
}

#[test]
fn a_mode_without_theta_takes_its_largest_component() {
    // u decoupled (x_u only): the eigenvector of λ = x_u is pure u.
    let a = Matrix4::new(
        -0.5, 0.0, 0.0, 0.0, 0.0, -2.0, 1.0, 0.0, 0.0, -30.0, -3.0, 0.0, 0.0, 0.0, 1.0, 0.0,
    );
    let model = LinearModel {
        a,
        b: None,
        input: None,
        time: TimeUnit::Seconds,
        load_factor: None,
    };
    let v = eigenvector(&a, Complex64::new(-0.5, 0.0)).unwrap();
    assert!(v[1].norm() < 1e-15 && v[3].norm() < 1e-15);
    let e = Engineering::of_model(model, &model_roots(&a), None, Some(AirplaneClass::IV));
    let u_mode = e
        .mode_shapes
        .iter()
        .find(|s| (s.lambda.re + 0.5).abs() < 1e-9 && s.lambda.im == 0.0)
        .expect("the u mode");
    assert_eq!(u_mode.reference, 0);
    assert!((u_mode.vector[0] - 1.0).norm() < 1e-15);
}

fn model_roots(a: &Matrix4<f64>) -> [Complex64; 4] {
    LinearModel {
        a: *a,
        b: None,
        input: None,
        time: TimeUnit::Seconds,
        load_factor: None,
    }
    .eigenvalues()
}

#[test]
fn the_damp_table_is_the_roots_over_tau() {
    let d = tailless_delta_60();
    let tau = tailless_delta_60_flight().tau();
    let a = Analysis::of(&d).unwrap();
    let e = Engineering::of_report(&d, &a, Some(tau), None, Some(AirplaneClass::IV)).unwrap();
    let damp = e.damp.as_ref().unwrap();
    for (m, s) in a.modes.iter().zip(damp.modes()) {
        assert_eq!(m.name, s.name);
        assert!((s.re - m.re / tau).abs() < 1e-15 && (s.im - m.im / tau).abs() < 1e-15);
        assert!((s.natural_frequency - m.natural_frequency / tau).abs() < 1e-14);
        assert!((s.damping_ratio.unwrap() - m.damping_ratio.unwrap()).abs() < 1e-15);
        assert!((s.period.unwrap() - m.period.unwrap() * tau).abs() < 1e-12);
        assert!((s.cycles_to_half.unwrap() - m.cycles_to_half.unwrap()).abs() < 1e-12);
    }
    // the eigenvalues of the model in seconds are these roots (Schur)
    let ev = e.model.eigenvalues();
    for m in damp.modes() {
        let z = Complex64::new(m.re, m.im);
        let nearest = ev
            .iter()
            .map(|w| (w - z).norm())
            .fold(f64::INFINITY, f64::min);
        assert!(nearest < 1e-10 * z.norm(), "{z}: {nearest}");
    }
    // the frequency requirement uses ω_sp and n/α = −z_w/C_L
    let f = e.short_period_frequency.unwrap();
    assert_eq!(
        f.natural_frequency_rad_s,
        damp.0.short_period().unwrap().natural_frequency
    );
    assert!((f.n_alpha - 3.65 / 0.121).abs() < 1e-12);
}

#[test]
fn an_undefined_cap_is_not_assessed() {
    use stability_core::criteria::cap::not_assessed;
    for n in [
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        0.0,
        -0.0,
        1e-320,
    ] {
        assert!(not_assessed(7.0, n).is_some(), "n/α = {n}");
        assert!(ShortPeriodFrequency::assess(7.0, n, Some(AirplaneClass::IV)).is_err());
    }
    let f = ShortPeriodFrequency::assess(3.0, 20.0, Some(AirplaneClass::IV)).unwrap();
    assert_eq!(
        f,
        ShortPeriodFrequency::of(3.0, 20.0, Some(AirplaneClass::IV))
    );
}

#[test]
fn n_alpha_two_ways() {
    // (V/g)(−Z_w) with Z_w = z_w/τ (per unit mass) is −z_w/C_L when
    // C_L = W/(½ρV²S).
    let fl = tailless_delta_60_flight();
    let z_w = -3.65;
    let dimensional = n_alpha_dimensional(z_w / fl.tau(), fl.v, STANDARD_GRAVITY);
    assert!((dimensional - n_alpha(z_w, fl.c_l())).abs() < 1e-12 * dimensional);
}

#[test]
fn the_frequency_levels_at_their_boundaries() {
    let class = AirplaneClass::IV;
    // ω for a CAP at n/α: ω = √(CAP·n/α)
    let omega = |cap: f64, na: f64| (cap * na).sqrt();
    // just outside a bound, and just inside (the CAP of ω = √(CAP·n/α)
    // rounds by an ulp or two, so a bound itself is tested from inside)
    let up = 1.0 + 1e-9;
    let dn = 1.0 - 1e-9;
    let (lo, hi) = (1.0 + 1e-12, 1.0 - 1e-12);
    let level = |cap: f64, na: f64, c| frequency_level(omega(cap, na), na, c, class);
    // Category A at n/α = 20: 0.28 ≤ CAP ≤ 3.6 (Level 1), 0.16 ≤ CAP ≤ 10 (2)
    for (cap, expect) in [
        (0.28 * lo, Level::One),
        (0.28 * dn, Level::Two),
        (3.6 * hi, Level::One),
        (3.6 * up, Level::Two),
        (10.0 * hi, Level::Two),
        (10.0 * up, Level::Three),
        (0.16 * lo, Level::Two),
        (0.16 * dn, Level::WorseThanThree),
    ] {
        assert_eq!(level(cap, 20.0, Category::A), expect, "A, CAP {cap}");
    }
    // the ω floors of Category A: 1.0 rad/s (Level 1), 0.6 (Level 2),
    // none for Level 3: at n/α = 2, CAP = 0.5 is Level 1 only if ω ≥ 1
    assert_eq!(frequency_level(1.0, 2.0, Category::A, class), Level::One);
    assert_eq!(
        frequency_level(1.0 * dn, 1.99, Category::A, class),
        Level::Two
    );
    assert_eq!(frequency_level(0.6, 1.0, Category::A, class), Level::Two);
    assert_eq!(
        frequency_level(0.6 * dn, 1.0, Category::A, class),
        Level::Three
    );
}

/// ω for a CAP at n/α, and factors just outside and just inside a bound
/// (the CAP of ω = √(CAP·n/α) rounds by an ulp or two, so a bound itself
/// is tested from inside).
fn omega(cap: f64, na: f64) -> f64 {
    (cap * na).sqrt()
}
const UP: f64 = 1.0 + 1e-9;
const DN: f64 = 1.0 - 1e-9;
const LO: f64 = 1.0 + 1e-12;

#[test]
fn the_frequency_levels_of_categories_b_and_c() {
    let class = AirplaneClass::IV;
    let (up, dn, lo) = (UP, DN, LO);
    let level = |cap: f64, na: f64, c| frequency_level(omega(cap, na), na, c, class);
    // Category B: 0.085–3.6, 0.038–10, Level 3 down to 0.038
    for (cap, expect) in [
        (0.085 * lo, Level::One),
        (0.085 * dn, Level::Two),
        (0.038 * lo, Level::Two),
        (0.038 * dn, Level::WorseThanThree),
        (10.0 * up, Level::Three),
    ] {
        assert_eq!(level(cap, 5.0, Category::B), expect, "B, CAP {cap}");
    }
    // Category C: 0.16–3.6 with ω ≥ 0.87 and n/α ≥ 2.7 (Class IV), 0.096–10
    // with ω ≥ 0.6 and n/α ≥ 1.8; Classes II-L and III: 0.7/2.0, 0.4/1.0
    assert_eq!(level(0.16 * lo, 10.0, Category::C), Level::One);
    assert_eq!(level(0.16 * dn, 10.0, Category::C), Level::Two);
    assert_eq!(level(0.096 * dn, 10.0, Category::C), Level::WorseThanThree);
    assert_eq!(frequency_level(1.0, 2.7, Category::C, class), Level::One);
    assert_eq!(
        frequency_level(1.0, 2.7 * dn, Category::C, class),
        Level::Two
    );
    assert_eq!(
        frequency_level(0.87 * dn, 4.0, Category::C, class),
        Level::Two
    );
    let heavy = AirplaneClass::III;
    assert_eq!(frequency_level(0.7, 2.0, Category::C, heavy), Level::One);
    assert_eq!(
        frequency_level(0.7 * dn, 2.0, Category::C, heavy),
        Level::Two
    );
    assert_eq!(
        frequency_level(0.4 * dn, 1.0, Category::C, heavy),
        Level::Three
    );
}

#[test]
fn the_frequency_levels_outside_the_figures_and_the_747() {
    let class = AirplaneClass::IV;
    // no frequency, no level
    assert_eq!(
        frequency_level(0.0, 5.0, Category::B, class),
        Level::WorseThanThree
    );
    assert_eq!(
        frequency_level(1.0, -5.0, Category::B, class),
        Level::WorseThanThree
    );
    // each level's region lies inside the next one's
    for c in [Category::A, Category::B, Category::C] {
        let r = regions(c, class);
        for k in 0..2 {
            assert!(r[k].cap_min >= r[k + 1].cap_min);
        }
    }
    // the 747 in cruise (Etkin & Reid's): ω_sp 0.962 rad/s, n/α = 4.92/0.654
    let f = ShortPeriodFrequency::of(0.9616, 4.920 / 0.654, Some(AirplaneClass::III));
    assert!((f.cap - 0.9616f64.powi(2) / (4.920 / 0.654)).abs() < 1e-15);
    assert_eq!((f.a, f.b), (Level::WorseThanThree, Level::One));
}

#[test]
fn the_control_column_in_seconds() {
    // B of a control (C_Xδ, C_Zδ, C_mδ) in seconds: the ẇ row is C_Zδ/(Aτ)
    // and the q row ((μ₁/i_B)C_mδ + (m_ẇ/i_B)·C_Zδ/A)/τ², A = 1 − z_ẇ/μ₁.
    let d = tailless_delta_60();
    let tau = 3.455;
    let c = Control {
        name: "elevon".into(),
        c_x: 0.0,
        c_z: -0.6,
        c_m: -0.25,
    };
    let m = LinearModel::of_report(&d, Some(&c))
        .unwrap()
        .in_seconds(tau);
    let b = m.b.unwrap();
    let a_mass = 1.0 - d.z_wdot / d.mu1;
    let wdot = c.c_z / a_mass;
    assert!((b[1] - wdot / tau).abs() < 1e-15);
    let q = (d.mu1 / d.i_b * c.c_m + d.m_wdot / d.i_b * wdot) / (tau * tau);
    assert!((b[2] - q).abs() < 1e-12 * q.abs());
    assert_eq!(b[3], 0.0);
    let shapes = ModeShape::all(&m, &[]);
    assert!(shapes.is_empty());
}

/// MIL-F-8785C §3.2.2.1.1: only Category C's floors depend on the airplane
/// class (Fig 3: Classes I, II-C, IV against II-L, III), so without a class
/// Categories A and B are assessed as with any, and C is not.
#[test]
fn without_a_class_only_category_c_is_not_assessed() {
    for c in [Category::A, Category::B] {
        let r = regions(c, AirplaneClass::I);
        for k in AirplaneClass::ALL {
            assert_eq!(regions(c, k), r, "{c:?} {k:?}");
        }
    }
    // Category C's floors differ: ω_sp = 0.8 rad/s at n/α = 2.5 g/rad
    // (CAP 0.256) is Level 1 for the heavy classes (ω ≥ 0.7, n/α ≥ 2.0),
    // Level 2 for a fighter (ω ≥ 0.87 and n/α ≥ 2.7 fail)
    let heavy = ShortPeriodFrequency::of(0.8, 2.5, Some(AirplaneClass::III));
    let fighter = ShortPeriodFrequency::of(0.8, 2.5, Some(AirplaneClass::IV));
    assert_eq!((heavy.c, fighter.c), (Some(Level::One), Some(Level::Two)));
    let none = ShortPeriodFrequency::of(0.8, 2.5, None);
    assert_eq!((none.a, none.b, none.c), (fighter.a, fighter.b, None));
    assert_eq!(none.class, None);
    for k in AirplaneClass::ALL {
        assert_eq!(AirplaneClass::parse(k.name()), Some(k));
    }
    assert_eq!(AirplaneClass::parse("V"), None);
}
