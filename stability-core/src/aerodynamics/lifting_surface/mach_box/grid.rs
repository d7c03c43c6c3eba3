//! The characteristic grid of Mach boxes over the half wing and its
//! diaphragm: boxes Δx = βΔy (a box's diagonals are Mach lines), strips
//! centred on y = jΔy (the root strip straddles the plane of symmetry, the
//! tip strip's outer side is the tip: Δy = s/(N − ½) for N strips), rows
//! [iΔx, (i + 1)Δx] from the apex.
//!
//! Each box is classed by its centre (Pines, Dugundji & Neuringer 1955):
//! on the wing (normalwash known), in the wake behind the trailing edge
//! (no influence on the wing when that edge is supersonic), or in the
//! diaphragm — the plane z = 0 off the wing and off the wake, where the
//! pressure jump, hence the potential, vanishes and the normalwash is the
//! unknown. A box cut by an edge carries the fraction f of its area on the
//! wing (exact, by clipping the box against the edges) and the x of that
//! part's centroid, so the jagged "centre in, centre out" edge of the
//! classic method becomes the true one for the known normalwash.

use crate::geometry::Trapezoid;
use arrayvec::ArrayVec;
use rayon::prelude::*;

/// Where a box's centre lies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    Wing,
    /// Off the wing, in the disturbed region: normalwash unknown, φ = 0.
    Diaphragm,
    /// Off the wing, outside every aft Mach cone of the wing (ahead of a
    /// supersonic edge): undisturbed, normalwash zero.
    Undisturbed,
    Wake,
}

/// One box: its class, wing-area fraction f and the x of its wing part's
/// centroid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    pub kind: Kind,
    pub fraction: f64,
    pub x_wing: f64,
}

/// The grid: `rows` × `columns` boxes, row-major.
#[derive(Debug, Clone)]
pub struct Grid {
    pub dx: f64,
    pub dy: f64,
    pub rows: usize,
    pub columns: usize,
    /// Strips on the wing (columns 0..strips).
    pub strips: usize,
    pub cells: Vec<Cell>,
}

/// The straight edges of the half wing (y ≥ 0) as half-planes
/// a·x + b·y ≤ c: leading edge, trailing edge, tip.
fn edges(w: &Trapezoid) -> [(f64, f64, f64); 3] {
    let t_le = w.sweep_le.tan();
    let t_te = (w.leading_edge_at(w.semi_span) + w.tip_chord - w.root_chord) / w.semi_span;
    [
        (-1.0, t_le, 0.0),
        (1.0, -t_te, w.root_chord),
        (0.0, 1.0, w.semi_span),
    ]
}

impl Grid {
    /// The grid of `strips` strips on `wing` at β, long enough for the
    /// trailing edge and wide enough for every diaphragm box a wing box's
    /// forward Mach cone reaches.
    pub fn new(wing: &Trapezoid, beta: f64, strips: usize) -> Grid {
        let dy = wing.semi_span / (strips as f64 - 0.5);
        let dx = beta * dy;
        let x_end = wing
            .root_chord
            .max(wing.leading_edge_at(wing.semi_span) + wing.tip_chord);
        let rows = (x_end / dx).ceil() as usize;
        let columns = strips + rows;
        let edges = edges(wing);
        let mut cells = vec![
            Cell {
                kind: Kind::Undisturbed,
                fraction: 0.0,
                x_wing: 0.0,
            };
            rows * columns
        ];
        cells
            .par_chunks_mut(columns.max(1))
            .enumerate()
            .for_each(|(i, row)| {
                for (j, c) in row.iter_mut().enumerate() {
                    *c = cell(wing, &edges, dx, dy, i, j);
                }
            });
        Grid {
            dx,
            dy,
            rows,
            columns,
            strips,
            cells,
        }
    }

    /// The centre of box (i, j).
    pub fn centre(&self, i: usize, j: usize) -> (f64, f64) {
        ((i as f64 + 0.5) * self.dx, j as f64 * self.dy)
    }
}

/// Where the disturbed region begins at station y ≥ 0: the least
/// LE(η) + β|y − η| over the leading edge |η| ≤ s (the most forward wing
/// point whose aft Mach cone holds (x, y); piecewise linear in η, so a
/// vertex: η = 0, min(y, s) or s).
fn disturbed_from(w: &Trapezoid, beta: f64, y: f64) -> f64 {
    [0.0, y.min(w.semi_span), w.semi_span]
        .iter()
        .map(|&eta| w.leading_edge_at(eta) + beta * (y - eta).abs())
        .fold(f64::INFINITY, f64::min)
}

