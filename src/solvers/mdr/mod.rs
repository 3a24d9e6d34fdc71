//! The Method of Dimensionality Reduction (paper §3, Eqs. 4–9).
//!
//! The sphere's profile `f(r) = r^2/(2R)` maps to `g(x) = x^2/R` (Eq. 6). A one-dimensional
//! foundation of independent viscoelastic elements at `x_i = (i + 1/2) dx`, `i = 0, 1, ...`
//! (midpoints, each standing for the pair at `+-x_i`), carries `u_i = d - g(x_i)` while in
//! contact (Eq. 7) and a force per pair `8 dx` times the hereditary response of the element of
//! Eq. (8). Elements enter as the indentation reaches them during compression, leave when their
//! force would turn negative (outermost first: last in, first out) and are never traced again.
//! The sphere obeys `m d'' = -F` (Eq. 9).
//!
//! Two time schemes: [`Scheme::Euler`] (the paper's explicit Euler on the network of Eq. 8,
//! standard solid only) and [`Scheme::Exponential`] (exact exponential update of the Prony
//! internal variables, trapezoidal rule for the sphere: unconditionally stable, second order),
//! on the standard solid's `G_eq` or on a general material's element network built from `G` and
//! `K` ([`crate::model::material::GeneralNetwork`], module `network`). Both work in canonical units
//! (`m = R = v0 = G_inf = 1`, see [`crate::model::impact`]); [`indent`] drives the foundation with a
//! prescribed indentation instead.

mod adaptive;
pub(crate) mod euler;
pub(crate) mod exponential;
pub mod indent;

use adaptive::accept;
pub use adaptive::{euler_step_bound, pilot, pilot_material, run_resolution, solve_rtol};
pub(crate) mod network;
pub mod oblique;

use crate::error::{Error, Result};
pub use crate::model::contact::Network;
use crate::model::contact::{CanonicalOutcome, Contact, Geometry};
use crate::model::impact::Impact;
use crate::model::impact::{History, Method, Outcome, Work};
use crate::model::material::{ElementModel, Prony};
use crate::model::tolerances;
use crate::solvers::api::{ImpactSolver, SolveOptions, SolverKind};
use euler::EulerFoundation;
use exponential::ExpFoundation;
use network::NetFoundation;

/// Element positions of the foundation: uniform cells of width `dx`, or for a power law with
/// `n < 2` (a cone: `n = 1`) cells graded towards the tip, `x = s^p` over a uniform `s` of
/// spacing `dx` with `p = 2 / n`, so that the first element's `g` is `O(dx^2)` as for the
/// paraboloid (a uniform grid would leave an `O(dx)` tail of the force unresolved at the start
/// and the end of contact). The map is `x = S (s / S)^p` with `S` the contact radius the grid
/// was laid out for (`capacity` covers four of them), so that a graded grid has as many
/// elements across that radius as a uniform one. Each element's force weight is
/// `8` times its cell width.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Foundation {
    dx: f64,
    geometry: Geometry,
    /// `1 / R` of a paraboloid (its `g` costs two products), `None` for other shapes.
    inv_radius: Option<f64>,
    /// The grading exponent `p` (`1`: uniform).
    grade: f64,
    /// The length `S` of the graded map.
    span: f64,
    capacity: usize,
}

