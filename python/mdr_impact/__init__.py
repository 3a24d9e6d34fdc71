"""Normal impact of a rigid sphere (or two bodies) on compressible linear-viscoelastic material.

A Python interface to the Rust library ``mdr-impact``: the Method of Dimensionality Reduction
(MDR) solver of Willert et al., *The influence of compressibility on the restitution
coefficient for viscoelastic spheres in low-velocity normal impacts*, with the Lee-Radok/Ting
reference theory and a reduced solver. The Rust library is the single source of the physics;
this package converts types. SI units in and out throughout.

Functions
---------
cor(nu, p2, p3, rtol=1e-6, solver="auto", full_output=False)
    Coefficient of restitution from the dimensionless groups of Eq. (11), vectorised over numpy
    arrays (broadcasting), solved in parallel.
impact(target, ...)
    One impact (a ``Scene``, or a material with sphere and velocity): an ``ImpactResult``.
curve(scene, v0)
    CoR, contact time, maximum force and compression of a scene at many impact velocities.
dem(scene, v0=(min, max, n), log=False, modulus="relaxed")
    DEM damping laws (LAMMPS, LIGGGHTS) fitted to the scene's CoR against impact velocity.
fit(data, scene=None, model="standard-solid", fix=None, tau_range=None, out=None)
    Material parameters from drop tests, with intervals (``mdr-impact fit``).

Classes
-------
Material, GeneralMaterial, Prony, Sphere (profile: paraboloid or exact sphere), Indenter (cone,
power law, flat punch, ...), Body, Scene (``temperature=``), Shift (WLF or Arrhenius, a material's
``shift=``), ImpactResult, Curve; ``Error`` (a
``ValueError``) for bad input and refused solves, with the message the command line prints.

``__version__`` is the package's version (as ``importlib.metadata.version("mdr-impact")``),
that of the ``mdr-impact`` crate and of ``mdr-impact --version``.

Example
-------
>>> import mdr_impact as mi
>>> round(mi.Scene.default().run().cor, 4)
0.4094
"""

from __future__ import annotations

import json
import operator

import numpy as np

from . import _core
from ._core import (
    DEFAULT_RTOL,
    DEFAULT_SCENE,
    MAX_RTOL,
    MIN_RTOL,
    SOLVERS,
    Body,
    Error,
    GeneralMaterial,
    ImpactResult,
    Indenter,
    Material,
    Prony,
    Scene,
    Shift,
    Sphere,
    __version__,
)

__all__ = [
    "DEFAULT_RTOL",
    "DEFAULT_SCENE",
    "MAX_RTOL",
    "MIN_RTOL",
    "SOLVERS",
    "Body",
    "Curve",
    "Error",
    "GeneralMaterial",
    "ImpactResult",
    "Indenter",
    "Material",
    "Prony",
    "Scene",
    "Shift",
    "Sphere",
    "angle_curve",
    "catalogue",
    "cor",
    "curve",
    "dem",
    "fit",
    "impact",
    "oblique",
    "prony",
]


def _floats(name, x):
    """``x`` as a float64 array; anything but real numbers (strings, complex numbers, ``None``,
    objects) is an ``Error`` naming ``name``, never silently converted."""
    try:
        a = np.asarray(x)
    except (TypeError, ValueError) as e:
        raise Error(f"{name}: not a real number or array of real numbers ({e})") from None
    if a.dtype.kind not in "biuf":
        raise Error(f"{name}: not a real number or array of real numbers (dtype {a.dtype})")
    return a.astype(np.float64, copy=False)


