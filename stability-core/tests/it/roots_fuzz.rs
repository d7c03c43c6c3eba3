//! Fuzzing the quartic solver (issue 10, item 7): random coefficients over
//! the whole finite f64 range, scaled families of a stability quartic, and
//! clustered and multiple roots. For every quartic `solve_quartic` must
//! either return four roots that
//!
//! - are finite, with every non-real root's exact conjugate among them;
//! - each have a backward error |P(λ)|/Σ|cₖ||λ|^(4−k) within
//!   `roots::TOLERANCE`, evaluated here at the root's own scale (the test's
//!   own evaluation, every term scaled by one power of two);
//! - agree with Routh's test of the same coefficients (stable exactly when
//!   every real part is negative), unless the quartic is on the stability
//!   boundary to working precision: Routh's discriminant within its
//!   rounding error of zero, or a root within `AXIS`·|λ| of the imaginary
//!   axis, where a normwise backward-stable solver cannot resolve the sign
//!   of the real part (B = 0 exactly with roots ±8e69i and a real part of
//!   4e-223 that only the structural zero determines — the corpus has it);
//!
//! or the typed error of roots beyond f64's range (`Overflow`,
//! `Underflow`); never `Inaccurate`. The proptest regression
//! file (`tests/roots_fuzz.proptest-regressions`) and the corpus below (what
//! fuzzing found on the way) run first.
//!
//! A modest case count runs in `cargo test`; `PROPTEST_CASES=100000` runs
//! more.

use num_complex::Complex64;
use proptest::prelude::*;
use stability_core::Quartic;
use stability_core::criteria::Routh;
use stability_core::numerics::roots::{RootsError, TOLERANCE, solve_quartic};

/// |P(z)|/Σ|cₖ||z|^(4−k) with z = 2^k·x, |x| ~ 1, and each term cₘzᵐ
/// divided by a common power of two: no overflow, and no underflow of a
/// term that matters.
fn backward_error(c: &[f64; 5], z: Complex64) -> f64 {
    let big = z.re.abs().max(z.im.abs());
    if big == 0.0 {
        return if c[4] == 0.0 { 0.0 } else { 1.0 };
    }
    let k = big.log2().floor() as i32;
    let x = Complex64::new(scale(z.re, -k), scale(z.im, -k));
    let exps: Vec<i32> = (0..5)
        .filter(|&m| c[m] != 0.0)
        .map(|m| c[m].abs().log2().floor() as i32 + k * (4 - m as i32))
        .collect();
    let top = exps.into_iter().max().unwrap_or(0);
    let mut p = Complex64::new(0.0, 0.0);
    let mut abs = 0.0;
    let n = x.norm();
    for (m, &cm) in c.iter().enumerate() {
        let s = scale(cm, k * (4 - m as i32) - top);
        p = p * x + s;
        abs = abs * n + s.abs();
    }
    if abs == 0.0 { 0.0 } else { p.norm() / abs }
}

/// x·2ⁿ in steps that keep x in range.
fn scale(mut x: f64, mut n: i32) -> f64 {
    while n > 600 {
        x *= 2f64.powi(600);
        n -= 600;
    }
    while n < -600 {
        x *= 2f64.powi(-600);
        n += 600;
    }
    x * 2f64.powi(n)
}

/// |re| ≤ AXIS·|λ|: on the imaginary axis to working precision (see
/// `analysis::ON_AXIS`).
const AXIS: f64 = stability_core::analysis::ON_AXIS;

fn check(c: [f64; 5]) -> Result<(), TestCaseError> {
    match solve_quartic(c) {
        Err(RootsError::LeadingZero) => prop_assert_eq!(c[0], 0.0),
        Err(RootsError::Overflow { .. } | RootsError::Underflow { .. }) => {}
        Err(e) => prop_assert!(false, "{c:?}: {e}"),
        Ok(roots) => {
            for z in roots {
                prop_assert!(z.re.is_finite() && z.im.is_finite(), "{c:?}: {roots:?}");
                let b = backward_error(&c, z);
                prop_assert!(b <= TOLERANCE, "{c:?}: root {z}: backward error {b:e}");
            }
            let mut used = [false; 4];
            for i in 0..4 {
                if roots[i].im != 0.0 && !used[i] {
                    let j = (0..4).find(|&j| j != i && !used[j] && roots[j] == roots[i].conj());
                    prop_assert!(
                        j.is_some(),
                        "{c:?}: {} has no conjugate in {roots:?}",
                        roots[i]
                    );
                    used[i] = true;
                    used[j.unwrap_or(i)] = true;
                }
            }
            let routh = Routh::of(&Quartic::from_array(c));
            let off_axis = roots.iter().all(|z| z.re.abs() > AXIS * z.norm());
            if !routh.marginal && off_axis {
                let decaying = roots.iter().all(|z| z.re < 0.0);
                prop_assert_eq!(
                    routh.stable,
                    decaying,
                    "{:?}: Routh {:?}, roots {:?}",
                    c,
                    routh,
                    roots
                );
            }
        }
    }
    Ok(())
}

/// Any non-zero finite f64, log-uniform in magnitude, either sign.
fn non_zero() -> impl Strategy<Value = f64> {
    (any::<bool>(), 1.0f64..2.0, -1074i32..=1023).prop_map(|(neg, m, e)| {
        let x = scale(m, e);
        let x = if x == 0.0 {
            f64::from_bits(1)
        } else {
            x.min(f64::MAX)
        };
        if neg { -x } else { x }
    })
}

/// Any finite f64, zero sometimes.
fn any_finite() -> impl Strategy<Value = f64> {
    prop_oneof![1 => Just(0.0), 8 => non_zero()]
}

