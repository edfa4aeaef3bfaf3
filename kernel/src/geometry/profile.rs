//! Wheel and rail profile tables: plain data a firmware can hold in flash.
//!
//! A [`ProfileTable`] is a profile curve sampled **uniformly in arc length** (step `ds`, mm) in the
//! profile file's own coordinates after the file's own options (mirroring, re-ordering) are applied:
//!
//! * `y` lateral, positive towards the **field side** (CONTACT/SIMPACK canonical "right-side"
//!   profile); the points run with `y` non-decreasing (for the rail: from the track-centre side to
//!   the field side; for the wheel: from the flange to the field side);
//! * `z` vertical, positive **downwards** (file convention). For a wheel, `z` is the increase of the
//!   rolling radius over the nominal radius: `r(y) = R0 + z(y)`.
//!
//! Arc-length sampling keeps near-vertical parts (rail side faces, flange back) well conditioned,
//! which a table `z(y)` on a uniform `y` grid would not. Each node stores the position, the tangent
//! angle β (`tan β = dz/dy`), the signed curvature κ = dβ/ds (1/mm, = z''/(1+z'²)^{3/2}), and, for
//! convenience, the derived `dz/dy = tan β` and `d²z/dy² = κ/cos³β` (clamped where the curve is
//! vertical). Between nodes the curve is a cubic Hermite in (y, z) with the unit tangents of the
//! nodes (C¹, fourth-order accurate in `ds`); the curvature is interpolated linearly.
//!
//! Tables are produced on the host (`wrc_host_tests::profiles`: readers, smoothing spline with a
//! stated filter wavelength, resampling) and are validated here by [`ProfileTable::validate`].

use crate::{math, Error, Real};

/// Whether a table describes a rail or a wheel profile.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum ProfileKind {
    /// Rail profile (`z` = depth below the profile origin, mm).
    Rail,
    /// Wheel profile (`z` = radius increase over the nominal radius, mm).
    Wheel,
}

/// A profile curve sampled uniformly in arc length (capacity `N` nodes, `len` used).
///
/// All lengths in mm, angles in rad, curvature in 1/mm. See the module documentation for the
/// coordinate conventions.
#[derive(Clone, Debug)]
pub struct ProfileTable<T, const N: usize> {
    /// Rail or wheel.
    pub kind: ProfileKind,
    /// Number of valid nodes (4 ≤ `len` ≤ `N`).
    pub len: usize,
    /// Arc-length step between nodes, mm.
    pub ds: T,
    /// Filter wavelength of the smoothing applied on the host, mm (0 = interpolation only).
    /// Informational.
    pub filter_wavelength: T,
    /// Lateral coordinate y of node i, mm (non-decreasing in i).
    pub y: [T; N],
    /// Vertical coordinate z of node i (positive downwards), mm.
    pub z: [T; N],
    /// Tangent angle β of node i, rad, β ∈ [−π/2, π/2], `tan β = dz/dy`.
    pub angle: [T; N],
    /// Signed curvature κ = dβ/ds of node i, 1/mm.
    pub curvature: [T; N],
    /// First derivative dz/dy = tan β at node i (clamped to ±1e6 where vertical).
    pub dz_dy: [T; N],
    /// Second derivative d²z/dy² = κ / cos³β at node i, 1/mm (clamped to ±1e12 where vertical).
    pub d2z_dy2: [T; N],
}

/// A point on a profile curve with its local tangent angle and curvature (profile coordinates).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct CurvePoint<T> {
    /// Lateral coordinate, mm.
    pub y: T,
    /// Vertical coordinate (down positive), mm.
    pub z: T,
    /// Tangent angle β, rad (`tan β = dz/dy`).
    pub angle: T,
    /// Signed curvature dβ/ds, 1/mm.
    pub curvature: T,
}

