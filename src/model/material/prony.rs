//! Prony series `G(t) = relaxed + sum_k c_k exp(-t / tau_k)`: the form in which every solver
//! receives a relaxation function (docs/theory.md §2).

use crate::error::{check, Result};

/// One term `c exp(-t / tau)` of a Prony series.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PronyTerm {
    /// Coefficient `c` (Pa).
    pub coefficient: f64,
    /// Relaxation time `tau` (s), `> 0`.
    pub tau: f64,
}

/// A Prony series `G(t) = relaxed + sum_k c_k exp(-t / tau_k)` with non-negative coefficients.
#[derive(Debug, Clone, PartialEq)]
pub struct Prony {
    /// Relaxed value `G(inf)` (Pa); 0 for a viscoelastic liquid.
    pub relaxed: f64,
    /// The decaying terms.
    pub terms: Vec<PronyTerm>,
}

impl Prony {
    /// Check that the series is a valid relaxation function: `0 <= relaxed < inf`, every
    /// `0 < tau_k < inf` and `0 <= c_k < inf`, and `G(0) > 0` (errors name the field;
    /// `relaxed = 0` is a viscoelastic liquid).
    pub fn validate(&self) -> Result<()> {
        check(
            "relaxed",
            self.relaxed,
            self.relaxed >= 0.0,
            "0 <= G_eq(inf) < inf",
        )?;
        for p in &self.terms {
            check("tau", p.tau, p.tau > 0.0, "0 < tau < inf")?;
            check(
                "coefficient",
                p.coefficient,
                p.coefficient >= 0.0,
                "0 <= c_k < inf",
            )?;
        }
        check(
            "glassy",
            self.glassy(),
            self.glassy() > 0.0,
            "0 < G_eq(0) < inf",
        )?;
        Ok(())
    }

    /// `G(t)` (Pa) for `t >= 0`.
    pub fn eval(&self, t: f64) -> f64 {
        self.relaxed
            + self
                .terms
                .iter()
                .map(|p| p.coefficient * (-t / p.tau).exp())
                .sum::<f64>()
    }
    /// Glassy value `G(0)` (Pa).
    pub fn glassy(&self) -> f64 {
        self.relaxed + self.terms.iter().map(|p| p.coefficient).sum::<f64>()
    }
    /// Initial slope `G'(0)` (Pa/s), `<= 0`.
    pub fn initial_slope(&self) -> f64 {
        -self
            .terms
            .iter()
            .map(|p| p.coefficient / p.tau)
            .sum::<f64>()
    }
    /// Shortest relaxation time (s), `inf` without terms.
    pub fn min_tau(&self) -> f64 {
        self.terms
            .iter()
            .map(|p| p.tau)
            .fold(f64::INFINITY, f64::min)
    }
    /// True without decaying terms.
    pub fn is_elastic(&self) -> bool {
        self.terms.is_empty()
    }
    /// The same series with moduli divided by `modulus` and times by `time` (non-dimensionalise).
    pub fn scaled(&self, modulus: f64, time: f64) -> Prony {
        Prony {
            relaxed: self.relaxed / modulus,
            terms: self
                .terms
                .iter()
                .map(|p| PronyTerm {
                    coefficient: p.coefficient / modulus,
                    tau: p.tau / time,
                })
                .collect(),
        }
    }
}
