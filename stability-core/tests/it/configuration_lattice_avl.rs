//! The configuration lattice's steady derivatives against AVL's (an
//! independent vortex lattice over the same surfaces:
//! `scripts/avl_configuration_fixtures.py` writes the fixture with optvl)
//! for the note's 60° delta with a straight-tapered surface in three
//! layouts — a coplanar tailplane, one 0.3 root chords above the wing's
//! plane, a foreplane 0.1 above it — at M = 0 and 0.5. Same references:
//! the wing's S and c̄, moments about the wing M.A.C.'s leading edge.
//!
//! Asserted for the tailplane above and the foreplane: C_Lα, z_q = −C_Lq/2
//! and m_q = C_mq/2 (AVL's rates are per qc̄/2V) within 3 %, the neutral
//! point within 0.01c̄ (issue 21 item 7). Found: C_Lα within 0.05 %, z_q
//! 0.1 %, m_q 0.35 %, the neutral point within 0.0023c̄.
//!
//! # The coplanar tailplane
//! It lies in the wing's wake, half a strip from the wing's trailing legs.
//! AVL by default gives every horseshoe acting on another *component* a
//! finite core of twice its strip width (AVL 3.36, `aic.f`, `VVOR`:
//! r_core = VRCOREW·Δy, VRCOREW = 2), which smears the wing's downwash at
//! the tail: with that default AVL's C_Lα falls only slowly, 2.828, 2.798,
//! 2.765, 2.745 at 8, 16, 32, 48 strips (the fixture's
//! `coplanar_default_core`; 3.5 % above ours at 48). The script therefore
//! makes the two surfaces one COMPONENT (AVL's singular kernel, as this
//! lattice's), and measures AVL's convergence on 4, 8, 16 chordwise ×
//! 12, 24, 48 strips (`coplanar_study`), Richardson-extrapolated in the
//! strips and then chordwise at the orders observed on the three densities
//! (strips: 1.0–2.2; chordwise 0.6–0.9). Our lattice's own raw lattices,
//! 4, 8, 16 chordwise × 8, 16, 32 strips, extrapolated the same way
//! (strips: order 0.9–1.3, not the default's assumed 2; chordwise
//! 1.4–1.9), meet AVL's extrapolation within 0.06 % in C_Lα, 0.02 % in
//! z_q, 0.31 % in m_q and 0.0022c̄ in the neutral point (asserted: 1 % and
//! 0.005c̄). The default lattice (its strip extrapolation assumes order 2)
//! stays within 0.32 % (C_Lα), 1.1 % (z_q), 2.3 % (m_q) and 0.0072c̄ (the
//! neutral point) of AVL's extrapolated values: asserted 3 % and 0.01c̄.
//!
//! # Issue 30: the 45° delta with a coplanar tailplane
//! The report's 45° delta (c₀ = 10) with the tailplane a config's keys
//! give (sweep 45°, taper 0.3, root chord 3, apex 11 aft, z = 0), studied
//! in AVL as the coplanar layout above at M = 0.05 and 0.5 (the fixture's
//! `tailed_45`). The configuration lattice's quasi-steady solution meets
//! AVL's extrapolation about h = 0 and 0.25 within 3 % in C_Lα, z_q, m_q
//! and 0.01c̄ in the neutral point; the design point through
//! `case::evaluate` does the same at every i_B, μ₁ and C_L·M²: under a
//! quasi-steady damping model the configuration's increment is quasi-steady
//! too (the model's frequency policy), so its derivatives do not change
//! with i_B or μ₁.

use serde_json::Value;
use stability_core::aerodynamics::damping::Theory;
use stability_core::aerodynamics::lifting_surface::configuration::ConfigurationLattice;
use stability_core::aerodynamics::lifting_surface::{LatticeSpec, Solution, Spacing};
use stability_core::aerodynamics::models::aero::AeroModelName;
use stability_core::design::case::{DampingModel, evaluate};
use stability_core::design::study::report_wing;
use stability_core::geometry::configuration::Configuration;
use stability_core::geometry::configuration::Surface;
use stability_core::geometry::configuration::SurfaceKind;
use stability_core::geometry::{Planform, Size, Trapezoid};
use std::sync::Arc;

