//! `delta-stability quartic FILE [--json]`: the stability quartic of a
//! derivative set (eqs 4–6).

use crate::Failure;
use crate::input;
use serde_json::json;
use stability_core::Quartic;

pub fn run(file: &str, json: bool) -> Result<(), Failure> {
    let input = input::read(file)?;
    let q = Quartic::from_derivatives(&input.derivatives);
    if !q.is_finite() {
        return Err(Failure::Input(crate::diag::InputError::file(
            file,
            format!(
                "the quartic's coefficient(s) {} overflow f64: the derivatives are too large to be a derivative set",
                ["A", "B", "C", "D", "E"]
                    .iter()
                    .zip(q.to_array())
                    .filter(|(_, v)| !v.is_finite())
                    .map(|(n, _)| *n)
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        )));
    }
    if json {
        let out = json!({
            "file": file,
            "notation": input.notation,
            "coefficients": { "A": q.a, "B": q.b, "C": q.c, "D": q.d, "E": q.e },
        });
        println!("{}", serde_json::to_string_pretty(&out).unwrap_or_default());
    } else {
        println!("Stability quartic of {file} (eqs 4–6, the errata of docs/errata.md applied)");
        println!("  A λ⁴ + B λ³ + C λ² + D λ + E = 0,  λ in units of 1/τ, τ = m/(½ρSV)");
        println!();
        for (name, v) in ["A", "B", "C", "D", "E"].iter().zip(q.to_array()) {
            println!("  {name} = {:>14}", crate::fmt::sig(v, 7));
        }
    }
    Ok(())
}