def cor(nu, p2, p3, rtol=DEFAULT_RTOL, solver="auto", full_output=False):
    """Coefficient of restitution from the dimensionless groups of Eq. (11).

    The impact of a rigid sphere on a half-space of the paper's standard solid (shear
    ``G(t) = G_inf + G_1 exp(-t / tau)``, elastic bulk) depends only on

    - ``p1 = nu``, the static Poisson ratio, ``-1 < nu <= 0.5`` (0.5: incompressible);
    - ``p2 = G_inf / G_1``, ``0 < p2 < inf``;
    - ``p3 = eta (v0 R / (m^2 G_inf^3))^(1/5)``, ``0 <= p3 < inf`` (0: elastic, Hertz, ``e = 1``).

    Parameters
    ----------
    nu, p2, p3 : float or array_like
        The groups; broadcast against each other with numpy's rules. Every value must be finite.
    rtol : float, optional
        Requested relative accuracy of each CoR, ``1e-12 <= rtol <= 0.1`` (default ``1e-6``).
        Every answer is verified to it or refused.
    solver : {"auto", "fast", "reference", "mdr", "mdr-euler"}, optional
        ``auto`` (default) answers with the reduced solver ``fast`` and falls back to
        ``reference`` (Lee-Radok/Ting) when ``fast`` refuses.
    full_output : bool, optional
        Also return the contact time and the maximum indentation, in canonical units
        ``m = R = v0 = G_inf = 1`` (the columns of ``mdr-impact cor --input``).

    Returns
    -------
    cor : float or ndarray
        The CoR, of the broadcast shape; a float when all three inputs are scalars.
    contact_time, max_indentation : float or ndarray
        Only with ``full_output=True``.

    Raises
    ------
    Error
        (a ``ValueError``) for a value out of range or not finite, naming the group and, for
        arrays, the index (``index (1, 2): p2 = -1e0 is out of range: allowed ...``), a bad
        ``rtol`` or ``solver``, or a solve that cannot be verified to ``rtol``; the message after
        the index is the one ``mdr-impact cor`` prints. Nothing is returned then.

    Notes
    -----
    The elements are solved in parallel on all cores with the GIL released, in chunks between
    which Ctrl-C (``KeyboardInterrupt``) ends the call; the results equal
    ``mdr-impact cor --input`` on the same rows bit for bit. Willert et al., Eqs. (10)-(11).

    Examples
    --------
    >>> import numpy as np, mdr_impact as mi
    >>> e = mi.cor(0.45, np.logspace(-3, 0, 4)[:, None], np.array([0.1, 1.0, 10.0]))
    >>> e.shape
    (4, 3)
    """
    try:
        arrays = np.broadcast_arrays(_floats("nu", nu), _floats("p2", p2), _floats("p3", p3))
    except ValueError as e:
        if isinstance(e, Error):
            raise
        raise Error(f"nu, p2, p3: shapes cannot be broadcast together ({e})") from None
    shape = arrays[0].shape
    # contiguous and aligned copies where needed (arrays that arrive pickled, e.g. a dask
    # chunk on a worker, can be misaligned views of a byte buffer)
    flat = [np.require(a, dtype=np.float64, requirements=["C", "A"]).reshape(-1) for a in arrays]
    c, t, d = _core.cor_groups(flat[0], flat[1], flat[2], list(shape), float(rtol), str(solver))
    out = tuple(float(x) if shape == () else x for x in (c, t, d))
    return out if full_output else out[0]


