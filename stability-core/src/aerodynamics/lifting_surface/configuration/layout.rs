//! The configuration's surfaces as lattices in one frame: the wing's apex
//! at the origin, each other surface moved to its apex (x) and height (z);
//! what is checked of the geometry before anything is solved.

use super::ConfigurationError;
use crate::aerodynamics::lifting_surface::lattice::{Grid, Strip};
use crate::aerodynamics::lifting_surface::{Lattice, LatticeSpec, LiftingSurfaceError};
use crate::geometry::Trapezoid;
use crate::geometry::configuration::{Configuration, Part, Surface, SurfaceKind};

/// One surface's lattice and place.
#[derive(Debug, Clone)]
pub(super) struct Member {
    pub part: Part,
    pub shape: Trapezoid,
    pub lattice: Lattice,
    pub x: f64,
    pub z: f64,
}

/// One surface's boxes at one level of the extrapolation, in the
/// configuration's frame.
#[derive(Debug, Clone)]
pub(super) struct Block {
    pub grid: Grid,
    pub z: f64,
}

impl Member {
    /// Its grid of level `k` moved to its apex.
    pub fn block(&self, k: usize) -> Block {
        let mut grid = self.lattice.grids()[k].clone();
        for b in &mut grid.boxes {
            b.line.xi += self.x;
            b.x_c += self.x;
        }
        Block { grid, z: self.z }
    }
}

fn part(kind: SurfaceKind) -> Part {
    match kind {
        SurfaceKind::Tailplane => Part::Tailplane,
        SurfaceKind::Foreplane => Part::Foreplane,
    }
}

/// The surface's planform checked, or `None` for a surface of zero area
/// (absent).
fn checked_shape(s: &Surface) -> Result<Option<Trapezoid>, ConfigurationError> {
    let name = s.kind.name();
    let t = s.shape;
    let numbers = [
        ("root chord", t.root_chord),
        ("tip chord", t.tip_chord),
        ("semi-span", t.semi_span),
        ("leading-edge sweep", t.sweep_le),
        ("apex x", s.x),
        ("height z", s.z),
    ];
    for (what, v) in numbers {
        if !v.is_finite() {
            return Err(ConfigurationError::Geometry(format!(
                "the {name}'s {what} must be a finite number, not {v}"
            )));
        }
    }
    if t.semi_span == 0.0 || (t.root_chord == 0.0 && t.tip_chord == 0.0) {
        return Ok(None);
    }
    Trapezoid::new(t.root_chord, t.tip_chord, t.semi_span, t.sweep_le)
        .map(Some)
        .map_err(|e| ConfigurationError::Geometry(format!("the {name}'s planform: {e}")))
}

/// Two surfaces closer in height than this fraction of the wing's root
/// chord are in one plane (where overlapping boxes make the lattice
/// singular).
const SAME_PLANE: f64 = 1e-6;

/// The most by which the chordwise extents of `a` (apex at `xa`) and `b`
/// overlap at any station of their common span (≤ 0: they do not).
fn plan_overlap(a: &Trapezoid, xa: f64, b: &Trapezoid, xb: f64) -> f64 {
    let s = a.semi_span.min(b.semi_span);
    // min(TE) − max(LE) is concave in y: its largest value is at an end or
    // where two leading or two trailing edges cross
    let le = |t: &Trapezoid, x: f64, y: f64| x + t.leading_edge_at(y);
    let te = |t: &Trapezoid, x: f64, y: f64| le(t, x, y) + t.chord_at(y);
    let gap = |y: f64| te(a, xa, y).min(te(b, xb, y)) - le(a, xa, y).max(le(b, xb, y));
    let cross = |f: &dyn Fn(&Trapezoid, f64, f64) -> f64| {
        let (d0, d1) = (f(a, xa, 0.0) - f(b, xb, 0.0), f(a, xa, s) - f(b, xb, s));
        if d0 != d1 {
            (d0 / (d0 - d1)).clamp(0.0, 1.0) * s
        } else {
            0.0
        }
    };
    [0.0, s, cross(&le), cross(&te)]
        .into_iter()
        .map(gap)
        .fold(f64::NEG_INFINITY, f64::max)
}