impl<T: Real, const N: usize> ProfileTable<T, N> {
    /// An empty table (len 0) of the given kind; fill the arrays and `len`, `ds` before use.
    pub fn empty(kind: ProfileKind) -> Self {
        ProfileTable {
            kind,
            len: 0,
            ds: T::ZERO,
            filter_wavelength: T::ZERO,
            y: [T::ZERO; N],
            z: [T::ZERO; N],
            angle: [T::ZERO; N],
            curvature: [T::ZERO; N],
            dz_dy: [T::ZERO; N],
            d2z_dy2: [T::ZERO; N],
        }
    }

    /// Checks the table: 4 ≤ len ≤ N, ds > 0, all values finite, `y` non-decreasing
    /// (tolerance 1e-6 mm), |β| ≤ π/2 (+1e-6), and consecutive nodes ds apart (within 2 %).
    pub fn validate(&self) -> Result<(), Error> {
        if self.len < 4 {
            return Err(Error::BadProfile("fewer than 4 nodes"));
        }
        if self.len > N {
            return Err(Error::BadProfile("len exceeds the table capacity"));
        }
        if !math::is_finite(self.ds) || self.ds <= T::ZERO {
            return Err(Error::BadProfile("arc-length step ds must be positive"));
        }
        let tol = math::c::<T>(1e-6);
        let half_pi = T::PI * T::HALF + tol;
        for i in 0..self.len {
            let (y, z, a, k) = (self.y[i], self.z[i], self.angle[i], self.curvature[i]);
            if !(math::is_finite(y)
                && math::is_finite(z)
                && math::is_finite(a)
                && math::is_finite(k))
            {
                return Err(Error::BadProfile("non-finite node"));
            }
            if math::abs(a) > half_pi {
                return Err(Error::BadProfile("tangent angle outside [-pi/2, pi/2]"));
            }
            if i > 0 {
                if y < self.y[i - 1] - tol {
                    return Err(Error::BadProfile("lateral coordinate decreases"));
                }
                let chord = math::hypot(y - self.y[i - 1], z - self.z[i - 1]);
                if math::abs(chord - self.ds) > math::c::<T>(0.02) * self.ds {
                    return Err(Error::BadProfile("nodes are not ds apart"));
                }
            }
        }
        Ok(())
    }

    /// Largest valid fractional node index (`len − 1`).
    #[inline]
    pub fn t_max(&self) -> T {
        T::from_usize(self.len.saturating_sub(1))
    }

    /// Segment index and local coordinate u ∈ [0, 1] for a fractional node index `t`
    /// (clamped to the table).
    #[inline]
    fn segment(&self, t: T) -> (usize, T) {
        let tmax = self.t_max();
        let t = if math::is_finite(t) {
            math::clamp(t, T::ZERO, tmax)
        } else {
            T::ZERO
        };
        let last = self.len.saturating_sub(2);
        // t ∈ [0, len − 1] here: truncation is the floor
        let i = (T::to_f64(t) as usize).min(last);
        (i, t - T::from_usize(i))
    }

    /// The curve at fractional node index `t` ∈ [0, len−1] (clamped): cubic Hermite position,
    /// tangent angle from the Hermite derivative, linearly interpolated curvature.
    /// The table must be valid ([`Self::validate`]); out-of-range indices are clamped, never panic.
    pub fn point(&self, t: T) -> CurvePoint<T> {
        self.point_cached(t, &mut SegmentCache::new())
    }

    /// [`Self::point`] reusing the node tangents of the last segment evaluated with `cache`
    /// (saves four trigonometric calls per evaluation when marching along the curve).
    pub fn point_cached(&self, t: T, cache: &mut SegmentCache<T>) -> CurvePoint<T> {
        let e = self.hermite(t, cache);
        CurvePoint {
            y: e.y,
            z: e.z,
            angle: math::atan2(e.ts, e.tc),
            curvature: e.curvature,
        }
    }

