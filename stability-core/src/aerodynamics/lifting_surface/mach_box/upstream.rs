//! The earlier rows' part of the potential at a row's boxes: the march's
//! causal convolution.
//!
//! The influence of box (i′, j′) on box (i, j) depends on (i − i′, j − j′)
//! alone ([`super::influence`]), so with the mirror images of the half
//! wing's boxes (the symmetric motion) the earlier rows' sum is
//!
//! b(i, j) = Σ_{m=1}^{i} Σ_{j′} s(i − m, j′)·[C(m, j − j′) + C(m, j + j′)·(j′ ≥ 1)],
//!
//! a two-dimensional convolution, causal in the rows, whose sources s of
//! row i are known only once b of row i is (the diaphragm's normalwash
//! makes the potential there vanish, [`super::march`]): an *online*
//! convolution. [`Method::Direct`] sums it term by term, O(N²) for N boxes;
//! [`Method::Relaxed`] by fast transforms ([`Relaxed`]), O(N log² N).

use super::grid::Grid;
use super::influence::{Influence, Pair};
use num_complex::Complex64;
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

/// How the march sums the earlier rows' influence (the same numbers to
/// rounding: `tests/supersonic_oscillatory.rs` compares them).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// Term by term, [`direct`]: O(N²) over N boxes; the reference.
    Direct,
    /// By the relaxed (online) FFT convolution of [`Relaxed`].
    #[default]
    Relaxed,
}

/// b(i, j) by direct summation over the earlier rows, with the mirror
/// image of each box; `spans` bounds each row's non-zero sources
/// (`spans.len()` = i).
pub fn direct(
    grid: &Grid,
    table: &Influence,
    (source, spans): (&[Pair], &[(usize, usize)]),
    i: usize,
    j: usize,
) -> Pair {
    let mut sum = [Complex64::default(); 2];
    for (ip, &(slo, shi)) in spans.iter().enumerate().take(i) {
        if slo > shi {
            continue;
        }
        let m = i - ip;
        let c = table.row(m);
        let row = &source[ip * grid.columns..(ip + 1) * grid.columns];
        let (lo, hi) = (j.saturating_sub(m).max(slo), (j + m).min(shi));
        // ahead and inboard of the receiver: C(m, j − j′), j′ ≤ j
        if lo <= j.min(hi) {
            let a = j.min(hi);
            accumulate(&row[lo..=a], c[j - a..=j - lo].iter().rev(), &mut sum);
        }
        // outboard: C(m, j′ − j), j′ > j
        let b = (j + 1).max(lo);
        if b <= hi {
            accumulate(&row[b..=hi], c[b - j..=hi - j].iter(), &mut sum);
        }
        // mirror images at −j′, j′ ≥ 1: offset j + j′ ≤ m
        let (mlo, mhi) = (slo.max(1), (m.saturating_sub(j)).min(shi));
        if mlo <= mhi {
            accumulate(&row[mlo..=mhi], c[j + mlo..=j + mhi].iter(), &mut sum);
        }
    }
    sum
}

/// sum += Σ sources × coefficients, term by term.
#[inline]
fn accumulate<'a>(
    sources: &[Pair],
    coefficients: impl Iterator<Item = &'a Complex64>,
    sum: &mut Pair,
) {
    let (mut s0, mut s1) = (sum[0], sum[1]);
    for (s, &c) in sources.iter().zip(coefficients) {
        s0 += s[0] * c;
        s1 += s[1] * c;
    }
    *sum = [s0, s1];
}

/// Lags below this are summed by direct products of the spanwise
/// transforms; lags [L, 2L), L = DIRECT_LAGS·2ᵏ, by one block product each.
const DIRECT_LAGS: usize = 8;

