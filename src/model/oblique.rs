//! Oblique impacts (docs/theory.md §14): Coulomb friction, the tangential velocity and the spin
//! of the impactor, and what the tangential problem needs from the model.
//!
//! # Sign conventions
//! `x` points along the surface in the direction of the incoming tangential velocity, `z` out
//! of the target towards the impactor, `y = z × x`. The spin `omega` (rad/s) is the angular
//! velocity about `y` (right-handed): a sphere rolling forward on the surface has
//! `omega = v_t / R > 0`. The contact point's tangential velocity (slip velocity) is
//! `v_c = v_t - R omega`; friction acts against it. The normal approach speed is `v_n > 0`
//! (`[impact] velocity`), the normal rebound speed `e v_n`.
//!
//! After the impact (tangential impulse `J`, along `+x` on the target, `-x` on the impactor):
//! `v_t' = v_t - J / m`, `omega' = omega + J / (kappa m R)` and
//! `v_c' = v_c - J (1 + 1 / kappa) / m` (`I = kappa m R^2`). For two bodies, `v_t` and `omega`
//! are those of body A (the first `[[body]]`) relative to body B at rest and not spinning;
//! the slip velocity is `v_c = v_t - R_A omega_A` and the impulse acts on both,
//! `v_c' = v_c - J ((1 + 1/kappa_A) / m_A + (1 + 1/kappa_B) / m_B)`, a body of infinite mass
//! dropping out.
//!
//! # Outputs
//! - `tangential_cor = v_c' / v_c` (negative: the contact point's velocity reversed);
//! - `tangential_cor_centre = v_t' / v_t` (relative centre velocity);
//! - `spin_after = omega'` (body A for two bodies);
//! - `rebound_angle_deg = atan(v_t' / (e v_n))` of the centre;
//! - `contact_patch_rebound_angle_deg = atan(v_c' / (e v_n))` (negative when reversed);
//! - `friction_dissipated_energy`: the work of the slip increments against the element forces.

use crate::error::{check, Error, Result};
use crate::model::bodies::TwoBodies;
use crate::model::impact::{Impact, Target};
use crate::model::material::{carson, Material, Prony};

/// The default inertia factor `kappa = I / (m R^2)` of a solid sphere.
pub const SOLID_SPHERE: f64 = 0.4;

/// The tangential inputs of an impact (SI; module docs for the conventions).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oblique {
    /// Coulomb friction coefficient `mu >= 0` (0: frictionless).
    pub friction: f64,
    /// Tangential velocity of the centre before contact, `v_t` (m/s), relative to body B for
    /// two bodies.
    pub tangential_velocity: f64,
    /// Spin `omega` (rad/s) before contact (body A for two bodies).
    pub spin: f64,
    /// Inertia factor of the impactor (body A): `I = kappa m R^2`, `0 < kappa <= 1`.
    pub inertia: f64,
    /// Inertia factor of body B (unused on a half-space).
    pub inertia_b: f64,
}

impl Default for Oblique {
    fn default() -> Self {
        Self {
            friction: 0.0,
            tangential_velocity: 0.0,
            spin: 0.0,
            inertia: SOLID_SPHERE,
            inertia_b: SOLID_SPHERE,
        }
    }
}

/// Validate an inertia factor `0 < kappa <= 1` (a body within its radius has `I <= m R^2`).
pub fn inertia_factor(field: &'static str, kappa: f64) -> Result<f64> {
    check(
        field,
        kappa,
        kappa > 0.0 && kappa <= 1.0,
        "0 < inertia_factor <= 1 (I = factor m R^2; 0.4 a solid sphere)",
    )
}

impl Oblique {
    /// Validated tangential inputs: `0 <= friction < inf`, finite velocity and spin, inertia
    /// factors in `(0, 1]`.
    pub fn new(
        friction: f64,
        tangential_velocity: f64,
        spin: f64,
        inertia: f64,
        inertia_b: f64,
    ) -> Result<Self> {
        Ok(Self {
            friction: check(
                "coefficient",
                friction,
                friction >= 0.0,
                "0 <= [friction] coefficient < inf",
            )?,
            tangential_velocity: check(
                "tangential_velocity",
                tangential_velocity,
                true,
                "finite (m/s)",
            )?,
            spin: check("spin", spin, true, "finite (rad/s)")?,
            inertia: inertia_factor("inertia_factor", inertia)?,
            inertia_b: inertia_factor("inertia_factor", inertia_b)?,
        })
    }

