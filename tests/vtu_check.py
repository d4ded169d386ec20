#!/usr/bin/env python3
"""Check liftoff's plate.vtu with independent VTK readers, against the CSV tables of the same run.

Usage:
    cargo run --release -- solve example:slab-on-grade --out /tmp/vtkcheck
    python3 tests/vtu_check.py /tmp/vtkcheck

Reads <dir>/plate.vtu with VTK's own reader (`pip install vtk`, the reader ParaView uses) and
with meshio (`pip install meshio`), whichever are installed (at least one must be), and compares
with <dir>/nodes.csv and <dir>/elements.csv:

* point count = rows of nodes.csv, cell count = rows of elements.csv, every cell a VTK_QUAD (9);
* points = (x, y, 0) of nodes.csv;
* point arrays w, psi_x, psi_y, pressure, gap, V, sigma, contact and displacement = (0, 0, -w);
* cell arrays mx, my, mxy, qx, qy, and cell centroids (from points and connectivity) = the
  element centres x, y of elements.csv, which checks the connectivity and the cell order;
* every quad counter-clockwise (positive shoelace area);
* (VTK only) active scalars sigma / vectors displacement on points, active scalars mx on cells.

Not part of `cargo test` (CI has no Python packages); run by hand. Exit status 0 when all pass.
"""

import csv
import sys
from pathlib import Path

import numpy as np

VTK_QUAD = 9  # vtkCellType.h

# The CSV tables are written with 13 significant digits ("%.12e"): rounding to them changes a
# value by at most 5e-13 relative; the .vtu holds the exact doubles. rtol 1e-9 covers the
# rounding with a wide margin; atol covers values the CSV prints as 0.
RTOL, ATOL = 1e-9, 1e-300

POINT_ARRAYS = {
    "w": "w",
    "psi_x": "psi_x",
    "psi_y": "psi_y",
    "pressure": "pressure",
    "gap": "gap",
    "V": "V",
    "sigma": "sigma",
    "contact": "contact",
}
CELL_ARRAYS = ["mx", "my", "mxy", "qx", "qy"]

failures = []


def check(ok, what):
    print(("  ok    " if ok else "  FAIL  ") + what)
    if not ok:
        failures.append(what)


def close(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.allclose(a, b, rtol=RTOL, atol=ATOL))


def max_rel(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape:
        return float("inf")
    scale = np.maximum(np.abs(b), np.finfo(float).tiny)
    return float(np.max(np.abs(a - b) / scale))


def read_csv(path):
    with open(path, newline="") as f:
        # Headers carry their unit, `x [m]`: read by name.
        rows = [{k.split(" [")[0]: v for k, v in r.items()} for r in csv.DictReader(f)]
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def compare(points, quads, types, point_data, cell_data, nodes, elems):
    """The checks common to both readers; arrays are numpy arrays, quads is (n, 4)."""
    quads = np.asarray(quads).astype(np.int64)  # meshio turns UInt64 connectivity into floats
    n_nodes, n_cells = len(nodes["x"]), len(elems["x"])
    check(len(points) == n_nodes, f"{len(points)} points, nodes.csv has {n_nodes} rows")
    check(len(quads) == n_cells, f"{len(quads)} cells, elements.csv has {n_cells} rows")
    check(bool(np.all(types == VTK_QUAD)), "every cell is VTK_QUAD (9)")
    check(close(points[:, 0], nodes["x"]) and close(points[:, 1], nodes["y"]),
          f"points x, y = nodes.csv (max rel diff {max(max_rel(points[:, 0], nodes['x']), max_rel(points[:, 1], nodes['y'])):.1e})")
    check(bool(np.all(points[:, 2] == 0.0)), "points z = 0")
    for name, column in POINT_ARRAYS.items():
        got = point_data.get(name)
        if got is None:
            check(False, f"point array {name} present")
            continue
        got = np.asarray(got).reshape(-1)
        check(close(got, nodes[column]),
              f"point array {name} = nodes.csv {column} (max rel diff {max_rel(got, nodes[column]):.1e})")
    disp = point_data.get("displacement")
    if disp is None:
        check(False, "point array displacement present")
    else:
        disp = np.asarray(disp).reshape(-1, 3)
        check(bool(np.all(disp[:, :2] == 0.0)) and close(disp[:, 2], -nodes["w"]),
              "displacement = (0, 0, -w)")
    for name in CELL_ARRAYS:
        got = cell_data.get(name)
        if got is None:
            check(False, f"cell array {name} present")
            continue
        got = np.asarray(got).reshape(-1)
        check(close(got, elems[name]),
              f"cell array {name} = elements.csv (max rel diff {max_rel(got, elems[name]):.1e})")
    xy = points[:, :2][quads]  # (n, 4, 2)
    centroid = xy.mean(axis=1)
    check(close(centroid[:, 0], elems["x"]) and close(centroid[:, 1], elems["y"]),
          "cell centroids = element centres of elements.csv (connectivity and cell order)")
    x, y = xy[:, :, 0], xy[:, :, 1]
    area2 = np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1)
    check(bool(np.all(area2 > 0.0)), f"all quads counter-clockwise (min 2·area {area2.min():.3e})")


