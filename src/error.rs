//! The crate's error type.
//!
//! Every variant names the field or quantity it is about and carries the numbers, so that a
//! message can be acted on without a debugger. The library never panics on user input.

use thiserror::Error;

/// Result alias used throughout the crate.
pub type Result<T> = std::result::Result<T, Error>;

/// Everything that can go wrong, from bad input to a solver that cannot reach its accuracy.
#[derive(Debug, Error, Clone, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// An input is outside its allowed range (or not finite).
    #[error("{field} = {value:e} is out of range: allowed {allowed}")]
    OutOfRange {
        /// Name of the field as the user wrote it.
        field: &'static str,
        /// The offending value.
        value: f64,
        /// The allowed range, in words (e.g. `"0 < g_inf < inf"`).
        allowed: &'static str,
    },
    /// A term of a Prony series (shear or bulk) is out of range: the field, the term's index in
    /// the input (0-based, before sorting and merging) and the value.
    #[error("{field}[{index}] = {value:e} is out of range: allowed {allowed}")]
    PronyTerm {
        /// Name of the field (e.g. `"g_i"`, `"tau_i"`, `"k_j"`, `"theta_j"`).
        field: &'static str,
        /// 0-based index of the term as given.
        index: usize,
        /// The offending value.
        value: f64,
        /// The allowed range, in words.
        allowed: &'static str,
    },
    /// An explicit time step is above the stability bound of an explicit scheme.
    #[error(
        "time step {dt:e} (dimensionless) exceeds the stability bound {bound:e} of {scheme}; \
             reduce the step or use a stable solver (mdr, fast, reference)"
    )]
    UnstableStep {
        /// The scheme that would blow up.
        scheme: &'static str,
        /// Requested step, in units of the impact's time scale.
        dt: f64,
        /// Largest stable step in the same units.
        bound: f64,
    },
    /// A solver would need more work than its hard cap allows.
    #[error(
        "{solver}: {what}: {needed} needed, above the work limit of {limit}; loosen rtol or use \
         another solver"
    )]
    WorkLimit {
        /// Solver name.
        solver: &'static str,
        /// What is counted (time steps, elements, ...).
        what: &'static str,
        /// What would be needed.
        needed: u64,
        /// The cap.
        limit: u64,
    },
    /// An adaptive driver's refinement did not settle into asymptotic convergence, so no error
    /// estimate could be trusted.
    #[error("{solver}: requested rtol {rtol:e} not reached: the CoR did not converge asymptotically in {levels} refinements (last change between levels {last_change:.2e} relative); use another solver")]
    NotAsymptotic {
        /// Solver name.
        solver: &'static str,
        /// Requested relative tolerance of the CoR.
        rtol: f64,
        /// The relative change of the CoR between the last two levels.
        last_change: f64,
        /// Refinement levels tried.
        levels: u32,
    },
    /// An adaptive step size fell below the solver's smallest step.
    #[error("{solver}: step size {step:e} fell below its minimum at t = {time:e} (canonical units) for rtol {rtol:e}")]
    StepSizeTooSmall {
        /// Solver name.
        solver: &'static str,
        /// Time where it happened, in units of `L / v0`.
        time: f64,
        /// The step size.
        step: f64,
        /// Requested local tolerance.
        rtol: f64,
    },
    /// An adaptive driver could not reach the requested accuracy.
    #[error("{solver}: requested rtol {rtol:e} not reached: estimated relative error {estimate:.2e} (accepted at or below {required:.2e}) after {levels} refinements")]
    AccuracyNotReached {
        /// Solver name.
        solver: &'static str,
        /// Requested relative tolerance of the CoR.
        rtol: f64,
        /// The relative error estimate of the last refinement: the one that caused the refusal.
        estimate: f64,
        /// The level an estimate must reach to be accepted (`rtol`, or `rtol` times a safety
        /// factor of the driver).
        required: f64,
        /// Refinement levels tried.
        levels: u32,
    },
    /// An iteration (root finder, contact-set iteration, time loop) did not finish within its bound.
    #[error("{what} did not converge within {iterations} iterations")]
    NoConvergence {
        /// What was iterating.
        what: &'static str,
        /// The bound that was hit.
        iterations: u64,
    },
    /// A numerical integral failed its accuracy check.
    #[error("quadrature of {what} on [{a:e}, {b:e}] failed: error estimate {estimate:e} > tolerance {tolerance:e}")]
    Quadrature {
        /// What was integrated.
        what: &'static str,
        /// Lower limit.
        a: f64,
        /// Upper limit.
        b: f64,
        /// Error estimate returned.
        estimate: f64,
        /// Requested absolute tolerance.
        tolerance: f64,
    },
    /// A computed quantity was not finite (a bug or an input far outside any physical range).
    #[error("{what} is not finite ({value})")]
    NonFinite {
        /// The quantity.
        what: &'static str,
        /// Its value.
        value: f64,
    },
    /// A scene file could not be read or parsed.
    #[error("scene: {0}")]
    Scene(String),
    /// A CSV input row is bad.
    #[error("{file}:{line}: {message}")]
    Csv {
        /// File name.
        file: String,
        /// 1-based physical line number in the file (lines end at `\r\n`, `\n` or a lone `\r`;
        /// blank lines count).
        line: u64,
        /// What is wrong (user text in it is escaped with [`escape_text`]).
        message: String,
    },
    /// `auto`: the first solver refused and so did the fallback.
    #[error("{first}; fallback {second}")]
    NoSolver {
        /// Why the first solver refused.
        first: Box<Error>,
        /// Why the fallback refused.
        second: Box<Error>,
    },
    /// An output path that is empty.
    #[error("{field} is an empty path: give a file name")]
    EmptyPath {
        /// The key or flag that holds the path (e.g. `"[output] history"`).
        field: &'static str,
    },
    /// An output path that cannot be written as asked: the key or flag that gave it, the path
    /// and why (an existing path that is not a regular file, a file used as a folder, two
    /// outputs at one path).
    #[error("{key} = {path}: {reason}")]
    OutputPath {
        /// The scene key or flag (e.g. `"[output] plot"`, `"--out"`).
        key: String,
        /// The path as given.
        path: String,
        /// What is wrong, in words.
        reason: String,
    },
    /// A Prony series of the input with more terms than the documented limit
    /// ([`crate::io::prony_table::MAX_PRONY_TERMS`]).
    #[error("{field}: {terms} Prony terms exceed the limit of {max} terms per series")]
    TooManyPronyTerms {
        /// Where the series was given (e.g. `"[material.shear] terms"`, a table file).
        field: String,
        /// Terms given.
        terms: usize,
        /// The limit.
        max: usize,
    },
    /// Inputs whose magnitudes, scaled to the contact (canonical units), leave the range of
    /// double precision: what overflowed or vanished, and the inputs that made it so.
    #[error("{what} = {value:e} once scaled to the contact: {inputs}; check their units")]
    OutOfScale {
        /// The scaled quantity (e.g. `"a relaxation time of G_eq over the contact time"`).
        what: &'static str,
        /// Its value.
        value: f64,
        /// The inputs with their values, in words.
        inputs: String,
    },
    /// A request that the chosen solver does not support.
    #[error("{0}")]
    Unsupported(String),
    /// A text input (a flag, a key's value, a range) that cannot be read: what it is, what was
    /// given and what is expected.
    #[error("{what}: cannot read '{input}': expected {expected}")]
    Parse {
        /// The flag or key (e.g. `"--v0"`).
        what: &'static str,
        /// The text as given (escaped with [`escape_text`]).
        input: String,
        /// What would have been accepted, in words.
        expected: String,
    },
    /// A valid request that this solver or command does not handle (a capability refusal).
    #[error("{solver}: {what}")]
    NotSupported {
        /// The solver or command that refuses.
        solver: &'static str,
        /// What it does not support and what to use instead.
        what: String,
    },
    /// A Prony series with more terms than a solver handles.
    #[error("{solver}: {terms} prony terms exceed its limit of {max}")]
    TooManyTerms {
        /// The solver that refuses.
        solver: &'static str,
        /// Terms of the equivalent relaxation function after merging.
        terms: usize,
        /// The solver's cap.
        max: usize,
    },
    /// Two bodies that do not make a collision (both rigid, ...).
    #[error("{reason}")]
    InvalidBodies {
        /// What is wrong, in words.
        reason: &'static str,
    },
    /// An error with the place it arose: a file, a table, a body, a row or a velocity.
    #[error("{place}: {source}")]
    In {
        /// Where (e.g. `"scene.toml [material.shear]"`, `"body A"`, `"v0 = 2.5 m/s"`).
        place: String,
        /// What went wrong there.
        #[source]
        source: Box<Error>,
    },
    /// A broken invariant of the library: a bug, never the user's input.
    #[error("internal error (please report): {0}")]
    Internal(&'static str),
    /// `fit`: fewer measured values (CoRs and contact times) than free parameters.
    #[error(
        "fit: {observations} measured values cannot determine {parameters} free parameters: add \
         drops at other velocities or contact times, or fix parameters with --fix"
    )]
    TooFewObservations {
        /// Measured values (one per CoR, one per contact time).
        observations: usize,
        /// Free parameters of the fit.
        parameters: usize,
    },
    /// `fit`: every CoR equals 1, so no viscoelastic parameter is identifiable.
    #[error(
        "fit: all {observations} CoRs equal 1: elastic data determine no viscoelastic parameter \
         (g_1, eta and the groups p2, eta / g_inf^(3/5) are not identifiable)"
    )]
    ElasticData {
        /// Number of drops.
        observations: usize,
    },
    /// `fit`: standard deviations given for some measured values but not for all of them (one
    /// noise scale cannot be estimated for residuals of different scales).
    #[error(
        "fit: {column} is given for {given} of {values} measured values: give the standard \
         deviations of every CoR and contact time, or of none"
    )]
    PartialNoise {
        /// The column (`cor_sd` or `contact_time_sd`).
        column: &'static str,
        /// Values that have it.
        given: usize,
        /// Values that need it.
        values: usize,
    },
    /// `fit`: no start of the least-squares fit reached a finite misfit.
    #[error("fit: no start of the least-squares fit reached a finite misfit ({starts} tried; last: {last})")]
    FitFailed {
        /// Starts tried.
        starts: usize,
        /// Why the last one failed.
        last: String,
    },
    /// File system or output error.
    #[error("{path}: {message}")]
    Io {
        /// The path involved.
        path: String,
        /// The OS message.
        message: String,
    },
}

