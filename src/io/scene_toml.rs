//! A validated [`Scene`] written back as scene TOML ([`Scene::to_toml`]), so that a scene built
//! in code (or by the Python package) can be saved and read again by `mdr-impact run`.
//!
//! The text is in the validated form, with the bulk as it was given: an elastic bulk given by a
//! Poisson ratio is written as `poisson` (the ratio given, [`Material::written_poisson`]), one
//! given as a modulus with `k_0`, an incompressible one as `poisson = 0.5` (standard solid) or
//! `incompressible = true`; a general material with `g_inf` and `terms` (a Prony table `file` or
//! the normalised FE form are written as the terms they were turned into), a body given by its
//! density with its `mass`. Numbers are written in Rust's shortest round-trip form, so
//! [`Scene::parse`] of the text gives back a scene equal to the original (`==`), bit for bit.

use std::fmt::Write;

use crate::io::scene::Scene;
use crate::model::bodies::{Body, BodyMaterial};
use crate::model::geometry::Shape;
use crate::model::impact::Target;
use crate::model::material::{Bulk, BulkRheology, Material, StandardSolid};
use crate::model::oblique::SOLID_SPHERE;

/// An `f64` as a TOML float: shortest round-trip digits, always with a `.` or an exponent
/// (`1.0`, `5e-3`, `inf`).
fn num(x: f64) -> String {
    // `{:?}` prints `1.0`, `0.005`, `1e-7`, `inf`: all valid TOML floats
    format!("{x:?}")
}

/// `[[modulus, time], ...]` on one line.
fn pairs(terms: &[(f64, f64)]) -> String {
    let inner: Vec<String> = terms
        .iter()
        .map(|&(g, t)| format!("[{}, {}]", num(g), num(t)))
        .collect();
    format!("[{}]", inner.join(", "))
}

