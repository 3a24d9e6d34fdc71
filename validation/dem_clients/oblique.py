#!/usr/bin/env python3
"""Bounce an elastic sphere obliquely in the installed LAMMPS and LIGGGHTS and compare the
tangential restitution of their tangential models with `mdr-impact`'s partial slip.

The scene (default scenes/oblique_alumina.toml: the alumina sphere of Chung & Ooi's benchmark)
gives the sphere (density, radius, inertia factor, shear modulus and Poisson ratio of an
elastic material) and the friction coefficient; the script bounces it at a fixed speed (the
scene's, |v|) and at each incidence angle (degrees from the normal) on a rigid wall, and two
such spheres against each other (one at rest), in

- LAMMPS `fix wall/gran granular` / `pair_style granular`: `hertz/material` with no normal
  damping and each tangential model of the version (`linear_history`, `mindlin`,
  `mindlin_rescale`, `mindlin/force`, `mindlin_rescale/force`; no tangential damping,
  `rolling none`, `twisting none`). The Mindlin models get `k_t = 8 G_eff` explicitly
  (force `k_t a xi`, `a = sqrt(R d)`, `1/G_eff = (2 - nu_1)/G_1 + (2 - nu_2)/G_2`: `G/(2 - nu)`
  on a rigid wall, `G/(2(2 - nu))` for two equal spheres). `linear_history` gets the constant
  `k_t = 8 G_eff a_max` (Mindlin's stiffness at the largest contact radius of the normal
  impact at that angle). `k_t NULL` is not used: on this version's wall it gave 0.48 times
  the rigid wall's stiffness for the alumina sphere. Before LAMMPS 28 Mar 2023 a wall mixes
  its modulus as `E / (2 (1 - nu))`, so the wall's `E` is `2 (1 - nu) E*`; two spheres take
  the material's `E` and `nu`, whose mixing is exact for equal spheres.
- LIGGGHTS 3.8.0 `model hertz tangential history` (pair and `fix wall/gran`), no damping
  (restitution 1), both types `E = 2 (1 - nu^2) E*` with the material's `nu` (a rigid wall:
  LIGGGHTS mixes `E*` and `G*` from both types, and this pair gives the wall's `E*` and
  `G_eff`).

Time step: the normal contact time at that angle (Hertz) over STEPS, velocity Verlet
(`nve/sphere`). After the contact it reads the centre velocities and spins, forms the contact
point's tangential velocity (`v_x - R w_y` on the wall; relative for two spheres) and reports
`tangential_cor` (after over before) and `contact_patch_rebound_angle_deg`
(`atan(v_c' / v_n')`), the conventions of docs/theory.md §14, beside `mdr-impact run --json`
of the same scene at that angle.

Check: the four Mindlin models on the wall must agree with their emulation in
`src/apps/dem/tangential.rs` (the equations of the LAMMPS documentation, integrated with the
same step), whose values the generator writes into VALIDATION.md §1g (the block between
`<!-- dem-emulation -->` markers, six decimals), within BOUND in the tangential CoR
(absolute; observed 1e-12 before the table's rounding).

A viscoelastic scene (scenes/oblique_elastomer.toml) runs instead, on the wall, the normal law
`mdr-impact dem` fits (`damping viscoelastic`) with `mindlin/force` and `mindlin_rescale/force`,
`k_t` from the relaxed or the glassy shear modulus, against `mdr`; it prints, writes no CSV and
checks nothing (the emulation is elastic).

Stdlib only. Usage (from the repository root, after `cargo build --release`):

    python3 validation/dem_clients/oblique.py [--bin target/release/mdr-impact]
        [--lmp lmp] [--liggghts liggghts] [--lammps-version 20220106]
        [--scene scenes/oblique_alumina.toml] [--angles 2,5,10,20,30,45,60] [--speed V]
        [--tuned MODEL:FACTOR] [--scan MIN:MAX:STEP [--scan-models M,...]] [--csv FILE]
        [--validation VALIDATION.md]

`--scan MIN:MAX:STEP` runs, instead, each LAMMPS model on the wall with `k_t` times each
factor and prints the factor closest to `mdr` per model. `--tuned MODEL:FACTOR` adds a run of
a LAMMPS model with `k_t` times FACTOR (default: the closest found,
`mindlin_rescale/force:0.8`). `--csv FILE` writes every run (the file VALIDATION.md §1g is
generated from: validation/dem_clients/oblique.csv). Exit status 0 when the check holds, 1
otherwise (2 for a missing binary).
"""

