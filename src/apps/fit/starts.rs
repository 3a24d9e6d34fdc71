//! The starting values of the fit (module docs of `fit`): the Hertz modulus the contact times
//! point to, the scale of the group `p3`, and the candidates over the box.

use super::*;

/// The Hertz shear modulus (Pa, incompressible) that gives contact time `t_c` (s) at `v0` for
/// `sphere` (docs/theory.md §6: `t_c = 2.943 d_max / v0`, `d_max = (5 m v0^2 / (4 k))^(2/5)`,
/// `k = (16/3) G sqrt(R)`).
pub fn hertz_modulus(sphere: impl Into<data::Impactor>, v0: f64, t_c: f64) -> f64 {
    let sphere = sphere.into();
    let d_max = t_c * v0 / (2.0 * crate::model::hertz::HERTZ_I);
    let k = 5.0 * sphere.sphere.mass() * v0 * v0 / (4.0 * d_max.powf(2.5));
    3.0 * k / (16.0 * sphere.start_radius(v0).sqrt())
}

/// `p3 / (eta / g_inf^(3/5)) = (v R / m^2)^(1/5)` at the data's mean velocity (geometric) and
/// the first drop's sphere.
pub(super) fn p3_scale(data: &Data) -> f64 {
    let n = data.observations.len().max(1) as f64;
    let v_ref = (data.observations.iter().map(|o| o.v0.ln()).sum::<f64>() / n).exp();
    let sphere = data.setups[data.observations.first().map_or(0, |o| o.setup)].sphere;
    let (m, r) = (sphere.sphere.mass(), sphere.start_radius(v_ref));
    (v_ref * r / (m * m)).powf(0.2)
}

/// Starting values over the sensible box (see the module docs), with the fixed values kept,
/// each once.
pub(super) fn candidates(
    model: &Model,
    data: &Data,
    fixed: &[Option<f64>],
    hold: bool,
) -> Vec<Vec<f64>> {
    let n = data.observations.len() as f64;
    let v_ref = (data.observations.iter().map(|o| o.v0.ln()).sum::<f64>() / n).exp();
    let sphere = data.setups[data.observations[0].setup].sphere;
    let (m, r) = (sphere.sphere.mass(), sphere.start_radius(v_ref));
    let hertz: Vec<f64> = data
        .observations
        .iter()
        .filter_map(|o| {
            o.contact_time
                .map(|t| hertz_modulus(data.setups[o.setup].sphere, o.v0, t))
        })
        .collect();
    let g_levels: Vec<f64> = if hertz.is_empty() || hold {
        vec![COR_ONLY_REFERENCE_MODULUS]
    } else {
        let g_h = (hertz.iter().map(|g| g.ln()).sum::<f64>() / hertz.len() as f64).exp();
        [1e-3, 1e-2, 1e-1, 1.0].iter().map(|f| f * g_h).collect()
    };
    let p2s = [1e-4, 1e-3, 1e-2, 3e-2, 1e-1, 3e-1, 1.0];
    let p3s = [0.03, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 300.0];
    // denser towards 0.5, where the bulk-to-shear ratio 2 (1 + nu) / (3 (1 - 2 nu)) changes
    // fastest: a basin between 0.45 and 0.49 (or 0.3 and 0.45) was missed with coarser levels
    let nus = [-0.5, 0.0, 0.3, 0.4, 0.45, 0.47, 0.48, 0.49];
    let mut out = Vec::new();
    for &g in &g_levels {
        for &p2 in &p2s {
            for &p3 in &p3s {
                for &nu in &nus {
                    let mut v = vec![0.0; model.params.len()];
                    let fixed_of = |p: Parameter| model.slot(p).and_then(|i| fixed[i]);
                    let standard = model.kind == ModelKind::StandardSolid;
                    // g_inf from the fixed value, a fixed g_1 (p2), a fixed eta (p3), or the grid
                    let g_inf = match (fixed_of(Parameter::GInf), fixed_of(Parameter::G1)) {
                        (Some(g), _) => g,
                        (None, Some(g1)) if standard => p2 * g1,
                        _ => match fixed_of(Parameter::Eta) {
                            Some(eta) if standard => {
                                ((eta / p3).powi(5) * v_ref * r / (m * m)).cbrt()
                            }
                            _ => g,
                        },
                    };
                    model.set(&mut v, Parameter::GInf, g_inf);
                    let eta = p3 * (m * m * g_inf.powi(3) / (v_ref * r)).powf(0.2);
                    match model.kind {
                        ModelKind::StandardSolid => {
                            model.set(&mut v, Parameter::G1, g_inf / p2);
                            model.set(&mut v, Parameter::Eta, eta);
                        }
                        ModelKind::Prony { n } => {
                            // equal moduli summing to g_inf / p2 (the times are fixed: p3 unused)
                            if p3 != p3s[0] {
                                continue;
                            }
                            for i in 1..=n {
                                model.set(&mut v, Parameter::Term(i), g_inf / p2 / n as f64);
                            }
                        }
                    }
                    model.set(&mut v, Parameter::Nu, nu);
                    for (x, f) in v.iter_mut().zip(fixed) {
                        if let Some(f) = f {
                            *x = *f;
                        }
                    }
                    // fixed values make grid points coincide (every nu level with nu fixed)
                    if !out.contains(&v) {
                        out.push(v);
                    }
                }
            }
        }
    }
    out
}
