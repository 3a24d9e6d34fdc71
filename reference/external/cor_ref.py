#!/usr/bin/env python3
"""Independent high-accuracy reference: CoR of a rigid sphere on a compressible
viscoelastic standard linear solid (Ting-type compression/restitution solution).

Canonical units m = R = v0 = G_inf = 1.

Method
------
Compression (d' >= 0): state y = [d, v, q_k, S_k] integrated in the stretched
time s = sqrt(t) (makes the t^{3/2} start analytic), implicit Radau IIA (order 5)
with analytic Jacobian (stiff q_k, S_k for tau << contact time).  All accepted
step nodes are stored; compression quantities at arbitrary t1 are obtained by
local barycentric Lagrange interpolation (K nodes) in s.  End of compression
(v = 0) is refined by Newton + re-integration.

Restitution: state z = [d, v, S_k] in t, Radau with analytic Jacobian
(implicit function theorem: dF/dd = 8 sqrt(d1) c_inf, dF/dS_k = 8 sqrt(d1) c_k).
At every RHS call t1 is found by safeguarded Newton on Phi(t1) = 0.
Contact end: c_inf d + sum c_k S_k = 0, refined by Newton + re-integration.

A second, independent method (explicit DOP853 for everything, its own order-7
dense output for the compression history, brentq roots) is used for
non-stiff cases for validation.
"""
import sys, math, time, bisect
import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq
from scipy.special import dawsn

ATOLF = 1e-3
T0FAC = 1e-7
HERTZ_TC = 2.9432751843247047


def model(nu, p2, p3):
    G1 = 1.0 / p2
    tau = p2 * p3
    G0 = 1.0 + G1
    if nu == 0.5:
        kap = 0.0
    else:
        kap = (1.0 - 2.0 * nu) / (2.0 * (1.0 + nu))
    cinf = (1.0 + kap) / (1.0 + 4.0 * kap)
    if G1 == 0.0:        # purely elastic
        cs, taus = [], []
    elif kap == 0.0:
        cs = [G1]
        taus = [tau]
    else:
        cs = [G1 / 4.0, 0.75 * G1 / ((1.0 + 4.0 * kap * G0) * (1.0 + 4.0 * kap))]
        taus = [tau, tau * (1.0 + 4.0 * kap * G0) / (1.0 + 4.0 * kap)]
    return cinf, np.array(cs, float), np.array(taus, float)


def sqrt_minus_dawson(x):
    """int_0^x exp(-(x-u)) sqrt(u) du = sqrt(x) - D(sqrt(x))"""
    if x < 2.0:
        term = 2.0 / 3.0 * x ** 1.5
        tot = term
        n = 0
        while abs(term) > 1e-18 * abs(tot):
            n += 1
            term *= -2.0 * x / (2 * n + 3)
            tot += term
        return tot
    r = math.sqrt(x)
    return r - float(dawsn(r))


class Interp:
    """local barycentric Lagrange interpolation of tabulated rows (K-point
    stencils, weights precomputed)."""

    def __init__(self, x, Y, K):
        self.x = np.asarray(x)
        self.xl = list(self.x)
        self.Y = np.ascontiguousarray(Y)
        self.K = K
        n = self.n = len(x)
        nst = n - K + 1
        idx = np.arange(nst)[:, None] + np.arange(K)[None, :]
        X = self.x[idx]                      # (nst, K)
        dd = X[:, :, None] - X[:, None, :]
        dd[:, np.arange(K), np.arange(K)] = 1.0
        self.W = 1.0 / np.prod(dd, axis=2)   # (nst, K)
        self.Ys = self.Y[idx]                # (nst, K, m)
        self.Xs = X
        self.ncall = 0

    def __call__(self, xq):
        self.ncall += 1
        n, K = self.n, self.K
        i = bisect.bisect_left(self.xl, xq)
        if i < n and self.xl[i] == xq:
            return self.Y[i].copy()
        lo = i - K // 2
        lo = 0 if lo < 0 else (n - K if lo > n - K else lo)
        a = self.W[lo] / (xq - self.Xs[lo])
        return (a @ self.Ys[lo]) / a.sum()