    /// Segment index and local coordinate of `t` (as [`Self::segment`]), with the segment's node
    /// tangents loaded into `cache`. A node evaluated right after its left segment (a root
    /// bracket [k, k+1]) is that segment's end, u = 1: the same values (Hermite position, node
    /// tangent, node curvature) without refilling the cache. Needs `len ≥ 2`.
    #[inline]
    fn segment_cached(&self, t: T, cache: &mut SegmentCache<T>) -> (usize, T) {
        let (mut i, mut u) = self.segment(t);
        if u == T::ZERO && i > 0 && cache.valid && cache.i + 1 == i {
            i -= 1;
            u = T::ONE;
        }
        if !cache.valid || cache.i != i {
            let j = i + 1;
            if cache.valid && cache.i + 1 == i {
                // marching forward: the old end node is the new start node (same values)
                cache.c0 = cache.c1;
                cache.s0 = cache.s1;
                cache.c1 = math::cos(self.angle[j]);
                cache.s1 = math::sin(self.angle[j]);
            } else if cache.valid && cache.i == j {
                // marching backward: the old start node is the new end node
                cache.c1 = cache.c0;
                cache.s1 = cache.s0;
                cache.c0 = math::cos(self.angle[i]);
                cache.s0 = math::sin(self.angle[i]);
            } else {
                cache.c0 = math::cos(self.angle[i]);
                cache.s0 = math::sin(self.angle[i]);
                cache.c1 = math::cos(self.angle[j]);
                cache.s1 = math::sin(self.angle[j]);
            }
            cache.i = i;
            cache.valid = true;
        }
        (i, u)
    }

    /// Cubic Hermite position on segment `i` at `u` with the node tangents in `cache`.
    #[inline]
    fn position(&self, i: usize, u: T, cache: &SegmentCache<T>) -> (T, T) {
        let j = i + 1;
        let (c0, s0, c1, s1) = (cache.c0, cache.s0, cache.c1, cache.s1);
        let (y0, z0, y1, z1) = (self.y[i], self.z[i], self.y[j], self.z[j]);
        let h = self.ds;
        let u2 = u * u;
        let u3 = u2 * u;
        let two = T::TWO;
        let three = math::c::<T>(3.0);
        let h00 = two * u3 - three * u2 + T::ONE;
        let h10 = u3 - two * u2 + u;
        let h01 = three * u2 - two * u3;
        let h11 = u3 - u2;
        let y = h00 * y0 + h10 * h * c0 + h01 * y1 + h11 * h * c1;
        let z = h00 * z0 + h10 * h * s0 + h01 * z1 + h11 * h * s1;
        (y, z)
    }

    /// Position (y, z) at `t` only — the values of [`Self::hermite`] without the tangent (what
    /// root searches on a curve need).
    pub fn hermite_pos(&self, t: T, cache: &mut SegmentCache<T>) -> (T, T) {
        if self.len < 2 {
            return (T::ZERO, T::ZERO);
        }
        let (i, u) = self.segment_cached(t, cache);
        self.position(i, u, cache)
    }

    /// Derivative (dy/dt, dz/dt) of the cubic Hermite position on segment `i` at `u`.
    #[inline]
    fn derivative(&self, i: usize, u: T, cache: &SegmentCache<T>) -> (T, T) {
        let j = i + 1;
        let (c0, s0, c1, s1) = (cache.c0, cache.s0, cache.c1, cache.s1);
        let (y0, z0, y1, z1) = (self.y[i], self.z[i], self.y[j], self.z[j]);
        let h = self.ds;
        let u2 = u * u;
        let two = T::TWO;
        let three = math::c::<T>(3.0);
        let six = math::c::<T>(6.0);
        let d00 = six * u2 - six * u;
        let d10 = three * u2 - math::c::<T>(4.0) * u + T::ONE;
        let d01 = six * u - six * u2;
        let d11 = three * u2 - two * u;
        let dy = d00 * y0 + d10 * h * c0 + d01 * y1 + d11 * h * c1;
        let dz = d00 * z0 + d10 * h * s0 + d01 * z1 + d11 * h * s1;
        (dy, dz)
    }

