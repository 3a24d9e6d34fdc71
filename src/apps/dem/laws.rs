//! The DEM force laws (Hertz spring with constant-CoR or viscoelastic damping) and their
//! integration by the Dormand–Prince 5(4) pair.

use super::*;

/// How the DEM code sees the contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Geometry {
    /// Two particles (types 1 and 2): both bodies of finite radius and mass.
    Pair,
    /// A particle (type 1) on a flat wall (type 2): a one-sphere scene, or a body of infinite
    /// radius or mass.
    Wall,
}

/// The Hertz contact a DEM code needs (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzContact {
    /// Effective mass `m` (kg).
    pub mass: f64,
    /// Effective radius `R` (m).
    pub radius: f64,
    /// Effective plane-strain modulus `E*` (Pa).
    pub effective_modulus: f64,
}

impl HertzContact {
    /// A contact of effective mass (kg), radius (m) and modulus `E*` (Pa), all finite and
    /// positive.
    pub fn new(mass: f64, radius: f64, effective_modulus: f64) -> Result<Self> {
        crate::error::check("dem mass", mass, mass > 0.0, "0 < m < inf (kg)")?;
        crate::error::check("dem radius", radius, radius > 0.0, "0 < R < inf (m)")?;
        crate::error::check(
            "dem effective modulus",
            effective_modulus,
            effective_modulus > 0.0,
            "0 < E* < inf (Pa)",
        )?;
        Ok(Self {
            mass,
            radius,
            effective_modulus,
        })
    }

    /// Hertz stiffness `k = (4/3) E* sqrt(R)` (N/m^(3/2)): `F = k delta^(3/2)`.
    pub fn stiffness(&self) -> f64 {
        4.0 / 3.0 * self.effective_modulus * self.radius.sqrt()
    }

    /// Young's modulus (Pa) to give both types of the DEM code, with Poisson ratio
    /// [`DEM_POISSON`], so that its mixing returns `E*`: `E = 2 (1 - nu^2) E*`.
    pub fn dem_young(&self) -> f64 {
        2.0 * (1.0 - DEM_POISSON * DEM_POISSON) * self.effective_modulus
    }

    /// Young's modulus (Pa) for a LAMMPS wall of a version that mixes the wall's modulus as
    /// `E / (2 (1 - nu))` ([`LammpsVersion::legacy_wall_modulus`]): `E = 2 (1 - nu) E*`.
    pub fn lammps_legacy_wall_young(&self) -> f64 {
        2.0 * (1.0 - DEM_POISSON) * self.effective_modulus
    }

    /// `(k / m)^(2/5)` (s^(-2/5) m^(-1/5)), the scale of the viscoelastic law's coefficient.
    fn rate_scale(&self) -> f64 {
        (self.stiffness() / self.mass).powf(0.4)
    }

    /// The dimensionless coefficient `c = (3/2) A v0^(1/5) (k/m)^(2/5)` of the viscoelastic law
    /// with dissipative constant `a` (s) at `v0` (m/s).
    pub fn viscoelastic_c(&self, a: f64, v0: f64) -> f64 {
        1.5 * a * v0.powf(0.2) * self.rate_scale()
    }

    /// The dissipative constant `A` (s) of the dimensionless coefficient `c` at `v0` (m/s).
    pub fn viscoelastic_a(&self, c: f64, v0: f64) -> f64 {
        c / (1.5 * v0.powf(0.2) * self.rate_scale())
    }

    /// LAMMPS `damping viscoelastic` prefactor `eta_n0 = 2 E* A / m` (1/(m s)) of `A` (s).
    pub fn lammps_eta_n0(&self, a: f64) -> f64 {
        2.0 * self.effective_modulus * a / self.mass
    }

