//! The floating-point abstraction: one trait implemented for `f32` and `f64`.
//!
//! Maths functions are associated functions (`T::sqrt(x)`), never methods, so that unit tests
//! (which link `std`) cannot silently resolve `x.sqrt()` to `std`'s inherent method while the
//! target build uses `libm`. Call them through [`crate::math`].

use core::fmt::Debug;
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// A real number type the kernel computes in (`f32` or `f64`).
pub trait Real:
    Copy
    + Debug
    + Default
    + PartialEq
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + DivAssign
    + Send
    + Sync
    + 'static
{
    /// 0
    const ZERO: Self;
    /// 1
    const ONE: Self;
    /// 2
    const TWO: Self;
    /// 0.5
    const HALF: Self;
    /// π
    const PI: Self;
    /// Machine epsilon of the type.
    const EPSILON: Self;
    /// Largest finite value.
    const MAX: Self;
    /// Smallest positive normal value.
    const MIN_POSITIVE: Self;

    /// Size in bytes (4 for `f32`, 8 for `f64`).
    const BYTES: usize;

    /// Writes the little-endian bytes into `out[..Self::BYTES]` (shorter `out`: nothing written).
    fn write_le(self, out: &mut [u8]);
    /// Reads from the little-endian bytes `b[..Self::BYTES]` (shorter `b`: 0).
    fn read_le(b: &[u8]) -> Self;
    /// Conversion from `f64` (rounds for `f32`).
    fn from_f64(x: f64) -> Self;
    /// A constant given in both precisions (`x32` the f32 rounding of `x64`): `x64` for `f64`,
    /// `x32` for `f32`. Same value as [`Real::from_f64`] of `x64`, without the run-time
    /// conversion (on a Cortex-M4F f64 → f32 is a software call, ≈ 35 instructions).
    fn from_rounded(x64: f64, x32: f32) -> Self;
    /// Conversion to `f64` (exact).
    fn to_f64(self) -> f64;
    /// Conversion from a count.
    fn from_usize(n: usize) -> Self;
    /// `true` unless NaN or ±∞.
    fn is_finite(x: Self) -> bool;

    /// Square root.
    fn sqrt(x: Self) -> Self;
    /// Cube root.
    fn cbrt(x: Self) -> Self;
    /// Absolute value.
    fn abs(x: Self) -> Self;
    /// `x^y`.
    fn powf(x: Self, y: Self) -> Self;
    /// e^x.
    fn exp(x: Self) -> Self;
    /// Natural logarithm.
    fn ln(x: Self) -> Self;
    /// Sine.
    fn sin(x: Self) -> Self;
    /// Cosine.
    fn cos(x: Self) -> Self;
    /// Tangent.
    fn tan(x: Self) -> Self;
    /// Arc sine.
    fn asin(x: Self) -> Self;
    /// Arc cosine.
    fn acos(x: Self) -> Self;
    /// Arc tangent.
    fn atan(x: Self) -> Self;
    /// Four-quadrant arc tangent of `y/x`.
    fn atan2(y: Self, x: Self) -> Self;
    /// Inverse hyperbolic sine.
    fn asinh(x: Self) -> Self;
    /// `sqrt(x² + y²)` without undue overflow.
    fn hypot(x: Self, y: Self) -> Self;
    /// Largest integer ≤ x.
    fn floor(x: Self) -> Self;
    /// Fused or unfused `x*a + b` (whatever is fastest and deterministic on the target).
    fn mul_add(x: Self, a: Self, b: Self) -> Self;
}

mod sqrt_impl {
    //! Square-root backend. Both libm's and the hardware (`VSQRT`) square roots are correctly
    //! rounded IEEE-754 operations, so the `hw-sqrt` feature changes speed, never results.
    //! `hw-sqrt` (nightly `core_float_math`, i.e. `RUSTC_BOOTSTRAP=1`) routes through
    //! `core::{f32,f64}::math::sqrt`, which LLVM lowers to `VSQRT.F32` on Cortex-M4F/M7 and
    //! `VSQRT.F64` on a double-precision M7 (a soft-float library call elsewhere). It takes
    //! precedence over `fast-math`'s approximate f32 square root.

