#!/usr/bin/env python3
"""Self-checks of tests/references/two_plates.py (the references of tests/joints_reference.rs).

Run (Python 3 with numpy and scipy; a few seconds; ./test runs it):

    python3 tests/references/two_plates.py --check      (or: python3 tests/references/two_plates_check.py)

Each check compares a routine of two_plates.py with something that routine did not produce,
prints its largest error beside its tolerance, and the script exits with status 1 naming every
check that failed. Units D = k = 1 (ell = 1, w in P/(k ell^2), moments in P), as in two_plates.py.

  equilibrium      the soil takes the load: int int k w = P over both plates (the eta = 0
                   transform integrated in x by adaptive quadrature), the soil under the
                   unloaded right plate takes exactly the force the joint transfers,
                   c (w- - w+) at eta = 0, and its moment about the joint is the joint's moment
                   -c_r (theta+ - theta-) (Kirchhoff and Mindlin);
  continuous       a rigid joint (c = c_r = inf, and c = c_r = 1e8 through the finite-spring
                   branch; Mindlin also ties the tangential rotation, ct) is the one plate,
                   computed here by the 2-D convolution of the patch with the point-load
                   Green's function of a plate on a Winkler soil (Hankel transform of
                   1/(D xi^4 + k), Kirchhoff, and of (1 + D xi^2/S)/(D xi^4 + k (1 + D xi^2/S)),
                   Mindlin, in closed form with K0), the patch split into four rectangles
                   cornered at the point and each integrated in polar coordinates;
  hinge            a hinge (c = inf, c_r = 0) under a load symmetric about it is two free
                   edges each carrying its half (by symmetry no shear crosses, the hinge
                   carries no moment): the patch plus its mirror image on the hinged plates
                   against the patch alone on the free-edge plates (c = 0);
  mindlin->kirch.  with D held, H -> 0: the Mindlin plates approach the Kirchhoff ones (w at
                   the eight points, m_y beside the joint, the LTE), at first order in H (the
                   Mindlin edge zone at the joint);
  eta rule         the printed numbers (sections A, L, W, D, F) against a finer eta rule, and
                   section F's disk as 128 strips against 64;
  moment           Kirchhoff m_y = -D (w_yy + nu w_xx) from the transforms' analytic
                   derivatives against finite differences of w (Richardson-extrapolated);
  westergaard      a small patch far from a free edge: Westergaard's interior deflection
                   P / (8 sqrt(k D)); a small patch on a free edge against edge_green (the
                   free-edge Green's function, a separate closed form), and that against
                   Westergaard's 1948 edge formula (an approximation: 1e-3);
  dowel            dowel_spring and friberg_y0 against the direct 8 x 8 beam solution of
                   tests/references/dowel_beam.py.

Not checked here: discrete_dowels (section D's discrete row) beyond its ingredients edge_green
and TwoPlates, and the published regressions of section L (quoted, not derived).
"""

import os
import sys
import time

import numpy as np
from scipy.integrate import quad
from scipy.special import kv

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import two_plates as tp  # noqa: E402

INF = np.inf
PATCH = (-0.5, 0.0, 0.25)  # [x1, x2] x [-b, b] of tp.RECTS, pressure 4 (P = 1)
ETA0 = (np.array([0.0]), np.array([1.0]))  # the eta = 0 component alone


def shear_stiffness(H, nu=tp.NU, chi=5.0 / 6.0):
    """S = chi G H in units of D / ell^2 (as TwoMindlin)."""
    return chi * 6 * (1 - nu) / H ** 2


# ------------------------------------------------------------------------------------------
# The one plate (no joint): the patch convolved with the point-load Green's function.
# ------------------------------------------------------------------------------------------