impl Foundation {
    /// Foundation with spacing `dx` for the indenter `geometry`, with at most `capacity`
    /// elements. A flat punch's spacing is adjusted to fit a whole number of elements in its
    /// radius (its force is then exact in the spacing).
    pub fn new(dx: f64, geometry: &Geometry, capacity: usize) -> Self {
        let (dx, grade) = match *geometry {
            Geometry::Flat { radius } => (radius / (radius / dx).round().max(1.0), 1.0),
            // x = s^p with s of the order of the contact radius: the same element count
            Geometry::PowerLaw { exponent, .. } if exponent < 2.0 => {
                let p = 2.0 / exponent;
                (dx, p)
            }
            _ => (dx, 1.0),
        };
        Self {
            dx,
            geometry: *geometry,
            inv_radius: geometry.inverse_radius(),
            grade,
            span: (capacity.saturating_sub(16).max(4) as f64) * dx / 4.0,
            capacity,
        }
    }
    /// Position of element `i` (the image of its cell's midpoint in `s`).
    #[inline]
    pub fn x(&self, i: usize) -> f64 {
        let s = (i as f64 + 0.5) * self.dx;
        if self.grade == 1.0 {
            s
        } else {
            self.span * (s / self.span).powf(self.grade)
        }
    }
    /// Outer edge of cell `i - 1`: the contact radius of `i` elements.
    #[inline]
    fn edge(&self, i: usize) -> f64 {
        let s = i as f64 * self.dx;
        if self.grade == 1.0 {
            s
        } else {
            self.span * (s / self.span).powf(self.grade)
        }
    }
    /// Width of cell `i` relative to `dx` (exactly 1 on a uniform grid).
    #[inline]
    pub fn rel_weight(&self, i: usize) -> f64 {
        if self.grade == 1.0 {
            1.0
        } else {
            (self.edge(i + 1) - self.edge(i)) / self.dx
        }
    }
    /// Equivalent profile at element `i`: `g(x_i)` ([`Geometry::profile`]; `x_i^2 / R` for the
    /// paraboloid).
    #[inline]
    pub fn g(&self, i: usize) -> f64 {
        let x = self.x(i);
        match self.inv_radius {
            Some(k) => x * x * k,
            None => self.geometry.profile(x),
        }
    }
    /// Force weight of one element pair of relative width 1, `2 * 4 dx`
    /// (times [`Foundation::rel_weight`] for element `i`).
    #[inline]
    pub fn weight(&self) -> f64 {
        8.0 * self.dx
    }
    /// Element spacing (m).
    pub fn dx(&self) -> f64 {
        self.dx
    }
    /// Maximum element count.
    pub fn capacity(&self) -> usize {
        self.capacity
    }
    /// The indenter's shape.
    pub fn shape(&self) -> &Geometry {
        &self.geometry
    }
    /// Contact radius represented by `n` elements in contact: the outer cell edge.
    pub fn radius_of(&self, n: usize) -> f64 {
        self.edge(n)
    }
}

/// MDR time scheme.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scheme {
    /// The paper's explicit Euler on the element network of Eq. (8).
    Euler,
    /// Exact exponential update of the internal variables, trapezoidal rule for the sphere.
    Exponential,
}

impl Scheme {
    /// Solver name of the scheme.
    pub fn name(self) -> &'static str {
        match self {
            Scheme::Euler => "mdr-euler",
            Scheme::Exponential => "mdr",
        }
    }
    /// Observed order of the scheme in the time step (asymptotic).
    pub fn time_order(self) -> f64 {
        match self {
            Scheme::Euler => 1.0,
            Scheme::Exponential => 2.0,
        }
    }
}

/// The material of a canonical problem in the forms the schemes need, with the geometry.
#[derive(Debug, Clone)]
pub struct CanonicalMaterial {
    /// Equivalent relaxation function (moduli / `G_inf`, times / time scale).
    pub prony: Prony,
    /// The element network in the same units.
    pub network: Network,
    /// The indenter's shape (the canonical paraboloid today).
    pub geometry: Geometry,
}

impl CanonicalMaterial {
    /// The MDR's view of a contact: its `G_eq`, network and geometry.
    pub fn of(contact: &Contact) -> Self {
        Self {
            prony: (*contact.g_eq).clone(),
            network: contact.network.clone(),
            geometry: contact.geometry,
        }
    }
}

/// The impact's material in canonical units, in the forms the MDR schemes need (the network is
/// chosen by shape in [`Impact::contact`]).
pub fn canonical_material(impact: &Impact) -> Result<CanonicalMaterial> {
    Ok(CanonicalMaterial::of(&impact.contact()?))
}

