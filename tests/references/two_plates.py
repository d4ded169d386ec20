#!/usr/bin/env python3
"""Independent references for tests/joints_reference.rs (issue 23, jointed slabs) and
tests/backcalc_joint.rs (issue 34, section F).

Run (Python 3 with numpy and scipy; a few seconds):

    python3 tests/references/two_plates.py

It prints, in the units D = k = 1 (ell = (D/k)^(1/4) = 1; w in P/(k ell^2); joint shear
stiffness c in k ell, i.e. c is AGG/(k ell); rotational stiffness c_r in D/ell; dowel spring
k_d in k ell^2), every number tests/joints_reference.rs embeds:

  A. two semi-infinite MINDLIN plates (H = 0.25 ell, chi = 5/6, nu = 0.15) on a bonded Winkler
     soil joined along x = 0 by a shear spring c (and a rotational spring c_r), the patch
     [-0.5, 0] x [-0.25, 0.25] on the left plate: w k ell^2 / P at eight points on both sides,
     the deflection LTE w(0+, 0) / w(0-, 0), the transferred force, and the stress LTE read at
     the element centres beside the joint (x = -+h/2, y = h/2 for h = ell/8, ell/16, ell/32), which
     is where liftoff reads it;
  W. c = 0 (two free edges), KIRCHHOFF plates: the same points, and the exact free-edge
     deflection under a point load against Westergaard's 1926 and 1948 formulas;
  L. the deflection LTE against AGG/(k ell) = 0.01 ... 1000 (Mindlin, H = 0.25 ell) beside the
     two published regressions (Crovetti's 1/(1 + 1.2 f^-0.849) and the log form with a/ell of
     the circle of equal area);
  F. a deflectometer's disk (radius 0.15 ell, as 64 strips of its exact band areas) touching
     the joint on the left plate, Mindlin H = 0.25 ell: w k ell^2 / P at the FWD's eight
     sensors along x from the disk's centre, for c = 0.3, 1, 3 (tests/backcalc_joint.rs);
  D. a row of dowels (ell = 0.9 m, k = 80 MN/m^3, 32 mm steel bars every 0.3 m, opening 6 mm,
     K = 4.07e11 N/m^3, a 0.25 m square wheel patch at the joint centred on a bar): the smeared
     Mindlin reference c = k_d / s (dowel force c (w- - w+)(y_i) s) for the plate of the test,
     and the exact discrete-dowel row for Kirchhoff plates (how much smearing costs).

Method (details in the docstrings): Fourier transform in y (loads even in y), per wavenumber
eta a closed-form (Kirchhoff, 4 x 4) or eigen-decomposed (Mindlin, 6 x 6) solution on each side
with the joint conditions derived from the energy; Gauss-Legendre in eta on doubling panels.

Self-checks (tests/references/two_plates_check.py; ./test runs them; a few seconds):

    python3 tests/references/two_plates.py --check

equilibrium of the soil with the load and of the unloaded plate with the joint's force and
moment; the rigid joint against the one plate by a 2-D convolution with the closed-form
(Hankel) point-load Green's function, Kirchhoff and Mindlin; the hinge under a symmetric load =
the free edge with half the load; Mindlin -> Kirchhoff as H -> 0 (first order in H); m_y
against differences of w; Westergaard's interior deflection and the free edge's Green's
function; the dowel formulas against dowel_beam.py; the eta rules against finer ones. Measured
there, the printed numbers' error from the eta rule: w and the deflection LTEs below 1.3e-8,
the stress LTE up to 6.5e-7 (h = ell/16, ell/32; 1.7e-7 at ell/8), section D's dowel forces up
to 1.8e-6 (48 points per panel under-resolve the oscillation there), all far inside the
tolerances of the Rust tests that use them.

Kirchhoff plates: D lap^2 w + k w = q; joint energy per length 1/2 c (w+ - w-)^2 +
1/2 c_r (w+_x - w-_x)^2, natural conditions M+ = M- = c_r (w+_x - w-_x), V+ = V- = c (w- - w+).
Mindlin plates: liftoff's kinematics (w, psi_x, psi_y, gamma = grad w - psi, w downward); the
joint couples w and the normal rotation psi_x only (the twisting moment vanishes on both faces).
"""

import numpy as np
from scipy.integrate import quad

# ------------------------------------------------------------------------------------------
# Kirchhoff plates (from the design's ref_two_plates.py).
# ------------------------------------------------------------------------------------------


