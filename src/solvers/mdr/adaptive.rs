//! The adaptive drivers of the MDR schemes: the pilot layout, a run on an explicit resolution,
//! and the refinement to a requested accuracy of the CoR (with its error estimate).

use super::*;

/// Stability bound of the explicit Euler step (canonical units): `min(2 tau, 2/omega)`.
pub fn euler_step_bound(prony: &Prony, contact_radius: f64) -> f64 {
    let relax = 2.0 * prony.min_tau();
    let omega = (8.0 * prony.glassy() * contact_radius).sqrt();
    relax.min(2.0 / omega)
}

/// Estimate the layout of an impact with coarse exponential-MDR runs, restarting with a
/// rescaled grid when the first guess (the glassy Hertz impact) was far off.
pub fn pilot(prony: &Prony) -> Result<Layout> {
    pilot_with(&Geometry::UNIT_SPHERE, prony.glassy(), |grid, capacity| {
        run_exponential(prony, grid, capacity, false)
    })
}

/// [`pilot`] for a canonical material: a general material's layout comes from coarse runs of
/// its own network (glassy modulus from the network's instantaneous stiffness), the standard
/// solid's from [`pilot`] on its `G_eq`.
pub fn pilot_material(material: &CanonicalMaterial) -> Result<Layout> {
    let g = &material.geometry;
    match &material.network {
        Network::General(net) => pilot_with(g, net.entry_stiffness(0.0).0, |grid, capacity| {
            run_network_on(g, net, grid, capacity, false)
        }),
        Network::Stacked(net) => pilot_with(g, net.entry_stiffness(0.0).0, |grid, capacity| {
            run_network_on(g, net, grid, capacity, false)
        }),
        Network::StandardSolid(_) => pilot_with(g, material.prony.glassy(), |grid, capacity| {
            run_exponential_on(g, &material.prony, grid, capacity, false)
        }),
    }
}

fn pilot_with(
    geometry: &Geometry,
    glassy: f64,
    run: impl Fn(&Grid, usize) -> Result<Outcome>,
) -> Result<Layout> {
    // the glassy elastic impact: for the paraboloid k = 16/3 G_eq(0), d = (5/(4k))^(2/5),
    // a = sqrt(d), t_c = 2.943 d; other shapes take their own d and a, and the paraboloid's
    // times, which the restarts correct
    let d = if *geometry == Geometry::UNIT_SPHERE {
        (1.25 / (16.0 / 3.0 * glassy)).powf(0.4)
    } else {
        geometry.elastic_max_indentation(glassy)
    };
    let mut layout = Layout {
        contact_radius: geometry.contact_radius(d),
        compression_time: 1.4716 * d,
        contact_time: 2.9433 * d,
    };
    let (n, m) = (tolerances::PILOT_ELEMENTS, tolerances::PILOT_STEPS);
    for _ in 0..tolerances::PILOT_MAX_RESTARTS {
        let mut grid = Grid::from_layout(&layout, n, m);
        grid.max_steps = 8 * m as u64;
        match run(&grid, 8 * n) {
            Ok(o) => {
                let new = Layout {
                    contact_radius: o.max_contact_radius,
                    compression_time: o.time_of_max_indentation,
                    contact_time: o.contact_time,
                };
                // The restitution of a nearly plastic impact (e ~ 1e-4) is a slow creep whose
                // coarse estimate can flip between values: the layout is judged by the contact
                // radius and the compression time, and the longer contact time is kept.
                let off = (new.contact_radius / layout.contact_radius)
                    .max(layout.contact_radius / new.contact_radius)
                    .max(new.compression_time / layout.compression_time)
                    .max(layout.compression_time / new.compression_time)
                    .max(new.contact_time / layout.contact_time);
                layout = Layout {
                    contact_time: new.contact_time.max(layout.contact_time),
                    ..new
                };
                if off < 2.0 {
                    return Ok(layout);
                }
            }
            Err(Error::WorkLimit { .. }) => {
                layout.contact_radius *= 4.0;
            }
            Err(Error::NoConvergence { .. }) => {
                layout.contact_time *= 8.0;
                layout.compression_time *= 2.0;
            }
            Err(e) => return Err(e),
        }
    }
    Err(Error::NoConvergence {
        what: "mdr pilot run (layout estimate)",
        iterations: tolerances::PILOT_MAX_RESTARTS as u64,
    })
}

