"""liftoff from Python, notebook style: the paper's case by both methods, and a sweep of slab
thickness × soil modulus on a local Dask cluster.

    pip install "./python[dask]" matplotlib
    python python/examples/sweep.py [OUT_DIR]

Writes paper-pressure.png and sweep-liftoff.png into OUT_DIR (default: the current directory).
"""

import pathlib
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import liftoff  # noqa: E402
from dask.distributed import Client, LocalCluster  # noqa: E402


def main() -> None:
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    out.mkdir(parents=True, exist_ok=True)

    # %% The paper's case (Fig. 3: square plate, central point load, half-space) by both methods.
    scene = "example:paper-halfspace"
    pen = liftoff.solve(scene, method="penalty", mesh=64)
    qp = liftoff.solve(scene, method="qp", mesh=64)
    print(f"penalty: V_max {pen.V_max:.6e}, contact radius {pen.contact_radius:.4f} L, "
          f"{pen.iterations} steps, {pen.time_s['total']:.2f} s")
    print(f"qp     : V_max {qp.V_max:.6e}, contact radius {qp.contact_radius:.4f} L, "
          f"{qp.iterations} face solves ({qp.qp_solver}), {qp.time_s['total']:.2f} s")
    print(f"max |σ_penalty − σ_qp| / max σ = {np.abs(pen.sigma - qp.sigma).max() / qp.sigma.max():.2e}")

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    im = axes[0].pcolormesh(qp.s, qp.t, qp.sigma, shading="gouraud", cmap="YlOrRd")
    axes[0].contour(qp.s, qp.t, qp.sigma, levels=[1e-9], colors="k", linewidths=0.8)
    axes[0].set(aspect="equal", xlabel="s = x/L", ylabel="t = y/μL", title="QP: contact pressure σ")
    fig.colorbar(im, ax=axes[0], label="σ = μL²r/P")
    j = qp.sigma.shape[0] // 2
    axes[1].plot(pen.s[j], pen.sigma[j], label="penalty (ε̄ auto)")
    axes[1].plot(qp.s[j], qp.sigma[j], "--", label="QP")
    axes[1].set(xlabel="s = x/L on t = 0", ylabel="σ", title="σ along the x-axis", yscale="symlog")
    axes[1].legend()
    fig.suptitle(qp.title)
    fig.tight_layout()
    fig.savefig(out / "paper-pressure.png", dpi=120)

    # %% A sweep: thickness × subgrade modulus of the slab-on-grade bay, on a local Dask cluster.

    thickness = [0.12, 0.15, 0.18, 0.21, 0.25, 0.30]
    modulus = [1e7, 2e7, 4e7, 8e7, 1.6e8, 3.2e8]
    grid = liftoff.grid("example:slab-on-grade", {"plate.thickness": thickness, "foundation.modulus": modulus})
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as cluster, Client(cluster) as client:
        t0 = time.perf_counter()
        rows = liftoff.sweep(grid, method="penalty", client=client)
        print(f"{len(rows)} slabs on 2 Dask workers in {time.perf_counter() - t0:.1f} s; "
              f"{rows.meta['failed']} failed")

    lifted = np.full((len(thickness), len(modulus)), np.nan)
    for r in rows:
        if r["ok"]:
            i = thickness.index(r["plate.thickness"])
            k = modulus.index(r["foundation.modulus"])
            lifted[i, k] = 100.0 * (1.0 - r["contact_fraction"])

    fig, ax = plt.subplots(figsize=(6.5, 4.8))
    im = ax.imshow(lifted, origin="lower", cmap="viridis", aspect="auto")
    ax.set_xticks(range(len(modulus)), [f"{k / 1e6:g}" for k in modulus])
    ax.set_yticks(range(len(thickness)), [f"{h * 1000:g}" for h in thickness])
    ax.set(xlabel="subgrade modulus k (MN/m³)", ylabel="slab thickness (mm)",
           title="slab-on-grade: lifted area (% of the slab)")
    for i in range(len(thickness)):
        for k in range(len(modulus)):
            ax.text(k, i, "—" if np.isnan(lifted[i, k]) else f"{lifted[i, k]:.0f}",
                    ha="center", va="center", color="w", fontsize=8)
    fig.colorbar(im, ax=ax, label="lifted area, %")
    fig.tight_layout()
    fig.savefig(out / "sweep-liftoff.png", dpi=120)
    print(f"written: {out / 'paper-pressure.png'}, {out / 'sweep-liftoff.png'}")


# Dask's worker processes import this file again: only the main process runs the study.
if __name__ == "__main__":
    main()