def eta_rule(eta_max=4000.0, first=0.25, per_panel=48):
    xg, wg = np.polynomial.legendre.leggauss(per_panel)
    edges = [0.0, first]
    while edges[-1] < eta_max:
        edges.append(edges[-1] * 2.0)
    nodes, weights = [], []
    for a, b in zip(edges[:-1], edges[1:]):
        nodes.append(0.5 * (b - a) * xg + 0.5 * (b + a))
        weights.append(0.5 * (b - a) * wg)
    return np.concatenate(nodes), np.concatenate(weights)


# ------------------------------------------------------------------------------------------
# Kirchhoff, per wavenumber.
# ------------------------------------------------------------------------------------------


def _box_particular(x, mu, cg, x1, x2):
    """sum_j cg_j int_{x1}^{x2} exp(-mu_j |x - s|) ds, and its x-derivatives 0..3 (x scalar or
    array broadcast against mu of shape (n_eta, 2))."""
    x = np.asarray(x, dtype=float)
    out = np.zeros((4,) + np.broadcast(x[..., None], mu).shape[:-1], dtype=complex)
    for j in range(2):
        m = mu[..., j]
        c = cg[..., j]
        right = x >= x2  # x to the right of the box
        left = x <= x1
        # arguments clipped to each branch so that no branch overflows where it is not used
        xr = np.where(right, x, x2)
        xl = np.where(left, x, x1)
        xi = np.clip(x, x1, x2)
        width = 1.0 - np.exp(-m * (x2 - x1))
        fr = np.exp(-m * (xr - x2)) * width / m  # right of the box
        fl = np.exp(m * (xl - x1)) * width / m  # left of the box
        ea, eb = np.exp(-m * (xi - x1)), np.exp(-m * (x2 - xi))  # inside
        for n in range(4):
            dr = (-m) ** n * fr
            dl = m ** n * fl
            di = (-(-m) ** n * ea - m ** n * eb) / m if n > 0 else (2.0 - ea - eb) / m
            val = np.where(right, dr, np.where(left, dl, di))
            out[n] += c * val
    return out


def kirchhoff_amplitudes(eta, c, cr, nu, x1, x2):
    """Per eta (array): mu (n,2), Green coefficients cg (n,2), and the amplitudes B (left,
    exp(+mu x)) and C (right, exp(-mu x)) for a unit load density Q(x) = 1 on [x1, x2]."""
    eta = np.asarray(eta, dtype=float)
    e2 = eta ** 2
    mu = np.stack([np.sqrt(e2 + 1j), np.sqrt(e2 - 1j)], axis=-1)
    cg = np.stack([-1.0 / (2j) / (2 * mu[:, 0]), 1.0 / (2j) / (2 * mu[:, 1])], axis=-1)
    p = _box_particular(0.0, mu, cg, x1, x2)  # (4, n): P, P', P'', P''' at x = 0
    n = eta.size
    # derivative vectors at x = 0 of the basis functions, shape (n, 4 derivs, 2 modes)
    L = np.stack([mu ** k for k in range(4)], axis=1)
    R = np.stack([(-mu) ** k for k in range(4)], axis=1)

    # Build the 4x4 system A u = b, u = (B1, B2, C1, C2).
    A = np.zeros((n, 4, 4), dtype=complex)
    b = np.zeros((n, 4), dtype=complex)
    e2c = e2[:, None]
    ML = L[:, 2, :] - nu * e2c * L[:, 0, :]
    MR = R[:, 2, :] - nu * e2c * R[:, 0, :]
    VL = L[:, 3, :] - (2 - nu) * e2c * L[:, 1, :]
    VR = R[:, 3, :] - (2 - nu) * e2c * R[:, 1, :]
    MP = p[2] - nu * e2 * p[0]
    VP = p[3] - (2 - nu) * e2 * p[1]
    # E1: M+ - c_r (theta+ - theta-) = 0
    if np.isinf(cr):
        A[:, 0, 2:] = R[:, 1, :]
        A[:, 0, :2] = -L[:, 1, :]
        b[:, 0] = p[1]
    else:
        s = 1.0 / (1.0 + cr)
        A[:, 0, 2:] = s * (MR - cr * R[:, 1, :])
        A[:, 0, :2] = s * cr * L[:, 1, :]
        b[:, 0] = -s * cr * p[1]
    # E2: M- - M+ = 0
    A[:, 1, :2] = ML
    A[:, 1, 2:] = -MR
    b[:, 1] = -MP
    # E3: V+ - c (w- - w+) = 0
    if np.isinf(c):
        A[:, 2, :2] = L[:, 0, :]
        A[:, 2, 2:] = -R[:, 0, :]
        b[:, 2] = -p[0]
    else:
        s = 1.0 / (1.0 + c)
        A[:, 2, 2:] = s * (VR + c * R[:, 0, :])
        A[:, 2, :2] = -s * c * L[:, 0, :]
        b[:, 2] = s * c * p[0]
    # E4: V- - V+ = 0
    A[:, 3, :2] = VL
    A[:, 3, 2:] = -VR
    b[:, 3] = -VP
    u = np.linalg.solve(A, b[..., None])[..., 0]
    return mu, cg, u[:, :2], u[:, 2:]


