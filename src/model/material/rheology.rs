//! General linear viscoelasticity: a Prony series in shear and an incompressible, elastic or
//! Prony-series bulk (docs/theory.md §8).
//!
//! Shear relaxation and bulk relaxation, all moduli in pascal (Pa), all times in seconds (s):
//!
//! ```text
//! G(t) = g_inf + sum_i g_i exp(-t / tau_i)          (0 terms: elastic shear)
//! K(t) = k_inf + sum_j k_j exp(-t / theta_j)        (or K(t) = K_0, or K = inf)
//! ```
//!
//! The standard solid of the paper (Eq. 1, elastic bulk Eq. 2) is the one-term case
//! `g_1 = G_1`, `tau_1 = eta / G_1` ([`Material::as_standard_solid`](super::Material::as_standard_solid)).
//!
//! Constructors validate and normalise: terms are sorted by increasing time, terms with equal
//! times are merged (their moduli added) and terms whose modulus is zero (after merging) are
//! dropped. Negative or non-finite moduli, non-positive or non-finite times are refused with
//! [`Error::PronyTerm`] (field, input index, value); `g_inf < 0`, `k_inf < 0`, `K_0 <= 0` and
//! a Poisson ratio outside `(-1, 0.5]` with [`Error::OutOfRange`].
//!
//! A relaxed modulus `g_inf = 0` (or `k_inf = 0`) is allowed when the series has a term: a
//! viscoelastic liquid (a Maxwell fluid when one term), whose modulus relaxes to zero
//! (docs/theory.md §15). A shear series of no term and `g_inf = 0` (no modulus at all) is
//! refused, and so is a static Poisson ratio below 0.5 with `g_inf = 0`, which would give
//! `K_0 = 0`.

use crate::error::{check, Error, Result};

/// Shear relaxation `G(t) = g_inf + sum_i g_i exp(-t / tau_i)` (docs/theory.md §8), validated.
///
/// `g_inf` is the relaxed (static) shear modulus in Pa, `0 <= g_inf < inf` (0: a viscoelastic
/// liquid, which needs a term); each term is a pair `(g_i, tau_i)`: modulus in Pa
/// (`0 <= g_i < inf`) and relaxation time in s (`0 < tau_i < inf`). Terms are kept sorted by
/// increasing `tau_i`, with distinct times and positive moduli. No terms: an elastic solid with
/// shear modulus `g_inf > 0`.
#[derive(Debug, Clone, PartialEq)]
pub struct ShearProny {
    g_inf: f64,
    terms: Vec<(f64, f64)>,
}

impl ShearProny {
    /// Validated shear series from `g_inf` (Pa) and the pairs `(g_i` (Pa), `tau_i` (s)`)`.
    ///
    /// ```
    /// # use mdr_impact::model::material::rheology::ShearProny;
    /// // unsorted, a duplicate time and a zero modulus: sorted, merged, dropped
    /// let g = ShearProny::new(1.0, &[(2.0, 10.0), (3.0, 0.1), (4.0, 10.0), (0.0, 5.0)]).unwrap();
    /// assert_eq!(g.terms(), &[(3.0, 0.1), (6.0, 10.0)]);
    /// assert_eq!(g.glassy(), 10.0);
    /// ```
    pub fn new(g_inf: f64, terms: &[(f64, f64)]) -> Result<Self> {
        let g_inf = check("g_inf", g_inf, g_inf >= 0.0, "0 <= g_inf < inf (Pa)")?;
        let terms = normalise(terms, ("g_i", "0 <= g_i < inf (Pa)"), ("tau_i", TIME_RANGE))?;
        if g_inf == 0.0 && terms.is_empty() {
            return Err(Error::OutOfRange {
                field: "g_inf",
                value: g_inf,
                allowed: "g_inf > 0 when the shear series has no term of positive modulus \
                          (g_inf = 0 needs a term: a viscoelastic liquid)",
            });
        }
        Ok(Self { g_inf, terms })
    }

    /// Elastic shear, `G(t) = g_inf` (Pa), `0 < g_inf < inf`.
    pub fn elastic(g_inf: f64) -> Result<Self> {
        Self::new(g_inf, &[])
    }

    /// The shear of a standard solid as its constructors store it: no term when elastic, else
    /// `(g_1, tau)`; `g_inf`, `g_1`, `tau` checked by the caller (`tau` may be `inf` there, as
    /// for `Material::new` with a vanishing `G_1`).
    pub(super) fn standard(g_inf: f64, term: Option<(f64, f64)>) -> Self {
        Self {
            g_inf,
            terms: term.into_iter().collect(),
        }
    }

    /// Relaxed (static) shear modulus `G(inf) = g_inf` (Pa); 0 for a viscoelastic liquid.
    pub fn g_inf(&self) -> f64 {
        self.g_inf
    }