fn cell(w: &Trapezoid, edges: &[(f64, f64, f64); 3], dx: f64, dy: f64, i: usize, j: usize) -> Cell {
    let beta = dx / dy;
    let (xc, yc) = ((i as f64 + 0.5) * dx, j as f64 * dy);
    let le = w.leading_edge_at(yc);
    let kind = if yc > w.semi_span || xc < le {
        if xc >= disturbed_from(w, beta, yc) {
            Kind::Diaphragm
        } else {
            Kind::Undisturbed
        }
    } else if xc > le + w.chord_at(yc) {
        Kind::Wake
    } else {
        Kind::Wing
    };
    let (y0, y1) = ((yc - 0.5 * dy).max(0.0), yc + 0.5 * dy);
    let (x0, x1) = (i as f64 * dx, (i as f64 + 1.0) * dx);
    let corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)];
    let side = |(a, b, c): (f64, f64, f64), p: (f64, f64)| a * p.0 + b * p.1 - c;
    // wholly outside one edge, or inside all: no clipping
    if edges
        .iter()
        .any(|&e| corners.iter().all(|&p| side(e, p) >= 0.0))
    {
        return Cell {
            kind,
            fraction: 0.0,
            x_wing: xc,
        };
    }
    if edges
        .iter()
        .all(|&e| corners.iter().all(|&p| side(e, p) <= 0.0))
    {
        return Cell {
            kind,
            fraction: 1.0,
            x_wing: 0.5 * (x0 + x1),
        };
    }
    let mut poly: ArrayVec<(f64, f64), 16> = ArrayVec::new();
    poly.extend(corners);
    for &e in edges {
        poly = clip(&poly, e);
    }
    let (area, x_wing) = area_centroid_x(&poly);
    let full = (x1 - x0) * (y1 - y0);
    Cell {
        kind,
        fraction: (area / full).clamp(0.0, 1.0),
        x_wing: if area > 0.0 { x_wing } else { xc },
    }
}

/// Sutherland–Hodgman: `poly` clipped to a·x + b·y ≤ c.
fn clip(poly: &[(f64, f64)], (a, b, c): (f64, f64, f64)) -> ArrayVec<(f64, f64), 16> {
    let mut out = ArrayVec::new();
    let inside = |p: (f64, f64)| a * p.0 + b * p.1 - c;
    for k in 0..poly.len() {
        let (p, q) = (poly[k], poly[(k + 1) % poly.len()]);
        let (fp, fq) = (inside(p), inside(q));
        if fp <= 0.0 {
            out.push(p);
        }
        if (fp < 0.0 && fq > 0.0) || (fp > 0.0 && fq < 0.0) {
            let t = fp / (fp - fq);
            out.push((p.0 + t * (q.0 - p.0), p.1 + t * (q.1 - p.1)));
        }
    }
    out
}

/// The area of a polygon and the x of its centroid (shoelace).
fn area_centroid_x(poly: &[(f64, f64)]) -> (f64, f64) {
    let (mut a2, mut mx) = (0.0, 0.0);
    for k in 0..poly.len() {
        let (p, q) = (poly[k], poly[(k + 1) % poly.len()]);
        let cross = p.0 * q.1 - q.0 * p.1;
        a2 += cross;
        mx += (p.0 + q.0) * cross;
    }
    if a2.abs() < 1e-300 {
        (0.0, 0.0)
    } else {
        (0.5 * a2.abs(), mx / (3.0 * a2))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The boxes' wing areas add up to the half wing's area exactly, and
    /// their first moments to its first moment (a cropped 50° wing).
    #[test]
    fn the_wing_parts_tile_the_half_wing() {
        let w = Trapezoid::new(1.0, 0.3, 0.8, 50f64.to_radians()).unwrap();
        let g = Grid::new(&w, 1.3, 9);
        let (mut area, mut moment) = (0.0, 0.0);
        for (k, c) in g.cells.iter().enumerate() {
            let j = k % g.columns;
            let strip = if j == 0 { 0.5 * g.dy } else { g.dy };
            area += c.fraction * g.dx * strip;
            moment += c.fraction * g.dx * strip * c.x_wing;
        }
        let half = 0.5 * w.area();
        // first moment of the half trapezoid: ∫ (c·LE + c²/2) dy
        let n = 2000;
        let h = w.semi_span / n as f64;
        let m: f64 = (0..n)
            .map(|k| {
                let y = (k as f64 + 0.5) * h;
                let (le, c) = (w.leading_edge_at(y), w.chord_at(y));
                h * (c * le + 0.5 * c * c)
            })
            .sum();
        assert!((area - half).abs() < 1e-12, "{area} vs {half}");
        assert!((moment - m).abs() < 1e-6, "{moment} vs {m}");
    }
}
