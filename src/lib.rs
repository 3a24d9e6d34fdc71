//! # mdr-impact
//!
//! Quasi-static impact of a rigid sphere on a linear-viscoelastic, compressible half-space, and of
//! two viscoelastic bodies, after Willert, Leroy, Satora & Scholtyssek, *The influence of
//! compressibility on the restitution coefficient for viscoelastic spheres in low-velocity normal
//! impacts* \[W\]: the coefficient of restitution (CoR), the contact time, force and indentation
//! histories, for the paper's standard solid and for general Prony rheologies in shear and bulk.
//! SI units at every public entry point; the solvers work in canonical units (`m = R = v0 = 1`,
//! moduli in units of the relaxed equivalent modulus, `docs/theory.md`).
//!
//! ```
//! use mdr_impact::{solve, Impact, Material, SolveOptions, Sphere};
//! // a 5 mm steel-like ball at 1 m/s on the paper's standard solid (nu = 0.45)
//! let material = Material::with_poisson(1.0e6, 1.0e7, 1.0e3, 0.45).unwrap();
//! let sphere = Sphere::new(4.1e-3, 5.0e-3).unwrap();
//! let impact = Impact::new(sphere, 1.0, material).unwrap();
//! let outcome = solve(&impact, &SolveOptions::default()).unwrap();
//! assert!(outcome.cor > 0.0 && outcome.cor < 1.0);
//! ```
//!
//! ## Architecture
//!
//! Layers, each importing only those below it (`docs/architecture.md`):
//!
//! ```text
//!   report   validate · bench · stress · catalogue · figures      (VALIDATION.md, the paper's figures)
//!   apps     curve · sweep · batch · dem · fit                    (what users run)
//!   io       scene · scene_toml · prony_table · lines · output · plot
//!   solvers  dispatch (solve) · theory (reference) · mdr · fast · indentation
//!   model    material · bodies · impact · hertz · tolerances
//!   math     roots · special · quad                 error · rng
//! ```
//!
//! Where the paper lives in the code:
//! - [`model::material`]: Eqs. (1)–(3), the equivalent relaxation function and the element of
//!   Eq. (8); general Prony rheologies in shear and bulk, their exact `G_eq` and the two-body
//!   combination (`docs/theory.md` §2, §8);
//! - [`model::impact`]: Eqs. (10)–(11), scales and outcome; [`model::bodies`]: two colliding
//!   bodies (`docs/theory.md` §7, §8);
//! - [`solvers::mdr`]: the MDR foundation, Eqs. (4)–(9), with two time schemes (§3, §5);
//! - [`solvers::theory`]: Lee–Radok and Ting/Graham by quadrature, independent of
//!   [`solvers::mdr`] (§4); [`model::hertz`]: the elastic closed forms (§6);
//! - [`solvers::fast`]: the reduced collocation solver (§9); [`solvers::solve`]: solver choice and
//!   dispatch, with each solver's error estimate (§10);
//! - [`apps::fit`]: material parameters from drop tests, and which of them (or of the Eq. (11)
//!   groups) the data determine; [`apps::dem`]: parameters for DEM codes (LAMMPS, LIGGGHTS).
//!
//! # References
//!
//! - \[W\] E. Willert, J.-E. Leroy, M. Satora, Y. Scholtyssek: The influence of compressibility on
//!   the restitution coefficient for viscoelastic spheres in low-velocity normal impacts,
//!   Technische Universität Berlin.
//! - E. H. Lee, J. R. M. Radok: The contact problem for viscoelastic bodies, J. Appl. Mech. 27,
//!   438–444 (1960).
//! - T. C. T. Ting: The contact stresses between a rigid indenter and a viscoelastic half-space,
//!   J. Appl. Mech. 33, 845–854 (1966).
//! - G. A. C. Graham: The contact problem in the linear theory of viscoelasticity, Int. J. Eng.
//!   Sci. 3, 27–46 (1965).
//! - S. C. Hunter: The Hertz problem for a rigid spherical indenter and a viscoelastic
//!   half-space, J. Mech. Phys. Solids 8, 219–234 (1960).
//! - V. L. Popov, M. Heß: Method of Dimensionality Reduction in Contact Mechanics and Friction,
//!   Springer (2015), DOI 10.1007/978-3-642-53876-6.
//!
//! Full list with the derivations: `docs/theory.md`.
#![warn(missing_docs)]
#![forbid(unsafe_code)]
// `!(x > 0.0)` is used on purpose: it is true for NaN, which must be rejected too.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod apps;
pub mod error;
pub mod io;
pub mod math;
pub mod model;
pub mod report;
pub mod rng;
pub mod solvers;

pub use error::{Error, Result};
pub use model::bodies::{Body, BodyMaterial, Side, TwoBodies};
pub use model::impact::{Groups, History, Impact, Outcome, Sphere, Target, Work};
pub use model::material::{Bulk, BulkInput, Material, Prony, PronyTerm, StandardSolid};
pub use solvers::{solve, Resolution, SolveOptions, SolverKind};
