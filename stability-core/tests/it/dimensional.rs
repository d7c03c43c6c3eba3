//! The general dimensional model (issue 12, `stability_core::data::dimensional`):
//! its generated quartic (specs/dimensional.toml) against independent
//! routes, eq (4) as its special case, the axis rotation and the
//! conversions to and from the report's notation.

use nalgebra::{Complex, Matrix4};
use stability_core::Derivatives;
use stability_core::data::dimensional::{
    Axes, DimensionalAnalysis, DimensionalDerivatives, DimensionalModel, Reference, Trim, Units,
};
use stability_core::numerics::roots::solve_quartic;

/// SplitMix64 (Steele, Lea & Flood 2014): a reproducible stream of u64.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    fn between(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// ± a magnitude log-uniform in [lo, hi].
    fn signed(&mut self, lo: f64, hi: f64) -> f64 {
        let m = (lo.ln() + (hi.ln() - lo.ln()) * self.unit()).exp();
        if self.unit() < 0.5 { -m } else { m }
    }
}

/// A random body-axis set with every term present: θ₀ and W₀ ≠ 0, ẇ, u̇
/// and q derivatives, magnitudes spanning those of the published sets.
fn random_model(rng: &mut Rng) -> DimensionalModel {
    let d = DimensionalDerivatives {
        x_u: rng.signed(1e-3, 0.1),
        x_w: rng.signed(1e-3, 0.3),
        x_wdot: rng.signed(1e-4, 0.02),
        x_udot: rng.signed(1e-4, 0.02),
        x_q: rng.signed(0.01, 5.0),
        z_u: rng.signed(1e-2, 0.5),
        z_w: -rng.between(0.2, 3.0),
        z_wdot: rng.signed(1e-4, 0.05),
        z_udot: rng.signed(1e-4, 0.02),
        z_q: rng.signed(0.1, 10.0),
        m_u: rng.signed(1e-5, 3e-3),
        m_w: -rng.between(1e-3, 0.1),
        m_wdot: rng.signed(1e-5, 5e-3),
        m_udot: rng.signed(1e-6, 1e-3),
        m_q: -rng.between(0.2, 3.0),
    };
    let u0 = rng.between(50.0, 900.0);
    let alpha = rng.between(-0.05, 0.3);
    DimensionalModel {
        axes: Axes::Body,
        units: Units::Ft,
        derivatives: d,
        trim: Trim {
            u0,
            w0: u0 * alpha.tan(),
            theta0: alpha + rng.between(-0.1, 0.1),
            g: 32.174,
        },
    }
}

fn to_complex(m: &Matrix4<f64>) -> Matrix4<Complex<f64>> {
    m.map(|x| Complex::new(x, 0.0))
}

/// The generated coefficients against det(λE − A) computed numerically
/// (nalgebra's LU of the complex 4×4) at five points of the complex plane:
/// the polynomial through them is unique.
#[test]
fn the_generated_quartic_is_the_numerical_determinant_of_the_descriptor_system() {
    let mut rng = Rng(0xD1_3E75);
    for _ in 0..300 {
        let m = random_model(&mut rng);
        let q = m.quartic();
        let (e, a) = m.descriptor();
        let (e, a) = (to_complex(&e), to_complex(&a));
        for k in 0..5 {
            let lam = Complex::from_polar(0.3 + 0.7 * k as f64, 0.4 + 1.1 * k as f64);
            let det = (e * lam - a).determinant();
            let poly = q.eval(lam);
            let scale = [q.a, q.b, q.c, q.d, q.e]
                .iter()
                .enumerate()
                .map(|(p, c)| c.abs() * lam.norm().powi(4 - p as i32))
                .sum::<f64>();
            assert!(
                (det - poly).norm() <= 1e-12 * scale,
                "λ = {lam}: det {det}, generated {poly} (scale {scale})"
            );
        }
    }
}

/// Match `b` to `a` (each root of `a` to its nearest in `b`, without
/// reuse) and return the largest relative distance.
fn worst_match(a: &[Complex<f64>], b: &[Complex<f64>]) -> f64 {
    let mut free: Vec<Complex<f64>> = b.to_vec();
    let mut worst: f64 = 0.0;
    for z in a {
        let (k, d) = free
            .iter()
            .enumerate()
            .map(|(k, w)| (k, (z - w).norm()))
            .min_by(|x, y| x.1.total_cmp(&y.1))
            .unwrap();
        worst = worst.max(d / z.norm());
        free.remove(k);
    }
    worst
}