class CoR:
    def __init__(self, nu, p2, p3, rtol=1e-13, K=8, method='Radau', verbose=False):
        self.cinf, self.c, self.tau = model(nu, p2, p3)
        self.nk = len(self.c)
        self.rtol = rtol
        self.K = K
        self.method = method
        self.verbose = verbose
        self.k16 = 16.0 / 3.0
        self.G0 = self.cinf + self.c.sum()

    # ---------------- compression, independent variable s = sqrt(t) --------
    def f_comp(self, s, y):
        nk = self.nk
        d = y[0]; v = y[1]
        q = y[2:2 + nk]; S = y[2 + nk:]
        sd = math.sqrt(d) if d > 0 else 0.0
        F = self.k16 * (self.cinf * d * sd + self.c @ q)
        out = np.empty_like(y)
        out[0] = v
        out[1] = -F
        out[2:2 + nk] = -q / self.tau + 1.5 * sd * v
        out[2 + nk:] = -S / self.tau + v
        return 2.0 * s * out

    def j_comp(self, s, y):
        nk = self.nk
        n = 2 + 2 * nk
        d = y[0]; v = y[1]
        sd = math.sqrt(d) if d > 0 else 1e-300
        J = np.zeros((n, n))
        J[0, 1] = 1.0
        J[1, 0] = -self.k16 * 1.5 * self.cinf * sd
        J[1, 2:2 + nk] = -self.k16 * self.c
        for k in range(nk):
            J[2 + k, 0] = 0.75 * v / sd
            J[2 + k, 1] = 1.5 * sd
            J[2 + k, 2 + k] = -1.0 / self.tau[k]
            J[2 + nk + k, 1] = 1.0
            J[2 + nk + k, 2 + nk + k] = -1.0 / self.tau[k]
        return 2.0 * s * J

    def y_start(self, s0):
        """state at t0 = s0^2 << contact time: d = t0, v = 1 up to O(t0^2.5)
        (neglected, t0 <= 1e-7 tc0), q_k, S_k exact for d(t) = t."""
        t0 = s0 * s0
        nk = self.nk
        y = np.zeros(2 + 2 * nk)
        kG = self.k16 * self.G0
        y[0] = t0 - kG * t0 ** 3.5 / (2.5 * 3.5)
        y[1] = 1.0 - kG * t0 ** 2.5 / 2.5
        for k in range(nk):
            tk = self.tau[k]
            x = t0 / tk
            y[2 + k] = 1.5 * tk ** 1.5 * sqrt_minus_dawson(x)
            y[2 + nk + k] = tk * (-math.expm1(-x))
        return y

    def _ivp(self, f, span, y0, jac, events=None, dense=False, first_step=None):
        kw = dict(rtol=self.rtol, atol=self.atol, events=events, dense_output=dense)
        if self.method in ('Radau', 'BDF', 'LSODA'):
            kw['jac'] = jac
        if first_step is not None:
            kw['first_step'] = first_step
        return solve_ivp(f, span, y0, method=self.method, **kw)

    def compression(self):
        nk = self.nk
        # Hertz glassy scales for tolerances
        kg = self.k16 * self.G0
        dmg = (5.0 / (4.0 * kg)) ** 0.4
        self.tc0 = HERTZ_TC * dmg
        self.dmg = dmg
        s0 = math.sqrt(T0FAC * self.tc0)
        y0 = self.y_start(s0)
        # absolute tolerances: tiny compared to the scales
        sc = np.empty(2 + 2 * nk)
        sc[0] = dmg * 10; sc[1] = 1.0
        for k in range(nk):
            sc[2 + k] = min(10 * dmg ** 1.5, self.tau[k] * 1.5 * math.sqrt(10 * dmg))
            sc[2 + nk + k] = min(10 * dmg, self.tau[k])
        self.atol_c = sc * self.rtol * ATOLF
        self.atol = self.atol_c

        def ev(s, y):
            return y[1]
        ev.terminal = True
        ev.direction = -1
        smax = 20.0 * math.sqrt(self.tc0 * 10)
        dense = self.method == 'DOP853'
        sol = self._ivp(self.f_comp, (s0, smax), y0, self.j_comp, events=[ev], dense=dense)
        if sol.status != 1:
            raise RuntimeError('compression: no max ' + str(sol.message))
        S = list(sol.t[:-1]); Y = list(sol.y[:, :-1].T)
        sm = sol.t_events[0][0]
        # refine: Newton on v(s)=0 from the last accepted node
        sa, ya = S[-1], Y[-1]
        for it in range(3):
            r = self._ivp(self.f_comp, (sa, sm), ya, self.j_comp)
            ym = r.y[:, -1]
            dv = self.f_comp(sm, ym)[1]
            ds = -ym[1] / dv
            sm = sm + ds
            if abs(ds) < 1e-15 * sm:
                break
        r = self._ivp(self.f_comp, (sa, sm), ya, self.j_comp, dense=dense)
        ym = r.y[:, -1].copy()
        ym[1] = 0.0 if abs(ym[1]) < 1e-13 else ym[1]
        S += list(r.t[1:]); Y += list(r.y[:, 1:].T)
        self.sm = sm
        self.tm = sm * sm
        self.ym = ym
        self.nodes_s = np.array(S)
        self.nodes_y = np.array(Y)
        self.ncomp_steps = len(S)
        if dense:
            # piecewise dense output (both pieces)
            self.dense_pieces = [(sol.t[0], sol.t[-2], sol.sol), (sa, sm, r.sol)]
        self.interp = Interp(self.nodes_s, self.nodes_y, self.K)
        return ym

    def comp_at(self, s1):
        if self.method == 'DOP853':
            if s1 <= self.dense_pieces[0][1]:
                if s1 < self.nodes_s[0]:
                    return self.y_start(max(s1, 1e-30))
                return self.dense_pieces[0][2](s1)
            return self.dense_pieces[1][2](s1)
        if s1 < self.nodes_s[0]:
            return self.y_start(max(s1, 1e-30))
        return self.interp(s1)

    # ---------------- restitution -------------------------------------------
    def root_t1(self, t, d, S):
        """solve Phi(s1)=0 for s1 in [0, sm]; returns s1 and comp state there."""
        cinf, c, tau, nk = self.cinf, self.c, self.tau, self.nk
        P0 = cinf * d + c @ S  # Phi at t1=0
        if P0 <= 0.0:
            return 0.0, None

        def phi(s1):
            y1 = self.comp_at(s1)
            t1 = s1 * s1
            e = np.exp(-(t - t1) / tau)
            P = cinf * (d - y1[0]) + c @ (S - e * y1[2 + nk:])
            return P, y1, e

        if self.method == 'DOP853':
            if phi(self.sm)[0] >= 0.0:
                return self.sm, self.comp_at(self.sm)
            s1 = brentq(lambda x: phi(x)[0], 0.0, self.sm, xtol=1e-17, rtol=8.9e-16, maxiter=200)
            return s1, phi(s1)[1]
        lo, hi = 0.0, self.sm  # phi(lo)>0, phi(hi)<=0
        s1 = min(max(self.s1_guess, lo), hi)
        for it in range(100):
            P, y1, e = phi(s1)
            if P > 0:
                lo = s1
            else:
                hi = s1
            if P == 0.0:
                break
            G = cinf + c @ e
            dP = -G * y1[1] * 2.0 * s1
            if dP < 0:
                sn = s1 - P / dP
            else:
                sn = 0.5 * (lo + hi)
            if not (lo < sn < hi):
                sn = 0.5 * (lo + hi)
            ds = abs(sn - s1)
            if ds <= 1e-12 * min(s1, self.sm - s1) or ds <= 1e-15 * self.sm \
                    or hi - lo < 1e-16 * self.sm:
                # quadratic convergence: next correction is below roundoff
                s1 = sn
                break
            s1 = sn
        self.s1_guess = s1
        return s1, self.comp_at(s1)

    def F_rest(self, t, d, S):
        s1, y1 = self.root_t1(t, d, S)
        if y1 is None:
            return 0.0, 0.0
        nk = self.nk
        t1 = s1 * s1
        e = np.exp(-(t - t1) / self.tau)
        d1 = max(y1[0], 0.0)
        F = self.k16 * (self.cinf * d1 ** 1.5 + self.c @ (e * y1[2:2 + nk]))
        return F, d1

    def f_rest(self, t, z):
        nk = self.nk
        d = z[0]; v = z[1]; S = z[2:]
        F, _ = self.F_rest(t, d, S)
        out = np.empty_like(z)
        out[0] = v
        out[1] = -F
        out[2:] = -S / self.tau + v
        return out

    def j_rest(self, t, z):
        nk = self.nk
        n = 2 + nk
        _, d1 = self.F_rest(t, z[0], z[2:])
        a = self.k16 * 1.5 * math.sqrt(d1)
        J = np.zeros((n, n))
        J[0, 1] = 1.0
        J[1, 0] = -a * self.cinf
        J[1, 2:] = -a * self.c
        for k in range(nk):
            J[2 + k, 1] = 1.0
            J[2 + k, 2 + k] = -1.0 / self.tau[k]
        return J

    def restitution(self):
        nk = self.nk
        ym = self.ym
        z0 = np.concatenate(([ym[0], ym[1]], ym[2 + nk:]))
        self.s1_guess = self.sm
        sc = np.concatenate(([self.atol_c[0], self.atol_c[1]], self.atol_c[2 + nk:]))
        self.atol = sc
        cinf, c = self.cinf, self.c

        def ev(t, z):
            return cinf * z[0] + c @ z[2:]
        ev.terminal = True
        ev.direction = -1
        tmax = self.tm + 50.0 * self.tc0 + 50 * HERTZ_TC
        sol = self._ivp(self.f_rest, (self.tm, tmax), z0, self.j_rest, events=[ev])
        if sol.status != 1:
            raise RuntimeError('restitution: no end ' + str(sol.message))
        te = sol.t_events[0][0]
        ta, za = sol.t[-2], sol.y[:, -2]
        self.nrest_steps = len(sol.t)
        for it in range(3):
            self.s1_guess = 0.0
            r = self._ivp(self.f_rest, (ta, te), za, self.j_rest)
            ze = r.y[:, -1]
            g = ev(te, ze)
            dz = self.f_rest(te, ze)
            dg = cinf * dz[0] + c @ dz[2:]
            dt = -g / dg
            te += dt
            if abs(dt) < 1e-15 * te:
                break
        r = self._ivp(self.f_rest, (ta, te), za, self.j_rest)
        ze = r.y[:, -1]
        self.te = te
        self.ze = ze
        return -ze[1], te

    def run(self):
        self.compression()
        e, te = self.restitution()
        return dict(cor=e, contact_time=te, max_indentation=self.ym[0],
                    tm=self.tm, nsteps=(self.ncomp_steps, self.nrest_steps))


