//! Hertz theory of elliptic contact (methods.md §1.2–§1.3).
//!
//! * [`elliptic_integrals`]: complete elliptic integrals K, E by the arithmetic–geometric mean in the
//!   cancellation-free form of §1.3 item 2 (bounded: at most [`AGM_MAX_ITER`] steps).
//! * [`shape_ratio`]: ρ(g) = g²(m/2 + Σ)/(m/2 − Σ), the curvature ratio min(A,B)/max(A,B) that produces a
//!   contact ellipse of semi-axis ratio g = min(a,b)/max(a,b).
//! * [`solve_axis_ratio`]: the inverse g(ρ), safeguarded secant on ln g inside a bisection bracket.
//! * [`coefficients`], [`coefficients_theta`], [`coefficients_ratio`]: Hertz m, n, r (cheap enough to
//!   call once per strip).
//! * [`from_load`], [`from_approach`]: the full solution (a, b, p0, δ) from curvatures A, B (1/mm) and the
//!   normal load N (N) or the approach δ (mm).
//! * [`curvatures_from_semi_axes`]: the inverse problem of §1.3 item 7, semi-axes a, b (mm) and N → A, B.
//!
//! Conventions: A, B are gap curvatures along x (rolling) and y (1/mm), gap h = A x² + B y² − δ;
//! a along x, b along y (not necessarily a ≥ b); cos θ = (B − A)/(A + B).

use crate::error::{check_positive, Error};
use crate::math::{self, c};
use crate::{Material, Real};

/// Maximum number of AGM steps. The AGM converges quadratically; for g = 1e-8 it needs 6 steps in f64.
pub const AGM_MAX_ITER: u32 = 32;
/// Maximum number of root-finding steps of [`solve_axis_ratio`] (secant steps with bisection fallback).
pub const SOLVE_MAX_ITER: u32 = 100;
/// Smallest semi-axis ratio g the solver searches (bracket [`G_MIN`], 1]).
pub const G_MIN: f64 = 1e-8;

/// Complete elliptic integrals for modulus e, e² = 1 − g².
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct EllipticIntegrals<T> {
    /// K(e), complete elliptic integral of the first kind.
    pub k: T,
    /// E(e), complete elliptic integral of the second kind.
    pub e: T,
    /// m/2 + Σ = (K − E)/K (cancellation-free).
    pub k_minus_e_over_k: T,
    /// m/2 − Σ = (E − g²K)/K (cancellation-free).
    pub e_minus_g2k_over_k: T,
    /// AGM steps used.
    pub iterations: u32,
}

/// K(e), E(e) for the complementary modulus g = √(1 − e²) ∈ (0, 1] by the AGM (§1.3 item 2).
///
/// Errors: `NonFinite("g")`, `NonPositive("g")`, `OutOfRange("g")` if g > 1.
pub fn elliptic_integrals<T: Real>(g: T) -> Result<EllipticIntegrals<T>, Error> {
    check_positive(g, "g")?;
    if g > T::ONE {
        return Err(Error::OutOfRange("g"));
    }
    // m = e² = 1 − g² = (1 − g)(1 + g), exact for g near 1.
    let m2 = (T::ONE - g) * (T::ONE + g);
    let mut a = T::ONE;
    let mut b = g;
    let mut sigma = T::ZERO;
    let mut pow2 = T::ONE; // 2^{k−1} for k = 1
    let mut iterations = 0;
    let tol = T::EPSILON * c(0.5);
    for _ in 0..AGM_MAX_ITER {
        let ck = (a - b) * T::HALF;
        if math::abs(ck) <= tol * a {
            break;
        }
        let an = (a + b) * T::HALF;
        let bn = math::sqrt(a * b);
        sigma += pow2 * ck * ck;
        pow2 *= T::TWO;
        a = an;
        b = bn;
        iterations += 1;
    }
    let k = T::PI / (T::TWO * a);
    let kme = m2 * T::HALF + sigma;
    let emg = m2 * T::HALF - sigma;
    Ok(EllipticIntegrals {
        k,
        e: k * (T::ONE - kme),
        k_minus_e_over_k: kme,
        e_minus_g2k_over_k: emg,
        iterations,
    })
}

/// Curvature ratio ρ = min(A,B)/max(A,B) for a contact ellipse of semi-axis ratio g = min(a,b)/max(a,b):
/// ρ(g) = g²(K − E)/(E − g²K), monotone increasing, ρ(1) = 1 (§1.3 item 1).
pub fn shape_ratio<T: Real>(g: T) -> Result<T, Error> {
    let ei = elliptic_integrals(g)?;
    Ok(rho_of(g, &ei))
}