fn g(v: &Value, k: &str) -> f64 {
    v[k].as_f64().unwrap()
}

/// The fixture's wing and other surface's planform.
fn planforms(avl: &Value) -> (Trapezoid, Trapezoid) {
    let w = &avl["wing"];
    let wing = Trapezoid::new(1.0, 0.0, g(w, "semi_span"), g(w, "sweep_deg").to_radians()).unwrap();
    assert!(
        (wing.mac() - g(w, "mac")).abs() < 1e-12 && (wing.x_mac() - g(w, "x_mac")).abs() < 1e-12
    );
    let s = &avl["surface"];
    let shape = Trapezoid::new(
        g(s, "root_chord"),
        g(s, "tip_chord"),
        g(s, "semi_span"),
        g(s, "sweep_deg").to_radians(),
    )
    .unwrap();
    (wing, shape)
}

/// One layout's configuration.
fn configuration(layout: &Value, wing: Trapezoid, shape: Trapezoid) -> Configuration {
    let kind = match layout["kind"].as_str().unwrap() {
        "tailplane" => SurfaceKind::Tailplane,
        _ => SurfaceKind::Foreplane,
    };
    let surface = Surface {
        kind,
        shape,
        x: g(layout, "x"),
        z: g(layout, "z"),
        incidence: 0.0,
    };
    Configuration {
        tailplane: (kind == SurfaceKind::Tailplane).then_some(surface),
        foreplane: (kind == SurfaceKind::Foreplane).then_some(surface),
        ..Configuration::wing_alone(wing)
    }
}

/// AVL's (C_Lα, h_n, z_q, m_q) of one run (or extrapolation).
fn avl_numbers(cfg: &Configuration, run: &Value) -> [f64; 4] {
    let r = |k: &str| g(run, k);
    [
        r("CLa"),
        (r("Xnp") - cfg.wing.x_mac()) / cfg.wing.mac(),
        -r("CLq") / 2.0,
        r("Cmq") / 2.0,
    ]
}

/// Our (C_Lα, h_n, z_q, m_q) of the default lattice at `mach`.
fn our_numbers(cfg: &Configuration, mach: f64) -> [f64; 4] {
    let d = cfg
        .solve_subsonic(mach, 0.0)
        .unwrap()
        .total
        .derivatives(0.0, 0.0)
        .unwrap();
    [d.lift_slope, d.aerodynamic_centre, d.z_q, d.m_q]
}

/// (C_Lα, h_n, z_q, m_q), ours and AVL's, of one run.
fn pairs(cfg: &Configuration, run: &Value) -> [(f64, f64); 4] {
    let ours = our_numbers(cfg, g(run, "mach"));
    let avl = avl_numbers(cfg, run);
    std::array::from_fn(|k| (ours[k], avl[k]))
}

/// The differences of ours from AVL's: relative in C_Lα, z_q, m_q, in c̄
/// in h_n.
fn differences(pairs: [(f64, f64); 4]) -> [f64; 4] {
    std::array::from_fn(|k| {
        let (ours, theirs) = pairs[k];
        if k == 1 {
            (ours - theirs).abs()
        } else {
            (ours / theirs - 1.0).abs()
        }
    })
}

/// Richardson's extrapolation of f at densities N, 2N, 4N (error ~ N^−p)
/// at the order p observed on the three — (p, value) — or `None` if the
/// differences do not shrink with one sign (as the script's `richardson`).
fn richardson(f: [f64; 3]) -> Option<(f64, f64)> {
    let (d1, d2) = (f[1] - f[0], f[2] - f[1]);
    if d1 == 0.0 || d2 / d1 <= 0.0 || d2.abs() >= d1.abs() {
        return None;
    }
    let p = (d1 / d2).log2();
    Some((p, f[2] + d2 / (2f64.powf(p) - 1.0)))
}

/// Extrapolates `at(chordwise index, strip index)` (three of each, each
/// twice the last) in the strips at each chordwise count, then chordwise:
/// (the strips' orders, the chordwise order, the value).
fn extrapolated(at: impl Fn(usize, usize) -> f64) -> ([f64; 3], f64, f64) {
    let spanwise: [(f64, f64); 3] =
        std::array::from_fn(|c| richardson([at(c, 0), at(c, 1), at(c, 2)]).unwrap());
    let (p, v) = richardson(spanwise.map(|s| s.1)).unwrap();
    (spanwise.map(|s| s.0), p, v)
}

