//! Independent reference theory: Hertz, Lee–Radok (compression) and Ting/Graham (restitution).
//!
//! Shares nothing with [`crate::mdr`] but the material definition.
