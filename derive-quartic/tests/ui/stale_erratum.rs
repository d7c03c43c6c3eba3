use derive_quartic::Quartic;

#[derive(Quartic)]
#[quartic(spec = "tests/ui/specs/stale_erratum.toml")]
struct Toy {
    c: f64,
    k: f64,
}

fn main() {}
