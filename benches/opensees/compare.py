"""The OpenSees side of the comparison in BENCHMARKS.md (issue 26): benches/opensees/slab.toml
as the same discrete problem — the 80 × 80 quarter model of a 2 m square plate, MITC4 shells
(ShellMITC4, ElasticMembranePlateSection: the plate's bending and Mindlin shear; the membrane,
uncoupled on a flat plate, fixed) on compression-only Winkler springs (zeroLength elements of
ENT material, k times the node's lumped area, as liftoff's nodal constraints), symmetry on
x = 0 and y = 0, the quarter of the 100 kN point load at the centre. Newton on the whole load in
one step (the springs are piecewise linear: it settles the contact set as an active-set
method). Prints the time of analyze() alone and the peak deflection, for comparison with
`liftoff solve benches/opensees/slab.toml`.

    pip install openseespy   (Debian also needs libblas3 and liblapack3)
    python3 benches/opensees/compare.py [N]       N elements per side of the quarter, default 80
"""
import sys
import time

import openseespy.opensees as ops

n = int(sys.argv[1]) if len(sys.argv) > 1 else 80
L, H, E, nu, P = 1.0, 0.1, 30e9, 0.3, 1.0e5
D = E * H**3 / (12 * (1 - nu**2))
k = D / (0.25e-3 * L**4)
h = L / n

ops.wipe()
ops.model("basic", "-ndm", 3, "-ndf", 6)
ops.section("ElasticMembranePlateSection", 1, E, nu, H, 0.0)


def node(i, j):
    return 1 + i + j * (n + 1)


ground = (n + 1) ** 2
for j in range(n + 1):
    for i in range(n + 1):
        t = node(i, j)
        ops.node(t, i * h, j * h, 0.0)
        ops.node(ground + t, i * h, j * h, 0.0)
        ops.fix(ground + t, 1, 1, 1, 1, 1, 1)
        # Membrane and drilling fixed; symmetry: ∂w/∂x = 0 on x = 0 (ry), ∂w/∂y = 0 on y = 0 (rx).
        ops.fix(t, 1, 1, 0, 1 if j == 0 else 0, 1 if i == 0 else 0, 1)
e = 1
for j in range(n):
    for i in range(n):
        ops.element("ShellMITC4", e, node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1), 1)
        e += 1
# Lumped areas: h² inside, h²/2 on an edge, h²/4 at a corner of the quarter model.
for tag, share in ((1, 1.0), (2, 0.5), (3, 0.25)):
    ops.uniaxialMaterial("ENT", tag, k * h * h * share)
for j in range(n + 1):
    for i in range(n + 1):
        edges = (i in (0, n)) + (j in (0, n))
        ops.element("zeroLength", e, ground + node(i, j), node(i, j), "-mat", 1 + edges, "-dir", 3)
        e += 1

ops.timeSeries("Constant", 1)
ops.pattern("Plain", 1, 1)
ops.load(node(0, 0), 0.0, 0.0, -P / 4, 0.0, 0.0, 0.0)
ops.constraints("Plain")
ops.numberer("RCM")
ops.system("UmfPack")
ops.test("NormDispIncr", 1e-12, 100)
ops.algorithm("Newton")
ops.integrator("LoadControl", 1.0)
ops.analysis("Static")
t0 = time.perf_counter()
ok = ops.analyze(1)
t = time.perf_counter() - t0
w = -min(ops.nodeDisp(node(i, j), 3) for j in range(n + 1) for i in range(n + 1))
lifted = sum(ops.nodeDisp(node(i, j), 3) > 0 for j in range(n + 1) for i in range(n + 1))
print(f"opensees {n}x{n} quarter: analyze {'ok' if ok == 0 else f'FAILED ({ok})'} in {t:.3f} s, "
      f"Newton iterations {ops.testIter()}, w_max {w:.10e} m, lifted nodes {lifted} of {(n + 1) ** 2}")
