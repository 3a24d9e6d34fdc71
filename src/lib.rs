//! # mdr-impact
//!
//! Quasi-static normal impact of a rigid sphere on a linear-viscoelastic, compressible half-space
//! (a standard solid in shear with elastic bulk), after Willert et al., *The influence of
//! compressibility on the restitution coefficient for viscoelastic spheres in low-velocity normal
//! impacts*.
//!
//! Where the paper lives in the code:
//! - [`material`]: Eqs. (1)–(3), the equivalent relaxation function and the element of Eq. (8);
//!   general Prony rheologies in shear and bulk, their exact `G_eq` and the two-body combination
//!   (theory notes §8);
//! - [`impact`]: Eqs. (10)–(11), scales and outcome; [`bodies`]: two colliding bodies (theory
//!   notes §8);
//! - [`fit`]: material parameters from drop tests, and which of them (or of the Eq. (11) groups)
//!   the data determine;
//! - [`mdr`]: the MDR foundation, Eqs. (4)–(9), with two time schemes;
//! - [`theory`]: Hertz, Lee–Radok and Ting/Graham, independent of [`mdr`];
//! - [`solver`]: solver choice and dispatch.
//! - [`dem`]: parameters for DEM codes (LAMMPS, LIGGGHTS): damping laws fitted to `e(v0)` by
//!   integrating their force laws, and the Hertz stiffness.
#![warn(missing_docs)]
// `!(x > 0.0)` is used on purpose: it is true for NaN, which must be rejected too.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod batch;
pub mod bench;
pub mod bodies;
pub mod catalogue;
pub mod curve;
pub mod dem;
pub mod error;
pub mod fast;
pub mod figures;
pub mod fit;
pub mod impact;
pub mod indentation;
pub mod lines;
pub mod material;
pub mod mdr;
pub mod output;
pub mod plot;
pub mod scene;
pub mod scene_toml;
pub mod solver;
pub mod stress;
pub mod sweep;
pub mod theory;
pub mod tolerances;
pub mod validate;

pub use bodies::{Body, BodyMaterial, Side, TwoBodies};
pub use error::{Error, Result};
pub use impact::{Groups, History, Impact, ImpactMaterial, Outcome, Sphere, Work};
pub use material::{Bulk, GeneralMaterial, Material, Prony, PronyTerm};
pub use solver::{solve, Resolution, SolveOptions, SolverKind};
