//! Dimensionless groups: `cor` over arrays and the catalogue of validation cases.

use super::*;

/// CoR, contact time and maximum indentation (canonical units `m = R = v0 = G_inf = 1`) of the
/// flat arrays `nu`, `p2`, `p3` (equal lengths) that were broadcast to `shape`: the computation
/// of `mdr-impact cor --input`, in parallel, GIL released ([`in_chunks`]). Errors name the
/// element's index.
#[pyfunction]
#[pyo3(signature = (nu, p2, p3, shape, rtol, solver))]
pub(crate) fn cor_groups<'py>(
    py: Python<'py>,
    nu: PyReadonlyArray1<'py, f64>,
    p2: PyReadonlyArray1<'py, f64>,
    p3: PyReadonlyArray1<'py, f64>,
    shape: Vec<usize>,
    rtol: f64,
    solver: &str,
) -> PyResult<Bound<'py, PyTuple>> {
    let opts = options(solver, rtol)?;
    let (nu, p2, p3) = (nu.to_vec()?, p2.to_vec()?, p3.to_vec()?);
    if nu.len() != p2.len() || nu.len() != p3.len() {
        return Err(usage(format!(
            "nu, p2 and p3 have {}, {} and {} elements: broadcast them first",
            nu.len(),
            p2.len(),
            p3.len()
        )));
    }
    if nu.len() != shape.iter().product::<usize>() {
        return Err(usage(format!(
            "{} elements do not fill the shape {shape:?}",
            nu.len()
        )));
    }
    // every input checked before anything is solved, as `cor --input` reads its file first
    let mut groups = Vec::with_capacity(nu.len());
    for i in 0..nu.len() {
        groups.push(Groups::new(nu[i], p2[i], p3[i]).map_err(|e| element_err(i, &shape, e))?);
    }
    let outcomes = in_chunks(py, &groups, |g| batch::solve_groups(g, &opts))?
        .map_err(|(i, e)| element_err(i, &shape, e))?;
    let pick = |f: fn(&Outcome) -> f64| outcomes.iter().map(f).collect::<Vec<f64>>();
    let cor = array(py, pick(|o| o.cor), &shape)?;
    let time = array(py, pick(|o| o.contact_time), &shape)?;
    let depth = array(py, pick(|o| o.max_indentation), &shape)?;
    PyTuple::new(py, [cor, time, depth])
}

/// The catalogue of validation cases (`src/report/catalogue.rs`): a list of dicts with the keys `id`,
/// `regime`, `nu`, `p2`, `p3`.
#[pyfunction]
pub(crate) fn catalogue_impacts(py: Python<'_>) -> PyResult<Vec<Bound<'_, PyDict>>> {
    catalogue::IMPACTS
        .iter()
        .map(|c| {
            let d = PyDict::new(py);
            d.set_item("id", c.id)?;
            d.set_item("regime", c.regime.name())?;
            d.set_item("nu", c.nu)?;
            d.set_item("p2", c.p2)?;
            d.set_item("p3", c.p3)?;
            Ok(d)
        })
        .collect()
}