/// The wing's strips up to semi-span `s`, the last one cut at `s` (and its
/// station then mid-strip): a surface of no greater span in the wing's
/// plane (or near it, [`in_the_wake`]) on these has the
/// wing's trailing legs on its strip edges, never beside its collocation
/// points, and its own legs where the wing's are.
///
/// A vortex lattice's trailing legs are a discrete stand-in for the wake
/// sheet: the normalwash of a leg in (or near) its own plane grows as 1/d
/// beside it, so a surface in the wing's wake whose collocation points fall
/// at arbitrary distances d from the wing's legs sees an erratic downwash
/// (measured: a coplanar tailplane's lift 80 % above AVL's with strips
/// spaced for the tail alone, and its lift varying non-monotonically with
/// its height for z below a strip's width). Aligning the strips is AVL's
/// own advice for a tail behind a wing (M. Drela and H. Youngren, *AVL
/// 3.36 User Primer*, "Vortex lattice spacing distributions").
fn aligned(wing: &[Strip], s: f64) -> Vec<Strip> {
    let mut out: Vec<Strip> = wing
        .iter()
        .copied()
        .take_while(|&(_, y1, _)| y1 < s * (1.0 - 1e-9))
        .collect();
    let y0 = out.last().map_or(0.0, |&(_, y1, _)| y1);
    out.push((y0, s, 0.5 * (y0 + s)));
    out
}

/// Whether a surface of semi-span `s` at height `z` lies in the wing's
/// discrete wake — no wider than the wing, and nearer its plane than the
/// widest of the wing's strips within `s` (above that height the legs'
/// ripple about the continuous sheet's normalwash, which decays as
/// e^{−2π|z|/w} for legs w apart, is below 0.2 %): then its strips are the
/// wing's ([`aligned`]); otherwise its own, which resolve its tip better.
fn in_the_wake(wing: &[Strip], s: f64, z: f64) -> bool {
    let widest = wing
        .iter()
        .filter(|&&(y0, _, _)| y0 < s)
        .map(|&(y0, y1, _)| y1 - y0)
        .fold(0.0, f64::max);
    s <= wing.last().map_or(0.0, |&(_, y1, _)| y1) && z.abs() < widest
}

/// The configuration's members, the wing first, each with the lattice
/// `spec_for` gives its planform.
pub(super) fn members(
    cfg: &Configuration,
    spec_for: impl Fn(&Trapezoid) -> LatticeSpec,
) -> Result<Vec<Member>, ConfigurationError> {
    let wing = cfg.wing;
    Trapezoid::new(
        wing.root_chord,
        wing.tip_chord,
        wing.semi_span,
        wing.sweep_le,
    )
    .map_err(|e| ConfigurationError::Geometry(format!("the wing's planform: {e}")))?;
    let mut out = vec![Member {
        part: Part::Wing,
        shape: wing,
        lattice: Lattice::new(&wing, spec_for(&wing))
            .map_err(|e| too_many(e, Part::Wing, &wing, &spec_for(&wing)))?,
        x: 0.0,
        z: 0.0,
    }];
    for s in cfg.surfaces() {
        if let Some(shape) = checked_shape(s)? {
            let wing_lattice = &out[0].lattice;
            let lattice = if in_the_wake(&wing_lattice.strips_of(0), shape.semi_span, s.z) {
                Lattice::on_strips(&shape, spec_for(&shape), |k| {
                    aligned(&wing_lattice.strips_of(k), shape.semi_span)
                })
            } else {
                Lattice::new(&shape, spec_for(&shape))
            }
            .map_err(|e| too_many(e, part(s.kind), &shape, &spec_for(&shape)))?;
            out.push(Member {
                part: part(s.kind),
                shape,
                lattice,
                x: s.x,
                z: s.z,
            });
        }
    }
    check_layout(&out, wing.root_chord)?;
    check_cost(&out)?;
    Ok(out)
}

/// How many of a lattice's `levels` (finest first) the solve uses: all of
/// Richardson's six, three of a chordwise extrapolation, or the one.
pub(super) fn levels_solved(levels: usize) -> usize {
    match levels {
        1 => 1,
        2..6 => 3,
        _ => 6,
    }
}

