#!/usr/bin/env python3
"""Run the input lines `mdr-impact dem` emits in the installed LAMMPS and LIGGGHTS.

For each scene the script asks `mdr-impact dem ... --format json` for the fitted laws and their
own CoR and contact time (our integration of each law, the prediction), then writes a bounce
input for every emitted line (LAMMPS: the active law and the commented "other law"; LIGGGHTS:
the constant-CoR law) at three of the curve's velocities: a sphere on the wall `zplane 0.0`, or
two identical spheres of twice the effective radius and mass colliding head-on, no gravity,
time step 2e-8 s. It runs the binary, reads the rebound velocity after the contact and the
contact time (steps with a non-zero contact force times the step) from a `fix print` trace,
and compares both with the prediction.

Bound: relative error <= 1e-4 for the CoR and the contact time. The contact time is counted in
whole steps, so it carries up to one step, dt / t_c <= 2e-8 s / 0.9 ms = 2.2e-5; the CoR's
time-step error is of the same order (velocity Verlet, the force continuous at both ends of the
contact; observed up to 2e-5 for the CoR and 5e-5 for the contact time at e = 0.2, 10 m/s).
A scene whose Young's modulus LIGGGHTS refuses (at or below 5 MPa) is run in LAMMPS only.

Stdlib only. Usage (from the repository root, after `cargo build --release`):

    python3 validation/dem_clients/verify.py [--bin target/release/mdr-impact]
        [--lmp lmp] [--liggghts liggghts] [--lammps-version 20220106] [--table FILE]
        [SCENE:V0MIN:V0MAX ...]

Exit status 0 when every run is within the bound, 1 otherwise (2 for a missing binary).
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

DT = 2e-8  # s, time step
BOUND = 1e-4  # relative, CoR and contact time
GAP = 1e-7  # m, initial gap between the surfaces
LIGGGHTS_MIN_YOUNG = 5e6  # Pa, LIGGGHTS refuses Young's moduli at or below (src/dem.rs)
DEFAULT_CASES = [
    "scenes/polymer_ball_on_steel.toml:0.5:5",
    "scenes/two_identical_spheres.toml:0.5:5",
]


def run(cmd, cwd=None):
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(
            "command failed ({}): {}\n{}{}".format(
                p.returncode, " ".join(cmd), p.stdout[-2000:], p.stderr[-2000:]
            )
        )
    return p.stdout


def dem(args, scene, vmin, vmax, fmt, out, extra=()):
    cmd = [args.bin, "dem", scene, "--v0", f"{vmin}:{vmax}", "--log", "--format", fmt]
    cmd += list(extra) + ["--out", out]
    return run(cmd)


def law_lines(text):
    """The emitted input lines of each law: {'viscoelastic': line, 'constant': line}."""
    lines = {}
    for raw in text.splitlines():
        line = raw[2:] if raw.startswith("# ") else raw
        if not re.match(r"(pair_coeff 1 2|fix wall all wall/gran granular) hertz/material", line):
            continue
        if "damping viscoelastic" in line:
            lines["viscoelastic"] = line
        elif "damping coeff_restitution" in line or "damping tsuji" in line:
            lines["constant"] = line
    return lines


def geometry_setup(hertz, v0):
    """Atoms (radius m, mass kg, z m, vz m/s) for the bounce: one sphere above the wall, or two
    identical spheres with the effective radius and mass of the contact."""
    m, r = hertz["effective_mass"], hertz["effective_radius"]
    if hertz["geometry"] == "wall":
        return [(r, m, r + GAP, -v0)]
    rr, mm = 2 * r, 2 * m
    return [(rr, mm, -(rr + GAP / 2), v0 / 2), (rr, mm, rr + GAP / 2, -v0 / 2)]


def density(radius, mass):
    return mass / (4.0 / 3.0 * math.pi * radius**3)


def lammps_input(line, hertz, v0, steps):
    atoms = geometry_setup(hertz, v0)
    wall = hertz["geometry"] == "wall"
    size = 4 * max(a[0] for a in atoms)
    s = [
        "units si",
        "atom_style sphere",
        "atom_modify map array",
        "boundary p p f" if wall else "boundary f f f",
        f"region box block {-size} {size} {-size} {size} {-GAP if wall else -size} {size}",
        "create_box 2 box",
    ]
    for i, (r, m, z, vz) in enumerate(atoms):
        s.append(f"create_atoms {i + 1} single 0.0 0.0 {z!r}")
        s.append(f"set atom {i + 1} diameter {2 * r!r} density {density(r, m)!r}")
    for i, (r, m, z, vz) in enumerate(atoms):
        s.append(f"group a{i + 1} id {i + 1}")
        s.append(f"velocity a{i + 1} set 0.0 0.0 {vz!r}")
    s += ["comm_modify vel yes", f"neighbor {GAP * 10} bin", f"timestep {DT}", "pair_style granular"]
    if wall:
        coeffs = line.replace("fix wall all wall/gran granular", "pair_coeff * *")
        s += [coeffs.replace(" zplane 0.0 NULL", ""), line]
    else:
        # the like-type lines the user supplies (no like-type contact happens here)
        s += [line.replace("pair_coeff 1 2", "pair_coeff 1 1"),
              line.replace("pair_coeff 1 2", "pair_coeff 2 2"), line]
    return s + trace_lines(len(atoms), steps)


def liggghts_input(text, hertz, v0, steps):
    atoms = geometry_setup(hertz, v0)
    wall = hertz["geometry"] == "wall"
    size = 4 * max(a[0] for a in atoms)
    s = [
        "atom_style granular",
        "atom_modify map array",
        "boundary p p f" if wall else "boundary f f f",
        "newton off",
        "communicate single vel yes",
        "units si",
        f"region box block {-size} {size} {-size} {size} {-GAP if wall else -size} {size} "
        "units box",
        "create_box 2 box",
        f"neighbor {GAP * 10} bin",
        "neigh_modify delay 0",
    ]
    # the emitted lines, unchanged
    s += [l for l in text.splitlines() if l and not l.startswith("#")]
    s.append(f"timestep {DT}")
    for i, (r, m, z, vz) in enumerate(atoms):
        s.append(f"create_atoms {i + 1} single 0.0 0.0 {z!r} units box")
        s.append(f"set atom {i + 1} diameter {2 * r!r} density {density(r, m)!r}")
    for i, (r, m, z, vz) in enumerate(atoms):
        s.append(f"group a{i + 1} id {i + 1}")
        s.append(f"velocity a{i + 1} set 0.0 0.0 {vz!r} units box")
    s.append("fix integr all nve/sphere")
    return s + trace_lines(len(atoms), steps, integrate=False)


def trace_lines(n_atoms, steps, integrate=True):
    s = ["fix integr all nve/sphere"] if integrate else []
    s += ["variable n equal step", "variable f equal fz[1]"]
    if n_atoms == 1:
        s.append("variable v equal vz[1]")
    else:
        s.append("variable v equal vz[2]-vz[1]")
    s += [
        'fix trace all print 1 "${n} ${v} ${f}" file trace.txt screen no',
        "thermo 1000000",
        f"run {steps}",
    ]
    return s


def measure(binary, lines, workdir, v0):
    with open(os.path.join(workdir, "in.bounce"), "w") as f:
        f.write("\n".join(lines) + "\n")
    run([binary, "-in", "in.bounce", "-log", "none", "-screen", "none"], cwd=workdir)
    rows = []
    with open(os.path.join(workdir, "trace.txt")) as f:
        for l in f:
            if l.startswith("#"):
                continue
            n, v, fz = l.split()
            rows.append((int(n), float(v), float(fz)))
    on = [n for n, _, fz in rows if fz != 0.0]
    if not on:
        sys.exit(f"no contact in {workdir}")
    if rows[-1][2] != 0.0:
        sys.exit(f"contact not over at the end of {workdir}")
    # the sphere moves away: the rebound velocity over the approach velocity
    cor = abs(rows[-1][1]) / v0
    return cor, (on[-1] - on[0] + 1) * DT


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("cases", nargs="*", default=DEFAULT_CASES, help="SCENE:V0MIN:V0MAX")
    ap.add_argument("--bin", default="target/release/mdr-impact")
    ap.add_argument("--lmp", default="lmp")
    ap.add_argument("--liggghts", default="liggghts")
    ap.add_argument("--lammps-version", default="20220106")
    ap.add_argument("--table", help="write the results as a Markdown table to this file")
    args = ap.parse_args()
    for b in (args.bin, args.lmp, args.liggghts):
        if shutil.which(b) is None:
            print(f"missing binary: {b}", file=sys.stderr)
            sys.exit(2)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for k, case in enumerate(args.cases):
            scene, vmin, vmax = case.rsplit(":", 2)
            base = os.path.join(tmp, str(k))
            pred = json.loads(dem(args, scene, vmin, vmax, "json", base + "j"))
            lammps = dem(args, scene, vmin, vmax, "lammps", base + "l",
                         ["--lammps-version", args.lammps_version])
            liggghts = dem(args, scene, vmin, vmax, "liggghts", base + "g")
            hertz, curve = pred["hertz"], pred["curve"]
            picks = [curve[0], curve[len(curve) // 2], curve[-1]]
            jobs = [("LAMMPS " + args.lammps_version, args.lmp, law, line)
                    for law, line in sorted(law_lines(lammps).items())]
            if hertz["young_modulus"] > LIGGGHTS_MIN_YOUNG:
                jobs.append(("LIGGGHTS 3.8.0", args.liggghts, "constant", liggghts))
            else:
                # the emitted file carries the warning; LIGGGHTS stops on it
                print(f"{scene}: E = {hertz['young_modulus']:.4e} Pa is at or below LIGGGHTS's "
                      f"limit {LIGGGHTS_MIN_YOUNG:.0e} Pa: LIGGGHTS skipped", file=sys.stderr)
            for code, binary, law, text in jobs:
                for c in picks:
                    v0 = c["v0"]
                    e_law, t_law = c["cor_" + law], c["contact_time_" + law]
                    steps = int((GAP / v0 + 1.3 * t_law) / DT) + 1000
                    work = tempfile.mkdtemp(dir=tmp)
                    if binary == args.lmp:
                        lines = lammps_input(text, hertz, v0, steps)
                    else:
                        lines = liggghts_input(text, hertz, v0, steps)
                    e, t = measure(binary, lines, work, v0)
                    rows.append((os.path.basename(scene), hertz["geometry"], code, law, v0,
                                 e, e_law, e / e_law - 1, t, t_law, t / t_law - 1))
    head = ("| scene | contact | code | law | v0 (m/s) | e (code) | e (law) | rel. error "
            "| t_c (code, s) | t_c (law, s) | rel. error |\n"
            "|---|---|---|---|---|---|---|---|---|---|---|\n")
    body = "".join(
        f"| {s} | {g} | {c} | {l} | {v:.4g} | {e:.6f} | {el:.6f} | {de:.1e} "
        f"| {t:.6e} | {tl:.6e} | {dt:.1e} |\n"
        for s, g, c, l, v, e, el, de, t, tl, dt in rows
    )
    worst_e = max(abs(r[7]) for r in rows)
    worst_t = max(abs(r[10]) for r in rows)
    foot = (f"\nworst relative error: CoR {worst_e:.1e}, contact time {worst_t:.1e} "
            f"(bound {BOUND:.0e}, time step {DT:.0e} s)\n")
    print(head + body + foot, end="")
    if args.table:
        with open(args.table, "w") as f:
            f.write(head + body + foot)
    sys.exit(0 if max(worst_e, worst_t) <= BOUND else 1)


if __name__ == "__main__":
    main()
