//! The workspace-level tests, one test binary (each module was a test
//! target of its own): the generated code against its reviewed copies, the
//! quartic's roots against the reference, responses and properties of
//! random derivative sets. Their shared helpers are the crate's library
//! (`lib.rs`).

mod generated_code;
mod manifests;
mod quartic_reference;
mod responses;
mod stability_properties;
