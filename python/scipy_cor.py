"""The CoR of a sphere on a standard linear solid as a SciPy user would compute it: DOP853.

    python python/scipy_cor.py --input rows.csv [--rtol 1e-8] [--repeats 3]

Reads `nu,p2,p3` rows (the paper's dimensionless groups, as `mdr-impact cor --input`), prints
`nu,p2,p3,cor,seconds`: the CoR and the median wall time of `--repeats` solves of each row.
`mdr-impact bench` calls it to time `fast` against the script a user would write (VALIDATION.md
section 9); it needs numpy and scipy and shares no code with the Rust solvers.

Canonical units m = R = v0 = G_inf = 1. With `G_eq(t) = c_inf + sum_k c_k exp(-t/tau_k)`:

- compression (Lee-Radok): y = [d, v, q_k, S_k], d' = v, v' = -F,
  F = 16/3 (c_inf d^(3/2) + sum c_k q_k), q_k' = (3/2) sqrt(d) v - q_k/tau_k,
  S_k' = v - S_k/tau_k, until v = 0 (dense output kept);
- restitution (Ting): z = [d, v, S_k]; at every right-hand side t_1 in [0, t_m] solves
  c_inf (d - d_c(t_1)) + sum c_k (S_k - exp(-(t - t_1)/tau_k) S_k^c(t_1)) = 0 (brentq), and
  F = 16/3 (c_inf d_c(t_1)^(3/2) + sum c_k exp(-(t - t_1)/tau_k) q_k^c(t_1)); contact ends
  when c_inf d + sum c_k S_k = 0, and e = -v there (the paper's Eqs. 1-3 and 10).

Both phases by `scipy.integrate.solve_ivp(method="DOP853", rtol=rtol, atol=rtol * 1e-3)`.
"""

import argparse
import math
import statistics
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

K16 = 16.0 / 3.0


def relaxation(nu, p2, p3):
    """`c_inf` and the terms `(c_k, tau_k)` of G_eq for the groups (nu, p2, p3): shear
    relaxation 1 + (1/p2) exp(-t/(p2 p3)) with a compressible elastic bulk (paper section 2)."""
    g1, tau = 1.0 / p2, p2 * p3
    kap = 0.0 if nu == 0.5 else (1.0 - 2.0 * nu) / (2.0 * (1.0 + nu))
    c_inf = (1.0 + kap) / (1.0 + 4.0 * kap)
    if kap == 0.0:
        return c_inf, np.array([g1]), np.array([tau])
    g0 = 1.0 + g1
    cs = [g1 / 4.0, 0.75 * g1 / ((1.0 + 4.0 * kap * g0) * (1.0 + 4.0 * kap))]
    taus = [tau, tau * (1.0 + 4.0 * kap * g0) / (1.0 + 4.0 * kap)]
    return c_inf, np.array(cs), np.array(taus)


def cor(nu, p2, p3, rtol):
    c_inf, c, tau = relaxation(nu, p2, p3)
    n = len(c)
    atol = rtol * 1e-3

    def comp(t, y):
        d, v = y[0], y[1]
        q, s = y[2:2 + n], y[2 + n:]
        f = K16 * (c_inf * max(d, 0.0) ** 1.5 + c @ q)
        return np.concatenate(([v, -f], 1.5 * math.sqrt(max(d, 0.0)) * v - q / tau, v - s / tau))

    def turn(t, y):
        return y[1]

    turn.terminal, turn.direction = True, -1
    t0 = 1e-9 * min(1.0, tau.min())
    y0 = np.concatenate(([t0, 1.0], np.full(n, t0 ** 1.5), np.full(n, t0)))
    a = solve_ivp(comp, (t0, 1e3), y0, method="DOP853", rtol=rtol, atol=atol,
                  events=turn, dense_output=True)
    t_m = a.t_events[0][0]
    ym = a.y_events[0][0]
    hist = a.sol

    def force(t, z):
        d, s = z[0], z[2:]
        g0 = c_inf * d + c @ s
        if g0 <= 0.0:
            return 0.0

        def phi(t1):
            h = hist(t1)
            return c_inf * (d - h[0]) + c @ (s - np.exp(-(t - t1) / tau) * h[2 + n:])

        if phi(t0) <= 0.0:
            return 0.0
        p_m = phi(t_m)
        t1 = t_m if p_m >= 0.0 else brentq(phi, t0, t_m, xtol=1e-15, rtol=1e-15)
        h = hist(t1)
        return K16 * (c_inf * max(h[0], 0.0) ** 1.5 + c @ (np.exp(-(t - t1) / tau) * h[2:2 + n]))

    def rest(t, z):
        return np.concatenate(([z[1], -force(t, z)], z[1] - z[2:] / tau))

    def end(t, z):
        return c_inf * z[0] + c @ z[2:]

    end.terminal, end.direction = True, -1
    z0 = np.concatenate(([ym[0], ym[1]], ym[2 + n:]))
    b = solve_ivp(rest, (t_m, t_m + 1e3), z0, method="DOP853", rtol=rtol, atol=atol, events=end)
    return -b.y_events[0][0][1]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--input", required=True)
    ap.add_argument("--rtol", type=float, default=1e-8)
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    if args.repeats < 1 or not (0.0 < args.rtol < 1.0):
        sys.exit("error: --repeats must be at least 1 and --rtol in (0, 1)")
    with open(args.input) as f:
        header = f.readline().strip()
        if header != "nu,p2,p3":
            sys.exit(f"error: {args.input}: header must be nu,p2,p3, found {header!r}")
        rows = [tuple(map(float, line.split(","))) for line in f if line.strip()]
    print("nu,p2,p3,cor,seconds")
    for nu, p2, p3 in rows:
        times = []
        for _ in range(args.repeats):
            t0 = time.perf_counter()
            e = cor(nu, p2, p3, args.rtol)
            times.append(time.perf_counter() - t0)
        print(f"{nu!r},{p2!r},{p3!r},{float(e)!r},{statistics.median(times)!r}")


if __name__ == "__main__":
    main()
