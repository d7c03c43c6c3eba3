//! The notation conversions generated from `specs/notation.toml`:
//! round trips between every pair, factors by hand, and a published
//! aircraft case in American notation whose published roots the program
//! reproduces.

use proptest::prelude::*;
use stability_core::analysis::Analysis;
use stability_core::data::notation::{
    N_ROWS, Notation, Values, derivatives_from_report, row, tables,
};

fn report_values(seed: [f64; N_ROWS]) -> Values {
    let mut v = [None; N_ROWS];
    for (i, x) in seed.iter().enumerate() {
        // μ, i_B, τ, the standard length must be positive
        let positive = matches!(tables::ROWS[i], "mu" | "i_b" | "tau" | "length");
        v[i] = Some(if positive { x.abs() + 0.1 } else { *x });
    }
    v
}

proptest! {
    #[test]
    fn every_notation_round_trips_through_the_report(
        seed in proptest::array::uniform21(-50.0f64..50.0),
        lt in 1.0f64..5.0,
    ) {
        let r = report_values(seed);
        let p = [lt];
        for n in Notation::all() {
            let theirs = n.from_report(&r, &p).unwrap();
            let back = n.to_report(&theirs, &p).unwrap();
            for i in 0..N_ROWS {
                if n.names()[i].is_some() {
                    let (a, b) = (r[i].unwrap(), back[i].expect("defined row comes back"));
                    prop_assert!((a - b).abs() <= 1e-14 * (1.0 + a.abs()), "{} row {}: {a} → {b}", n.name(), tables::ROWS[i]);
                }
            }
        }
    }

    #[test]
    fn conversions_between_any_pair_round_trip(
        seed in proptest::array::uniform21(-50.0f64..50.0),
        lt in 1.0f64..5.0,
    ) {
        let r = report_values(seed);
        let p = [lt];
        for x in Notation::all() {
            let vx = x.from_report(&r, &p).unwrap();
            for y in Notation::all() {
                let vy = x.convert(y, &vx, &p).unwrap();
                let vx2 = y.convert(x, &vy, &p).unwrap();
                for i in 0..N_ROWS {
                    if let (Some(a), Some(b)) = (vx[i], vx2[i]) {
                        prop_assert!((a - b).abs() <= 1e-14 * (1.0 + a.abs()), "{} → {} → {}: row {}", x.name(), y.name(), x.name(), tables::ROWS[i]);
                    }
                    // nothing is lost through a notation that defines every
                    // row the first one does, from what the first one gives
                    // (American's C_L/C_D form defines C_xu's row as C_Du,
                    // which needs C_D, a row the C_x/C_z form lacks)
                    let superset = (0..N_ROWS).all(|k| x.names()[k].is_none() || vy[k].is_some());
                    if superset && x.names()[i].is_some() {
                        prop_assert!(vx2[i].is_some(), "{} ↔ {} lost row {}", x.name(), y.name(), tables::ROWS[i]);
                    }
                }
            }
        }
    }
}

#[test]
fn factors_by_hand() {
    let garner = Notation::named("garner").unwrap();
    let american = Notation::named("american").unwrap();
    let mut g = [None; N_ROWS];
    let at = |n: &str| row(n).unwrap();
    g[at("z_w")] = Some(-1.5); // ρ instead of ½ρ: report z_w = 2·(−1.5)
    g[at("m_q")] = Some(-0.8); // and c̄ₛ = ¾c̄: report m_q = 2·(9/16)·(−0.8) = −0.9
    g[at("mu")] = Some(40.0); // report μ₁ = 2·¾·40 = 60
    let r = garner.to_report(&g, &[1.0]).unwrap();
    assert_eq!(r[at("z_w")], Some(-3.0));
    assert_eq!(r[at("m_q")], Some(-0.9));
    assert_eq!(r[at("mu")], Some(60.0));
    // American z_u = C_zu − 2C_W0 (trim term); z_q = C_zq/2
    let mut a = [None; N_ROWS];
    a[at("z_u")] = Some(-0.1);
    a[at("c_l")] = Some(0.5);
    a[at("z_q")] = Some(-6.0);
    let r = american.to_report(&a, &[1.0]).unwrap();
    assert_eq!(r[at("z_u")], Some(-1.1));
    assert_eq!(r[at("z_q")], Some(-3.0));
}

