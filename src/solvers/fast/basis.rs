//! Collocation bases of a step: the Radau IIA nodes, the exponents of the first step (powers
//! of `sqrt(θ)`) and of the regular steps (powers of `θ`), their tables, and the exact kernels
//! `Ĵ` at a step's exponents.

// Index loops mirror the formulas (i: node, j: basis function, k: Prony term).
#![allow(clippy::needless_range_loop)]

use super::*;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    /// First step: powers of `sqrt(theta)`.
    First,
    /// Any later step: powers of `theta`.
    Regular,
}

/// Exponents of the free coefficients: `d = dfix + Σ α_j θ^{dexp_j}`, `w = wfix + Σ β_j θ^{wexp_j}`.
pub(super) fn dexp(kind: Kind, j: usize) -> f64 {
    match kind {
        Kind::First => 2.5 + 0.5 * j as f64,
        Kind::Regular => (j + 2) as f64,
    }
}

pub(super) fn wexp(kind: Kind, j: usize) -> f64 {
    match kind {
        Kind::First => 3.0 + 0.5 * j as f64,
        Kind::Regular => (j + 1) as f64,
    }
}

/// Powers of `theta`: `θ^{dexp_j}`, `θ^{dexp_j - 1}`, `θ^{dexp_j - 2}`, `θ^{wexp_j}`.
pub(super) struct Powers {
    pub(super) d0: [f64; S],
    pub(super) d1: [f64; S],
    pub(super) d2: [f64; S],
    pub(super) w: [f64; S],
    /// `θ^{3/2}` (first step's fixed `w` term).
    pub(super) w15: f64,
    /// `θ`.
    pub(super) th: f64,
}

pub(super) fn powers(kind: Kind, th: f64) -> Powers {
    let mut p = Powers {
        d0: [0.0; S],
        d1: [0.0; S],
        d2: [0.0; S],
        w: [0.0; S],
        w15: 0.0,
        th,
    };
    match kind {
        Kind::Regular => {
            let mut x = 1.0;
            for j in 0..S {
                p.d2[j] = x; // θ^j
                p.d1[j] = x * th; // θ^{j+1}
                p.d0[j] = x * th * th; // θ^{j+2}
                p.w[j] = x * th; // θ^{j+1}
                x *= th;
            }
        }
        Kind::First => {
            let s = th.sqrt();
            p.w15 = th * s;
            let mut x = th * th * s; // θ^{2.5}
            let mut y = th * th * th; // θ^3
            for j in 0..S {
                p.d0[j] = x;
                p.w[j] = y;
                x *= s;
                y *= s;
            }
            // θ^{e-1} = θ^{1.5 + j/2}, θ^{e-2} = θ^{0.5 + j/2}, computed directly (θ may be 0)
            let mut a = th * s;
            let mut b = s;
            for j in 0..S {
                p.d1[j] = a;
                p.d2[j] = b;
                a *= s;
                b *= s;
            }
        }
    }
    p
}

pub(super) struct Basis {
    /// `c_i^{dexp_j}` and `c_i^{wexp_j}`.
    pub(super) pd: Mat<S>,
    pub(super) pw: Mat<S>,
    /// `α = vd_inv (D - dfix)`, `β = vw_inv (W - wfix)`.
    pub(super) vd_inv: Mat<S>,
    pub(super) vw_inv: Mat<S>,
    /// Collocation: `D = dfix - h^2 A F`.
    pub(super) a: Mat<S>,
    /// `A^-1` (the Newton matrix is formed as `A^-1 + h^2 J`).
    pub(super) a_inv: Mat<S>,
    /// `|A|_inf`.
    pub(super) a_norm: f64,
}

pub(super) struct Tables {
    pub(super) c: [f64; S],
    /// Barycentric weights of the nodes, `1 / Π_(m != j) (c_j - c_m)`.
    pub(super) bary: [f64; S],
    pub(super) theta_star: f64,
    pub(super) reg: Basis,
    pub(super) first: Basis,
}

