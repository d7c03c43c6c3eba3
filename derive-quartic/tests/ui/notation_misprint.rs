//! A printed conversion factor that the definitions contradict, undeclared.
derive_quartic::notations!("tests/ui/specs/notation_misprint.toml");

fn main() {}