    /// True when the tangential problem is trivial: no friction or no slip velocity and no
    /// spin (the normal impact is then the whole answer, bit for bit).
    pub fn is_trivial(&self) -> bool {
        self.friction == 0.0 || (self.tangential_velocity == 0.0 && self.spin == 0.0)
    }

    /// True when any tangential input is given (outputs then include the tangential ones).
    pub fn is_oblique(&self) -> bool {
        self.tangential_velocity != 0.0 || self.spin != 0.0
    }
}

/// The tangential problem of an impact in canonical units (`m = v0 = 1`, the indentation scale
/// `L` for the tangential displacement, forces in `m v0^2 / L`).
#[derive(Debug, Clone, PartialEq)]
pub struct Tangential {
    /// `G_t / 4` (moduli over `G_inf`, times over `L / v0`).
    pub g_t: Prony,
    /// Coulomb coefficient.
    pub friction: f64,
    /// Initial slip velocity `v_c / v0`.
    pub slip_velocity: f64,
    /// Tangential compliance of the motion over that of the normal one, `lambda = m / m_t`:
    /// `1 + 1/kappa` for one sphere (module docs).
    pub compliance: f64,
}

/// Radius of the impactor (body A) that carries the spin, its mass and inertia factor.
fn spinning(impact: &Impact, o: &Oblique) -> (f64, f64, f64) {
    match impact.bodies() {
        Some(b) => (b.a().radius(), b.a().mass(), o.inertia),
        None => (impact.sphere().radius(), impact.sphere().mass(), o.inertia),
    }
}

/// `lambda = m_eff ((1 + 1/kappa_A)/m_A + (1 + 1/kappa_B)/m_B)`, an infinite mass dropping out.
fn compliance(impact: &Impact, o: &Oblique) -> f64 {
    match impact.bodies() {
        None => 1.0 + 1.0 / o.inertia,
        Some(b) => {
            let m = b.effective_mass();
            let part = |mass: f64, kappa: f64| {
                if mass.is_infinite() {
                    0.0
                } else {
                    m / mass * (1.0 + 1.0 / kappa)
                }
            };
            part(b.a().mass(), o.inertia) + part(b.b().mass(), o.inertia_b)
        }
    }
}

/// `G_t / 4` of the impact in SI (Pa, s): the half-space's ([`carson::tangential_relaxation`]),
/// or two bodies' in series (`1/G_t = 1/G_t,A + 1/G_t,B` in Carson form, [`carson::combine`];
/// Goodman's uncoupling: the normal and tangential problems are solved as if decoupled, exact
/// for similar materials, an approximation for dissimilar ones).
pub fn tangential_relaxation(impact: &Impact) -> Result<Prony> {
    match impact.target() {
        Target::HalfSpace(m) => carson::tangential_relaxation(m),
        Target::TwoBodies(b) => bodies_tangential(b),
    }
}

fn bodies_tangential(b: &TwoBodies) -> Result<Prony> {
    let one = |m: Option<&Material>| m.map(carson::tangential_relaxation).transpose();
    match (
        one(b.a().material().material())?,
        one(b.b().material().material())?,
    ) {
        (Some(x), Some(y)) => carson::combine(&x, &y),
        (Some(x), None) | (None, Some(x)) => Ok(x),
        (None, None) => Err(Error::Internal(
            "two rigid bodies have no tangential modulus",
        )),
    }
}