    /// f64 square root.
    #[inline(always)]
    pub fn sqrt(x: f64) -> f64 {
        #[cfg(feature = "hw-sqrt")]
        {
            core::f64::math::sqrt(x)
        }
        #[cfg(not(feature = "hw-sqrt"))]
        {
            libm::sqrt(x)
        }
    }

    /// f32 square root.
    #[inline(always)]
    pub fn sqrtf(x: f32) -> f32 {
        #[cfg(feature = "hw-sqrt")]
        {
            core::f32::math::sqrt(x)
        }
        #[cfg(all(not(feature = "hw-sqrt"), feature = "fast-math"))]
        {
            super::fast::sqrt(x)
        }
        #[cfg(all(not(feature = "hw-sqrt"), not(feature = "fast-math")))]
        {
            libm::sqrtf(x)
        }
    }
}

macro_rules! impl_real {
    ($t:ty, $sqrt:path, $cbrt:path, $abs:path, $pow:path, $exp:path, $ln:path, $sin:path,
     $cos:path, $tan:path, $asin:path, $acos:path, $atan:path, $atan2:path, $asinh:path,
     $hypot:path, $floor:path) => {
        impl Real for $t {
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const TWO: Self = 2.0;
            const HALF: Self = 0.5;
            const PI: Self = core::f64::consts::PI as $t;
            const EPSILON: Self = <$t>::EPSILON;
            const MAX: Self = <$t>::MAX;
            const MIN_POSITIVE: Self = <$t>::MIN_POSITIVE;
            const BYTES: usize = core::mem::size_of::<$t>();
            #[inline(always)]
            fn write_le(self, out: &mut [u8]) {
                if let Some(d) = out.get_mut(..Self::BYTES) {
                    d.copy_from_slice(&self.to_le_bytes());
                }
            }
            #[inline(always)]
            fn read_le(b: &[u8]) -> Self {
                let mut w = [0u8; core::mem::size_of::<$t>()];
                match b.get(..Self::BYTES) {
                    Some(s) => {
                        w.copy_from_slice(s);
                        <$t>::from_le_bytes(w)
                    }
                    None => 0.0,
                }
            }
            #[inline(always)]
            fn from_f64(x: f64) -> Self {
                x as $t
            }
            #[inline(always)]
            fn from_rounded(x64: f64, x32: f32) -> Self {
                if Self::BYTES == 4 {
                    x32 as $t
                } else {
                    x64 as $t
                }
            }
            #[inline(always)]
            fn to_f64(self) -> f64 {
                self as f64
            }
            #[inline(always)]
            fn from_usize(n: usize) -> Self {
                n as $t
            }
            #[inline(always)]
            fn is_finite(x: Self) -> bool {
                x.is_finite()
            }
            #[inline(always)]
            fn sqrt(x: Self) -> Self {
                $sqrt(x)
            }
            #[inline(always)]
            fn cbrt(x: Self) -> Self {
                $cbrt(x)
            }
            #[inline(always)]
            fn abs(x: Self) -> Self {
                $abs(x)
            }
            #[inline(always)]
            fn powf(x: Self, y: Self) -> Self {
                $pow(x, y)
            }
            #[inline(always)]
            fn exp(x: Self) -> Self {
                $exp(x)
            }
            #[inline(always)]
            fn ln(x: Self) -> Self {
                $ln(x)
            }
            #[inline(always)]
            fn sin(x: Self) -> Self {
                $sin(x)
            }
            #[inline(always)]
            fn cos(x: Self) -> Self {
                $cos(x)
            }
            #[inline(always)]
            fn tan(x: Self) -> Self {
                $tan(x)
            }
            #[inline(always)]
            fn asin(x: Self) -> Self {
                $asin(x)
            }
            #[inline(always)]
            fn acos(x: Self) -> Self {
                $acos(x)
            }
            #[inline(always)]
            fn atan(x: Self) -> Self {
                $atan(x)
            }
            #[inline(always)]
            fn atan2(y: Self, x: Self) -> Self {
                $atan2(y, x)
            }
            #[inline(always)]
            fn asinh(x: Self) -> Self {
                $asinh(x)
            }
            #[inline(always)]
            fn hypot(x: Self, y: Self) -> Self {
                $hypot(x, y)
            }
            #[inline(always)]
            fn floor(x: Self) -> Self {
                $floor(x)
            }
            #[inline(always)]
            fn mul_add(x: Self, a: Self, b: Self) -> Self {
                x * a + b
            }
        }
    };
}

