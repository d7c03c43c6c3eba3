//! No input makes the reader panic: arbitrary text, and the example with any
//! line deleted or any value replaced, gives a derivative set or an error.

use delta_stability::input::parse;
use proptest::prelude::*;

const EXAMPLE: &str = include_str!("../../examples/tailless-delta-45.toml");

proptest! {
    #[test]
    fn arbitrary_text_never_panics(text in "\\PC{0,400}") {
        let _ = parse("fuzz.toml", &text);
    }

    #[test]
    fn damaged_examples_give_a_result_or_a_located_error(
        line in 0usize..30,
        replacement in prop_oneof![
            Just(String::new()),
            Just("x_u = ".to_string()),
            Just("mu1 = -inf".to_string()),
            Just("[flight".to_string()),
            "[a-z_]{1,8} = -?[0-9]{1,3}(\\.[0-9]{1,3})?",
            "\\PC{0,30}",
        ],
    ) {
        let mut lines: Vec<&str> = EXAMPLE.lines().collect();
        if line < lines.len() {
            lines[line] = &replacement;
        }
        let text = lines.join("\n");
        match parse("fuzz.toml", &text) {
            Ok(f) => {
                prop_assert!(f.derivatives.mu1 > 0.0 && f.derivatives.i_b > 0.0);
                prop_assert!(f.derivatives.quartic_input_values().iter().all(|v| v.is_finite()));
            }
            Err(e) => prop_assert!(e.to_string().starts_with("fuzz.toml")),
        }
    }
}