def radial_integral(R, S):
    """int_0^R g(r) r dr of the point-load Green's function g of a plate on Winkler (D = k = 1).

    g's Hankel transform is (1 + xi^2/S) / (xi^4 + xi^2/S + 1) (S = inf: Kirchhoff). With
    xi^4 + xi^2/S + 1 = (xi^2 + a)(xi^2 + b) and partial fractions A/(xi^2 + a) + B/(xi^2 + b),
    g = (A K0(sqrt(a) r) + B K0(sqrt(b) r)) / (2 pi), and int_0^R K0(s r) r dr =
    (1 - s R K1(s R)) / s^2."""
    inv = 0.0 if np.isinf(S) else 1.0 / S
    disc = np.sqrt(complex(inv * inv - 4.0))
    a, b = (inv + disc) / 2, (inv - disc) / 2  # a + b = 1/S, a b = 1
    A = (1 - a * inv) / (b - a)
    B = (1 - b * inv) / (a - b)
    total = 0.0
    for coef, root in ((A, a), (B, b)):
        z = np.sqrt(root) * R
        total += coef * (1 - z * kv(1, z)) / root
    return total.real / (2 * np.pi)


def corner_rectangle(a, b, S):
    """int_0^a int_0^b g(sqrt(s^2 + t^2)) dt ds, in polar coordinates about the corner."""
    if a == 0 or b == 0:
        return 0.0
    th = np.arctan2(b, a)
    opts = dict(epsabs=1e-15, epsrel=1e-13, limit=200)
    f1 = quad(lambda t: radial_integral(a / np.cos(t), S), 0, th, **opts)[0]
    f2 = quad(lambda t: radial_integral(b / np.sin(t), S), th, np.pi / 2, **opts)[0]
    return f1 + f2


def one_plate(x, y, x1, x2, b, pressure, S=INF):
    """w at (x, y) of the unjointed plate under `pressure` on [x1, x2] x [-b, b]."""

    def signed(X, Y):  # oriented integral over [0, X] x [0, Y] (g even in both axes)
        return np.sign(X) * np.sign(Y) * corner_rectangle(abs(X), abs(Y), S)

    X1, X2, Y1, Y2 = x1 - x, x2 - x, -b - y, b - y
    return pressure * (signed(X2, Y2) - signed(X1, Y2) - signed(X2, Y1) + signed(X1, Y1))


# ------------------------------------------------------------------------------------------
# The checks. Each returns rows (label, error, tolerance).
# ------------------------------------------------------------------------------------------

CHECKS = []


def check(fn):
    CHECKS.append(fn)
    return fn


def _eta0_integrals(W, x1):
    """(int over the left plate, over the right plate, int x W over the right plate) of the
    eta = 0 transform W(x, side); the exponentials decay like exp(-|x|/sqrt 2) (Kirchhoff) or
    faster, so 60 ell is infinity to 1e-18."""
    opts = dict(epsabs=1e-14, epsrel=1e-13, limit=200)
    left = quad(lambda x: W(x, "L"), -60.0, x1, **opts)[0] + quad(lambda x: W(x, "L"), x1, 0.0, **opts)[0]
    right = quad(lambda x: W(x, "R"), 0.0, 60.0, **opts)[0]
    moment = quad(lambda x: x * W(x, "R"), 0.0, 60.0, **opts)[0]
    return left, right, moment


# Tolerance of the equilibrium checks: the eta = 0 solutions are single closed forms (4 x 4 or
# 6 x 6 solves) and the x-integrals adaptive quadrature of smooth exponentials asked for 1e-13;
# round-off leaves ~1e-15, so 1e-10 flags any wrong factor or sign while ignoring the method.
TOL_EQUILIBRIUM = 1e-10
JOINTS = [(0.0, 0.0), (0.1, 0.0), (1.0, 0.0), (10.0, 1.0), (INF, 0.0), (INF, INF)]