/// The online convolution b of the module doc by fast transforms.
///
/// Spanwise, each row's sources (with their mirror images at −j′) and each
/// row of the kernel C(m, ·) are transformed once, on P ≥ columns + 2·lags
/// points, so that the cyclic convolution is the linear one on every
/// column used; the rows' convolution is then, at each spanwise frequency,
/// a one-dimensional online product with a kernel known in advance — the
/// semi-relaxed multiplication of J. van der Hoeven ("Relax, but don't be
/// too lazy", J. Symbolic Comput. 34(6), 2002, §4), the zero-delay block
/// convolution of W.G. Gardner ("Efficient convolution without
/// input-output delay", J. Audio Eng. Soc. 43(3), 1995): lags below
/// `DIRECT_LAGS` (8) by direct products, and the lags [L, 2L) for
/// L = 8·2ᵏ by one FFT product of length 2L of the kernel's
/// block with each aligned block of L source rows, done as soon as the
/// block's last row is known — L rows before the first row it reaches.
/// Each (source row, lag) pair falls in exactly one product.
///
/// All buffers are made by [`Relaxed::new`]: [`Relaxed::row`] and
/// [`Relaxed::push`] allocate nothing. Rows never pushed count as empty
/// (the march makes it at its first row with a source).
pub struct Relaxed {
    rows: usize,
    /// P, the spanwise transforms' length.
    span: usize,
    forward: Arc<dyn Fft<f64>>,
    inverse: Arc<dyn Fft<f64>>,
    /// The spanwise transforms of C(m, ·)/P, m = 1..DIRECT_LAGS,
    /// frequency-major (P × (DIRECT_LAGS − 1)).
    near: Vec<Complex64>,
    levels: Vec<Level>,
    /// Each right-hand side's transformed source rows, frequency-major
    /// (P × rows: a block of rows at one frequency is contiguous).
    history: [Vec<Complex64>; 2],
    /// Each right-hand side's sums of the block products still to be
    /// used, by target row, frequency-major (P × rows).
    pending: [Vec<Complex64>; 2],
    /// Whether each pushed row has a non-zero source.
    active: Vec<bool>,
    /// The block products' work space (P × 2L for the largest L).
    block: Vec<Complex64>,
    /// One spanwise row's work space.
    line: Vec<Complex64>,
    scratch: Vec<Complex64>,
}

/// The lags [length, 2·length) of the kernel: at each spanwise frequency p,
/// the transform of length 2L of C(length + b, ·)/P, b < L, over 2L.
struct Level {
    length: usize,
    /// P × 2L, frequency-major.
    kernel: Vec<Complex64>,
    forward: Arc<dyn Fft<f64>>,
    inverse: Arc<dyn Fft<f64>>,
}

/// The least n ≥ `at_least` of the form 2ᵃ3ᵇ5ᶜ (a fast FFT length).
fn fast_length(at_least: usize) -> usize {
    (at_least.max(1)..)
        .find(|&n| {
            let mut k = n;
            for f in [2, 3, 5] {
                while k.is_multiple_of(f) {
                    k /= f;
                }
            }
            k == 1
        })
        .unwrap_or(at_least)
}