class TwoPlates:
    """Kirchhoff reference. Load: uniform pressure on [x1, x2] x [-b, b] (x2 <= 0), resultant
    `force` (default 1). Joint: shear c (units k ell), rotation c_r (units D/ell); inf allowed."""

    def __init__(self, c, cr=0.0, nu=0.15, x1=-0.2, x2=0.0, b=0.1, force=1.0, rule=None):
        if x2 > 0 or x1 >= x2:
            raise ValueError("the patch must lie on the left plate: x1 < x2 <= 0")
        self.c, self.cr, self.nu = c, cr, nu
        self.x1, self.x2, self.b = x1, x2, b
        self.pressure = force / ((x2 - x1) * 2 * b)
        self.eta, self.weta = rule if rule is not None else eta_rule()
        self.mu, self.cg, self.B, self.C = kirchhoff_amplitudes(self.eta, c, cr, nu, x1, x2)
        e = self.eta
        with np.errstate(invalid="ignore", divide="ignore"):
            q = np.where(e > 0, 2 * np.sin(e * b) / np.where(e > 0, e, 1), 2 * b)
        self.qhat = self.pressure * q  # transform of the y-profile times pressure

    def W(self, x, side, deriv=0):
        """Transform W(x, eta) (complex array over eta) at a point x on `side` ('L' or 'R')."""
        if side == "L":
            if x > 0:
                raise ValueError("left plate is x <= 0")
            h = np.sum(self.B * self.mu ** deriv * np.exp(self.mu * x), axis=-1)
            p = _box_particular(x, self.mu, self.cg, self.x1, self.x2)[deriv]
            return self.qhat * (h + p)
        if x < 0:
            raise ValueError("right plate is x >= 0")
        h = np.sum(self.C * (-self.mu) ** deriv * np.exp(-self.mu * x), axis=-1)
        return self.qhat * h

    def w(self, x, y, side, deriv=0):
        Wx = self.W(x, side, deriv)
        val = np.sum(self.weta * Wx * np.cos(self.eta * y)) / np.pi
        return val.real

    def lte(self, y=0.0):
        """Deflection LTE = w(0+, y) / w(0-, y)."""
        return self.w(0.0, y, "R") / self.w(0.0, y, "L")

    def my(self, x, y, side):
        """Bending moment m_y = -D (w_yy + nu w_xx) (positive: soil side in tension, liftoff's
        sign), in P: the moment of the edge stress sigma_yy = 6 m_y / H^2 along the joint."""
        W0 = self.W(x, side, 0)
        W2 = self.W(x, side, 2)
        val = np.sum(self.weta * (self.eta ** 2 * W0 - self.nu * W2) * np.cos(self.eta * y)) / np.pi
        return val.real

    def stress_lte(self, y=0.0):
        """Stress LTE = m_y(0+, y) / m_y(0-, y) (edge stresses along the joint)."""
        return self.my(0.0, y, "R") / self.my(0.0, y, "L")

    def joint_shear(self, y=0.0):
        """Shear force per length carried by the joint, c (w- - w+), in P/ell."""
        jump = self.w(0.0, y, "L") - self.w(0.0, y, "R")
        return self.c * jump

    def transferred_force(self):
        """Total force through the joint = c int (w- - w+) dy = c (W-(0,0) - W+(0,0)) (eta = 0)."""
        mu, cg, B, C = kirchhoff_amplitudes(np.array([0.0]), self.c, self.cr, self.nu,
                                            self.x1, self.x2)
        q0 = self.pressure * 2 * self.b
        p = _box_particular(0.0, mu, cg, self.x1, self.x2)[0]
        wl = q0 * (np.sum(B) + p[0])
        wr = q0 * np.sum(C)
        return (self.c * (wl - wr)).real



