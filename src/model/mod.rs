//! The physical model: materials (shear and bulk rheology, the equivalent relaxation function),
//! bodies and the impact problem with its outcome, and the named default tolerances.
//!
//! Nothing here knows a solver; the solvers consume what this layer builds.

pub mod bodies;
pub mod contact;
pub mod geometry;
pub mod hertz;
pub mod impact;
pub mod material;
pub mod oblique;
pub mod plausibility;
pub mod tolerances;
pub mod validity;
