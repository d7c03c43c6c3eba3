//! The Mach box method (stability_core::supersonic::oscillatory).

use stability_core::geometry::Trapezoid;
use stability_core::supersonic::oscillatory::{MachBoxSpec, solve};

#[test]
fn explore() {
    let r = Trapezoid::new(1.0, 1.0, 5.0, 0.0).unwrap();
    let w = Trapezoid::new(1.0, 0.0, 1.0, 45f64.to_radians()).unwrap();
    let beta = (2.5f64 * 2.5 - 1.0).sqrt();
    println!("rect exact {}", 4.0 / beta * (1.0 - 1.0 / (2.0 * beta * 10.0)));
    for n in [8, 16, 32, 64, 128] {
        let s = solve(&r, 2.5, 0.0, MachBoxSpec { strips: n, richardson: false }).unwrap();
        let d = solve(&w, 2.5, 0.0, MachBoxSpec { strips: n, richardson: false }).unwrap();
        println!("{n} rect {} {}  delta {} {}", s.lift_alpha, s.moment_alpha, d.lift_alpha, d.moment_alpha);
    }
}