/// B. Etkin & L.D. Reid, *Dynamics of flight: stability and control*, 3rd
/// ed., Wiley 1996: the Boeing 747 in cruise at 40 000 ft, M = 0.8 (§6.2,
/// Table 6.1, non-dimensional stability-axis derivatives, rates per qc̄/2V),
/// W = 2.83176e6 N, I_y = 0.449e8 kg·m², ρ = 0.3045 kg/m³, V = 235.9 m/s,
/// S = 511 m², c̄ = 8.324 m; published roots λ₁,₂ = −0.3719 ± 0.8875i,
/// λ₃,₄ = −0.003289 ± 0.06723i (1/s).
#[test]
fn the_boeing_747_of_etkin_and_reid() {
    let american = Notation::named("american").unwrap();
    let (rho, v, s, c, iy) = (0.3045, 235.9, 511.0, 8.324, 0.449e8);
    let mass = 2.83176e6 / 9.81;
    let c_w0 = 2.83176e6 / (0.5 * rho * v * v * s); // 0.654
    let mut a = [None; N_ROWS];
    let at = |n: &str| row(n).unwrap();
    for (name, x) in [
        ("x_u", -0.1080),
        ("x_w", 0.2193),
        ("z_u", -0.1060),
        ("z_w", -4.920),
        ("z_wdot", 5.896),
        ("z_q", -5.921),
        ("m_u", 0.1043),
        ("m_w", -1.023),
        ("m_wdot", -6.314),
        ("m_q", -23.92),
        ("c_l", c_w0),
        ("x_wdot", 0.0),
        ("x_q", 0.0),
    ] {
        a[at(name)] = Some(x);
    }
    let mut r = american.to_report(&a, &[1.0]).unwrap();
    r[at("mu")] = Some(mass / (0.5 * rho * s * c));
    r[at("i_b")] = Some(iy / (mass * c * c));
    let d = derivatives_from_report(&r).unwrap();
    let tau = mass / (0.5 * rho * s * v);
    let an = Analysis::of(&d).unwrap();
    let sp = an.modes.short_period().unwrap();
    let ph = an.modes.phugoid().unwrap();
    let close = |got: f64, want: f64, rel: f64| {
        assert!((got - want).abs() <= rel * want.abs(), "{got} vs {want}")
    };
    close(sp.re / tau, -0.3719, 0.002);
    close(sp.im / tau, 0.8875, 0.002);
    close(ph.re / tau, -0.003289, 0.002);
    close(ph.im / tau, 0.06723, 0.002);
}

/// Fuzzing found `convert` writing `C_Lq = -inf` with exit 0: a conversion
/// whose result is not finite is an error naming the quantity, in the
/// target notation; so is a non-finite input.
#[test]
fn a_conversion_never_returns_a_non_finite_value() {
    use stability_core::data::notation::{NotationError, report_values};
    use stability_core::design::examples::tailless_delta_45;
    let ribner = Notation::named("ribner").unwrap();
    let mut d = tailless_delta_45();
    d.z_q = 1e308; // C_Lq = −2z_q overflows
    let e = ribner.from_report(&report_values(&d), &[1.0]).unwrap_err();
    assert_eq!(
        e,
        NotationError::Overflow {
            notation: "ribner",
            quantity: "C_Lq",
            value: f64::NEG_INFINITY
        }
    );
    let m = e.to_string();
    assert!(
        m.contains("C_Lq") && m.contains("ribner") && m.contains("-inf"),
        "{m}"
    );
    // the same derivative set converts where the factors allow it
    assert!(
        ribner
            .from_report(&report_values(&tailless_delta_45()), &[1.0])
            .is_ok()
    );
    // non-finite inputs are named in the notation they are given in
    let mut v = report_values(&tailless_delta_45());
    v[row("m_q").unwrap()] = Some(f64::NAN);
    let e = Notation::REPORT.convert(ribner, &v, &[1.0]).unwrap_err();
    assert!(
        matches!(e, NotationError::NonFiniteInput { notation: "report", quantity, .. } if quantity == Notation::REPORT.name_of(row("m_q").unwrap())),
        "{e}"
    );
    let e = ribner.to_report(&report_values(&tailless_delta_45()), &[f64::INFINITY]);
    assert!(
        matches!(e, Err(NotationError::NonFiniteInput { .. })),
        "{e:?}"
    );
}
