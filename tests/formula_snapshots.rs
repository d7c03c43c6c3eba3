//! Snapshots of what the symbolic engine makes of `specs/quartic.toml`: the
//! expansion of eq (4), and the Rust that `#[derive(Quartic)]` emits. A
//! formula change shows up as a snapshot diff for review; `cargo xtask
//! regen` accepts it, `cargo xtask regen --check` fails while it is stale.

use formula_engine::docs;
use workspace_tests::{notation_model, quartic_model};

#[test]
fn quartic_expansion() {
    let model = quartic_model();
    insta::with_settings!({ description => docs::PREAMBLE, omit_expression => true }, {
        insta::assert_snapshot!("quartic_expansion", docs::expansion_text(&model));
    });
}

#[test]
fn quartic_generated_rust() {
    let model = quartic_model();
    insta::with_settings!({ description => docs::PREAMBLE, omit_expression => true }, {
        insta::assert_snapshot!("quartic_generated_rust", docs::generated_rust(&model, "Derivatives"));
    });
}

#[test]
fn notation_generated_rust() {
    let model = notation_model();
    insta::with_settings!({ description => docs::PREAMBLE, omit_expression => true }, {
        insta::assert_snapshot!("notation_generated_rust", docs::generated_notation_rust(&model));
    });
}
