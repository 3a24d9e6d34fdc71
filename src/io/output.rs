//! Writing results: atomic file writes, history CSV, the human-readable summary.

use std::io::Write;
use std::path::{Path, PathBuf};

use crate::error::{Error, Result};
use crate::model::bodies::BodyMaterial;
use crate::model::geometry::Shape;
use crate::model::impact::{Groups, History, Impact, Method, Outcome, Target};
use crate::model::material::{Bulk, BulkRheology, Material, StandardSolid};
use crate::model::plausibility;
use crate::model::validity::Validity;
use crate::solvers::{SolveOptions, SolverKind};

/// Mode bits of a new output file before the umask: `0666 & !umask`, as `touch` or a shell
/// redirection would create it (a temporary file alone would be `0600`).
#[cfg(unix)]
const NEW_FILE_MODE: u32 = 0o666;

/// A temporary file in `dir` that becomes an output file: created with the usual permissions
/// (`0666` less the umask on Unix).
fn staged_file(dir: &Path) -> Result<tempfile::NamedTempFile> {
    let mut builder = tempfile::Builder::new();
    builder.prefix(".mdr-impact-");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(std::fs::Permissions::from_mode(NEW_FILE_MODE));
    }
    builder.tempfile_in(dir).map_err(|e| Error::io(dir, e))
}

/// Write a file atomically: the bytes go to a temporary file in the same directory, which is
/// renamed over `path` only when complete. Parent directories are created; the file gets the
/// usual permissions (`0666` less the umask). An existing `path` that is not a regular file (a
/// folder, device, FIFO or symbolic link) is refused, not replaced.
pub fn write_atomic(path: &Path, write: impl FnOnce(&mut dyn Write) -> Result<()>) -> Result<()> {
    let mut body = Vec::new();
    write(&mut body)?;
    write_outputs(&[OutputFile {
        key: "output".into(),
        path: path.to_path_buf(),
        bytes: body,
    }])
}

/// Write several files atomically ([`write_outputs`]), all or none, each named by the flag
/// `--out` in messages.
pub fn write_all_atomic(files: &[(&Path, &[u8])]) -> Result<()> {
    let list: Vec<OutputFile> = files
        .iter()
        .map(|(path, body)| OutputFile {
            key: "--out".into(),
            path: path.to_path_buf(),
            bytes: body.to_vec(),
        })
        .collect();
    write_outputs(&list)
}

/// One file a run writes: the key or flag that asked for it (e.g. `"[output] plot"`,
/// `"--out"`), its path and its contents.
#[derive(Debug, Clone, PartialEq)]
pub struct OutputFile {
    /// The scene key or flag, for messages.
    pub key: String,
    /// Where it goes.
    pub path: PathBuf,
    /// What it holds.
    pub bytes: Vec<u8>,
}

/// Write the files of one run, all or none. Before anything is written, every path is checked:
/// two files at the same path, an existing path that is not a regular file (a folder, device,
/// FIFO or symbolic link: refused rather than replaced) and a path below an existing file are
/// refused with [`Error::OutputPath`], naming the key and the path. The files are then staged as
/// temporary files beside their targets (created with the usual permissions) and renamed into
/// place; should any step fail, the staged files and the folders created for them are removed
/// again, so a failed run leaves none of its files (a rename that fails after others succeeded,
/// which needs the file system to change under the run, is the one exception).
pub fn write_outputs(files: &[OutputFile]) -> Result<()> {
    check_outputs(files)?;
    let mut created: Vec<PathBuf> = Vec::new();
    let result = stage_and_persist(files, &mut created);
    if result.is_err() {
        // deepest first: only folders this call created, and only when empty
        for dir in created.iter().rev() {
            let _ = std::fs::remove_dir(dir);
        }
    }
    result
}

fn stage_and_persist(files: &[OutputFile], created: &mut Vec<PathBuf>) -> Result<()> {
    let fail = |f: &OutputFile, reason: String| Error::OutputPath {
        key: f.key.clone(),
        path: f.path.display().to_string(),
        reason,
    };
    let mut staged = Vec::with_capacity(files.len());
    for f in files {
        let dir = folder_of(&f.path);
        create_folders(dir, created).map_err(|e| fail(f, format!("cannot create {e}")))?;
        let mut tmp = staged_file(dir).map_err(|e| fail(f, format!("cannot write in {e}")))?;
        tmp.as_file_mut()
            .write_all(&f.bytes)
            .and_then(|_| tmp.as_file_mut().flush())
            .map_err(|e| fail(f, e.to_string()))?;
        staged.push(tmp);
    }
    for (tmp, f) in staged.into_iter().zip(files) {
        tmp.persist(&f.path)
            .map_err(|e| fail(f, e.error.to_string()))?;
    }
    Ok(())
}