def solve(nu, p2, p3, **kw):
    return CoR(nu, p2, p3, **kw).run()


DOP_TAU_MIN = 1e-2   # use explicit DOP853 (independent method) when tau >= this


def reference(nu, p2, p3):
    """main + check run; returns dict with est_rel_err = |cor_main-cor_check|/cor
    (floored at 1e-14)."""
    t0 = time.time()
    tau = p2 * p3
    if tau >= DOP_TAU_MIN:
        mm = dict(method='DOP853', rtol=3e-14)
    else:
        mm = dict(method='Radau', rtol=1e-13, K=8)
    mc = dict(method='Radau', rtol=1e-12, K=6)
    a = solve(nu, p2, p3, **mm)
    b = solve(nu, p2, p3, **mc)
    err = max(abs(a['cor'] - b['cor']) / abs(a['cor']), 1e-14)
    return dict(nu=nu, p2=p2, p3=p3, cor=a['cor'], contact_time=a['contact_time'],
                max_indentation=a['max_indentation'], est_rel_err=err,
                main=mm['method'], cor_check=b['cor'],
                tc_rel_diff=abs(a['contact_time'] / b['contact_time'] - 1),
                dmax_rel_diff=abs(a['max_indentation'] / b['max_indentation'] - 1),
                seconds=time.time() - t0)


