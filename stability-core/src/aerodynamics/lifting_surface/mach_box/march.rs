//! The Mach box's march and the loads from the potential.
//!
//! A box's centre sees only the boxes of earlier rows in its forward Mach
//! cone and its own forward half, so the potential is swept row by row
//! (Pines, Dugundji & Neuringer 1955): in each row the diaphragm boxes
//! first, whose normalwash makes the potential at their centres vanish,
//! then the wing boxes, whose potential follows. The wing's own part of
//! every potential is exact ([`super::direct`]); the boxes carry the
//! diaphragm's normalwash on the part of their area off the wing (a wing
//! box cut by a subsonic edge: its diaphragm neighbour's normalwash).
//!
//! The loads, by parts along each strip (ΔC_p = 4(iκφ̂ + ∂φ̂/∂x),
//! φ̂ = φ/V, κ = ω/V, φ̂ = 0 on the leading edge):
//! ∫ΔC_p dx = 4(iκ∫φ̂ dx + φ̂_TE), ∫(x − x̄)ΔC_p dx =
//! 4(iκ∫(x − x̄)φ̂ dx + (x_TE − x̄)φ̂_TE − ∫φ̂ dx), φ̂ piecewise linear
//! through the wing boxes' centres, from zero at the leading edge and
//! extrapolated linearly to the trailing edge.

use super::direct::{Flow, wing_potential};
use super::edge;
use super::grid::{Grid, Kind};
use super::influence::{Influence, Pair};
use super::upstream::{self, Method, Relaxed};
use crate::geometry::Trapezoid;
use num_complex::Complex64;
use rayon::prelude::*;
use std::f64::consts::PI;

/// The potentials φ̂ at the box centres (zero off the wing) for the two
/// normalwash distributions: the wing's own part exactly
/// ([`super::direct`]), the diaphragm's by its boxes. With a subsonic
/// leading edge (β cot Λ < 1) the diaphragm's upwash carries its edge
/// singularity exactly ([`super::edge`]): each box's unknown is the
/// smooth factor a of w̄ = a/√d. The earlier rows' sum by `method`
/// ([`super::upstream`]).
pub fn march(
    wing: &Trapezoid,
    grid: &Grid,
    table: &Influence,
    flow: &Flow,
    method: Method,
) -> Vec<Pair> {
    let n = grid.cells.len();
    let zero = [Complex64::default(); 2];
    let mut source = vec![zero; n];
    let mut wash = vec![zero; n];
    let mut phi = vec![zero; n];
    let mut near = vec![0.0; n];
    let edge = EdgeBoxes {
        singular: flow.beta < wing.sweep_le.tan(),
        sigma_hat: flow.sigma * grid.dx,
        nu_hat: flow.nu * grid.dx,
        c00: table.get(0, 0),
    };
    let own = own_potentials(wing, grid, flow);
    let mut any_diaphragm = false;
    // each row's columns of non-zero sources (empty: lo > hi)
    let mut spans = vec![(usize::MAX, 0usize); grid.rows];
    // each box's own potential and the earlier rows' sum, row by row
    let mut ahead = vec![[zero; 2]; grid.columns];
    // made at the first row with a source (the rows before have none; a
    // wing with no diaphragm needs none)
    let mut relaxed: Option<Relaxed> = None;
    let mut summed = vec![zero; grid.columns];
    for i in 0..grid.rows {
        let width = reach(grid, i);
        if let Some(r) = relaxed.as_mut() {
            r.row(i, &mut summed[..width]);
        }
        let earlier = Earlier {
            grid,
            table,
            own: &own,
            source: &source,
            spans: &spans,
            summed: relaxed.as_ref().map(|_| &summed[..width]),
            near: &near,
            wash: &wash,
            any: any_diaphragm,
        };
        // independent across the row (earlier rows only): in parallel, in
        // pieces of at least PARALLEL_PIECE boxes, once there are sources to
        // sum (without, each box only copies its own potential)
        let row = &mut ahead[..width];
        let at = |(j, slot): (usize, &mut [Pair; 2])| *slot = earlier.at(wing, &edge, i, j);
        if any_diaphragm {
            row.par_iter_mut()
                .with_min_len(PARALLEL_PIECE)
                .enumerate()
                .for_each(at);
        } else {
            row.iter_mut().enumerate().for_each(at);
        }
        let boxes = Boxes {
            source: &mut source,
            wash: &mut wash,
            phi: &mut phi,
            near: &mut near,
        };
        spans[i] = boxes.settle_row(wing, grid, &edge, i, &ahead[..width]);
        any_diaphragm |= spans[i].0 <= spans[i].1;
        if method == Method::Relaxed && any_diaphragm {
            let r = relaxed.get_or_insert_with(|| Relaxed::new(grid, table));
            r.push(i, &source[i * grid.columns..i * grid.columns + width]);
        }
    }
    phi
}

