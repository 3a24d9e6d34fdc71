//! Writing results: atomic file writes, history CSV, the human-readable summary.

use std::io::Write;
use std::path::Path;

use crate::error::{Error, Result};
use crate::model::bodies::BodyMaterial;
use crate::model::geometry::Shape;
use crate::model::impact::{History, Impact, Outcome, Target};
use crate::model::material::{Bulk, BulkRheology, Material, StandardSolid};
use crate::model::validity::Validity;

/// Write a file atomically: the bytes go to a temporary file in the same directory, which is
/// renamed over `path` only when complete. Parent directories are created.
pub fn write_atomic(path: &Path, write: impl FnOnce(&mut dyn Write) -> Result<()>) -> Result<()> {
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let mut tmp = tempfile::NamedTempFile::new_in(dir).map_err(|e| Error::io(dir, e))?;
    {
        let mut buf = std::io::BufWriter::new(tmp.as_file_mut());
        write(&mut buf)?;
        buf.flush().map_err(|e| Error::io(path, e))?;
    }
    tmp.persist(path).map_err(|e| Error::io(path, e.error))?;
    Ok(())
}

/// Write several files atomically ([`write_atomic`]), all or none: when one fails, the ones
/// already written by this call are removed again.
pub fn write_all_atomic(files: &[(&Path, &[u8])]) -> Result<()> {
    for (k, (path, body)) in files.iter().enumerate() {
        if let Err(e) = write_atomic(path, |w| w.write_all(body).map_err(|e| Error::io(path, e))) {
            for (done, _) in &files[..k] {
                let _ = std::fs::remove_file(done);
            }
            return Err(e);
        }
    }
    Ok(())
}

/// Write a history as CSV with the header `t,d,v,force,a` (SI: s, m, m/s, N, m).
pub fn write_history_csv(path: &Path, h: &History) -> Result<()> {
    write_atomic(path, |w| {
        let mut c = csv::Writer::from_writer(w);
        let io = |e: csv::Error| Error::io(path, e);
        c.write_record(["t", "d", "v", "force", "a"]).map_err(io)?;
        for i in 0..h.len() {
            c.write_record(&[
                fmt(h.t[i]),
                fmt(h.d[i]),
                fmt(h.v[i]),
                fmt(h.force[i]),
                fmt(h.a[i]),
            ])
            .map_err(io)?;
        }
        c.flush().map_err(|e| Error::io(path, e))?;
        Ok(())
    })
}

/// Full-precision, round-trip formatting of an `f64` for CSV.
pub fn fmt(x: f64) -> String {
    format!("{x:e}")
}

/// One line describing a material as it was written: a standard solid by its parameters, any
/// other by its terms.
fn material(m: &Material) -> String {
    match m.as_standard_solid() {
        Some(s) if m.is_written_as_standard_solid() => standard_solid(&s),
        _ => general(m),
    }
}

/// One line describing a standard solid.
fn standard_solid(m: &StandardSolid) -> String {
    let nu = if m.bulk() == Bulk::Incompressible {
        0.5
    } else {
        m.poisson()
    };
    format!(
        "G_inf = {:.4e} Pa, G_1 = {:.4e} Pa, eta = {:.4e} Pa s, nu = {}",
        m.g_inf(),
        m.g_1(),
        m.eta(),
        if nu == 0.5 {
            "0.5 (incompressible)".to_string()
        } else {
            format!("{nu:.6}")
        }
    )
}

/// One line describing a general material.
fn general(m: &Material) -> String {
    let shear = m.shear();
    let bulk = match m.bulk() {
        BulkRheology::Incompressible => "incompressible".to_string(),
        BulkRheology::Elastic(k) => format!("elastic, K_0 = {k:.4e} Pa"),
        BulkRheology::Prony(p) => format!(
            "{} term{}, k_inf = {:.4e} Pa",
            p.terms().len(),
            if p.terms().len() == 1 { "" } else { "s" },
            p.k_inf()
        ),
    };
    format!(
        "general: {} shear term{}, g_inf = {:.4e} Pa; bulk {bulk}",
        shear.terms().len(),
        if shear.terms().len() == 1 { "" } else { "s" },
        shear.g_inf()
    )
}