fn rho_of<T: Real>(g: T, ei: &EllipticIntegrals<T>) -> T {
    if g >= T::ONE || ei.e_minus_g2k_over_k <= T::ZERO {
        return T::ONE;
    }
    g * g * ei.k_minus_e_over_k / ei.e_minus_g2k_over_k
}

/// Solution of ρ(g) = target.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct AxisRatio<T> {
    /// Semi-axis ratio g = min(a,b)/max(a,b).
    pub g: T,
    /// Elliptic integrals at g.
    pub integrals: EllipticIntegrals<T>,
    /// Root-finding steps used.
    pub iterations: u32,
    /// `true` if |Δ ln g| fell below the tolerance (1e-13 in f64, ~1e-6 in f32) within [`SOLVE_MAX_ITER`].
    pub converged: bool,
}

/// Semi-axis ratio g ∈ [1e-8, 1] with ρ(g) = `rho` (curvature ratio min/max, ∈ (0, 1]).
///
/// Safeguarded secant on t = ln g for f(t) = ln ρ(eᵗ) − ln ρ_target (nearly linear in t), started from
/// the Hamrock–Brewe guess g₀ = ρ^0.636/1.0339 and kept inside a bisection bracket. Reaches ~1e-13
/// relative accuracy in g in 5–8 steps in f64.
///
/// Errors: non-finite or non-positive ρ; `OutOfRange("rho")` if ρ > 1 or ρ < ρ(1e-8) ≈ 2e-15.
pub fn solve_axis_ratio<T: Real>(rho: T) -> Result<AxisRatio<T>, Error> {
    check_positive(rho, "rho")?;
    if rho > T::ONE {
        return Err(Error::OutOfRange("rho"));
    }
    if rho == T::ONE {
        return Ok(AxisRatio {
            g: T::ONE,
            integrals: elliptic_integrals(T::ONE)?,
            iterations: 0,
            converged: true,
        });
    }
    let ln_target = math::ln(rho);
    let f = |t: T| -> Result<(T, EllipticIntegrals<T>), Error> {
        let g = math::exp(t);
        let ei = elliptic_integrals(g)?;
        Ok((math::ln(rho_of(g, &ei)) - ln_target, ei))
    };
    let mut lo = math::ln(c::<T>(G_MIN));
    let mut hi = T::ZERO;
    let (f_lo, _) = f(lo)?;
    if f_lo > T::ZERO {
        return Err(Error::OutOfRange("rho"));
    }
    let tol = if T::EPSILON < c(1e-10) {
        c::<T>(1e-13)
    } else {
        c::<T>(2e-6)
    };
    // Hamrock–Brewe start; second point: slope ≈ 1.5 (ρ ≈ g^1.5 for small g).
    let g0 = math::powf(rho, c(0.636)) / c(1.0339);
    let mut t0 = math::clamp(math::ln(g0), lo, -tol);
    let (mut f0, mut ei0) = f(t0)?;
    let mut t1 = math::clamp(t0 - f0 / c(1.55), lo, -tol);
    let mut iterations = 1;
    let mut converged = false;
    for _ in 0..SOLVE_MAX_ITER {
        if f0 < T::ZERO {
            lo = math::max(lo, t0);
        } else {
            hi = math::min(hi, t0);
        }
        let (f1, ei1) = f(t1)?;
        iterations += 1;
        if f1 < T::ZERO {
            lo = math::max(lo, t1);
        } else {
            hi = math::min(hi, t1);
        }
        let dt = t1 - t0;
        if f1 == T::ZERO || math::abs(dt) < tol || hi - lo < tol {
            t0 = t1;
            ei0 = ei1;
            converged = true;
            break;
        }
        let df = f1 - f0;
        let mut t2 = if df != T::ZERO {
            t1 - f1 * dt / df
        } else {
            (lo + hi) * T::HALF
        };
        if !(t2 > lo && t2 < hi && math::is_finite(t2)) {
            t2 = (lo + hi) * T::HALF;
        }
        t0 = t1;
        f0 = f1;
        ei0 = ei1;
        t1 = t2;
    }
    Ok(AxisRatio {
        g: math::exp(t0),
        integrals: ei0,
        iterations,
        converged,
    })
}

/// Hertz coefficients of one curvature pair.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct HertzCoefficients<T> {
    /// m: a = m Q (semi-axis along x).
    pub m: T,
    /// n: b = n Q (semi-axis along y).
    pub n: T,
    /// r: δ = r (A+B) Q² = r (3N/(4E*))^(2/3) (A+B)^(1/3).
    pub r: T,
    /// Semi-axis ratio min(a,b)/max(a,b).
    pub g: T,
    /// K(e).
    pub k: T,
    /// E(e).
    pub e: T,
    /// Root-finding steps used.
    pub iterations: u32,
    /// Whether the axis-ratio solve converged.
    pub converged: bool,
}