/// A TOML basic string (paths): quotes, backslashes and control characters escaped.
fn string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if c.is_control() => {
                let _ = write!(out, "\\u{:04X}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// The keys of a material as it was written, in the table `table` (`material` or
/// `body.material`): a standard solid's parameters, or the shear and bulk tables.
fn material(out: &mut String, table: &str, m: &Material) {
    match m.as_standard_solid() {
        Some(s) if m.is_written_as_standard_solid() => {
            standard_solid(out, table, &s, m.written_poisson())
        }
        _ => general(out, table, m),
    }
}

/// The keys of a standard solid, in the table `table` (`material` or `body.material`); an
/// elastic bulk as the Poisson ratio `poisson` it was computed from, when given.
fn standard_solid(out: &mut String, table: &str, m: &StandardSolid, poisson: Option<f64>) {
    let _ = writeln!(out, "[{table}]");
    let _ = writeln!(out, "g_inf = {}       # Pa", num(m.g_inf()));
    let _ = writeln!(out, "g_1 = {}         # Pa", num(m.g_1()));
    let _ = writeln!(out, "eta = {}         # Pa s", num(m.eta()));
    match (m.bulk(), poisson) {
        (Bulk::Modulus(_), Some(nu)) => {
            let _ = writeln!(out, "poisson = {}     # static Poisson ratio", num(nu));
        }
        (Bulk::Modulus(k), None) => {
            let _ = writeln!(out, "k_0 = {}         # Pa", num(k));
        }
        (Bulk::Incompressible, _) => out.push_str("poisson = 0.5       # incompressible\n"),
    }
}

/// The tables `[TABLE.shear]` and `[TABLE.bulk]` of a general material.
fn general(out: &mut String, table: &str, m: &Material) {
    let _ = writeln!(out, "[{table}.shear]");
    let _ = writeln!(out, "g_inf = {}       # Pa", num(m.shear().g_inf()));
    let _ = writeln!(
        out,
        "terms = {}       # [g_i (Pa), tau_i (s)]",
        pairs(m.shear().terms())
    );
    let _ = writeln!(out, "\n[{table}.bulk]");
    match m.bulk() {
        BulkRheology::Incompressible => out.push_str("incompressible = true\n"),
        BulkRheology::Elastic(k) => match m.written_poisson() {
            Some(nu) => {
                let _ = writeln!(out, "poisson = {}     # static Poisson ratio", num(nu));
            }
            None => {
                let _ = writeln!(out, "k_0 = {}         # Pa", num(*k));
            }
        },
        BulkRheology::Prony(p) => {
            let _ = writeln!(out, "k_inf = {}       # Pa", num(p.k_inf()));
            let _ = writeln!(
                out,
                "terms = {}       # [k_j (Pa), theta_j (s)]",
                pairs(p.terms())
            );
        }
    }
}

/// `inertia_factor = ...` when it is not the default (a solid sphere).
fn inertia(kappa: f64) -> String {
    if kappa == SOLID_SPHERE {
        String::new()
    } else {
        format!("inertia_factor = {}\n", num(kappa))
    }
}

fn body(out: &mut String, b: &Body, exact: bool, kappa: f64) {
    out.push_str("\n[[body]]\n");
    let _ = writeln!(out, "mass = {}        # kg", num(b.mass()));
    let _ = writeln!(out, "radius = {}      # m", num(b.radius()));
    if exact {
        out.push_str("profile = \"sphere\"\n");
    }
    out.push_str(&inertia(kappa));
    match b.material() {
        BodyMaterial::Rigid => out.push_str("rigid = true\n"),
        BodyMaterial::Viscoelastic(m) => {
            out.push('\n');
            material(out, "body.material", m);
        }
    }
}

impl Scene {
    /// The scene as TOML text in the scene format (SI units; see the module docs):
    /// `Scene::parse(&scene.to_toml())` equals `scene`.
    ///
    /// ```
    /// # use mdr_impact::io::scene::Scene;
    /// let scene = Scene::default_scene();
    /// assert_eq!(Scene::parse(&scene.to_toml()).unwrap(), scene);
    /// ```
    pub fn to_toml(&self) -> String {
        let mut out = String::new();
        let imp = &self.impact;
        let _ = writeln!(
            out,
            "[impact]\nvelocity = {}     # m/s",
            num(imp.velocity())
        );
        let ob = &self.oblique;
        if ob.tangential_velocity != 0.0 {
            let _ = writeln!(
                out,
                "tangential_velocity = {}     # m/s",
                num(ob.tangential_velocity)
            );
        }
        if ob.spin != 0.0 {
            let _ = writeln!(out, "spin = {}     # rad/s", num(ob.spin));
        }
        let sphere = |out: &mut String| {
            let s = imp.sphere();
            let indenter = |out: &mut String, keys: &str| {
                let _ = writeln!(
                    out,
                    "\n[indenter]\nmass = {}        # kg\n{keys}",
                    num(s.mass())
                );
            };
            match *imp.shape() {
                Shape::Paraboloid { .. } | Shape::Spheres { .. } => {
                    let profile = if matches!(imp.shape(), Shape::Spheres { .. }) {
                        "profile = \"sphere\"\n"
                    } else {
                        ""
                    };
                    let _ = writeln!(
                        out,
                        "\n[sphere]\nmass = {}        # kg\nradius = {}      # m\n{profile}{}",
                        num(s.mass()),
                        num(s.radius()),
                        inertia(ob.inertia)
                    );
                }
                Shape::Cone { half_angle_deg } => indenter(
                    out,
                    &format!("shape = \"cone\"\nhalf_angle_deg = {}\n", num(half_angle_deg)),
                ),
                Shape::PowerLaw {
                    exponent,
                    coefficient,
                } => indenter(
                    out,
                    &format!(
                        "shape = \"power-law\"\nexponent = {}\ncoefficient = {}   # m^(1 - exponent)\n",
                        num(exponent),
                        num(coefficient)
                    ),
                ),
                Shape::Flat { radius } => indenter(
                    out,
                    &format!("shape = \"flat\"\nradius = {}      # m\n", num(radius)),
                ),
            }
        };
        match imp.target() {
            Target::HalfSpace(m) => {
                sphere(&mut out);
                material(&mut out, "material", m);
            }
            Target::TwoBodies(b) => {
                let exact = match imp.shape() {
                    Shape::Spheres { caps } => [caps[0].exact, caps[1].exact],
                    _ => [false, false],
                };
                body(&mut out, b.a(), exact[0], ob.inertia);
                body(&mut out, b.b(), exact[1], ob.inertia_b);
            }
        }
        if ob.friction != 0.0 {
            let _ = writeln!(out, "\n[friction]\ncoefficient = {}", num(ob.friction));
        }
        let o = &self.options;
        let _ = writeln!(
            out,
            "\n[solver]\nname = {}\nrtol = {}",
            string(o.solver.name()),
            num(o.rtol)
        );
        if let Some(r) = o.resolution {
            let _ = writeln!(out, "elements = {}\nsteps = {}", r.elements, r.steps);
        }
        if self.history_csv.is_some() || self.plot.is_some() {
            out.push_str("\n[output]\n");
            if let Some(p) = &self.history_csv {
                let _ = writeln!(out, "history = {}", string(&p.display().to_string()));
            }
            if let Some(p) = &self.plot {
                let _ = writeln!(out, "plot = {}", string(&p.display().to_string()));
            }
        }
        out
    }
}