def impact(target, *, velocity=None, mass=None, radius=None, solver=None, rtol=None,
           history=None):
    """One impact: CoR, contact time, maximum force and the rest, optionally with histories.

    Parameters
    ----------
    target : Scene, Material or GeneralMaterial
        A ``Scene`` (its sphere or bodies, material(s), velocity and solver), or the half-space
        material, then with ``mass``, ``radius`` and ``velocity``.
    velocity : float, optional
        Impact velocity (m/s), ``0 < v0 < inf``; replaces a scene's.
    mass, radius : float, optional
        The rigid sphere (kg, m); only with a material.
    solver : str, optional
        ``auto`` (default), ``fast``, ``reference``, ``mdr`` or ``mdr-euler``; replaces a
        scene's.
    rtol : float, optional
        Requested relative accuracy of the CoR (default ``1e-6``); replaces a scene's.
    history : bool, optional
        Also return the histories ``t, d, v, force, a`` as numpy arrays (SI). The default
        ``None`` returns them when the scene has ``[output]`` paths (as ``mdr-impact run``
        computes them then; with ``solver="auto"`` they are then sampled from the reference
        solution, so the CoR can differ from a CoR-only solve within ``rtol``), never for a
        material.

    Returns
    -------
    ImpactResult
        ``cor``, ``rebound_velocity`` (m/s), ``contact_time`` (s), ``max_indentation`` (m),
        ``time_of_max_indentation`` (s), ``max_force`` (N), ``max_contact_radius`` (m),
        ``dissipated_energy`` (J), ``solver``, ``estimated_rel_error``, ``fallback``, ``work``,
        ``history`` (dict of arrays or ``None``), ``bodies`` (two bodies only).

    Raises
    ------
    Error
        (a ``ValueError``) with the message of ``mdr-impact run``.

    Examples
    --------
    >>> import mdr_impact as mi
    >>> m = mi.Material(1.0e6, 1.0e7, 500.0, poisson=0.49)
    >>> r = mi.impact(m, mass=4.11e-3, radius=5.0e-3, velocity=0.99)
    >>> r.cor == mi.Scene.default().run(history=False).cor
    True
    """
    if isinstance(target, Scene):
        if mass is not None or radius is not None:
            raise Error("mass and radius belong to the scene: give a material to set them")
        scene = target
        if solver is not None or rtol is not None:
            scene = scene.with_solver(solver=solver, rtol=rtol)
        if velocity is not None:
            scene = scene.with_velocity(velocity)
    else:
        if mass is None or radius is None or velocity is None:
            raise Error("impact(material, ...) needs mass (kg), radius (m) and velocity (m/s)")
        scene = Scene(
            sphere=Sphere(mass, radius),
            material=target,
            velocity=velocity,
            solver="auto" if solver is None else solver,
            rtol=DEFAULT_RTOL if rtol is None else rtol,
        )
        history = bool(history)
    return scene.run(history=history)


class Curve:
    """CoR against impact velocity of one scene (the result of ``curve``).

    Attributes
    ----------
    v0 : ndarray
        Impact velocities (m/s), as given.
    cor : ndarray
        Coefficient of restitution at each velocity.
    contact_time : ndarray
        Contact time (s).
    max_force : ndarray
        Maximum contact force (N).
    max_compression : ndarray
        Maximum compression = maximum indentation (m).
    contact_radius_ratio, indentation_ratio : ndarray
        ``a_max / R`` and ``d_max / R`` at each velocity (the model's validity measures).
    wave_transit_ratio : ndarray
        Transit time of shear waves over the contact diameter against the contact time (the
        quasi-static check; NaN where the scene gives no ``density``).
    outside_validity : ndarray of bool
        Where the answer carries a validity warning (``ImpactResult.warnings``): a contact too
        large for the paraboloid, or elastic waves too slow for the quasi-static model.
    limits : dict
        The elastic limits of the material (see ``mdr-impact curve``): ``relaxed_modulus`` and
        ``glassy_modulus`` (plane-strain ``E* = 4 G_eq``, Pa), ``p3_unit_velocity`` (m/s, the
        standard solid's ``p3 = 1``, near which the CoR is smallest), ``slowest_tau``,
        ``fastest_tau`` (s), ``relaxed_crossover``, ``glassy_crossover`` (m/s, general
        materials); ``None`` where not defined.
    """

    def __init__(self, values):
        """From the binding's dict of arrays (SI) and limits; made by ``curve``."""
        self.v0 = values["v0"]
        self.cor = values["cor"]
        self.contact_time = values["contact_time"]
        self.max_force = values["max_force"]
        self.max_compression = values["max_compression"]
        self.contact_radius_ratio = values["contact_radius_ratio"]
        self.indentation_ratio = values["indentation_ratio"]
        self.wave_transit_ratio = values["wave_transit_ratio"]
        self.outside_validity = values["outside_validity"]
        self.limits = dict(values["limits"])

    def __len__(self):
        return self.v0.size

    def __repr__(self):
        return f"Curve(v0 of shape {self.v0.shape}, cor from {self.cor.min(initial=np.inf):.6g} " \
            f"to {self.cor.max(initial=-np.inf):.6g})"


