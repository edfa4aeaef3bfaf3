//! Helpers shared by the NORM validation tests: a Hertz reference (methods.md §1.3, independent of
//! the kernel) and estimators of a discrete Hertz-like solution.
#![allow(dead_code, clippy::needless_range_loop)]

use std::f64::consts::PI;
use wrc_host_tests::norm::NormSolution;

/// Complete elliptic integrals by the AGM in the cancellation-free form of methods.md §1.3:
/// returns (K, m/2 + Σ, m/2 − Σ) for b₀ = g, m = 1 − g².
fn agm(g: f64) -> (f64, f64, f64) {
    let m = 1.0 - g * g;
    let (mut a, mut b, mut c) = (1.0f64, g, m.sqrt());
    let mut sigma = 0.0;
    let mut w = 1.0;
    for _ in 0..64 {
        if c.abs() < 1e-16 {
            break;
        }
        let (an, bn, cn) = (0.5 * (a + b), (a * b).sqrt(), 0.5 * (a - b));
        a = an;
        b = bn;
        c = cn;
        sigma += w * c * c;
        w *= 2.0;
    }
    let k = PI / (2.0 * a);
    // Σ = Σ_{k≥1} 2^{k−1} c_k² with c_k from the AGM
    (k, 0.5 * m + sigma, 0.5 * m - sigma)
}

/// A Hertz contact defined by its semi-axes (inverse problem, methods.md §1.3 step 7).
#[derive(Clone, Copy, Debug)]
pub struct Hertz {
    pub a: f64,
    pub b: f64,
    pub n: f64,
    pub e_star: f64,
    pub ca: f64,
    pub cb: f64,
    pub delta: f64,
    pub p0: f64,
}

impl Hertz {
    /// Semi-axes a (x), b (y) in mm, load N in N, contact modulus E* in MPa.
    pub fn from_axes(a: f64, b: f64, n: f64, e_star: f64) -> Self {
        let g = a.min(b) / a.max(b);
        let (k, km, ks) = agm(g);
        let e = k * ks + g * g * k; // E − g²K = K(m/2 − Σ)
        let rho = if g == 1.0 { 1.0 } else { g * g * km / ks };
        let m_maj = (2.0 * e / (PI * g * g)).cbrt();
        let r = (2.0 * g / PI).powf(2.0 / 3.0) * k * e.powf(-1.0 / 3.0);
        let q = a.max(b) / m_maj;
        let sum = 3.0 * n / (4.0 * e_star * q.powi(3));
        let small = rho * sum / (1.0 + rho);
        let (ca, cb) = if a >= b {
            (small, sum - small)
        } else {
            (sum - small, small)
        };
        let delta = r * (3.0 * n / (4.0 * e_star)).powf(2.0 / 3.0) * sum.cbrt();
        Self {
            a,
            b,
            n,
            e_star,
            ca,
            cb,
            delta,
            p0: 3.0 * n / (2.0 * PI * a * b),
        }
    }

    /// Hertz pressure at (x, y), MPa.
    pub fn p(&self, x: f64, y: f64) -> f64 {
        let s = 1.0 - (x / self.a).powi(2) - (y / self.b).powi(2);
        if s > 0.0 {
            self.p0 * s.sqrt()
        } else {
            0.0
        }
    }

    /// Undeformed gap A x² + B y², mm.
    pub fn gap(&self, x: f64, y: f64) -> f64 {
        self.ca * x * x + self.cb * y * y
    }

    /// Force for approach δ by the Hertz law N ∝ δ^{3/2}.
    pub fn force_at(&self, delta: f64) -> f64 {
        self.n * (delta / self.delta).powf(1.5)
    }
}

/// Fitted Hertz parameters of a discrete solution: least squares of p_I² = c0 − c1 x_I² − c2 y_I²
/// over the contact elements (an exact representation of the Hertz pressure); p0 = √c0,
/// a = √(c0/c1), b = √(c0/c2). The centre is taken at the origin (symmetric grids).
pub fn fit_ellipse(s: &NormSolution) -> (f64, f64, f64) {
    // Normal equations for unknowns (c0, c1, c2) with basis (1, −x², −y²).
    let mut m = [[0.0f64; 3]; 3];
    let mut rhs = [0.0f64; 3];
    let g = &s.grid;
    for j in 0..g.my {
        for i in 0..g.mx {
            let p = s.p(i, j);
            if p <= 0.0 {
                continue;
            }
            let f = [1.0, -g.x(i).powi(2), -g.y(j).powi(2)];
            for r in 0..3 {
                for c in 0..3 {
                    m[r][c] += f[r] * f[c];
                }
                rhs[r] += f[r] * p * p;
            }
        }
    }
    let c = solve3(m, rhs);
    (c[0].sqrt(), (c[0] / c[1]).sqrt(), (c[0] / c[2]).sqrt())
}

fn solve3(mut m: [[f64; 3]; 3], mut b: [f64; 3]) -> [f64; 3] {
    for k in 0..3 {
        let piv = (k..3)
            .max_by(|&x, &y| m[x][k].abs().partial_cmp(&m[y][k].abs()).unwrap())
            .unwrap();
        m.swap(k, piv);
        b.swap(k, piv);
        for i in k + 1..3 {
            let f = m[i][k] / m[k][k];
            for c in k..3 {
                m[i][c] -= f * m[k][c];
            }
            b[i] -= f * b[k];
        }
    }
    let mut x = [0.0; 3];
    for k in (0..3).rev() {
        let mut s = b[k];
        for c in k + 1..3 {
            s -= m[k][c] * x[c];
        }
        x[k] = s / m[k][k];
    }
    x
}

/// Relative error.
pub fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}