/// An MDR scheme behind the solver interface: `mdr` ([`Scheme::Exponential`]) or `mdr-euler`
/// ([`Scheme::Euler`]), to `rtol` ([`solve_rtol`]) or on an explicit resolution
/// ([`run_resolution`], within the work limit).
#[derive(Debug, Clone, Copy)]
pub struct Mdr(pub Scheme);

impl ImpactSolver for Mdr {
    fn kind(&self) -> SolverKind {
        match self.0 {
            Scheme::Euler => SolverKind::MdrEuler,
            Scheme::Exponential => SolverKind::Mdr,
        }
    }
    fn solve(&self, contact: &Contact, opts: &SolveOptions) -> Result<CanonicalOutcome> {
        let scheme = self.0;
        let material = CanonicalMaterial::of(contact);
        let o = match opts.resolution {
            Some(r) => {
                let needed = (r.elements as u64).saturating_mul(r.steps as u64);
                if needed > opts.work_limit {
                    return Err(Error::WorkLimit {
                        solver: scheme.name(),
                        what: "elements x steps",
                        needed,
                        limit: opts.work_limit,
                    });
                }
                let layout = pilot_material(&material)?;
                run_resolution(
                    scheme,
                    &material,
                    &layout,
                    r.elements,
                    r.steps,
                    opts.history,
                )?
            }
            None => solve_rtol(scheme, &material, opts.rtol, opts.history, opts.work_limit)?,
        };
        Ok(CanonicalOutcome::new(o))
    }
}

/// The one-line refusal of [`Scheme::Euler`] for two viscoelastic bodies (the text of its
/// [`Error::NotSupported`], [`euler_refusal`]).
pub const EULER_GENERAL_UNSUPPORTED: &str = "mdr-euler: the paper's explicit Euler runs on one \
     body's element network; use mdr, fast or reference for two viscoelastic bodies";

/// The refusal of [`Scheme::Euler`] for two viscoelastic bodies; prints
/// [`EULER_GENERAL_UNSUPPORTED`].
pub fn euler_refusal() -> Error {
    Error::NotSupported {
        solver: "mdr-euler",
        what: "the paper's explicit Euler runs on one body's element network; use mdr, fast or \
               reference for two viscoelastic bodies"
            .into(),
    }
}

/// The step interface of the exponential scheme's foundations: the standard solid's through
/// `G_eq` ([`ExpFoundation`]) and the general network ([`NetFoundation`]).
pub(crate) trait Stepper {
    /// Set the step size.
    fn set_step(&mut self, dt: f64);
    /// Force over the current contact set at depth `d` with the current states.
    fn force_now(&self, d: f64) -> f64;
    /// End-of-step force over the current contact set, affine in the rate `r`.
    fn affine(&self, d: f64) -> exponential::Affine;
    /// End-of-step force and `df/dr` of the elements entering during a step at rate `r > 0`.
    fn entering(&self, d: f64, r: f64) -> (f64, f64);
    /// End-of-step force (per `8 dx`) of the outermost element in contact, if any.
    fn outer_force(&self, d: f64, r: f64) -> Option<f64>;
    /// Force (per `8 dx`) of the outermost element with the current states.
    fn outer_force_start(&self, d: f64) -> f64;
    /// Affine contribution of the outermost element.
    fn outer_affine(&self, d: f64) -> exponential::Affine;
    /// Remove the outermost element.
    fn pop(&mut self);
    /// Advance all elements by one step at rate `r` from depth `d` (admitting entering ones).
    fn commit(&mut self, d: f64, r: f64, admit: bool);
    /// Elements in contact.
    fn in_contact(&self) -> usize;
    /// Element positions.
    fn geometry(&self) -> &Foundation;
    /// `(maximum elements in contact, element updates)`.
    fn counters(&self) -> (usize, u64);
    /// Normal force of element `i < in_contact()` (per `8 dx` and relative width) at depth `d`
    /// with the current states.
    fn element_force(&self, i: usize, d: f64) -> f64;
}