/// The march's unknowns, box by box: each box's source, normalwash,
/// potential and edge weight q (zero off the edge).
struct Boxes<'a> {
    source: &'a mut [Pair],
    wash: &'a mut [Pair],
    phi: &'a mut [Pair],
    near: &'a mut [f64],
}

impl Boxes<'_> {
    /// Row i settled from its boxes' [own, before] (`ahead`): first the
    /// diaphragm's, whose normalwash makes φ vanish at their centres, then
    /// the wing's, whose potential follows. Returns the row's span of
    /// columns with a non-zero source (empty: lo > hi).
    fn settle_row(
        self,
        wing: &Trapezoid,
        grid: &Grid,
        edge: &EdgeBoxes,
        i: usize,
        ahead: &[[Pair; 2]],
    ) -> (usize, usize) {
        let scale = grid.dy / PI;
        let mut span = (usize::MAX, 0usize);
        for pass in [Kind::Diaphragm, Kind::Wing] {
            for (j, &[own, before]) in ahead.iter().enumerate() {
                let k = i * grid.columns + j;
                let cell = grid.cells[k];
                if cell.kind != pass {
                    continue;
                }
                let (q, s) = edge.weights(wing, grid, i, j, cell.fraction);
                if edge.singular && edge.is_near(wing, grid, i, j) {
                    self.near[k] = q;
                }
                if pass == Kind::Diaphragm {
                    for r in 0..2 {
                        self.wash[k][r] = if s.norm() > 0.0 {
                            -(before[r] + own[r] / scale) / s
                        } else {
                            Complex64::default()
                        };
                        self.source[k][r] = self.wash[k][r] * q;
                    }
                } else {
                    let beside = neighbour_wash(grid, self.wash, i, j);
                    self.wash[k] = beside;
                    for r in 0..2 {
                        self.source[k][r] = beside[r] * q;
                        self.phi[k][r] = own[r] + (before[r] + beside[r] * s) * scale;
                    }
                }
                if self.source[k].iter().any(|s| s.norm() > 0.0) {
                    span = (span.0.min(j), span.1.max(j));
                }
            }
        }
        span
    }
}

/// The wing's own potential ([`wing_potential`]) at the centre of every
/// wing and diaphragm box the march solves (zero elsewhere): independent
/// of the march, so all of them at once, in parallel — most of a solve's
/// work.
fn own_potentials(wing: &Trapezoid, grid: &Grid, flow: &Flow) -> Vec<Pair> {
    let zero = [Complex64::default(); 2];
    (0..grid.cells.len())
        .into_par_iter()
        .with_min_len(PARALLEL_PIECE)
        .map(|k| {
            let (i, j) = (k / grid.columns, k % grid.columns);
            let solved = matches!(grid.cells[k].kind, Kind::Wing | Kind::Diaphragm);
            if solved && j < reach(grid, i) {
                let (x, y) = grid.centre(i, j);
                wing_potential(wing, flow, x, y)
            } else {
                zero
            }
        })
        .collect()
}

