//! Compile-fail behaviour: each bad spec under `tests/ui/specs/` must stop
//! the build with a message that names the file, line and entry, and says
//! what to do. The expected messages are the `.stderr` files beside each
//! case (`TRYBUILD=overwrite cargo test -p derive-quartic` regenerates them).

#[test]
fn bad_specs_are_compile_errors() {
    // trybuild compiles the cases in its own project under target/; point the
    // macro back at this crate so that the spec paths resolve.
    // SAFETY: the binary's other tests (`derive`'s) read no environment
    // variable, and the variable is only ever set to this one value.
    unsafe { std::env::set_var("DERIVE_QUARTIC_MANIFEST_DIR", env!("CARGO_MANIFEST_DIR")) };
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
}