# ------------------------------------------------------------------------------------------
# Mindlin plates (from the design's ref_two_plates_mindlin.py). Per eta the first-order system
# z' = A z + g, z = (W, W', X, X', Y, Y') with w = W cos(eta y), psi_x = X cos(eta y),
# psi_y = Y sin(eta y), S = chi G H = chi 6 (1 - nu) / H^2 (D = 1):
#   W'' = X' + eta^2 W + eta Y + (k W - q)/S
#   X'' = ((1-nu)/2 eta^2 + S/D) X - (1+nu)/2 eta Y' - (S/D) W'
#   Y'' = (1+nu)/(1-nu) eta X' + 2/(1-nu) [(eta^2 + S/D) Y + (S/D) eta W]
# Joint: Qx+ = Qx- = c (W+ - W-), Mx+ = Mx- = c_r (X+ - X-), Mxy+ = Mxy- = 0 with
# Mx = D (X' + nu eta Y), Mxy = D (1-nu)/2 (Y' - eta X), Qx = S (W' - X).
# ------------------------------------------------------------------------------------------


def system_matrix(eta, nu, S):
    D = 1.0
    k = 1.0
    A = np.zeros((6, 6))
    A[0, 1] = 1
    A[2, 3] = 1
    A[4, 5] = 1
    # W''
    A[1, 0] = eta ** 2 + k / S
    A[1, 3] = 1.0
    A[1, 4] = eta
    # X''
    A[3, 1] = -S / D
    A[3, 2] = (1 - nu) / 2 * eta ** 2 + S / D
    A[3, 5] = -(1 + nu) / 2 * eta
    # Y''
    A[5, 0] = 2 / (1 - nu) * (S / D) * eta
    A[5, 3] = (1 + nu) / (1 - nu) * eta
    A[5, 4] = 2 / (1 - nu) * (eta ** 2 + S / D)
    return A