/// The folder a file goes into (`.` for a bare file name).
fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// Create `dir` and its missing ancestors, recording each folder created (outermost first).
fn create_folders(dir: &Path, created: &mut Vec<PathBuf>) -> Result<()> {
    let missing: Vec<&Path> = dir
        .ancestors()
        .take_while(|a| !a.as_os_str().is_empty() && std::fs::symlink_metadata(a).is_err())
        .collect();
    for d in missing.into_iter().rev() {
        match std::fs::create_dir(d) {
            Ok(()) => created.push(d.to_path_buf()),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {}
            Err(e) => return Err(Error::io(d, e)),
        }
    }
    Ok(())
}

/// The checks of [`write_outputs`], before anything is written.
fn check_outputs(files: &[OutputFile]) -> Result<()> {
    let refuse = |f: &OutputFile, reason: String| Error::OutputPath {
        key: f.key.clone(),
        path: f.path.display().to_string(),
        reason,
    };
    let mut seen: Vec<(PathBuf, &OutputFile)> = Vec::new();
    for f in files {
        if f.path.as_os_str().is_empty() {
            return Err(refuse(f, "an empty path: give a file name".into()));
        }
        // an ancestor that exists must be a folder (after following links, as the OS does)
        for a in f.path.ancestors().skip(1) {
            if a.as_os_str().is_empty() {
                break;
            }
            if let Ok(m) = std::fs::metadata(a) {
                if !m.is_dir() {
                    return Err(refuse(
                        f,
                        format!("{} is a file, not a folder", a.display()),
                    ));
                }
                break;
            }
        }
        if let Ok(m) = std::fs::symlink_metadata(&f.path) {
            let t = m.file_type();
            if !t.is_file() {
                let what = if t.is_symlink() {
                    "a symbolic link"
                } else if t.is_dir() {
                    "a folder"
                } else {
                    "not a regular file (a device, FIFO or socket)"
                };
                return Err(refuse(
                    f,
                    format!(
                        "exists and is {what}: refused rather than replaced; give another path"
                    ),
                ));
            }
        }
        let id = file_identity(&f.path);
        if let Some((_, first)) = seen.iter().find(|(p, _)| *p == id) {
            return Err(refuse(
                f,
                format!(
                    "the same file as {} = {}: one would overwrite the other; give two paths",
                    first.key,
                    first.path.display()
                ),
            ));
        }
        seen.push((id, f));
    }
    Ok(())
}

/// A path that is equal for two spellings of one file: the folder resolved by the file system
/// when it exists (links, `..`), else the path without `.` components, joined to the working
/// directory.
fn file_identity(path: &Path) -> PathBuf {
    let name = path.file_name().map(PathBuf::from).unwrap_or_default();
    let dir = folder_of(path);
    let dir = std::fs::canonicalize(dir).unwrap_or_else(|_| {
        let cwd = std::env::current_dir().unwrap_or_default();
        cwd.join(dir)
            .components()
            .filter(|c| !matches!(c, std::path::Component::CurDir))
            .collect()
    });
    dir.join(name)
}

/// Write a history as CSV with the header `t,d,v,force,a` (SI: s, m, m/s, N, m)
/// ([`history_csv_text`]).
pub fn write_history_csv(path: &Path, h: &History) -> Result<()> {
    let text = history_csv_text(h);
    write_atomic(path, |w| {
        w.write_all(text.as_bytes()).map_err(|e| Error::io(path, e))
    })
}

