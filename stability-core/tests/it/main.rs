//! stability-core's integration tests, one test binary: each module was a
//! test file of its own (each linking the crate, 47 binaries), and the
//! modules share what they share once — the reference CSVs' reader
//! ([`support`]), the counting allocator ([`allocations`]) and the store of
//! lifting-surface solutions, which a module's solves fill for the others.
//! Data and fixtures are in `tests/data/` and `tests/fixtures/`; proptest's
//! saved failures in `tests/proptest-regressions/` (where its default
//! `SourceParallel` persistence puts a module of this binary's).
//!
//! One test stays a binary of its own, `tests/sweep_solves.rs`: it counts
//! the process's solves and clears the store, which it cannot do beside
//! other tests.

mod allocations;
mod support;

mod aircraft_published;
mod atmosphere;
mod avl;
mod badly_scaled;
mod case;
mod configuration_case;
mod configuration_lattice;
mod configuration_lattice_avl;
mod configuration_lattice_panelaero;
mod configuration_sizing;
mod configuration_supersonic;
mod configuration_tail_volume;
mod damping;
mod dimensional;
mod engineering;
mod errors;
mod examples;
mod frozen_solutions;
mod geometry;
mod json;
mod lifting_surface;
mod lifting_surface_avl;
mod lifting_surface_case;
mod lifting_surface_convergence;
mod lifting_surface_mach_range;
mod lifting_surface_near_sonic;
mod lifting_surface_no_alloc;
mod lifting_surface_panelaero;
mod lifting_surface_wiring;
mod mach_table;
mod neutral_point;
mod no_alloc;
mod notation;
mod p_method;
mod roots_accuracy;
mod roots_batch;
mod roots_fuzz;
mod stiffness;
mod supersonic;
mod supersonic_case;
mod supersonic_oscillatory;
mod supersonic_oscillatory_cache;
mod sweep;
mod trapezoid;
mod typical_section;
mod uncertainty;
mod uncertainty_batch;
mod uncertainty_quasi;
