//! The configuration's doublet lattice (`Configuration::solve_subsonic`)
//! against the routes that do not need it: the wing's own lattice (a
//! configuration of the wing alone, or with a zero-area tail), the two
//! isolated surfaces added by hand (a tail far above the wing), the planar
//! lattice at vanishing height (continuity of the non-planar kernel), AVL
//! (`configuration_lattice_avl.rs`) and the classical tail-volume formulas
//! (`configuration_tail_volume.rs`).

use stability_core::aerodynamics::lifting_surface::configuration::ConfigurationError;
use stability_core::aerodynamics::lifting_surface::configuration::ConfigurationLattice;
use stability_core::aerodynamics::lifting_surface::{
    Lattice, LatticeSpec, LiftingSurfaceError, Solution,
};
use stability_core::geometry::Trapezoid;
use stability_core::geometry::configuration::Configuration;
use stability_core::geometry::configuration::Part;
use stability_core::geometry::configuration::Surface;
use stability_core::geometry::configuration::SurfaceKind;

fn delta(sweep_deg: f64) -> Trapezoid {
    let t = sweep_deg.to_radians().tan();
    Trapezoid::new(1.0, 0.0, 1.0 / t, sweep_deg.to_radians()).unwrap()
}

fn tail(x: f64, z: f64) -> Surface {
    Surface {
        kind: SurfaceKind::Tailplane,
        shape: Trapezoid::new(0.3, 0.15, 0.35, 30f64.to_radians()).unwrap(),
        x,
        z,
        incidence: 0.0,
    }
}

fn numbers(s: &Solution) -> [f64; 6] {
    [
        s.lift_alpha,
        s.moment_alpha,
        s.lift_alphadot,
        s.moment_alphadot,
        s.lift_q,
        s.moment_q,
    ]
}

/// The largest difference of the six numbers, relative to the largest of
/// `b`'s.
fn worst(a: &Solution, b: &Solution) -> f64 {
    let scale = numbers(b).iter().fold(0.0f64, |m, v| m.max(v.abs()));
    numbers(a)
        .iter()
        .zip(numbers(b))
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        / scale
}

#[test]
fn the_wing_alone_is_the_wings_lattice() {
    let wing = delta(60.0);
    let lattice = Lattice::new(&wing, LatticeSpec::for_wing(&wing)).unwrap();
    let cfg = Configuration::wing_alone(wing);
    for (m, w) in [(0.0, 0.0), (0.5, 0.0), (0.5, 0.4), (0.8, 1.0)] {
        let ours = cfg.solve_subsonic(m, w).unwrap();
        let theirs = lattice.solve(m, w).unwrap();
        assert_eq!(ours.parts.len(), 1);
        assert_eq!(ours.parts[0].part, Part::Wing);
        assert!(
            worst(&ours.total, &theirs) < 1e-13,
            "{m} {w}: {:?} {:?}",
            ours.total,
            theirs
        );
    }
}

#[test]
fn a_tail_of_zero_area_is_absent() {
    let wing = delta(45.0);
    let alone = Configuration::wing_alone(wing)
        .solve_subsonic(0.3, 0.2)
        .unwrap();
    for shape in [
        Trapezoid {
            semi_span: 0.0,
            ..tail(1.5, 0.0).shape
        },
        Trapezoid {
            root_chord: 0.0,
            tip_chord: 0.0,
            ..tail(1.5, 0.0).shape
        },
    ] {
        let cfg = Configuration {
            tailplane: Some(Surface {
                shape,
                ..tail(1.5, 0.1)
            }),
            ..Configuration::wing_alone(wing)
        };
        let s = cfg.solve_subsonic(0.3, 0.2).unwrap();
        assert_eq!(s.parts.len(), 1);
        assert!(worst(&s.total, &alone.total) < 1e-13);
    }
}