impl_real!(
    f64,
    sqrt_impl::sqrt,
    libm::cbrt,
    libm::fabs,
    libm::pow,
    libm::exp,
    libm::log,
    libm::sin,
    libm::cos,
    libm::tan,
    libm::asin,
    libm::acos,
    libm::atan,
    libm::atan2,
    libm::asinh,
    libm::hypot,
    libm::floor
);

#[cfg(not(feature = "fast-math"))]
impl_real!(
    f32,
    sqrt_impl::sqrtf,
    libm::cbrtf,
    libm::fabsf,
    libm::powf,
    libm::expf,
    libm::logf,
    libm::sinf,
    libm::cosf,
    libm::tanf,
    libm::asinf,
    libm::acosf,
    libm::atanf,
    libm::atan2f,
    libm::asinhf,
    libm::hypotf,
    libm::floorf
);

#[cfg(feature = "fast-math")]
mod fast {
    //! micromath approximations for the f32 hot paths (sqrt, exp, ln, atan2, trigonometry);
    //! functions micromath lacks (cbrt, asinh, pow, acos, asin, hypot) stay on libm.
    //!
    //! Measured against libm (host-tests/tests/fast_math.rs, micromath 2.1): sqrt 6.1e-2
    //! relative, exp 2.4e-3 relative, ln 0.118 absolute, sin/cos 1.1e-3, atan/atan2 2.8e-3 rad.
    //! That is too coarse for contact pressures and angles (2 mrad tolerances): prefer the
    //! accurate `hw-sqrt` feature on Cortex-M; `fast-math` is for experiments only.
    use micromath::F32;
    #[cfg_attr(feature = "hw-sqrt", allow(dead_code))]
    #[inline(always)]
    pub fn sqrt(x: f32) -> f32 {
        F32(x).sqrt().0
    }
    #[inline(always)]
    pub fn exp(x: f32) -> f32 {
        F32(x).exp().0
    }
    #[inline(always)]
    pub fn ln(x: f32) -> f32 {
        F32(x).ln().0
    }
    #[inline(always)]
    pub fn sin(x: f32) -> f32 {
        F32(x).sin().0
    }
    #[inline(always)]
    pub fn cos(x: f32) -> f32 {
        F32(x).cos().0
    }
    #[inline(always)]
    pub fn tan(x: f32) -> f32 {
        F32(x).tan().0
    }
    #[inline(always)]
    pub fn atan(x: f32) -> f32 {
        F32(x).atan().0
    }
    #[inline(always)]
    pub fn atan2(y: f32, x: f32) -> f32 {
        F32(y).atan2(F32(x)).0
    }
}

#[cfg(feature = "fast-math")]
impl_real!(
    f32,
    sqrt_impl::sqrtf,
    libm::cbrtf,
    libm::fabsf,
    libm::powf,
    fast::exp,
    fast::ln,
    fast::sin,
    fast::cos,
    fast::tan,
    libm::asinf,
    libm::acosf,
    fast::atan,
    fast::atan2,
    libm::asinhf,
    libm::hypotf,
    libm::floorf
);
