//! The configuration's normalwash matrices, block by block: a surface on
//! itself exactly as the wing's own lattice ([`crate::aerodynamics::lifting_surface`]'s
//! blocked assembly), two surfaces in one plane by the planar doublet line
//! pair by pair, two surfaces at different heights by the non-planar kernel
//! ([`super::nonplanar`]).

use super::layout::Block;
use super::nonplanar::{self, Radial2};
use crate::aerodynamics::lifting_surface::LineRule;
use crate::aerodynamics::lifting_surface::doublet_line::DoubletLine;
use crate::aerodynamics::lifting_surface::kernel::{self, KernelFlow};
use crate::aerodynamics::lifting_surface::lattice::Box;
use crate::aerodynamics::lifting_surface::solve;
use nalgebra::DMatrix;
use num_complex::Complex64;

/// How one receiving block sees one sending block.
enum Pair<'a> {
    Own(&'a Block),
    Planar(&'a Block, &'a Block),
    NonPlanar(&'a Block, &'a Block, f64),
}

/// `fill` for every block pair into its place in the n × n matrix.
fn assemble<T: nalgebra::Scalar + Default>(
    blocks: &[Block],
    fill: impl Fn(&Pair) -> DMatrix<T>,
) -> DMatrix<T> {
    let sizes: Vec<usize> = blocks.iter().map(|b| b.grid.boxes.len()).collect();
    let n = sizes.iter().sum();
    let mut d = DMatrix::from_element(n, n, T::default());
    let mut ro = 0;
    for (i, r) in blocks.iter().enumerate() {
        let mut so = 0;
        for (j, s) in blocks.iter().enumerate() {
            let pair = if i == j {
                Pair::Own(r)
            } else if r.z == s.z {
                Pair::Planar(r, s)
            } else {
                Pair::NonPlanar(r, s, r.z - s.z)
            };
            d.view_mut((ro, so), (sizes[i], sizes[j]))
                .copy_from(&fill(&pair));
            so += sizes[j];
        }
        ro += sizes[i];
    }
    d
}

/// dᵢⱼ = f(line j) + f(mirror of line j) at receiving box i, pair by pair.
fn pairwise<T: nalgebra::Scalar + std::ops::Add<Output = T>>(
    rows: &[Box],
    cols: &[Box],
    f: impl Fn(&DoubletLine, f64, f64) -> T,
) -> DMatrix<T> {
    DMatrix::from_fn(rows.len(), cols.len(), |i, j| {
        let (x, y) = (rows[i].x_c, rows[i].y_c);
        let line = cols[j].line;
        f(&line, x, y) + f(&line.mirrored(), x, y)
    })
}

/// The non-planar line integrals of one block pair: for every strip pair
/// (and the mirror image) the rule's stations and weights
/// ([`nonplanar::rule`]) and `prep` of their distance r are shared by all
/// its boxes; `eval(x₀, prepared)` gives the two numerators.
fn nonplanar_lines<T, R>(
    r: &Block,
    s: &Block,
    z0: f64,
    prep: impl Fn(f64) -> R,
    eval: impl Fn(f64, &R) -> (T, T),
) -> DMatrix<T>
where
    T: nalgebra::Scalar + Copy + Default + std::ops::AddAssign + std::ops::Mul<f64, Output = T>,
{
    let (rows, cols) = (&r.grid.boxes[..], &s.grid.boxes[..]);
    let (nr, ns) = (r.grid.chordwise, s.grid.chordwise);
    let mut d = DMatrix::from_element(rows.len(), cols.len(), T::default());
    for rs in (0..rows.len()).step_by(nr) {
        let y = rows[rs].y_c;
        for ss in (0..cols.len()).step_by(ns) {
            for mirror in [false, true] {
                let at = |j: usize| {
                    let l = cols[j].line;
                    if mirror { l.mirrored() } else { l }
                };
                let (stations, m) = nonplanar::rule(y - at(ss).eta, at(ss).e, z0);
                let stations = &stations[..m];
                let prepared: Vec<R> = stations.iter().map(|st| prep(st.y0.hypot(z0))).collect();
                for i in rs..rs + nr {
                    for j in ss..ss + ns {
                        let line = at(j);
                        let xbar = rows[i].x_c - line.xi;
                        let mut acc = T::default();
                        for (st, p) in stations.iter().zip(&prepared) {
                            let (a, b) = eval(xbar - st.eta * line.tan_sweep, p);
                            acc += a * st.w1;
                            acc += b * st.w2;
                        }
                        d[(i, j)] += acc * line.factor();
                    }
                }
            }
        }
    }
    d
}

/// The harmonic matrix D, steady plus oscillatory.
pub(super) fn harmonic(blocks: &[Block], flow: &KernelFlow, rule: LineRule) -> DMatrix<Complex64> {
    let beta = flow.beta2.sqrt();
    assemble(blocks, |pair| match *pair {
        Pair::Own(b) => solve::harmonic_matrix(&b.grid, flow, rule),
        Pair::Planar(r, s) => pairwise(&r.grid.boxes, &s.grid.boxes, |line, x, y| {
            Complex64::new(line.steady(x, y, beta), 0.0) + line.oscillatory(x, y, flow, rule)
        }),
        Pair::NonPlanar(r, s, z0) => {
            let steady = pairwise(&r.grid.boxes, &s.grid.boxes, |line, x, y| {
                Complex64::new(nonplanar::steady(line, x, y, z0, beta), 0.0)
            });
            let lines = nonplanar_lines(
                r,
                s,
                z0,
                |rr| Radial2::new(rr, flow),
                |x0, radial| nonplanar::increments(x0, radial, flow),
            );
            steady + lines
        }
    })
}

/// The steady matrix D₀.
pub(super) fn steady(blocks: &[Block], beta: f64) -> DMatrix<f64> {
    assemble(blocks, |pair| match *pair {
        Pair::Own(b) => solve::matrix(&b.grid.boxes, |line, x, y| line.steady(x, y, beta)),
        Pair::Planar(r, s) => pairwise(&r.grid.boxes, &s.grid.boxes, |line, x, y| {
            line.steady(x, y, beta)
        }),
        Pair::NonPlanar(r, s, z0) => pairwise(&r.grid.boxes, &s.grid.boxes, |line, x, y| {
            nonplanar::steady(line, x, y, z0, beta)
        }),
    })
}

/// The first-order matrix per unit iκ (D = D₀ + iκD₁ + O(κ² ln κ)).
pub(super) fn first_order(blocks: &[Block], beta2: f64, rule: LineRule) -> DMatrix<f64> {
    assemble(blocks, |pair| match *pair {
        Pair::Own(b) => {
            let n = b.grid.boxes.len();
            let mut d = DMatrix::zeros(n, n);
            solve::add_blocked(
                &mut d,
                &b.grid,
                rule,
                |_| (),
                solve::each(|x0, y0, _| kernel::first_order_numerator(x0, y0, beta2)),
                |line, x, y| line.first_order(x, y, beta2, rule),
            );
            d
        }
        Pair::Planar(r, s) => pairwise(&r.grid.boxes, &s.grid.boxes, |line, x, y| {
            line.first_order(x, y, beta2, rule)
        }),
        Pair::NonPlanar(r, s, z0) => nonplanar_lines(
            r,
            s,
            z0,
            |rr| rr,
            |x0, &rr| nonplanar::first_order(x0, rr, beta2),
        ),
    })
}