import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import tomllib

STEPS = 20000  # time steps per Hertz contact time
BOUND = 1e-5  # absolute, tangential CoR, real run against the emulation
# the sphere starts 5 steps of approach (and a millionth of one) away from contact: no step ends
# at an overlap of round-off size, where LAMMPS stores a step of displacement history with no
# force (the displacement-history models keep it: 1.5e-4 in the tangential CoR at 2 deg)
GAP_STEPS = 5.000001
LAMMPS_WALL_MIX_SINCE = 20230328
LAMMPS_MODELS = ["linear_history", "mindlin", "mindlin_rescale", "mindlin/force",
                 "mindlin_rescale/force"]
EMULATED = ["mindlin", "mindlin_rescale", "mindlin/force", "mindlin_rescale/force"]
DEFAULT_ANGLES = "2,5,10,20,30,45,60"
# the closest model and stiffness found (VALIDATION.md 1g): mindlin_rescale/force with k_t
# scaled by 0.8 (a scan of the factor from 0.25 to 2 in steps down to 0.005)
TUNED = "mindlin_rescale/force:0.8"
CSV_HEAD = ("geometry,angle_deg,code,model,tangential_cor,contact_patch_rebound_angle_deg,"
            "cor,mdr_tangential_cor,mdr_contact_patch_rebound_angle_deg")


def run(cmd, cwd=None):
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("command failed ({}): {}\n{}{}".format(
            p.returncode, " ".join(cmd), p.stdout[-2000:], p.stderr[-2000:]))
    return p.stdout


def sphere_of(scene):
    """The sphere of a scene: mass (kg), radius (m), inertia factor, relaxed and glassy shear
    modulus G_inf and G_0 (Pa, equal when elastic), nu. One sphere on a rigid plane (or a rigid
    sphere on the material's half-space, the same contact)."""
    if "body" in scene:
        body = scene["body"][0]
        mat = body["material"]
        shear = mat["shear"] if "shear" in mat else mat
        bulk = mat["bulk"] if "bulk" in mat else mat
        other = scene["body"][1]
        if not other.get("rigid", False):
            sys.exit("the second body must be the rigid plane")
    else:
        body = scene["sphere"]
        shear = bulk = mat = scene["material"]
    if "poisson" not in bulk:
        sys.exit("the material needs a Poisson ratio (poisson)")
    g_inf = shear["g_inf"]
    g_0 = g_inf + shear.get("g_1", 0.0) + sum(t[0] for t in shear.get("terms", []))
    r = body["radius"]
    m = body["mass"] if "mass" in body else body["density"] * 4.0 / 3.0 * math.pi * r**3
    return m, r, body.get("inertia_factor", 0.4), g_inf, g_0, bulk["poisson"]


def hertz(m, r, e_star, v_n):
    """Largest indentation (m) and contact time (s) of the elastic Hertz impact."""
    d_max = (15.0 * m * v_n**2 / (16.0 * e_star * math.sqrt(r))) ** 0.4
    return d_max, 2.943275184324705 * d_max / v_n


def toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, float):
        return "inf" if v == math.inf else repr(v)
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    return str(v)