def curve(scene, v0):
    """CoR against impact velocity: ``scene`` solved at every velocity of ``v0``.

    The sphere (or bodies), material(s) and solver settings of ``scene`` are kept; only the
    impact velocity changes. The rows equal ``mdr-impact curve`` (and ``Scene.run`` at each
    velocity) bit for bit.

    Parameters
    ----------
    scene : Scene
        The impact (for example ``Scene.default()`` or ``Scene.load("my.toml")``).
    v0 : float or array_like
        Impact velocities (m/s), each finite and ``> 0``; any shape, any order.

    Returns
    -------
    Curve
        Arrays ``v0``, ``cor``, ``contact_time`` (s), ``max_force`` (N), ``max_compression`` (m)
        of the shape of ``v0``, and the material's ``limits``.

    Raises
    ------
    Error
        (a ``ValueError``) naming the index and velocity of the first failing solve
        (``index (3,): at v0 = -1e0 m/s: velocity = ...``).

    Examples
    --------
    >>> import numpy as np, mdr_impact as mi
    >>> c = mi.curve(mi.Scene.default(), np.logspace(-2, 1, 50))
    >>> c.cor.shape, bool(np.all((c.cor > 0) & (c.cor < 1)))
    ((50,), True)
    """
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a Scene, not {type(scene).__name__}")
    v = _floats("v0", v0)
    flat = np.ascontiguousarray(v, dtype=np.float64).reshape(-1)
    return Curve(_core.curve_values(scene, flat, list(v.shape)))


def oblique(scene, friction=None, tangential_velocity=None, spin=None, inertia_factor=None):
    """The oblique impact of ``scene`` (docs/theory.md §14): its ``[friction]``,
    ``tangential_velocity``, ``spin`` and inertia factors, each replaced by the argument when
    given (``friction``: Coulomb coefficient; ``tangential_velocity``: m/s; ``spin``: rad/s,
    positive in the forward rolling sense; ``inertia_factor``: ``I = factor m R^2``).

    Returns a dict with ``cor``, ``solver`` and the keys of ``mdr-impact run --json``:
    ``tangential_cor``, ``tangential_cor_centre``, ``spin_after`` (rad/s),
    ``rebound_angle_deg``, ``contact_patch_rebound_angle_deg``, ``friction_dissipated_energy``
    (J), ``tangential_impulse`` (N s), ``tangential_error_estimate`` (``None`` when not
    estimated); a ratio whose initial velocity is zero is NaN.

    Examples
    --------
    >>> import mdr_impact as mi
    >>> o = mi.oblique(mi.Scene.default(), friction=0.3, tangential_velocity=0.5)
    >>> o["solver"], -1.0 < o["tangential_cor"] < 1.0
    ('mdr', True)
    """
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a Scene, not {type(scene).__name__}")
    return _core.oblique_values(scene, friction, tangential_velocity, spin, inertia_factor)


def angle_curve(scene, angles, speed, friction=None, spin=None, inertia_factor=None):
    """``mdr-impact curve --angle`` in Python: ``scene`` hit at ``speed`` (m/s) from each of
    ``angles`` (degrees from the normal, ``0 <= angle < 90``), the normal speed
    ``speed cos(angle)`` and the tangential ``speed sin(angle)``; ``friction``, ``spin`` and
    ``inertia_factor`` replace the scene's when given.

    Returns a dict of 1-D arrays with the columns of ``curve.csv``: ``angle_deg``, ``cor``,
    ``tangential_cor``, ``tangential_cor_centre``, ``rebound_angle_deg``,
    ``contact_patch_rebound_angle_deg``, ``spin_after``.
    """
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a Scene, not {type(scene).__name__}")
    a = _floats("angles", angles).reshape(-1)
    return _core.angle_curve_values(scene, [float(x) for x in a], float(speed), friction,
                                    spin, inertia_factor)


