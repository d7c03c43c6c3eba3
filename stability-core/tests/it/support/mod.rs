//! Shared by the root-accuracy tests: the reference CSVs written by
//! `scripts/quartic_reference.py` and `scripts/badly_scaled_reference.py`,
//! and the error measure.

use num_complex::Complex64;

pub struct Case {
    pub set: String,
    pub name: String,
    pub coeffs: [f64; 5],
    pub roots: [Complex64; 4],
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

/// The cases of a reference CSV's text.
pub fn cases(text: &str) -> Vec<Case> {
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
pub fn case_error(got: &[Complex64; 4], want: &[Complex64; 4]) -> f64 {
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