def _ref_safe(args):
    import warnings
    warnings.simplefilter('ignore')
    try:
        return reference(*args)
    except Exception as ex:  # report, do not abort the grid
        return dict(nu=args[0], p2=args[1], p3=args[2], error=repr(ex))


def grid_points():
    pts = []
    for nu in [-0.9, -0.5, 0.0, 0.3, 0.45, 0.49, 0.499, 0.5]:
        for l2 in [-4, -3, -2, -1, 0, 1, 2]:
            for l3 in [-3, -2, -1, -0.5, 0, 0.5, 1, 2, 3, 4]:
                pts.append((nu, 10.0 ** l2, 10.0 ** l3))
    rng = np.random.default_rng(1)
    nus = rng.uniform(-0.99, 0.5, 100)
    l2s = rng.uniform(-4.0, 2.0, 100)
    l3s = rng.uniform(-3.0, 4.0, 100)
    for nu, l2, l3 in zip(nus, l2s, l3s):
        pts.append((float(nu), 10.0 ** l2, 10.0 ** l3))
    return pts


def corner_points():
    # the most dissipative corner of the range (CoR down to ~5e-4): 60 random points
    rng = np.random.default_rng(2)
    nus = rng.uniform(-0.99, 0.5, 60)
    l2s = rng.uniform(-4.0, -2.5, 60)
    l3s = rng.uniform(0.5, 2.3, 60)
    pts = [(float(nu), 10.0 ** l2, 10.0 ** l3) for nu, l2, l3 in zip(nus, l2s, l3s)]
    # and its extreme edge (nu -> -1, p2 = 1e-4): the smallest CoR of the range, ~5e-4
    for nu in [-0.99, -0.95, -0.9, -0.5]:
        for p2 in [1e-4, 1.5e-4]:
            for p3 in [50.0, 80.0]:
                pts.append((nu, p2, p3))
    # groups with CoR < 0.002 found among 5000 random points (seed 7) checked against the crate's
    # own reference solver, where an earlier version of its `fast` solver missed rtol = 1e-6
    # (up to 4e-6), and two more from a 100000-point batch
    pts += [
        (-0.6119995785262256, 0.00015536819728154824, 44.77226299000736),
        (-0.04028869925543532, 0.00011575527369478646, 65.61615155087266),
        (-0.8196660691656366, 0.0002608153375600203, 38.94123938279773),
        (-0.9829232428436594, 0.0001418830392152847, 68.88640051496428),
        (-0.841024458883741, 0.00010741371811654466, 57.77775941210965),
        (-0.256367196127388, 0.00017271621473142535, 55.99465436181105),
        (-0.9481100479699118, 0.00020087851066887482, 56.10350788458204),
        (-0.8035891682482896, 0.0001692315818654534, 61.398774162721914),
        (-0.8973090960838359, 0.00010690725163324156, 57.28203038019462),
        (-0.22761680833300124, 0.00011978557648755152, 52.212937340142275),
        (-0.4965477503337593, 0.00014537850800417057, 46.4970655427448),
        (-0.5757653566237007, 0.00010449387312745878, 56.2561742110363),
        (-0.8858089682026211, 0.00010293193284230261, 65.52348520974131),
        (-0.008515428859206309, 0.00010456559447761422, 85.09387800086242),
        (-0.0487695264734509, 0.00011228155867438105, 74.41297623026385),
        (-0.5853921552718184, 0.00011741961263122137, 62.692826107643576),
        (-0.5448569295735728, 0.0001534477865789188, 45.58583264392536),
        (-0.7470615525110309, 0.00014826817172503207, 62.50707252944973),
        (-0.4537288698018176, 0.00012857328645180075, 72.62231644244592),
        (-0.9715181900146992, 0.00010580662598151772, 76.94252573935694),
        (-0.6133924153400414, 0.0001332013217388037, 46.176325981150164),
        (-0.6563671496249801, 0.00010712384382311017, 55.23580408315748),
        (-0.1576118622186472, 0.00019671911519370964, 54.647575342713196),
        (-0.6948275324381943, 0.00022797544842454996, 43.222429873637154),
        (-0.52654937787954, 0.00012299237747762193, 46.62051847288303),
        (-0.3763981289989221, 0.00010793878240001379, 60.83202187391501),
        (-0.6898025809248969, 0.00022883118584121907, 44.79072878274209),
        (-0.9546431735508178, 0.0004141211459845676, 36.94205472640575),
        (-0.8637184681962737, 0.00010034710288792148, 84.20362233059502),
    ]
    return pts