    /// The impact of the DEM law `law` at `v0` (m/s): CoR and contact time (s).
    pub fn impact(&self, law: DemLaw, v0: f64) -> Result<DemImpact> {
        crate::error::check("dem v0", v0, v0 > 0.0, "0 < v0 < inf (m/s)")?;
        let (p, c) = match law {
            DemLaw::Elastic => (0.5, 0.0),
            DemLaw::CoeffRestitution { cor_input } => (0.25, cor_gamma(cor_input)?),
            DemLaw::Viscoelastic { a } => {
                crate::error::check("dem A", a, a >= 0.0, "0 <= A < inf (s)")?;
                (0.5, self.viscoelastic_c(a, v0))
            }
        };
        let d = integrate(p, c)?;
        // time unit: Hertz length / v0, the length (m v0^2 / k)^(2/5)
        let length = (self.mass * v0 * v0 / self.stiffness()).powf(0.4);
        Ok(DemImpact {
            cor: d.cor,
            contact_time: d.contact_time * length / v0,
            steps: d.steps,
        })
    }
}

/// A DEM normal force law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DemLaw {
    /// Hertz without damping (`e = 1`).
    Elastic,
    /// LAMMPS `damping coeff_restitution` / LIGGGHTS `model hertz` with the input CoR
    /// `cor_input` (`0 < e_in <= 1`).
    CoeffRestitution {
        /// The CoR written into the input file (not exactly the CoR it produces).
        cor_input: f64,
    },
    /// Brilliantov et al.'s viscoelastic law with dissipative constant `a` (s).
    Viscoelastic {
        /// Dissipative constant `A` (s).
        a: f64,
    },
}

/// `gamma = sqrt(5) (-ln e) / sqrt(pi^2 + ln^2 e)` of the constant-CoR law for the input CoR `e`.
pub fn cor_gamma(cor_input: f64) -> Result<f64> {
    let e = crate::error::check(
        "dem input CoR",
        cor_input,
        cor_input > 0.0 && cor_input <= 1.0,
        "0 < e <= 1",
    )?;
    let l = e.ln();
    Ok(5f64.sqrt() * (-l) / (std::f64::consts::PI.powi(2) + l * l).sqrt())
}

/// Result of one DEM impact (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DemImpact {
    /// Coefficient of restitution.
    pub cor: f64,
    /// Contact time (s): until the clipped force vanishes.
    pub contact_time: f64,
    /// Accepted integration steps.
    pub steps: u64,
}

/// Result of [`integrate`] (dimensionless).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dimensionless {
    /// CoR: minus the rate `x'` when the force vanishes.
    pub cor: f64,
    /// Contact time in units of the Hertz length over `v0`.
    pub contact_time: f64,
    /// Accepted steps.
    pub steps: u64,
}

/// `sign(x) |x|^p` (the overlap may dip below zero inside the last trial step).
fn spow(x: f64, p: f64) -> f64 {
    x.signum() * x.abs().powf(p)
}

/// Right-hand side of `x'' = -(x^(3/2) + c x^p x')`, the force clipped at zero.
fn rhs(y: [f64; 2], p: f64, c: f64) -> [f64; 2] {
    let f = spow(y[0], 1.5) + c * spow(y[0], p) * y[1];
    [y[1], -f.max(0.0)]
}

/// The end-of-contact function `x^(3/2 - p) + c x'` (the force over `x^p`): positive in contact.
fn contact(y: [f64; 2], p: f64, c: f64) -> f64 {
    spow(y[0], 1.5 - p) + c * y[1]
}

