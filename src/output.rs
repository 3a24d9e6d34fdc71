//! Writing results: atomic file writes, history CSV, the human-readable summary.

use std::io::Write;
use std::path::Path;

use crate::error::{Error, Result};
use crate::impact::{History, Impact, Outcome};

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

/// Human-readable summary of an impact and its outcome, with units.
pub fn summary(impact: &Impact, o: &Outcome) -> String {
    let m = impact.material();
    let g = impact.groups();
    let s = impact.sphere();
    let mut out = String::new();
    let mut line = |k: &str, v: String| out.push_str(&format!("{k:<28}{v}\n"));
    line(
        "sphere",
        format!("m = {:.6e} kg, R = {:.6e} m", s.mass(), s.radius()),
    );
    line("impact velocity", format!("{:.6e} m/s", impact.velocity()));
    line(
        "material",
        format!(
            "G_inf = {:.4e} Pa, G_1 = {:.4e} Pa, eta = {:.4e} Pa s, nu = {}",
            m.g_inf(),
            m.g_1(),
            m.eta(),
            if g.nu == 0.5 {
                "0.5 (incompressible)".to_string()
            } else {
                format!("{:.6}", g.nu)
            }
        ),
    );
    line(
        "groups (Eq. 11)",
        format!(
            "p1 = nu = {:.6}, p2 = {:.6e}, p3 = {:.6e}",
            g.nu, g.p2, g.p3
        ),
    );
    line("solver", o.solver.to_string());
    if let Some(why) = &o.fallback {
        line("  instead of fast", why.clone());
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
    out
}