/// m, n, r for a curvature ratio ρ = min/max ∈ (0, 1]; `a_is_major` says whether the long axis lies
/// along x (true when A ≤ B). Cheap: one root solve (≈ 6–8 AGM evaluations).
pub fn coefficients_ratio<T: Real>(
    rho: T,
    a_is_major: bool,
) -> Result<HertzCoefficients<T>, Error> {
    let sol = solve_axis_ratio(rho)?;
    Ok(coefficients_from_g(
        sol.g,
        &sol.integrals,
        a_is_major,
        sol.iterations,
        sol.converged,
    ))
}

fn coefficients_from_g<T: Real>(
    g: T,
    ei: &EllipticIntegrals<T>,
    a_is_major: bool,
    iterations: u32,
    converged: bool,
) -> HertzCoefficients<T> {
    let third = c::<T>(1.0 / 3.0);
    let two_over_pi = T::TWO / T::PI;
    let m_maj = math::cbrt(two_over_pi * ei.e / (g * g));
    let n_min = math::cbrt(two_over_pi * ei.e * g);
    let r = math::powf(two_over_pi * g, T::TWO * third) * ei.k / math::cbrt(ei.e);
    let (m, n) = if a_is_major {
        (m_maj, n_min)
    } else {
        (n_min, m_maj)
    };
    HertzCoefficients {
        m,
        n,
        r,
        g,
        k: ei.k,
        e: ei.e,
        iterations,
        converged,
    }
}

/// m, n, r from gap curvatures A (along x) and B (along y), both > 0 (1/mm).
pub fn coefficients<T: Real>(curv_a: T, curv_b: T) -> Result<HertzCoefficients<T>, Error> {
    check_positive(curv_a, "A")?;
    check_positive(curv_b, "B")?;
    if curv_a <= curv_b {
        coefficients_ratio(curv_a / curv_b, true)
    } else {
        coefficients_ratio(curv_b / curv_a, false)
    }
}

/// m, n, r for the Hertz angle θ ∈ (0, π) (rad), cos θ = (B − A)/(A + B); m(π − θ) = n(θ).
pub fn coefficients_theta<T: Real>(theta: T) -> Result<HertzCoefficients<T>, Error> {
    check_positive(theta, "theta")?;
    if theta >= T::PI {
        return Err(Error::OutOfRange("theta"));
    }
    let ct = math::cos(theta);
    coefficients(T::ONE - ct, T::ONE + ct)
}

/// Hertz solution of an elliptic contact.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct HertzSolution<T> {
    /// Semi-axis along x (rolling direction), mm.
    pub a: T,
    /// Semi-axis along y, mm.
    pub b: T,
    /// Maximum pressure p0 = 3N/(2πab), MPa.
    pub p0: T,
    /// Approach δ (maximum virtual overlap), mm.
    pub delta: T,
    /// Normal load N, N.
    pub load: T,
    /// Curvature A along x, 1/mm.
    pub curv_a: T,
    /// Curvature B along y, 1/mm.
    pub curv_b: T,
    /// Coefficients used.
    pub coef: HertzCoefficients<T>,
}

impl<T: Real> HertzSolution<T> {
    /// Every output finite and positive (extreme inputs can overflow or underflow in the
    /// intermediate products): `NonFinite("hertz result")` / `NonPositive("hertz result")` otherwise.
    fn checked(self) -> Result<Self, Error> {
        for v in [
            self.a,
            self.b,
            self.p0,
            self.delta,
            self.load,
            self.curv_a,
            self.curv_b,
        ] {
            check_positive(v, "hertz result")?;
        }
        Ok(self)
    }

    /// Hertz pressure p0 √(1 − x²/a² − y²/b²) at (x, y) (mm), 0 outside, MPa.
    pub fn pressure(&self, x: T, y: T) -> T {
        let s = T::ONE - (x / self.a) * (x / self.a) - (y / self.b) * (y / self.b);
        if s > T::ZERO {
            self.p0 * math::sqrt(s)
        } else {
            T::ZERO
        }
    }
    /// Normal stiffness dN/dδ = 3N/(2δ), N/mm.
    pub fn stiffness(&self) -> T {
        c::<T>(1.5) * self.load / self.delta
    }
}

/// Hertz solution from curvatures A, B (1/mm) and normal load N (N) (§1.3 items 4–5).
pub fn from_load<T: Real>(
    curv_a: T,
    curv_b: T,
    load: T,
    mat: &Material<T>,
) -> Result<HertzSolution<T>, Error> {
    check_positive(load, "N")?;
    check_positive(mat.e_star, "E*")?;
    let coef = coefficients(curv_a, curv_b)?;
    let sum = curv_a + curv_b;
    let q = math::cbrt(c::<T>(3.0) * load / (c::<T>(4.0) * mat.e_star * sum));
    let a = coef.m * q;
    let b = coef.n * q;
    HertzSolution {
        a,
        b,
        p0: c::<T>(3.0) * load / (T::TWO * T::PI * a * b),
        delta: coef.r * sum * q * q,
        load,
        curv_a,
        curv_b,
        coef,
    }
    .checked()
}