fn fixture() -> Value {
    serde_json::from_str(include_str!("../fixtures/avl_configuration.json")).unwrap()
}

/// The coplanar layout's configuration.
fn coplanar(avl: &Value) -> Configuration {
    let (wing, shape) = planforms(avl);
    let layout = avl["layouts"]
        .as_array()
        .unwrap()
        .iter()
        .find(|l| g(l, "z") == 0.0)
        .unwrap();
    configuration(layout, wing, shape)
}

#[test]
fn steady_derivatives_agree_with_avl() {
    let avl = fixture();
    let (wing, shape) = planforms(&avl);
    let mut worst = [0.0f64; 4];
    let mut ours_coplanar = 0.0;
    println!("layout | M | C_Lα ours/AVL | h_n ours/AVL | z_q ours/AVL | m_q ours/AVL");
    for layout in avl["layouts"].as_array().unwrap() {
        let cfg = configuration(layout, wing, shape);
        let is_coplanar = g(layout, "z") == 0.0;
        for run in layout["runs"].as_array().unwrap() {
            let pairs = pairs(&cfg, run);
            println!(
                "{} | {} | {}",
                layout["name"].as_str().unwrap(),
                g(run, "mach"),
                pairs.map(|(a, b)| format!("{a:.4}/{b:.4}")).join(" | ")
            );
            if is_coplanar {
                // against AVL's extrapolation instead (below)
                ours_coplanar = if g(run, "mach") == 0.0 {
                    pairs[0].0
                } else {
                    ours_coplanar
                };
                continue;
            }
            for (w, d) in worst.iter_mut().zip(differences(pairs)) {
                *w = w.max(d);
            }
        }
    }
    println!("largest differences (C_Lα, h_n, z_q, m_q): {worst:?}");
    assert!(
        worst[0] < 0.03 && worst[2] < 0.03 && worst[3] < 0.03,
        "{worst:?}"
    );
    assert!(worst[1] < 0.01, "{worst:?}");
    // AVL's default finite cores between the surfaces: its C_Lα falls
    // slowly towards ours and stays above it
    let default_core: Vec<f64> = avl["coplanar_default_core"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| g(c, "CLa"))
        .collect();
    assert!(
        default_core
            .windows(2)
            .all(|p| p[1] < p[0] && p[1] > ours_coplanar),
        "{default_core:?}"
    );
}

/// AVL's coplanar study (one component): its grid converges in the
/// strips and chordwise, the fixture's extrapolation is the grid's
/// (recomputed here), equal strips reach the cosine strips' value to 0.1 %,
/// the densest lattice lies within 0.5 % of it in C_Lα while the default
/// cores' densest lies over 3 % above; and the default
/// lattice agrees with it within 3 % (C_Lα, z_q, m_q) and 0.01c̄ (h_n).
#[test]
fn the_coplanar_tailplane_agrees_with_avls_extrapolation() {
    let avl = fixture();
    let cfg = coplanar(&avl);
    let default_core_densest = avl["coplanar_default_core"]
        .as_array()
        .unwrap()
        .last()
        .unwrap();
    for study in avl["coplanar_study"].as_array().unwrap() {
        let mach = g(study, "mach");
        check_study(study, 1e-3);
        let fixture_ext = &study["extrapolated"];
        if mach == 0.0 {
            assert!(g(default_core_densest, "CLa") / g(fixture_ext, "CLa") > 1.03);
        }
        let avl_numbers = avl_numbers(&cfg, fixture_ext);
        let ours = our_numbers(&cfg, mach);
        let d = differences(std::array::from_fn(|k| (ours[k], avl_numbers[k])));
        println!(
            "M {mach}: ours {ours:.4?}, AVL extrapolated {avl_numbers:.4?}, differences {d:.4?}"
        );
        assert!(d[0] < 0.03 && d[2] < 0.03 && d[3] < 0.03, "{d:?}");
        assert!(d[1] < 0.01, "{d:?}");
    }
}

