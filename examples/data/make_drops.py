#!/usr/bin/env python3
"""Makes examples/data/drops.csv: a synthetic drop test of the default scene's steel ball on its
elastomer (g_inf = 1 MPa, g_1 = 10 MPa, eta = 500 Pa s, nu = 0.49), ten drops from 0.2 to 1.2 m/s (inside the model's validity, a_max/R < 0.35),
CoR and contact time with 1 % Gaussian noise (seed 7) and those standard deviations given.

Run from the repository root after `cargo build --release`:
    python3 examples/data/make_drops.py
"""
import csv
import io
import random
import subprocess
import tempfile

with tempfile.TemporaryDirectory() as out:
    subprocess.run(["target/release/mdr-impact", "curve", "--v0", "0.2:1.2:10", "--out", out],
                   check=True, capture_output=True)
    rows = list(csv.DictReader(open(f"{out}/curve.csv")))
rng = random.Random(7)
text = io.StringIO()
w = csv.writer(text, lineterminator="\n")
w.writerow(["v0", "cor", "cor_sd", "contact_time", "contact_time_sd"])
for r in rows:
    e, t = float(r["cor"]), float(r["contact_time"])
    e_m, t_m = e * (1 + 0.01 * rng.gauss(0, 1)), t * (1 + 0.01 * rng.gauss(0, 1))
    w.writerow([f"{float(r['v0']):.6g}", f"{e_m:.5g}", f"{0.01 * e:.3g}", f"{t_m:.5g}", f"{0.01 * t:.3g}"])
open("examples/data/drops.csv", "w").write(text.getvalue())
