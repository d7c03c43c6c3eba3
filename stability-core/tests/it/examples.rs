//! `stability_core::design::examples` against the files it stands for,
//! `examples/tailless-delta-45.toml` and
//! `examples/tailless-delta-60-dimensional.toml` (one definition in code,
//! checked against the one a user runs).

use stability_core::Derivatives;
use stability_core::design::examples::{
    tailless_delta_45, tailless_delta_60, tailless_delta_60_flight,
};

fn example(name: &str) -> toml::Table {
    let path = format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.parse().unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn number(t: &toml::Table, table: &str, key: &str) -> f64 {
    let v = &t[table][key];
    v.as_float()
        .or_else(|| v.as_integer().map(|i| i as f64))
        .unwrap_or_else(|| panic!("[{table}] {key}: {v}"))
}

fn derivatives_of(t: &toml::Table) -> Derivatives {
    assert_eq!(t["notation"].as_str(), Some("report"));
    let values = Derivatives::QUARTIC_INPUTS.map(|name| {
        let table = if ["c_l", "mu1", "i_b"].contains(&name) {
            "flight"
        } else {
            "derivatives"
        };
        number(t, table, name)
    });
    Derivatives::from_quartic_input_values(values)
}

#[test]
fn the_45_degree_example_is_the_file() {
    assert_eq!(
        derivatives_of(&example("tailless-delta-45.toml")),
        tailless_delta_45()
    );
}

#[test]
fn the_60_degree_example_is_the_file() {
    let t = example("tailless-delta-60-dimensional.toml");
    assert_eq!(derivatives_of(&t), tailless_delta_60());
    let f = tailless_delta_60_flight();
    for (key, v) in [
        ("V", f.v),
        ("rho", f.rho),
        ("S", f.s),
        ("chord", f.chord),
        ("mass", f.mass),
    ] {
        assert_eq!(number(&t, "dimensional", key), v, "{key}");
    }
    // the file's comment: μ₁ = m/(½ρSc̄) = 138.2 and C_L = mg/(½ρV²S) = 0.121
    assert!((f.mu1() - 138.2).abs() < 0.05, "{}", f.mu1());
    assert!((f.c_l() - 0.121).abs() < 5e-4, "{}", f.c_l());
}