/// A tail's own solution (on its area, M.A.C. and frequency parameter) on
/// the wing's S, c̄ and moment axis: a load (L_t, M_t) on the tail's S_t, c̄_t
/// about its M.A.C.'s leading edge x̄_t is L = L_t S_t/S and
/// M = (S_t/S)(M_t c̄_t/c̄ − (x̄_t − x̄)L_t/c̄); the α̇ pair, divided by ω̄_t
/// = ω̄c̄_t/c̄, gains c̄_t/c̄; the configuration's rate normalwash (x − x̄)/c̄ is
/// (c̄_t/c̄) times the tail's plus (x̄_t − x̄)/c̄ times unit incidence.
fn moved(t: &Solution, tail: &Surface, wing: &Trapezoid, omega_bar: f64) -> Solution {
    let (s, c, xr) = (wing.area(), wing.mac(), wing.x_mac());
    let (st, ct, xt) = (
        tail.shape.area(),
        tail.shape.mac(),
        tail.x + tail.shape.x_mac(),
    );
    let (a, b) = (ct / c, (xt - xr) / c);
    let load = |l: f64, m: f64| (l * st / s, st / s * (m * ct / c - b * l));
    let (la, ma) = load(t.lift_alpha, t.moment_alpha);
    let (ld, md) = load(t.lift_alphadot * a, t.moment_alphadot * a);
    let (lq, mq) = load(
        a * t.lift_q + b * t.lift_alpha,
        a * t.moment_q + b * t.moment_alpha,
    );
    Solution {
        mach: t.mach,
        omega_bar,
        lift_alpha: la,
        moment_alpha: ma,
        lift_alphadot: ld,
        moment_alphadot: md,
        lift_q: lq,
        moment_q: mq,
    }
}

#[test]
fn a_tail_far_above_is_the_two_isolated_surfaces() {
    let wing = delta(60.0);
    let far = tail(1.5, 2000.0);
    let cfg = Configuration {
        tailplane: Some(far),
        ..Configuration::wing_alone(wing)
    };
    let wing_lattice = Lattice::new(&wing, LatticeSpec::for_wing(&wing)).unwrap();
    let tail_lattice = Lattice::new(&far.shape, LatticeSpec::for_wing(&far.shape)).unwrap();
    for (m, w) in [(0.0, 0.0), (0.5, 0.0), (0.0, 0.3)] {
        let s = cfg.solve_subsonic(m, w).unwrap();
        let w_t = w * far.shape.mac() / wing.mac();
        let t = moved(&tail_lattice.solve(m, w_t).unwrap(), &far, &wing, w);
        let alone = wing_lattice.solve(m, w).unwrap();
        let parts = [&s.parts[0].solution, &s.parts[1].solution];
        assert!(
            worst(parts[0], &alone) < 1e-5,
            "{m} {w}: wing {:?} {alone:?}",
            parts[0]
        );
        assert!(
            worst(parts[1], &t) < 1e-5,
            "{m} {w}: tail {:?} {t:?}",
            parts[1]
        );
        // the total is the sum of the parts
        let sum: Vec<f64> = (0..6)
            .map(|k| numbers(parts[0])[k] + numbers(parts[1])[k])
            .collect();
        for (k, v) in numbers(&s.total).iter().enumerate() {
            assert!((v - sum[k]).abs() < 1e-12 * (1.0 + v.abs()));
        }
    }
}

#[test]
fn the_nonplanar_kernel_tends_to_the_planar_one() {
    let wing = delta(45.0);
    let at = |z: f64, m: f64, w: f64| {
        Configuration {
            tailplane: Some(tail(1.4, z)),
            ..Configuration::wing_alone(wing)
        }
        .solve_subsonic(m, w)
        .unwrap()
    };
    for (m, w) in [(0.0, 0.0), (0.6, 0.0), (0.6, 0.5)] {
        let planar = at(0.0, m, w);
        let near = at(1e-7, m, w);
        let off = at(0.05, m, w);
        for k in 0..2 {
            let (a, b) = (&near.parts[k].solution, &planar.parts[k].solution);
            assert!(worst(a, b) < 1e-5, "{m} {w} part {k}: {a:?} {b:?}");
        }
        // a real height changes the tail's share
        assert!(worst(&off.parts[1].solution, &planar.parts[1].solution) > 1e-3);
    }
}

