//! The tangential models of LAMMPS's `pair granular` / `fix wall/gran granular` with Mindlin
//! stiffness, integrated for one elastic sphere on a rigid wall, to compare their tangential
//! restitution with the MDR's partial slip (docs/dem.md, VALIDATION.md 1g).
//!
//! Both use the Hertz normal force `F_n = (4/3) E* sqrt(R) d^(3/2)` (elastic, no damping) and
//! the Mindlin stiffness `k_t = 8 G_eff a`, `a = sqrt(R d)`, `G_eff = G / (2 - nu)` for a rigid
//! wall (so `k_t = 2 a G*`, the MDR's full-stick stiffness), no tangential damping, and the
//! Coulomb limit `|F_t| <= mu F_n`:
//!
//! - [`DemTangential::Mindlin`] (`tangential mindlin`): the history is the accumulated
//!   tangential displacement `xi`, `F_t = -k_t(a) xi` with the current stiffness, `xi` rescaled
//!   to the Coulomb limit when the trial force exceeds it;
//! - [`DemTangential::MindlinForce`] (`tangential mindlin/force`): the history is the force,
//!   incremented by `-k_t dxi` and clipped to the Coulomb limit;
//! - [`DemTangential::MindlinRescale`] and [`DemTangential::MindlinRescaleForce`]
//!   (`mindlin_rescale`, `mindlin_rescale/force`): the same, but while the contact shrinks
//!   (`a` below the previous step's) the history is first scaled by `a / a_prev`.
//!
//! Velocity Verlet with `steps` steps over the Hertz contact time (the force model is explicit),
//! the order of LAMMPS's `nve/sphere` with its granular contacts: half kick, drift, history
//! update with the half-step slip velocity, force, half kick. The real codes run the same
//! bounce in `validation/dem_clients/oblique.py`; VALIDATION.md 1g compares both.

use crate::error::{check, Result};

/// Which LAMMPS tangential model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DemTangential {
    /// `tangential mindlin` (displacement history, current stiffness).
    Mindlin,
    /// `tangential mindlin/force` (incremental force history).
    MindlinForce,
    /// `tangential mindlin_rescale` (displacement history scaled down as the contact shrinks).
    MindlinRescale,
    /// `tangential mindlin_rescale/force` (force history scaled down as the contact shrinks).
    MindlinRescaleForce,
}

impl DemTangential {
    /// The LAMMPS keyword.
    pub fn keyword(self) -> &'static str {
        match self {
            DemTangential::Mindlin => "mindlin",
            DemTangential::MindlinForce => "mindlin/force",
            DemTangential::MindlinRescale => "mindlin_rescale",
            DemTangential::MindlinRescaleForce => "mindlin_rescale/force",
        }
    }

    /// Every model, in LAMMPS's order.
    pub const ALL: [DemTangential; 4] = [
        DemTangential::Mindlin,
        DemTangential::MindlinRescale,
        DemTangential::MindlinForce,
        DemTangential::MindlinRescaleForce,
    ];

    /// True when the history is the force (`/force`), false when it is the displacement.
    fn force_history(self) -> bool {
        matches!(
            self,
            DemTangential::MindlinForce | DemTangential::MindlinRescaleForce
        )
    }

    /// True when the history is scaled down as the contact shrinks (`_rescale`).
    fn rescales(self) -> bool {
        matches!(
            self,
            DemTangential::MindlinRescale | DemTangential::MindlinRescaleForce
        )
    }
}

/// An elastic sphere (mass `m` kg, radius `R` m, inertia factor `kappa`) of shear modulus `G`
/// (Pa) and Poisson ratio `nu` hitting a rigid wall at `v_n` (m/s) with the slip velocity
/// `v_c` (m/s) and friction `mu`: the tangential CoR `v_c' / v_c` of the DEM `model`.
#[allow(clippy::too_many_arguments)]
pub fn dem_tangential_cor(
    model: DemTangential,
    g: f64,
    nu: f64,
    mass: f64,
    radius: f64,
    kappa: f64,
    mu: f64,
    v_n: f64,
    v_c: f64,
    steps: usize,
) -> Result<f64> {
    check("g", g, g > 0.0, "0 < G < inf (Pa)")?;
    check("v_n", v_n, v_n > 0.0, "0 < v_n < inf (m/s)")?;
    let e_star = 2.0 * g / (1.0 - nu);
    let g_eff = g / (2.0 - nu);
    let kn = 4.0 / 3.0 * e_star * radius.sqrt();
    let lambda = 1.0 + 1.0 / kappa;
    // Hertz contact time
    let d_max = (15.0 * mass * v_n * v_n / (16.0 * e_star * radius.sqrt())).powf(0.4);
    let t_c = 2.943_275_184_324_704_7 * d_max / v_n;
    let dt = t_c / steps as f64;
    let (mut d, mut vn) = (0.0f64, v_n);
    let mut vc = v_c;
    // the history (displacement or force) and the previous step's contact radius
    let (mut hist, mut a_prev) = (0.0f64, 0.0f64);
    let mut forces = |d: f64, dxi: f64| -> (f64, f64) {
        if d <= 0.0 {
            (hist, a_prev) = (0.0, 0.0);
            return (0.0, 0.0);
        }
        let fn_ = kn * d.powf(1.5);
        let a = (radius * d).sqrt();
        let kt = 8.0 * g_eff * a;
        let lim = mu * fn_;
        if model.rescales() {
            if a < a_prev {
                hist *= a / a_prev;
            }
            a_prev = a;
        }
        if model.force_history() {
            hist += kt * dxi;
            if hist.abs() > lim {
                hist = lim.copysign(hist);
            }
            (fn_, hist)
        } else {
            hist += dxi;
            let trial = kt * hist;
            if trial.abs() > lim {
                hist = lim.copysign(trial) / kt;
            }
            (fn_, kt * hist)
        }
    };
    let (mut fnn, mut q) = (0.0, 0.0);
    let mut t = 0.0;
    let mut started = false;
    while t < 3.0 * t_c {
        // velocity Verlet: half kick, drift, forces, half kick (normal force pushes d back)
        vn -= 0.5 * dt * fnn / mass;
        vc -= 0.5 * dt * lambda * q / mass;
        d += dt * vn;
        let dxi = dt * vc;
        (fnn, q) = forces(d, dxi);
        vn -= 0.5 * dt * fnn / mass;
        vc -= 0.5 * dt * lambda * q / mass;
        t += dt;
        started |= d > 0.0;
        if started && d <= 0.0 {
            break;
        }
    }
    Ok(vc / v_c)
}