/// The roots of the generated quartic against the eigenvalues of E⁻¹A
/// (nalgebra's Schur decomposition), on the random sets.
#[test]
fn the_roots_are_the_eigenvalues_of_the_state_matrix() {
    let mut rng = Rng(0x5EED_0042);
    for _ in 0..300 {
        let m = random_model(&mut rng);
        let roots = solve_quartic(m.quartic().to_array()).unwrap();
        let eig = m.state_matrix().unwrap().complex_eigenvalues();
        let eig: Vec<Complex<f64>> = eig.iter().copied().collect();
        let w = worst_match(&roots, &eig);
        assert!(w < 1e-8, "{roots:?} against {eig:?}: {w}");
    }
}

/// Eq (4) is the general model's special case: a report-notation set
/// converted with the report's non-dimensionalisation (x_u = X_u τ, …,
/// stability axes, θ₀ = W₀ = 0, g = C_L V/τ) has the quartic of eq (4)
/// after λ = λ̂/τ: its coefficient of λ^p times τ^(4−p) is eq (4)'s. The two
/// quartics come from two specs whose determinants were written
/// independently.
#[test]
fn eq_4_is_the_special_case_of_the_general_quartic() {
    let mut rng = Rng(0xE94);
    for _ in 0..300 {
        let d = random_report(&mut rng);
        let v = rng.between(30.0, 600.0);
        let tau = rng.between(0.5, 20.0);
        let (model, _) = DimensionalModel::from_report(&d, v, tau, Units::Si);
        let general = model.quartic().to_array();
        let report = d.quartic_coefficients();
        for p in 0..5 {
            let scaled = general[4 - p] * tau.powi(4 - p as i32);
            let r = report[4 - p];
            let scale = d
                .quartic_gradient()
                .iter()
                .zip(d.quartic_input_values())
                .map(|(row, x)| (row[4 - p] * x).abs())
                .sum::<f64>()
                .max(r.abs());
            assert!(
                (scaled - r).abs() <= 1e-12 * scale,
                "λ^{p}: general·τ^(4−p) = {scaled}, eq (4) = {r}"
            );
        }
    }
}

fn random_report(rng: &mut Rng) -> Derivatives {
    let mut v = [0.0; 15];
    for x in v.iter_mut().take(12) {
        *x = rng.signed(1e-2, 10.0);
    }
    v[12] = rng.between(0.02, 1.5);
    v[13] = rng.between(5.0, 5000.0);
    v[14] = rng.between(0.01, 2.0);
    Derivatives::from_quartic_input_values(v)
}

/// Report → dimensional → report is the identity (to rounding).
#[test]
fn report_to_dimensional_and_back_to_1e_12() {
    let mut rng = Rng(0x0B0B);
    for _ in 0..300 {
        let d = random_report(&mut rng);
        let v = rng.between(30.0, 600.0);
        let tau = rng.between(0.5, 20.0);
        let (model, reference) = DimensionalModel::from_report(&d, v, tau, Units::Si);
        let back = model.to_report(&reference);
        assert!(back.is_exact());
        assert!((back.tau - tau).abs() <= 1e-12 * tau);
        for (a, b) in back
            .derivatives
            .quartic_input_values()
            .iter()
            .zip(d.quartic_input_values())
        {
            assert!((a - b).abs() <= 1e-12 * b.abs(), "{a} against {b}");
        }
    }
}

