#!/usr/bin/env python3
"""The OpenSees reference for plates of any outline (issue 35): tests/scenes/outline-l-raft.toml
(an L-shaped raft, `[plate] outline`) and tests/scenes/outline-opening.toml (a slab with a
rectangular `[[opening]]`) as the same discrete problem liftoff solves, built like
benches/opensees/compare.py (which matched liftoff to 1e-10 relative on the full rectangle).

The scenes are read with tomllib, so they stay the single source. The grid is
`mesh.elements` = [nx, ny] uniform cells over the bounding box [-a/2, a/2] x [-b/2, b/2]
(a = plate.length, b = plate.width). A cell is plate when its centre lies inside the outline
polygon (even-odd rule; the whole box when there is no outline) and inside no opening (an
`[[opening]]` rectangle x = [x0, x1], y = [y0, y1], or its `outline` polygon). The live nodes
are the corners of plate cells; nothing else exists. On them: one ShellMITC4 per plate cell
(nodes counter-clockwise, ElasticMembranePlateSection: the plate's bending and Mindlin shear;
the membrane, uncoupled on a flat plate, fixed with the drilling rotation at every node), the
whole plate (no symmetry), and compression-only Winkler springs as liftoff's nodal constraints:
a zeroLength element in direction 3 from a fixed ground node to each live node, ENT material of
stiffness k times the node's lumped area (number of plate cells touching it) x hx hy / 4. The
point loads (on grid nodes) are nodal forces -force in direction 3: liftoff's w is positive
downward and OpenSees' z is up, so w = -uz. Newton on the whole load in one step (the springs
are piecewise linear: it settles the contact set as an active-set method), UmfPack,
NormDispIncr 1e-12.

For each scene it prints the live nodes, w_max (the largest downward deflection) and where,
the lifted nodes (uz > 1e-12 w_max: the spring is off), the total contact (the ground nodes'
reactions, and k A w summed over the springs in contact) against the total load, and w at the
named points: the load points, the bounding box's corners and the outline's and openings'
vertices that are live nodes, and the origin when it is one (the L's re-entrant corner).

    pip install openseespy   (Debian also needs libblas3 and liblapack3)
    python3 tests/references/outline_opensees.py [--json] [SCENE.toml ...]

Without scenes it runs the two above (paths from the repository's root or this file's place).
--json writes one JSON document (full-precision floats) to stdout instead of the text.
"""
import json
import os
import sys
import tomllib

import openseespy.opensees as ops

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
DEFAULT_SCENES = ["tests/scenes/outline-l-raft.toml", "tests/scenes/outline-opening.toml"]


def inside(poly, x, y):
    """Even-odd rule: a ray from (x, y) towards +x crosses the polygon's edges an odd number of
    times. Cell centres are never on a grid line, so no crossing is ambiguous."""
    c = False
    n = len(poly)
    for k in range(n):
        x0, y0 = poly[k]
        x1, y1 = poly[(k + 1) % n]
        if (y0 > y) != (y1 > y):
            xc = x0 + (y - y0) * (x1 - x0) / (y1 - y0)
            if xc > x:
                c = not c
    return c