    /// Position (y, z) and its derivative (dy/dt, dz/dt) per unit of the node index at `t` (mm):
    /// what a Newton root search on a curve needs.
    pub(crate) fn hermite_pos_d(&self, t: T, cache: &mut SegmentCache<T>) -> (T, T, T, T) {
        if self.len < 2 {
            return (T::ZERO, T::ZERO, T::ZERO, T::ZERO);
        }
        let (i, u) = self.segment_cached(t, cache);
        let (y, z) = self.position(i, u, cache);
        let (dy, dz) = self.derivative(i, u, cache);
        (y, z, dy, dz)
    }

    /// Position and unit tangent (cos β, sin β) at `t` without the angle (no trigonometry when
    /// the segment is cached).
    pub fn hermite(&self, t: T, cache: &mut SegmentCache<T>) -> HermitePoint<T> {
        self.hermite_d(t, cache).0
    }

    /// [`Self::hermite`] and the derivative (dy/dt, dz/dt) per unit of the node index, mm.
    #[inline]
    pub(crate) fn hermite_d(&self, t: T, cache: &mut SegmentCache<T>) -> (HermitePoint<T>, T, T) {
        if self.len < 2 {
            let p = HermitePoint {
                y: T::ZERO,
                z: T::ZERO,
                tc: T::ONE,
                ts: T::ZERO,
                curvature: T::ZERO,
            };
            return (p, T::ZERO, T::ZERO);
        }
        let (i, u) = self.segment_cached(t, cache);
        let j = i + 1;
        let (c0, s0) = (cache.c0, cache.s0);
        let (y, z) = self.position(i, u, cache);
        let (dy, dz) = self.derivative(i, u, cache);
        // √(dy² + dz²) instead of `hypot` (a third of the cost): dy, dz are Hermite derivatives
        // of a validated table (finite nodes ds apart, unit node tangents), so |dy|, |dz| ≤ 3·ds
        // and neither overflows nor underflows to a wrong zero for any ds between 1e-15 and 1e15
        // mm in f32 (and far beyond in f64); a zero norm falls back to the node tangent below.
        let norm = math::sqrt(dy * dy + dz * dz);
        let (tc, ts) = if norm > T::ZERO {
            (dy / norm, dz / norm)
        } else {
            (c0, s0)
        };
        let curvature = self.curvature[i] + u * (self.curvature[j] - self.curvature[i]);
        let p = HermitePoint {
            y,
            z,
            tc,
            ts,
            curvature,
        };
        (p, dy, dz)
    }

    /// Node `i` as a [`CurvePoint`] (clamped to the table).
    pub fn node(&self, i: usize) -> CurvePoint<T> {
        let i = i.min(self.len.saturating_sub(1)).min(N.saturating_sub(1));
        CurvePoint {
            y: self.y[i],
            z: self.z[i],
            angle: self.angle[i],
            curvature: self.curvature[i],
        }
    }
}

/// Node tangents of the last evaluated segment (see [`ProfileTable::point_cached`]).
#[derive(Clone, Copy, Debug, Default)]
pub struct SegmentCache<T> {
    i: usize,
    valid: bool,
    c0: T,
    s0: T,
    c1: T,
    s1: T,
}

impl<T: Real> SegmentCache<T> {
    /// An empty cache.
    pub fn new() -> Self {
        SegmentCache {
            i: 0,
            valid: false,
            c0: T::ONE,
            s0: T::ZERO,
            c1: T::ONE,
            s1: T::ZERO,
        }
    }
}

/// Position, unit tangent and curvature of a profile curve at a parameter (profile coordinates).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HermitePoint<T> {
    /// Lateral coordinate, mm.
    pub y: T,
    /// Vertical coordinate (down), mm.
    pub z: T,
    /// cos β of the unit tangent.
    pub tc: T,
    /// sin β of the unit tangent.
    pub ts: T,
    /// Curvature dβ/ds, 1/mm.
    pub curvature: T,
}

