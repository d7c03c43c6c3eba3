use derive_quartic::Quartic;

#[derive(Quartic)]
#[quartic(spec = "tests/ui/specs/unparsable_expression.toml")]
struct Toy {
    c: f64,
    k: f64,
}

fn main() {}