impl Relaxed {
    /// The kernel's transforms and every buffer for `grid` and `table`.
    pub fn new(grid: &Grid, table: &Influence) -> Relaxed {
        let rows = grid.rows;
        // the largest lag used: row rows − 1 sees row 0
        let lags = rows.saturating_sub(1);
        let span = fast_length(grid.columns + 2 * lags);
        let mut planner = FftPlanner::new();
        let forward = planner.plan_fft_forward(span);
        let inverse = planner.plan_fft_inverse(span);
        let mut scratch: Vec<Complex64> = Vec::new();
        let kernel_row = |m: usize, out: &mut [Complex64], scratch: &mut Vec<Complex64>| {
            out.fill(Complex64::default());
            if (1..=lags).contains(&m) {
                let scale = 1.0 / span as f64;
                for (n, &c) in table.row(m).iter().enumerate() {
                    out[n] = c * scale;
                    if n > 0 {
                        out[span - n] = c * scale;
                    }
                }
            }
            scratch.resize(forward.get_inplace_scratch_len(), Complex64::default());
            forward.process_with_scratch(out, scratch);
        };
        let mut line = vec![Complex64::default(); span];
        let mut near = vec![Complex64::default(); (DIRECT_LAGS - 1) * span];
        for m in 1..DIRECT_LAGS {
            kernel_row(m, &mut line, &mut scratch);
            for (q, &v) in line.iter().enumerate() {
                near[q * (DIRECT_LAGS - 1) + m - 1] = v;
            }
        }
        let mut levels = Vec::new();
        let mut length = DIRECT_LAGS;
        while length <= lags {
            let twice = 2 * length;
            let lf = planner.plan_fft_forward(twice);
            let li = planner.plan_fft_inverse(twice);
            let mut kernel = vec![Complex64::default(); span * twice];
            for b in 0..length {
                kernel_row(length + b, &mut line, &mut scratch);
                for (p, &v) in line.iter().enumerate() {
                    kernel[p * twice + b] = v / twice as f64;
                }
            }
            scratch.resize(lf.get_inplace_scratch_len(), Complex64::default());
            lf.process_with_scratch(&mut kernel, &mut scratch);
            levels.push(Level {
                length,
                kernel,
                forward: lf,
                inverse: li,
            });
            length = twice;
        }
        let widest = levels.last().map_or(0, |l| 2 * l.length);
        let most_scratch = levels
            .iter()
            .flat_map(|l| {
                [
                    l.forward.get_inplace_scratch_len(),
                    l.inverse.get_inplace_scratch_len(),
                ]
            })
            .chain([
                forward.get_inplace_scratch_len(),
                inverse.get_inplace_scratch_len(),
            ])
            .max()
            .unwrap_or(0);
        scratch.resize(most_scratch, Complex64::default());
        let zeros = || vec![Complex64::default(); rows * span];
        Relaxed {
            rows,
            span,
            forward,
            inverse,
            near,
            levels,
            history: [zeros(), zeros()],
            pending: [zeros(), zeros()],
            active: vec![false; rows],
            block: vec![Complex64::default(); span * widest],
            line,
            scratch,
        }
    }

    /// b(i, j) for j < `out.len()`, once rows 0..i are pushed.
    pub fn row(&mut self, i: usize, out: &mut [Pair]) {
        let (rows, lags) = (self.rows, DIRECT_LAGS.min(i + 1) - 1);
        let any = self.active[i - lags..i].iter().any(|&a| a);
        for r in 0..2 {
            let line = &mut self.line;
            let (history, pending) = (&self.history[r], &self.pending[r]);
            let near = self.near.chunks_exact(DIRECT_LAGS - 1);
            for (q, (l, k)) in line.iter_mut().zip(near).enumerate() {
                *l = pending[q * rows + i];
                if any {
                    // C(m)·s(i − m), m = 1..=lags
                    let s = &history[q * rows + i - lags..q * rows + i];
                    for (&k, &s) in k[..lags].iter().zip(s.iter().rev()) {
                        *l += k * s;
                    }
                }
            }
            self.inverse.process_with_scratch(line, &mut self.scratch);
            for (o, &v) in out.iter_mut().zip(line.iter()) {
                o[r] = v;
            }
        }
    }

    /// Row i's sources (`sources[j]`, column j; none beyond), now known:
    /// their transform, and every block product whose last row is i.
    pub fn push(&mut self, i: usize, sources: &[Pair]) {
        let (p, rows) = (self.span, self.rows);
        let lags = rows.saturating_sub(1);
        self.active[i] = sources
            .iter()
            .any(|s| s[0].norm() > 0.0 || s[1].norm() > 0.0);
        // an empty row's transform stays zero, as made
        for r in (0..2).filter(|_| self.active[i]) {
            let h = &mut self.line;
            h.fill(Complex64::default());
            for (j, s) in sources.iter().enumerate() {
                h[j] += s[r];
                // the mirror image at −j (it reaches back to j′ = 0
                // only from |j| ≤ the largest lag)
                if j > 0 && j <= lags {
                    h[p - j] += s[r];
                }
            }
            self.forward.process_with_scratch(h, &mut self.scratch);
            for (q, &v) in h.iter().enumerate() {
                self.history[r][q * rows + i] = v;
            }
        }
        for level in 0..self.levels.len() {
            let length = self.levels[level].length;
            if (i + 1).is_multiple_of(length) && i + 1 < self.rows {
                self.block_product(level, i + 1 - length);
            }
        }
    }

