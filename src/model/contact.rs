//! The contact problem every solver consumes, in canonical units: effective mass, the contact
//! geometry and the equivalent relaxation function `G_eq(t)` as a Prony series (with the element
//! network the MDR schemes integrate), built from a validated [`Impact`] by [`Impact::contact`].
//!
//! # Units
//! Canonical units are those of [`crate::model::impact`]: `m = R = v0 = G_inf = 1`. Everything
//! here is canonical, and the types say so: a [`CanonicalProny`] cannot be confused with the SI
//! [`Prony`] of [`Impact::equivalent_relaxation`], and a [`CanonicalOutcome`] leaves canonical
//! units only through [`CanonicalOutcome::to_si`] with the impact's [`Scales`].
//!
//! # What a solver learns
//! A solver sees the mass, the [`Geometry`], `G_eq` (and the MDR its [`Network`]); never bodies,
//! Poisson ratios or files. The reference solver's `G_eq`, derived by a second route
//! ([`crate::model::material::poles`]), is computed on first request
//! ([`Contact::independent_g_eq`]).

use std::sync::OnceLock;

use crate::error::{Error, Result};
use crate::model::impact::{Impact, Outcome, Scales, Target};
use crate::model::material::{
    ElementNetwork, GeneralNetwork, Material, Prony, PronyTerm, StackedNetwork,
};

/// A Prony series in canonical units (moduli in units of `G_inf`, times in units of `L / v0`).
///
/// The model builds one from an impact ([`Impact::contact`]); [`CanonicalProny::assume_canonical`]
/// states the units of a series built by hand (tests, the groups of Eq. 11). It reads as a
/// [`Prony`] (`Deref`); [`CanonicalProny::to_si`] maps it back with the impact's [`Scales`].
#[derive(Debug, Clone, PartialEq)]
pub struct CanonicalProny(Prony);

impl CanonicalProny {
    /// `prony`, declared to be in canonical units by the caller (no scaling happens).
    pub fn assume_canonical(prony: Prony) -> Self {
        Self(prony)
    }
    /// The SI series with the scales of its impact (moduli times `G_inf`, times times `L / v0`).
    pub fn to_si(&self, scales: &Scales) -> Prony {
        Prony {
            relaxed: self.0.relaxed * scales.modulus,
            terms: self
                .0
                .terms
                .iter()
                .map(|t| PronyTerm {
                    coefficient: t.coefficient * scales.modulus,
                    tau: t.tau * scales.time,
                })
                .collect(),
        }
    }
    /// The plain series (still canonical).
    pub fn into_inner(self) -> Prony {
        self.0
    }
}

impl std::ops::Deref for CanonicalProny {
    type Target = Prony;
    fn deref(&self) -> &Prony {
        &self.0
    }
}

pub use crate::model::geometry::Geometry;

/// The element network of the contact's material in canonical units, in the form the MDR
/// integrates it; chosen by shape in this one place ([`Impact::contact`]).
#[derive(Debug, Clone)]
pub enum Network {
    /// The standard solid's network of Eq. (8). The exponential MDR scheme integrates the
    /// standard solid through its closed-form `G_eq` ([`Contact::g_eq`]) and the explicit Euler
    /// through this network.
    StandardSolid(ElementNetwork),
    /// A general material's network built from `G` and `K` ([`GeneralNetwork`]), which both MDR
    /// schemes integrate (the Euler on its dashpot positions).
    General(GeneralNetwork),
    /// Two colliding bodies' networks in series ([`StackedNetwork`], docs/theory.md §8), never
    /// combined into `G_tot`; the exponential scheme integrates it, the Euler refuses it.
    Stacked(StackedNetwork),
}

/// One validated contact problem in canonical units (module docs).
#[derive(Debug, Clone)]
pub struct Contact {
    /// Mass of the indenter (1 in canonical units: the unit of mass).
    pub mass: f64,
    /// The indenter's shape.
    pub geometry: Geometry,
    /// `G_eq(t)`, by the composition of `material::carson` (or the standard solid's closed form).
    pub g_eq: CanonicalProny,
    /// The element network of the material(s) for the MDR.
    pub network: Network,
    independent: Independent,
}

