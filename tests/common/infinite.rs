//! The infinite bonded Mindlin plate on any soil of known surface compliance, by its wavenumber
//! integral: a reference that no library code takes part in.

/// The plate: Young's modulus (Pa), Poisson's ratio, thickness (m); shear correction 5/6.
pub struct Plate {
    /// E, Pa.
    pub e: f64,
    /// ν.
    pub nu: f64,
    /// H, m.
    pub h: f64,
}

/// Gauss–Legendre nodes and weights on [−1, 1] (Golub–Welsch by Newton on P_n).
pub fn gauss(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let dx = p1 / dp;
                x -= dx;
                if dx.abs() < 1e-15 {
                    break;
                }
            }
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}

/// The infinite bonded Mindlin plate on a soil of surface compliance C(ξ) (`compliance`,
/// settlement over pressure at wavenumber ξ: 1/k for Winkler springs, 1/c + 1/(k + Gξ²) for a
/// Kerr soil) under a uniform c × c square of total force `p`, at the square's centre: (m_x,
/// w). With ψ = ∇φ the plate's symbol is ŵ = (1 + Dξ²/S) q̂ / (Dξ⁴ + (1 + Dξ²/S)/C(ξ)),
/// m̂_x + m̂_y = D(1 + ν)ξ² q̂ / den (DESIGN.md §4); at the centre of
/// the square m_x = m_y, so m_x(0) = (1 + ν)/(4π) ∫ Dξ³ Q̄(ξ)/den dξ with Q̄ the angular mean of
/// q̂, Q̄(ξ) = 8q ∫₀^{π/4} R J₁(ξR)/ξ dt, R = c/(2 cos t). Quadrature: 8-point Gauss panels in ξ
/// up to 400/c (the integrand decays as ξ^(−5/2) and oscillates: the tail is below 1e-4 of the
/// whole), panels in t finer as ξc grows.
pub fn centre(plate: &Plate, compliance: &dyn Fn(f64) -> f64, c: f64, p: f64) -> (f64, f64) {
    let (e, nu, h) = (plate.e, plate.nu, plate.h);
    let d = e * h.powi(3) / (12.0 * (1.0 - nu * nu));
    let s = 5.0 / 6.0 * e / (2.0 * (1.0 + nu)) * h;
    let q = p / (c * c);
    let g8 = gauss(8);
    let g4 = gauss(4);
    let qbar = |xi: f64| -> f64 {
        if xi == 0.0 {
            return p;
        }
        let panels = 4 + (xi * c) as usize / 2;
        let width = std::f64::consts::FRAC_PI_4 / panels as f64;
        let mut sum = 0.0;
        for k in 0..panels {
            for &(x, w) in &g4 {
                let t = width * (k as f64 + 0.5 + 0.5 * x);
                let r = c / (2.0 * t.cos());
                sum += 0.5 * width * w * r * libm::j1(xi * r) / xi;
            }
        }
        8.0 * q * sum
    };
    let (mut m, mut w0) = (0.0, 0.0);
    let step = 0.5 / c;
    let panels = (400.0 / c / step) as usize;
    for k in 0..panels {
        for &(x, wt) in &g8 {
            let xi = step * (k as f64 + 0.5 + 0.5 * x);
            let a = 1.0 + d * xi * xi / s;
            let den = d * xi.powi(4) + a / compliance(xi);
            let qb = qbar(xi);
            m += 0.5 * step * wt * d * xi.powi(3) * qb / den;
            w0 += 0.5 * step * wt * xi * a * qb / den;
        }
    }
    let pi = std::f64::consts::PI;
    ((1.0 + nu) / (4.0 * pi) * m, w0 / (2.0 * pi))
}

/// A uniform rectangular print: centre (x, y) and sides along x and y (m), total force (N).
pub struct Rect {
    /// Centre (x, y), m.
    pub centre: [f64; 2],
    /// Sides along x and y, m.
    pub size: [f64; 2],
    /// Force, N.
    pub force: f64,
}

