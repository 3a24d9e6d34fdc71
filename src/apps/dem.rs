//! Parameters for DEM codes (`mdr-impact dem`): the damping laws of LAMMPS and LIGGGHTS that best
//! reproduce a scene's `e(v0)` over a velocity range, with the Hertz stiffness they need.
//!
//! # The DEM force laws
//! A DEM code models the normal contact of two spheres (or a sphere and a wall) by a Hertz
//! spring and a damper acting on the overlap `delta` (m) and its rate `delta'` (m/s):
//!
//! ```text
//! m delta'' = -F,   F = max(0, k delta^(3/2) + F_d),   k = (4/3) E* sqrt(R)   (N/m^(3/2))
//! ```
//!
//! with the effective mass `m` (kg), radius `R` (m) and plane-strain modulus `E*` (Pa). Two
//! damping laws are fitted:
//!
//! - **constant CoR** (LAMMPS `damping coeff_restitution`, LIGGGHTS `model hertz` with
//!   `coefficientRestitution`): `F_d = gamma sqrt(m k) delta^(1/4) delta'` with
//!   `gamma = sqrt(5) (-ln e_in) / sqrt(pi^2 + ln^2 e_in)` for the input CoR `e_in`. LAMMPS
//!   computes `eta_n = sqrt(3/2) 2 sqrt(5/6) (-ln e) / sqrt(pi^2 + ln^2 e) sqrt(m F_ne / delta)`
//!   with `F_ne / delta = k sqrt(delta)`
//!   (<https://docs.lammps.org/pair_granular.html>, section on `damping coeff_restitution`);
//!   LIGGGHTS computes `gamma_n = -2 sqrt(5/6) beta sqrt(S_n m)`, `S_n = 2 Y* sqrt(R delta)`,
//!   `beta = ln e / sqrt(ln^2 e + pi^2)`
//!   (<https://www.cfdem.com/media/DEM/docu/gran_model_hertz.html>): the same force. Its CoR
//!   does not depend on `v0` (the force law has no scale), but it is not exactly `e_in` either,
//!   so the input value is found by root finding on our own integration of the law.
//! - **viscoelastic** (Brilliantov, Spahn, Hertzsch, Pöschel, Phys. Rev. E 53, 5382 (1996);
//!   Kuwabara–Kono): `F = k (delta^(3/2) + (3/2) A sqrt(delta) delta')` with the dissipative
//!   constant `A` (s). In LAMMPS this is `damping viscoelastic`, `eta_n = eta_n0 a m` with the
//!   contact radius `a = sqrt(R delta)` (<https://docs.lammps.org/pair_granular.html>), so
//!   `eta_n0 = 2 E* A / m` (1/(m s)). Its CoR falls with `v0^(1/5)`
//!   (`1 - e ~ 1.15344 (3/2) A (k/m)^(2/5) v0^(1/5)` for small `A`, Schwager and Pöschel,
//!   Phys. Rev. E 57, 650 (1998)). LIGGGHTS-PUBLIC's `model hertz` has no such law.
//!
//! **The tensile force.** Near the end of a damped contact the damping term outgrows the
//! elastic one (`delta'` stays finite while `delta -> 0`) and the sum turns attractive. We
//! clip the force at zero, as LAMMPS does with the `limit_damping` keyword ("zero out the normal
//! component of the force if there is an effective attractive force", same page) and LIGGGHTS
//! with `limitForce on`; the emitted input lines carry that keyword. Physically the surfaces
//! separate when the force vanishes, before the overlap returns to zero (Schwager and Pöschel,
//! Phys. Rev. E 78, 051304 (2008)); from then on the spheres fly apart at constant velocity, so
//! the CoR is the rebound velocity at the instant the force reaches zero.
//!
//! **The integration.** In units of the Hertz length `(m v0^2 / k)^(2/5)` and time
//! `length / v0` every law becomes `x'' = -(x^(3/2) + c x^p x')`, `x(0) = 0`, `x'(0) = 1`, with
//! `p = 1/4`, `c = gamma` (constant CoR) and `p = 1/2`, `c = (3/2) A v0^(1/5) (k/m)^(2/5)`
//! (viscoelastic). [`integrate`] solves it by the adaptive Dormand–Prince 5(4) pair and locates
//! the end of contact (`x^(3/2 - p) + c x' = 0`, the zero of `F / x^p`) by bisection on the last
//! step.
//!
//! # The Hertz stiffness
//! `E*` comes from the equivalent incompressible relaxation function (docs/theory.md §2, §8):
//! `E* = 4 G_eq(inf)` with `--modulus relaxed` (the default) and `E* = 4 G_eq(0)` with
//! `--modulus glassy`, `G_eq` the combined `G_tot` for two bodies. LAMMPS `hertz/material` and
//! LIGGGHTS take a Young's modulus and a Poisson ratio per type and mix them as
//! `E* = (2 (1 - nu^2) / E)^-1` for equal types (and walls); we give both types
//! `E = 2 (1 - nu^2) E* = 1.5 E*` with `nu = 0.5`, the equivalent incompressible solid, so that
//! the codes' mixing returns our `E*` exactly. `nu` enters their tangential stiffness only,
//! which a normal impact does not determine.
//!
//! # LAMMPS versions
//! LAMMPS before [`LAMMPS_WALL_MIX_SINCE`] mixes a `fix wall/gran` wall as `E / (2 (1 - nu))`:
//! the wall line then gets `E = 2 (1 - nu) E* = E*`. LAMMPS before
//! [`LAMMPS_COEFF_RESTITUTION_SINCE`] has no `damping coeff_restitution`; its `damping tsuji`
//! multiplies the same `sqrt(m F_ne / delta) delta'` by Marshall's polynomial of its input, so
//! the constant-CoR law is written as `damping tsuji` with [`tsuji_input`]. Both were checked by
//! running LAMMPS [`LAMMPS_PROVEN`] and LIGGGHTS 3.8.0 (`validation/dem_clients/verify.py`).