def toml_text(d, prefix=""):
    """A TOML document of nested tables and arrays of tables (what scenes use)."""
    out = [f"{k} = {toml_value(v)}" for k, v in d.items()
           if not isinstance(v, dict) and not (isinstance(v, list) and v
                                               and isinstance(v[0], dict))]
    for k, v in d.items():
        name = f"{prefix}{k}"
        if isinstance(v, dict):
            out += ["", f"[{name}]", toml_text(v, name + ".")]
        elif isinstance(v, list) and v and isinstance(v[0], dict):
            for item in v:
                out += ["", f"[[{name}]]", toml_text(item, name + ".")]
    return "\n".join(out)


def mdr(args, scene, geometry, v_n, v_t, work):
    """`mdr-impact run --json` of the scene at (v_n, v_t), on the wall or against its twin."""
    s = json.loads(json.dumps(scene))
    s.setdefault("impact", {})
    s["impact"].update(velocity=v_n, tangential_velocity=v_t, spin=0.0)
    s.pop("output", None)
    if geometry == "spheres":
        if "body" in s:
            s["body"][1] = s["body"][0]
        else:
            sphere, mat = s.pop("sphere"), s.pop("material")
            s["body"] = [dict(sphere, material=mat), dict(sphere, material=mat)]
    path = os.path.join(work, "scene.toml")
    with open(path, "w") as f:
        f.write(toml_text(s) + "\n")
    return json.loads(run([args.bin, "run", path, "--json"]))


def atoms(geometry, r, m, v_n, v_t, gap):
    """(z, vx, vz) of the moving sphere, and of the one at rest for two spheres."""
    if geometry == "wall":
        return [(r + gap, v_t, -v_n)]
    return [(-r, 0.0, 0.0), (r + gap, v_t, -v_n)]


def lammps_input(geometry, model, p, v_n, v_t, dt, steps, version, kt_scale=1.0):
    m, r, g, nu, mu = p["m"], p["r"], p["g"], p["nu"], p["mu"]
    e_star = 2.0 * g / (1.0 - nu)
    wall = geometry == "wall"
    g_eff = g / (2.0 - nu) if wall else g / (2.0 * (2.0 - nu))
    if model == "linear_history":
        e_eff = e_star if wall else e_star / 2.0
        r_eff, m_eff = (r, m) if wall else (r / 2.0, m / 2.0)
        d_max, _ = hertz(m_eff, r_eff, e_eff, v_n)
        kt = 8.0 * g_eff * math.sqrt(r_eff * d_max)
    else:
        kt = 8.0 * g_eff
    kt *= kt_scale
    if wall:
        young = 2.0 * (1.0 - nu) * e_star if version < LAMMPS_WALL_MIX_SINCE \
            else 2.0 * (1.0 - nu * nu) * e_star
    else:
        young = 2.0 * g * (1.0 + nu)
    coeffs = (f"hertz/material {young!r} 0.0 {nu!r} tangential {model} {kt!r} 0.0 {mu!r} "
              "rolling none twisting none")
    size = 4 * r
    s = ["units si", "atom_style sphere", "atom_modify map array",
         "boundary p p f" if wall else "boundary f f f",
         f"region box block {-size} {size} {-size} {size} {-1e-7 if wall else -3 * r} {size}",
         "create_box 1 box"]
    a = atoms(geometry, r, m, v_n, v_t, GAP_STEPS * v_n * dt)
    for i, (z, vx, vz) in enumerate(a):
        s += [f"create_atoms 1 single 0.0 0.0 {z!r}",
              f"set atom {i + 1} diameter {2 * r!r} density {m / (4 / 3 * math.pi * r**3)!r}",
              f"group a{i + 1} id {i + 1}", f"velocity a{i + 1} set {vx!r} 0.0 {vz!r}"]
    s += ["comm_modify vel yes", f"neighbor {r / 100} bin", f"timestep {dt!r}",
          "pair_style granular", f"pair_coeff * * {coeffs}"]
    if wall:
        s.append(f"fix wall all wall/gran granular {coeffs} zplane 0.0 NULL")
    s.append("fix integr all nve/sphere")
    return s + trace(len(a), steps)


