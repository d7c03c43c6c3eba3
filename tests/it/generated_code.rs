//! The generated code as a reviewer reads it — `docs/generated/*.rs.txt`,
//! written by `cargo xtask regen` — compiled here as it is, so that `cargo
//! clippy --workspace --all-targets` lints it with no allowance, and checked
//! to compute, bit for bit, what the macros' expansions in stability-core
//! compute. (That the files are up to date is xtask's
//! `generated_artefacts_are_up_to_date`.)

use stability_core::Derivatives;
use stability_core::data::notation::tables;
use workspace_tests::{SplitMix64, random_derivatives};

/// What `#[derive(Quartic)]` emits, on a struct with the spec's inputs.
mod reviewed_quartic {
    #[derive(Clone, Copy)]
    pub struct Derivatives {
        pub x_u: f64,
        pub x_w: f64,
        pub x_wdot: f64,
        pub x_q: f64,
        pub z_u: f64,
        pub z_w: f64,
        pub z_wdot: f64,
        pub z_q: f64,
        pub m_u: f64,
        pub m_w: f64,
        pub m_wdot: f64,
        pub m_q: f64,
        pub c_l: f64,
        pub mu1: f64,
        pub i_b: f64,
    }

    include!("../../docs/generated/quartic.rs.txt");
}

/// What `#[derive(Quartic)]` emits for the general dimensional model
/// (stability-core/specs/dimensional.toml).
mod reviewed_dimensional {
    #[derive(Clone, Copy)]
    pub struct DescriptorSystem {
        pub x_u: f64,
        pub x_w: f64,
        pub x_wdot: f64,
        pub x_udot: f64,
        pub x_q: f64,
        pub z_u: f64,
        pub z_w: f64,
        pub z_wdot: f64,
        pub z_udot: f64,
        pub z_q: f64,
        pub m_u: f64,
        pub m_w: f64,
        pub m_wdot: f64,
        pub m_udot: f64,
        pub m_q: f64,
        pub u0: f64,
        pub w0: f64,
        pub g_cos: f64,
        pub g_sin: f64,
    }

    include!("../../docs/generated/dimensional.rs.txt");
}

/// What `notations!` emits.
mod reviewed_notation {
    include!("../../docs/generated/notation.rs.txt");
}

fn bits<const N: usize>(v: [f64; N]) -> [u64; N] {
    v.map(f64::to_bits)
}

#[test]
fn the_reviewed_quartic_code_is_the_compiled_code() {
    use reviewed_quartic::Derivatives as Reviewed;
    assert_eq!(Reviewed::QUARTIC_INPUTS, Derivatives::QUARTIC_INPUTS);
    assert_eq!(
        Reviewed::QUARTIC_COEFFICIENTS,
        Derivatives::QUARTIC_COEFFICIENTS
    );
    let mut rng = SplitMix64(0x0C0D_E6E2);
    for _ in 0..200 {
        let d = random_derivatives(&mut rng);
        let r = Reviewed::from_quartic_input_values(d.quartic_input_values());
        assert_eq!(
            bits(r.quartic_input_values()),
            bits(d.quartic_input_values())
        );
        assert_eq!(
            bits(r.quartic_coefficients()),
            bits(d.quartic_coefficients())
        );
        // the generic program (the p-method's complex derivatives) over f64
        assert_eq!(
            bits(Reviewed::quartic_coefficients_of(d.quartic_input_values())),
            bits(Derivatives::quartic_coefficients_of(
                d.quartic_input_values()
            ))
        );
        let (rg, dg) = (r.quartic_gradient(), d.quartic_gradient());
        for (a, b) in rg.into_iter().zip(dg) {
            assert_eq!(bits(a), bits(b));
        }
    }
}

#[test]
fn the_reviewed_dimensional_code_is_the_compiled_code() {
    use reviewed_dimensional::DescriptorSystem as Reviewed;
    use stability_core::data::dimensional::DescriptorSystem;
    assert_eq!(Reviewed::QUARTIC_INPUTS, DescriptorSystem::QUARTIC_INPUTS);
    assert_eq!(
        Reviewed::QUARTIC_COEFFICIENTS,
        DescriptorSystem::QUARTIC_COEFFICIENTS
    );
    let mut rng = SplitMix64(0x00D1_3E75);
    for _ in 0..200 {
        let v: [f64; 19] = std::array::from_fn(|_| {
            let m = rng.log_uniform(1e-4, 1e3);
            if rng.unit() < 0.5 { -m } else { m }
        });
        let (r, d) = (
            Reviewed::from_quartic_input_values(v),
            DescriptorSystem::from_quartic_input_values(v),
        );
        assert_eq!(bits(r.quartic_input_values()), bits(v));
        assert_eq!(
            bits(r.quartic_coefficients()),
            bits(d.quartic_coefficients())
        );
        assert_eq!(
            bits(Reviewed::quartic_coefficients_of(v)),
            bits(DescriptorSystem::quartic_coefficients_of(v))
        );
        for (a, b) in r.quartic_gradient().into_iter().zip(d.quartic_gradient()) {
            assert_eq!(bits(a), bits(b));
        }
    }
}

/// Values of every row (positive where a quantity must be), with some
/// missing.
fn row_values(rng: &mut SplitMix64) -> [Option<f64>; tables::ROWS.len()] {
    std::array::from_fn(|_| (rng.unit() > 0.1).then(|| rng.log_uniform(0.01, 10.0)))
}

#[test]
fn the_reviewed_notation_code_is_the_compiled_code() {
    use reviewed_notation as reviewed;
    assert_eq!(reviewed::ROWS, tables::ROWS);
    assert_eq!(reviewed::ROW_DOCS, tables::ROW_DOCS);
    assert_eq!(reviewed::NOTATIONS, tables::NOTATIONS);
    assert_eq!(reviewed::TITLES, tables::TITLES);
    assert_eq!(reviewed::NAMES, tables::NAMES);
    assert_eq!(reviewed::PARAMETERS, tables::PARAMETERS);
    let mut rng = SplitMix64(0x0C0D_E6E3);
    let same = |a: [Option<f64>; 21], b: [Option<f64>; 21]| {
        a.map(|x| x.map(f64::to_bits)) == b.map(|x| x.map(f64::to_bits))
    };
    for _ in 0..100 {
        let values = row_values(&mut rng);
        let parameters = [rng.uniform(1.0, 5.0)];
        for k in 0..=tables::NOTATIONS.len() {
            let to = reviewed::to_report(k, &values, &parameters);
            assert!(
                same(to, tables::to_report(k, &values, &parameters)),
                "notation {k}"
            );
            let from = reviewed::from_report(k, &values, &parameters);
            assert!(
                same(from, tables::from_report(k, &values, &parameters)),
                "notation {k}"
            );
        }
    }
}

#[test]
fn a_conversion_needing_an_absent_value_has_none() {
    // Perkins & Hage's m_ẇ is μ·C_mα̇: without μ there is no report m_ẇ.
    let perkins = tables::NOTATIONS
        .iter()
        .position(|n| *n == "perkins")
        .unwrap();
    let row = |name: &str| tables::ROWS.iter().position(|r| *r == name).unwrap();
    let mut values = [None; 21];
    values[row("m_wdot")] = Some(-0.4);
    assert_eq!(
        tables::to_report(perkins, &values, &[1.0])[row("m_wdot")],
        None
    );
    values[row("mu")] = Some(25.0);
    let m_wdot = tables::to_report(perkins, &values, &[1.0])[row("m_wdot")];
    assert_eq!(m_wdot, Some(-0.4 * 25.0));
}
