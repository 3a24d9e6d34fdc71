//! Every default tolerance and accuracy setting of the crate, with names. They only ever get tighter.

/// Default requested relative accuracy of the CoR.
pub const DEFAULT_RTOL: f64 = 1e-6;
/// Smallest rtol accepted.
pub const MIN_RTOL: f64 = 1e-12;
/// Largest rtol accepted.
pub const MAX_RTOL: f64 = 0.1;

/// Iteration cap of every scalar root finder.
pub const ROOT_MAX_ITER: usize = 200;
/// Elements per contact radius of the MDR pilot run that lays out the grid.
pub const PILOT_ELEMENTS: usize = 16;
/// Steps per contact time of the MDR pilot run.
pub const PILOT_STEPS: usize = 48;
/// Restarts of the pilot run before giving up.
pub const PILOT_MAX_RESTARTS: usize = 24;
/// Hard cap on MDR elements.
pub const MDR_MAX_ELEMENTS: usize = 1 << 22;
/// Elements per contact radius on the first level of the adaptive MDR driver.
pub const MDR_START_ELEMENTS: usize = 16;
/// Steps per contact time on the first level of the adaptive MDR driver.
pub const MDR_START_STEPS: usize = 32;
/// Refinement levels of the adaptive MDR driver.
pub const MDR_MAX_LEVELS: u32 = 16;
/// Cap on element updates (element-steps) of one adaptive MDR solve (a few seconds of work).
pub const MDR_MAX_ELEMENT_UPDATES: u64 = 4_000_000_000;
/// Default elements across the maximum contact radius of a displacement-controlled MDR run.
pub const INDENT_ELEMENTS: usize = 2000;
/// Default time steps over a prescribed indentation history.
pub const INDENT_STEPS: usize = 4000;
/// Samples of the Hertz closed-form history when an elastic impact's history is requested.
pub const HERTZ_HISTORY_SAMPLES: usize = 401;
/// Safety factor of the adaptive MDR driver: the error estimate must be below this times rtol.
pub const MDR_SAFETY: f64 = 0.5;
/// Uniform samples of an impact history from the reference solver (requested by `auto` or
/// `reference` with histories).
pub const HISTORY_SAMPLES: usize = 1001;

/// `fit`: requested relative accuracy of every forward solve (well below 1 % data noise, and
/// small enough that central differences with [`FIT_FD_STEP`] stay accurate to about 1e-5).
pub const FIT_RTOL: f64 = 1e-8;
/// `fit`: requested relative accuracy of the forward solves that screen the starting points.
pub const FIT_SCREEN_RTOL: f64 = 1e-5;
/// `fit`: step of the central differences in the fit coordinates (log moduli, logistic `nu`).
pub const FIT_FD_STEP: f64 = 1e-3;
/// `fit`: a singular value of the weighted Jacobian at or below this fraction of the largest
/// one spans a direction the data do not determine (structural non-identifiability).
pub const FIT_NULL_RATIO: f64 = 1e-4;
/// `fit`: a combination whose unit direction has a component above this in the null space is
/// not identifiable.
pub const FIT_NULL_COMPONENT: f64 = 1e-3;
/// `fit`: a parameter whose 95 % interval reaches further than this in its coordinate (natural
/// log of a modulus: a factor of 10 either way) is reported as not well determined.
pub const FIT_MAX_HALF_WIDTH: f64 = std::f64::consts::LN_10;
/// `fit`: relative tolerances (`ftol`, `xtol`, `gtol`) of the Levenberg-Marquardt iteration.
pub const FIT_LM_TOL: f64 = 1e-9;
/// `fit`: the Levenberg-Marquardt iteration stops after this many residual evaluations per
/// free parameter (plus one).
pub const FIT_LM_PATIENCE: usize = 40;
/// `fit`: relative tolerances of the short Levenberg-Marquardt runs that scout the basins of
/// the stiffness ratio before the full minimisations.
pub const FIT_SCOUT_TOL: f64 = 1e-4;
/// `fit`: residual evaluations per free parameter (plus one) of a scouting run.
pub const FIT_SCOUT_PATIENCE: usize = 4;
/// `fit`: the best screened points (distinct) that each start a scouting run, besides the best
/// one of every decade of the stiffness ratio.
pub const FIT_SCOUT_TOP: usize = 8;
/// `fit`: Levenberg-Marquardt runs started from the best screened points.
pub const FIT_LM_STARTS: usize = 2;
/// `fit`: a basin scouted from a decade of the stiffness ratio is minimised fully when its
/// scouted misfit lies within this many likelihood-ratio thresholds of the best scouted one
/// (besides the best): a second basin within the threshold of the best minimum then reaches the
/// intervals, which widen to it, instead of being dropped after the scout (the scouted misfit
/// lies above the basin's minimum, hence the margin).
pub const FIT_SCOUT_KEEP: f64 = 4.0;
/// `fit`: step of the profile likelihood in a parameter's coordinate (a quarter decade).
pub const FIT_PROFILE_STEP: f64 = std::f64::consts::LN_10 / 4.0;
/// `fit`: steps of the profile likelihood on each side (four decades).
pub const FIT_PROFILE_STEPS: usize = 16;
/// `fit`: other minima met by the fit that also start the profile minimisations which check
/// the ends of the Wald intervals (besides the previous profile point).
pub const FIT_PROFILE_OTHERS: usize = 2;
/// `fit`: those minima are taken only when their misfit is at most this factor times the
/// estimate's (at least 1).
pub const FIT_PROFILE_OTHERS_SSR: f64 = 3.0;
/// `fit`: points screened or evaluated by the fit (smallest misfit first) that also start each
/// of those profile minimisations, taken among the points whose quantity lies at or beyond the
/// profile point (a basin on the far side of the interval's end).
pub const FIT_PROFILE_BEYOND: usize = 2;
/// `fit`: the 95 % level of the chi-square law with two degrees of freedom, `-2 ln 0.05`. An
/// interval's end is on a flat shoulder when the profile at twice the end's distance from the
/// estimate lies less than this level (in units of the noise variance; scaled like the threshold
/// when the noise is estimated) above the minimum (docs/theory.md §16.1).
pub const FIT_SHOULDER_LEVEL: f64 = 5.991_464_547_107_979;

/// Absolute accuracy floor of the tangential CoR of an oblique `mdr` run: the adaptive driver
/// accepts `v_c' / v_c` at `max(rtol, OBLIQUE_TANGENTIAL_ATOL)` (absolute; the normal CoR keeps
/// `rtol`). The tangential foundation converges at first order in the resolution (the slip
/// front crosses an element inside a step, where the exponential update assumes a linear
/// displacement), so each level halves its error at four times the work; the estimate is
/// reported (`tangential_error_estimate`).
pub const OBLIQUE_TANGENTIAL_ATOL: f64 = 1e-4;