/// A history as CSV text with the header `t,d,v,force,a` (SI: s, m, m/s, N, m), full precision.
pub fn history_csv_text(h: &History) -> String {
    let mut out = String::from("t,d,v,force,a\n");
    for i in 0..h.len() {
        out.push_str(&format!(
            "{},{},{},{},{}\n",
            fmt(h.t[i]),
            fmt(h.d[i]),
            fmt(h.v[i]),
            fmt(h.force[i]),
            fmt(h.a[i])
        ));
    }
    out
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
/// For two bodies it lists both bodies and their velocities after the impact. `opts` are the
/// options it was solved with: the line under `solver` says why that solver answered
/// ([`solver_reason`]).
pub fn summary(impact: &Impact, opts: &SolveOptions, o: &Outcome) -> String {
    let s = impact.sphere();
    let mut out = String::new();
    let mut line = |k: &str, v: String| out.push_str(&format!("{k:<28}{v}\n"));
    let sphere = match impact.bodies() {
        Some(_) => "effective sphere",
        None => "sphere",
    };
    match impact.shape() {
        Shape::Paraboloid { .. } => line(
            sphere,
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
                "  (effective sphere:",
                "reduced mass and radius of the two bodies; velocity: relative)".to_string(),
            );
        }
    }
    let geq = impact.equivalent_relaxation();
    match impact.groups() {
        // p2 = g_inf / g_1 has no finite value without a relaxing branch (g_1 = 0): elastic
        Some(g) if !g.p2.is_finite() => line(
            "groups (Eq. 11)",
            format!(
                "p1 = nu = {:.6}, p2 unbounded (no relaxing branch: elastic), p3 = {:.6e}",
                g.nu, g.p3
            ),
        ),
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
    if impact.target().relaxes_to_zero() {
        line(
            "relaxed limits",
            "do not apply: g_inf = 0, a viscoelastic liquid (no groups of Eq. 11, no relaxed \
             Hertz limit)"
                .to_string(),
        );
    }
    line("solver", o.solver.to_string());
    if let Some(why) = solver_reason(opts, o) {
        let label = match opts.solver {
            SolverKind::Auto => "  chosen by auto",
            _ => "  why",
        };
        line(label, why);
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
    line("work", work_line(o));
    let v = Validity::of(impact, o);
    let mut measures = if impact.sphere().radius().is_finite() {
        format!(
            "a_max/R = {}, d_max/R = {}",
            crate::model::validity::ratio_text(v.contact_radius_ratio),
            crate::model::validity::ratio_text(v.indentation_ratio)
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
    for w in plausibility::warnings(impact).iter().chain(&v.warnings) {
        line("warning", w.clone());
    }
    out
}

/// The outcome as one JSON object (SI units, the keys of [`Outcome`]): `cor`,
/// `rebound_velocity` (m/s), `contact_time` (s), `max_indentation` (m),
/// `time_of_max_indentation` (s), `max_force` (N), `max_contact_radius` (m),
/// `dissipated_energy` (J), `solver`, `estimated_rel_error` (null when the solver gives none),
/// `fallback` (null when the refusal of `fast` did not make `auto` fall back; see
/// [`impact_json`] for the key with the solve's options) and `work` (`steps`, `elements`,
/// `element_updates`, `evaluations`, `levels`; a counter that does not apply to the solver is 0).
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
///
/// With the options `opts` it was solved with, `requested_solver` is the solver asked for,
/// `solver_reason` why the solver that answered did ([`solver_reason`], null when there is
/// nothing to say: the solver asked for answered) and `fallback` why `auto` did not answer with
/// `fast` (null when it did, or when another solver was asked for).
pub fn impact_json(impact: &Impact, opts: &SolveOptions, o: &Outcome) -> String {
    impact_value(impact, opts, o, true).to_string()
}

/// The object of [`impact_json`] (for callers that add keys to it).
pub fn impact_value_of(impact: &Impact, opts: &SolveOptions, o: &Outcome) -> serde_json::Value {
    impact_value(impact, opts, o, true)
}

/// The object of [`impact_json`]; `warnings` with the plausibility warnings of the inputs
/// ([`plausibility::warnings`]) first when `check_inputs` (not for canonical units, where a
/// sphere of `m = R = 1` has no plausible density).
fn impact_value(
    impact: &Impact,
    opts: &SolveOptions,
    o: &Outcome,
    check_inputs: bool,
) -> serde_json::Value {
    let mut v = value(o);
    let validity = Validity::of(impact, o);
    if let Some(map) = v.as_object_mut() {
        let reason = solver_reason(opts, o);
        map.insert("requested_solver".into(), opts.solver.name().into());
        map.insert("solver_reason".into(), serde_json::json!(reason));
        map.insert("fallback".into(), serde_json::json!(fallback(opts, o)));
        map.insert(
            "validity".into(),
            serde_json::json!({
                "contact_radius_ratio": validity.contact_radius_ratio,
                "indentation_ratio": validity.indentation_ratio,
                "sphere_force_excess": validity.sphere_force_excess,
                "wave_transit_ratio": validity.wave_transit_ratio,
            }),
        );
        let mut warnings = match check_inputs {
            true => plausibility::warnings(impact),
            false => Vec::new(),
        };
        warnings.extend(validity.warnings);
        map.insert("warnings".into(), serde_json::json!(warnings));
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
    v
}

/// The outcome of an impact given by its dimensionless groups (`mdr-impact cor --json`) as one
/// JSON object: `groups` (`nu`, `p2`, `p3`), `units` (`"canonical: m = R = v0 = G_inf = 1"`,
/// the units of every dimensional number in it) and the keys of [`impact_json`], with
/// `validity` null and `warnings` empty: the groups fix the CoR but not the size of the contact
/// (`a_max / R` grows as `(m v0^2 / (G_inf R^3))^(1/5)`, which the canonical units set to 1
/// and a physical impact with the same groups need not have), and the plausibility of the
/// inputs is meaningless in canonical units; `run` on a scene judges both. `groups` are the
/// groups as given (the impact's own are recomputed from its canonical moduli and may differ in
/// the last bit).
pub fn groups_json(groups: &Groups, impact: &Impact, opts: &SolveOptions, o: &Outcome) -> String {
    let mut v = impact_value(impact, opts, o, false);
    if let Some(map) = v.as_object_mut() {
        map.insert("validity".into(), serde_json::Value::Null);
        map.insert("warnings".into(), serde_json::json!([]));
        let g = groups;
        map.insert(
            "groups".into(),
            serde_json::json!({"nu": g.nu, "p2": g.p2, "p3": g.p3}),
        );
        map.insert("units".into(), "canonical: m = R = v0 = G_inf = 1".into());
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

/// Why the solver that answered did, in one line, or `None` when the solver asked for answered
/// as asked. `auto` ([`crate::solvers::Auto`]) answers with `fast` unless the material
/// is elastic (the Hertz closed form), an explicit resolution is given (`mdr`), a force history
/// is requested (`reference`, sampled uniformly) or `fast` refuses (`reference`, with the
/// refusal); any solver asked for an elastic material gives way to the Hertz closed form.
pub fn solver_reason(opts: &SolveOptions, o: &Outcome) -> Option<String> {
    if o.solver == Method::Hertz {
        return Some(
            "the material is elastic (no relaxation): the Hertz closed form is exact".into(),
        );
    }
    if opts.solver != SolverKind::Auto {
        return None;
    }
    if let Some(why) = o.fallback_reason() {
        return Some(format!("fast refused, reference answered: {why}"));
    }
    Some(match o.solver {
        Method::Fast => "no force history requested: fast, the cheapest solver, answered".into(),
        Method::Mdr if opts.resolution.is_some() => {
            "an explicit resolution ([solver] elements and steps) is for mdr".into()
        }
        Method::Reference if opts.history => {
            "a force history was requested (--out or [output]): reference samples it \
             uniformly (fast gives no history)"
                .into()
        }
        other => format!("auto answered with {other}"),
    })
}

/// JSON's `fallback`: why `auto` did not answer with `fast` ([`solver_reason`]), `None` when
/// it did or when another solver was asked for.
pub fn fallback(opts: &SolveOptions, o: &Outcome) -> Option<String> {
    let fell_back = opts.solver == SolverKind::Auto && o.solver != Method::Fast;
    solver_reason(opts, o).filter(|_| fell_back)
}

/// The work counters that mean something for the solver that answered: steps and evaluations
/// for `fast`; steps, evaluations and refinement levels for `reference`; steps, elements,
/// element updates and levels for `mdr` and `mdr-euler`; none for the Hertz closed form.
pub fn work_line(o: &Outcome) -> String {
    let w = &o.work;
    let plural = |n: u64, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
    let steps = plural(w.steps, "step", "steps");
    let evaluations = plural(w.evaluations, "evaluation", "evaluations");
    let levels = plural(u64::from(w.levels), "level", "levels");
    let parts = match o.solver {
        Method::Hertz => return "none (closed form)".into(),
        Method::Fast => vec![steps, evaluations],
        Method::Reference => vec![steps, evaluations, levels],
        Method::Mdr | Method::MdrEuler => vec![
            steps,
            plural(w.elements, "element", "elements"),
            plural(w.element_updates, "element update", "element updates"),
            levels,
        ],
    };
    parts.join(", ")
}
