//! Reference files (placeholder).
use crate::error::{Error, Result};
use std::path::Path;
/// Write reference files.
pub fn generate_reference(_dir: &Path) -> Result<()> {
    Err(Error::Unsupported("not yet".into()))
}
