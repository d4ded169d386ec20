"""Wall time of a sweep of 64 scenes: serial (this process) against a 2-worker Dask
LocalCluster and a 2-process pool, in one run (BENCHMARKS.md).

    python python/benches/sweep_bench.py [SCENE] [MESH]

Default: the slab-on-grade bay at 96 × 64 elements, 8 thicknesses × 8 subgrade moduli, penalty.
"""

import sys
import time

from dask.distributed import Client, LocalCluster

import liftoff


def main() -> None:
    scene = sys.argv[1] if len(sys.argv) > 1 else "example:slab-on-grade"
    mesh = [int(v) for v in (sys.argv[2] if len(sys.argv) > 2 else "96,64").split(",")]
    grid = liftoff.grid(scene, {
        "plate.thickness": [0.12, 0.14, 0.16, 0.18, 0.20, 0.23, 0.26, 0.30],
        "foundation.modulus": [1e7, 1.5e7, 2e7, 3e7, 4.5e7, 7e7, 1e8, 1.5e8],
    })
    opts = {"method": "penalty", "mesh": mesh}
    t0 = time.perf_counter()
    serial = liftoff.sweep(grid, workers=1, **opts)
    t_serial = time.perf_counter() - t0
    t0 = time.perf_counter()
    pool = liftoff.sweep(grid, workers=2, **opts)
    t_pool = time.perf_counter() - t0
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        # Workers up and warm (first solve in a fresh process pays page faults and thread
        # start-up) before the clock starts; the process pool starts cold and pays it.
        client.run(liftoff.solve, "example:slab-on-grade")
        t0 = time.perf_counter()
        dask = liftoff.sweep(grid, client=client, **opts)
        t_dask = time.perf_counter() - t0
    assert dask == serial == pool, "the sweeps differ"
    # Timings of failed or unconverged solves would not be timings of answers.
    failed = [r for r in serial if not (r["ok"] and r["converged"])]
    assert not failed, f"{len(failed)} scenes gave no solution, nothing to time: {failed[:3]}"
    print(f"{len(grid)} scenes ({scene}, {mesh[0]} × {mesh[1]} elements), "
          f"{sum(not r['ok'] for r in serial)} failed")
    print(f"serial        {t_serial:7.2f} s  1.00")
    print(f"process pool  {t_pool:7.2f} s  {t_serial / t_pool:.2f}× faster")
    print(f"Dask 2 workers{t_dask:7.2f} s  {t_serial / t_dask:.2f}× faster")


if __name__ == "__main__":
    main()
