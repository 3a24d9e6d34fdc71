//! Input and output: the strict TOML scene and its writer, CSV line readers, atomic output files
//! and SVG charts of plain series.

pub mod lines;
pub mod oblique;
pub mod output;
pub mod plot;
pub mod prony_table;
pub mod run_files;
pub mod scene;
pub mod scene_toml;