/// What the boxes of a row see of the rows before it.
struct Earlier<'a> {
    grid: &'a Grid,
    table: &'a Influence,
    /// Every box's own potential ([`own_potentials`]).
    own: &'a [Pair],
    source: &'a [Pair],
    spans: &'a [(usize, usize)],
    /// The earlier rows' sums of this row by [`Relaxed`] (else summed
    /// [`upstream::direct`]ly).
    summed: Option<&'a [Pair]>,
    near: &'a [f64],
    wash: &'a [Pair],
    /// Whether any earlier row has a source.
    any: bool,
}

impl Earlier<'_> {
    /// [own, before] of box (i, j): the wing's own potential at its centre
    /// and the earlier rows' sources' (zero for boxes neither on the wing
    /// nor in the diaphragm).
    fn at(&self, wing: &Trapezoid, edge: &EdgeBoxes, i: usize, j: usize) -> [Pair; 2] {
        let zero = [Complex64::default(); 2];
        let g = self.grid;
        if !matches!(
            g.cells[i * g.columns + j].kind,
            Kind::Wing | Kind::Diaphragm
        ) {
            return [zero; 2];
        }
        let own = self.own[i * g.columns + j];
        if !self.any {
            return [own, zero];
        }
        let mut before = match self.summed {
            Some(summed) => summed[j],
            None => upstream::direct(g, self.table, (self.source, &self.spans[..i]), i, j),
        };
        if edge.singular {
            let field = (self.near, self.wash);
            edge.near_field(wing, g, self.table, field, (i, j), &mut before);
        }
        [own, before]
    }
}

/// The fewest boxes of a row one thread takes.
const PARALLEL_PIECE: usize = 48;

/// Rows back over which the near field's coefficients are the exact
/// weighted ones ([`edge::coefficient`]).
const NEAR_ROWS: usize = 2;

/// Boxes whose centre is within this many strips of the edge take the
/// near field's exact coefficients.
const NEAR_STRIPS: f64 = 3.0;

/// How the boxes off the wing (in part or whole) carry the diaphragm's
/// upwash: uniform (the classic box), or with the edge's 1/√d
/// ([`super::edge`]).
struct EdgeBoxes {
    singular: bool,
    sigma_hat: f64,
    nu_hat: f64,
    c00: Complex64,
}

impl EdgeBoxes {
    /// Whether box (i, j) lies within [`NEAR_STRIPS`] of the edge.
    fn is_near(&self, wing: &Trapezoid, grid: &Grid, i: usize, j: usize) -> bool {
        let (x, y) = grid.centre(i, j);
        (y - edge::half_width(wing, x)).abs() < NEAR_STRIPS * grid.dy
    }

    /// Replaces, in `sum`, the uniform boxes' C(m, n) of the edge's boxes
    /// within [`NEAR_ROWS`] rows ahead of (i, j) by their exact weighted
    /// coefficients: Σ a (S − q C). `near` holds q (zero for boxes not
    /// near the edge), `wash` a.
    fn near_field(
        &self,
        wing: &Trapezoid,
        grid: &Grid,
        table: &Influence,
        (near, wash): (&[f64], &[Pair]),
        (i, j): (usize, usize),
        sum: &mut Pair,
    ) {
        let centre = grid.centre(i, j);
        for m in 1..=NEAR_ROWS.min(i) {
            let ip = i - m;
            let (lo, hi) = (j.saturating_sub(m), (j + m).min(grid.columns - 1));
            for jp in lo..=hi {
                let kp = ip * grid.columns + jp;
                if near[kp] <= 0.0 {
                    continue;
                }
                let exact =
                    edge::coefficient(wing, grid, centre, (ip, jp), self.sigma_hat, self.nu_hat);
                let c = exact - table.get(m, j.abs_diff(jp)) * near[kp];
                sum[0] += wash[kp][0] * c;
                sum[1] += wash[kp][1] * c;
            }
        }
    }