impl Stepper for ExpFoundation {
    fn set_step(&mut self, dt: f64) {
        ExpFoundation::set_step(self, dt)
    }
    fn force_now(&self, d: f64) -> f64 {
        ExpFoundation::force_now(self, d)
    }
    fn affine(&self, d: f64) -> exponential::Affine {
        ExpFoundation::affine(self, d)
    }
    fn entering(&self, d: f64, r: f64) -> (f64, f64) {
        ExpFoundation::entering(self, d, r)
    }
    fn outer_force(&self, d: f64, r: f64) -> Option<f64> {
        ExpFoundation::outer_force(self, d, r)
    }
    fn outer_force_start(&self, d: f64) -> f64 {
        ExpFoundation::outer_force_start(self, d)
    }
    fn outer_affine(&self, d: f64) -> exponential::Affine {
        ExpFoundation::outer_affine(self, d)
    }
    fn pop(&mut self) {
        ExpFoundation::pop(self)
    }
    fn commit(&mut self, d: f64, r: f64, admit: bool) {
        ExpFoundation::commit(self, d, r, admit)
    }
    fn in_contact(&self) -> usize {
        ExpFoundation::in_contact(self)
    }
    fn geometry(&self) -> &Foundation {
        ExpFoundation::geometry(self)
    }
    fn counters(&self) -> (usize, u64) {
        (self.max_elements, self.element_updates)
    }
    fn element_force(&self, i: usize, d: f64) -> f64 {
        ExpFoundation::element_force(self, i, d)
    }
}

/// Characteristic sizes of an impact used to lay out the discretisation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Layout {
    /// Estimated maximum contact radius (canonical).
    pub contact_radius: f64,
    /// Estimated time of maximum indentation (canonical).
    pub compression_time: f64,
    /// Estimated contact time (canonical).
    pub contact_time: f64,
}

/// Discretisation of one MDR run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    /// Element spacing.
    pub dx: f64,
    /// Time step during compression.
    pub dt_compression: f64,
    /// Time step during restitution.
    pub dt_restitution: f64,
    /// Maximum number of steps before the run is declared not to end.
    pub max_steps: u64,
}

impl Grid {
    /// Step size of the current phase.
    fn dt(&self, compression: bool) -> f64 {
        if compression {
            self.dt_compression
        } else {
            self.dt_restitution
        }
    }

    /// Error when the time loop has used its step budget without the contact ending.
    fn check_budget(&self, steps: u64, what: &'static str) -> Result<()> {
        if steps >= self.max_steps {
            Err(Error::NoConvergence {
                what,
                iterations: steps,
            })
        } else {
            Ok(())
        }
    }

    /// Grid with `elements` across the estimated contact radius and `steps` per estimated
    /// contact time, split between the phases in proportion to their number of steps
    /// (`steps / 2` each, so that a fast compression and a slow restitution are both resolved).
    pub fn from_layout(layout: &Layout, elements: usize, steps: usize) -> Self {
        let half = (steps as f64 / 2.0).max(2.0);
        let tr = (layout.contact_time - layout.compression_time).max(0.05 * layout.contact_time);
        Grid {
            dx: layout.contact_radius / elements as f64,
            dt_compression: layout.compression_time / half,
            dt_restitution: tr / half,
            max_steps: 20 * steps as u64 + 1000,
        }
    }
}

/// Hard work limits of the MDR solvers.
fn capacity_for(dx: f64, contact_radius: f64) -> usize {
    ((4.0 * contact_radius / dx).ceil() as usize + 16).min(tolerances::MDR_MAX_ELEMENTS)
}

/// Running maxima and events shared by the schemes.
#[derive(Debug, Default, Clone)]
struct Tracker {
    max_force: f64,
    prev: [(f64, f64); 2],
    count: usize,
    t_max_d: Option<f64>,
    d_max: f64,
}