use std::path::{Path, PathBuf};

use rayon::prelude::*;

use crate::apps::curve::{self, CurveRow, VelocityRange};
use crate::error::{Error, Result};
use crate::io::output::{fmt, write_atomic};
use crate::io::plot::{cor_chart_svg, velocity_span, CorLine};
use crate::model::impact::Impact;
use crate::solvers::SolveOptions;
use plotters::style::RGBColor;

/// Velocities of `--v0 MIN:MAX` when `N` is left out.
pub const DEFAULT_VELOCITIES: usize = 50;

/// A law whose worst relative CoR error over the range exceeds this is reported with a warning.
pub const WARN_REL_ERROR: f64 = 0.05;

/// Poisson ratio given to both types in the emitted input lines (the equivalent incompressible
/// solid, see the module docs).
pub const DEM_POISSON: f64 = 0.5;

/// LIGGGHTS refuses Young's moduli at or below this in SI units (Pa; restriction on
/// <https://www.cfdem.com/media/DEM/docu/gran_model_hertz.html>).
pub const LIGGGHTS_MIN_YOUNG: f64 = 5e6;

/// Relative tolerance of the DEM ODE integration (per step, mixed with [`ODE_ATOL`]).
pub const ODE_RTOL: f64 = 1e-11;
/// Absolute tolerance of the DEM ODE integration (dimensionless overlap and rate).
pub const ODE_ATOL: f64 = 1e-13;
/// Step cap of one DEM ODE integration.
pub const ODE_MAX_STEPS: u64 = 200_000;

/// Smallest input CoR of the constant-CoR law the fit writes. The law's CoR has a floor as the
/// input goes to zero (`gamma -> sqrt(5)`), so a curve below it is answered with this input and
/// a warning.
pub const MIN_COR_INPUT: f64 = 1e-6;

/// Velocities the viscoelastic fit uses at most (an even subsample of a longer curve; its
/// errors are still evaluated at every velocity).
pub const FIT_MAX_VELOCITIES: usize = 200;

/// Largest damping coefficient `c` of the viscoelastic law searched by the fit (dimensionless;
/// `e` is about 0.1 there).
const MAX_VISCO_C: f64 = 100.0;

/// The output format of `mdr-impact dem`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// LAMMPS `pair_style granular` / `fix wall/gran granular` lines for a LAMMPS version.
    Lammps(LammpsVersion),
    /// LIGGGHTS `pair_style gran model hertz` lines with `fix property/global`.
    Liggghts,
    /// One JSON object.
    Json,
}

impl std::str::FromStr for Format {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "lammps" => Ok(Self::Lammps(LammpsVersion::CURRENT)),
            "liggghts" => Ok(Self::Liggghts),
            "json" => Ok(Self::Json),
            other => Err(Error::Unsupported(format!(
                "--format = '{}': expected lammps, liggghts or json",
                crate::error::escape_text(other)
            ))),
        }
    }
}

impl Format {
    /// The format with `--lammps-version YYYYMMDD` applied (`None`: current LAMMPS). A version
    /// with a format other than `lammps` is an error.
    pub fn with_lammps_version(self, version: Option<&str>) -> Result<Self> {
        match (self, version) {
            (_, None) => Ok(self),
            (Self::Lammps(_), Some(v)) => Ok(Self::Lammps(v.parse()?)),
            (_, Some(_)) => Err(Error::Unsupported(
                "--lammps-version applies to --format lammps only".into(),
            )),
        }
    }
}

/// First LAMMPS version (YYYYMMDD) whose `fix wall/gran granular hertz/material` mixes the
/// wall's Young's modulus as `E / (2 (1 - nu^2))` (`GranSubMod::mix_stiffnessE_wall` of the
/// granular-model classes, feature release 28 Mar 2023). Before it `fix_wall_gran.cpp` took
/// `E / (2 (1 - nu))`: with our `E = 1.5 E*` and `nu = 0.5` a wall 1.5 times too stiff.
pub const LAMMPS_WALL_MIX_SINCE: u32 = 20230328;

/// First LAMMPS version (YYYYMMDD) with `damping coeff_restitution` (pull request 4068,
/// feature release 17 Apr 2024). Before it the constant-CoR law is written as `damping tsuji`.
pub const LAMMPS_COEFF_RESTITUTION_SINCE: u32 = 20240417;

/// Oldest LAMMPS version (YYYYMMDD) the lines are written for: the stable release of
/// 29 Sep 2021 (`limit_damping` and the granular walls' damping fixes are in it).
pub const LAMMPS_OLDEST: u32 = 20210929;

/// The LAMMPS version the verification (`validation/dem_clients/verify.py`) ran: Debian's
/// package `lammps 20220106`, whose `lmp -h` prints "29 Sep 2021 - Update 2".
pub const LAMMPS_PROVEN: u32 = 20220106;

/// The LIGGGHTS version the verification ran (Debian's package `liggghts 3.8.0`).
pub const LIGGGHTS_PROVEN: &str = "LIGGGHTS-PUBLIC 3.8.0";

/// Coefficients of Marshall's (2009, Eq. 53) polynomial `alpha(e)` by which LAMMPS's
/// `damping tsuji` turns its input `e` into the prefactor of `sqrt(m F_ne / delta) delta'`
/// (lowest power first; no further factor before [`LAMMPS_COEFF_RESTITUTION_SINCE`], checked by
/// running LAMMPS 20220106).
pub const TSUJI_POLY: [f64; 7] = [1.2728, -4.2783, 11.087, -22.348, 27.467, -18.022, 4.8218];

/// `alpha(e)` of LAMMPS's `damping tsuji` ([`TSUJI_POLY`]); it falls monotonically from 1.2728
/// at `e = 0` to 3e-4 at `e = 1`.
pub fn tsuji_alpha(e: f64) -> f64 {
    TSUJI_POLY.iter().rev().fold(0.0, |acc, c| acc * e + c)
}