def with_vtk(vtu, nodes, elems):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

    print(f"VTK {vtk_version()}:")
    messages = []
    r = vtkXMLUnstructuredGridReader()
    for event in ("ErrorEvent", "WarningEvent"):
        r.AddObserver(event, lambda _obj, ev: messages.append(ev))
    r.SetFileName(str(vtu))
    r.Update()
    check(r.GetErrorCode() == 0 and not messages,
          f"VTK reader: error code {r.GetErrorCode()}, errors/warnings {messages}")
    g = r.GetOutput()
    points = vtk_to_numpy(g.GetPoints().GetData())
    cells = g.GetCells()
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    conn = vtk_to_numpy(cells.GetConnectivityArray())
    check(bool(np.all(np.diff(offsets) == 4)), "VTK: every cell has 4 nodes")
    quads = conn.reshape(-1, 4)
    # GetCellTypes() returns the array since VTK 9.6; GetCellTypesArray() before.
    types = vtk_to_numpy(g.GetCellTypes() if hasattr(g, "GetCellTypes") else g.GetCellTypesArray())
    pd, cd = g.GetPointData(), g.GetCellData()
    point_data = {pd.GetArrayName(i): vtk_to_numpy(pd.GetArray(i)) for i in range(pd.GetNumberOfArrays())}
    cell_data = {cd.GetArrayName(i): vtk_to_numpy(cd.GetArray(i)) for i in range(cd.GetNumberOfArrays())}
    compare(points, quads, types, point_data, cell_data, nodes, elems)
    check(pd.GetScalars() is not None and pd.GetScalars().GetName() == "sigma", "active point scalars sigma")
    check(pd.GetVectors() is not None and pd.GetVectors().GetName() == "displacement",
          "active point vectors displacement")
    check(cd.GetScalars() is not None and cd.GetScalars().GetName() == "mx", "active cell scalars mx")
    check(point_data["contact"].dtype == np.int32, f"contact is Int32 ({point_data['contact'].dtype})")


def vtk_version():
    from vtkmodules.vtkCommonCore import vtkVersion

    return vtkVersion.GetVTKVersion()


def with_meshio(vtu, nodes, elems):
    import meshio

    print(f"meshio {meshio.__version__}:")
    m = meshio.read(vtu)
    blocks = [b.type for b in m.cells]
    check(blocks == ["quad"], f"meshio: one block of quads ({blocks})")
    quads = np.concatenate([b.data for b in m.cells if b.type == "quad"])
    types = np.full(len(quads), VTK_QUAD)
    cell_data = {k: v[0] for k, v in m.cell_data.items()}
    compare(m.points, quads, types, m.point_data, cell_data, nodes, elems)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    vtu = out / "plate.vtu"
    nodes, elems = read_csv(out / "nodes.csv"), read_csv(out / "elements.csv")
    readers = 0
    for name, run in [("vtk", with_vtk), ("meshio", with_meshio)]:
        try:
            __import__("vtkmodules" if name == "vtk" else name)
        except ImportError:
            print(f"{name}: not installed, skipped")
            continue
        readers += 1
        run(vtu, nodes, elems)
    if readers == 0:
        sys.exit("neither vtk nor meshio is installed: pip install vtk meshio")
    if failures:
        print(f"{len(failures)} check(s) FAILED")
        sys.exit(1)
    print(f"all checks passed with {readers} reader(s)")


if __name__ == "__main__":
    main()
