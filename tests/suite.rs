//! The integration tests: one module per file of `tests/`, built and linked as one binary (one
//! link against the library instead of one per file; the tests of all files share the threads).
//! One file's tests: a filter, e.g. `cargo test --release --test suite fast_xcheck::`.

mod common;

mod accuracy_contract;
mod catalogue;
mod cli;
mod cli_grammar;
mod cli_messages;
mod cli_outputs;
mod cli_plausibility;
mod cli_plots;
mod contact;
mod core;
mod csv_reader;
mod curve;
mod dem;
mod dem_clients;
mod dma;
mod external_reference;
mod fast_core;
mod fast_general;
mod fast_independent;
mod fast_reduce;
mod fast_xcheck;
mod fit;
mod fit_basins;
mod general_input;
mod general_limits;
mod input_checks;
mod liquid;
mod mdr_general;
mod never_wrong;
mod oblique;
mod rheology;
mod scene_toml;
mod shapes;
mod shapes_fast;
mod snapshots;
mod stability;
mod stress;
mod sweep_core;
mod temperature;
mod theory_grid;
mod theory_hertz;
mod theory_quad;
mod theory_reference;
mod theory_reference_files;
mod theory_special;
mod theory_viscoelastic;
mod two_bodies;
mod validity;
mod verification;
