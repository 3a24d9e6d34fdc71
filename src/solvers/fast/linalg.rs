//! Small dense linear algebra on fixed-size arrays (no allocation in the time loop).

// Index loops mirror the formulas (i: node, j: basis function, k: Prony term).
#![allow(clippy::needless_range_loop)]

/// Square matrix of the collocation size.
pub(crate) type Mat<const N: usize> = [[f64; N]; N];

/// Solve `m x = b` by Gaussian elimination with partial pivoting; `None` if singular.
/// The reciprocal pivots are kept for the back substitution (one division per column).
pub(crate) fn solve<const N: usize>(mut m: Mat<N>, mut b: [f64; N]) -> Option<[f64; N]> {
    let mut inv = [0.0; N];
    for col in 0..N {
        let mut p = col;
        let mut best = m[col][col].abs();
        for r in col + 1..N {
            let v = m[r][col].abs();
            if v > best {
                best = v;
                p = r;
            }
        }
        if !(best > 0.0 && best.is_finite()) {
            return None;
        }
        if p != col {
            m.swap(col, p);
            b.swap(col, p);
        }
        let pivot = m[col];
        inv[col] = 1.0 / pivot[col];
        let bc = b[col];
        for r in col + 1..N {
            let f = m[r][col] * inv[col];
            // all columns: those left of `col` are never read again, and a fixed trip count
            // lets the compiler unroll and vectorise
            for (x, p) in m[r].iter_mut().zip(&pivot) {
                *x -= f * p;
            }
            b[r] -= f * bc;
        }
    }
    // back substitution over full rows: the x not yet computed are still 0
    let mut x = [0.0; N];
    for r in (0..N).rev() {
        let mut s = b[r];
        for (mc, xc) in m[r].iter().zip(&x) {
            s -= mc * xc;
        }
        x[r] = s * inv[r];
    }
    Some(x)
}

/// Inverse by `N` solves; `None` if singular.
pub(crate) fn inverse<const N: usize>(m: &Mat<N>) -> Option<Mat<N>> {
    let mut out = [[0.0; N]; N];
    for j in 0..N {
        let mut e = [0.0; N];
        e[j] = 1.0;
        let col = solve(*m, e)?;
        for i in 0..N {
            out[i][j] = col[i];
        }
    }
    Some(out)
}

/// Matrix product.
pub(crate) fn mul<const N: usize>(a: &Mat<N>, b: &Mat<N>) -> Mat<N> {
    let mut out = [[0.0; N]; N];
    for i in 0..N {
        for k in 0..N {
            let a_ik = a[i][k];
            for j in 0..N {
                out[i][j] += a_ik * b[k][j];
            }
        }
    }
    out
}

/// Matrix–vector product.
#[inline]
pub(crate) fn mul_vec<const N: usize>(a: &Mat<N>, x: &[f64; N]) -> [f64; N] {
    let mut out = [0.0; N];
    for i in 0..N {
        let mut s = 0.0;
        for j in 0..N {
            s += a[i][j] * x[j];
        }
        out[i] = s;
    }
    out
}

/// Maximum absolute row sum (the induced infinity norm).
pub(crate) fn norm_inf<const N: usize>(a: &Mat<N>) -> f64 {
    a.iter()
        .map(|row| row.iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max)
}