/// Run an MDR scheme on an explicit resolution (elements per contact radius, steps per contact
/// time) laid out from `layout`.
pub fn run_resolution(
    scheme: Scheme,
    material: &CanonicalMaterial,
    layout: &Layout,
    elements: usize,
    steps: usize,
    history: bool,
) -> Result<Outcome> {
    let grid = Grid::from_layout(layout, elements, steps);
    let capacity = capacity_for(grid.dx, layout.contact_radius);
    let g = &material.geometry;
    match (scheme, &material.network) {
        (Scheme::Exponential, Network::General(net)) => {
            run_network_on(g, net, &grid, capacity, history)
        }
        (Scheme::Exponential, Network::Stacked(net)) => {
            run_network_on(g, net, &grid, capacity, history)
        }
        (Scheme::Exponential, Network::StandardSolid(_)) => {
            run_exponential_on(g, &material.prony, &grid, capacity, history)
        }
        (Scheme::Euler, Network::Stacked(_)) => Err(euler_refusal()),
        (Scheme::Euler, Network::StandardSolid(_) | Network::General(_)) => {
            let bound = euler_step_bound(&material.prony, layout.contact_radius);
            let dt = grid.dt_compression.max(grid.dt_restitution);
            if dt > bound {
                return Err(Error::UnstableStep {
                    scheme: "mdr-euler",
                    dt,
                    bound,
                });
            }
            run_euler(material, &grid, capacity, history)
        }
    }
}

/// Error estimate of the finest level from the signed CoR differences between successive
/// levels, or `None` while the sequence does not look asymptotic.
///
/// The last three differences must share their sign and shrink by ratios between `sqrt 2` and
/// `2^(p_max + 1)` (`p_max` the scheme's order): MDR sequences have pre-asymptotic plateaus and
/// sign changes (the element sum and the contact-edge events interact), and a single small
/// difference there is an accident, not convergence. The estimate is `delta_L / (2^p - 1)`
/// with `p` the observed order `log2` of the last ratio, floored at 1 (where relaxation is fast
/// against the impact the force density jumps at the contact edge and the element sum converges
/// at first order only). When the last two differences are both below `tiny` / 100 the
/// sequence is at round-off and the larger of them is the estimate.
pub(super) fn accept(deltas: &[f64], p_max: f64, tiny: f64) -> Option<f64> {
    let n = deltas.len();
    if n >= 2 && deltas[n - 1].abs().max(deltas[n - 2].abs()) <= 0.01 * tiny {
        return Some(deltas[n - 1].abs().max(deltas[n - 2].abs()));
    }
    if n < 3 {
        return None;
    }
    let (d0, d1, d2) = (deltas[n - 3], deltas[n - 2], deltas[n - 1]);
    if d0.signum() != d1.signum() || d1.signum() != d2.signum() || d2 == 0.0 {
        return None;
    }
    let p_max = p_max.max(1.0);
    let (lo, hi) = (2f64.sqrt(), 2f64.powf(p_max + 1.0));
    let (r1, r2) = (d0 / d1, d1 / d2);
    if !(lo..=hi).contains(&r1) || !(lo..=hi).contains(&r2) {
        return None;
    }
    let order = r2.log2().clamp(1.0, p_max);
    Some(d2.abs() / (2f64.powf(order) - 1.0))
}