    /// (q, S) of box (i, j): its source and its self-influence per unit
    /// unknown — with the singular weighting a/√d (S exact within
    /// [`NEAR_STRIPS`] of the edge), or for a uniform upwash
    /// the area off the wing, 1 − f, and the forward half's C(0, 0) times
    /// it (f the wing fraction).
    fn weights(
        &self,
        wing: &Trapezoid,
        grid: &Grid,
        i: usize,
        j: usize,
        fraction: f64,
    ) -> (f64, Complex64) {
        let rest = 1.0 - fraction;
        if rest <= 0.0 {
            (0.0, Complex64::default())
        } else if self.singular {
            let q = edge::weight(wing, grid, i, j);
            // away from the edge 1/√d is smooth across the box: its own
            // influence is C(0, 0) times its mean (to second order)
            let s = if self.is_near(wing, grid, i, j) {
                edge::self_influence(wing, grid, i, j, self.sigma_hat, self.nu_hat)
            } else {
                self.c00 * q
            };
            (q, s)
        } else {
            // the classic box: the upwash over the off-wing part, its own
            // influence C(0, 0) on the whole box's unknown
            (rest, self.c00 * rest)
        }
    }
}

/// The diaphragm normalwash beside a cut wing box: of the box outboard in
/// its row, else of the box ahead, else none.
fn neighbour_wash(grid: &Grid, wash: &[Pair], i: usize, j: usize) -> Pair {
    let diaphragm =
        |ii: usize, jj: usize| grid.cells[ii * grid.columns + jj].kind == Kind::Diaphragm;
    if j + 1 < grid.columns && diaphragm(i, j + 1) {
        wash[i * grid.columns + j + 1]
    } else if i > 0 && diaphragm(i - 1, j) {
        wash[(i - 1) * grid.columns + j]
    } else {
        [Complex64::default(); 2]
    }
}

/// The columns 0..reach of row i whose boxes can act on the wing: a box's
/// influence runs only down its aft Mach cone (|Δj| ≤ Δi), which from
/// column j of row i reaches a wing strip (j′ < strips) by the last row
/// only if j ≤ strips − 1 + (rows − 1 − i). The diaphragm beyond is never
/// solved: its normalwash acts on nothing the loads use (exact pruning).
fn reach(grid: &Grid, i: usize) -> usize {
    (grid.strips + grid.rows - i).min(grid.columns)
}

/// C_L and C_m (about the M.A.C.'s leading edge, on c̄) of the two
/// potentials, at κ = ω/V.
pub fn loads(wing: &Trapezoid, grid: &Grid, phi: &[Pair], kappa: f64) -> [Pair; 2] {
    let (x_mac, mac) = (wing.x_mac(), wing.mac());
    let half_area = 0.5 * wing.area();
    let ik = Complex64::new(0.0, kappa);
    let (mut lift, mut moment) = ([Complex64::default(); 2], [Complex64::default(); 2]);
    // a subsonic leading edge (β = Δx/Δy < tan Λ): φ̂ ∝ √(x − x_LE) there
    let root = grid.dx / grid.dy < wing.sweep_le.tan();
    for j in 0..grid.strips {
        let width = if j == 0 { 0.5 * grid.dy } else { grid.dy };
        let y = j as f64 * grid.dy;
        let (le, te) = (
            wing.leading_edge_at(y),
            wing.leading_edge_at(y) + wing.chord_at(y),
        );
        for (r, (l, m)) in lift.iter_mut().zip(moment.iter_mut()).enumerate() {
            let [i0, i1, phi_te] = strip(grid, phi, (j, r), (le, te), x_mac, root);
            *l += (ik * i0 + phi_te) * (4.0 * width / half_area);
            *m -= (ik * i1 + phi_te * (te - x_mac) - i0) * (4.0 * width / (half_area * mac));
        }
    }
    [lift, moment]
}