def glassy_points():
    # the glassy corner G_0 / G_inf >= 1e5 (p2 <= 1e-5): the 19 rows of the crate's stress run
    # (`mdr-impact stress`, 5000 rows, seed 1) where its `fast` and `reference` solvers disagreed
    # beyond rtol 1e-10 / 1e-11, the three rows where `fast` once missed rtol 1e-6 by 11x to 41x,
    # and the two glassy catalogue cases; then two rows of a second stress run
    return [
        (0.5, 5.328934363710385e-8, 1.0064524118988043e3),
        (-0.28707228709668076, 1.8912661753001934e-8, 6.161641823138884e2),
        (0.14733475359526582, 7.71365796065113e-8, 3.1541611541886596e2),
        (-0.43199850887542546, 1.6664606917734325e-8, 1.9035769988044842e2),
        (0.5, 1.9346660547414204e-7, 2.1222769517982564e2),
        (0.5, 1.969197696178696e-8, 7.087258876707235e2),
        (-0.6307077696374037, 7.564247345377573e-7, 2.2898060977967566e2),
        (0.5, 4.26951480945505e-8, 5.751361626450921e3),
        (-0.07951445834491044, 5.394251137873905e-8, 9.98963181093141e2),
        (-0.21618401398301046, 2.447264644315916e-8, 1.9235082932280977e3),
        (-0.1970402089921699, 7.156768348738605e-8, 2.209119954596536e3),
        (0.09905353161528374, 1.789167660946833e-8, 8.579079755030929e2),
        (-0.6183875636167493, 8.799676799042e-8, 8.139656141400994e2),
        (0.5, 6.546909522282015e-8, 7.121634332999923e2),
        (0.024331334614953015, 1.110019536842662e-7, 5.2237299804726035e3),
        (0.0901157244202121, 2.7613609277956433e-7, 1.003123485043436e3),
        (0.25111059728790863, 2.688859944357129e-8, 2.9344514960191227e3),
        (-0.1788609170609311, 5.06704057971389e-8, 1.9016285516943772e3),
        (-0.27692250341191693, 1.0455568036675751e-6, 9.775077189775463e1),
        (0.5, 1e-6, 724.43596007498911),
        (-0.41203258205740656, 1.4753274411455244e-07, 1664.165931457365),
        (-0.3395292848110374, 4.5154341207008734e-07, 1685.543050300158),
        (0.45, 1e-6, 1e4),
        (0.5, 1e-7, 1e4),
        # where the reference, refusing rtol e < 1e-12 there, was still 1.6x and 2.1x off at
        # rtol 1e-8 (a second stress run)
        (-0.9046865292688011, 1.2524662586622674e-8, 1.5155369722433988e2),
        (0.5, 1.3139105905300423e-8, 1.0910241925328017e2),
    ]


