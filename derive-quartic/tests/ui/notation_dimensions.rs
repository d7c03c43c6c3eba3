//! Definitions whose dimensions do not cancel.
derive_quartic::notations!("tests/ui/specs/notation_dimensions.toml");

fn main() {}
