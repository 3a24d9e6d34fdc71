//! Every default tolerance and accuracy setting of the crate, with names. They only ever get tighter.

/// Default requested relative accuracy of the CoR.
pub const DEFAULT_RTOL: f64 = 1e-6;
/// Smallest rtol accepted.
pub const MIN_RTOL: f64 = 1e-12;
/// Largest rtol accepted.
pub const MAX_RTOL: f64 = 0.1;
