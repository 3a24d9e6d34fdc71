//! The files of `run`: the force history (CSV), the force-time plot and, beside it, the
//! force-indentation plot, from the scene's `[output]` or into a folder given by `--out`;
//! rendered in memory and written together ([`crate::io::output::write_outputs`]).

use std::path::{Path, PathBuf};

use crate::error::Result;
use crate::io::output::{history_csv_text, OutputFile};
use crate::io::plot::{force_indentation_svg, force_time_svg, short, Caption};
use crate::io::scene::Scene;
use crate::model::impact::{Impact, Outcome};

/// The file name of the force-indentation plot, beside the force-time plot.
pub const FORCE_INDENTATION_SVG: &str = "force_indentation.svg";

/// Where the files of one `run` go, each with the key or flag that asked for it.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RunFiles {
    /// The history CSV (`t,d,v,force,a`, SI).
    pub history: Option<(String, PathBuf)>,
    /// The force-time plot (SVG).
    pub force_plot: Option<(String, PathBuf)>,
    /// The force-indentation plot (SVG), loading and unloading branches.
    pub force_indentation_plot: Option<(String, PathBuf)>,
}

impl RunFiles {
    /// The scene's `[output]`: `history`, `plot` and [`FORCE_INDENTATION_SVG`] beside the plot.
    pub fn of_scene(scene: &Scene) -> Self {
        let key = |k: &str| format!("[output] {k}");
        RunFiles {
            history: scene.history_csv.clone().map(|p| (key("history"), p)),
            force_plot: scene.plot.clone().map(|p| (key("plot"), p)),
            force_indentation_plot: scene
                .plot
                .as_ref()
                .map(|p| (key("plot"), p.with_file_name(FORCE_INDENTATION_SVG))),
        }
    }

    /// `dir/history.csv`, `dir/force.svg` and `dir/force_indentation.svg` (`run --out DIR`).
    pub fn in_folder(dir: &Path) -> Self {
        let at = |name: &str| Some(("--out".to_string(), dir.join(name)));
        RunFiles {
            history: at("history.csv"),
            force_plot: at("force.svg"),
            force_indentation_plot: at(FORCE_INDENTATION_SVG),
        }
    }

    /// True when there is any file to write (the solve must then compute a history).
    pub fn any(&self) -> bool {
        self.history.is_some() || self.force_plot.is_some()
    }

    /// The files with their contents for the history `o.history` of `impact` (none without a
    /// history), the plots titled with the scene's `name`.
    pub fn render(&self, name: &str, impact: &Impact, o: &Outcome) -> Result<Vec<OutputFile>> {
        let Some(h) = &o.history else {
            return Ok(Vec::new());
        };
        let subtitle = subtitle(name, impact, o);
        let mut files = Vec::new();
        if let Some((key, path)) = &self.history {
            let bytes = history_csv_text(h).into_bytes();
            files.push(file(key, path, bytes));
        }
        if let Some((key, path)) = &self.force_plot {
            let caption = Caption {
                title: "Contact force against time".into(),
                subtitle: subtitle.clone(),
            };
            let label = format!("contact force ({} solver)", o.solver);
            let svg = force_time_svg(path, h, &caption, &label)?;
            files.push(file(key, path, svg.into_bytes()));
        }
        if let Some((key, path)) = &self.force_indentation_plot {
            let caption = Caption {
                title: "Contact force against indentation (hysteresis)".into(),
                subtitle,
            };
            let svg = force_indentation_svg(path, h, &caption)?;
            files.push(file(key, path, svg.into_bytes()));
        }
        Ok(files)
    }

    /// The paths, each with what it holds, in the order they are written.
    pub fn described(&self) -> Vec<(&'static str, &Path)> {
        [
            ("history written to", &self.history),
            ("force plot written to", &self.force_plot),
            ("force-indentation plot to", &self.force_indentation_plot),
        ]
        .into_iter()
        .filter_map(|(what, f)| f.as_ref().map(|(_, p)| (what, p.as_path())))
        .collect()
    }
}

fn file(key: &str, path: &Path, bytes: Vec<u8>) -> OutputFile {
    OutputFile {
        key: key.to_string(),
        path: path.to_path_buf(),
        bytes,
    }
}

/// The subtitle of a run's plots: the scene's name, the sphere (the effective sphere of a
/// collision), the impact velocity, the solver and the CoR.
pub fn subtitle(name: &str, impact: &Impact, o: &Outcome) -> String {
    let s = impact.sphere();
    let sphere = match impact.bodies() {
        Some(_) => "effective sphere",
        None => "sphere",
    };
    format!(
        "{name}: {sphere} m = {} kg, R = {} m; v0 = {} m/s; e = {:.6} ({})",
        short(s.mass()),
        short(s.radius()),
        short(impact.velocity()),
        o.cor,
        o.solver
    )
}
