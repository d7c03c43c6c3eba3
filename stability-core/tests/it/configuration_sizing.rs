//! `size-tail`'s search (configuration::sizing) against a brute-force scan
//! of areas: the tailless 45° delta fails the §8 standard at M = 1.2–1.5
//! (the note's Fig 33), and a tailplane of some area mends it.

use stability_core::criteria::Verdict;
use stability_core::design::case::{Case, DampingModel, evaluate_point};
use stability_core::design::sizing::{TOLERANCE, size_surface};
use stability_core::design::study::report_wing;
use stability_core::geometry::configuration::Configuration;
use stability_core::geometry::configuration::Surface;
use stability_core::geometry::configuration::SurfaceKind;
use stability_core::geometry::{Planform, Size, Trapezoid};
use std::sync::Arc;

const MACHS: [f64; 4] = [1.2, 1.3, 1.4, 1.5];

/// The report's 45° delta (c₀ = 10, μ₁ = 50) with the example's tail: a
/// cropped 45° delta (λ = 0.2) of area 16, apex 12 aft, in the plane.
fn tailed() -> Case {
    let mut case = report_wing(45.0, 1.2);
    case.planform = Planform::new(45f64.to_radians(), 0.0, Size::RootChord(10.0)).unwrap();
    // the note's fairing, under which the wing alone fails at M = 1.2 (the
    // default model meets there: no tail to size)
    case.damping = DampingModel::FairedTheories;
    let tail = Planform::new(45f64.to_radians(), 0.2, Size::Area(16.0)).unwrap();
    case.aero.configuration = Some(Arc::new(Configuration {
        tailplane: Some(Surface {
            kind: SurfaceKind::Tailplane,
            shape: Trapezoid::from(&tail),
            x: 12.0,
            z: 0.0,
            incidence: 0.0,
        }),
        ..Configuration::wing_alone(Trapezoid::from(&case.planform))
    }));
    case
}

/// Whether the tail of `area` (the same shape and apex) meets the
/// standard at every Mach number, evaluated directly.
fn meets(case: &Case, area: f64) -> bool {
    let tail = Planform::new(45f64.to_radians(), 0.2, Size::Area(area)).unwrap();
    let mut config = (**case.aero.configuration.as_ref().unwrap()).clone();
    config.tailplane.as_mut().unwrap().shape = Trapezoid::from(&tail);
    MACHS.iter().all(|&m| {
        let mut c = case.clone();
        c.mach = m;
        c.aero.configuration = Some(Arc::new(config.clone()));
        let r = evaluate_point(&c).unwrap();
        stability_core::analysis::verdict::overall(&r.analysis) == Verdict::Meets
    })
}

#[test]
fn the_smallest_tail_matches_a_brute_force_scan() {
    let case = tailed();
    let s = size_surface(&case, SurfaceKind::Tailplane, &MACHS, None).unwrap();
    let area = s.area.expect("a tail up to the wing's area mends it");
    assert!((s.limit - 100.0).abs() < 1e-12);
    // the brute force: areas 0.05, 0.10, … 100 — the first that meets
    let dense = (1..=2000)
        .map(|i| 0.05 * i as f64)
        .find(|&a| meets(&case, a))
        .unwrap();
    eprintln!(
        "size-tail: S_T = {area:.4}; brute force (step 0.05): {dense:.2}; V̄ = {:?}",
        s.volume
    );
    assert!(
        area <= dense + 1e-9 && area > dense - 0.05,
        "{area} vs {dense}"
    );
    assert!(meets(&case, area));
    assert!(!meets(&case, area * (1.0 - 2.0 * TOLERANCE)));
    assert!(s.outcomes.iter().all(|o| o.verdict == Some(Verdict::Meets)));
    // V̄ = S_T l/(S c̄), l from the c.g. (3.333 + 0.25·6.667 = 5) to the
    // tail's M.A.C. quarter chord, by hand for the scaled cropped delta
    let tail = Planform::new(45f64.to_radians(), 0.2, Size::Area(area)).unwrap();
    let l = 12.0 + tail.x_mac() + 0.25 * tail.mac() - 5.0;
    let v = area * l / (100.0 * 20.0 / 3.0);
    assert!((s.volume.unwrap() - v).abs() < 1e-12 * v);
}

#[test]
fn no_area_up_to_the_limit_is_said_plainly() {
    let mut case = tailed();
    case.mu1 = 2000.0;
    let s = size_surface(&case, SurfaceKind::Tailplane, &MACHS, Some(1.0)).unwrap();
    assert_eq!(s.area, None);
    assert!(s.outcomes.iter().any(|o| o.verdict != Some(Verdict::Meets)));
    let e = size_surface(&case, SurfaceKind::Foreplane, &MACHS, None).unwrap_err();
    assert!(e.to_string().contains("no [foreplane]"), "{e}");
}

/// The search starts where tails are, whatever the limit: a limit of
/// 1e100 (the scan once began at 1e97, where the numbers overflow and no
/// area met) finds the tail a limit of the wing's area does.
#[test]
fn a_limit_far_above_the_wing_finds_the_same_tail() {
    let case = tailed();
    let own = size_surface(&case, SurfaceKind::Tailplane, &MACHS, None)
        .unwrap()
        .area
        .unwrap();
    for limit in [1e4, 1e100] {
        let s = size_surface(&case, SurfaceKind::Tailplane, &MACHS, Some(limit)).unwrap();
        let area = s.area.expect("a tail below the wing's area mends it");
        assert!(
            (area - own).abs() <= 2.0 * TOLERANCE * own,
            "{limit}: {area} vs {own}"
        );
        assert!(meets(&case, area), "{limit}: {area}");
        assert!(
            !meets(&case, area * (1.0 - 2.0 * TOLERANCE)),
            "{limit}: {area}"
        );
        assert_eq!(s.limit, limit);
    }
}