/// Solve an impact with an MDR scheme to a requested relative accuracy of the CoR.
///
/// Adaptive refinement from a pilot layout: each level doubles the steps per contact time
/// (and, for the second-order [`Scheme::Exponential`], the elements; for [`Scheme::Euler`],
/// the elements every other level, since its time error is first order). With `delta_L` the
/// change of the CoR between levels, a level is accepted when the differences look asymptotic
/// and the error estimate of `accept` (private, documented at its definition) is below `MDR_SAFETY * rtol |e|`.
pub fn solve_rtol(
    scheme: Scheme,
    material: &CanonicalMaterial,
    rtol: f64,
    history: bool,
    work_limit: u64,
) -> Result<Outcome> {
    if let (Scheme::Euler, Network::Stacked(_)) = (scheme, &material.network) {
        return Err(euler_refusal());
    }
    let layout = pilot_material(material)?;
    let (mut n, mut m) = match scheme {
        Scheme::Exponential => (tolerances::MDR_START_ELEMENTS, tolerances::MDR_START_STEPS),
        Scheme::Euler => (
            tolerances::MDR_START_ELEMENTS,
            2 * tolerances::MDR_START_STEPS,
        ),
    };
    if scheme == Scheme::Euler {
        // respect the stability bound with a margin (the paper's choice of a small enough step)
        let bound = euler_step_bound(&material.prony, layout.contact_radius);
        let grid = Grid::from_layout(&layout, n, m);
        let dt = grid.dt_compression.max(grid.dt_restitution);
        if dt > 0.5 * bound {
            m = ((m as f64) * dt / (0.5 * bound)).ceil() as usize;
        }
    }
    let mut work = Work::default();
    let mut prev: Option<f64> = None;
    let mut deltas: Vec<f64> = Vec::new();
    // the relative estimate of the last level when its sequence looked asymptotic
    let mut asymptotic: Option<f64> = None;
    let mut last_change = f64::INFINITY;
    let refuse = |levels: u32, asymptotic: Option<f64>, last_change: f64| match asymptotic {
        Some(estimate) => Error::AccuracyNotReached {
            solver: scheme.name(),
            rtol,
            estimate,
            required: tolerances::MDR_SAFETY * rtol,
            levels,
        },
        None => Error::NotAsymptotic {
            solver: scheme.name(),
            rtol,
            last_change,
            levels,
        },
    };
    // element updates of a level with `n` elements per contact radius and `m` steps
    let level_work = |n: usize, m: usize| {
        (capacity_for(layout.contact_radius / n as f64, layout.contact_radius) as u64 / 4)
            .saturating_mul(m as u64 + 8)
    };
    let refine = |level: u32, n: usize, m: usize| match scheme {
        Scheme::Exponential => (2 * n, 2 * m),
        Scheme::Euler if level % 2 == 1 => (2 * n, 2 * m),
        Scheme::Euler => (n, 2 * m),
    };
    for level in 0..tolerances::MDR_MAX_LEVELS {
        let predicted = level_work(n, m);
        if work.element_updates.saturating_add(predicted) > work_limit {
            if level == 0 {
                // the coarsest grid the stability bound allows is already over the limit
                return Err(Error::WorkLimit {
                    solver: scheme.name(),
                    what: "element updates of the coarsest stable grid",
                    needed: predicted,
                    limit: work_limit,
                });
            }
            return Err(refuse(level, asymptotic, last_change));
        }
        let mut o = run_resolution(scheme, material, &layout, n, m, history)?;
        work.steps += o.work.steps;
        work.element_updates += o.work.element_updates;
        work.elements = work.elements.max(o.work.elements);
        work.levels = level + 1;
        if let Some(p) = prev {
            deltas.push(o.cor - p);
            let scale = o.cor.abs().max(1e-300);
            last_change = (o.cor - p).abs() / scale;
            asymptotic = None;
            if let Some(est) = accept(&deltas, scheme.time_order(), rtol * scale) {
                if est <= tolerances::MDR_SAFETY * rtol * scale {
                    o.work = work;
                    o.cor_error_estimate = Some(est / scale);
                    return Ok(o);
                }
                asymptotic = Some(est / scale);
                // the asymptotic rate tells how many more levels rtol needs: refuse now if
                // their work is over the limit, instead of after it. The rate is taken at
                // least at the scheme's order (error / 2^p per level), so that only a request
                // out of reach even at full order is refused early (the observed rate can
                // still be pre-asymptotic)
                let k = deltas.len();
                let observed = if k >= 2 {
                    (deltas[k - 2] / deltas[k - 1]).abs()
                } else {
                    0.0
                };
                let rate = observed.max(2f64.powf(scheme.time_order()));
                if rate > 1.0 {
                    let more = ((est / (tolerances::MDR_SAFETY * rtol * scale)).ln() / rate.ln())
                        .ceil()
                        .clamp(1.0, f64::from(tolerances::MDR_MAX_LEVELS));
                    let (mut nn, mut mm, mut needed) = (n, m, work.element_updates);
                    for j in 0..more as u32 {
                        (nn, mm) = refine(level + j, nn, mm);
                        needed = needed.saturating_add(level_work(nn, mm));
                    }
                    if needed > work_limit {
                        return Err(Error::WorkLimit {
                            solver: scheme.name(),
                            what: "element updates predicted to reach rtol",
                            needed,
                            limit: work_limit,
                        });
                    }
                }
            }
        }
        prev = Some(o.cor);
        (n, m) = refine(level, n, m);
    }
    Err(refuse(tolerances::MDR_MAX_LEVELS, asymptotic, last_change))
}
