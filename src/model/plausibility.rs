//! Is a scene plausible, or almost certainly a unit mistake? A 5 mm ball of 4.11 mg (a scene
//! written in mm, g and MPa) has a density of 0.0011 kg/m³ and still gives a believable CoR;
//! these checks say so. They are warnings, not refusals: an unusual but real input (a hollow
//! ball, an aerogel, a dense alloy) still gets its answer.
//!
//! The ranges are deliberately wide (about two decades beyond common engineering materials):
//! a sphere's density implied by its mass and radius in [`DENSITY_RANGE`] (kg/m³, from foams
//! to osmium and beyond), every modulus of a material in [`MODULUS_RANGE`] (Pa, from soft gels
//! to above diamond), and, when a material's density is given, an impact velocity below the
//! glassy shear wave speed `sqrt(G(0) / rho)`.

use crate::model::bodies::{Body, BodyMaterial};
use crate::model::impact::{Impact, Target};
use crate::model::material::Material;

/// Plausible densities of a solid sphere (kg/m³): below 100 is lighter than the lightest
/// solid foams used as impactors, above 25 000 denser than any element (osmium: 22 590).
pub const DENSITY_RANGE: (f64, f64) = (1.0e2, 2.5e4);

/// Plausible moduli of a solid (Pa): 1 kPa (soft hydrogels) to 1 TPa (diamond's shear modulus
/// is 0.5 TPa).
pub const MODULUS_RANGE: (f64, f64) = (1.0e3, 1.0e12);

/// The warnings of an impact's inputs, one sentence each (empty when everything is plausible).
pub fn warnings(impact: &Impact) -> Vec<String> {
    let mut out = Vec::new();
    let v0 = impact.velocity();
    match impact.target() {
        Target::HalfSpace(m) => {
            let s = impact.sphere();
            // an indenter without a radius (cone, power law, flat punch) implies no density
            if s.radius().is_finite() {
                density(&mut out, "the sphere", s.mass(), s.radius());
            }
            material(&mut out, "the material", m, v0);
        }
        Target::TwoBodies(b) => {
            for (name, body) in [("body A", b.a()), ("body B", b.b())] {
                body_warnings(&mut out, name, body, v0);
            }
        }
    }
    out
}

fn body_warnings(out: &mut Vec<String>, name: &str, body: &Body, v0: f64) {
    // a wall (infinite mass or radius) has no density to check
    if body.mass().is_finite() && body.radius().is_finite() {
        density(out, name, body.mass(), body.radius());
    }
    if let BodyMaterial::Viscoelastic(m) = body.material() {
        material(out, &format!("{name}'s material"), m, v0);
    }
}

/// The density of a solid sphere of mass `m` (kg) and radius `r` (m), kg/m³.
pub fn sphere_density(m: f64, r: f64) -> f64 {
    m / (4.0 / 3.0 * std::f64::consts::PI * r.powi(3))
}

fn density(out: &mut Vec<String>, name: &str, m: f64, r: f64) {
    let rho = sphere_density(m, r);
    let (lo, hi) = DENSITY_RANGE;
    if !(lo..=hi).contains(&rho) {
        let rho = if rho.is_finite() {
            format!("{rho:.3e}")
        } else {
            "above 1e308".to_string()
        };
        out.push(format!(
            "{name}: mass {m:.4e} kg and radius {r:.4e} m imply a density of {rho} kg/m^3, \
             outside {lo:.0}-{hi:.0} kg/m^3 of solids: check the units (kg and m, not g and mm)"
        ));
    }
}

fn material(out: &mut Vec<String>, name: &str, m: &Material, v0: f64) {
    let (lo, hi) = MODULUS_RANGE;
    let mut moduli = vec![
        ("relaxed shear modulus", m.g_inf()),
        ("glassy shear modulus", m.shear().glassy()),
    ];
    // a bulk computed from a Poisson ratio carries the units of the shear modulus, checked here,
    // and grows without bound towards 0.5 (nu = 0.4999999999 gives K = 5e15 Pa on purpose)
    if m.written_poisson().is_none() {
        moduli.extend([
            ("relaxed bulk modulus", m.bulk_relaxed()),
            ("glassy bulk modulus", m.bulk_glassy()),
        ]);
    }
    for (what, x) in moduli {
        // an incompressible bulk is infinite on purpose, and a liquid relaxes to zero
        if x.is_finite() && x != 0.0 && !(lo..=hi).contains(&x) {
            out.push(format!(
                "{name}: {what} {x:.3e} Pa is outside {lo:.0e}-{hi:.0e} Pa of solids: check the \
                 units (Pa, not MPa or GPa)"
            ));
        }
    }
    if let Some(rho) = m.density() {
        let c = (m.shear().glassy() / rho).sqrt();
        if v0 > c {
            out.push(format!(
                "{name}: impact velocity {v0:.3e} m/s exceeds its fastest shear wave speed \
                 sqrt(G(0)/rho) = {c:.3e} m/s: a quasi-static contact model cannot apply; check \
                 the units of velocity, moduli and density"
            ));
        }
    }
}