#[test]
fn a_foreplane_loads_the_wing() {
    // the foreplane's downwash unloads the wing behind it
    let wing = delta(60.0);
    let canard = Surface {
        kind: SurfaceKind::Foreplane,
        shape: Trapezoid::new(0.25, 0.1, 0.3, 40f64.to_radians()).unwrap(),
        x: -0.5,
        z: 0.05,
        incidence: 0.0,
    };
    let cfg = Configuration {
        foreplane: Some(canard),
        ..Configuration::wing_alone(wing)
    };
    let s = cfg.solve_subsonic(0.3, 0.0).unwrap();
    let alone = Configuration::wing_alone(wing)
        .solve_subsonic(0.3, 0.0)
        .unwrap();
    let w = s.parts.iter().find(|p| p.part == Part::Wing).unwrap();
    let f = s.parts.iter().find(|p| p.part == Part::Foreplane).unwrap();
    assert!(w.solution.lift_alpha < alone.total.lift_alpha);
    assert!(f.solution.lift_alpha > 0.0 && f.solution.moment_alpha > 0.0);
}

#[test]
fn bad_input_is_an_error() {
    let wing = delta(60.0);
    let cfg = Configuration::wing_alone(wing);
    for m in [1.0, 1.5, -0.1, f64::NAN] {
        assert!(matches!(
            cfg.solve_subsonic(m, 0.0),
            Err(ConfigurationError::LiftingSurface(
                LiftingSurfaceError::Mach(_)
            ))
        ));
    }
    for w in [-0.1, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            cfg.solve_subsonic(0.5, w),
            Err(ConfigurationError::LiftingSurface(
                LiftingSurfaceError::Frequency(_)
            ))
        ));
    }
    // a tailplane on the wing, in its plane
    let on = Configuration {
        tailplane: Some(tail(0.5, 0.0)),
        ..Configuration::wing_alone(wing)
    };
    let e = on.solve_subsonic(0.5, 0.0).unwrap_err().to_string();
    assert!(
        e.contains("tailplane") && e.contains("wing") && e.contains("overlap"),
        "{e}"
    );
    // a height lifts the objection
    assert!(
        ConfigurationLattice::new(&Configuration {
            tailplane: Some(tail(0.5, 0.2)),
            ..Configuration::wing_alone(wing)
        })
        .is_ok()
    );
    // a non-finite number is named
    let nan = Configuration {
        tailplane: Some(tail(f64::NAN, 0.0)),
        ..Configuration::wing_alone(wing)
    };
    let e = nan.solve_subsonic(0.5, 0.0).unwrap_err().to_string();
    assert!(e.contains("tailplane") && e.contains("apex x"), "{e}");
    let negative = Configuration {
        tailplane: Some(Surface {
            shape: Trapezoid {
                root_chord: -0.3,
                ..tail(1.5, 0.0).shape
            },
            ..tail(1.5, 0.0)
        }),
        ..Configuration::wing_alone(wing)
    };
    assert!(negative.solve_subsonic(0.5, 0.0).is_err());
}

/// The quasi-steady α̇ numbers come from the first-order term of the
/// non-planar kernel in closed form (K₂'s included); the harmonic solution
/// with I₁ and I₂ by quadrature (no exponential fit) must tend to them as
/// ω̄ → 0, the difference O(ω̄ ln ω̄).
#[test]
fn the_harmonic_solution_tends_to_the_quasi_steady_one() {
    use stability_core::aerodynamics::lifting_surface::{I1Approximation, Spacing};
    let wing = delta(60.0);
    let cfg = Configuration {
        tailplane: Some(tail(1.3, 0.3)),
        ..Configuration::wing_alone(wing)
    };
    let lattice = ConfigurationLattice::with_spec(&cfg, |_| {
        LatticeSpec::new(4, 8, Spacing::Auto).with_kernel(I1Approximation::Quadrature)
    })
    .unwrap();
    for m in [0.0, 0.6] {
        let qs = lattice.solve(m, 0.0).unwrap();
        let mut previous = f64::INFINITY;
        for w in [4e-3, 1e-3] {
            let h = lattice.solve(m, w).unwrap();
            let tail_qs = &qs.parts[1].solution;
            let tail_h = &h.parts[1].solution;
            let err = (tail_h.lift_alphadot - tail_qs.lift_alphadot)
                .abs()
                .max((tail_h.moment_alphadot - tail_qs.moment_alphadot).abs())
                / tail_qs.moment_alphadot.abs();
            println!(
                "M {m} ω̄ {w}: tail ℓ_α̇ {} / {}, μ_α̇ {} / {} ({err:.2e})",
                tail_h.lift_alphadot,
                tail_qs.lift_alphadot,
                tail_h.moment_alphadot,
                tail_qs.moment_alphadot
            );
            assert!(err < 2e-3 && err < previous, "{m} {w}: {err}");
            previous = err;
        }
    }
}

