//! The one door to maths functions: free functions generic over [`Real`].
//!
//! Kernel code writes `math::sqrt(x)`, never `x.sqrt()`. The backend is `libm` (bit-identical on
//! every target for the same input), or micromath for `f32` with the `fast-math` feature.

use crate::Real;

/// Square root.
#[inline(always)]
pub fn sqrt<T: Real>(x: T) -> T {
    T::sqrt(x)
}
/// Cube root.
#[inline(always)]
pub fn cbrt<T: Real>(x: T) -> T {
    T::cbrt(x)
}
/// Absolute value.
#[inline(always)]
pub fn abs<T: Real>(x: T) -> T {
    T::abs(x)
}
/// `x^y`.
#[inline(always)]
pub fn powf<T: Real>(x: T, y: T) -> T {
    T::powf(x, y)
}
/// e^x.
#[inline(always)]
pub fn exp<T: Real>(x: T) -> T {
    T::exp(x)
}
/// Natural logarithm.
#[inline(always)]
pub fn ln<T: Real>(x: T) -> T {
    T::ln(x)
}
/// Sine.
#[inline(always)]
pub fn sin<T: Real>(x: T) -> T {
    T::sin(x)
}
/// Cosine.
#[inline(always)]
pub fn cos<T: Real>(x: T) -> T {
    T::cos(x)
}
/// Tangent.
#[inline(always)]
pub fn tan<T: Real>(x: T) -> T {
    T::tan(x)
}
/// Arc sine.
#[inline(always)]
pub fn asin<T: Real>(x: T) -> T {
    T::asin(x)
}
/// Arc cosine.
#[inline(always)]
pub fn acos<T: Real>(x: T) -> T {
    T::acos(x)
}
/// Arc tangent.
#[inline(always)]
pub fn atan<T: Real>(x: T) -> T {
    T::atan(x)
}
/// Four-quadrant arc tangent of `y/x`.
#[inline(always)]
pub fn atan2<T: Real>(y: T, x: T) -> T {
    T::atan2(y, x)
}
/// Inverse hyperbolic sine.
#[inline(always)]
pub fn asinh<T: Real>(x: T) -> T {
    T::asinh(x)
}
/// `sqrt(x² + y²)`.
#[inline(always)]
pub fn hypot<T: Real>(x: T, y: T) -> T {
    T::hypot(x, y)
}
/// `sqrt(x² + y²)` evaluated as written (two products, a sum, one square root) when x² + y² is a
/// finite normal number, else [`hypot`] (overflow, underflow, NaN). Within about one ulp of
/// [`hypot`] but not always bit-identical to it; it costs one square root instead of libm's
/// scaled `hypot` (which for `f32` works in `f64`: soft-float on a Cortex-M4F). For the per-cell
/// loops of FASTSIM/FaStrip and the wear sink.
#[inline(always)]
pub fn hypot_fast<T: Real>(x: T, y: T) -> T {
    let s = x * x + y * y;
    if s >= T::MIN_POSITIVE && s <= T::MAX {
        T::sqrt(s)
    } else {
        T::hypot(x, y)
    }
}
/// Largest integer ≤ x.
#[inline(always)]
pub fn floor<T: Real>(x: T) -> T {
    T::floor(x)
}
/// Finite (not NaN, not ±∞).
#[inline(always)]
pub fn is_finite<T: Real>(x: T) -> bool {
    T::is_finite(x)
}
/// The smaller of two values (NaN-free inputs assumed; returns `b` if `a` is NaN).
#[inline(always)]
pub fn min<T: Real>(a: T, b: T) -> T {
    if a < b {
        a
    } else {
        b
    }
}
/// The larger of two values (returns `b` if `a` is NaN).
#[inline(always)]
pub fn max<T: Real>(a: T, b: T) -> T {
    if a > b {
        a
    } else {
        b
    }
}
/// `x` clamped to `[lo, hi]`.
#[inline(always)]
pub fn clamp<T: Real>(x: T, lo: T, hi: T) -> T {
    max(lo, min(x, hi))
}
/// Shorthand for `T::from_f64(x)`.
#[inline(always)]
pub fn c<T: Real>(x: f64) -> T {
    T::from_f64(x)
}
/// (sin x, cos x) for |x| ≤ π/2 by their Taylor series (to x²¹ and x²²: truncation below
/// 1.3e-18 at π/2, i.e. rounding-limited in `f64` and `f32`), with no library call; beyond π/2
/// (or NaN) the library's [`sin`] and [`cos`]. For angles known to be small, such as contact
/// angles, yaw and roll in the real-time step, where the library's range reduction is the cost
/// (on a Cortex-M4F libm's `f32` sine works in software `f64`: about 1.3 k instructions).
#[inline]
#[allow(clippy::neg_cmp_op_on_partial_ord)] // NaN takes the library path
pub fn sin_cos_small<T: Real>(x: T) -> (T, T) {
    if !(abs(x) <= c::<T>(core::f64::consts::FRAC_PI_2)) {
        return (sin(x), cos(x));
    }
    let x2 = x * x;
    // Horner from the highest term, k = 11 … 1: s ← 1 − x² s / ((2k)(2k+1)),
    // co ← 1 − x² co / ((2k−1)(2k)); literal constants, so that they fold at compile time
    const S: [f64; 11] = [
        1.0 / 506.0,
        1.0 / 420.0,
        1.0 / 342.0,
        1.0 / 272.0,
        1.0 / 210.0,
        1.0 / 156.0,
        1.0 / 110.0,
        1.0 / 72.0,
        1.0 / 42.0,
        1.0 / 20.0,
        1.0 / 6.0,
    ];
    const C: [f64; 11] = [
        1.0 / 462.0,
        1.0 / 380.0,
        1.0 / 306.0,
        1.0 / 240.0,
        1.0 / 182.0,
        1.0 / 132.0,
        1.0 / 90.0,
        1.0 / 56.0,
        1.0 / 30.0,
        1.0 / 12.0,
        1.0 / 2.0,
    ];
    let (mut s, mut co) = (T::ZERO, T::ZERO);
    s = T::ONE - x2 * s * c::<T>(S[0]);
    co = T::ONE - x2 * co * c::<T>(C[0]);
    s = T::ONE - x2 * s * c::<T>(S[1]);
    co = T::ONE - x2 * co * c::<T>(C[1]);
    s = T::ONE - x2 * s * c::<T>(S[2]);
    co = T::ONE - x2 * co * c::<T>(C[2]);
    s = T::ONE - x2 * s * c::<T>(S[3]);
    co = T::ONE - x2 * co * c::<T>(C[3]);
    s = T::ONE - x2 * s * c::<T>(S[4]);
    co = T::ONE - x2 * co * c::<T>(C[4]);
    s = T::ONE - x2 * s * c::<T>(S[5]);
    co = T::ONE - x2 * co * c::<T>(C[5]);
    s = T::ONE - x2 * s * c::<T>(S[6]);
    co = T::ONE - x2 * co * c::<T>(C[6]);
    s = T::ONE - x2 * s * c::<T>(S[7]);
    co = T::ONE - x2 * co * c::<T>(C[7]);
    s = T::ONE - x2 * s * c::<T>(S[8]);
    co = T::ONE - x2 * co * c::<T>(C[8]);
    s = T::ONE - x2 * s * c::<T>(S[9]);
    co = T::ONE - x2 * co * c::<T>(C[9]);
    s = T::ONE - x2 * s * c::<T>(S[10]);
    co = T::ONE - x2 * co * c::<T>(C[10]);
    (x * s, co)
}