/// Hertz solution from curvatures A, B (1/mm) and the approach δ (mm): N = C_H δ^(3/2),
/// C_H = (4E*/3)(A+B)^(−1/2) r^(−3/2).
pub fn from_approach<T: Real>(
    curv_a: T,
    curv_b: T,
    delta: T,
    mat: &Material<T>,
) -> Result<HertzSolution<T>, Error> {
    check_positive(delta, "delta")?;
    check_positive(mat.e_star, "E*")?;
    let coef = coefficients(curv_a, curv_b)?;
    let sum = curv_a + curv_b;
    // δ = r (A+B) Q² → Q = √(δ/(r(A+B))); N = 4E*(A+B)Q³/3.
    let q = math::sqrt(delta / (coef.r * sum));
    let load = c::<T>(4.0 / 3.0) * mat.e_star * sum * q * q * q;
    let a = coef.m * q;
    let b = coef.n * q;
    HertzSolution {
        a,
        b,
        p0: c::<T>(3.0) * load / (T::TWO * T::PI * a * b),
        delta,
        load,
        curv_a,
        curv_b,
        coef,
    }
    .checked()
}

/// Curvatures A, B (1/mm) that give semi-axes a (along x), b (along y) (mm) under load N (N)
/// (§1.3 item 7, CONTACT IPOTCN = −3). Returns the full solution (δ, p0 included).
pub fn curvatures_from_semi_axes<T: Real>(
    a: T,
    b: T,
    load: T,
    mat: &Material<T>,
) -> Result<HertzSolution<T>, Error> {
    check_positive(a, "a")?;
    check_positive(b, "b")?;
    check_positive(load, "N")?;
    check_positive(mat.e_star, "E*")?;
    let a_is_major = a >= b;
    let g = if a_is_major { b / a } else { a / b };
    let ei = elliptic_integrals(g)?;
    let rho = rho_of(g, &ei);
    let coef = coefficients_from_g(g, &ei, a_is_major, 0, true);
    // Q from both semi-axes symmetrically: Q² = ab/(mn).
    let q = math::sqrt(a * b / (coef.m * coef.n));
    let sum = c::<T>(3.0) * load / (c::<T>(4.0) * mat.e_star * q * q * q);
    let (curv_a, curv_b) = if a_is_major {
        (sum * rho / (T::ONE + rho), sum / (T::ONE + rho))
    } else {
        (sum / (T::ONE + rho), sum * rho / (T::ONE + rho))
    };
    HertzSolution {
        a,
        b,
        p0: c::<T>(3.0) * load / (T::TWO * T::PI * a * b),
        delta: coef.r * sum * q * q,
        load,
        curv_a,
        curv_b,
        coef,
    }
    .checked()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn circle_is_unity() {
        let c = coefficients::<f64>(1e-3, 1e-3).unwrap();
        assert!(
            (c.m - 1.0).abs() < 1e-14 && (c.n - 1.0).abs() < 1e-14 && (c.r - 1.0).abs() < 1e-14
        );
    }

    #[test]
    fn solve_inverts_shape_ratio() {
        for &g in &[
            1e-7f64, 1e-5, 1e-3, 0.01, 0.1, 0.3, 0.5, 0.9, 0.999, 0.999_999,
        ] {
            let rho = shape_ratio(g).unwrap();
            let s = solve_axis_ratio(rho).unwrap();
            assert!(s.converged, "g={g}");
            assert!(((s.g - g) / g).abs() < 1e-11, "g={g} got {}", s.g);
        }
    }

    #[test]
    fn f32_solves() {
        for &g in &[1e-3f32, 0.01, 0.5, 0.99] {
            let rho = shape_ratio(g).unwrap();
            let s = solve_axis_ratio(rho).unwrap();
            assert!(s.converged);
            assert!(((s.g - g) / g).abs() < 1e-4, "g={g} got {}", s.g);
        }
    }

    #[test]
    fn rejects_bad() {
        assert_eq!(coefficients(f64::NAN, 1.0), Err(Error::NonFinite("A")));
        assert_eq!(coefficients(1.0, -1.0), Err(Error::NonPositive("B")));
        assert_eq!(
            solve_axis_ratio(1.5f64).map(|s| s.g),
            Err(Error::OutOfRange("rho"))
        );
        assert_eq!(
            solve_axis_ratio(1e-30f64).map(|s| s.g),
            Err(Error::OutOfRange("rho"))
        );
    }
}