/// The broad kind of an [`Error`](enum@Error), for callers that react by kind rather than by variant.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ErrorKind {
    /// The input is invalid: out of range, unreadable, inconsistent.
    Input,
    /// A valid request that a solver refused: accuracy, work or capability limits.
    Refusal,
    /// A fit could not be carried out on these data.
    Fit,
    /// Reading or writing files failed.
    Io,
    /// A bug in this library.
    Internal,
}

impl ErrorKind {
    /// Lower-case name (`input`, `refusal`, `fit`, `io`, `internal`).
    pub fn name(self) -> &'static str {
        match self {
            ErrorKind::Input => "input",
            ErrorKind::Refusal => "refusal",
            ErrorKind::Fit => "fit",
            ErrorKind::Io => "io",
            ErrorKind::Internal => "internal",
        }
    }
}

impl Error {
    /// The variant name of an error (of the error it wraps, for [`Error::In`]): the category names
    /// of the stress section (`report::stress`). Exhaustive, so a new variant must be named here.
    pub fn variant_name(&self) -> &'static str {
        match self {
            Error::OutOfRange { .. } => "OutOfRange",
            Error::PronyTerm { .. } => "PronyTerm",
            Error::UnstableStep { .. } => "UnstableStep",
            Error::WorkLimit { .. } => "WorkLimit",
            Error::NotAsymptotic { .. } => "NotAsymptotic",
            Error::StepSizeTooSmall { .. } => "StepSizeTooSmall",
            Error::AccuracyNotReached { .. } => "AccuracyNotReached",
            Error::NoConvergence { .. } => "NoConvergence",
            Error::Quadrature { .. } => "Quadrature",
            Error::NonFinite { .. } => "NonFinite",
            Error::OutOfScale { .. } => "OutOfScale",
            Error::Scene(_) => "Scene",
            Error::Csv { .. } => "Csv",
            Error::NoSolver { .. } => "NoSolver",
            Error::EmptyPath { .. } => "EmptyPath",
            Error::OutputPath { .. } => "OutputPath",
            Error::TooManyPronyTerms { .. } => "TooManyPronyTerms",
            Error::Unsupported(_) => "Unsupported",
            Error::Parse { .. } => "Parse",
            Error::NotSupported { .. } => "NotSupported",
            Error::TooManyTerms { .. } => "TooManyTerms",
            Error::InvalidBodies { .. } => "InvalidBodies",
            Error::In { source, .. } => source.variant_name(),
            Error::Internal(_) => "Internal",
            Error::TooFewObservations { .. } => "TooFewObservations",
            Error::ElasticData { .. } => "ElasticData",
            Error::PartialNoise { .. } => "PartialNoise",
            Error::FitFailed { .. } => "FitFailed",
            Error::Io { .. } => "Io",
        }
    }

    /// The kind of this error; [`Error::In`] reports the kind of what it wraps. Exhaustive, so
    /// that a new variant must be classified here.
    pub fn kind(&self) -> ErrorKind {
        match self {
            Error::OutOfRange { .. }
            | Error::PronyTerm { .. }
            | Error::Scene(_)
            | Error::Csv { .. }
            | Error::EmptyPath { .. }
            | Error::OutputPath { .. }
            | Error::TooManyPronyTerms { .. }
            | Error::Parse { .. }
            | Error::OutOfScale { .. }
            | Error::InvalidBodies { .. } => ErrorKind::Input,
            Error::UnstableStep { .. }
            | Error::WorkLimit { .. }
            | Error::NotAsymptotic { .. }
            | Error::StepSizeTooSmall { .. }
            | Error::AccuracyNotReached { .. }
            | Error::NoConvergence { .. }
            | Error::Quadrature { .. }
            | Error::NonFinite { .. }
            | Error::NoSolver { .. }
            | Error::Unsupported(_)
            | Error::NotSupported { .. }
            | Error::TooManyTerms { .. } => ErrorKind::Refusal,
            Error::TooFewObservations { .. }
            | Error::ElasticData { .. }
            | Error::PartialNoise { .. }
            | Error::FitFailed { .. } => ErrorKind::Fit,
            Error::Io { .. } => ErrorKind::Io,
            Error::Internal(_) => ErrorKind::Internal,
            Error::In { source, .. } => source.kind(),
        }
    }

    /// This error with the place it arose in front (`place: message`).
    pub fn at(self, place: impl Into<String>) -> Self {
        Error::In {
            place: place.into(),
            source: Box::new(self),
        }
    }

    /// The innermost error under any [`Error::In`] wrappers.
    pub fn root(&self) -> &Error {
        match self {
            Error::In { source, .. } => source.root(),
            e => e,
        }
    }

    /// Helper for I/O errors that keeps the path.
    pub fn io(path: impl AsRef<std::path::Path>, err: impl std::fmt::Display) -> Self {
        Error::Io {
            path: path.as_ref().display().to_string(),
            message: err.to_string(),
        }
    }
}