/// The infinite bonded Mindlin plate on a soil of surface compliance C(ξ) under any number of
/// uniform rectangles, at the point `at`: (m_x, m_y, w), by the 2D wavenumber integral in
/// Cartesian ξ = (ξx, ξy) — no angular averaging, so the prints need not be centred on `at`.
/// A rectangle of sides a × b centred at c has q̂ = q · 2 sin(ξx a/2)/ξx · 2 sin(ξy b/2)/ξy ·
/// e^(−iξ·c), even in ξx and in ξy; so is the plate's symbol, so the odd sin·sin part of
/// e^(iξ·(x − c)) integrates to zero and the plane is four times the quadrant:
/// w(x) = (1/π²) ∫₀^∞∫₀^∞ (1 + Dξ²/S) Σ q̂_j cos(ξx dx_j) cos(ξy dy_j) / den dξx dξy,
/// den = Dξ⁴ + (1 + Dξ²/S)/C(ξ), and with ψ = ∇φ the moments m̂_x = D(ξx² + νξy²) q̂/den,
/// m̂_y = D(ξy² + νξx²) q̂/den (their sum is [`centre`]'s D(1 + ν)ξ² q̂/den).
///
/// Quadrature: 8-point Gauss panels of width 0.25/s in each of ξx, ξy up to `cut`/s, s the
/// smallest side of a print or distance between prints (so every sine and cosine has ≥ 16
/// nodes a period). The moment integrand falls as ρ⁻² q̂ ~ ξ⁻³ along the axes and faster
/// elsewhere: the tail beyond `cut`/s is O((s/cut)²) of the whole (checked by the caller by
/// doubling `cut`).
pub fn rectangles(
    plate: &Plate,
    compliance: &dyn Fn(f64) -> f64,
    prints: &[Rect],
    at: [f64; 2],
    cut: f64,
) -> (f64, f64, f64) {
    let (e, nu, h) = (plate.e, plate.nu, plate.h);
    let d = e * h.powi(3) / (12.0 * (1.0 - nu * nu));
    let s = 5.0 / 6.0 * e / (2.0 * (1.0 + nu)) * h;
    let mut scale = f64::INFINITY;
    for p in prints {
        scale = scale.min(p.size[0]).min(p.size[1]);
        for (a, c) in at.iter().zip(&p.centre) {
            let dist = (a - c).abs();
            if dist > 1e-12 {
                scale = scale.min(dist);
            }
        }
    }
    let step = 0.25 / scale;
    let panels = (cut / scale / step).ceil() as usize;
    let g8 = gauss(8);
    // Nodes and weights along one axis.
    let mut nodes = Vec::with_capacity(panels * 8);
    for k in 0..panels {
        for &(x, wt) in &g8 {
            nodes.push((step * (k as f64 + 0.5 + 0.5 * x), 0.5 * step * wt));
        }
    }
    // Per print and axis: q-free factor 2 sin(ξ a/2)/ξ · cos(ξ d), tabulated once.
    let factor = |axis: usize| -> Vec<Vec<f64>> {
        prints
            .iter()
            .map(|p| {
                let (side, dist) = (p.size[axis], at[axis] - p.centre[axis]);
                nodes
                    .iter()
                    .map(|&(xi, _)| 2.0 * (xi * side / 2.0).sin() / xi * (xi * dist).cos())
                    .collect()
            })
            .collect()
    };
    let (fx, fy) = (factor(0), factor(1));
    let q: Vec<f64> = prints
        .iter()
        .map(|p| p.force / (p.size[0] * p.size[1]))
        .collect();
    let (mut mx, mut my, mut w) = (0.0, 0.0, 0.0);
    for (i, &(xx, wx)) in nodes.iter().enumerate() {
        let (mut row_mx, mut row_my, mut row_w) = (0.0, 0.0, 0.0);
        for (k, &(yy, wy)) in nodes.iter().enumerate() {
            let r2 = xx * xx + yy * yy;
            let a = 1.0 + d * r2 / s;
            let den = d * r2 * r2 + a / compliance(r2.sqrt());
            let load: f64 = (q.iter().zip(&fx).zip(&fy))
                .map(|((q, fx), fy)| q * fx[i] * fy[k])
                .sum();
            let common = wy * load / den;
            row_w += a * common;
            row_mx += d * (xx * xx + nu * yy * yy) * common;
            row_my += d * (yy * yy + nu * xx * xx) * common;
        }
        mx += wx * row_mx;
        my += wx * row_my;
        w += wx * row_w;
    }
    let pi2 = std::f64::consts::PI.powi(2);
    (mx / pi2, my / pi2, w / pi2)
}

/// J_n(x) = (1/π) ∫₀^π cos(nτ − x sin τ) dτ by the trapezoid rule: the integrand is smooth and
/// periodic, so the rule converges geometrically once the points outnumber |x| (Trefethen &
/// Weideman 2014); 40 + |x| points leave round-off.
pub fn bessel(n: u32, x: f64) -> f64 {
    let m = 40 + x.abs().ceil() as usize;
    let h = std::f64::consts::PI / m as f64;
    let f = |tau: f64| (f64::from(n) * tau - x * tau.sin()).cos();
    let mut sum = 0.5 * (f(0.0) + f(std::f64::consts::PI));
    for i in 1..m {
        sum += f(i as f64 * h);
    }
    sum * h / std::f64::consts::PI
}