/// The rotation into stability axes: E and A become TᵀET and TᵀAT (the θ
/// column included, as gravity at θ₀ − α₀), the eigenvalues and the quartic
/// are unchanged, and the ẇ derivatives of a body-axis set without u̇ terms
/// bring u̇ terms in (the previous helper's finding).
#[test]
fn rotating_into_stability_axes_keeps_the_motion_and_brings_in_udot_terms() {
    let mut rng = Rng(0x0A1F);
    for _ in 0..200 {
        let mut m = random_model(&mut rng);
        m.derivatives.x_udot = 0.0;
        m.derivatives.z_udot = 0.0;
        m.derivatives.m_udot = 0.0;
        let s = m.in_stability_axes();
        assert_eq!(s.axes, Axes::Stability);
        assert_eq!(s.trim.w0, 0.0);
        let alpha = m.trim.alpha0();
        let (sn, cs) = alpha.sin_cos();
        let mut t = Matrix4::identity();
        t[(0, 0)] = cs;
        t[(0, 1)] = -sn;
        t[(1, 0)] = sn;
        t[(1, 1)] = cs;
        let (e, a) = m.descriptor();
        let (es, as_) = s.descriptor();
        assert!((t.transpose() * e * t - es).amax() < 1e-12);
        assert!((t.transpose() * a * t - as_).amax() < 1e-9 * a.amax());
        let (qb, qs) = (m.quartic().to_array(), s.quartic().to_array());
        for (x, y) in qb.iter().zip(qs) {
            assert!((x - y).abs() <= 1e-9 * x.abs().max(qb[0].abs()), "{x} {y}");
        }
        // u̇ terms: M_u̇ = M_ẇ sin α₀ (the M row turned by T).
        let d = &s.derivatives;
        assert!((d.m_udot - m.derivatives.m_wdot * sn).abs() < 1e-15);
        assert!(d.has_udot_terms());
    }
}

/// The analysis in seconds against the report's in τ for a report set with
/// a flight condition: the same modes, times scaled by τ; the §8 verdict and
/// eq (41) the same.
#[test]
fn the_dimensional_analysis_of_a_report_set_is_its_analysis_in_seconds() {
    let d = stability_core::design::examples::tailless_delta_45();
    let (v, tau) = (250.0, 2.3);
    let (model, reference) = DimensionalModel::from_report(&d, v, tau, Units::Si);
    let dim = DimensionalAnalysis::of(&model, Some(&reference)).unwrap();
    let rep = stability_core::analysis::Analysis::of(&d).unwrap();
    assert_eq!(dim.verdict, rep.verdict);
    for (a, b) in dim.modes.iter().zip(rep.modes.iter()) {
        assert_eq!(a.name, b.name);
        assert!((a.re * tau - b.re).abs() < 1e-10 * b.re.abs());
        assert!((a.im * tau - b.im).abs() < 1e-10 * b.im.abs().max(1e-12));
        let (ca, cb) = (a.cycles_to_half.unwrap(), b.cycles_to_half.unwrap());
        assert!((ca - cb).abs() < 1e-10 * cb);
        let (fa, fb) = (
            a.frequency_parameter.unwrap(),
            b.frequency_parameter.unwrap(),
        );
        assert!((fa - fb).abs() < 1e-10 * fb);
    }
    let ds = dim.report.unwrap().damping_standard;
    assert!((ds.m_thetadot - rep.damping_standard.m_thetadot).abs() < 1e-12);
    assert_eq!(dim.tau(), Some(tau));
}

/// A physical reference: μ₁ and i_B from ρ, S, c̄, m, I_y, and the SI
/// flight condition from ft–slug values.
#[test]
fn a_physical_reference_in_ft_gives_the_reports_parameters() {
    // The 747 of CR-2144 F/C 9: W = 636 636 lb, I_y = 0.331e8 slug·ft²,
    // S = 5500 ft², c̄ = 27.3 ft, ρ = 2q/V² = 2·177/774² slug/ft³.
    let mass = 636_636.0 / 32.174;
    let rho = 2.0 * 177.0 / (774.0f64 * 774.0);
    let r = Reference::physical(rho, 5500.0, 27.3, mass, 0.331e8);
    assert!((r.mu1 - mass / (0.5 * rho * 5500.0 * 27.3)).abs() < 1e-9);
    let dim = r.dimensional(774.0, Units::Ft).unwrap();
    // τ is the same in both unit systems
    assert!((dim.tau() - r.tau(774.0)).abs() < 1e-12 * r.tau(774.0));
    assert!((dim.v - 774.0 * 0.3048).abs() < 1e-12);
    assert!((dim.mu1() - r.mu1).abs() < 1e-9 * r.mu1);
}

#[test]
fn a_stability_axis_set_with_w0_is_refused() {
    let mut m = random_model(&mut Rng(7));
    m.axes = Axes::Stability;
    let e = DimensionalAnalysis::of(&m, None).unwrap_err();
    assert!(e.to_string().contains("axes = \"body\""), "{e}");
}