def liggghts_input(geometry, p, v_n, v_t, dt, steps):
    m, r, g, nu, mu = p["m"], p["r"], p["g"], p["nu"], p["mu"]
    e_star = 2.0 * g / (1.0 - nu)
    wall = geometry == "wall"
    young = 2.0 * (1.0 - nu * nu) * e_star if wall else 2.0 * g * (1.0 + nu)
    size = 4 * r
    s = ["atom_style granular", "atom_modify map array",
         "boundary p p f" if wall else "boundary f f f", "newton off",
         "communicate single vel yes", "units si", "hard_particles yes",
         f"region box block {-size} {size} {-size} {size} {-1e-7 if wall else -3 * r} {size} "
         "units box", "create_box 2 box", f"neighbor {r / 100} bin", "neigh_modify delay 0",
         f"fix m1 all property/global youngsModulus peratomtype {young!r} {young!r}",
         f"fix m2 all property/global poissonsRatio peratomtype {nu!r} {nu!r}",
         "fix m3 all property/global coefficientRestitution peratomtypepair 2 1.0 1.0 1.0 1.0",
         f"fix m4 all property/global coefficientFriction peratomtypepair 2 {mu!r} {mu!r} "
         f"{mu!r} {mu!r}",
         "pair_style gran model hertz tangential history", "pair_coeff * *",
         f"timestep {dt!r}"]
    if wall:
        s.append("fix wall all wall/gran model hertz tangential history primitive type 2 "
                 "zplane 0.0")
    a = atoms(geometry, r, m, v_n, v_t, GAP_STEPS * v_n * dt)
    for i, (z, vx, vz) in enumerate(a):
        s += [f"create_atoms 1 single 0.0 0.0 {z!r} units box",
              f"set atom {i + 1} diameter {2 * r!r} density {m / (4 / 3 * math.pi * r**3)!r}",
              f"group a{i + 1} id {i + 1}", f"velocity a{i + 1} set {vx!r} 0.0 {vz!r} units box"]
    s.append("fix integr all nve/sphere")
    return s + trace(len(a), steps)


def trace(n, steps):
    s = ["compute w all property/atom omegay"]
    fields = []
    for i in range(1, n + 1):
        s += [f"variable x{i} equal vx[{i}]", f"variable z{i} equal vz[{i}]",
              f"variable w{i} equal c_w[{i}]", f"variable p{i} equal z[{i}]",
              f"variable q{i} equal x[{i}]"]
        fields += [f"${{x{i}}}", f"${{w{i}}}", f"${{z{i}}}", f"${{p{i}}}", f"${{q{i}}}"]
    s += [f'fix out all print {steps} "RESULT {" ".join(fields)}"', "thermo 100000000",
          f"run {steps}"]
    return s


def measure(binary, lines, work, geometry, r, v_n, v_t):
    with open(os.path.join(work, "in.oblique"), "w") as f:
        f.write("\n".join(lines) + "\n")
    out = run([binary, "-in", "in.oblique", "-log", "none", "-echo", "none"], cwd=work)
    vals = [float(x) for x in [l for l in out.splitlines() if l.startswith("RESULT")][-1]
            .split()[1:]]
    if geometry == "wall":
        vx, wy, vz, z, _ = vals
        if z <= r:
            sys.exit(f"contact not over at the end of {work}")
        vc, vn = vx - r * wy, vz
    else:
        # in the frame of the line of centres at the end (it turned during the contact)
        vx1, wy1, vz1, z1, x1, vx2, wy2, vz2, z2, x2 = vals
        dist = math.hypot(x2 - x1, z2 - z1)
        if dist <= 2 * r:
            sys.exit(f"contact not over at the end of {work}")
        nx, nz = (x2 - x1) / dist, (z2 - z1) / dist
        vrx, vrz = vx2 - vx1, vz2 - vz1
        vc, vn = vrx * nz - vrz * nx - r * (wy1 + wy2), vrx * nx + vrz * nz
    return vc / v_t, math.degrees(math.atan(vc / vn)), vn / v_n


