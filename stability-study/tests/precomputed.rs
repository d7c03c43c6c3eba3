//! The precomputed solutions are up to date — what `cargo xtask tables
//! --check` says, here a test of the README's command, in a process of its
//! own (so that the store holds the note's study's solutions alone): the
//! file is made by the solvers as they are (its fingerprints), and holds
//! every lifting-surface solution the study needs.

use stability_core::aerodynamics::lifting_surface::precomputed::{Precomputed, SOLVERS};
use stability_core::aerodynamics::lifting_surface::store;
use stability_study::report::{Report, Step, Stopped};

#[test]
fn the_precomputed_solutions_are_the_solvers_and_hold_the_studys() {
    let file = Precomputed::parse(stability_study::study::PRECOMPUTED)
        .unwrap_or_else(|e| panic!("{e}: run `cargo xtask tables`"));
    let quiet = |_: Step<'_>| Ok::<(), std::convert::Infallible>(());
    if let Err(Stopped::Study { what, why }) = Report::compute(quiet) {
        panic!("{what}: {why}");
    }
    let used = store::wing_solutions(&SOLVERS);
    assert!(
        !used.is_empty(),
        "the study used no lifting-surface solution"
    );
    let missing = used.iter().filter(|(k, _)| !file.contains(k)).count();
    assert_eq!(
        missing, 0,
        "the study solved {missing} solutions the file does not hold: run `cargo xtask tables --add`"
    );
}