impl Tracker {
    fn sample_force(&mut self, t: f64, f: f64) {
        if self.count >= 2 {
            let (t0, f0) = self.prev[0];
            let (t1, f1) = self.prev[1];
            if f1 >= f0 && f1 > f && f1 >= self.max_force {
                self.max_force = parabola_peak(t0, f0, t1, f1, t, f).max(f1);
            }
        }
        if f > self.max_force {
            self.max_force = f;
        }
        self.prev = [self.prev[1], (t, f)];
        self.count += 1;
    }
    /// Detect `v` crossing zero over a step and record the interpolated maximum indentation.
    fn sample_turn(&mut self, t: f64, dt: f64, d: f64, v: f64, v1: f64) {
        if self.t_max_d.is_none() && v > 0.0 && v1 <= 0.0 {
            let s = dt * v / (v - v1);
            self.t_max_d = Some(t + s);
            self.d_max = d + 0.5 * v * s;
        }
    }
}

/// A history buffer with the initial state (`d = 0`, `v = 1`), if requested.
fn start_history(history: bool) -> Option<History> {
    history.then(|| {
        let mut h = History::default();
        h.push(0.0, 0.0, 1.0, 0.0, 0.0);
        h
    })
}

/// Peak of the parabola through three points (the middle one the largest).
fn parabola_peak(t0: f64, f0: f64, t1: f64, f1: f64, t2: f64, f2: f64) -> f64 {
    let d01 = (f1 - f0) / (t1 - t0);
    let d12 = (f2 - f1) / (t2 - t1);
    let c = (d12 - d01) / (t2 - t0);
    if !(c < 0.0) {
        return f1;
    }
    // f(t) = f1 + b (t - t1) + c (t - t1)^2 with b the slope at t1
    let b = d01 + c * (t1 - t0);
    f1 - b * b / (4.0 * c)
}

/// Run one impact with the exponential scheme on a fixed grid (canonical units).
pub fn run_exponential(
    prony: &Prony,
    grid: &Grid,
    capacity: usize,
    history: bool,
) -> Result<Outcome> {
    run_exponential_on(&Geometry::UNIT_SPHERE, prony, grid, capacity, history)
}

fn run_exponential_on(
    geometry: &Geometry,
    prony: &Prony,
    grid: &Grid,
    capacity: usize,
    history: bool,
) -> Result<Outcome> {
    let geom = Foundation::new(grid.dx, geometry, capacity);
    run_stepper(
        ExpFoundation::new(geom, prony),
        grid,
        capacity,
        history,
        &mut |_: &ExpFoundation, _: f64, _: f64| Ok(()),
    )
}

/// Run one impact with the exponential scheme on the element network of a general material
/// (built from `G` and `K`, not from `G_eq`) on a fixed grid (canonical units).
pub fn run_network<N: ElementModel>(
    network: &N,
    grid: &Grid,
    capacity: usize,
    history: bool,
) -> Result<Outcome> {
    run_network_on(&Geometry::UNIT_SPHERE, network, grid, capacity, history)
}

fn run_network_on<N: ElementModel>(
    geometry: &Geometry,
    network: &N,
    grid: &Grid,
    capacity: usize,
    history: bool,
) -> Result<Outcome> {
    let geom = Foundation::new(grid.dx, geometry, capacity);
    run_stepper(
        NetFoundation::new(geom, network.clone()),
        grid,
        capacity,
        history,
        &mut |_: &NetFoundation<N>, _: f64, _: f64| Ok(()),
    )
}