/// Finds u ∈ [0, 1] with `f(u) = 0` given `f(0)` and `f(1)` of opposite signs (or zero), by the
/// Illinois variant of regula falsi; at most `max_iter` evaluations. Returns the best u found.
pub(crate) fn illinois<T: Real, F: FnMut(T) -> T>(
    mut f: F,
    f0: T,
    f1: T,
    max_iter: usize,
    tol_f: T,
) -> T {
    let (mut a, mut b) = (T::ZERO, T::ONE);
    let (mut fa, mut fb) = (f0, f1);
    if fa == T::ZERO {
        return a;
    }
    if fb == T::ZERO {
        return b;
    }
    if (fa > T::ZERO) == (fb > T::ZERO) {
        return if math::abs(fa) < math::abs(fb) { a } else { b };
    }
    let mut side = 0i8;
    let mut x = a;
    for _ in 0..max_iter {
        let denom = fb - fa;
        x = if denom != T::ZERO {
            (a * fb - b * fa) / denom
        } else {
            (a + b) * T::HALF
        };
        if !(x > a && x < b) {
            x = (a + b) * T::HALF;
        }
        let fx = f(x);
        if math::abs(fx) <= tol_f || (b - a) <= math::c::<T>(1e-13) {
            return x;
        }
        if (fx > T::ZERO) == (fb > T::ZERO) {
            b = x;
            fb = fx;
            if side == -1 {
                fa *= T::HALF;
            }
            side = -1;
        } else {
            a = x;
            fa = fx;
            if side == 1 {
                fb *= T::HALF;
            }
            side = 1;
        }
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A circle arc of radius 20 mm sampled at ds = 0.5 mm, centre (0, 20) (z down: convex "rail").
    fn arc() -> ProfileTable<f64, 64> {
        let mut t = ProfileTable::<f64, 64>::empty(ProfileKind::Rail);
        let r = 20.0;
        let n = 41;
        let ds = 0.5;
        let s0 = -0.5 * ds * (n - 1) as f64;
        for i in 0..n {
            let s = s0 + ds * i as f64;
            let phi = s / r;
            t.y[i] = r * libm::sin(phi);
            t.z[i] = r - r * libm::cos(phi);
            t.angle[i] = phi;
            t.curvature[i] = 1.0 / r;
            t.dz_dy[i] = libm::tan(phi);
            t.d2z_dy2[i] = 1.0 / r / libm::pow(libm::cos(phi), 3.0);
        }
        t.len = n;
        t.ds = ds;
        t
    }

    #[test]
    fn hermite_reproduces_a_circle() {
        let t = arc();
        t.validate().unwrap();
        let mut worst: f64 = 0.0;
        for k in 0..400 {
            let tt = k as f64 * 0.1;
            let p = t.point(tt);
            let r = libm::hypot(p.y, p.z - 20.0);
            worst = worst.max((r - 20.0).abs());
            let phi = libm::atan2(p.y, 20.0 - p.z);
            assert!((p.angle - phi).abs() < 1e-5, "angle at t={tt}");
        }
        assert!(worst < 1e-6, "radius error {worst}");
    }

    #[test]
    fn validate_rejects_bad_tables() {
        let mut t = arc();
        t.y[5] = t.y[3];
        assert!(matches!(t.validate(), Err(Error::BadProfile(_))));
        let mut t = arc();
        t.len = 3;
        assert!(t.validate().is_err());
        let mut t = arc();
        t.z[7] = f64::NAN;
        assert!(t.validate().is_err());
        // out-of-range evaluation clamps instead of panicking
        let t = arc();
        let p = t.point(1e9);
        assert!((p.y - t.y[40]).abs() < 1e-12);
        let p = t.point(f64::NAN);
        assert!((p.y - t.y[0]).abs() < 1e-12);
    }
}
