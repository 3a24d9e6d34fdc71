//! Applications built on the solvers: CoR curves over velocity, parameter sweeps, batches of
//! rows, DEM export and fits of material parameters to drop tests.
//!
//! Each is a library entry point with a thin command in `main.rs` and, where bound, a function of
//! the Python package.

pub mod batch;
pub mod curve;
pub mod curve_angle;
pub mod curve_temperature;
pub mod dem;
pub mod dma;
pub mod fit;
pub mod indent;
pub mod sweep;