@check
def equilibrium_kirchhoff():
    rows = []
    x1, x2, b = PATCH
    for c, cr in JOINTS:
        z = tp.TwoPlates(c, cr, tp.NU, x1, x2, b, rule=ETA0)
        left, right, moment = _eta0_integrals(lambda x, s: z.W(x, s)[0].real, x1)
        rows.append((f"c={c:g} c_r={cr:g}: k int int w = P", abs(left + right - 1.0), TOL_EQUILIBRIUM))
        if np.isfinite(c):
            rows.append((f"c={c:g} c_r={cr:g}: soil under the right plate = c (w- - w+)",
                         abs(right - z.transferred_force()), TOL_EQUILIBRIUM))
        if np.isfinite(cr):
            jump = (z.W(0.0, "R", 1)[0] - z.W(0.0, "L", 1)[0]).real
            rows.append((f"c={c:g} c_r={cr:g}: its moment = -c_r (theta+ - theta-)",
                         abs(moment + cr * jump), TOL_EQUILIBRIUM))
    return rows


@check
def equilibrium_mindlin():
    rows = []
    x1 = PATCH[0]
    for c, cr in JOINTS:
        z = tp.TwoMindlin(c, cr, tp.NU, tp.H_A, tp.RECTS, rule=ETA0)
        left, right, moment = _eta0_integrals(lambda x, s: z.Wt(x, s)[0].real, x1)
        rows.append((f"H={tp.H_A} c={c:g} c_r={cr:g}: k int int w = P", abs(left + right - 1.0), TOL_EQUILIBRIUM))
        if np.isfinite(c):
            rows.append((f"H={tp.H_A} c={c:g} c_r={cr:g}: soil under the right plate = c (w- - w+)",
                         abs(right - z.transferred_force()), TOL_EQUILIBRIUM))
        if np.isfinite(cr):
            jump = (z.Wt(0.0, "R", 2)[0] - z.Wt(0.0, "L", 2)[0]).real  # psi_x
            rows.append((f"H={tp.H_A} c={c:g} c_r={cr:g}: its moment = -c_r (psi_x+ - psi_x-)",
                         abs(moment + cr * jump), TOL_EQUILIBRIUM))
    return rows


# Tolerance of the continuous limit: the convolution is exact to ~1e-15 (checked against a
# direct 2-D quadrature while writing this); what remains is the eta rule of two_plates.py
# (Kirchhoff ~3e-12; Mindlin up to 6e-9 at (0, 0.5), where its 48-point panels start to
# under-resolve cos(eta y) sin(eta b) near eta_max) and, for c = c_r = 1e8, the springs'
# compliance (~w / c: up to 3.5e-9). 1e-7: w is printed to 8 decimals.
TOL_POINTS = 1e-7


@check
def continuous_kirchhoff():
    x1, x2, b = PATCH
    rows = []
    for stiff in (INF, 1e8):
        z = tp.TwoPlates(stiff, stiff, tp.NU, x1, x2, b)
        err = max(abs(z.w(x, y, s) - one_plate(x, y, x1, x2, b, 4.0)) for (x, y, s) in tp.POINTS)
        rows.append((f"c=c_r={stiff:g}: w at the 8 points = the one plate", err, TOL_POINTS))
    return rows


@check
def continuous_mindlin():
    x1, x2, b = PATCH
    S = shear_stiffness(tp.H_A)
    ref = [one_plate(x, y, x1, x2, b, 4.0, S) for (x, y, s) in tp.POINTS]
    rows = []
    for stiff in (INF, 1e8):
        z = tp.TwoMindlin(stiff, stiff, tp.NU, tp.H_A, tp.RECTS, ct=stiff)
        err = max(abs(z.w(x, y, s) - r) for (x, y, s), r in zip(tp.POINTS, ref))
        rows.append((f"H={tp.H_A} c=c_r=ct={stiff:g}: w at the 8 points = the one plate", err, TOL_POINTS))
    # (liftoff's joint leaves the twisting moment free, ct = 0: a rigid one is then not the one
    # plate, 3.9e-4 off here, so this check also fails if ct is ignored.)
    return rows