impl Oblique {
    /// The canonical tangential problem of `impact` with these inputs. An impactor without a
    /// radius (a cone or power-law `[indenter]`) is refused when it has spin
    /// ([`Error::NotSupported`]).
    pub fn tangential(&self, impact: &Impact) -> Result<Tangential> {
        let (radius, _, _) = spinning(impact, self);
        if !radius.is_finite() && self.spin != 0.0 {
            return Err(Error::NotSupported {
                solver: "oblique impact",
                what: "spin needs an impactor with a radius ([sphere] or [[body]])".into(),
            });
        }
        let s = impact.scales();
        let spin_part = if self.spin == 0.0 {
            0.0
        } else {
            radius * self.spin
        };
        Ok(Tangential {
            g_t: tangential_relaxation(impact)?.scaled(s.modulus, s.time),
            friction: self.friction,
            slip_velocity: (self.tangential_velocity - spin_part) / s.velocity,
            compliance: compliance(impact, self),
        })
    }

    /// The tangential outputs (SI) from the normal CoR `cor`, the tangential impulse `impulse`
    /// (canonical: units of `m v0`) and the friction work `friction_work` (canonical: `m v0^2`).
    pub fn outputs(
        &self,
        impact: &Impact,
        cor: f64,
        impulse: f64,
        friction_work: f64,
    ) -> TangentialOutcome {
        let s = impact.scales();
        let (radius, mass, kappa) = spinning(impact, self);
        // the impulse in SI, on the effective mass
        let m_eff = impact.sphere().mass();
        let j = impulse * m_eff * s.velocity;
        let lambda = compliance(impact, self);
        let vc0 = self.tangential_velocity
            - if self.spin == 0.0 {
                0.0
            } else {
                radius * self.spin
            };
        let vc1 = vc0 - j * lambda / m_eff;
        // the centres: relative velocity changes by J (1/m_A + 1/m_B) = J / m_eff
        let vt1 = self.tangential_velocity - j / m_eff;
        let spin_after = if radius.is_finite() && mass.is_finite() {
            self.spin + j / (kappa * mass * radius)
        } else {
            self.spin
        };
        let vn1 = cor * s.velocity;
        let angle = |v: f64| v.atan2(vn1).to_degrees();
        let ratio = |a: f64, b: f64| if b == 0.0 { f64::NAN } else { a / b };
        TangentialOutcome {
            tangential_cor: ratio(vc1, vc0),
            tangential_cor_centre: ratio(vt1, self.tangential_velocity),
            spin_after,
            rebound_angle_deg: angle(vt1),
            contact_patch_rebound_angle_deg: angle(vc1),
            friction_dissipated_energy: friction_work * s.energy,
            impulse: j,
            slip_velocity_after: vc1,
            tangential_velocity_after: vt1,
        }
    }
}

/// The tangential results of an oblique impact (SI; module docs for the conventions). A ratio
/// whose initial velocity is zero is `NaN` (undefined), printed as `null` in JSON.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TangentialOutcome {
    /// `v_c' / v_c`.
    pub tangential_cor: f64,
    /// `v_t' / v_t`.
    pub tangential_cor_centre: f64,
    /// `omega'` (rad/s).
    pub spin_after: f64,
    /// `atan(v_t' / (e v_n))` (degrees).
    pub rebound_angle_deg: f64,
    /// `atan(v_c' / (e v_n))` (degrees).
    pub contact_patch_rebound_angle_deg: f64,
    /// Work of friction (J).
    pub friction_dissipated_energy: f64,
    /// Tangential impulse on the target, `J` (N s).
    pub impulse: f64,
    /// Slip velocity after, `v_c'` (m/s).
    pub slip_velocity_after: f64,
    /// Centre tangential velocity after, `v_t'` (m/s).
    pub tangential_velocity_after: f64,
}

/// Histories of the tangential problem (SI), sampled at the normal solver's steps.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TangentialHistory {
    /// Time (s).
    pub t: Vec<f64>,
    /// Tangential force on the target (N).
    pub force: Vec<f64>,
    /// Inner radius of the slip zone (m): the elements inside it stick, those from it to the
    /// contact radius slide (0: gross slip; the contact radius: full stick).
    pub slip_radius: Vec<f64>,
    /// Slip velocity `v_c` (m/s).
    pub slip_velocity: Vec<f64>,
}