    /// True when the relaxed modulus is zero (`g_inf = 0`): a viscoelastic liquid, whose
    /// relaxed limits (Hertz with `g_inf`, the groups of Eq. 11) do not exist.
    pub fn is_liquid(&self) -> bool {
        self.g_inf == 0.0
    }

    /// The terms `(g_i` (Pa), `tau_i` (s)`)`, sorted by increasing `tau_i`, times distinct,
    /// moduli positive.
    pub fn terms(&self) -> &[(f64, f64)] {
        &self.terms
    }

    /// Glassy (instantaneous) shear modulus `G(0) = g_inf + sum_i g_i` (Pa).
    pub fn glassy(&self) -> f64 {
        self.g_inf + self.terms.iter().map(|&(g, _)| g).sum::<f64>()
    }

    /// `G(t)` (Pa) at `t >= 0` (s).
    pub fn relaxation(&self, t: f64) -> f64 {
        series(self.g_inf, &self.terms, t)
    }

    /// True without terms (elastic shear).
    pub fn is_elastic(&self) -> bool {
        self.terms.is_empty()
    }
}

/// Bulk relaxation `K(t) = k_inf + sum_j k_j exp(-t / theta_j)` (docs/theory.md §8), validated.
///
/// `k_inf` is the relaxed bulk modulus in Pa, `0 <= k_inf < inf` (0 only beside a liquid shear,
/// `g_inf = 0`, checked by [`Material::general`](super::Material::general)); each term is a pair
/// `(k_j, theta_j)`: modulus in Pa (`0 <= k_j < inf`) and time in s (`0 < theta_j < inf`).
/// At least one term must be given (an elastic bulk is [`BulkRheology::Elastic`]); terms are
/// normalised like those of [`ShearProny`], and if every modulus is zero the series is refused.
#[derive(Debug, Clone, PartialEq)]
pub struct BulkProny {
    k_inf: f64,
    terms: Vec<(f64, f64)>,
}

impl BulkProny {
    /// Validated bulk series from `k_inf` (Pa) and the pairs `(k_j` (Pa), `theta_j` (s)`)`.
    pub fn new(k_inf: f64, terms: &[(f64, f64)]) -> Result<Self> {
        let k_inf = check("k_inf", k_inf, k_inf >= 0.0, "0 <= k_inf < inf (Pa)")?;
        let terms = normalise(
            terms,
            ("k_j", "0 <= k_j < inf (Pa)"),
            ("theta_j", TIME_RANGE),
        )?;
        if terms.is_empty() {
            return Err(Error::OutOfRange {
                field: "k_j",
                value: 0.0,
                allowed: "a bulk Prony series with at least one term of positive modulus \
                          (an elastic bulk is BulkRheology::Elastic)",
            });
        }
        Ok(Self { k_inf, terms })
    }

    /// Relaxed bulk modulus `K(inf) = k_inf` (Pa).
    pub fn k_inf(&self) -> f64 {
        self.k_inf
    }

    /// The terms `(k_j` (Pa), `theta_j` (s)`)`, sorted by increasing `theta_j`, times distinct,
    /// moduli positive, never empty.
    pub fn terms(&self) -> &[(f64, f64)] {
        &self.terms
    }

    /// Glassy bulk modulus `K(0) = k_inf + sum_j k_j` (Pa).
    pub fn glassy(&self) -> f64 {
        self.k_inf + self.terms.iter().map(|&(k, _)| k).sum::<f64>()
    }

    /// `K(t)` (Pa) at `t >= 0` (s).
    pub fn relaxation(&self, t: f64) -> f64 {
        series(self.k_inf, &self.terms, t)
    }
}

/// The bulk as written: incompressible, an elastic modulus, a static Poisson ratio or a Prony
/// series. [`Material::general`](super::Material::general) resolves it into a [`BulkRheology`].
#[derive(Debug, Clone, PartialEq)]
pub enum BulkInput {
    /// `K = inf` (static Poisson ratio 0.5).
    Incompressible,
    /// Elastic bulk modulus `K_0` in Pa, `0 < K_0 < inf`.
    Elastic(f64),
    /// Static Poisson ratio `nu`, `-1 < nu <= 0.5`, resolved into the elastic bulk
    /// `K_0 = 2 g_inf (1 + nu) / (3 (1 - 2 nu))` of paper Eq. (3) with the relaxed shear modulus
    /// (or an incompressible bulk for `nu = 0.5`).
    Poisson(f64),
    /// Viscoelastic bulk, a [`BulkProny`].
    Prony(BulkProny),
}

