//! Verification and reporting: the catalogue of cases, the `validate` runner and its
//! VALIDATION.md writer, the work-precision bench, the stress run of the accuracy contract and the
//! paper's figures.

pub mod bench;
pub mod catalogue;
pub mod expected;
pub mod external;
pub mod figures;
pub mod markdown;
pub mod sections;
pub mod stress;
pub mod validate;