/// The exponential scheme's time loop over a foundation; `observe(f, dt, d)` sees the
/// foundation at the end of every step (step size `dt`, depth `d`) and never changes it.
fn run_stepper<F: Stepper>(
    mut f: F,
    grid: &Grid,
    capacity: usize,
    history: bool,
    observe: &mut dyn FnMut(&F, f64, f64) -> Result<()>,
) -> Result<Outcome> {
    let (mut t, mut d, mut v, mut force) = (0.0_f64, 0.0_f64, 1.0_f64, 0.0_f64);
    let mut hist = start_history(history);
    let mut tr = Tracker::default();
    let mut compression = true;
    let mut steps = 0u64;
    let t_end;
    loop {
        grid.check_budget(steps, "mdr time loop (contact did not end)")?;
        let dt = grid.dt(compression);
        f.set_step(dt);
        let mut aff = f.affine(d);
        let q = 0.25 * dt; // trapezoidal: r = v - dt (F_n + F_{n+1}) / (4 m)
        let solve_fixed = |aff: &exponential::Affine| (v - q * (force + aff.a)) / (1.0 + q * aff.b);
        let mut r = solve_fixed(&aff);
        let admit = compression && r > 0.0;
        if admit {
            r = solve_with_entering(&f, d, v, force, q, aff, r)?;
            if d + r * dt > f.geometry().g(capacity - 1) {
                return Err(Error::WorkLimit {
                    solver: "mdr",
                    what: "elements",
                    needed: capacity as u64 + 1,
                    limit: capacity as u64,
                });
            }
        }
        let mut ended_at = None;
        if r < 0.0 {
            // exits, outermost first, until the outermost element carries a non-negative force
            while let Some(fo) = f.outer_force(d, r) {
                if fo >= 0.0 {
                    break;
                }
                let start = f.outer_force_start(d);
                let sub = f.outer_affine(d);
                aff.a -= sub.a;
                aff.b -= sub.b;
                f.pop();
                compression = false;
                r = solve_fixed(&aff);
                if f.in_contact() == 0 {
                    ended_at = Some(t + dt * start / (start - fo));
                }
            }
        }
        f.commit(d, r, admit);
        let d1 = d + r * dt;
        let v1 = 2.0 * r - v;
        let f1 = f.force_now(d1);
        tr.sample_turn(t, dt, d, v, v1);
        if v1 <= 0.0 && compression {
            // past the turning point: the restitution step size from now on
            compression = false;
        }
        t += dt;
        steps += 1;
        d = d1;
        v = v1;
        force = f1;
        observe(&f, dt, d)?;
        tr.sample_force(t, force);
        if let Some(h) = hist.as_mut() {
            h.push(t, d, v, force, f.geometry().radius_of(f.in_contact()));
        }
        if let Some(te) = ended_at {
            t_end = te;
            break;
        }
        if !(d.is_finite() && v.is_finite() && force.is_finite()) {
            return Err(Error::NonFinite {
                what: "mdr state",
                value: d + v + force,
            });
        }
    }
    let (max_elements, element_updates) = f.counters();
    Ok(finish(
        Method::Mdr,
        f.geometry().shape(),
        v,
        t_end,
        &tr,
        hist,
        (steps, max_elements, element_updates),
    ))
}

/// Solve `phi(r) = r - v + q (F_n + F_{n+1}(r)) = 0` with entering elements: `phi` is
/// continuous and increasing, with a root in `(0, r_fixed]`. Safeguarded Newton.
fn solve_with_entering<F: Stepper>(
    f: &F,
    d: f64,
    v: f64,
    force: f64,
    q: f64,
    aff: exponential::Affine,
    r_fixed: f64,
) -> Result<f64> {
    let phi = |r: f64| {
        let (fe, dfe) = f.entering(d, r);
        (
            r - v + q * (force + aff.a + aff.b * r + fe),
            1.0 + q * (aff.b + dfe),
        )
    };
    let (mut lo, mut hi) = (0.0, r_fixed);
    let (p_hi, _) = phi(hi);
    if p_hi <= 0.0 {
        return Ok(hi);
    }
    let mut r = hi;
    for _ in 0..tolerances::ROOT_MAX_ITER {
        let (p, dp) = phi(r);
        if p > 0.0 {
            hi = r;
        } else {
            lo = r;
        }
        let mut next = r - p / dp;
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        if (next - r).abs() <= 1e-15 * r.abs().max(1e-300) || hi - lo <= 1e-15 * hi {
            return Ok(next);
        }
        r = next;
    }
    Err(Error::NoConvergence {
        what: "mdr implicit step with entering elements",
        iterations: tolerances::ROOT_MAX_ITER as u64,
    })
}