def opening_polygon(o):
    if "outline" in o:
        return [tuple(p) for p in o["outline"]]
    (x0, x1), (y0, y1) = sorted(o["x"]), sorted(o["y"])
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def solve(path):
    with open(path, "rb") as f:
        s = tomllib.load(f)
    p = s["plate"]
    a, b, H, E, nu = p["length"], p["width"], p["thickness"], p["youngs_modulus"], p["poissons_ratio"]
    fnd = s["foundation"]
    if fnd.get("model", "winkler") != "winkler":
        raise SystemExit(f"{path}: only a Winkler foundation is modelled, got {fnd['model']!r}")
    k = fnd["modulus"]
    contact = s.get("solver", {}).get("contact", "unbonded")
    if contact != "unbonded":
        raise SystemExit(f"{path}: only tensionless (unbonded) contact is modelled, got {contact!r}")
    if s.get("mesh", {}).get("symmetry", "none") not in ("none", "auto"):
        raise SystemExit(f"{path}: the whole plate is modelled; symmetry must be none or auto")
    nx, ny = s["mesh"]["elements"]
    hx, hy = a / nx, b / ny
    outline = [tuple(q) for q in p["outline"]] if "outline" in p else None
    if outline and outline[0] == outline[-1]:
        outline.pop()
    openings = [opening_polygon(o) for o in s.get("opening", [])]

    def X(i):
        return -a / 2 + i * hx

    def Y(j):
        return -b / 2 + j * hy

    # The cell mask.
    plate = {}
    for j in range(ny):
        for i in range(nx):
            xc, yc = X(i + 0.5), Y(j + 0.5)
            plate[i, j] = (outline is None or inside(outline, xc, yc)) and not any(
                inside(o, xc, yc) for o in openings)
    cells = [c for c in sorted(plate, key=lambda c: (c[1], c[0])) if plate[c]]
    # Live nodes and how many plate cells touch each.
    touch = {}
    for i, j in cells:
        for q in ((i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)):
            touch[q] = touch.get(q, 0) + 1
    live = sorted(touch, key=lambda q: (q[1], q[0]))
    tag = {q: t + 1 for t, q in enumerate(live)}
    ground = len(live)

    def grid_node(x, y, what):
        fi, fj = (x + a / 2) / hx, (y + b / 2) / hy
        i, j = round(fi), round(fj)
        if abs(fi - i) > 1e-6 or abs(fj - j) > 1e-6:
            raise SystemExit(f"{path}: {what} ({x}, {y}) is not a grid node")
        return (i, j)

    loads = []
    for n, ld in enumerate(s.get("load", [])):
        if ld.get("kind") != "point":
            raise SystemExit(f"{path}: load[{n}] is {ld.get('kind')!r}; only point loads are modelled")
        q = grid_node(ld["x"], ld["y"], f"load[{n}]")
        if q not in tag:
            raise SystemExit(f"{path}: load[{n}] at ({ld['x']}, {ld['y']}) is not on the plate")
        loads.append((q, ld["force"], (ld["x"], ld["y"])))
    total = sum(f for _, f, _ in loads)

    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.section("ElasticMembranePlateSection", 1, E, nu, H, 0.0)
    for (i, j), t in tag.items():
        ops.node(t, X(i), Y(j), 0.0)
        ops.node(ground + t, X(i), Y(j), 0.0)
        ops.fix(ground + t, 1, 1, 1, 1, 1, 1)
        ops.fix(t, 1, 1, 0, 0, 0, 1)  # membrane (ux, uy) and drilling (rz) fixed
    e = 1
    for i, j in cells:
        ops.element("ShellMITC4", e, tag[i, j], tag[i + 1, j], tag[i + 1, j + 1], tag[i, j + 1], 1)
        e += 1
    for m in range(1, 5):  # a node touched by m plate cells: lumped area m hx hy / 4
        ops.uniaxialMaterial("ENT", m, k * m * hx * hy / 4)
    for q, t in tag.items():
        ops.element("zeroLength", e, ground + t, t, "-mat", touch[q], "-dir", 3)
        e += 1

    ops.timeSeries("Constant", 1)
    ops.pattern("Plain", 1, 1)
    for q, f, _ in loads:
        ops.load(tag[q], 0.0, 0.0, -f, 0.0, 0.0, 0.0)
    ops.constraints("Plain")
    ops.numberer("RCM")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-12, 100)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    ok = ops.analyze(1)
    iters = ops.testIter()

    w = {q: -ops.nodeDisp(t, 3) for q, t in tag.items()}
    qmax = max(w, key=lambda q: w[q])
    wmax = w[qmax]
    lifted = sum(-w[q] > 1e-12 * wmax for q in live)
    ops.reactions()
    reaction = sum(ops.nodeReaction(ground + t, 3) for t in tag.values())
    springs = sum(k * touch[q] * hx * hy / 4 * w[q] for q in live if w[q] > 0)

    named = []
    for _, _, (x, y) in loads:
        named.append(("load", x, y))
    for x in (-a / 2, a / 2):
        for y in (-b / 2, b / 2):
            named.append(("box corner", x, y))
    for x, y in outline or []:
        named.append(("outline vertex", x, y))
    for n, o in enumerate(openings):
        for x, y in o:
            named.append((f"opening[{n}] vertex", x, y))
    named.append(("origin", 0.0, 0.0))
    points, seen = [], set()
    for what, x, y in named:
        q = grid_node(x, y, what)
        if q in tag and q not in seen:
            seen.add(q)
            points.append({"what": what, "x": X(q[0]), "y": Y(q[1]), "w": w[q]})

    return {
        "scene": path,
        "title": s.get("title", ""),
        "elements": [nx, ny],
        "plate_cells": len(cells),
        "live_nodes": len(live),
        "analyze": ok,
        "newton_iterations": iters,
        "w_max": wmax,
        "w_max_at": [X(qmax[0]), Y(qmax[1])],
        "lifted_nodes": lifted,
        "total_load": total,
        "contact_reactions": reaction,
        "contact_springs": springs,
        "points": points,
    }


def show(r):
    g = lambda v: f"{v:.9e}"  # 10 significant digits
    print(f"{r['scene']}: {r['title']}")
    print(f"  grid {r['elements'][0]} x {r['elements'][1]}, plate cells {r['plate_cells']}, "
          f"live nodes {r['live_nodes']}")
    print(f"  analyze {'ok' if r['analyze'] == 0 else 'FAILED (%d)' % r['analyze']}, "
          f"Newton iterations {r['newton_iterations']}")
    print(f"  w_max {g(r['w_max'])} m at ({r['w_max_at'][0]:g}, {r['w_max_at'][1]:g})")
    print(f"  lifted nodes {r['lifted_nodes']} of {r['live_nodes']}")
    tl = r["total_load"]
    for name in ("contact_reactions", "contact_springs"):
        print(f"  {name.replace('_', ' ')} {g(r[name])} N, total load {g(tl)} N, "
              f"relative difference {abs(r[name] - tl) / tl:.2e}")
    for pt in r["points"]:
        print(f"  w({pt['x']:g}, {pt['y']:g}) = {g(pt['w'])} m   [{pt['what']}]")


def main():
    args = sys.argv[1:]
    as_json = "--json" in args
    scenes = [x for x in args if x != "--json"] or DEFAULT_SCENES
    results = []
    for sc in scenes:
        path = sc if os.path.exists(sc) else os.path.join(ROOT, sc)
        r = solve(path)
        r["scene"] = sc
        results.append(r)
        if not as_json:
            show(r)
    ok = all(r["analyze"] == 0 and abs(r["contact_reactions"] - r["total_load"]) <= 1e-8 * r["total_load"]
             for r in results)
    if as_json:
        version = ops.version() if hasattr(ops, "version") else None
        print(json.dumps({"opensees": version, "scenes": results}, indent=1))
    sys.stdout.flush()
    if not ok:
        sys.exit("analysis failed or the contact does not balance the load")


if __name__ == "__main__":
    main()
