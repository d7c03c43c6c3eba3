//! The struct's fields must be the spec's inputs.
use derive_quartic::Quartic;

#[derive(Quartic)]
#[quartic(spec = "tests/ui/specs/field_mismatch.toml")]
struct Toy {
    c: f32,
    kk: f64,
}

fn main() {}