class TwoMindlin:
    """rects: list of (x1, x2, b, pressure) with x2 <= 0 (load on the left plate)."""

    def __init__(self, c, cr, nu, H, rects, chi=5.0 / 6.0, rule=None, ct=0.0):
        self.c, self.cr, self.nu, self.H = c, cr, nu, H
        # ct: spring on the jump of the tangential rotation psi_y (0 in liftoff's joints; inf
        # with c = cr = inf makes the joint the continuous plate).
        self.ct = ct
        self.S = chi * 6 * (1 - nu) / H ** 2
        self.rects = rects
        self.eta, self.weta = rule if rule is not None else eta_rule(eta_max=2000.0)
        self._solve()

    def _solve(self):
        nu, S = self.nu, self.S
        n = self.eta.size
        self.lam = np.zeros((n, 6), dtype=complex)
        self.V = np.zeros((n, 6, 6), dtype=complex)
        self.gt = np.zeros((n, len(self.rects), 6), dtype=complex)  # V^-1 g per rectangle
        self.amp = np.zeros((n, 6), dtype=complex)  # 3 left (Re>0), 3 right (Re<0)
        for i, e in enumerate(self.eta):
            A = system_matrix(e, nu, S)
            lam, V = np.linalg.eig(A)
            order = np.argsort(lam.real)  # 3 negative (right plate) then 3 positive (left)
            lam, V = lam[order], V[:, order]
            Vinv = np.linalg.inv(V)
            self.lam[i], self.V[i] = lam, V
            for r, (x1, x2, b, p) in enumerate(self.rects):
                qhat = p * (2 * np.sin(e * b) / e if e > 0 else 2 * b)
                g = np.zeros(6)
                g[1] = -qhat / S
                self.gt[i, r] = Vinv @ g
            zp = self._particular(i, 0.0)  # at x = 0 (all loads at x2 <= 0)
            # homogeneous: left z = sum_{j in 3..5} a_j V[:, j] e^{lam_j x}; right j in 0..2
            VL, VR = V[:, 3:], V[:, :3]

            def res(z):  # (Mx, Mxy, Qx, W, X) of a state vector at x = 0
                W, W1, X, X1, Y, Y1 = z
                return np.array([X1 + nu * e * Y, (1 - nu) / 2 * (Y1 - e * X), S * (W1 - X), W, X, Y])

            RL = np.array([res(VL[:, j]) for j in range(3)]).T  # (5, 3)
            RR = np.array([res(VR[:, j]) for j in range(3)]).T
            RP = res(zp)
            M = np.zeros((6, 6), dtype=complex)
            rhs = np.zeros(6, dtype=complex)
            c, cr = self.c, self.cr
            # E1: Mx+ - cr (X+ - X-) = 0
            if np.isinf(cr):
                M[0, 3:] = RR[4]
                M[0, :3] = -RL[4]
                rhs[0] = RP[4]
            else:
                s = 1 / (1 + cr)
                M[0, 3:] = s * (RR[0] - cr * RR[4])
                M[0, :3] = s * cr * RL[4]
                rhs[0] = -s * cr * RP[4]
            # E2: Mx- - Mx+ = 0
            M[1, :3] = RL[0]
            M[1, 3:] = -RR[0]
            rhs[1] = -RP[0]
            # E3: Qx+ - c (W+ - W-) = 0
            if np.isinf(c):
                M[2, 3:] = RR[3]
                M[2, :3] = -RL[3]
                rhs[2] = RP[3]
            else:
                s = 1 / (1 + c)
                M[2, 3:] = s * (RR[2] - c * RR[3])
                M[2, :3] = s * c * RL[3]
                rhs[2] = -s * c * RP[3]
            # E4: Qx- - Qx+ = 0
            M[3, :3] = RL[2]
            M[3, 3:] = -RR[2]
            rhs[3] = -RP[2]
            # E5: Mxy+ - ct (Y+ - Y-) = 0 (ct = 0: Mxy+ = 0)
            ct = self.ct
            if np.isinf(ct):
                M[4, 3:] = RR[5]
                M[4, :3] = -RL[5]
                rhs[4] = RP[5]
            else:
                s = 1 / (1 + ct)
                M[4, 3:] = s * (RR[1] - ct * RR[5])
                M[4, :3] = s * ct * RL[5]
                rhs[4] = -s * ct * RP[5]
            # E6: Mxy- - Mxy+ = 0
            M[5, :3] = RL[1]
            M[5, 3:] = -RR[1]
            rhs[5] = -RP[1]
            a = np.linalg.solve(M, rhs)
            self.amp[i, 3:] = a[:3]  # left
            self.amp[i, :3] = a[3:]  # right

    def _particular(self, i, x):
        lam, V = self.lam[i], self.V[i]
        out = np.zeros(6, dtype=complex)
        for r, (x1, x2, b, p) in enumerate(self.rects):
            coef = np.zeros(6, dtype=complex)
            for j in range(6):
                L = lam[j]
                if L.real < 0:
                    if x > x1:
                        u = min(x, x2)
                        coef[j] = (np.exp(L * (x - x1)) - np.exp(L * (x - u))) / L
                else:
                    if x < x2:
                        v = max(x, x1)
                        coef[j] = -(np.exp(L * (x - v)) - np.exp(L * (x - x2))) / L
            out += V @ (coef * self.gt[i, r])
        return out

    def Wt(self, x, side, comp=0):
        """Transform of state component `comp` (0 W, 1 W', 2 X, 3 X', 4 Y, 5 Y') at x."""
        vals = np.zeros(self.eta.size, dtype=complex)
        for i in range(self.eta.size):
            if side == "L":
                j = slice(3, 6)
                z = self.V[i][:, j] @ (self.amp[i, j] * np.exp(self.lam[i, j] * x))
                z = z + self._particular(i, x)
            else:
                j = slice(0, 3)
                z = self.V[i][:, j] @ (self.amp[i, j] * np.exp(self.lam[i, j] * x))
            vals[i] = z[comp]
        return vals

    def w(self, x, y, side):
        return (np.sum(self.weta * self.Wt(x, side) * np.cos(self.eta * y)) / np.pi).real

    def lte(self, y=0.0):
        return self.w(0.0, y, "R") / self.w(0.0, y, "L")

    def my(self, x, y, side):
        """m_y = -D (psi_y,y + nu psi_x,x) (liftoff's sign: soil side in tension), in P."""
        Y = self.Wt(x, side, 4)
        X1 = self.Wt(x, side, 3)
        return (np.sum(self.weta * (-(self.eta * Y + self.nu * X1)) * np.cos(self.eta * y)) / np.pi).real

    def stress_lte(self, y=0.0):
        return self.my(0.0, y, "R") / self.my(0.0, y, "L")

    def transferred_force(self):
        """c * int (W+ - W-) dy ... = c (W-(0) - W+(0)) at eta = 0 (force carried by the joint)."""
        i = 0  # eta_rule has no node at 0: evaluate a separate eta = 0 solve
        other = TwoMindlin(self.c, self.cr, self.nu, self.H, self.rects, rule=(np.array([0.0]), np.array([1.0])), ct=self.ct)
        wl = other.Wt(0.0, "L")[0]
        wr = other.Wt(0.0, "R")[0]
        return (self.c * (wl - wr)).real



# ------------------------------------------------------------------------------------------
# Dowels (from the design's ref_dowels.py): Friberg (1940) / Timoshenko & Lessels (1925), the
# equivalent spring between the slabs, Friberg's distribution, the exact discrete row
# (Kirchhoff): F = (I / k_d + 2 G)^-1 w_load, G_ij = g(y_i - y_j) the free-edge deflection
# under a unit edge point force, w_load the left free edge under the load.
# ------------------------------------------------------------------------------------------