/// ∫φ̂ dx, ∫(x − x̄)φ̂ dx and φ̂_TE along strip j, right-hand side r
/// (`root`: the first segment after a subsonic leading edge's √ law).
fn strip(
    grid: &Grid,
    phi: &[Pair],
    (j, r): (usize, usize),
    (le, te): (f64, f64),
    x_mac: f64,
    root: bool,
) -> [Complex64; 3] {
    let zero = Complex64::default();
    let mut prev = (le, zero);
    let mut last = None;
    let (mut i0, mut i1) = (zero, zero);
    for i in 0..grid.rows {
        let k = i * grid.columns + j;
        if grid.cells[k].kind != Kind::Wing {
            continue;
        }
        let here = (grid.centre(i, j).0, phi[k][r]);
        let [a, b] = if root && last.is_none() {
            first_segment(le, here, x_mac)
        } else {
            segment(prev, here, x_mac)
        };
        i0 += a;
        i1 += b;
        last = Some(prev);
        prev = here;
    }
    let Some(before) = last else {
        return [zero; 3];
    };
    let end = (
        te,
        if root {
            root_extrapolation(le, before, prev, te)
        } else {
            let slope = (prev.1 - before.1) / (prev.0 - before.0);
            prev.1 + slope * (te - prev.0)
        },
    );
    let [a, b] = segment(prev, end, x_mac);
    [i0 + a, i1 + b, end.1]
}

/// φ̂ at the trailing edge x_TE of a strip behind a subsonic leading edge
/// x_LE, through its last two points p, q by φ̂ = a√s + b·s, s = x − x_LE
/// (the first two terms of the edge's expansion, φ̂ ∝ √s·(1 + O(s)),
/// Ribner & Malvestuto, NACA Rep. 908); p on the edge (φ̂ = 0): a√s alone.
fn root_extrapolation(le: f64, p: (f64, Complex64), q: (f64, Complex64), te: f64) -> Complex64 {
    let (s1, s2, s) = (p.0 - le, q.0 - le, te - le);
    if s1 <= 1e-12 * s2 || s2 <= s1 {
        return q.1 * (s / s2).max(0.0).sqrt();
    }
    let (r1, r2) = (s1.sqrt(), s2.sqrt());
    let det = r1 * s2 - r2 * s1;
    let a = (p.1 * s2 - q.1 * s1) / det;
    let b = (q.1 * r1 - p.1 * r2) / det;
    a * s.sqrt() + b * s
}

/// ∫φ dx and ∫(x − x̄)φ dx from a subsonic leading edge x_LE to the
/// first centre q, where φ̂ = φ_q√((x − x_LE)/L), L = q − x_LE (the edge's
/// square-root potential, Ribner & Malvestuto, NACA Rep. 908): (2/3)φ_q L
/// and φ_q((x_LE − x̄)(2/3)L + (2/5)L²).
fn first_segment(le: f64, q: (f64, Complex64), x_mac: f64) -> [Complex64; 2] {
    let l = q.0 - le;
    [
        q.1 * (2.0 / 3.0 * l),
        q.1 * ((le - x_mac) * 2.0 / 3.0 * l + 0.4 * l * l),
    ]
}

/// ∫φ dx and ∫(x − x̄)φ dx over one segment of a piecewise-linear φ (exact).
fn segment(p: (f64, Complex64), q: (f64, Complex64), x_mac: f64) -> [Complex64; 2] {
    let h = q.0 - p.0;
    let (g0, g1) = (p.0 - x_mac, q.0 - x_mac);
    let i0 = (p.1 + q.1) * (0.5 * h);
    let i1 = (p.1 * (g0 / 3.0 + g1 / 6.0) + q.1 * (g0 / 6.0 + g1 / 3.0)) * h;
    [i0, i1]
}