/// One of AVL's convergence studies: its grid converges in the strips
/// (order 0.8–2.5) and chordwise (0.5–1.5), the fixture's extrapolation is
/// the grid's (recomputed here), the densest lattice lies within 0.5 % of
/// it in C_Lα, and equal strips (4 chordwise) reach the cosine strips'
/// value within `equal_tolerance`.
fn check_study(study: &Value, equal_tolerance: f64) {
    let mach = g(study, "mach");
    let grid = study["grid"].as_array().unwrap();
    let fixture_ext = &study["extrapolated"];
    for key in ["CLa", "Cma", "CLq", "Cmq", "Xnp"] {
        let (orders, order, value) = extrapolated(|c, s| g(&grid[3 * c + s], key));
        println!(
            "AVL M {mach} {key}: strips' orders {orders:.2?}, chordwise {order:.2}, {value:.5}"
        );
        assert!(
            orders.iter().all(|p| (0.8..2.5).contains(p)),
            "{key} {orders:?}"
        );
        assert!((0.5..1.5).contains(&order), "{key} {order}");
        assert!((value / g(fixture_ext, key) - 1.0).abs() < 1e-9, "{key}");
    }
    let equal = g(&study["equal_strips_extrapolated"], "CLa");
    let cosine = g(&study["spanwise_extrapolated"][0], "CLa");
    assert!(
        (equal / cosine - 1.0).abs() < equal_tolerance,
        "{equal} {cosine}"
    );
    let densest = g(&grid[8], "CLa");
    assert!((densest / g(fixture_ext, "CLa") - 1.0).abs() < 0.005);
}

/// Our lattice's own convergence on the coplanar layout: single lattices
/// of 4, 8, 16 chordwise × 8, 16, 32 strips, extrapolated as AVL's (at the
/// observed orders), meet AVL's extrapolation within 1 % (C_Lα, z_q, m_q)
/// and 0.005c̄ (h_n). The strips converge at order ≈ 1 here (asserted
/// 0.8–1.5), not 2.
#[test]
fn the_coplanar_lattice_converges_to_avls_extrapolation() {
    let avl = fixture();
    let cfg = coplanar(&avl);
    let lattices: Vec<ConfigurationLattice> = [4, 8, 16]
        .iter()
        .flat_map(|&c| [8, 16, 32].map(|s| (c, s)))
        .map(|(c, s)| {
            ConfigurationLattice::with_spec(&cfg, |_| LatticeSpec::new(c, s, Spacing::Auto))
                .unwrap()
        })
        .collect();
    for study in avl["coplanar_study"].as_array().unwrap() {
        let mach = g(study, "mach");
        let numbers: Vec<[f64; 4]> = lattices
            .iter()
            .map(|l| {
                let d = l
                    .solve(mach, 0.0)
                    .unwrap()
                    .total
                    .derivatives(0.0, 0.0)
                    .unwrap();
                [d.lift_slope, d.aerodynamic_centre, d.z_q, d.m_q]
            })
            .collect();
        let avl_numbers = avl_numbers(&cfg, &study["extrapolated"]);
        let mut ours = [0.0; 4];
        for (k, slot) in ours.iter_mut().enumerate() {
            let (orders, order, value) = extrapolated(|c, s| numbers[3 * c + s][k]);
            println!(
                "ours M {mach} #{k}: strips' orders {orders:.2?}, chordwise {order:.2}, {value:.5}"
            );
            assert!(
                orders.iter().all(|p| (0.8..1.5).contains(p)),
                "{k} {orders:?}"
            );
            *slot = value;
        }
        let d = differences(std::array::from_fn(|k| (ours[k], avl_numbers[k])));
        println!(
            "M {mach}: ours extrapolated {ours:.4?}, AVL's {avl_numbers:.4?}, differences {d:.4?}"
        );
        assert!(d[0] < 0.01 && d[2] < 0.01 && d[3] < 0.01, "{d:?}");
        assert!(d[1] < 0.005, "{d:?}");
    }
}