def dowel_props(d, E_d, K, nu_d=0.3):
    I = np.pi * d ** 4 / 64
    A = np.pi * d ** 2 / 4
    G = E_d / (2 * (1 + nu_d))
    beta = (K * d / (4 * E_d * I)) ** 0.25
    return I, A, G, beta


def friberg_y0(P, d, E_d, K, z):
    I, _, _, beta = dowel_props(d, E_d, K)
    return P * (2 + beta * z) / (4 * beta ** 3 * E_d * I)


def bearing_stress(P, d, E_d, K, z):
    return K * friberg_y0(P, d, E_d, K, z)


def dci(d, E_d, K, z):
    I, _, _, beta = dowel_props(d, E_d, K)
    return 4 * beta ** 3 * E_d * I / (2 + beta * z)


def dowel_spring(d, E_d, K, z, shear=False, nu_d=0.3, kappa_d=0.9):
    """Equivalent spring k_d = P / Delta between the slabs (N/m)."""
    I, A, G, beta = dowel_props(d, E_d, K, nu_d)
    flex = (2 + beta * z) / (2 * beta ** 3 * E_d * I)  # 2 y0 / P
    flex += z * (1 + beta * z) / (2 * beta ** 2 * E_d * I)  # theta0 z / P
    flex += z ** 3 / (12 * E_d * I)  # bending across the opening
    if shear:
        flex += z / (kappa_d * G * A)
    return 1.0 / flex


def friberg_shares(y_dowels, y_load, ell, reach=1.8):
    w = np.clip(1 - np.abs(np.asarray(y_dowels) - y_load) / (reach * ell), 0, None)
    return w / w.sum()


# ------------------------------------------------------------------------------------------
# 4. Exact discrete dowels between two semi-infinite Kirchhoff plates (D = k = 1 units).
# ------------------------------------------------------------------------------------------


def edge_green(nu, y):
    """Deflection at (0, y) of a free edge (semi-infinite Kirchhoff plate on Winkler, D = k = 1)
    under a unit downward point force at (0, 0) on the edge."""

    def f(e):
        m1 = np.sqrt(e * e + 1j)
        m2 = np.sqrt(e * e - 1j)
        a1 = (1 - nu) * e * e + 1j
        a2 = (1 - nu) * e * e - 1j
        return (-2j / (m1 * a2 ** 2 - m2 * a1 ** 2)).real

    y = abs(y)
    if y == 0:
        return quad(f, 0, np.inf, limit=800, epsabs=1e-14, epsrel=1e-12)[0] / np.pi
    # finite part by adaptive quadrature, the oscillatory tail by QAWF (weight cos)
    head = quad(lambda e: f(e) * np.cos(e * y), 0, 20.0, limit=800, epsabs=1e-14)[0]
    tail = quad(f, 20.0, np.inf, weight="cos", wvar=y, limlst=200)[0]
    return (head + tail) / np.pi


def discrete_dowels(kd, y_dowels, nu, x1, x2, b, force=1.0):
    """Dowel forces (positive: carried from the loaded left plate to the right one) for springs
    kd (units k ell^2 = D/ell^2) at y_dowels (ell); patch [x1, x2] x [-b, b], resultant `force`."""
    y = np.asarray(y_dowels, dtype=float)
    free = TwoPlates(c=0.0, cr=0.0, nu=nu, x1=x1, x2=x2, b=b, force=force,
                     rule=eta_rule(eta_max=2e4))
    wl = np.array([free.w(0.0, yi, "L") for yi in y])
    offs = np.unique(np.round(np.abs(y[:, None] - y[None, :]), 12))
    gval = {o: edge_green(nu, o) for o in offs}
    G = np.array([[gval[np.round(abs(a - c), 12)] for c in y] for a in y])
    F = np.linalg.solve(np.eye(len(y)) / kd + 2 * G, wl)
    return F, wl, G


# ------------------------------------------------------------------------------------------
# Westergaard's formulas (as given by Ioannides, Thompson & Barenberg 1985, TRR 1043).
# ------------------------------------------------------------------------------------------


def westergaard_edge_1926(nu):
    """Westergaard (1926) edge deflection, point load: (1/sqrt 6)(1 + 0.4 nu) P/(k ell^2)."""
    return (1 + 0.4 * nu) / np.sqrt(6.0)