# Tolerance of the hinge: both sides of the identity come from the same eta rule, so it holds
# node by node; what is left is round-off (measured ~6e-16).
TOL_IDENTITY = 1e-12


def _hinge_rows(name, make):
    hinge, free = make(INF, 0.0), make(0.0, 0.0)
    err_w = err_m = 0.0
    for (x, y, s) in tp.POINTS:
        if s != "L":
            continue
        # the mirror image of the patch on the right plate gives at (x, y) the patch's w at (-x, y)
        err_w = max(err_w, abs(hinge.w(x, y, "L") + hinge.w(-x, y, "R") - free.w(x, y, "L")))
        err_m = max(err_m, abs(hinge.my(x, y, "L") + hinge.my(-x, y, "R") - free.my(x, y, "L")))
    return [(f"{name}: w (symmetric load, hinge) = w (half the load, free edge)", err_w, TOL_IDENTITY),
            (f"{name}: m_y likewise", err_m, TOL_IDENTITY)]


@check
def hinge():
    x1, x2, b = PATCH
    rows = _hinge_rows("Kirchhoff", lambda c, cr: tp.TwoPlates(c, cr, tp.NU, x1, x2, b))
    rows += _hinge_rows(f"Mindlin H={tp.H_A}", lambda c, cr: tp.TwoMindlin(c, cr, tp.NU, tp.H_A, tp.RECTS))
    return rows


@check
def mindlin_to_kirchhoff():
    """Differences Mindlin - Kirchhoff at H = 0.02 and 0.01 (D held). Measured (c, c_r) = (0, 0),
    (1, 0), (10, 1): max |dw| over the eight points 4.5e-4 / 2.2e-4, 2.9e-4 / 1.4e-4,
    6.3e-5 / 2.6e-5, halving with H (ratios 0.42-0.48, 0.48-0.50 from 0.01 to 0.005): first
    order, from the Mindlin edge zone of width ~H at the joint, whose O(H) change of the
    effective edge conditions reaches every point (at (-1, 0) and (1, 1) too).
    m_y at (-+1/32, 1/32), (-0.25, 0) 2.4e-4 at most at H = 0.01, LTE 8e-5.
    Tolerances: the H = 0.01 difference below 0.05 H (w, m_y) and 0.03 H (LTE), and the ratio
    between 0.35 and 0.65 (first order) — a wrong factor in either model breaks one of them."""
    x1, x2, b = PATCH
    rows = []
    near = [(1 / 32, 1 / 32, "R"), (-1 / 32, 1 / 32, "L"), (-0.25, 0.0, "L")]
    for c, cr in [(0.0, 0.0), (1.0, 0.0), (10.0, 1.0)]:
        k = tp.TwoPlates(c, cr, tp.NU, x1, x2, b)
        kw = [k.w(x, y, s) for (x, y, s) in tp.POINTS]
        km = [k.my(x, y, s) for (x, y, s) in near]
        dw, dm, dl = [], [], []
        for H in (0.02, 0.01):
            m = tp.TwoMindlin(c, cr, tp.NU, H, tp.RECTS)
            dw.append(max(abs(m.w(x, y, s) - r) for (x, y, s), r in zip(tp.POINTS, kw)))
            dm.append(max(abs(m.my(x, y, s) - r) for (x, y, s), r in zip(near, km)))
            dl.append(abs(m.lte() - k.lte()) if c > 0 else 0.0)
        tag = f"c={c:g} c_r={cr:g}"
        rows.append((f"{tag}: max |w_M - w_K| at H = 0.01 (0.02: {dw[0]:.2e})", dw[1], 0.05 * 0.01))
        ratio = dw[1] / dw[0]
        rows.append((f"{tag}: its ratio H=0.01/H=0.02 = {ratio:.3f}, first order (0.35..0.65)",
                     abs(ratio - 0.5), 0.15))
        rows.append((f"{tag}: max |m_y,M - m_y,K| beside the joint at H = 0.01", dm[1], 0.05 * 0.01))
        if c > 0:
            rows.append((f"{tag}: |LTE_M - LTE_K| at H = 0.01", dl[1], 0.03 * 0.01))
    return rows