/// Human-readable summary of an impact and its outcome, with units.
///
/// The line of dimensionless groups (Eq. 11) is printed for the standard solid only; a general
/// material is described by its number of shear and bulk terms, `g_inf` and the glassy and
/// relaxed `G_eq`.
/// For two bodies it lists both bodies and their velocities after the impact.
pub fn summary(impact: &Impact, o: &Outcome) -> String {
    let s = impact.sphere();
    let mut out = String::new();
    let mut line = |k: &str, v: String| out.push_str(&format!("{k:<28}{v}\n"));
    match impact.shape() {
        Shape::Paraboloid { .. } => line(
            "sphere",
            format!("m = {:.6e} kg, R = {:.6e} m", s.mass(), s.radius()),
        ),
        shape => line(
            "indenter",
            format!("m = {:.6e} kg, {}", s.mass(), shape.describe()),
        ),
    }
    line("impact velocity", format!("{:.6e} m/s", impact.velocity()));
    match impact.target() {
        Target::HalfSpace(m) => line("material", material(m)),
        Target::TwoBodies(b) => {
            for (name, body) in [("body A", b.a()), ("body B", b.b())] {
                line(
                    name,
                    format!(
                        "m = {:.6e} kg, R = {:.6e} m; {}",
                        body.mass(),
                        body.radius(),
                        match body.material() {
                            BodyMaterial::Rigid => "rigid".to_string(),
                            BodyMaterial::Viscoelastic(m) => material(m),
                        }
                    ),
                );
            }
            line(
                "  (sphere above:",
                "effective mass and radius; velocity: relative)".to_string(),
            );
        }
    }
    let geq = impact.equivalent_relaxation();
    match impact.groups() {
        Some(g) => line(
            "groups (Eq. 11)",
            format!(
                "p1 = nu = {:.6}, p2 = {:.6e}, p3 = {:.6e}",
                g.nu, g.p2, g.p3
            ),
        ),
        None => line(
            "G_eq (docs/theory.md §8)",
            format!(
                "{} terms, glassy {:.6e} Pa, relaxed {:.6e} Pa",
                geq.terms.len(),
                geq.glassy(),
                geq.relaxed
            ),
        ),
    }
    line("solver", o.solver.to_string());
    if let Some(why) = &o.fallback {
        line("  instead of fast", why.to_string());
    }
    line("coefficient of restitution", format!("{:.9}", o.cor));
    if let Some(est) = o.cor_error_estimate {
        // every solver's estimate is at most the requested rtol on success (see README)
        line("  estimated rel. error", format!("{est:.1e}"));
    }
    line(
        "rebound velocity",
        format!("{:.6e} m/s", o.rebound_velocity),
    );
    if let Some(b) = impact.bodies() {
        let (va, vb) = b.rebound_velocities(impact.velocity(), o.cor);
        line(
            "  body velocities after",
            format!("A {va:.6e} m/s, B {vb:.6e} m/s (B at rest before)"),
        );
    }
    line("contact time", format!("{:.6e} s", o.contact_time));
    line("max indentation", format!("{:.6e} m", o.max_indentation));
    line(
        "time of max indentation",
        format!("{:.6e} s", o.time_of_max_indentation),
    );
    line("max force", format!("{:.6e} N", o.max_force));
    line(
        "max contact radius",
        format!("{:.6e} m", o.max_contact_radius),
    );
    line(
        "dissipated energy",
        format!("{:.6e} J", o.dissipated_energy),
    );
    line(
        "work",
        format!(
            "{} steps, {} elements, {} element updates, {} evaluations, {} levels",
            o.work.steps,
            o.work.elements,
            o.work.element_updates,
            o.work.evaluations,
            o.work.levels
        ),
    );
    let v = Validity::of(impact, o);
    let mut measures = if impact.sphere().radius().is_finite() {
        format!(
            "a_max/R = {:.3}, d_max/R = {:.3}",
            v.contact_radius_ratio, v.indentation_ratio
        )
    } else {
        format!(
            "no radius of curvature to compare with ({})",
            impact.shape().name()
        )
    };
    if let Some(w) = v.wave_transit_ratio {
        measures.push_str(&format!(", wave transit / contact time = {w:.2e}"));
    }
    line("validity", measures);
    for w in &v.warnings {
        line("warning", w.clone());
    }
    out
}