def catalogue():
    """The validation catalogue's impact cases: a list of dicts ``id``, ``regime``, ``nu``,
    ``p2``, ``p3`` (the dimensionless groups of Eq. (11); the cases of ``VALIDATION.md``), to
    pass to ``cor``."""
    return _core.catalogue_impacts()


def dem(scene, v0, log=False, modulus="relaxed"):
    """DEM damping laws fitted to the scene's CoR against impact velocity (``mdr-impact dem``).

    A DEM code (LAMMPS, LIGGGHTS) needs a Hertz stiffness and a damping law. This computes the
    scene's ``e(v0)`` over the velocity range, fits the constant-CoR law and the viscoelastic
    (Brilliantov) law with the Hertz stiffness of the relaxed or glassy ``G_eq``, integrating
    each law as the DEM code does, and reports how far each stays from the curve (see the
    README's "For DEM users").

    Parameters
    ----------
    scene : Scene
        The impact (sphere or two bodies, material(s), solver settings).
    v0 : tuple
        Impact velocities (m/s): ``(min, max)`` or ``(min, max, n)``, ``n`` velocities from
        ``min`` to ``max`` (both included; finite ``0 < min < max``, ``2 <= n <= 100000``,
        ``n = 50`` when left out). The command's text ``"MIN:MAX[:N]"`` is accepted too (then
        errors name its ``--v0``).
    log : bool, optional
        Log-spaced velocities (default: evenly spaced).
    modulus : {"relaxed", "glassy"}, optional
        Which ``G_eq`` gives the Hertz stiffness (default ``relaxed``).

    Returns
    -------
    dict
        The report of ``mdr-impact dem --format json`` (SI units: the curve, the Hertz contact,
        both laws with their parameters and errors, warnings), plus ``lammps`` and ``liggghts``:
        the input lines for those codes, as the command writes them.

    Raises
    ------
    Error
        (a ``ValueError``) for a bad range, naming ``v0`` and the part that is wrong (``v0:
        cannot read '(5.0, 0.5, 12)': expected (MIN, MAX) or (MIN, MAX, N) ...; MIN = 5e0 is
        not below MAX = 5e-1``), a bad modulus, or a failing solve (named by its velocity), with
        the command's message otherwise.

    Examples
    --------
    >>> import mdr_impact as mi
    >>> r = mi.dem(mi.Scene.default(), v0=(0.5, 5.0, 8), log=True)
    >>> r["velocities"]["n"], r["velocities"]["max"], len(r["curve"])
    (8, 5.0, 8)
    """
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a Scene, not {type(scene).__name__}")
    text, lammps, liggghts = _core.dem_report(scene, _velocities(v0), bool(log), str(modulus))
    report = json.loads(text)
    report["lammps"] = lammps
    report["liggghts"] = liggghts
    return report


def _velocities(v0):
    """``dem``'s ``v0`` for the binding: the command's text as it is, a tuple ``(min, max)`` or
    ``(min, max, n)`` as ``(min, max, n or None)``; anything else is an ``Error`` naming ``v0``."""
    if isinstance(v0, str):
        return v0
    form = "expected (MIN, MAX) or (MIN, MAX, N): velocities in m/s, N a whole number"
    try:
        parts = list(v0)
    except TypeError:
        raise Error(f"v0: {form}, not {type(v0).__name__}") from None
    if len(parts) not in (2, 3):
        raise Error(f"v0: {form}, not {len(parts)} values")
    ends = []
    for name, x in zip(("MIN", "MAX"), parts):
        a = _floats(f"v0 {name}", x)
        if a.shape != ():
            raise Error(f"v0: {name} is a number, not an array of shape {a.shape}")
        ends.append(float(a))
    n = None
    if len(parts) == 3:
        try:
            n = operator.index(parts[2])
        except TypeError:
            raise Error(f"v0: N = {parts[2]!r} is not a whole number") from None
        if abs(n) >= 2**63:
            raise Error(f"v0: N = {n} is out of range: allowed 2 <= N <= 100000")
    return (ends[0], ends[1], n)