def westergaard_edge_1948(nu):
    """Westergaard (1948), point load on the edge: sqrt(2 + 1.2 nu) P / sqrt(E h^3 k) with
    sqrt(E h^3 k) = sqrt(12 (1 - nu^2)) k ell^2."""
    return np.sqrt(2 + 1.2 * nu) / np.sqrt(12 * (1 - nu ** 2))


# ------------------------------------------------------------------------------------------
# The numbers of tests/joints_reference.rs.
# ------------------------------------------------------------------------------------------

NU = 0.15
H_A = 0.25  # plate thickness of the section-a scene, in ell
RECTS = [(-0.5, 0.0, 0.25, 4.0)]  # the patch [-0.5, 0] x [-0.25, 0.25], P = 1
POINTS = [(0.0, 0.0, "L"), (0.0, 0.0, "R"), (-0.25, 0.0, "L"), (0.25, 0.0, "R"),
          (0.0, 0.5, "L"), (0.0, 0.5, "R"), (-1.0, 0.0, "L"), (1.0, 1.0, "R")]
AGG = [0.01, 0.03, 0.1, 0.3, 1, 3, 10, 30, 100, 300, 1000]


def crovetti(f):
    """Crovetti's regression (J. A. Crovetti, PhD thesis, University of Illinois at
    Urbana-Champaign, 1994), f = AGG/(k ell); constants as recalled, not re-read there."""
    return 1 / (1 + 1.2 * f ** -0.849)


def log_form(f, a):
    """The log form of Ioannides & Korovesis's family ("Aggregate interlock: a pure-shear load
    transfer mechanism", Transportation Research Record 1286, 1990, pp. 14-24), a = a/ell of
    the load; constants as recalled, not re-read there."""
    return 1 / (1 + 10 ** ((0.214 - 0.183 * a - np.log10(f)) / 1.18))


def section_a():
    print("A. Mindlin H = 0.25 ell, nu = 0.15: w k ell^2 / P at (x, y)/ell; LTE_d = w(0+,0)/w(0-,0);")
    print("   F/P transferred; sLTE(h) = m_y(h/2, h/2)+ / m_y(-h/2, h/2)- (element centres)")
    print("   c      c_r | " + " ".join(f"({x:+.2f},{y:.2f}){s}" for (x, y, s) in POINTS)
          + " | LTE_d      F/P        sLTE(1/8)  sLTE(1/16) sLTE(1/32)")
    for (c, cr) in [(0.1, 0.0), (1.0, 0.0), (10.0, 0.0), (100.0, 0.0), (10.0, 1.0)]:
        r = TwoMindlin(c, cr, NU, H_A, RECTS)
        vals = " ".join(f"{r.w(x, y, s):.8f}" for (x, y, s) in POINTS)
        sl = [r.my(h / 2, h / 2, "R") / r.my(-h / 2, h / 2, "L") for h in (1 / 8, 1 / 16, 1 / 32)]
        print(f"   {c:<6g} {cr:<3g} | {vals} | {r.lte():.8f} {r.transferred_force():.8f} "
              + " ".join(f"{v:.8f}" for v in sl))


def section_w():
    print("\nW. c = 0 (free joint), loaded side: w k ell^2 / P at (0,0) (-0.25,0) (0,0.5) (-1,0)")
    rule = eta_rule(eta_max=2e4)
    k = TwoPlates(0.0, 0.0, NU, -0.5, 0.0, 0.25, rule=rule)
    left = [p for p in POINTS if p[2] == "L"]
    print("   Kirchhoff          " + " ".join(f"{k.w(x, y, s):.8f}" for (x, y, s) in left))
    m = TwoMindlin(0.0, 0.0, NU, 0.02, RECTS, rule=rule)
    print("   Mindlin H = 0.02   " + " ".join(f"{m.w(x, y, s):.8f}" for (x, y, s) in left))
    print(f"   point load on the free edge (Kirchhoff, exact): {edge_green(NU, 0.0):.6f};"
          f" Westergaard 1948 {westergaard_edge_1948(NU):.6f}, 1926 {westergaard_edge_1926(NU):.6f}")


def section_l():
    a_eq = np.sqrt(0.25 / np.pi)  # radius of the circle of the patch's area
    print(f"\nL. deflection LTE vs f = AGG/(k ell) (Mindlin H = 0.25 ell); regressions with a/ell = {a_eq:.4f}")
    print("   f        exact Mindlin  Crovetti     log form")
    for f in AGG:
        m = TwoMindlin(f, 0.0, NU, H_A, RECTS).lte()
        print(f"   {f:<8g} {m:.8f}     {crovetti(f):.8f}   {log_form(f, a_eq):.8f}")