pub(super) fn legendre(n: usize, y: f64) -> f64 {
    let (mut p0, mut p1) = (1.0, y);
    if n == 0 {
        return 1.0;
    }
    for k in 1..n {
        let kf = k as f64;
        let p2 = ((2.0 * kf + 1.0) * y * p1 - kf * p0) / (kf + 1.0);
        p0 = p1;
        p1 = p2;
    }
    p1
}

/// Radau IIA nodes: zeros of `P_S(2x-1) - P_{S-1}(2x-1)` in `(0, 1]`.
pub(super) fn radau_nodes() -> [f64; S] {
    let f = |x: f64| legendre(S, 2.0 * x - 1.0) - legendre(S - 1, 2.0 * x - 1.0);
    let mut c = [1.0; S];
    let mut n = 0;
    let grid = 4000;
    for g in 0..grid - 1 {
        let (mut a, mut b) = (g as f64 / grid as f64, (g + 1) as f64 / grid as f64);
        let (fa, fb) = (f(a), f(b));
        if fa == 0.0 || fa * fb < 0.0 {
            for _ in 0..200 {
                let m = 0.5 * (a + b);
                if f(a) * f(m) <= 0.0 {
                    b = m;
                } else {
                    a = m;
                }
            }
            if n < S - 1 {
                c[n] = 0.5 * (a + b);
                n += 1;
            }
        }
    }
    c
}

pub(super) fn build_basis(kind: Kind, c: &[f64; S]) -> Basis {
    let mut pd = [[0.0; S]; S];
    let mut pw = [[0.0; S]; S];
    let mut p2 = [[0.0; S]; S];
    for i in 0..S {
        let p = powers(kind, c[i]);
        for j in 0..S {
            let e = dexp(kind, j);
            pd[i][j] = p.d0[j];
            pw[i][j] = p.w[j];
            p2[i][j] = e * (e - 1.0) * p.d2[j];
        }
    }
    // The tables are fixed and well conditioned; failure here is a programming error.
    let vd_inv = linalg::inverse(&pd).expect("collocation Vandermonde (d) is regular");
    let vw_inv = linalg::inverse(&pw).expect("collocation Vandermonde (w) is regular");
    let a_inv = linalg::mul(&p2, &vd_inv);
    let a = linalg::inverse(&a_inv).expect("collocation matrix is regular");
    Basis {
        pd,
        pw,
        vd_inv,
        vw_inv,
        a_norm: linalg::norm_inf(&a),
        a,
        a_inv,
    }
}

pub(super) fn tables() -> &'static Tables {
    static T: OnceLock<Tables> = OnceLock::new();
    T.get_or_init(|| {
        let c = radau_nodes();
        // defect probe: the midpoint of the widest gap between 0, c_1, ..., c_S
        let mut theta_star = 0.5 * c[0];
        let mut gap = c[0];
        for i in 1..S {
            if c[i] - c[i - 1] > gap {
                gap = c[i] - c[i - 1];
                theta_star = 0.5 * (c[i] + c[i - 1]);
            }
        }
        let bary = std::array::from_fn(|j| {
            (0..S)
                .filter(|&m| m != j)
                .fold(1.0, |acc, m| acc / (c[j] - c[m]))
        });
        Tables {
            c,
            bary,
            theta_star,
            reg: build_basis(Kind::Regular, &c),
            first: build_basis(Kind::First, &c),
        }
    })
}

/// `Ĵ` at the exponents of a step: `one` (`ν = 1`, the `v_n h θ` term), `wfix` (`ν = 3/2`,
/// first step), `d[j]` (`ν = dexp_j`), `w[j]` (`ν = wexp_j`).
#[derive(Clone, Copy)]
pub(super) struct Jt {
    pub(super) one: f64,
    pub(super) wfix: f64,
    pub(super) d: [f64; S],
    pub(super) w: [f64; S],
}

