//! Accuracy of `roots::solve_quartic` against reference roots computed at
//! 60 digits by mpmath from the same f64 coefficients
//! (`scripts/quartic_reference.py` → `tests/data/quartic_reference.csv`).
//!
//! Error of a case: the largest relative error over its four roots, after
//! matching computed to reference roots by the best of the 24 pairings
//! (Orellana & De Michele's measure). Run with `--nocapture` for the table.

use num_complex::Complex64;
use stability_core::roots::solve_quartic;

struct Case {
    set: String,
    name: String,
    coeffs: [f64; 5],
    roots: [Complex64; 4],
}

/// Split one CSV line (quoted fields allowed).
fn fields(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                cur.push('"');
                chars.next();
            }
            ('"', _) => quoted = !quoted,
            (',', false) => out.push(std::mem::take(&mut cur)),
            _ => cur.push(c),
        }
    }
    out.push(cur);
    out
}

fn cases() -> Vec<Case> {
    let text = include_str!("data/quartic_reference.csv");
    text.lines()
        .skip(1)
        .map(|line| {
            let f = fields(line);
            let num = |i: usize| {
                f[i].parse::<f64>()
                    .unwrap_or_else(|e| panic!("{line}: field {i}: {e}"))
            };
            Case {
                set: f[0].clone(),
                name: f[1].clone(),
                coeffs: [num(2), num(3), num(4), num(5), num(6)],
                roots: std::array::from_fn(|k| Complex64::new(num(7 + 2 * k), num(8 + 2 * k))),
            }
        })
        .collect()
}

/// The largest relative error after the best pairing. A zero reference
/// root is measured against the largest root's modulus.
fn case_error(got: &[Complex64; 4], want: &[Complex64; 4]) -> f64 {
    let scale = want
        .iter()
        .map(|z| z.norm())
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let rel =
        |g: Complex64, w: Complex64| (g - w).norm() / if w.norm() > 0.0 { w.norm() } else { scale };
    let mut best = f64::INFINITY;
    let mut perm = [0, 1, 2, 3];
    // Heap's algorithm over the 24 permutations.
    let mut c = [0usize; 4];
    let mut eval = |p: &[usize; 4]| {
        let e = (0..4).map(|i| rel(got[p[i]], want[i])).fold(0.0, f64::max);
        best = best.min(e);
    };
    eval(&perm);
    let mut i = 0;
    while i < 4 {
        if c[i] < i {
            if i % 2 == 0 {
                perm.swap(0, i)
            } else {
                perm.swap(c[i], i)
            }
            eval(&perm);
            c[i] += 1;
            i = 0;
        } else {
            c[i] = 0;
            i += 1;
        }
    }
    best
}

/// The condition number of each reference root:
/// κ = Σ|cₖ||r|^(4−k) / (|r|·|P′(r)|) — the relative forward error per unit
/// relative backward error.
fn condition(coeffs: &[f64; 5], r: Complex64) -> f64 {
    let n = r.norm();
    let abs_sum: f64 = coeffs
        .iter()
        .enumerate()
        .map(|(k, c)| c.abs() * n.powi(4 - k as i32))
        .sum();
    let dp = ((r * (4.0 * coeffs[0]) + 3.0 * coeffs[1]) * r + 2.0 * coeffs[2]) * r + coeffs[3];
    if n == 0.0 {
        1.0
    } else {
        abs_sum / (n * dp.norm())
    }
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

#[test]
fn random_sets_meet_the_targets() {
    let all = cases();
    println!(
        "{:<14} {:>6} {:>12} {:>12} {:>12}",
        "set", "cases", "median", "90%", "worst"
    );
    for set in [
        "real4",
        "pair_real2",
        "pairs2",
        "real4_s",
        "pair_real2_s",
        "pairs2_s",
        "stability",
    ] {
        let mut errs: Vec<f64> = all
            .iter()
            .filter(|c| c.set == set)
            .map(|c| {
                let got =
                    solve_quartic(c.coeffs).unwrap_or_else(|e| panic!("{set} {}: {e}", c.name));
                case_error(&got, &c.roots)
            })
            .collect();
        let n = errs.len();
        assert!(n >= 400, "{set}: {n} cases");
        let med = median(&mut errs);
        let p90 = errs[n * 9 / 10];
        let worst = errs[n - 1];
        println!("{set:<14} {n:>6} {med:>12.3e} {p90:>12.3e} {worst:>12.3e}");
        assert!(med <= 1e-14, "{set}: median {med:e}");
        assert!(worst <= 1e-12, "{set}: worst {worst:e}");
    }
}

#[test]
fn hard_cases_are_as_accurate_as_their_conditioning_allows() {
    println!("{:<48} {:>11} {:>11}", "hard case", "error", "ε·κ_max");
    for c in cases().iter().filter(|c| c.set == "hard") {
        let got = solve_quartic(c.coeffs).unwrap_or_else(|e| panic!("{}: {e}", c.name));
        assert!(
            got.iter().all(|z| z.re.is_finite() && z.im.is_finite()),
            "{}",
            c.name
        );
        let err = case_error(&got, &c.roots);
        let kappa = c
            .roots
            .iter()
            .map(|&r| condition(&c.coeffs, r))
            .fold(0.0, f64::max);
        println!(
            "{:<48} {err:>11.3e} {:>11.3e}",
            c.name,
            f64::EPSILON * kappa
        );
        // Simple roots, however clustered (κ up to 1e11 here): the compensated
        // polish makes them accurate to ~ε + κε², so 1e-14 whatever κ. A
        // multiple root (κ = ∞): the ε^(1/m) law would allow 2ε^(1/4); these
        // exact multiple roots come back exactly, but only the law is promised.
        let bound = if kappa.is_finite() {
            1e-14
        } else {
            2.0 * f64::EPSILON.powf(0.25)
        };
        assert!(err <= bound, "{}: error {err:e} > bound {bound:e}", c.name);
    }
}
