use derive_quartic::Quartic;

#[derive(Quartic)]
#[quartic(spec = "tests/ui/specs/duplicate_entry.toml")]
struct Toy {
    c: f64,
    k: f64,
}

fn main() {}