/// The second derivation of `G_eq`, on request: the SI description it starts from and its result.
#[derive(Debug, Clone)]
struct Independent {
    source: (Impact, Scales),
    cell: OnceLock<Result<CanonicalProny>>,
}

impl Contact {
    /// `G_eq(t)` derived independently of [`Contact::g_eq`] (by
    /// [`Impact::independent_relaxation`]), computed once, on the first call.
    pub fn independent_g_eq(&self) -> Result<&CanonicalProny> {
        let (impact, s) = &self.independent.source;
        self.independent
            .cell
            .get_or_init(|| {
                impact
                    .independent_relaxation()
                    .map(|p| CanonicalProny(p.scaled(s.modulus, s.time)))
            })
            .as_ref()
            .map_err(Clone::clone)
    }
}

impl Impact {
    /// The contact problem of this impact in canonical units: unit mass, the canonical shape
    /// ([`Impact::canonical_geometry`]),
    /// [`Impact::canonical_relaxation`] and the element network, chosen by shape here: a
    /// deformable material of the standard solid's shape (half-space, or the one deformable body
    /// beside a rigid one) gets the network of Eq. (8); any other material its network built
    /// from `G` and `K`; two deformable bodies their two networks in series.
    pub fn contact(&self) -> Result<Contact> {
        let s = self.scales();
        let one = |m: &Material| match m.as_standard_solid() {
            Some(ss) => Network::StandardSolid(ElementNetwork::new(&ss).scaled(s.modulus, s.time)),
            None => Network::General(GeneralNetwork::new(m, s.modulus, s.time)),
        };
        let network = match self.target() {
            Target::HalfSpace(m) => one(m),
            Target::TwoBodies(b) => {
                match (b.a().material().material(), b.b().material().material()) {
                    (Some(ma), Some(mb)) => Network::Stacked(StackedNetwork::new(
                        GeneralNetwork::new(ma, s.modulus, s.time),
                        GeneralNetwork::new(mb, s.modulus, s.time),
                    )),
                    (Some(m), None) | (None, Some(m)) => one(m),
                    (None, None) => {
                        return Err(Error::Internal("TwoBodies refuses two rigid bodies"))
                    }
                }
            }
        };
        Ok(Contact {
            mass: 1.0,
            geometry: self.canonical_geometry(),
            g_eq: CanonicalProny(self.canonical_relaxation()),
            network,
            independent: Independent {
                source: (self.clone(), s),
                cell: OnceLock::new(),
            },
        })
    }
}

/// An [`Outcome`] in canonical units (`m = R = v0 = G_inf = 1`), as the solvers return it; its
/// one way to SI is [`CanonicalOutcome::to_si`]. It reads as an [`Outcome`] (`Deref`).
#[derive(Debug, Clone, PartialEq)]
pub struct CanonicalOutcome(Outcome);

impl CanonicalOutcome {
    /// `outcome`, declared to be in canonical units by the solver that made it.
    pub fn new(outcome: Outcome) -> Self {
        Self(outcome)
    }
    /// The outcome in SI with the impact's scales.
    pub fn to_si(self, s: &Scales) -> Outcome {
        let mut o = self.0;
        o.rebound_velocity *= s.velocity;
        o.contact_time *= s.time;
        o.max_indentation *= s.length;
        o.time_of_max_indentation *= s.time;
        o.max_force *= s.force;
        o.max_contact_radius *= s.radius;
        // canonical energy is in units of m v0^2
        o.dissipated_energy *= s.energy;
        if let Some(h) = o.history.as_mut() {
            h.scale(s);
        }
        o
    }
    /// The plain outcome, still in canonical units (for the solvers' own tests and reports).
    pub fn into_canonical(self) -> Outcome {
        self.0
    }
    /// Mutable access for the dispatch (the projection `e <= 1`, the fallback reason).
    pub(crate) fn get_mut(&mut self) -> &mut Outcome {
        &mut self.0
    }
}

impl std::ops::Deref for CanonicalOutcome {
    type Target = Outcome;
    fn deref(&self) -> &Outcome {
        &self.0
    }
}