/// The outcome as one JSON object (SI units, the keys of [`Outcome`]): `cor`,
/// `rebound_velocity` (m/s), `contact_time` (s), `max_indentation` (m),
/// `time_of_max_indentation` (s), `max_force` (N), `max_contact_radius` (m),
/// `dissipated_energy` (J), `solver`, `estimated_rel_error` (null when the solver gives none),
/// `fallback` (null, or why `auto` did not answer with `fast`) and `work`
/// (`steps`, `elements`, `element_updates`, `evaluations`, `levels`).
pub fn json(o: &Outcome) -> String {
    value(o).to_string()
}

/// [`json`] of an impact's outcome, with `validity` (`contact_radius_ratio` a_max/R,
/// `indentation_ratio` d_max/R, `sphere_force_excess` (the exact sphere's extra force at a_max,
/// relative), `wave_transit_ratio` (null without a density); [`Validity`]) and `warnings` (an
/// array of strings, empty when the model applies); for a two-body collision with the key `bodies`
/// (`{"a": {"rebound_velocity": ..}, "b": {..}}`, m/s, positive in A's approach direction, in
/// the frame where B was at rest before the impact; see
/// [`crate::model::bodies::TwoBodies::rebound_velocities`]); `max_indentation` is then the total
/// compression of the two bodies.
pub fn impact_json(impact: &Impact, o: &Outcome) -> String {
    let mut v = value(o);
    let validity = Validity::of(impact, o);
    if let Some(map) = v.as_object_mut() {
        map.insert(
            "validity".into(),
            serde_json::json!({
                "contact_radius_ratio": validity.contact_radius_ratio,
                "indentation_ratio": validity.indentation_ratio,
                "sphere_force_excess": validity.sphere_force_excess,
                "wave_transit_ratio": validity.wave_transit_ratio,
            }),
        );
        map.insert("warnings".into(), serde_json::json!(validity.warnings));
        map.insert("shape".into(), serde_json::json!(impact.shape().name()));
    }
    if let (Some(b), Some(map)) = (impact.bodies(), v.as_object_mut()) {
        let (va, vb) = b.rebound_velocities(impact.velocity(), o.cor);
        map.insert(
            "bodies".into(),
            serde_json::json!({
                "a": {"rebound_velocity": va},
                "b": {"rebound_velocity": vb},
            }),
        );
    }
    v.to_string()
}

fn value(o: &Outcome) -> serde_json::Value {
    serde_json::json!({
        "cor": o.cor,
        "rebound_velocity": o.rebound_velocity,
        "contact_time": o.contact_time,
        "max_indentation": o.max_indentation,
        "time_of_max_indentation": o.time_of_max_indentation,
        "max_force": o.max_force,
        "max_contact_radius": o.max_contact_radius,
        "dissipated_energy": o.dissipated_energy,
        "solver": o.solver.name(),
        "estimated_rel_error": o.cor_error_estimate,
        "fallback": o.fallback.as_ref().map(|e| e.to_string()),
        "work": {
            "steps": o.work.steps,
            "elements": o.work.elements,
            "element_updates": o.work.element_updates,
            "evaluations": o.work.evaluations,
            "levels": o.work.levels,
        },
    })
}