@check
def eta_rule():
    """The numbers two_plates.py prints, with its eta rules (Gauss-Legendre, 48 points on
    doubling panels from 0.25 to 2000 (Mindlin) or 2e4 (section W)), against 192 points on
    panels to 8000 (8e4): w at the eight points, the deflection LTE and the stress LTE at
    h = 1/8, 1/16, 1/32 of sections A and L (c = 0.1, 10 with c_r = 1, 100, 1000: the error
    grows with c), the free joint of section W, the smeared dowels of section D (the force
    c (w- - w+) s at y = 0 ... 6s). Measured: w and LTE 1.3e-8 at most (w at (0, 0.5)); the
    free joint 1e-10; the dowel forces 1.75e-6 (at y = 5s = 1.67 ell: cos(eta y) oscillates 68
    times across the panel [256, 512]; 96 points: 2.4e-7); the stress LTE 1.7e-7
    (h = 1/8) to 6.5e-7 (h = 1/16, 1/32, c = 1000), 5.3e-7 at c = 100: m_y at (-h/2, h/2),
    inside the patch, has a slowly decaying oscillating integrand that 48 points per doubling
    panel under-resolve (96 points: 2e-8). The finer rule itself moves by < 2e-8 between
    eta_max 8000 and 16000 (2e-10 for the dowel forces). Tolerances: 1e-7 for w and the LTE,
    1e-6 for the stress LTE and 3e-6 for the dowel forces (tests/joints_reference.rs compares
    liftoff with them to 2.3e-3 and 4e-3 of the critical force)."""
    x1, x2, b = PATCH
    fine = tp.eta_rule(eta_max=8000.0, per_panel=192)
    hs = (1 / 8, 1 / 16, 1 / 32)

    def numbers(r):
        w = [r.w(x, y, s) for (x, y, s) in tp.POINTS]
        if r.c > 0:
            w.append(r.lte())
        slte = [r.my(h / 2, h / 2, "R") / r.my(-h / 2, h / 2, "L") for h in hs]
        return np.array(w), np.array(slte)

    rows = []
    err_w = err_s = 0.0
    for c, cr in [(0.1, 0.0), (10.0, 1.0), (100.0, 0.0), (1000.0, 0.0)]:
        (aw, as_), (fw, fs) = (numbers(tp.TwoMindlin(c, cr, tp.NU, tp.H_A, tp.RECTS, rule=rule))
                               for rule in (None, fine))
        err_w = max(err_w, np.max(np.abs(aw - fw)))
        err_s = max(err_s, np.max(np.abs(as_ - fs)))
    rows.append(("A, L: Mindlin H=0.25, w at the 8 points and LTE, default rule vs a finer one", err_w, TOL_POINTS))
    rows.append(("A: the stress LTE at h = 1/8, 1/16, 1/32, default rule vs a finer one", err_s, 1e-6))
    rule_w = tp.eta_rule(eta_max=2e4)
    fine_w = tp.eta_rule(eta_max=8e4, per_panel=192)
    err = 0.0
    for make in (lambda rule: tp.TwoPlates(0.0, 0.0, tp.NU, x1, x2, b, rule=rule),
                 lambda rule: tp.TwoMindlin(0.0, 0.0, tp.NU, 0.02, tp.RECTS, rule=rule)):
        one, two = make(rule_w), make(fine_w)
        err = max(err, max(abs(one.w(x, y, s) - two.w(x, y, s)) for (x, y, s) in tp.POINTS if s == "L"))
    rows.append(("W: free joint, Kirchhoff and Mindlin H=0.02, default rule vs a finer one", err, TOL_POINTS))
    # section D's smeared Mindlin plate (its scene, as section_d builds it)
    ell, ksub, E, nu = 0.9, 8e7, 30e9, tp.NU
    H = (12 * (1 - nu ** 2) * ksub * ell ** 4 / E) ** (1 / 3) / ell
    kd = tp.dowel_spring(0.032, 200e9, 4.07e11, 0.006) / (ksub * ell ** 2)
    s, a = 0.3 / ell, 0.25 / ell
    rects = [(-a, 0.0, a / 2, 1.0 / (a * a))]
    one, two = (tp.TwoMindlin(kd / s, 0.0, nu, H, rects, rule=rule) for rule in (None, fine))
    err = max(abs(kd * ((one.w(0.0, y, "L") - one.w(0.0, y, "R")) - (two.w(0.0, y, "L") - two.w(0.0, y, "R"))))
              for y in s * np.arange(0, 7))
    rows.append(("D: smeared dowels, the force c (w- - w+) s / P at y = 0 ... 6s, default rule vs a finer one",
                 err, 3e-6))
    # section F: the deflectometer's disk as 64 strips at the joint, c = 1; and 128 strips
    # against 64 (how far the strips are from the disk: 9e-7 at the plate, measured)
    a, xc = 0.15, -0.15
    where = [(xc + r, "L" if xc + r < 0 else "R") for r in tp.FWD_OFFSETS]
    one, two = (tp.TwoMindlin(1.0, 0.0, tp.NU, tp.H_A, tp.disk_strips(xc, a), rule=rule)
                for rule in (None, fine))
    rows.append(("F: the disk at the joint, w at the 8 sensors, default rule vs a finer one",
                 max(abs(one.w(x, 0.0, s) - two.w(x, 0.0, s)) for (x, s) in where), TOL_POINTS))
    more = tp.TwoMindlin(1.0, 0.0, tp.NU, tp.H_A, tp.disk_strips(xc, a, n=128))
    rows.append(("F: the disk as 128 strips against 64, w at the 8 sensors",
                 max(abs(one.w(x, 0.0, s) - more.w(x, 0.0, s)) for (x, s) in where), 2e-6))
    return rows


