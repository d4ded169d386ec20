#!/usr/bin/env python3
"""The dowel bar's constants of src/layout.rs (DowelBar) from a direct solution of the beam,
without its closed forms. Python 3 standard library only:

    python3 tests/references/dowel_beam.py

The bar (E_d, I_d = pi d^4 / 64) rests in each slab on a Winkler bed of modulus K d per unit
length (K the modulus of dowel support, N/m^3) and spans the joint opening z between them. The
left slab is displaced by Delta = 1 m relative to the right one; the bar then carries a shear
P across the opening, and the equivalent spring is k_d = P / Delta. Unknowns (8):

  left,  x <= 0:  u = y - Delta = exp(b x) (A cos b x + B sin b x)   (decays as x -> -inf)
  span, 0 <= x <= z:  y = a0 + a1 x + a2 x^2 + a3 x^3                 (E_d I_d y'''' = 0)
  right, x >= z:  y = exp(-b s) (C cos b s + D sin b s), s = x - z

with b = (K d / (4 E_d I_d))^(1/4), the root of E_d I_d y'''' + K d y = 0 (the definition of
beta, not a result). At x = 0 and x = z: y, y', y'' and y''' continuous (deflection, slope,
moment, shear). The derivatives of the exponentials are exact (the product rule, below); the
8 x 8 system is solved by Gaussian elimination with partial pivoting.

Printed: beta, k_d for z = 0, 3, 6, 12.7, 25 mm (src/layout.rs's
dowel_spring_matches_the_direct_beam_solution), and for P = 10 kN at z = 6 mm the face
deflection y0 = |u(0)| P / P_1 (P_1 the shear of the unit-Delta solution) and the bearing
stress K y0 — which Friberg (1940, "Design of dowels in transverse joints of concrete
pavements", Trans. ASCE 105) gives in closed form, after Timoshenko & Lessels (1925), as
y0 = P (2 + b z) / (4 b^3 E_d I_d); the same formula is in Huang's Pavement Analysis and
Design (dowel bars).
"""

import math

D_BAR, E_D, K_S = 0.032, 200e9, 4.07e11


def exp_trig(b, sign):
    """Value and first three derivatives at the origin of exp(sign b x) cos(b x) and
    exp(sign b x) sin(b x): (f, f', f'', f''') for each."""
    # d/dx [e^{s b x}(cos, sin)] = b [[s, -1], [1, s]] (cos, sin) in the basis (e cos, e sin).
    m = [[sign * b, -b], [b, sign * b]]
    out = {"cos": [], "sin": []}
    vec = {"cos": (1.0, 0.0), "sin": (0.0, 1.0)}  # (coefficient of e cos, of e sin)
    for key in ("cos", "sin"):
        c = vec[key]
        for _ in range(4):
            out[key].append(c[0])  # at x = 0: e cos = 1, e sin = 0
            c = (m[0][0] * c[0] + m[1][0] * c[1], m[0][1] * c[0] + m[1][1] * c[1])
    return out["cos"], out["sin"]


def solve(a, rhs):
    n = len(rhs)
    a = [row[:] + [r] for row, r in zip(a, rhs)]
    for col in range(n):
        piv = max(range(col, n), key=lambda r: abs(a[r][col]))
        a[col], a[piv] = a[piv], a[col]
        for r in range(col + 1, n):
            f = a[r][col] / a[col][col]
            for c in range(col, n + 1):
                a[r][c] -= f * a[col][c]
    x = [0.0] * n
    for r in reversed(range(n)):
        x[r] = (a[r][n] - sum(a[r][c] * x[c] for c in range(r + 1, n))) / a[r][r]
    return x


def bar(z, d=D_BAR, e_d=E_D, k=K_S):
    """(beta, k_d, u(0) per unit P) of the bar across an opening z."""
    ei = e_d * math.pi * d ** 4 / 64.0
    b = (k * d / (4.0 * ei)) ** 0.25
    lc, ls = exp_trig(b, +1.0)  # left: e^{+bx}
    rc, rs = exp_trig(b, -1.0)  # right: e^{-bs}
    # The span's cubic and its derivatives at x and the unknowns' order (A, B, a0..a3, C, D).
    def cubic(x):
        return [
            [1.0, x, x * x, x ** 3],
            [0.0, 1.0, 2 * x, 3 * x * x],
            [0.0, 0.0, 2.0, 6 * x],
            [0.0, 0.0, 0.0, 6.0],
        ]
    rows, rhs = [], []
    c0, cz = cubic(0.0), cubic(z)
    for n in range(4):
        # x = 0: left (u + Delta, Delta = 1 in y only) = span.
        rows.append([lc[n], ls[n]] + [-v for v in c0[n]] + [0.0, 0.0])
        rhs.append(-1.0 if n == 0 else 0.0)
        # x = z: span = right.
        rows.append([0.0, 0.0] + cz[n] + [-rc[n], -rs[n]])
        rhs.append(0.0)
    a_, b_, a0, a1, a2, a3, c_, d_ = solve(rows, rhs)
    shear = ei * 6.0 * a3  # E_d I_d y''' in the span: the force across the opening
    p = abs(shear)
    return b, p / 1.0, abs(a_) / p


if __name__ == "__main__":
    b0, _, _ = bar(0.0)
    print(f"beta = {b0!r} 1/m (d = {D_BAR} m, E_d = {E_D:g} Pa, K = {K_S:g} N/m^3)")
    for z in (0.0, 0.003, 0.006, 0.0127, 0.025):
        print(f"z = {z:<7g} k_d = {bar(z)[1]!r} N/m")
    _, _, y0_per_p = bar(0.006)
    y0 = 1e4 * y0_per_p
    print(f"P = 10 kN, z = 6 mm: y0 = {y0!r} m, bearing stress K y0 = {K_S * y0!r} Pa")
