//! N independent values computed in step: the real-time step's FaStrip strips in groups
//! ([`crate::fastrip::strip_forces_lanes`], [`crate::fastrip::LANES`]).
//!
//! One strip's slip zone is a chain of dependent operations (each interval's direction needs the
//! previous one), so a superscalar out-of-order core waits on latencies while its other units idle;
//! several strips side by side fill them, and the compiler may pack lanes into SIMD registers.
//! Every lane runs the same operations in the same order as a single strip would, so a lane's
//! result is bit-identical whatever N is (a control flow that differs between lanes becomes a
//! per-lane [`Lanes::select`] of values computed in every lane).

// Index loops over the lanes, not iterators or `core::array::from_fn`: measured, they compile to the
// tightest code on the Cortex-M (one lane) and x86-64 (16; `from_fn` was not always inlined there).
#![allow(clippy::needless_range_loop)]

use crate::{math, Real};
use core::ops::{Add, AddAssign, Div, Mul, Neg, Sub};

/// N values, one per lane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Lanes<T, const N: usize>(pub [T; N]);

/// One boolean per lane.
pub(crate) type Mask<const N: usize> = [bool; N];

/// A pair of lane vectors (a 2-vector per lane: a direction, or a cosine and sine).
pub(crate) type Pair<T, const N: usize> = (Lanes<T, N>, Lanes<T, N>);

impl<T: Real, const N: usize> Lanes<T, N> {
    /// Every lane `x`.
    #[inline(always)]
    pub(crate) fn splat(x: T) -> Self {
        Self([x; N])
    }
    /// Every lane `T::from_f64(x)`.
    #[inline(always)]
    pub(crate) fn c(x: f64) -> Self {
        Self::splat(T::from_f64(x))
    }
    /// `f` of each lane.
    #[inline(always)]
    pub(crate) fn map(self, f: impl Fn(T) -> T) -> Self {
        let mut r = self.0;
        for (r, &x) in r.iter_mut().zip(&self.0) {
            *r = f(x);
        }
        Self(r)
    }
    /// `f` of each lane's pair.
    #[inline(always)]
    pub(crate) fn zip(self, o: Self, f: impl Fn(T, T) -> T) -> Self {
        let mut r = self.0;
        for i in 0..N {
            r[i] = f(self.0[i], o.0[i]);
        }
        Self(r)
    }
    /// `f` of each lane's pair, a mask.
    #[inline(always)]
    pub(crate) fn test(self, o: Self, f: impl Fn(T, T) -> bool) -> Mask<N> {
        let mut r = [false; N];
        for i in 0..N {
            r[i] = f(self.0[i], o.0[i]);
        }
        r
    }
    /// Per lane: `a` where `m`, else `b`.
    #[inline(always)]
    pub(crate) fn select(m: Mask<N>, a: Self, b: Self) -> Self {
        let mut r = b.0;
        for i in 0..N {
            if m[i] {
                r[i] = a.0[i];
            }
        }
        Self(r)
    }
    /// Per lane [`math::sqrt`].
    #[inline(always)]
    pub(crate) fn sqrt(self) -> Self {
        self.map(math::sqrt)
    }
    /// Per lane [`math::max`].
    #[inline(always)]
    pub(crate) fn max(self, o: Self) -> Self {
        self.zip(o, math::max)
    }
    /// Per lane [`math::clamp`].
    #[inline(always)]
    pub(crate) fn clamp(self, lo: Self, hi: Self) -> Self {
        let mut r = self.0;
        for i in 0..N {
            r[i] = math::clamp(self.0[i], lo.0[i], hi.0[i]);
        }
        Self(r)
    }
}

/// Per lane: the pair `a` where `m`, else `b`.
#[inline(always)]
pub(crate) fn select2<T: Real, const N: usize>(
    m: Mask<N>,
    a: Pair<T, N>,
    b: Pair<T, N>,
) -> Pair<T, N> {
    (Lanes::select(m, a.0, b.0), Lanes::select(m, a.1, b.1))
}

/// Lane-wise `a & b`.
#[inline(always)]
pub(crate) fn and<const N: usize>(a: Mask<N>, b: Mask<N>) -> Mask<N> {
    let mut r = a;
    for i in 0..N {
        r[i] = a[i] && b[i];
    }
    r
}

/// Lane-wise `!a`.
#[inline(always)]
pub(crate) fn not<const N: usize>(a: Mask<N>) -> Mask<N> {
    let mut r = a;
    for i in 0..N {
        r[i] = !a[i];
    }
    r
}

macro_rules! lane_op {
    ($tr:ident, $f:ident, $op:tt) => {
        impl<T: Real, const N: usize> $tr for Lanes<T, N> {
            type Output = Self;
            #[inline(always)]
            fn $f(self, o: Self) -> Self {
                let mut r = self.0;
                for i in 0..N {
                    r[i] = self.0[i] $op o.0[i];
                }
                Self(r)
            }
        }
    };
}
lane_op!(Add, add, +);
lane_op!(Sub, sub, -);
lane_op!(Mul, mul, *);
lane_op!(Div, div, /);

impl<T: Real, const N: usize> Neg for Lanes<T, N> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        self.map(|x| -x)
    }
}

impl<T: Real, const N: usize> AddAssign for Lanes<T, N> {
    #[inline(always)]
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lanes_are_elementwise_and_select_per_lane() {
        let a = Lanes::<f64, 3>([1.0, -2.0, 4.0]);
        let b = Lanes::<f64, 3>([2.0, 2.0, 0.5]);
        assert_eq!((a + b).0, [3.0, 0.0, 4.5]);
        assert_eq!((a - b).0, [-1.0, -4.0, 3.5]);
        assert_eq!((a * b).0, [2.0, -4.0, 2.0]);
        assert_eq!((a / b).0, [0.5, -1.0, 8.0]);
        assert_eq!((-a).0, [-1.0, 2.0, -4.0]);
        let m = a.test(b, |x, y| x < y);
        assert_eq!(m, [true, true, false]);
        assert_eq!(Lanes::select(m, a, b).0, [1.0, -2.0, 0.5]);
        assert_eq!(not(m), [false, false, true]);
        assert_eq!(and(m, [true, false, true]), [true, false, false]);
        assert_eq!(
            a.clamp(Lanes::splat(0.0), Lanes::splat(3.0)).0,
            [1.0, 0.0, 3.0]
        );
        assert_eq!(b.sqrt().0[0], math::sqrt(2f64));
    }
}