def emulation(path):
    """The emulation's tangential CoR per angle and model from VALIDATION.md §1g."""
    with open(path) as f:
        text = f.read()
    block = re.search(r"<!-- dem-emulation -->(.*?)<!-- /dem-emulation -->", text, re.S)
    if not block:
        sys.exit(f"{path}: no emulation table (<!-- dem-emulation --> block)")
    lines = [[c.strip() for c in l.strip().strip("|").split("|")]
             for l in block.group(1).splitlines() if l.startswith("|")]
    head, rows = lines[0], {}
    for cells in lines[2:]:
        rows[float(cells[0])] = {m: float(cells[head.index(m)]) for m in EMULATED}
    return rows


def viscoelastic(args, scene, p, g_0, speed, angles):
    """A viscoelastic scene: on the wall, the normal law `mdr-impact dem` fits (viscoelastic
    damping, relaxed modulus) with the two closest tangential models, `k_t` from the relaxed or
    the glassy shear modulus, against `mdr`. No emulation check (the emulation is elastic)."""
    v_ns = [speed * math.cos(math.radians(th)) for th in angles]
    with tempfile.TemporaryDirectory() as tmp:
        text = run([args.bin, "dem", args.scene, "--v0", f"{0.9 * min(v_ns)}:{1.1 * max(v_ns)}",
                    "--format", "lammps", "--lammps-version", args.lammps_version,
                    "--out", tmp])
        line = next(l for l in text.splitlines()
                    if l.startswith("fix wall all wall/gran granular hertz/material")
                    and "damping viscoelastic" in l)
        young, damp, nu_dem = line.split()[6:9]
        print(f"normal law from mdr-impact dem: {line}")
        e_star = float(young) / (2.0 * (1.0 - float(nu_dem)))
        jobs = [("mindlin/force", p["g"], 1.0, "G_inf"),
                ("mindlin_rescale/force", p["g"], 1.0, "G_inf"),
                ("mindlin_rescale/force", p["g"], 0.8, "G_inf"),
                ("mindlin_rescale/force", g_0, 1.0, "G_0"),
                ("mindlin_rescale/force", g_0, 0.8, "G_0")]
        rows = []
        for th, v_n in zip(angles, v_ns):
            v_t = speed * math.sin(math.radians(th))
            o = mdr(args, scene, "wall", v_n, v_t, tempfile.mkdtemp(dir=tmp))
            dt = hertz(p["m"], p["r"], e_star, v_n)[1] / STEPS
            for model, g, f, which in jobs:
                kt = f * 8.0 * g / (2.0 - p["nu"])
                coeffs = (f"hertz/material {young} {damp} {nu_dem} tangential {model} {kt!r} "
                          f"0.0 {p['mu']!r} rolling none twisting none damping viscoelastic "
                          "limit_damping")
                size = 4 * p["r"]
                s = ["units si", "atom_style sphere", "atom_modify map array", "boundary p p f",
                     f"region box block {-size} {size} {-size} {size} -1e-7 {size}",
                     "create_box 1 box",
                     f"create_atoms 1 single 0.0 0.0 {p['r'] + GAP_STEPS * v_n * dt!r}",
                     f"set atom 1 diameter {2 * p['r']!r} density "
                     f"{p['m'] / (4 / 3 * math.pi * p['r']**3)!r}",
                     f"velocity all set {v_t!r} 0.0 {-v_n!r}", "comm_modify vel yes",
                     f"neighbor {p['r'] / 100} bin", f"timestep {dt!r}", "pair_style granular",
                     f"pair_coeff * * {coeffs}",
                     f"fix wall all wall/gran granular {coeffs} zplane 0.0 NULL",
                     "fix integr all nve/sphere"] + trace(1, int(GAP_STEPS + 1.5 * STEPS))
                et, ang, e = measure(args.lmp, s, tempfile.mkdtemp(dir=tmp), "wall", p["r"],
                                     v_n, v_t)
                label = f"{model} k_t x{f:g} from {which}"
                rows.append((th, label, et, e, o["tangential_cor"], o["cor"]))
                print(f"{th:5g} {label:38} e_t {et:+.4f} (mdr {o['tangential_cor']:+.4f}, "
                      f"{et - o['tangential_cor']:+.4f}) e {e:.4f} (mdr {o['cor']:.4f})",
                      flush=True)
    for label in dict.fromkeys(r[1] for r in rows):
        worst = max(abs(r[2] - r[4]) for r in rows if r[1] == label)
        print(f"{label:38} max |e_t - mdr| {worst:.3f}")


