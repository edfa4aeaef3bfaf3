//! Influence coefficients of uniformly loaded rectangular elements on two identical elastic
//! half-spaces (methods.md §9.1–§9.2), shared by the NORM and TANG reference solvers.
//!
//! For an observation point at offset (x, y) from the centre of an element with half sizes
//! α = δx/2, β = δy/2, the corner operator is
//! 𝒮[F] = F(x+α, y+β) − F(x+α, y−β) − F(x−α, y+β) + F(x−α, y−β), and
//! * A_zz = ((1−ν)/(πG)) 𝒮[Φ₁ + Φ₂]
//! * A_xx = (1/(πG)) 𝒮[(1−ν)Φ₁ + Φ₂],  A_yy = (1/(πG)) 𝒮[Φ₁ + (1−ν)Φ₂],  A_xy = −(ν/(πG)) 𝒮[R]
//!
//! with Φ₁ = X asinh(Y/|X|), Φ₂ = Y asinh(X/|Y|) (0 on the axes) and R = √(X² + Y²); the asinh form
//! avoids the cancellation of the textbook log(Y + r) form. Units: mm, MPa → coefficients in mm/MPa
//! (displacement difference per unit pressure).

use std::f64::consts::PI;

/// Φ₁(X, Y) = X asinh(Y/|X|), 0 for X = 0.
#[inline]
pub fn phi1(x: f64, y: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x * (y / x.abs()).asinh()
    }
}

/// Φ₂(X, Y) = Y asinh(X/|Y|), 0 for Y = 0.
#[inline]
pub fn phi2(x: f64, y: f64) -> f64 {
    if y == 0.0 {
        0.0
    } else {
        y * (x / y.abs()).asinh()
    }
}

/// R(X, Y) = √(X² + Y²).
#[inline]
pub fn rad(x: f64, y: f64) -> f64 {
    x.hypot(y)
}

/// The corner operator 𝒮[F] at offset (x, y) for half sizes (α, β).
#[inline]
pub fn corners(f: impl Fn(f64, f64) -> f64, x: f64, y: f64, alpha: f64, beta: f64) -> f64 {
    f(x + alpha, y + beta) - f(x + alpha, y - beta) - f(x - alpha, y + beta)
        + f(x - alpha, y - beta)
}

/// Elastic constants and element size for which coefficients are evaluated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Elements {
    /// Combined shear modulus G, MPa.
    pub g: f64,
    /// Combined Poisson ratio ν.
    pub nu: f64,
    /// Element size along x, mm.
    pub dx: f64,
    /// Element size along y, mm.
    pub dy: f64,
}

impl Elements {
    /// Normal displacement difference at offset (x, y) per unit pressure on the element, mm/MPa.
    pub fn a_zz(&self, x: f64, y: f64) -> f64 {
        let (al, be) = (0.5 * self.dx, 0.5 * self.dy);
        (1.0 - self.nu) / (PI * self.g) * corners(|u, v| phi1(u, v) + phi2(u, v), x, y, al, be)
    }

    /// Tangential coefficient u_x per unit p_x.
    pub fn a_xx(&self, x: f64, y: f64) -> f64 {
        let (al, be) = (0.5 * self.dx, 0.5 * self.dy);
        let nu = self.nu;
        corners(|u, v| (1.0 - nu) * phi1(u, v) + phi2(u, v), x, y, al, be) / (PI * self.g)
    }

    /// Tangential coefficient u_y per unit p_y.
    pub fn a_yy(&self, x: f64, y: f64) -> f64 {
        let (al, be) = (0.5 * self.dx, 0.5 * self.dy);
        let nu = self.nu;
        corners(|u, v| phi1(u, v) + (1.0 - nu) * phi2(u, v), x, y, al, be) / (PI * self.g)
    }

    /// Cross coefficient u_x per unit p_y (= u_y per unit p_x).
    pub fn a_xy(&self, x: f64, y: f64) -> f64 {
        let (al, be) = (0.5 * self.dx, 0.5 * self.dy);
        -self.nu / (PI * self.g) * corners(rad, x, y, al, be)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 𝒮[Φ₁+Φ₂] = ∫∫ dξdη / r over the element: compare with a midpoint quadrature far away.
    #[test]
    fn zz_matches_point_load_far_field() {
        let e = Elements {
            g: 80_000.0,
            nu: 0.28,
            dx: 0.5,
            dy: 0.3,
        };
        let (x, y) = (7.3f64, -4.1f64);
        let far = (1.0 - e.nu) / (PI * e.g) * e.dx * e.dy / x.hypot(y);
        assert!((e.a_zz(x, y) / far - 1.0).abs() < 1e-3);
    }

    /// Self-influence of a square element: ∫∫ 1/r over a square of side 2α centred on the point is
    /// 8α asinh(1).
    #[test]
    fn zz_self_influence_square() {
        let e = Elements {
            g: 1.0,
            nu: 0.0,
            dx: 2.0,
            dy: 2.0,
        };
        let exact = 8.0 * 1f64.asinh() / PI;
        assert!((e.a_zz(0.0, 0.0) - exact).abs() < 1e-14);
    }

    /// Tangential coefficients by brute-force quadrature of Cerruti's kernel at an off-element point.
    #[test]
    fn tangential_match_quadrature() {
        let e = Elements {
            g: 82_000.0,
            nu: 0.28,
            dx: 0.4,
            dy: 0.2,
        };
        let (x, y) = (0.9f64, 0.5f64);
        let n = 400;
        let (mut sxx, mut syy, mut sxy) = (0.0, 0.0, 0.0);
        for i in 0..n {
            for j in 0..n {
                let xi = -0.2 + (i as f64 + 0.5) * 0.4 / n as f64;
                let eta = -0.1 + (j as f64 + 0.5) * 0.2 / n as f64;
                let (dx, dy) = (x - xi, y - eta);
                let r = dx.hypot(dy);
                let w = 0.4 * 0.2 / (n * n) as f64 / (PI * e.g);
                sxx += w * ((1.0 - e.nu) / r + e.nu * dx * dx / r.powi(3));
                syy += w * ((1.0 - e.nu) / r + e.nu * dy * dy / r.powi(3));
                sxy += w * e.nu * dx * dy / r.powi(3);
            }
        }
        assert!(
            (e.a_xx(x, y) / sxx - 1.0).abs() < 1e-5,
            "{} {}",
            e.a_xx(x, y),
            sxx
        );
        assert!((e.a_yy(x, y) / syy - 1.0).abs() < 1e-5);
        assert!(
            (e.a_xy(x, y) / sxy - 1.0).abs() < 1e-4,
            "{} {}",
            e.a_xy(x, y),
            sxy
        );
    }
}