@check
def moment_kirchhoff():
    """m_y = -(w_yy + nu w_xx) by central differences of w, h = 4e-3 and 2e-3, Richardson:
    truncation O(h^4) ~ 1e-9, round-off of the smooth eta-quadrature ~1e-13 / h^2 ~ 1e-8."""
    x1, x2, b = PATCH
    rows = []
    pts = [(-1 / 32, 1 / 32, "L"), (1 / 32, 1 / 32, "R"), (-0.25, 0.1, "L"), (-0.7, 0.4, "L"), (0.3, 0.2, "R")]
    for c, cr in [(1.0, 0.0), (10.0, 1.0)]:
        z = tp.TwoPlates(c, cr, tp.NU, x1, x2, b)
        err = 0.0
        for (x, y, s) in pts:
            def fd(h):
                wyy = (z.w(x, y + h, s) - 2 * z.w(x, y, s) + z.w(x, y - h, s)) / h ** 2
                wxx = (z.w(x + h, y, s) - 2 * z.w(x, y, s) + z.w(x - h, y, s)) / h ** 2
                return -(wyy + tp.NU * wxx)
            ref = (4 * fd(2e-3) - fd(4e-3)) / 3
            err = max(err, abs(z.my(x, y, s) - ref))
        rows.append((f"c={c:g} c_r={cr:g}: m_y = -(w_yy + nu w_xx) by differences, 5 points", err, 1e-6))
    return rows