    /// The product of source rows start..start + L with the kernel's lags
    /// [L, 2L), added to the target rows start + L… it reaches.
    fn block_product(&mut self, level: usize, start: usize) {
        let Level {
            length,
            kernel,
            forward,
            inverse,
        } = &self.levels[level];
        let (length, p, rows) = (*length, self.span, self.rows);
        if !self.active[start..start + length].iter().any(|&a| a) {
            return;
        }
        let twice = 2 * length;
        let block = &mut self.block[..p * twice];
        for r in 0..2 {
            for (q, column) in block.chunks_exact_mut(twice).enumerate() {
                let h = &self.history[r][q * rows + start..q * rows + start + length];
                column[..length].copy_from_slice(h);
                column[length..].fill(Complex64::default());
            }
            forward.process_with_scratch(block, &mut self.scratch);
            for (v, &k) in block.iter_mut().zip(kernel.iter()) {
                *v *= k;
            }
            inverse.process_with_scratch(block, &mut self.scratch);
            // output c of the product: row start + L + c
            let first = start + length;
            let reach = (twice - 1).min(rows - first);
            let pending = &mut self.pending[r];
            for (q, column) in block.chunks_exact(twice).enumerate() {
                let target = &mut pending[q * rows + first..q * rows + first + reach];
                for (t, &v) in target.iter_mut().zip(column) {
                    *t += v;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Trapezoid;

    /// The relaxed convolution equals the direct sum, box by box, for
    /// sources that fill every box of every row (a grid of 40 rows: all
    /// four block levels and the direct lags), each row pushed only after
    /// its own sums are read, as the march does.
    #[test]
    fn the_relaxed_convolution_is_the_direct_sum() {
        let w = Trapezoid::new(1.0, 0.3, 0.8, 50f64.to_radians()).unwrap();
        let grid = Grid::new(&w, 1.1, 30);
        assert!(grid.rows > 4 * DIRECT_LAGS, "{}", grid.rows);
        let table = Influence::new(grid.rows, 0.4, 0.3);
        let mut relaxed = Relaxed::new(&grid, &table);
        let (rows, columns) = (grid.rows, grid.columns);
        let mut source = vec![[Complex64::default(); 2]; rows * columns];
        let mut spans = vec![(usize::MAX, 0usize); rows];
        let mut out = vec![[Complex64::default(); 2]; columns];
        let mut worst: f64 = 0.0;
        for i in 0..rows {
            relaxed.row(i, &mut out);
            for (j, got) in out.iter().enumerate() {
                let want = direct(&grid, &table, (&source, &spans[..i]), i, j);
                for r in 0..2 {
                    let scale = want[r].norm().max(1.0);
                    worst = worst.max((got[r] - want[r]).norm() / scale);
                }
            }
            // a smooth but irregular field, the two right-hand sides apart
            for j in 0..columns {
                let (x, y) = (i as f64, j as f64);
                source[i * columns + j] = [
                    Complex64::new((0.3 * x + 0.17 * y).sin(), (0.11 * x * y).cos()),
                    Complex64::new(1.0 / (1.0 + x + y), (0.05 * y).sin()),
                ];
            }
            spans[i] = (0, columns - 1);
            relaxed.push(i, &source[i * columns..(i + 1) * columns]);
        }
        assert!(worst < 1e-12, "{worst}");
    }
}