/// One Dormand–Prince 5(4) step: the new state and its error estimate.
fn dp_step(y: [f64; 2], h: f64, p: f64, c: f64) -> ([f64; 2], [f64; 2]) {
    const A: [[f64; 6]; 6] = [
        [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
        [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
        [
            19372.0 / 6561.0,
            -25360.0 / 2187.0,
            64448.0 / 6561.0,
            -212.0 / 729.0,
            0.0,
            0.0,
        ],
        [
            9017.0 / 3168.0,
            -355.0 / 33.0,
            46732.0 / 5247.0,
            49.0 / 176.0,
            -5103.0 / 18656.0,
            0.0,
        ],
        [
            35.0 / 384.0,
            0.0,
            500.0 / 1113.0,
            125.0 / 192.0,
            -2187.0 / 6784.0,
            11.0 / 84.0,
        ],
    ];
    // fifth-order weights minus fourth-order ones
    const E: [f64; 7] = [
        71.0 / 57600.0,
        0.0,
        -71.0 / 16695.0,
        71.0 / 1920.0,
        -17253.0 / 339200.0,
        22.0 / 525.0,
        -1.0 / 40.0,
    ];
    let mut k = [[0.0; 2]; 7];
    k[0] = rhs(y, p, c);
    for s in 0..6 {
        let mut z = y;
        for (j, kj) in k.iter().enumerate().take(s + 1) {
            z[0] += h * A[s][j] * kj[0];
            z[1] += h * A[s][j] * kj[1];
        }
        k[s + 1] = rhs(z, p, c);
    }
    // the last stage is evaluated at the new state (FSAL), row 6 of A are the weights
    let mut y1 = y;
    for (j, kj) in k.iter().enumerate().take(6) {
        y1[0] += h * A[5][j] * kj[0];
        y1[1] += h * A[5][j] * kj[1];
    }
    let mut err = [0.0; 2];
    for (j, kj) in k.iter().enumerate() {
        err[0] += h * E[j] * kj[0];
        err[1] += h * E[j] * kj[1];
    }
    (y1, err)
}

/// Integrate `x'' = -max(0, x^(3/2) + c x^p x')`, `x(0) = 0`, `x'(0) = 1` until the force
/// vanishes while the overlap recovers (`x^(3/2-p) + c x' = 0`; for `c = 0` that is `x = 0`).
/// `p` in `(0, 3/2)`, `c >= 0` finite. Adaptive Dormand–Prince 5(4) with [`ODE_RTOL`] and
/// [`ODE_ATOL`], at most [`ODE_MAX_STEPS`] steps; the end is located by bisection of the last
/// step's length.
///
/// ```
/// # use mdr_impact::apps::dem::integrate;
/// // elastic Hertz: e = 1, contact time 2 I (5/4)^(2/5) = 3.2145... (docs/theory.md §6)
/// let d = integrate(0.5, 0.0).unwrap();
/// assert!((d.cor - 1.0).abs() < 1e-9);
/// assert!((d.contact_time - 2.9432751843247047 * 1.25f64.powf(0.4)).abs() < 1e-8);
/// ```
pub fn integrate(p: f64, c: f64) -> Result<Dimensionless> {
    crate::error::check("dem exponent p", p, p > 0.0 && p < 1.5, "0 < p < 3/2")?;
    crate::error::check("dem damping c", c, c >= 0.0, "0 <= c < inf")?;
    let mut y = [0.0, 1.0];
    let mut t = 0.0;
    let mut h = 1e-3;
    let mut steps = 0u64;
    let mut tries = 0u64;
    loop {
        tries += 1;
        if tries > 4 * ODE_MAX_STEPS {
            return Err(Error::NoConvergence {
                what: "dem contact integration",
                iterations: ODE_MAX_STEPS,
            });
        }
        let (y1, err) = dp_step(y, h, p, c);
        let scale = |i: usize| ODE_ATOL + ODE_RTOL * y[i].abs().max(y1[i].abs());
        let norm = ((err[0] / scale(0)).powi(2) + (err[1] / scale(1)).powi(2)).sqrt()
            / std::f64::consts::SQRT_2;
        if !norm.is_finite() {
            h *= 0.1;
            continue;
        }
        if norm > 1.0 {
            h *= (0.9 * norm.powf(-0.2)).max(0.1);
            continue;
        }
        steps += 1;
        if steps > ODE_MAX_STEPS {
            return Err(Error::NoConvergence {
                what: "dem contact integration",
                iterations: ODE_MAX_STEPS,
            });
        }
        // t > 0 guard: at the start x = 0 and the function is 0 + c
        if contact(y1, p, c) <= 0.0 && y1[1] < 0.0 {
            let (mut lo, mut hi) = (0.0, h);
            for _ in 0..crate::model::tolerances::ROOT_MAX_ITER {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if contact(dp_step(y, mid, p, c).0, p, c) > 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let end = dp_step(y, hi, p, c).0;
            let cor = -end[1];
            if !(cor.is_finite() && cor >= 0.0) {
                return Err(Error::NonFinite {
                    what: "dem CoR",
                    value: cor,
                });
            }
            return Ok(Dimensionless {
                cor,
                contact_time: t + hi,
                steps,
            });
        }
        y = y1;
        t += h;
        h *= (0.9 * norm.max(1e-10).powf(-0.2)).min(5.0);
    }
}
