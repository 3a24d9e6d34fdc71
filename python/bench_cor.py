"""Time `mdr_impact.cor` against `mdr-impact cor --input` on the same rows.

    python python/bench_cor.py [--rows 100000] [--rtol 1e-6] [--repeats 5] [--seed 1]
                               [--bin target/release/mdr-impact] [--report VALIDATION.md]

Both solve the same random rows of the paper's range (nu in (-0.99, 0.5], log10 p2 in [-4, 2],
log10 p3 in [-3, 4], as `mdr-impact bench --batch-rows`) with the default solver, all cores; the
command line reads them from a CSV file and prints CSV, the package takes and returns numpy
arrays. Prints both median wall times and checks that the results agree bit for bit. With
`--report`, replaces the body of section 10 of VALIDATION.md (between `<!-- python:begin -->` and
`<!-- python:end -->`, written by `mdr-impact validate`) with the measurement.
"""

import argparse
import os
import pathlib
import platform
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

# run as `python python/bench_cor.py`, the script's folder (python/, the package's sources
# without the compiled extension) would shadow the installed package
_HERE = pathlib.Path(__file__).resolve().parent
sys.path = [p for p in sys.path if pathlib.Path(p or ".").resolve() != _HERE]

import mdr_impact as mi  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
BEGIN, END = "<!-- python:begin -->", "<!-- python:end -->"


def rows(n, seed):
    """`n` random (nu, p2, p3) rows of the paper's range, reproducible from `seed`."""
    u = np.random.default_rng(seed).random((3, n))
    return 0.5 - 1.49 * u[0], 10.0 ** (-4.0 + 6.0 * u[1]), 10.0 ** (-3.0 + 7.0 * u[2])


def cpu():
    try:
        for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rows", type=int, default=100_000)
    ap.add_argument("--rtol", type=float, default=mi.DEFAULT_RTOL)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--seed", type=int, default=1)
    target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    ap.add_argument("--bin", type=pathlib.Path, default=target / "release" / "mdr-impact")
    ap.add_argument("--report", type=pathlib.Path)
    args = ap.parse_args()
    if not args.bin.is_file():
        sys.exit(f"error: {args.bin} not found: build it with `cargo build --release` or give --bin")
    if args.rows < 1 or args.repeats < 1:
        sys.exit("error: --rows and --repeats must be at least 1")

    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    nu, p2, p3 = rows(args.rows, args.seed)
    with tempfile.TemporaryDirectory() as tmp:
        csv_in = pathlib.Path(tmp) / "rows.csv"
        csv_out = pathlib.Path(tmp) / "out.csv"
        with open(csv_in, "w") as f:
            f.write("nu,p2,p3\n")
            f.writelines(f"{a!r},{b!r},{c!r}\n" for a, b, c in zip(nu.tolist(), p2.tolist(), p3.tolist()))
        cli_times, py_times = [], []
        for _ in range(args.repeats):
            with open(csv_out, "w") as out:
                t0 = time.perf_counter()
                subprocess.run([str(args.bin), "cor", "--input", str(csv_in), "--rtol",
                                repr(args.rtol)], stdout=out, check=True)
                cli_times.append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            e, t, d = mi.cor(nu, p2, p3, rtol=args.rtol, full_output=True)
            py_times.append(time.perf_counter() - t0)
        table = np.loadtxt(csv_out, delimiter=",", skiprows=1, ndmin=2)
    same = (np.array_equal(table[:, 3], e) and np.array_equal(table[:, 4], t)
            and np.array_equal(table[:, 5], d))
    t_cli, t_py = statistics.median(cli_times), statistics.median(py_times)
    print(f"mdr-impact cor --input: {args.rows} rows in {t_cli:.2f} s (median of {args.repeats})")
    print(f"mdr_impact.cor:         {args.rows} rows in {t_py:.2f} s (median of {args.repeats})")
    print(f"ratio python / command line: {t_py / t_cli:.2f}; results bit for bit equal: {same}")
    if not same:
        sys.exit("error: the package and the command line disagree")
    if args.report:
        section = (
            f"Measured by `python python/bench_cor.py {' '.join(sys.argv[1:])}` on {cpu()}, "
            f"{os.cpu_count()} cores (load average {load:.1f} at the start: other work shares "
            f"them), Python {platform.python_version()}, numpy "
            f"{np.__version__}: {args.rows} random rows of the paper's range (seed {args.seed}; "
            f"nu in (-0.99, 0.5], log10 p2 in [-4, 2], log10 p3 in [-3, 4]), solver auto, "
            f"rtol {args.rtol:g}, all cores; median wall time of {args.repeats} runs, the two paths "
            f"alternating. "
            f"Machine-dependent, so not part of the staleness check.\n\n"
            f"| path | time for {args.rows} rows |\n| --- | --- |\n"
            f"| `mdr_impact.cor(nu, p2, p3)` (numpy arrays in and out, in-process) | "
            f"{t_py:.2f} s |\n"
            f"| `mdr-impact cor --input rows.csv` (a process: reads CSV, solves, prints CSV) | "
            f"{t_cli:.2f} s |\n\n"
            f"Ratio package / command line: {t_py / t_cli:.2f}. The CoR, contact time and "
            f"maximum indentation of every row are bit for bit equal on both paths (the same "
            f"library function, `batch::solve_groups`).\n"
        )
        text = args.report.read_text()
        b, e_ = text.find(BEGIN), text.find(END)
        if b < 0 or e_ < b:
            sys.exit(f"error: {args.report} has no {BEGIN} ... {END}: run `mdr-impact validate` "
                     "first")
        new = text[: b + len(BEGIN)] + "\n" + section + text[e_:]
        tmp = args.report.with_name(args.report.name + ".tmp")
        tmp.write_text(new)
        os.replace(tmp, args.report)
        print(f"section 10 of {args.report} updated")


if __name__ == "__main__":
    main()
