//! derive-quartic's integration tests, one test binary: the derive on the
//! project's spec ([`derive`]) and the bad specs that must not compile
//! ([`compile_fail`]).

mod compile_fail;
mod derive;