@check
def westergaard():
    rows = []
    # Interior: a 2e-3 square patch 30 ell from a free edge (the edge's effect there ~exp(-30/sqrt 2)
    # ~ 6e-10); the patch's own size changes the centre by O(eps^2 log eps), 2.1e-7 (the
    # one-plate value of the same patch, checked too, says so): tolerance 1e-6 on 1/8.
    eps = 1e-3
    z = tp.TwoPlates(0.0, 0.0, tp.NU, -30 - eps, -30 + eps, eps)
    w = z.w(-30.0, 0.0, "L")
    exact = one_plate(0.0, 0.0, -eps, eps, eps, 1 / (4 * eps * eps))
    rows.append((f"interior w = 1/(8 sqrt(kD)) = 0.125 (patch 2e-3: w {w:.9f})", abs(w - 0.125), 1e-6))
    rows.append(("interior, the same patch: TwoPlates(c=0) = the one plate", abs(w - exact), TOL_POINTS))
    # Free edge: a 1e-7 patch at the edge against edge_green. The force's offset of 5e-8 from
    # the edge moves w by ~2.5e-8 (measured: 1.9e-7 for a 1e-6 patch, 2.5e-8 for 1e-7). A
    # point-like load needs a finer eta rule than the patches of the references: at y = 1 the
    # default 48-point panels err by 2.2e-7 here, 96-point ones by < 3e-8. Tolerance 1e-7.
    eps = 1e-7
    z = tp.TwoPlates(0.0, 0.0, tp.NU, -eps, 0.0, eps / 2, rule=tp.eta_rule(per_panel=96))
    err = max(abs(z.w(0.0, y, "L") - tp.edge_green(tp.NU, y)) for y in (0.0, 0.3, 1.0))
    rows.append(("free edge, point load: TwoPlates(c=0) = edge_green at y = 0, 0.3, 1", err, 1e-7))
    g0 = tp.edge_green(tp.NU, 0.0)
    rel = abs(g0 / tp.westergaard_edge_1948(tp.NU) - 1)
    rows.append((f"edge_green(0) = {g0:.6f} against Westergaard 1948 {tp.westergaard_edge_1948(tp.NU):.6f} (relative)",
                 rel, 1e-3))
    return rows


@check
def dowel():
    import dowel_beam as db

    rows = []
    err_k = err_y = 0.0
    for z in (0.0, 0.003, 0.006, 0.0127, 0.025):
        beta, kd, u0 = db.bar(z)
        err_k = max(err_k, abs(tp.dowel_spring(db.D_BAR, db.E_D, db.K_S, z) / kd - 1))
        err_y = max(err_y, abs(tp.friberg_y0(1.0, db.D_BAR, db.E_D, db.K_S, z) / abs(u0) - 1))
    # both closed forms against a Gaussian elimination of the 8 x 8 beam: round-off (~1e-15)
    rows.append(("dowel_spring = the direct beam's k_d (z = 0 ... 25 mm, relative)", err_k, 1e-12))
    rows.append(("friberg_y0 = the direct beam's face deflection (relative)", err_y, 1e-12))
    return rows


def main():
    failed = []
    t_all = time.process_time()
    for fn in CHECKS:
        t0 = time.process_time()
        try:
            rows = fn()
        except Exception as exc:  # a crash is a failure of the check, reported with the others
            rows = [(f"raised {type(exc).__name__}: {exc}", np.inf, 0.0)]
        print(f"{fn.__name__} ({time.process_time() - t0:.1f} s)")
        for label, err, tol in rows:
            ok = bool(err <= tol)  # NaN fails
            print(f"  {'ok  ' if ok else 'FAIL'} {err:9.2e} <= {tol:7.1e}  {label}")
            if not ok:
                failed.append(f"{fn.__name__}: {label} (error {err:.3e} > {tol:.1e})")
    print(f"{len(CHECKS)} checks, {time.process_time() - t_all:.1f} s CPU")
    if failed:
        print("\nFAILED self-checks of tests/references/two_plates.py:", file=sys.stderr)
        for f in failed:
            print("  " + f, file=sys.stderr)
        return 1
    print("all self-checks of two_plates.py pass")
    return 0


if __name__ == "__main__":
    sys.exit(main())
