use derive_quartic::Quartic;

#[derive(Quartic)]
#[quartic(spec = "tests/ui/specs/unknown_symbol.toml")]
struct Toy {
    c: f64,
    k: f64,
}

fn main() {}