/// The most bytes the configuration's solve may hold in its matrices at
/// once: as much as the largest lattice a single wing may have, a dense
/// complex matrix of [`LatticeSpec::MAX_BOXES`]² (256 MB).
pub const MAX_SOLVE_BYTES: f64 =
    16.0 * LatticeSpec::MAX_BOXES as f64 * LatticeSpec::MAX_BOXES as f64;

/// The solve's cost, counted before anything is solved: each level of the
/// extrapolation is one dense complex matrix of every surface's boxes
/// (16 bytes an entry, its LU's work growing as the cube of its order),
/// and the levels are solved side by side. Above [`MAX_SOLVE_BYTES`] the
/// configuration is refused, naming the surface that costs most and what
/// to change.
fn check_cost(members: &[Member]) -> Result<(), ConfigurationError> {
    let used = levels_solved(members[0].lattice.grids().len());
    let order = |k: usize| -> f64 {
        members
            .iter()
            .map(|m| m.lattice.grids()[k].boxes.len() as f64)
            .sum()
    };
    let bytes: f64 = (0..used).map(|k| 16.0 * order(k) * order(k)).sum();
    if bytes <= MAX_SOLVE_BYTES {
        return Ok(());
    }
    let boxes: Vec<String> = members
        .iter()
        .map(|m| format!("{} {}", name(m.part), m.lattice.boxes().len()))
        .collect();
    let worst = members
        .iter()
        .max_by_key(|m| m.lattice.boxes().len())
        .expect("the wing at least");
    Err(costly(
        format!(
            "the configuration's lattice has {} boxes on the half configuration ({}), solved as one dense complex matrix at each of the extrapolation's {used} levels side by side: {:.0} MB at once, more than the {:.0} MB the solver takes",
            order(0),
            boxes.join(", "),
            bytes / 1e6,
            MAX_SOLVE_BYTES / 1e6
        ),
        worst.part,
        &worst.shape,
        &worst.lattice.spec(),
    ))
}

/// A surface's lattice with more boxes than a lattice may have, said as
/// [`check_cost`] says it (other errors as they are).
fn too_many(
    e: LiftingSurfaceError,
    part: Part,
    shape: &Trapezoid,
    spec: &LatticeSpec,
) -> ConfigurationError {
    match e {
        LiftingSurfaceError::TooManyBoxes { boxes, max } => costly(
            format!(
                "the {}'s lattice alone has {boxes} boxes on its half, more than the {max} the solver takes (one dense complex matrix of {:.0} MB)",
                name(part),
                MAX_SOLVE_BYTES / 1e6
            ),
            part,
            shape,
            spec,
        ),
        e => e.into(),
    }
}

/// The error of a lattice too costly to solve: `what`, then what makes the
/// surface `part` (of planform `shape`, lattice `spec`) so costly and what
/// to change.
fn costly(what: String, part: Part, shape: &Trapezoid, spec: &LatticeSpec) -> ConfigurationError {
    ConfigurationError::Geometry(format!(
        "{what}. The {name}'s aspect ratio {a:.0} takes {n} strips of {c} boxes (16 strips, and 2 more for each unit of aspect ratio above 4): give the {name} a smaller aspect ratio — more leading-edge sweep (it has {sweep:.1}°), more taper, or a shorter span",
        name = name(part),
        a = shape.aspect_ratio(),
        n = spec.spanwise,
        c = spec.chordwise,
        sweep = shape.sweep_le.to_degrees(),
    ))
}

fn name(p: Part) -> &'static str {
    match p {
        Part::Wing => "wing",
        Part::Tailplane => "tailplane",
        Part::Foreplane => "foreplane",
        Part::Body => "body",
    }
}