def section_d():
    ell, ksub = 0.9, 8e7
    E, d, E_d, K, z, spacing = 30e9, 0.032, 200e9, 4.07e11, 0.006, 0.3
    H = (12 * (1 - NU ** 2) * ksub * ell ** 4 / E) ** (1 / 3)  # D = k ell^4
    kd = dowel_spring(d, E_d, K, z) / (ksub * ell ** 2)
    s = spacing / ell
    a = 0.25 / ell
    print(f"\nD. dowels: ell = {ell} m, k = {ksub:g} N/m^3, H = {H:.6f} m (H/ell = {H/ell:.6f}),"
          f" k_d = {kd:.6f} k ell^2, c = k_d/s = {kd/s:.6f} k ell")
    rects = [(-a, 0.0, a / 2, 1.0 / (a * a))]
    m = TwoMindlin(kd / s, 0.0, NU, H / ell, rects)
    ys = s * np.arange(0, 7)
    jump = [m.w(0.0, y, "L") - m.w(0.0, y, "R") for y in ys]
    print(f"   smeared Mindlin: transferred {m.transferred_force():.8f} P; c (w- - w+)(y_i) s / P at y = 0, s, ..., 6s:")
    print("     " + " ".join(f"{kd / s * j * s:.8f}" for j in jump))
    ysym = s * np.arange(-18, 19)
    F, _, _ = discrete_dowels(kd, ysym, NU, -a, 0.0, a / 2)
    smk = TwoPlates(kd / s, 0.0, NU, -a, 0.0, a / 2)
    print(f"   Kirchhoff, 37 discrete bars: transferred {F.sum():.6f} P (smeared {smk.transferred_force():.6f});"
          f" forces / P at y = 0 ... 6s:")
    print("     " + " ".join(f"{v:.6f}" for v in F[18:25]))
    print("   Kirchhoff smeared at the same y:  " + " ".join(f"{smk.joint_shear(y) * s:.6f}" for y in ys))
    print(f"   Friberg's share of the critical bar: reach 1.8 ell {friberg_shares(ysym, 0, 1.0)[18]:.4f},"
          f" reach 1.0 ell {friberg_shares(ysym, 0, 1.0, 1.0)[18]:.4f}; exact {F[18] / F.sum():.4f}")


def disk_strips(xc, a, force=1.0, n=64):
    """A uniform disk of radius a centred at (xc, 0) as n strips [x_i, x_i+1] x [-b_i, b_i]
    of equal width h = 2a/n, each as long as the disk's area in its band over h (the band's
    area is the circle's segment difference, in closed form): the force and its distribution
    in x are the disk's exactly, only the spread in y within a band is the rectangle's."""
    p = force / (np.pi * a * a)
    h = 2 * a / n

    def area_left_of(u):  # the disk's area with x - xc <= u, -a <= u <= a
        u = min(max(u, -a), a)
        return u * np.sqrt(a * a - u * u) + a * a * np.arcsin(u / a) + np.pi * a * a / 2

    rects = []
    for i in range(n):
        u0, u1 = -a + i * h, -a + (i + 1) * h
        band = area_left_of(u1) - area_left_of(u0)
        rects.append((xc + u0, xc + u1, band / (2 * h), p))
    return rects


FWD_OFFSETS = [0.0, 0.203, 0.305, 0.457, 0.610, 0.914, 1.219, 1.524]


def section_f():
    a = 0.15
    xc = -a
    rects = disk_strips(xc, a)
    print(f"\nF. a deflectometer's disk (radius {a} ell, 64 strips) touching the joint on the left plate,")
    print(f"   centre x = {xc}; Mindlin H = {H_A} ell, nu = {NU}; w k ell^2 / P at the sensors x = {xc} + r, y = 0")
    print("   c      | " + " ".join(f"r={r:<6g}" for r in FWD_OFFSETS))
    for c in (0.3, 1.0, 3.0):
        m = TwoMindlin(c, 0.0, NU, H_A, rects)
        vals = [m.w(xc + r, 0.0, "L" if xc + r < 0 else "R") for r in FWD_OFFSETS]
        print(f"   {c:<6g} | " + " ".join(f"{v:.8f}" for v in vals))


if __name__ == "__main__":
    import sys

    if sys.argv[1:] == ["--check"]:
        import two_plates_check

        sys.exit(two_plates_check.main())
    if sys.argv[1:]:
        sys.exit(f"usage: {sys.argv[0]} [--check]")
    section_a()
    section_w()
    section_l()
    section_d()
    section_f()
