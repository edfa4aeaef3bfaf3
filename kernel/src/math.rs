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
