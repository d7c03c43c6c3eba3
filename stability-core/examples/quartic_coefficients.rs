//! Reads derivative sets, one per line (the 15 inputs of
//! `Derivatives::QUARTIC_INPUTS` separated by spaces), and prints each
//! one's quartic coefficients A B C D E as shortest round-trip decimals:
//! the f64 coefficients that `scripts/badly_scaled_reference.py` computes
//! reference roots for.
//!
//!     cargo run -q -p stability-core --example quartic_coefficients < sets.txt

use stability_core::{Derivatives, Quartic};
use std::io::BufRead;

fn main() {
    for line in std::io::stdin().lock().lines() {
        let line = line.expect("stdin");
        let v: Vec<f64> = line
            .split_whitespace()
            .map(|x| x.parse().expect("a number"))
            .collect();
        let Ok(values) = <[f64; 15]>::try_from(v) else {
            eprintln!("skipped (not 15 numbers): {line}");
            continue;
        };
        let q = Quartic::from_derivatives(&Derivatives::from_quartic_input_values(values));
        let c = q.to_array().map(|x| format!("{x:?}"));
        println!("{}", c.join(" "));
    }
}