impl Jt {
    pub(super) const ZERO: Jt = Jt {
        one: 0.0,
        wfix: 0.0,
        d: [0.0; S],
        w: [0.0; S],
    };
}

/// Kernels of a regular step from `Ĵ_1 ..= Ĵ_(S+1)` (`t[m] = Ĵ_m`, `t[0]` unused).
#[inline(always)]
pub(super) fn jt_regular(t: &[f64; S + 2]) -> Jt {
    let mut j = Jt::ZERO;
    j.one = t[1];
    j.d.copy_from_slice(&t[2..S + 2]);
    j.w.copy_from_slice(&t[1..S + 1]);
    j
}

/// Kernels of the first step (powers of `sqrt(θ)`) at `x`, the series truncated at `tol`,
/// with `exp(-x)` given (`ex`): both families from that one exponential.
pub(super) fn jt_first(x: f64, tol: f64, ex: f64) -> Jt {
    let kind = Kind::First;
    // integer family 1, 2, ..., S+1 and half-integer family 3/2, 5/2, ..., S+1/2
    let mut fi = [0.0; S + 1];
    let mut fh = [0.0; S + 1];
    kernel::jhat_family_ex(1.0, x, tol, ex, &mut fi);
    kernel::jhat_family_ex(1.5, x, tol, ex, &mut fh);
    let pick = |nu: f64| -> f64 {
        if nu.fract() == 0.0 {
            fi[nu as usize - 1]
        } else {
            fh[(nu - 1.5) as usize]
        }
    };
    let mut j = Jt {
        one: fi[0],
        wfix: fh[0],
        d: [0.0; S],
        w: [0.0; S],
    };
    for k in 0..S {
        j.d[k] = pick(dexp(kind, k));
        j.w[k] = pick(wexp(kind, k));
    }
    j
}

/// The kernels of a step at `x` and `exp(-x)` (from the same evaluation on regular steps); the
/// integer series truncated at `tol` relative.
pub(super) fn jt_ex(kind: Kind, x: f64, tol: f64) -> (Jt, f64) {
    let (jj, ex) = jt_lanes(kind, &[x], tol);
    (jj[0], ex[0])
}

/// [`jt_ex`] at `L` arguments, e.g. the nodes `x_i = c_i h / tau` of a step: on regular steps
/// in one pass ([`kernel::jhat_int_lanes`]).
pub(super) fn jt_lanes<const L: usize>(kind: Kind, xs: &[f64; L], tol: f64) -> ([Jt; L], [f64; L]) {
    let mut ex = [0.0; L];
    match kind {
        Kind::Regular => {
            let mut t = [[0.0; S + 2]; L];
            kernel::jhat_int_lanes(xs, tol, &mut t, &mut ex);
            let mut jj = [Jt::ZERO; L];
            for i in 0..L {
                jj[i] = jt_regular(&t[i]);
            }
            (jj, ex)
        }
        Kind::First => {
            for i in 0..L {
                ex[i] = kernel::exp_neg(xs[i]);
            }
            let mut jj = [Jt::ZERO; L];
            for i in 0..L {
                jj[i] = jt_first(xs[i], tol, ex[i]);
            }
            (jj, ex)
        }
    }
}

/// The polynomial through the node values `ys` of a step at `θ` (any `θ`, also beyond the
/// step): Lagrange form with the tables' barycentric weights and prefix/suffix products of
/// `θ - c_m` (no divisions).
pub(super) fn interp_nodes(tab: &Tables, ys: &[f64; S], th: f64) -> f64 {
    let mut pre = [1.0; S];
    for j in 1..S {
        pre[j] = pre[j - 1] * (th - tab.c[j - 1]);
    }
    let mut acc = 0.0;
    let mut suf = 1.0;
    for j in (0..S).rev() {
        acc += ys[j] * tab.bary[j] * pre[j] * suf;
        suf *= th - tab.c[j];
    }
    acc
}
