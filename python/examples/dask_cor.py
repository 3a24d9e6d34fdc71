"""CoR over a chunked dask array on a dask.distributed cluster (docs/reference.md, Python).

Each chunk of (nu, p2, p3) goes to a worker, which calls ``mdr_impact.cor`` on it (one call per
chunk: the Rust library solves the chunk's rows in parallel on the worker's cores). The same code
runs on any dask cluster: replace ``LocalCluster`` by the scheduler address of yours.

Checks, against one call of ``mdr_impact.cor`` on the whole array, that every value is the same
to the last bit (each row is solved independently, so chunking changes nothing) and prints the
timing. Run: ``python python/examples/dask_cor.py [ROWS]`` (default 20000).
"""

import sys
import time

import dask.array as da
import numpy as np
from dask.distributed import Client, LocalCluster

import mdr_impact as mi


def cor_chunk(nu, p2, p3):
    """The CoR of one chunk (numpy arrays of the same shape), as numpy."""
    return mi.cor(nu, p2, p3)


def main(rows):
    rng = np.random.default_rng(1)
    nu = rng.uniform(-0.5, 0.5, rows)
    p2 = 10 ** rng.uniform(-3, 2, rows)
    p3 = 10 ** rng.uniform(-2, 3, rows)
    chunk = max(rows // 8, 1)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True) as cluster, Client(
        cluster
    ) as client:
        arrays = [da.from_array(x, chunks=chunk) for x in (nu, p2, p3)]
        start = time.perf_counter()
        e = da.map_blocks(cor_chunk, *arrays, dtype=float).compute()
        elapsed = time.perf_counter() - start
        print(f"{rows} rows in {len(arrays[0].chunks[0])} chunks on {len(client.nthreads())} "
              f"workers: {elapsed:.2f} s")
    direct = mi.cor(nu, p2, p3)
    if not np.array_equal(e, direct):
        raise SystemExit("chunked CoR differs from the direct call")
    print(f"identical to the direct call; CoR from {e.min():.4f} to {e.max():.4f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 20000)