/// The infinite plate on a dense liquid of modulus `k` under a uniform disk of `radius` and
/// total `force`, at distance `r` from the disk's centre; Mindlin's plate with shear correction
/// 5/6, or Kirchhoff's (`kirchhoff`):
///
/// w(r) = q a ∫₀^∞ J₁(ξa) J₀(ξr) (1 + Dξ²/S) / (Dξ⁴ + k (1 + Dξ²/S)) dξ,
///
/// S = κ G h (∞ for Kirchhoff) — the plate equation D∇⁴w = (1 − D∇²/S)(q − k w) in Hankel
/// space. Simpson's rule on [0, 60/ℓ] in steps of ℓ⁻¹/400: the integrand falls like ξ⁻⁵
/// beyond, the tail is below 1e-8 of the centre deflection.
pub fn disk_on_springs(
    plate: &Plate,
    k: f64,
    radius: f64,
    force: f64,
    r: f64,
    kirchhoff: bool,
) -> f64 {
    let d = plate.e * plate.h.powi(3) / (12.0 * (1.0 - plate.nu * plate.nu));
    let ell = (d / k).powf(0.25);
    disk_on_soil(plate, &|_| k, ell, radius, force, r, kirchhoff)
}

/// The infinite plate under a uniform disk on an elastic half-space of Young's modulus `es` and
/// Poisson's ratio `nus` (Boussinesq's surface compliance 2(1 − ν_s²)/(E_s ξ)), at distance `r`:
/// [`disk_on_soil`] with the soil's stiffness E_s ξ / (2(1 − ν_s²)) and its radius of relative
/// stiffness ℓ = (2D(1 − ν_s²)/E_s)^⅓. At small ξ the denominator falls as ξ, and J₁(ξa)/ξ →
/// a/2: the integrand stays finite at 0.
pub fn disk_on_halfspace(plate: &Plate, es: f64, nus: f64, radius: f64, force: f64, r: f64) -> f64 {
    let d = plate.e * plate.h.powi(3) / (12.0 * (1.0 - plate.nu * plate.nu));
    let ell = (2.0 * d * (1.0 - nus * nus) / es).cbrt();
    let stiffness = |xi: f64| es * xi / (2.0 * (1.0 - nus * nus));
    disk_on_soil(plate, &stiffness, ell, radius, force, r, false)
}

/// [`disk_on_springs`] on any soil of surface stiffness K(ξ) (pressure over settlement at
/// wavenumber ξ), with its radius of relative stiffness `ell` setting the range:
/// w(r) = q a ∫₀^∞ J₁(ξa) J₀(ξr) (1 + Dξ²/S) / (Dξ⁴ + K(ξ)(1 + Dξ²/S)) dξ.
fn disk_on_soil(
    plate: &Plate,
    stiffness: &dyn Fn(f64) -> f64,
    ell: f64,
    radius: f64,
    force: f64,
    r: f64,
    kirchhoff: bool,
) -> f64 {
    let (e, nu, h) = (plate.e, plate.nu, plate.h);
    let d = e * h.powi(3) / (12.0 * (1.0 - nu * nu));
    let shear = if kirchhoff {
        f64::INFINITY
    } else {
        5.0 / 6.0 * e / (2.0 * (1.0 + nu)) * h
    };
    let q = force / (std::f64::consts::PI * radius * radius);
    let f = |xi: f64| {
        let s = 1.0 + d * xi * xi / shear;
        let den = d * xi.powi(4) + stiffness(xi) * s;
        if den == 0.0 {
            // ξ = 0 on a soil whose stiffness vanishes there: J₁(ξa)/den → (a/2)/(K'(0)),
            // taken from the next point's limit (the node's weight is a 1/72 000 share).
            let tiny = 1e-9 / ell;
            return bessel(1, tiny * radius) * s / (d * tiny.powi(4) + stiffness(tiny) * s);
        }
        bessel(1, xi * radius) * bessel(0, xi * r) * s / den
    };
    let steps = 24_000; // even
    let top = 60.0 / ell;
    let step = top / steps as f64;
    let mut sum = f(0.0) + f(top);
    for i in 1..steps {
        sum += if i % 2 == 1 { 4.0 } else { 2.0 } * f(i as f64 * step);
    }
    q * radius * sum * step / 3.0
}