/// The `damping tsuji` input whose prefactor equals the constant-CoR law's `gamma`
/// ([`cor_gamma`]), by bisection; `None` when `gamma` lies outside `alpha`'s range
/// `[alpha(1), alpha(0)]`.
pub fn tsuji_input(gamma: f64) -> Option<f64> {
    if !(gamma >= tsuji_alpha(1.0) && gamma <= tsuji_alpha(0.0)) {
        return None;
    }
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for _ in 0..crate::model::tolerances::ROOT_MAX_ITER {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if tsuji_alpha(mid) > gamma {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

/// The LAMMPS version the input lines are written for: the date `lmp -h` prints, as YYYYMMDD
/// (`--lammps-version`), or the current LAMMPS.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LammpsVersion(Option<u32>);

impl LammpsVersion {
    /// Current LAMMPS (at least [`LAMMPS_COEFF_RESTITUTION_SINCE`]).
    pub const CURRENT: Self = Self(None);

    /// The date YYYYMMDD, `None` for the current version.
    pub fn date(self) -> Option<u32> {
        self.0
    }

    fn at_least(self, date: u32) -> bool {
        self.0.map_or(true, |d| d >= date)
    }

    /// True when `fix wall/gran` mixes the wall's modulus as `E / (2 (1 - nu))` (before
    /// [`LAMMPS_WALL_MIX_SINCE`]).
    pub fn legacy_wall_modulus(self) -> bool {
        !self.at_least(LAMMPS_WALL_MIX_SINCE)
    }

    /// True when `damping coeff_restitution` exists ([`LAMMPS_COEFF_RESTITUTION_SINCE`]).
    pub fn has_coeff_restitution(self) -> bool {
        self.at_least(LAMMPS_COEFF_RESTITUTION_SINCE)
    }

    /// True for the versions the verification ran (the same code as [`LAMMPS_PROVEN`]: before
    /// [`LAMMPS_WALL_MIX_SINCE`]).
    pub fn proven(self) -> bool {
        self.legacy_wall_modulus()
    }

    /// `LAMMPS 20220106` or `current LAMMPS (20240417 or later)`.
    pub fn label(self) -> String {
        match self.0 {
            Some(d) => format!("LAMMPS {d}"),
            None => format!("current LAMMPS ({LAMMPS_COEFF_RESTITUTION_SINCE} or later)"),
        }
    }
}

impl std::str::FromStr for LammpsVersion {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        let bad = |why: &str| {
            Error::Unsupported(format!(
                "--lammps-version = '{}': {why}",
                crate::error::escape_text(s)
            ))
        };
        if s.len() != 8 || !s.bytes().all(|b| b.is_ascii_digit()) {
            return Err(bad(
                "expected the date YYYYMMDD of `lmp -h` (e.g. 20220106 for 7 Jan 2022)",
            ));
        }
        let d: u32 = s.parse().map_err(|_| bad("not a date"))?;
        let (month, day) = (d / 100 % 100, d % 100);
        if !(1..=12).contains(&month) || !(1..=31).contains(&day) {
            return Err(bad("not a date YYYYMMDD"));
        }
        if d < LAMMPS_OLDEST {
            return Err(bad(&format!(
                "older than {LAMMPS_OLDEST}, the oldest LAMMPS these lines are written for"
            )));
        }
        Ok(Self(Some(d)))
    }
}

/// Which limit of the viscoelastic material the Hertz stiffness takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModulusChoice {
    /// `E* = 4 G_eq(inf)`: long contacts, low velocities.
    Relaxed,
    /// `E* = 4 G_eq(0)`: short contacts, high velocities.
    Glassy,
}

impl ModulusChoice {
    /// The name used on the command line and in the output.
    pub fn name(self) -> &'static str {
        match self {
            Self::Relaxed => "relaxed",
            Self::Glassy => "glassy",
        }
    }
}

impl std::str::FromStr for ModulusChoice {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "relaxed" => Ok(Self::Relaxed),
            "glassy" => Ok(Self::Glassy),
            other => Err(Error::Unsupported(format!(
                "--modulus = '{}': expected relaxed or glassy",
                crate::error::escape_text(other)
            ))),
        }
    }
}

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

/// Errors of a law's `e(v0)` against ours, relative to ours.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// The law's CoR at each velocity of the curve (our integration of its force law).
    pub cor: Vec<f64>,
    /// Largest `|e_law - e| / e` over the range.
    pub worst_rel_error: f64,
    /// Root mean square of `(e_law - e) / e` over the range.
    pub rms_rel_error: f64,
}

impl Fit {
    fn new(cor: Vec<f64>, target: &[f64]) -> Self {
        let rel: Vec<f64> = cor
            .iter()
            .zip(target)
            .map(|(a, b)| ((a - b) / b).abs())
            .collect();
        let worst_rel_error = rel.iter().copied().fold(0.0, f64::max);
        let rms_rel_error = (rel.iter().map(|r| r * r).sum::<f64>() / rel.len() as f64).sqrt();
        Self {
            cor,
            worst_rel_error,
            rms_rel_error,
        }
    }
}

/// Contact times of a law against ours (the time until the contact force vanishes).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactTimes {
    /// The law's contact time (s) at each velocity of the curve, with the Hertz stiffness of
    /// the report.
    pub law: Vec<f64>,
    /// Largest `|t_law - t| / t` over the range.
    pub worst_rel_error: f64,
}

/// The fitted constant-CoR law.
#[derive(Debug, Clone, PartialEq)]
pub struct ConstantLaw {
    /// The CoR to write into the DEM input (`coeff_restitution`, `coefficientRestitution`).
    pub cor_input: f64,
    /// The CoR that input produces (our integration, the same at every velocity).
    pub cor: f64,
    /// True when the least-squares constant lies below what the law can produce: the input is
    /// then [`MIN_COR_INPUT`].
    pub at_floor: bool,
    /// Errors against our curve.
    pub fit: Fit,
}