/// The resolved bulk of a [`Material`](super::Material) (a Poisson ratio is an input form only,
/// [`BulkInput::Poisson`]).
#[derive(Debug, Clone, PartialEq)]
pub enum BulkRheology {
    /// `K = inf` (static Poisson ratio 0.5): then `G_eq = G`.
    Incompressible,
    /// Elastic bulk modulus `K_0` in Pa, `0 < K_0 < inf`.
    Elastic(f64),
    /// Viscoelastic bulk, a [`BulkProny`].
    Prony(BulkProny),
}

impl BulkInput {
    /// The resolved bulk for a shear series of relaxed modulus `g_inf` (Pa); checks `K_0`
    /// (`0 < K_0 < inf`, field `"k_0"`) and the Poisson ratio (`-1 < nu <= 0.5` with a finite
    /// positive `K_0`, field `"nu"`).
    pub fn resolve(self, g_inf: f64) -> Result<BulkRheology> {
        Ok(match self {
            BulkInput::Incompressible => BulkRheology::Incompressible,
            BulkInput::Elastic(k) => {
                BulkRheology::Elastic(check("k_0", k, k > 0.0, "0 < k_0 < inf (Pa)")?)
            }
            BulkInput::Poisson(nu) => {
                check("nu", nu, nu > -1.0 && nu <= 0.5, "-1 < nu <= 0.5")?;
                if nu == 0.5 {
                    BulkRheology::Incompressible
                } else if g_inf == 0.0 {
                    return Err(Error::OutOfRange {
                        field: "nu",
                        value: nu,
                        allowed: "nu = 0.5 when g_inf = 0 (a static Poisson ratio below 0.5 \
                                  gives K_0 = 2 g_inf (1 + nu) / (3 (1 - 2 nu)) = 0; give k_0, a \
                                  bulk series or incompressible)",
                    });
                } else {
                    let k = 2.0 * g_inf * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu));
                    if !(k.is_finite() && k > 0.0) {
                        return Err(Error::OutOfRange {
                            field: "nu",
                            value: nu,
                            allowed: "-1 < nu <= 0.5 with K_0 = 2 g_inf (1 + nu) / (3 (1 - 2 nu)) \
                                      finite and > 0",
                        });
                    }
                    BulkRheology::Elastic(k)
                }
            }
            BulkInput::Prony(p) => BulkRheology::Prony(p),
        })
    }
}

impl From<BulkRheology> for BulkInput {
    fn from(b: BulkRheology) -> Self {
        match b {
            BulkRheology::Incompressible => BulkInput::Incompressible,
            BulkRheology::Elastic(k) => BulkInput::Elastic(k),
            BulkRheology::Prony(p) => BulkInput::Prony(p),
        }
    }
}

/// `G (3K + G) / (3K + 4G)` (Pa) for elastic moduli `g`, `k` (Pa); `g` when `k = inf`.
pub fn equivalent_elastic(g: f64, k: f64) -> f64 {
    if k.is_infinite() {
        g
    } else {
        g * (3.0 * k + g) / (3.0 * k + 4.0 * g)
    }
}

const TIME_RANGE: &str = "0 < time < inf (s)";

/// Validate, sort by time, merge equal times (moduli added), drop zero moduli.
fn normalise(
    terms: &[(f64, f64)],
    (modulus, modulus_range): (&'static str, &'static str),
    (time, time_range): (&'static str, &'static str),
) -> Result<Vec<(f64, f64)>> {
    for (index, &(m, t)) in terms.iter().enumerate() {
        if !(m.is_finite() && m >= 0.0) {
            return Err(Error::PronyTerm {
                field: modulus,
                index,
                value: m,
                allowed: modulus_range,
            });
        }
        if !(t.is_finite() && t > 0.0) {
            return Err(Error::PronyTerm {
                field: time,
                index,
                value: t,
                allowed: time_range,
            });
        }
    }
    let mut sorted = terms.to_vec();
    sorted.sort_by(|a, b| a.1.total_cmp(&b.1));
    let mut out: Vec<(f64, f64)> = Vec::with_capacity(sorted.len());
    for (m, t) in sorted {
        match out.last_mut() {
            Some(last) if last.1 == t => last.0 += m,
            _ => out.push((m, t)),
        }
    }
    out.retain(|&(m, _)| m > 0.0);
    // The sum of two finite moduli can overflow.
    if let Some(&(m, _)) = out.iter().find(|&&(m, _)| !m.is_finite()) {
        return Err(Error::OutOfRange {
            field: modulus,
            value: m,
            allowed: "a finite sum of the moduli of terms with equal times",
        });
    }
    Ok(out)
}

fn series(relaxed: f64, terms: &[(f64, f64)], t: f64) -> f64 {
    relaxed
        + terms
            .iter()
            .map(|&(m, tau)| m * (-t / tau).exp())
            .sum::<f64>()
}