/// `text` with control characters and other characters that do not print (`\0`, `\r`, `\n`,
/// `\u{7}`, a byte-order mark, ...) written as Rust escapes, so that a message quoting a user's
/// text stays on one line and never carries a raw control byte. Backslashes and quotes are left
/// as they are, so escaping twice changes nothing.
///
/// ```
/// # use mdr_impact::error::escape_text;
/// assert_eq!(escape_text("0.4\u{0}5\u{7}"), "0.4\\05\\u{7}");
/// assert_eq!(escape_text("a\\b 'c' \"d\" é"), "a\\b 'c' \"d\" é");
/// assert_eq!(escape_text(&escape_text("x\ny")), "x\\ny");
/// ```
pub fn escape_text(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        let printable = !c.is_control()
            && (matches!(c, '\\' | '\'' | '"') || c.escape_debug().next() != Some('\\'));
        if printable {
            out.push(c);
        } else {
            out.extend(c.escape_debug());
        }
    }
    out
}

/// Check that `value` is finite and satisfies `ok`; otherwise return [`Error::OutOfRange`].
pub(crate) fn check(
    field: &'static str,
    value: f64,
    ok: bool,
    allowed: &'static str,
) -> Result<f64> {
    if value.is_finite() && ok {
        Ok(value)
    } else {
        Err(Error::OutOfRange {
            field,
            value,
            allowed,
        })
    }
}

/// [`Error::at`] on a [`Result`]: `solve(..).at("v0 = 2 m/s")?`.
pub trait ResultExt<T> {
    /// The error, if any, with the place it arose in front.
    fn at(self, place: impl FnOnce() -> String) -> Result<T>;
}

impl<T> ResultExt<T> for Result<T> {
    fn at(self, place: impl FnOnce() -> String) -> Result<T> {
        self.map_err(|e| e.at(place()))
    }
}