/// The fitted viscoelastic (Brilliantov) law.
#[derive(Debug, Clone, PartialEq)]
pub struct ViscoelasticLaw {
    /// Dissipative constant `A` (s).
    pub a: f64,
    /// LAMMPS `damping viscoelastic` prefactor `eta_n0 = 2 E* A / m` (1/(m s)).
    pub eta_n0: f64,
    /// Errors against our curve.
    pub fit: Fit,
}

/// The CoR of the constant-CoR law with input `e_in`.
fn constant_cor(cor_input: f64) -> Result<f64> {
    Ok(integrate(0.25, cor_gamma(cor_input)?)?.cor)
}

/// The constant-CoR law closest to `target` (least squares of the relative error: the constant
/// `sum(1/e) / sum(1/e^2)`), its input CoR found by bisection so that the law produces it.
pub fn fit_constant(target: &[f64]) -> Result<ConstantLaw> {
    let want = target.iter().map(|e| 1.0 / e).sum::<f64>()
        / target.iter().map(|e| 1.0 / (e * e)).sum::<f64>();
    // e(e_in) rises from its floor at e_in -> 0 (gamma -> sqrt 5) to 1 at e_in = 1
    let (mut lo, mut hi) = (MIN_COR_INPUT, 1.0);
    let at_floor = want < 1.0 && constant_cor(lo)? >= want;
    let cor_input = if want >= 1.0 {
        1.0
    } else if at_floor {
        lo
    } else {
        for _ in 0..crate::model::tolerances::ROOT_MAX_ITER {
            let mid = if hi / lo > 4.0 {
                (lo * hi).sqrt()
            } else {
                0.5 * (lo + hi)
            };
            if mid <= lo || mid >= hi || (hi - lo) < 1e-14 * hi {
                break;
            }
            if constant_cor(mid)? < want {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    };
    let cor = constant_cor(cor_input)?;
    Ok(ConstantLaw {
        cor_input,
        cor,
        at_floor,
        fit: Fit::new(vec![cor; target.len()], target),
    })
}

/// The viscoelastic law's CoR at the velocities `v0` (m/s) for the coefficient scale `s`
/// (`c = s v0^(1/5)`); in parallel, results in velocity order.
fn visco_cors(s: f64, v0: &[f64]) -> Result<Vec<f64>> {
    v0.par_iter()
        .map(|v| integrate(0.5, s * v.powf(0.2)).map(|d| d.cor))
        .collect()
}

fn rel_sq(cor: &[f64], target: &[f64]) -> f64 {
    cor.iter()
        .zip(target)
        .map(|(a, b)| ((a - b) / b).powi(2))
        .sum()
}

/// The viscoelastic law closest to `target` at `v0` (m/s) in least squares of the relative
/// error: a scan of the dissipative constant over seven decades, then a golden-section search
/// around the best scan point.
pub fn fit_viscoelastic(
    contact: &HertzContact,
    v0: &[f64],
    target: &[f64],
) -> Result<ViscoelasticLaw> {
    // s = (3/2) A (k/m)^(2/5): c = s v0^(1/5); scan c at the largest velocity up to MAX_VISCO_C
    let vmax = v0.iter().copied().fold(0.0, f64::max);
    let top = MAX_VISCO_C / vmax.powf(0.2);
    const SCAN: usize = 57;
    let scan: Vec<f64> = (0..SCAN)
        .map(|i| top * 10f64.powf(-7.0 * (SCAN - 1 - i) as f64 / (SCAN - 1) as f64))
        .collect();
    let obj = |s: f64| -> Result<f64> { Ok(rel_sq(&visco_cors(s, v0)?, target)) };
    let mut best = (0.0, rel_sq(&vec![1.0; target.len()], target), usize::MAX);
    for (i, &s) in scan.iter().enumerate() {
        let f = obj(s)?;
        if f < best.1 {
            best = (s, f, i);
        }
    }
    let mut s_best = best.0;
    if best.2 != usize::MAX {
        // golden section in ln s between the scan neighbours
        let i = best.2;
        let mut a = if i == 0 {
            scan[0].ln() - 7.0 / (SCAN - 1) as f64 * std::f64::consts::LN_10
        } else {
            scan[i - 1].ln()
        };
        let mut b = if i + 1 == SCAN {
            scan[i].ln()
        } else {
            scan[i + 1].ln()
        };
        let g = 0.5 * (5f64.sqrt() - 1.0);
        let mut x1 = b - g * (b - a);
        let mut x2 = a + g * (b - a);
        let (mut f1, mut f2) = (obj(x1.exp())?, obj(x2.exp())?);
        for _ in 0..crate::model::tolerances::ROOT_MAX_ITER {
            if b - a < 1e-10 {
                break;
            }
            if f1 < f2 {
                b = x2;
                x2 = x1;
                f2 = f1;
                x1 = b - g * (b - a);
                f1 = obj(x1.exp())?;
            } else {
                a = x1;
                x1 = x2;
                f1 = f2;
                x2 = a + g * (b - a);
                f2 = obj(x2.exp())?;
            }
        }
        let (s_mid, f_mid) = if f1 < f2 {
            (x1.exp(), f1)
        } else {
            (x2.exp(), f2)
        };
        if f_mid < best.1 {
            s_best = s_mid;
        }
    }
    let cor = visco_cors(s_best, v0)?;
    // s = (3/2) A (k/m)^(2/5), i.e. A = c(v0 = 1 m/s) / ((3/2) (k/m)^(2/5))
    let a = contact.viscoelastic_a(s_best, 1.0);
    Ok(ViscoelasticLaw {
        a,
        eta_n0: contact.lammps_eta_n0(a),
        fit: Fit::new(cor, target),
    })
}

/// Everything `mdr-impact dem` reports.
#[derive(Debug, Clone, PartialEq)]
pub struct DemReport {
    /// Our `e(v0)`.
    pub rows: Vec<CurveRow>,
    /// Log-spaced velocities.
    pub log: bool,
    /// The modulus limit of the Hertz stiffness.
    pub modulus: ModulusChoice,
    /// The Hertz contact.
    pub contact: HertzContact,
    /// Pair or wall.
    pub geometry: Geometry,
    /// The constant-CoR law.
    pub constant: ConstantLaw,
    /// The viscoelastic law.
    pub viscoelastic: ViscoelasticLaw,
    /// Contact times of the constant-CoR law.
    pub constant_times: ContactTimes,
    /// Contact times of the viscoelastic law.
    pub viscoelastic_times: ContactTimes,
    /// Warnings, one line each (without the `warning: ` prefix).
    pub warnings: Vec<String>,
}

/// How the DEM code sees `impact`'s contact, and a warning when a wall of finite mass moves or
/// a fixed body is not flat.
fn geometry(impact: &Impact) -> (Geometry, Option<String>) {
    let Some(b) = impact.bodies() else {
        return (Geometry::Wall, None);
    };
    let (a, bb) = (b.a(), b.b());
    let wall = a.radius().is_infinite() || bb.radius().is_infinite();
    let heavy = a.mass().is_infinite() || bb.mass().is_infinite();
    match (wall, heavy) {
        (false, false) => (Geometry::Pair, None),
        (true, true) => (Geometry::Wall, None),
        (false, true) => (
            Geometry::Wall,
            Some(
                "a body of infinite mass has a finite radius: DEM walls are flat, so the DEM \
                 code uses the particle's radius where these parameters assume the effective \
                 radius"
                    .into(),
            ),
        ),
        (true, false) => (
            Geometry::Wall,
            Some(
                "a body of infinite radius has finite mass: DEM walls do not move, so the DEM \
                 code uses the particle's mass where these parameters assume the effective mass"
                    .into(),
            ),
        ),
    }
}

/// Solve `impact` over `range` (our `e(v0)`, [`curve::run`]) and fit both laws with the Hertz
/// stiffness of `modulus`.
pub fn run(
    impact: &Impact,
    opts: &SolveOptions,
    range: &VelocityRange,
    modulus: ModulusChoice,
    progress: &(dyn Fn() + Sync),
) -> Result<DemReport> {
    let c = curve::run(impact, opts, range, progress)?;
    let e_star = match modulus {
        ModulusChoice::Relaxed => c.limits.relaxed_modulus,
        ModulusChoice::Glassy => c.limits.glassy_modulus,
    };
    let sphere = impact.sphere();
    let contact = HertzContact::new(sphere.mass(), sphere.radius(), e_star)?;
    let (geometry, note) = geometry(impact);
    fit(c.rows, range.log, modulus, contact, geometry, note)
}

/// Fit both laws to `rows` (our `e(v0)`) with the Hertz `contact`.
pub fn fit(
    rows: Vec<CurveRow>,
    log: bool,
    modulus: ModulusChoice,
    contact: HertzContact,
    geometry: Geometry,
    note: Option<String>,
) -> Result<DemReport> {
    let v0: Vec<f64> = rows.iter().map(|r| r.v0).collect();
    let target: Vec<f64> = rows.iter().map(|r| r.cor).collect();
    if let Some(bad) = target.iter().find(|e| !(**e > 0.0 && **e <= 1.0)) {
        return Err(Error::NonFinite {
            what: "CoR of the curve (outside (0, 1])",
            value: *bad,
        });
    }
    if let Some(bad) = rows.iter().find(|r| !(r.contact_time > 0.0)) {
        return Err(Error::NonFinite {
            what: "contact time of the curve (not positive)",
            value: bad.contact_time,
        });
    }
    let constant = fit_constant(&target)?;
    // long curves: the parameter from an even subsample, the errors from every velocity
    let viscoelastic = if v0.len() > FIT_MAX_VELOCITIES {
        let pick: Vec<usize> = (0..FIT_MAX_VELOCITIES)
            .map(|i| i * (v0.len() - 1) / (FIT_MAX_VELOCITIES - 1))
            .collect();
        let sub = |x: &[f64]| -> Vec<f64> { pick.iter().map(|&i| x[i]).collect() };
        let a = fit_viscoelastic(&contact, &sub(&v0), &sub(&target))?.a;
        let cor = visco_cors(contact.viscoelastic_c(a, 1.0), &v0)?;
        ViscoelasticLaw {
            a,
            eta_n0: contact.lammps_eta_n0(a),
            fit: Fit::new(cor, &target),
        }
    } else {
        fit_viscoelastic(&contact, &v0, &target)?
    };
    let times = |law: DemLaw| -> Result<ContactTimes> {
        let law: Vec<f64> = v0
            .par_iter()
            .map(|v| contact.impact(law, *v).map(|d| d.contact_time))
            .collect::<Result<_>>()?;
        let worst_rel_error = law
            .iter()
            .zip(&rows)
            .map(|(t, r)| ((t - r.contact_time) / r.contact_time).abs())
            .fold(0.0, f64::max);
        Ok(ContactTimes {
            law,
            worst_rel_error,
        })
    };
    let constant_times = times(DemLaw::CoeffRestitution {
        cor_input: constant.cor_input,
    })?;
    let viscoelastic_times = times(DemLaw::Viscoelastic { a: viscoelastic.a })?;
    let mut warnings: Vec<String> = note.into_iter().collect();
    if constant.at_floor {
        warnings.push(format!(
            "the constant CoR law cannot produce less than e = {:.4} (input e = \
             {MIN_COR_INPUT:e}); our e(v0) lies lower",
            constant.cor
        ));
    }
    let pct = |x: f64| format!("{:.1} %", 100.0 * x);
    let laws = [
        ("constant CoR", &constant.fit),
        ("viscoelastic", &viscoelastic.fit),
    ];
    for (name, f) in laws {
        if f.worst_rel_error > WARN_REL_ERROR {
            warnings.push(format!(
                "the {name} law misses our e(v0) by up to {} (rms {}) over this range, more \
                 than {}",
                pct(f.worst_rel_error),
                pct(f.rms_rel_error),
                pct(WARN_REL_ERROR)
            ));
        }
    }
    if laws.iter().all(|(_, f)| f.worst_rel_error > WARN_REL_ERROR) {
        warnings.push(format!(
            "no damping law fits our e(v0) within {} over this range: narrow the range",
            pct(WARN_REL_ERROR)
        ));
    }
    if contact.dem_young() <= LIGGGHTS_MIN_YOUNG {
        warnings.push(format!(
            "Young's modulus {:.4e} Pa is at or below LIGGGHTS's lower limit {LIGGGHTS_MIN_YOUNG:e} \
             Pa (SI units)",
            contact.dem_young()
        ));
    }
    Ok(DemReport {
        rows,
        log,
        modulus,
        contact,
        geometry,
        constant,
        viscoelastic,
        constant_times,
        viscoelastic_times,
        warnings,
    })
}

/// The CSV header of `dem.csv`.
pub const CSV_HEADER: &str = "v0,cor,cor_constant,cor_viscoelastic,contact_time,\
                              contact_time_constant,contact_time_viscoelastic";

impl DemReport {
    /// The better of the two laws (smaller worst error): `true` for the viscoelastic one.
    pub fn viscoelastic_is_better(&self) -> bool {
        self.viscoelastic.fit.worst_rel_error < self.constant.fit.worst_rel_error
    }

    /// `dem.csv`: our CoR and contact time (s) and both laws' at every velocity (SI, full
    /// precision).
    pub fn csv_text(&self) -> String {
        let mut s = String::from(CSV_HEADER);
        s.push('\n');
        for (i, r) in self.rows.iter().enumerate() {
            s.push_str(&format!(
                "{},{},{},{},{},{},{}\n",
                fmt(r.v0),
                fmt(r.cor),
                fmt(self.constant.fit.cor[i]),
                fmt(self.viscoelastic.fit.cor[i]),
                fmt(r.contact_time),
                fmt(self.constant_times.law[i]),
                fmt(self.viscoelastic_times.law[i])
            ));
        }
        s
    }

    fn header(&self, comment: &str, pages: &[&str]) -> String {
        let c = &self.contact;
        let (v0, vn) = (self.rows[0].v0, self.rows[self.rows.len() - 1].v0);
        let pct = |x: f64| format!("{:.2} %", 100.0 * x);
        let mut s = String::new();
        let mut line = |t: String| {
            s.push_str(comment);
            s.push(' ');
            s.push_str(&t);
            s.push('\n');
        };
        line(format!(
            "mdr-impact dem: {} velocities from {v0:.4e} to {vn:.4e} m/s, SI units",
            self.rows.len()
        ));
        for p in pages {
            line(format!("syntax: {p}"));
        }
        line(format!(
            "Hertz ({} modulus): E* = {:.6e} Pa, R* = {:.6e} m, m* = {:.6e} kg, \
             k = 4/3 E* sqrt(R*) = {:.6e} N/m^1.5",
            self.modulus.name(),
            c.effective_modulus,
            c.radius,
            c.mass,
            c.stiffness()
        ));
        line(format!(
            "both types: E = 2 (1 - nu^2) E* = {:.6e} Pa with nu = {DEM_POISSON} (the codes \
             mix E* = E / (2 (1 - nu^2)))",
            c.dem_young()
        ));
        line(format!(
            "constant CoR: input e = {:.6}, produces e = {:.6}; worst error {}, rms {}",
            self.constant.cor_input,
            self.constant.cor,
            pct(self.constant.fit.worst_rel_error),
            pct(self.constant.fit.rms_rel_error)
        ));
        line(format!(
            "viscoelastic: A = {:.6e} s, eta_n0 = 2 E* A / m* = {:.6e} 1/(m s); worst error {}, \
             rms {}",
            self.viscoelastic.a,
            self.viscoelastic.eta_n0,
            pct(self.viscoelastic.fit.worst_rel_error),
            pct(self.viscoelastic.fit.rms_rel_error)
        ));
        let (t0, tn) = (
            self.rows[0].contact_time,
            self.rows[self.rows.len() - 1].contact_time,
        );
        line(format!(
            "contact time {t0:.4e} to {tn:.4e} s; the laws' differ by up to {} (constant CoR), \
             {} (viscoelastic)",
            pct(self.constant_times.worst_rel_error),
            pct(self.viscoelastic_times.worst_rel_error)
        ));
        line("forces are clipped at zero (no attraction at the end of contact), as below".into());
        for w in &self.warnings {
            line(format!("warning: {w}"));
        }
        s
    }

    /// LAMMPS input lines for the current LAMMPS ([`Self::lammps_text_for`]).
    pub fn lammps_text(&self) -> String {
        self.lammps_text_for(LammpsVersion::CURRENT)
    }

    /// LAMMPS input lines for `version`: `pair_style granular` with `hertz/material` and both
    /// damping laws, the better one active and the other commented out; `pair_coeff 1 2` for two
    /// particles, `fix wall/gran granular` for a wall. The tangential model is a frictionless
    /// placeholder. Before [`LAMMPS_WALL_MIX_SINCE`] a wall gets
    /// [`HertzContact::lammps_legacy_wall_young`]; before [`LAMMPS_COEFF_RESTITUTION_SINCE`]
    /// the constant-CoR law is written as `damping tsuji` with [`tsuji_input`], or left out
    /// with a note when no input gives it.
    pub fn lammps_text_for(&self, version: LammpsVersion) -> String {
        let mut s = self.header(
            "#",
            &[
                "https://docs.lammps.org/pair_granular.html",
                "https://docs.lammps.org/fix_wall_gran.html",
            ],
        );
        let legacy_wall = self.geometry == Geometry::Wall && version.legacy_wall_modulus();
        let young = if legacy_wall {
            self.contact.lammps_legacy_wall_young()
        } else {
            self.contact.dem_young()
        };
        s.push_str(&format!(
            "# for {}; state yours with --lammps-version YYYYMMDD (the date `lmp -h` prints)\n",
            version.label()
        ));
        if version.proven() {
            s.push_str(&format!(
                "# proven on LAMMPS {LAMMPS_PROVEN} (Debian lammps, `lmp -h`: 29 Sep 2021 - \
                 Update 2) by validation/dem_clients/verify.py\n"
            ));
        } else {
            s.push_str(&format!(
                "# written from the LAMMPS sources, not run here; proven on LAMMPS \
                 {LAMMPS_PROVEN} (--lammps-version {LAMMPS_PROVEN})\n"
            ));
        }
        if legacy_wall {
            s.push_str(&format!(
                "# wall: this version's fix wall/gran takes E* = E / (2 (1 - nu)), so the wall \
                 gets E = 2 (1 - nu) E* = {} Pa\n",
                fmt_num(young)
            ));
        }
        let (head, tail) = match self.geometry {
            Geometry::Pair => ("pair_coeff 1 2 hertz/material".to_string(), String::new()),
            Geometry::Wall => (
                "fix wall all wall/gran granular hertz/material".to_string(),
                " zplane 0.0 NULL".to_string(),
            ),
        };
        let tangential = "tangential linear_nohistory 0.0 0.0";
        let line = |damp: f64, model: &str| {
            format!(
                "{head} {} {} {DEM_POISSON} {tangential} damping {model} limit_damping{tail}",
                fmt_num(young),
                fmt_num(damp)
            )
        };
        let gamma = cor_gamma(self.constant.cor_input).ok();
        let constant = if version.has_coeff_restitution() {
            Ok(line(self.constant.cor_input, "coeff_restitution"))
        } else {
            match gamma.and_then(tsuji_input) {
                Some(e) => Ok(line(e, "tsuji")),
                None => Err(format!(
                    "# the constant CoR law: {} has no coeff_restitution, and no damping tsuji \
                     input gives its prefactor {:.6e} (tsuji covers {:.4e} to {:.4e})",
                    version.label(),
                    gamma.unwrap_or(f64::NAN),
                    tsuji_alpha(1.0),
                    tsuji_alpha(0.0)
                )),
            }
        };
        if !version.has_coeff_restitution() {
            s.push_str(&format!(
                "# constant CoR law: {} has no damping coeff_restitution; damping tsuji with \
                 the input whose Marshall polynomial equals the law's prefactor gives the same \
                 force\n",
                version.label()
            ));
        }
        let visco = line(self.viscoelastic.eta_n0, "viscoelastic");
        s.push_str("# tangential: frictionless placeholder, set your own friction model\n");
        s.push_str("pair_style granular\n");
        match self.geometry {
            Geometry::Wall => {
                s.push_str("# particle-particle contacts: your own pair_coeff lines\n")
            }
            // LAMMPS refuses to run without the like-type coefficients too
            Geometry::Pair => s.push_str(
                "# like-type contacts (pair_coeff 1 1, pair_coeff 2 2): your own lines; \
                 these parameters are for the 1-2 contact\n",
            ),
        }
        match constant {
            Ok(constant) => {
                let (on, off) = if self.viscoelastic_is_better() {
                    (visco, constant)
                } else {
                    (constant, visco)
                };
                s.push_str(&on);
                s.push('\n');
                s.push_str("# the other law:\n# ");
                s.push_str(&off);
                s.push('\n');
            }
            Err(note) => {
                s.push_str(&visco);
                s.push('\n');
                s.push_str(&note);
                s.push('\n');
            }
        }
        s
    }

    /// LIGGGHTS input lines: `pair_style gran model hertz` with `limitForce on`, the material
    /// of both types by `fix property/global` (constant-CoR law only: LIGGGHTS's hertz model has
    /// no viscoelastic damping), and for a wall a `fix wall/gran` of type 2.
    pub fn liggghts_text(&self) -> String {
        let mut s = self.header(
            "#",
            &[
                "https://www.cfdem.com/media/DEM/docu/gran_model_hertz.html",
                "https://www.cfdem.com/media/DEM/docu/fix_property.html",
                "https://www.cfdem.com/media/DEM/docu/fix_wall_gran.html",
            ],
        );
        let y = fmt_num(self.contact.dem_young());
        let e = fmt_num(self.constant.cor_input);
        s.push_str(&format!(
            "# proven on {LIGGGHTS_PROVEN} (Debian liggghts) by validation/dem_clients/verify.py\n"
        ));
        s.push_str("# the viscoelastic law has no counterpart in LIGGGHTS's model hertz\n");
        s.push_str(&format!(
            "fix m1 all property/global youngsModulus peratomtype {y} {y}\n"
        ));
        s.push_str(&format!(
            "fix m2 all property/global poissonsRatio peratomtype {DEM_POISSON} {DEM_POISSON}\n"
        ));
        s.push_str(&format!(
            "fix m3 all property/global coefficientRestitution peratomtypepair 2 {e} {e} {e} {e}\n"
        ));
        s.push_str("# friction: a frictionless placeholder, set your own\n");
        s.push_str(
            "fix m4 all property/global coefficientFriction peratomtypepair 2 0.0 0.0 0.0 0.0\n",
        );
        s.push_str("pair_style gran model hertz tangential history limitForce on\n");
        s.push_str("pair_coeff * *\n");
        if self.geometry == Geometry::Wall {
            // LIGGGHTS 3.8 wants the wall's keywords (primitive ...) before limitForce
            s.push_str(
                "fix wall all wall/gran model hertz tangential history primitive type 2 zplane \
                 0.0 limitForce on\n",
            );
        }
        s
    }

    /// One JSON object: velocities, our curve, the Hertz stiffness, both laws with their
    /// parameters and errors, the warnings (SI units).
    pub fn json(&self) -> String {
        let c = &self.contact;
        let curve: Vec<serde_json::Value> = self
            .rows
            .iter()
            .enumerate()
            .map(|(i, r)| {
                serde_json::json!({
                    "v0": r.v0,
                    "cor": r.cor,
                    "cor_constant": self.constant.fit.cor[i],
                    "cor_viscoelastic": self.viscoelastic.fit.cor[i],
                    "contact_time": r.contact_time,
                    "contact_time_constant": self.constant_times.law[i],
                    "contact_time_viscoelastic": self.viscoelastic_times.law[i],
                })
            })
            .collect();
        serde_json::json!({
            "velocities": {
                "min": self.rows[0].v0,
                "max": self.rows[self.rows.len() - 1].v0,
                "n": self.rows.len(),
                "log": self.log,
            },
            "hertz": {
                "modulus": self.modulus.name(),
                "effective_modulus": c.effective_modulus,
                "effective_radius": c.radius,
                "effective_mass": c.mass,
                "stiffness": c.stiffness(),
                "young_modulus": c.dem_young(),
                "poisson_ratio": DEM_POISSON,
                "geometry": match self.geometry {
                    Geometry::Pair => "pair",
                    Geometry::Wall => "wall",
                },
            },
            "laws": {
                "constant": {
                    "cor_input": self.constant.cor_input,
                    "cor": self.constant.cor,
                    "worst_rel_error": self.constant.fit.worst_rel_error,
                    "rms_rel_error": self.constant.fit.rms_rel_error,
                    "worst_contact_time_rel_error": self.constant_times.worst_rel_error,
                },
                "viscoelastic": {
                    "dissipative_constant": self.viscoelastic.a,
                    "lammps_eta_n0": self.viscoelastic.eta_n0,
                    "worst_rel_error": self.viscoelastic.fit.worst_rel_error,
                    "rms_rel_error": self.viscoelastic.fit.rms_rel_error,
                    "worst_contact_time_rel_error": self.viscoelastic_times.worst_rel_error,
                },
            },
            "curve": curve,
            "warnings": self.warnings,
        })
        .to_string()
    }

    /// The text of `format`: input lines, or the JSON object.
    pub fn text(&self, format: Format) -> String {
        match format {
            Format::Lammps(v) => self.lammps_text_for(v),
            Format::Liggghts => self.liggghts_text(),
            Format::Json => self.json(),
        }
    }
}

/// A number for an input file: seven significant digits.
fn fmt_num(x: f64) -> String {
    format!("{x:.6e}")
}

/// Files written by [`write_outputs`].
#[derive(Debug, Clone, PartialEq)]
pub struct Written {
    /// `DIR/dem.csv`, `DIR/dem.svg` and, for `lammps` / `liggghts`, `DIR/dem_lammps.in` /
    /// `DIR/dem_liggghts.in`.
    pub files: Vec<PathBuf>,
}

/// Write `dir/dem.csv`, `dir/dem.svg` and the format's input file. Everything is rendered in
/// memory first and each file written atomically; on an error the files already written are
/// removed, so the folder gets all of them or none.
pub fn write_outputs(dir: &Path, report: &DemReport, format: Format) -> Result<Written> {
    let svg = dir.join("dem.svg");
    let mut bodies = vec![
        (dir.join("dem.csv"), report.csv_text()),
        (svg.clone(), dem_svg(&svg, report)?),
    ];
    match format {
        Format::Lammps(v) => bodies.push((dir.join("dem_lammps.in"), report.lammps_text_for(v))),
        Format::Liggghts => bodies.push((dir.join("dem_liggghts.in"), report.liggghts_text())),
        Format::Json => {}
    }
    let mut files = Vec::new();
    for (path, body) in bodies {
        if let Err(e) = write_atomic(&path, |w| {
            w.write_all(body.as_bytes())
                .map_err(|e| Error::io(&path, e))
        }) {
            for f in &files {
                let _ = std::fs::remove_file(f);
            }
            return Err(e);
        }
        files.push(path);
    }
    Ok(Written { files })
}

/// The SVG text of `mdr-impact dem`'s plot: our `e(v0)` and the `e(v0)` of each fitted DEM law
/// (our integration of its force law), on a linear or (with the report's `log`) logarithmic
/// velocity axis. Rendered in memory only; `path` names the file in errors.
pub fn dem_svg(path: &Path, report: &DemReport) -> Result<String> {
    let rows = &report.rows;
    let span = velocity_span(path, &rows.iter().map(|r| r.v0).collect::<Vec<_>>())?;
    let pct = |x: f64| format!("{:.1} %", 100.0 * x);
    let along = |cor: &[f64]| -> Vec<(f64, f64)> {
        rows.iter().zip(cor).map(|(r, e)| (r.v0, *e)).collect()
    };
    let (c, v) = (&report.constant, &report.viscoelastic);
    let lines: Vec<CorLine> = vec![
        (
            "e(v0), this model".to_string(),
            rows.iter().map(|r| (r.v0, r.cor)).collect(),
            RGBColor(30, 80, 200),
            2,
        ),
        (
            format!(
                "constant CoR e = {:.4}, input e = {:.4} (worst {}, rms {})",
                c.cor,
                c.cor_input,
                pct(c.fit.worst_rel_error),
                pct(c.fit.rms_rel_error)
            ),
            along(&c.fit.cor),
            RGBColor(200, 30, 30),
            2,
        ),
        (
            format!(
                "viscoelastic, A = {:.3e} s (worst {}, rms {})",
                v.a,
                pct(v.fit.worst_rel_error),
                pct(v.fit.rms_rel_error)
            ),
            along(&v.fit.cor),
            RGBColor(30, 140, 60),
            2,
        ),
    ];
    let title = format!(
        "DEM damping laws fitted to e(v0), Hertz with the {} modulus",
        report.modulus.name()
    );
    cor_chart_svg(path, &title, span, report.log, &lines)
}