def prony(data, terms="auto", modulus="shear", nu=None, t_ref=None, shift="wlf", out=None):
    """A Prony series and a shift law from DMA data (``mdr-impact prony``, docs/dma.md).

    Parameters
    ----------
    data : str or path
        CSV with ``frequency`` (Hz) or ``omega`` (rad/s), ``storage``, ``loss`` (Pa) and an
        optional ``temperature`` (°C) column.
    terms : "auto" or int, optional
        At most this many Prony terms (default: as many as the data carry).
    modulus : {"shear", "tensile"}, optional
        Shear moduli G', G'' or tensile E', E'' (converted with ``nu``).
    nu : float, optional
        Poisson ratio of the tensile conversion and of the written bulk (default 0.5).
    t_ref : float, optional
        Reference temperature (°C); default: the isotherm nearest 25 °C.
    shift : {"wlf", "arrhenius", "none"}, optional
        The law fitted to the isotherms' shift factors.
    out : str or path, optional
        Folder for ``material.toml``, ``prony.csv``, ``master.csv`` and ``dma.svg``.

    Returns
    -------
    dict
        The command's JSON report: ``g_inf`` (Pa), ``terms`` (``[g_i, tau_i]``, Pa and s),
        ``shift`` (the law, or None), ``log10_shift`` per temperature, ``rms_rel_error``,
        ``warnings``.

    Raises
    ------
    Error
        (a ``ValueError``) with the command's message for bad data or options.
    """
    text = _core.prony_report(str(data), str(terms), str(modulus), nu, t_ref, str(shift),
                              None if out is None else str(out))
    return json.loads(text)


def fit(data, scene=None, model="standard-solid", fix=None, tau_range=None, out=None):
    """Material parameters from drop tests (``mdr-impact fit``, docs/reference.md "Fitting").

    Parameters
    ----------
    data : str or path
        CSV ``v0,cor[,cor_sd,contact_time,contact_time_sd,setup]``: impact velocity (m/s), CoR,
        their standard deviations, contact time (s); ``setup`` names a scene file (relative to
        the data file) per row.
    scene : Scene, optional
        The impactor that was dropped (any shape) for rows without ``setup`` (default: the
        embedded default scene's sphere).
    model : str, optional
        ``"standard-solid"`` (default) or ``"prony:N"`` (N log-spaced times, fitted moduli).
    fix : dict, optional
        Parameters held fixed, in SI: ``{"nu": 0.49}``, ``{"g_inf": 1e6}``, ... (the names of
        ``--fix``).
    tau_range : tuple, optional
        ``(min, max)`` relaxation times (s) of a Prony model.
    out : str or path, optional
        Folder for ``fit.toml`` and ``fit.svg``.

    Returns
    -------
    dict
        The command's JSON report (``fit --json``): ``parameters`` and ``groups`` with values
        (SI), 95 % intervals and whether the data determine them, the goodness of fit, the
        residuals and ``warnings``.

    Raises
    ------
    Error
        (a ``ValueError``) with the command's message for bad data or options.
    """
    fixes = [] if fix is None else [(str(k), float(v)) for k, v in dict(fix).items()]
    if tau_range is not None:
        lo, hi = tau_range
        tau_range = (float(lo), float(hi))
    text = _core.fit_report(str(data), scene, str(model), fixes, tau_range,
                            None if out is None else str(out))
    return json.loads(text)