/// Every member's lattice alike in levels and chordwise boxes, and no two
/// overlapping in plan in one plane.
fn check_layout(members: &[Member], scale: f64) -> Result<(), ConfigurationError> {
    let first = members[0].lattice.grids();
    for m in members {
        let g = m.lattice.grids();
        if g.len() != first.len() || g.iter().zip(first).any(|(a, b)| a.chordwise != b.chordwise) {
            return Err(ConfigurationError::Geometry(format!(
                "the {}'s lattice must have the wing's chordwise boxes and extrapolation",
                name(m.part)
            )));
        }
    }
    for (i, a) in members.iter().enumerate() {
        for b in &members[i + 1..] {
            let same_plane = (a.z - b.z).abs() <= SAME_PLANE * scale;
            if same_plane && plan_overlap(&a.shape, a.x, &b.shape, b.x) > 1e-9 * scale {
                return Err(ConfigurationError::Geometry(format!(
                    "the {} and the {} overlap in plan at the same height (z = {}): move one \
                     of them fore or aft (x) or give it a height (z)",
                    name(a.part),
                    name(b.part),
                    b.z
                )));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tailplane swept 1° (aspect ratio 153: 314 strips, 3768 boxes) is
    /// within the single-surface limit, but the configuration's solve
    /// holds six matrices of all 3960 boxes at once — 411 MB — and is
    /// refused before anything is solved, naming the tailplane and what
    /// to change; swept 10°, it is solved.
    #[test]
    fn a_configuration_costlier_than_the_solver_takes_is_refused_first() {
        use crate::geometry::{Planform, Size};
        let wing = Trapezoid::from(
            &Planform::new(45f64.to_radians(), 0.0, Size::RootChord(10.0)).unwrap(),
        );
        let tail = |sweep: f64| {
            let p = Planform::new(sweep.to_radians(), 0.2, Size::Area(16.0)).unwrap();
            Configuration {
                tailplane: Some(Surface {
                    kind: SurfaceKind::Tailplane,
                    shape: Trapezoid::from(&p),
                    x: 12.0,
                    z: 0.0,
                    incidence: 0.0,
                }),
                ..Configuration::wing_alone(wing)
            }
        };
        let e = match members(&tail(1.0), LatticeSpec::for_wing) {
            Err(ConfigurationError::Geometry(m)) => m,
            other => panic!("{:?}", other.map(|m| m.len())),
        };
        // by hand: A = 4(1 − λ)/((1 + λ) tan 1°) = 152.8 → 16 + 2·149 = 314
        // strips of 12; 3768 + 192 = 3960 boxes; the levels' orders are
        // 3960, 1980, 990 (chordwise halved) and 1980, 990, 495 (strips
        // halved): 16·3960²·(1 + 1/4 + 1/16 + 1/4 + 1/16 + 1/64) = 411 MB
        let mb = 16.0 * 3960f64.powi(2) * (1.0 + 0.25 + 0.0625 + 0.25 + 0.0625 + 0.015625) / 1e6;
        assert!(
            e.contains("3960 boxes") && e.contains("tailplane 3768"),
            "{e}"
        );
        assert!(e.contains(&format!("{mb:.0} MB at once")), "{e}");
        assert!(
            e.contains("314 strips") && e.contains("more leading-edge sweep"),
            "{e}"
        );
        // swept 0.5°: the tailplane alone is beyond a lattice's boxes
        let e = members(&tail(0.5), LatticeSpec::for_wing)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("tailplane's lattice alone has 7440 boxes"),
            "{e}"
        );
        assert!(members(&tail(10.0), LatticeSpec::for_wing).is_ok());
    }

    #[test]
    fn overlap_in_plan() {
        let w = Trapezoid::new(1.0, 0.0, 1.0, 45f64.to_radians()).unwrap();
        let t = Trapezoid::new(0.3, 0.2, 0.4, 0.3).unwrap();
        // behind the root's trailing edge: apart
        assert!(plan_overlap(&w, 0.0, &t, 1.2) < 0.0);
        // on the wing
        assert!(plan_overlap(&w, 0.0, &t, 0.5) > 0.0);
        // beside the apex, ahead of the leading edge outboard: the tail's
        // tip (y = 0.4, x 0.3 + 0.4 tan 0.3 ≈ 0.42 to 0.62) meets the wing's
        // leading edge there (x = 0.4)
        assert!(plan_overlap(&w, 0.0, &t, 0.3) > 0.0);
        assert!(plan_overlap(&w, 0.0, &t, -1.0) < 0.0);
    }
}
