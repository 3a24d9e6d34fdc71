//! Numerical building blocks below the physics: bracketed root finding, special functions and a
//! checked adaptive quadrature. Nothing here knows a material or a solver.

pub mod quad;
pub mod roots;
pub mod special;

/// Iteration cap of every root finder of [`roots`].
pub const ROOT_MAX_ITER: u64 = 200;