/// Run one impact with the paper's explicit Euler on a fixed grid (canonical units): the
/// standard solid's network of Eq. (8), or a general material's network from G and K with its
/// dashpot positions as states (two bodies' stacked networks are refused).
pub fn run_euler(
    material: &CanonicalMaterial,
    grid: &Grid,
    capacity: usize,
    history: bool,
) -> Result<Outcome> {
    if material.geometry != Geometry::UNIT_SPHERE {
        return Err(Error::NotSupported {
            solver: "mdr-euler",
            what: format!(
                "the indenter shape {:?}: the paper's explicit Euler runs the paraboloid only; \
                 use mdr, reference or auto",
                material.geometry
            ),
        });
    }
    let geom = Foundation::new(grid.dx, &material.geometry, capacity);
    match &material.network {
        Network::StandardSolid(n) => {
            euler_loop(EulerFoundation::new(geom, *n), grid, capacity, history)
        }
        Network::General(n) => euler_loop(
            EulerFoundation::new(geom, n.clone()),
            grid,
            capacity,
            history,
        ),
        Network::Stacked(_) => Err(euler_refusal()),
    }
}

fn euler_loop<N: euler::Dashpots>(
    mut f: EulerFoundation<N>,
    grid: &Grid,
    capacity: usize,
    history: bool,
) -> Result<Outcome> {
    let (mut t, mut d, mut v) = (0.0_f64, 0.0_f64, 1.0_f64);
    let mut hist = start_history(history);
    let mut tr = Tracker::default();
    let mut compression = true;
    let mut steps = 0u64;
    let t_end;
    loop {
        grid.check_budget(steps, "mdr-euler time loop (contact did not end)")?;
        let dt = grid.dt(compression);
        let force = f.force_and_advance(d, dt);
        let v1 = v - dt * force;
        let d1 = d + dt * v1;
        tr.sample_turn(t, dt, d, v, v1);
        let mut ended_at = None;
        if v1 > 0.0 && compression {
            f.admit(d1);
            if f.in_contact() == capacity {
                return Err(Error::WorkLimit {
                    solver: "mdr-euler",
                    what: "elements",
                    needed: capacity as u64 + 1,
                    limit: capacity as u64,
                });
            }
        } else {
            compression = false;
            // force of the outermost element at the start of the step, for the end-time estimate
            while let Some(fo) = f.outer_force(d1) {
                if fo >= 0.0 {
                    break;
                }
                f.pop();
                if f.in_contact() == 0 {
                    ended_at = Some(t + dt);
                }
            }
        }
        t += dt;
        steps += 1;
        d = d1;
        v = v1;
        let f1 = if ended_at.is_some() { 0.0 } else { f.force(d) };
        tr.sample_force(t, f1.max(force));
        if let Some(h) = hist.as_mut() {
            h.push(t, d, v, f1, f.geometry().radius_of(f.in_contact()));
        }
        if let Some(te) = ended_at {
            t_end = te;
            break;
        }
        if !(d.is_finite() && v.is_finite() && f1.is_finite()) || v.abs() > 1e6 {
            return Err(Error::NonFinite {
                what: "mdr-euler state (explicit Euler unstable)",
                value: v,
            });
        }
    }
    Ok(finish(
        Method::MdrEuler,
        f.geometry().shape(),
        v,
        t_end,
        &tr,
        hist,
        (steps, f.max_elements, f.element_updates),
    ))
}

fn finish(
    solver: Method,
    geometry: &Geometry,
    v_end: f64,
    t_end: f64,
    tr: &Tracker,
    history: Option<History>,
    (steps, elements, element_updates): (u64, usize, u64),
) -> Outcome {
    let cor = -v_end;
    Outcome {
        cor,
        rebound_velocity: -v_end,
        contact_time: t_end,
        max_indentation: tr.d_max,
        time_of_max_indentation: tr.t_max_d.unwrap_or(f64::NAN),
        max_force: tr.max_force,
        max_contact_radius: geometry.contact_radius(tr.d_max),
        dissipated_energy: 0.5 * (1.0 - cor * cor),
        cor_error_estimate: None,
        history,
        work: Work {
            steps,
            elements: elements as u64,
            element_updates,
            evaluations: 0,
            levels: 1,
            tight_checks: 0,
        },
        solver,
        fallback: None,
    }
}