def scan(args, scene, p, speed, angles):
    """Per LAMMPS model, the factor on k_t whose largest |tangential CoR - mdr| over the angles
    (wall) is smallest."""
    lo, hi, step = (float(x) for x in args.scan.split(":"))
    factors = [lo + k * step for k in range(int(round((hi - lo) / step)) + 1)]
    e_star = 2.0 * p["g"] / (1.0 - p["nu"])
    with tempfile.TemporaryDirectory() as tmp:
        cases = []
        for th in angles:
            v_n, v_t = speed * math.cos(math.radians(th)), speed * math.sin(math.radians(th))
            dt = hertz(p["m"], p["r"], e_star, v_n)[1] / STEPS
            ref = mdr(args, scene, "wall", v_n, v_t, tempfile.mkdtemp(dir=tmp))["tangential_cor"]
            cases.append((th, v_n, v_t, dt, ref))
        for model in args.scan_models.split(","):
            best = None
            for f in factors:
                worst = 0.0
                for th, v_n, v_t, dt, ref in cases:
                    lines = lammps_input("wall", model, p, v_n, v_t, dt,
                                         int(GAP_STEPS + 1.2 * STEPS) + 100,
                                         int(args.lammps_version), f)
                    et = measure(args.lmp, lines, tempfile.mkdtemp(dir=tmp), "wall", p["r"],
                                 v_n, v_t)[0]
                    worst = max(worst, abs(et - ref))
                print(f"{model:24} k_t x{f:.4g}: max |e_t - mdr| {worst:.4f}", flush=True)
                if best is None or worst < best[1]:
                    best = (f, worst)
            print(f"{model:24} closest: k_t x{best[0]:.4g}, max |e_t - mdr| {best[1]:.4f}",
                  flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default="target/release/mdr-impact")
    ap.add_argument("--lmp", default="lmp")
    ap.add_argument("--liggghts", default="liggghts")
    ap.add_argument("--lammps-version", default="20220106")
    ap.add_argument("--scene", default="scenes/oblique_alumina.toml")
    ap.add_argument("--angles", default=DEFAULT_ANGLES, help="degrees, comma separated")
    ap.add_argument("--speed", type=float, help="m/s (default: the scene's)")
    ap.add_argument("--geometries", default="wall,spheres")
    ap.add_argument("--tuned", default=TUNED,
                    help="MODEL:FACTOR, one more LAMMPS model with k_t scaled (none: skip)")
    ap.add_argument("--scan", metavar="MIN:MAX:STEP",
                    help="instead: on the wall, each LAMMPS model with k_t times each factor "
                    "from MIN to MAX; print the factor closest to mdr per model")
    ap.add_argument("--scan-models", default=",".join(LAMMPS_MODELS),
                    help="the LAMMPS models of --scan, comma separated")
    ap.add_argument("--csv", help="write every run to this CSV file")
    ap.add_argument("--validation", default="VALIDATION.md",
                    help="where the emulation's table is (none: skip the check)")
    args = ap.parse_args()
    for b in (args.bin, args.lmp, args.liggghts):
        if shutil.which(b) is None:
            print(f"missing binary: {b}", file=sys.stderr)
            sys.exit(2)
    with open(args.scene, "rb") as f:
        scene = tomllib.load(f)
    m, r, kappa, g, g_0, nu = sphere_of(scene)
    mu = scene.get("friction", {}).get("coefficient", 0.0)
    imp = scene.get("impact", {})
    speed = args.speed or math.hypot(imp.get("velocity", 0.0), imp.get("tangential_velocity", 0.0))
    if mu <= 0.0 or speed <= 0.0:
        sys.exit("the scene needs a friction coefficient and a speed")
    p = dict(m=m, r=r, kappa=kappa, g=g, nu=nu, mu=mu)
    e_star = 2.0 * g / (1.0 - nu)
    angles = [float(a) for a in args.angles.split(",")]
    if g_0 != g:
        viscoelastic(args, scene, p, g_0, speed, angles)
        return
    if args.scan:
        scan(args, scene, p, speed, angles)
        return
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for geometry in args.geometries.split(","):
            e_eff, m_eff, r_eff = (e_star, m, r) if geometry == "wall" else \
                (e_star / 2, m / 2, r / 2)
            for th in angles:
                v_n, v_t = speed * math.cos(math.radians(th)), speed * math.sin(math.radians(th))
                _, t_c = hertz(m_eff, r_eff, e_eff, v_n)
                dt = t_c / STEPS
                steps = int(GAP_STEPS + 1.2 * STEPS) + 100
                work = tempfile.mkdtemp(dir=tmp)
                o = mdr(args, scene, geometry, v_n, v_t, work)
                ref = (o["tangential_cor"], o["contact_patch_rebound_angle_deg"])
                jobs = [("LAMMPS " + args.lammps_version, args.lmp, model,
                         lammps_input(geometry, model, p, v_n, v_t, dt, steps,
                                      int(args.lammps_version)))
                        for model in LAMMPS_MODELS]
                if args.tuned != "none":
                    model, scale = args.tuned.rsplit(":", 1)
                    jobs.append(("LAMMPS " + args.lammps_version, args.lmp,
                                 f"{model} k_t x{scale}",
                                 lammps_input(geometry, model, p, v_n, v_t, dt, steps,
                                              int(args.lammps_version), float(scale))))
                jobs.append(("LIGGGHTS 3.8.0", args.liggghts, "hertz tangential history",
                             liggghts_input(geometry, p, v_n, v_t, dt, steps)))
                for code, binary, model, lines in jobs:
                    work = tempfile.mkdtemp(dir=tmp)
                    et, ang, e = measure(binary, lines, work, geometry, r, v_n, v_t)
                    rows.append((geometry, th, code, model, et, ang, e) + ref)
                    print(f"{geometry:8} {th:5g} {code:16} {model:24} e_t {et:+.5f} "
                          f"(mdr {ref[0]:+.5f}, {et - ref[0]:+.5f}) angle {ang:+8.3f} "
                          f"(mdr {ref[1]:+8.3f}) e {e:.6f}", flush=True)
    if args.csv:
        with open(args.csv, "w") as f:
            f.write(CSV_HEAD + "\n")
            for row in rows:
                f.write(",".join(str(x) for x in row) + "\n")
    ok = True
    if args.validation != "none":
        emu = emulation(args.validation)
        worst, n = 0.0, 0
        for geometry, th, code, model, et, *_ in rows:
            if geometry == "wall" and model in EMULATED and th in emu:
                worst, n = max(worst, abs(et - emu[th][model])), n + 1
        if n == 0:
            sys.exit(f"no run to check against the emulation in {args.validation}")
        print(f"worst |real run - emulation| of the tangential CoR ({', '.join(EMULATED)}, "
              f"wall, {n} runs): {worst:.1e} (bound {BOUND:.0e})")
        ok = worst <= BOUND
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
