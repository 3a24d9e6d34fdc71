//! Output formats and the versions of LAMMPS and LIGGGHTS the emitted lines are written for.

use super::*;

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
        self.0.is_none_or(|d| d >= date)
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
    /// `E*` chosen so that the laws' contact times match ours over the range: the least-squares
    /// fit of `ln t` over both laws and every velocity (each law's contact time scales as
    /// `E*^(-2/5)` while its CoR does not depend on `E*`).
    Fit,
}

impl ModulusChoice {
    /// The name used on the command line and in the output.
    pub fn name(self) -> &'static str {
        match self {
            Self::Relaxed => "relaxed",
            Self::Glassy => "glassy",
            Self::Fit => "fit",
        }
    }
}

impl std::str::FromStr for ModulusChoice {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "relaxed" => Ok(Self::Relaxed),
            "glassy" => Ok(Self::Glassy),
            "fit" => Ok(Self::Fit),
            other => Err(Error::Parse {
                what: "--modulus",
                input: crate::error::escape_text(other),
                expected: "relaxed, glassy or fit".into(),
            }),
        }
    }
}