def run_grid(out='cor_ref.csv', diag='cor_ref_diag.csv', nproc=2, pts=None):
    from multiprocessing import Pool
    pts = grid_points() if pts is None else pts
    t0 = time.time()
    with Pool(nproc) as pool:
        res = []
        for i, r in enumerate(pool.imap(_ref_safe, pts, chunksize=1)):
            res.append(r)
            if 'error' in r:
                print('ERROR', r, flush=True)
            elif i % 20 == 0:
                print(i, '%.0fs' % (time.time() - t0), r['nu'], r['p2'], r['p3'],
                      r['cor'], '%.1e' % r['est_rel_err'], flush=True)
    with open(out, 'w') as f:
        f.write('nu,p2,p3,cor,contact_time,max_indentation,est_rel_err\n')
        for r in res:
            if 'error' in r:
                f.write('%.17g,%.17g,%.17g,nan,nan,nan,nan\n' % (r['nu'], r['p2'], r['p3']))
            else:
                f.write(','.join('%.17g' % r[k] for k in
                                 ['nu', 'p2', 'p3', 'cor', 'contact_time',
                                  'max_indentation', 'est_rel_err']) + '\n')
    with open(diag, 'w') as f:
        f.write('nu,p2,p3,main_method,cor,cor_check_radau_rtol1e-12_K6,est_rel_err,'
                'tc_rel_diff,dmax_rel_diff,seconds,error\n')
        for r in res:
            if 'error' in r:
                f.write('%.17g,%.17g,%.17g,,,,,,,,"%s"\n' % (r['nu'], r['p2'], r['p3'], r['error']))
            else:
                f.write('%.17g,%.17g,%.17g,%s,%.17g,%.17g,%.3e,%.3e,%.3e,%.2f,\n' % (
                    r['nu'], r['p2'], r['p3'], r['main'], r['cor'], r['cor_check'],
                    r['est_rel_err'], r['tc_rel_diff'], r['dmax_rel_diff'], r['seconds']))
    print('total %.0fs' % (time.time() - t0))


if __name__ == '__main__':
    if len(sys.argv) > 1 and sys.argv[1] == '--grid':
        run_grid()
    elif len(sys.argv) > 1 and sys.argv[1] == '--glassy':
        run_grid('cor_ref_glassy.csv', 'cor_ref_glassy_diag.csv', pts=glassy_points())
    elif len(sys.argv) > 1 and sys.argv[1] == '--corner':
        run_grid('cor_ref_corner.csv', 'cor_ref_corner_diag.csv', pts=corner_points())
    else:
        nu, p2, p3 = map(float, sys.argv[1:4])
        print(reference(nu, p2, p3))