#[test]
fn a_configuration_is_solved_once() {
    use stability_core::aerodynamics::lifting_surface::store;
    let cfg = Configuration {
        tailplane: Some(tail(1.31, 0.21)),
        ..Configuration::wing_alone(delta(55.0))
    };
    let before = store::configuration_solves();
    let a = cfg.solve_subsonic(0.41, 0.0).unwrap();
    let b = cfg.solve_subsonic(0.41, 1e-9).unwrap(); // quasi-steady too
    assert_eq!(a, b);
    // another height is another configuration
    let moved = Configuration {
        tailplane: Some(tail(1.31, 0.22)),
        ..cfg.clone()
    };
    assert_ne!(moved.solve_subsonic(0.41, 0.0).unwrap(), a);
    // (other tests run in parallel and solve too: at least these two)
    assert!(store::configuration_solves() >= before + 2);
    assert!(store::configuration_key(&cfg) != store::configuration_key(&moved));
}

/// A sizing's (or a sweep's) configuration solutions are interpolated
/// between frequency nodes (`store::configuration`, `Harmonic::Interpolated`)
/// as the wing's `FrequencyTable` is: the cubic through the four nodes
/// around ω̄, each node a direct solve. Against direct solves at ω̄ between
/// nodes, every part and the total, each number relative to the largest
/// (60° delta and tail, M = 0.7): measured 3.3e-6 at worst (ω̄ = 0.17), far
/// inside the wing's table's 0.3 % (docs/damping-theories.md); at a node,
/// the node's own solution.
#[test]
fn interpolated_configuration_solutions_are_the_direct_ones() {
    use stability_core::aerodynamics::lifting_surface::Harmonic;
    use stability_core::aerodynamics::lifting_surface::store;
    let cfg = Configuration {
        tailplane: Some(tail(1.3, 0.1)),
        ..Configuration::wing_alone(delta(60.0))
    };
    let mach = 0.7;
    let mut worst_seen = 0.0f64;
    for w in [0.005, 0.17, 0.33, 0.72] {
        let direct = store::configuration(&cfg, mach, w, Harmonic::Direct).unwrap();
        let table = store::configuration(&cfg, mach, w, Harmonic::Interpolated).unwrap();
        assert_eq!(table.total.omega_bar, w);
        assert_eq!(table.parts.len(), direct.parts.len());
        let mut e = worst(&table.total, &direct.total);
        for (p, q) in table.parts.iter().zip(&direct.parts) {
            assert_eq!(p.part, q.part);
            e = e.max(worst(&p.solution, &q.solution));
        }
        eprintln!("ω̄ = {w}: interpolated against direct, worst {e:.2e}");
        worst_seen = worst_seen.max(e);
    }
    assert!(worst_seen < 1e-4, "{worst_seen}");
    assert!(worst_seen > 0.0, "interpolated, not solved at ω̄");
    let at_node = store::configuration(&cfg, mach, 0.3, Harmonic::Interpolated).unwrap();
    let node = store::configuration(&cfg, mach, 0.3, Harmonic::Direct).unwrap();
    assert!(worst(&at_node.total, &node.total) < 1e-12);
}