/// Issue 30's case from the fixture's `tailed_45`: the report's 45° delta
/// (c₀ = 10) and the tailplane its config's keys give (`[tailplane]
/// sweep = 45, taper = 0.3, root_chord = 3`: an unswept trailing edge, so
/// tip chord 0.9, semi-span 2.1), apex at x = 11, z = 0; both built as a
/// config builds them and checked against the planforms AVL was given.
fn tailed_45(avl: &Value) -> (Planform, Configuration) {
    let t = &avl["tailed_45"];
    let (w, keys, s) = (&t["wing"], &t["tailplane_keys"], &t["surface"]);
    let planform = |k: &Value, taper: f64| {
        let size = Size::RootChord(g(k, "root_chord"));
        Planform::new(g(k, "sweep_deg").to_radians(), taper, size).unwrap()
    };
    let wing = planform(w, 0.0);
    let tail = Trapezoid::from(&planform(keys, g(keys, "taper")));
    let close = |a: f64, b: f64| (a - b).abs() < 1e-12 * b.abs();
    assert!(close(wing.semi_span(), g(w, "semi_span")) && close(wing.mac(), g(w, "mac")));
    assert!(close(Trapezoid::from(&wing).x_mac(), g(w, "x_mac")));
    assert!(
        close(tail.tip_chord, g(s, "tip_chord")) && close(tail.semi_span, g(s, "semi_span")),
        "{tail:?}"
    );
    (wing, configuration(t, Trapezoid::from(&wing), tail))
}

/// AVL's run (or extrapolation) as the program's quasi-steady solution
/// about the wing M.A.C.'s leading edge: its rates per qc̄/V, half AVL's
/// per qc̄/2V.
fn avl_solution(mach: f64, run: &Value) -> Solution {
    Solution {
        mach,
        omega_bar: 0.0,
        lift_alpha: g(run, "CLa"),
        moment_alpha: g(run, "Cma"),
        lift_alphadot: 0.0,
        moment_alphadot: 0.0,
        lift_q: g(run, "CLq") / 2.0,
        moment_q: g(run, "Cmq") / 2.0,
    }
}

/// (C_Lα, h_n, z_q, m_q) of an entry of the fixture's `program`.
fn avl_program(p: &Value) -> [f64; 4] {
    ["lift_slope", "aerodynamic_centre", "z_q", "m_q"].map(|k| g(p, k))
}

/// Issue 30: the configuration lattice's quasi-steady solution (ω̄ = 0) of
/// the 45° delta with its coplanar tailplane at M = 0.05 and 0.5, about
/// the c.g. h = 0 and 0.25, against AVL's extrapolation (one component,
/// aligned strips): C_Lα, z_q, m_q within 3 %, the neutral point within
/// 0.01c̄. Found: C_Lα 0.2 %, z_q 0.2 %, m_q 1.5 %, h_n 0.002c̄. Also:
/// AVL's study converges as the 60° delta's does; the fixture's values in
/// the note's notation are the program's axis transfer
/// (`Solution::derivatives`) of AVL's extrapolation, and that transfer
/// of AVL's densest lattice meets AVL's own run about h = 0.25 (1e-9).
#[test]
fn the_tailed_45_delta_quasi_steady_lattice_agrees_with_avl() {
    let avl = fixture();
    let (_, cfg) = tailed_45(&avl);
    for study in avl["tailed_45"]["study"].as_array().unwrap() {
        let mach = g(study, "mach");
        check_study(study, 2e-3);
        let (densest, about_cg) = (&study["grid"][8], &study["about_cg"]);
        let moved = avl_solution(mach, densest)
            .derivatives(g(about_cg, "h"), 0.0)
            .unwrap();
        let direct = avl_solution(mach, about_cg).derivatives(0.0, 0.0).unwrap();
        for (a, b) in [
            (moved.z_q, direct.z_q),
            (moved.m_q, direct.m_q),
            (moved.m_w, direct.m_w),
        ] {
            assert!((a / b - 1.0).abs() < 1e-9, "{a} {b}");
        }
        let ext = avl_solution(mach, &study["extrapolated"]);
        for p in study["program"].as_array().unwrap() {
            let h = g(p, "h");
            let theirs = avl_program(p);
            let d = ext.derivatives(h, 0.0).unwrap();
            for (a, b) in [
                (d.lift_slope, theirs[0]),
                (d.z_q, theirs[2]),
                (d.m_q, theirs[3]),
            ] {
                assert!((a / b - 1.0).abs() < 1e-12, "{a} {b}");
            }
            let ours = cfg
                .solve_subsonic(mach, 0.0)
                .unwrap()
                .total
                .derivatives(h, 0.0)
                .unwrap();
            let ours = [ours.lift_slope, ours.aerodynamic_centre, ours.z_q, ours.m_q];
            let diff = differences(std::array::from_fn(|k| (ours[k], theirs[k])));
            println!(
                "M {mach} h {h}: ω̄ = 0 lattice {ours:.4?}, AVL {theirs:.4?}, differences {diff:.4?}"
            );
            assert!(
                diff[0] < 0.03 && diff[2] < 0.03 && diff[3] < 0.03,
                "{diff:?}"
            );
            assert!(diff[1] < 0.01, "{diff:?}");
        }
    }
}

