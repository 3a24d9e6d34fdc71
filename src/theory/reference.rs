//! Reference impact solver (placeholder).
use crate::error::{Error, Result};
use crate::impact::Outcome;
use crate::material::Prony;
/// Reference impact.
pub fn impact(_prony: &Prony, _rtol: f64, _history: bool) -> Result<Outcome> {
    Err(Error::Unsupported("not yet".into()))
}