/// The coefficients of (λ − r₁)…(λ − r₄), roots closed under conjugation.
fn from_roots(r: [Complex64; 4]) -> [f64; 5] {
    let mut c = [
        Complex64::new(1.0, 0.0),
        Complex64::new(0.0, 0.0),
        Complex64::new(0.0, 0.0),
        Complex64::new(0.0, 0.0),
        Complex64::new(0.0, 0.0),
    ];
    for (k, root) in r.iter().enumerate() {
        for j in (1..=k + 1).rev() {
            c[j] -= c[j - 1] * root;
        }
    }
    c.map(|z| z.re)
}

/// Roots of a stability quartic's kind, or any kind: two pairs, a pair and
/// two reals, four reals; O(1) to O(100).
fn root_set() -> impl Strategy<Value = [Complex64; 4]> {
    let part = || -20.0f64..20.0;
    prop_oneof![
        (part(), 0.01f64..30.0, part(), 0.001f64..3.0).prop_map(|(a, b, c, d)| {
            [
                Complex64::new(a, b),
                Complex64::new(a, -b),
                Complex64::new(c, d),
                Complex64::new(c, -d),
            ]
        }),
        (part(), 0.01f64..30.0, part(), part()).prop_map(|(a, b, c, d)| {
            [
                Complex64::new(a, b),
                Complex64::new(a, -b),
                Complex64::new(c, 0.0),
                Complex64::new(d, 0.0),
            ]
        }),
        (part(), part(), part(), part())
            .prop_map(|(a, b, c, d)| { [a, b, c, d].map(|x| Complex64::new(x, 0.0)) }),
    ]
}

/// Clustered and multiple roots: a root repeated m times, split by δ
/// (exactly 0 for a multiple root).
fn clustered() -> impl Strategy<Value = [Complex64; 4]> {
    (
        -50.0f64..50.0,
        0.0f64..10.0,
        prop_oneof![Just(0.0), 1e-15f64..1e-6],
        1usize..=3,
    )
        .prop_map(|(re, im, delta, kind)| {
            let r = Complex64::new(re, 0.0);
            let d = Complex64::new(delta * (1.0 + re.abs()), 0.0);
            let p = Complex64::new(re, im + 0.1);
            match kind {
                // a double complex pair
                1 => [p, p.conj(), p + d, (p + d).conj()],
                // a triple real root and one more
                2 => [r, r + d, r - d, Complex64::new(-1.0, 0.0)],
                // a quadruple real root
                _ => [r, r + d, r + d + d, r - d],
            }
        })
}

/// ρ⁴…ρ⁰ and an overall σ: λ → ρλ, every coefficient times σ.
fn scaled(c: [f64; 5], rho_exp: i32, sigma_exp: i32) -> Option<[f64; 5]> {
    let out: [f64; 5] =
        std::array::from_fn(|k| scale(scale(c[k], rho_exp * (4 - k as i32)), sigma_exp));
    out.iter().all(|v| v.is_finite()).then_some(out)
}

/// What fuzzing found on the way, and the cases: run first, every
/// time.
const CORPUS: [[f64; 5]; 9] = [
    // i_B = 1e308 (a divergent slow pair, r = +1.3e-306, s = 4.5e-154)
    [1.012, 3.23036, 0.251, 9.9735e-309, 5.114999999999999e-308],
    // i_B = 1e-160 (three roots lost below the scaling's range)
    [
        1.012,
        8.497e159,
        2.8620491000000003e161,
        9.973500000000001e159,
        5.1150000000000006e160,
    ],
    // x_ẇ = 1e250: a pair with r = −2.1e-249 beside s = 2.6e-124
    [1.012, 1.24e248, 9.3e248, 12.466875000000002, 63.9375],
    // x_u = 1e250: roots 1e250 and 1.8e-251 beside the short period
    [
        1.012,
        -1.0119999999999999e250,
        -1.382125e251,
        -3.5743750000000003e252,
        63.9375,
    ],
    // A tiny, E large: roots of 1e100 whose ratios E/A overflow
    [1e-300, 0.0, 0.0, 0.0, 1e100],
    // every coefficient subnormal
    [5e-324, 1e-320, -3e-322, 2e-315, 7e-310],
    // a subnormal root, 1.1e-308, beside three of 6e24
    [
        1.0,
        0.0,
        0.0,
        2.261564242916332e74,
        -2.5160737381238802e-234,
    ],
    // two exact zero roots, −1.85e78 and −5.2e-54 (whose terms underflow
    // at the scale of the first)
    [
        3.777893186295716e22,
        6.999202319305638e100,
        3.6537540933272573e47,
        0.0,
        0.0,
    ],
    // B = 0: roots ±8.1e69i and ±1.9e-80i with real parts ∓4.3e-223
    [
        -4.326223218342334e19,
        0.0,
        -2.8560607135073913e159,
        -2.4308653429145085e-63,
        -1.0,
    ],
];

#[test]
fn the_corpus() {
    for c in CORPUS {
        check(c).unwrap_or_else(|e| panic!("{c:?}: {e}"));
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    #[test]
    fn any_finite_coefficients(a in non_zero(), rest in proptest::array::uniform4(any_finite())) {
        check([a, rest[0], rest[1], rest[2], rest[3]])?;
    }

    #[test]
    fn scaled_families(r in root_set(), a in 0.5f64..2.0, rho in -250i32..250, sigma in -900i32..900) {
        let base = from_roots(r).map(|x| x * a);
        if let Some(c) = scaled(base, rho, sigma) {
            check(c)?;
        }
    }

    #[test]
    fn clustered_and_multiple_roots(r in clustered(), rho in -100i32..100) {
        if let Some(c) = scaled(from_roots(r), rho, 0) {
            check(c)?;
        }
    }
}