/// Issue 30: the design point (`case::evaluate`, `--damping lifting-surface
/// --aero lifting-surface`, quasi-steady) of the 45° delta with its
/// coplanar tailplane at M = 0.05 and 0.5, h = 0 and 0.25: its z_q, m_q
/// the same at i_B = 0.08 and 8, μ₁ = 50 and 500, and C_L·M² = 0.05 (the
/// report's and the issue's; C_L = 20 at M = 0.05) and 0.2M² (C_L = 0.2) —
/// a quasi-steady derivative depends on none of them — and within 3 % of
/// AVL's extrapolation, its lift slope too, its aerodynamic centre within
/// 0.01c̄. Today the configuration's increment is taken at §9's estimate
/// of the short period's ω̄, √(−m_w/(μ₁i_B)) (`case.rs`:
/// `evaluate_with`'s quasi-steady run passes it to
/// `Point::add_configuration`): m_q 20 % off AVL's at M = 0.05, h = 0,
/// i_B = 0.08, μ₁ = 50, C_L·M² = 0.05.
#[test]
fn the_tailed_45_design_point_is_quasi_steady_and_agrees_with_avl() {
    let avl = fixture();
    let (wing, cfg) = tailed_45(&avl);
    let cfg = Arc::new(cfg);
    for study in avl["tailed_45"]["study"].as_array().unwrap() {
        let mach = g(study, "mach");
        for p in study["program"].as_array().unwrap() {
            let (h, theirs) = (g(p, "h"), avl_program(p));
            let mut first: Option<[f64; 4]> = None;
            let flights = [0.05, 0.2 * mach * mach].into_iter().flat_map(|cl_m2| {
                [(0.08, 50.0), (8.0, 50.0), (0.08, 500.0), (8.0, 500.0)]
                    .map(|(i_b, mu1)| (i_b, mu1, cl_m2))
            });
            for (i_b, mu1, cl_m2) in flights {
                let mut case = report_wing(45.0, mach);
                case.planform = wing;
                (case.h, case.i_b, case.mu1, case.cl_m2) = (h, i_b, mu1, cl_m2);
                case.damping = DampingModel::Theory(Theory::LiftingSurface);
                case.aero = case.aero.with_name(AeroModelName::LiftingSurface);
                case.aero.configuration = Some(Arc::clone(&cfg));
                let r = evaluate(&case).unwrap();
                let c = &r.coefficients;
                let ours = [
                    c.lift_slope.value,
                    c.aerodynamic_centre.value,
                    r.derivatives.z_q,
                    r.derivatives.m_q,
                ];
                let diff = differences(std::array::from_fn(|k| (ours[k], theirs[k])));
                println!(
                    "M {mach} h {h} i_B {i_b} μ₁ {mu1} C_L·M² {cl_m2}: {ours:.4?}, AVL {theirs:.4?}, differences {diff:.4?}"
                );
                let same = first.get_or_insert(ours);
                assert!(
                    (0..4).all(|k| (ours[k] - same[k]).abs() <= 1e-12 * same[k].abs()),
                    "{ours:?} against {same:?}"
                );
                assert!(
                    diff[0] < 0.03 && diff[2] < 0.03 && diff[3] < 0.03,
                    "{diff:?}"
                );
                assert!(diff[1] < 0.01, "{diff:?}");
            }
        }
    }
}
