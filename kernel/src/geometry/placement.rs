//! Wheelset placement in the track (methods.md §7.1) and the rigid gap on a uniform lateral grid
//! (§7.2 steps 1–3, 5).
//!
//! # Frames
//! * **Track frame T** (§7.1): x forward, y to the **left**, z up; origin on the track centre line
//!   in the plane touching both rail tops.
//! * **Side frame S** of the analysed wheel: the track frame for the left wheel, its mirror image
//!   (y_S = −y_T) for the right wheel. In S the analysed rail lies at positive y_S with its field
//!   side outwards, so both sides are computed with the same "right-side" profile files (CONTACT
//!   canonical form; a left pair is the mirrored right pair). Under the mirror, yaw and roll change
//!   sign: ψ_S = s ψ_T, φ_S = s φ_T, Δy_S = s Δy_T with s = +1 (left), −1 (right).
//!
//! # Placement
//! * Rail: the profile (file coordinates, y towards the field side, z down) is rotated by the
//!   extra inclination `cant` towards the track centre, then translated so that its highest point
//!   lies at z = 0 and its gauge face, at `gauge_depth` below that top, lies at y_S = gauge/2.
//! * Wheel: the profile point (y_w, z_w) lies at the axial coordinate
//!   u = back_to_back/2 + (y_w − flange_back_pos) from the wheelset centre and at the radius
//!   r = r0 + z_w. The wheelset is rolled (about x) and yawed (about z), R = R_z(ψ)·R_x(φ), and
//!   translated to (0, Δy, z_c).
//! * **Yaw in the gap**: for each lateral position the wheel's lowest point over the longitudinal
//!   coordinate x is used (the contact locus of a yawed body of revolution). For the profile point
//!   at axial u with slope r'(u) the lowest point sits at the angle θ about the axle with
//!   cos ψ sin θ − sin φ sin ψ cos θ = −r'(u) cos φ sin ψ (closed form), at the longitudinal
//!   position x reported in the gap grid. The surface normal there lies in the y–z plane, so the
//!   slope of this lowest-point curve is the wheel's local contact slope.
//! * The wheel height z_c is chosen so that the minimum of the vertical gap is zero ("touching",
//!   single-wheel mode with the roll given). [`equilibrium_roll`] finds the roll at which both
//!   wheels of the wheelset touch at the same height (§7.2 step 5, two-wheel mode).
//!
//! # Angle sign (§7.2 step 4)
//! Angles ("tilt") are those of the surface normal pointing into the wheel, positive when it tilts
//! towards the track centre (flange side), measured in the track frame (they include the roll).

use crate::profile::{illinois, CurvePoint, HermitePoint, ProfileKind, ProfileTable, SegmentCache};
use crate::{math, Error, Real};

/// Track and wheelset constants (mm, rad).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct TrackSetup<T> {
    /// Track gauge between the gauge faces, measured `gauge_depth` below the rail tops, mm.
    pub gauge: T,
    /// Depth below the rail top at which the gauge is measured, mm (EN 13848 / CONTACT: 14).
    pub gauge_depth: T,
    /// Back-to-back (flange-back) distance of the wheelset, mm.
    pub back_to_back: T,
    /// Lateral coordinate of the flange back in the wheel profile file (after the file's own
    /// options), mm (S1002 files: −70; the tape circle is at y_w = 0).
    pub flange_back_pos: T,
    /// Nominal rolling radius (radius at z_w = 0), mm.
    pub r0: T,
    /// Extra rail inclination towards the track centre, rad (0: the rail profile's own
    /// inclination is used as given; `MBench_UIC60_v3.prr` is already canted 1:40).
    pub cant: T,
}

impl<T: Real> TrackSetup<T> {
    /// Gauge 1435 mm at 14 mm, back-to-back 1360 mm, flange back at −70 mm, R0 = 460 mm, no
    /// extra cant: the Manchester benchmark / CONTACT `mbench_a22` set-up.
    pub fn standard() -> Self {
        TrackSetup {
            gauge: math::c(1435.0),
            gauge_depth: math::c(14.0),
            back_to_back: math::c(1360.0),
            flange_back_pos: math::c(-70.0),
            r0: math::c(460.0),
            cant: T::ZERO,
        }
    }

    fn check(&self) -> Result<(), Error> {
        crate::error::check_positive(self.gauge, "gauge")?;
        crate::error::check_positive(self.gauge_depth, "gauge_depth")?;
        crate::error::check_positive(self.back_to_back, "back_to_back")?;
        crate::error::check_positive(self.r0, "r0")?;
        crate::error::check_finite(self.flange_back_pos, "flange_back_pos")?;
        crate::error::check_finite(self.cant, "cant")?;
        if math::abs(self.cant) > math::c(0.2) {
            return Err(Error::OutOfRange("cant"));
        }
        Ok(())
    }
}

/// Which wheel of the wheelset is analysed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Side {
    /// Left wheel (+y_T side).
    Left,
    /// Right wheel (−y_T side).
    Right,
}

impl Side {
    /// +1 for the left wheel, −1 for the right wheel: y_T = sign · y_S.
    #[inline]
    pub fn sign<T: Real>(self) -> T {
        match self {
            Side::Left => T::ONE,
            Side::Right => -T::ONE,
        }
    }
}

/// Wheelset pose relative to the track, in the track frame T.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct WheelsetPose<T> {
    /// Lateral shift of the wheelset centre along +y_T (to the **left**), mm.
    pub dy: T,
    /// Yaw angle about +z_T (up), rad.
    pub yaw: T,
    /// Roll angle about +x_T, rad (positive raises the left wheel).
    pub roll: T,
}

impl<T: Real> WheelsetPose<T> {
    /// From CONTACT module-1 inputs (y_ws to the right, yaw about z down, roll about x):
    /// dy = −y_ws, yaw = −yaw_C, roll = roll_C (methods.md §0.2, §10.9).
    pub fn from_contact(y_ws: T, yaw_c: T, roll_c: T) -> Self {
        WheelsetPose {
            dy: -y_ws,
            yaw: -yaw_c,
            roll: roll_c,
        }
    }

    /// From a shift and yaw taken **towards the analysed wheel**, the convention of An et al.
    /// (2019) and of the `wrc` command line (`--dy`, `--yaw`): a positive `shift_mm` moves the
    /// wheelset towards `side`, bringing that wheel's flange towards its rail's gauge face, and a
    /// positive `yaw_rad` is the yaw that goes with it in the seed's cases (yaw = 1.2·dy mrad).
    /// For the right wheel this is CONTACT's (y_ws, yaw_C), for the left wheel its mirror image.
    /// `roll_rad` is in the track frame (positive raises the left wheel) for either side.
    pub fn towards_wheel(side: Side, shift_mm: T, yaw_rad: T, roll_rad: T) -> Self {
        match side {
            Side::Right => Self::from_contact(shift_mm, yaw_rad, roll_rad),
            Side::Left => Self::from_contact(-shift_mm, -yaw_rad, roll_rad),
        }
    }

    /// The mirror image (x–z plane): left wheel at `self` ≡ right wheel at `self.mirrored()`.
    pub fn mirrored(&self) -> Self {
        WheelsetPose {
            dy: -self.dy,
            yaw: -self.yaw,
            roll: -self.roll,
        }
    }

    fn check(&self) -> Result<(), Error> {
        crate::error::check_finite(self.dy, "dy")?;
        crate::error::check_finite(self.yaw, "yaw")?;
        crate::error::check_finite(self.roll, "roll")?;
        if math::abs(self.yaw) > math::c(0.2) {
            return Err(Error::OutOfRange("yaw"));
        }
        if math::abs(self.roll) > math::c(0.2) {
            return Err(Error::OutOfRange("roll"));
        }
        Ok(())
    }
}

/// A rail point in the side frame S.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct RailPoint<T> {
    /// Lateral position y_S, mm.
    pub y: T,
    /// Height z_S, mm (up).
    pub z: T,
    /// Surface tilt (contact-angle sign, track frame), rad.
    pub angle: T,
    /// Cross-section curvature, convex positive, 1/mm.
    pub curvature: T,
    /// Curve parameter (fractional node index).
    pub t: T,
    /// The point in the rail profile file's coordinates.
    pub profile: CurvePoint<T>,
}

/// The analysed rail placed in the side frame S.
#[derive(Clone, Copy, Debug)]
pub struct PlacedRail<'a, T, const N: usize> {
    /// The profile table.
    pub table: &'a ProfileTable<T, N>,
    cos_a: T,
    sin_a: T,
    ty: T,
    tz: T,
    cant: T,
    /// Curve parameter of the rail top (highest point in S).
    pub t_top: T,
}

impl<'a, T: Real, const N: usize> PlacedRail<'a, T, N> {
    fn raw(table: &'a ProfileTable<T, N>, cant: T) -> Self {
        PlacedRail {
            table,
            cos_a: math::cos(cant),
            sin_a: math::sin(cant),
            ty: T::ZERO,
            tz: T::ZERO,
            cant,
            t_top: T::ZERO,
        }
    }

    /// An unplaced rail (no rotation or translation) for storage that is placed later.
    const fn unplaced(table: &'a ProfileTable<T, N>) -> Self {
        PlacedRail {
            table,
            cos_a: T::ONE,
            sin_a: T::ZERO,
            ty: T::ZERO,
            tz: T::ZERO,
            cant: T::ZERO,
            t_top: T::ZERO,
        }
    }

    /// The rail point at curve parameter `t`.
    pub fn at(&self, t: T) -> RailPoint<T> {
        self.at_cached(t, &mut SegmentCache::new())
    }

    /// Lateral position y_S at parameter `t` (root finding; cached).
    pub fn y_cached(&self, t: T, cache: &mut SegmentCache<T>) -> T {
        let (y, z) = self.table.hermite_pos(t, cache);
        y * self.cos_a + z * self.sin_a + self.ty
    }

    /// Lateral origin of the local coordinates, mm: y_S = y_local + `y_origin()`. The geometry
    /// works in local lateral coordinates (the rail profile's origin placed in S), so f32 does
    /// not carry the rounding of the ≈ 700 mm track coordinates into gaps and separations.
    #[inline]
    pub fn y_origin(&self) -> T {
        self.ty
    }

    /// [`Self::at_cached`] in local lateral coordinates (`y` is y_S − [`Self::y_origin`]).
    pub(crate) fn at_local_cached(&self, t: T, cache: &mut SegmentCache<T>) -> RailPoint<T> {
        let p = self.table.point_cached(t, cache);
        let (qy, qz) = (p.y, -p.z);
        RailPoint {
            y: qy * self.cos_a - qz * self.sin_a,
            z: qy * self.sin_a + qz * self.cos_a + self.tz,
            angle: self.cant - p.angle,
            curvature: p.curvature,
            t,
            profile: p,
        }
    }

    /// [`Self::at`] in local lateral coordinates.
    pub(crate) fn at_local(&self, t: T) -> RailPoint<T> {
        self.at_local_cached(t, &mut SegmentCache::new())
    }

    /// [`Self::at`] with a segment cache.
    pub fn at_cached(&self, t: T, cache: &mut SegmentCache<T>) -> RailPoint<T> {
        let mut p = self.at_local_cached(t, cache);
        p.y += self.ty;
        p
    }

    /// Position (y_S, z_S) at parameter `t` (cached), without the angle of [`Self::at_cached`].
    #[inline]
    pub fn pos_cached(&self, t: T, cache: &mut SegmentCache<T>) -> (T, T) {
        let (y, z) = self.pos_local_cached(t, cache);
        (y + self.ty, z)
    }

    /// [`Self::pos_cached`] in local lateral coordinates.
    #[inline]
    pub(crate) fn pos_local_cached(&self, t: T, cache: &mut SegmentCache<T>) -> (T, T) {
        let (y, z) = self.table.hermite_pos(t, cache);
        let (qy, qz) = (y, -z);
        (
            qy * self.cos_a - qz * self.sin_a,
            qy * self.sin_a + qz * self.cos_a + self.tz,
        )
    }

    /// A point given in the rail profile file's coordinates (y, z) in the side frame S:
    /// (local lateral position, z_S), mm — the values [`Self::at_cached`] gives for the curve
    /// point with these profile coordinates (with y local).
    #[inline]
    pub(crate) fn local_of_profile(&self, y: T, z: T) -> (T, T) {
        let (qy, qz) = (y, -z);
        (
            qy * self.cos_a - qz * self.sin_a,
            qy * self.sin_a + qz * self.cos_a + self.tz,
        )
    }

    /// Local lateral position at parameter `t` (root finding; cached).
    #[inline]
    pub(crate) fn y_local_cached(&self, t: T, cache: &mut SegmentCache<T>) -> T {
        let (y, z) = self.table.hermite_pos(t, cache);
        y * self.cos_a + z * self.sin_a
    }

    /// Local lateral position of node `i` (exact node value).
    #[inline]
    fn node_y_local(&self, i: usize) -> T {
        let i = i.min(N - 1);
        self.table.y[i] * self.cos_a + self.table.z[i] * self.sin_a
    }

    /// Height z_S of node `i` (exact node value, no interpolation).
    #[inline]
    fn node_z(&self, i: usize) -> T {
        let i = i.min(N - 1);
        self.table.y[i] * self.sin_a - self.table.z[i] * self.cos_a + self.tz
    }

    /// Places the rail: top at z = 0, gauge face at y_S = gauge/2 (see module docs).
    pub fn place(table: &'a ProfileTable<T, N>, setup: &TrackSetup<T>) -> Result<Self, Error> {
        table.validate()?;
        if table.kind != ProfileKind::Rail {
            return Err(Error::BadProfile("rail table expected"));
        }
        let mut r = Self::raw(table, setup.cant);
        let n = table.len;
        // highest node
        let mut k_top = 0;
        let mut z_top = r.node_z(0);
        for i in 1..n {
            let z = r.node_z(i);
            if z > z_top {
                z_top = z;
                k_top = i;
            }
        }
        // refine by golden section on [k-1, k+1]
        let lo = T::from_usize(k_top.saturating_sub(1));
        let hi = T::from_usize((k_top + 1).min(n - 1));
        let t_top = golden_max(|t| r.at(t).z, lo, hi, 60);
        z_top = r.at(t_top).z;
        r.t_top = t_top;
        // gauge point: walk from the top towards the track-centre side (decreasing index)
        let target = z_top - setup.gauge_depth;
        let mut k = k_top;
        let mut found = false;
        for _ in 0..n {
            if k == 0 {
                break;
            }
            if r.node_z(k - 1) <= target {
                found = true;
                k -= 1;
                break;
            }
            k -= 1;
        }
        if !found {
            return Err(Error::BadProfile(
                "rail profile does not reach the gauge depth on the gauge side",
            ));
        }
        let tk = T::from_usize(k);
        let f0 = r.at(tk).z - target;
        let f1 = r.at(tk + T::ONE).z - target;
        let u = illinois(|u| r.at(tk + u).z - target, f0, f1, 60, math::c(1e-12));
        let y_gauge = r.at(tk + u).y;
        r.ty = setup.gauge * T::HALF - y_gauge;
        r.tz = -z_top;
        Ok(r)
    }

    /// Translation (y, z) applied after the cant rotation, mm.
    pub fn translation(&self) -> (T, T) {
        (self.ty, self.tz)
    }
}

/// A point of the wheel's lowest-point curve in the side frame S.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct WheelPoint<T> {
    /// Lateral position y_S, mm.
    pub y: T,
    /// Height z_S, mm.
    pub z: T,
    /// Longitudinal position x of the lowest point (nonzero with yaw), mm.
    pub x: T,
    /// Surface tilt (contact-angle sign, track frame), rad.
    pub angle: T,
    /// Cross-section curvature, convex (towards the rail) positive, 1/mm.
    pub curvature: T,
    /// Rolling radius: distance of the point from the axle, mm.
    pub radius: T,
    /// Curve parameter (fractional node index).
    pub t: T,
    /// The point in the wheel profile file's coordinates.
    pub profile: CurvePoint<T>,
}

/// The analysed wheel placed in the side frame S.
#[derive(Clone, Copy, Debug)]
pub struct PlacedWheel<'a, T, const N: usize> {
    /// The profile table.
    pub table: &'a ProfileTable<T, N>,
    u_off: T,
    r0: T,
    cphi: T,
    sphi: T,
    cpsi: T,
    spsi: T,
    theta_norm: T,
    /// sin θ₀, cos θ₀ of θ₀ = atan2(sin φ sin ψ, cos ψ) (precomputed per pose).
    st0: T,
    ct0: T,
    /// Lateral position of the wheelset centre in S, mm.
    pub cy: T,
    /// Height of the wheelset centre (axle) in S, mm. Set by the placement (touching); lower
    /// the wheel with [`Self::lowered`], which keeps the heights resolved to the rounding of
    /// the small local quantities (writing the field also moves the wheel, resolved to the
    /// rounding of the ≈ r0 magnitude of `cz`: ≈ 3e-5 mm in f32).
    pub cz: T,
    /// 1 − cos φ, computed without cancellation.
    omc_phi: T,
    /// Height offset of the wheel's positions: z_S = (z1 + r0) + `cz_off` + (`cz` − `cz_ref`)
    /// with z1 + r0 evaluated from small quantities (no ≈ r0 magnitudes are added and
    /// subtracted), mm.
    cz_off: T,
    /// The value of `cz` when `cz_off` was last set, mm.
    cz_ref: T,
    /// Lateral origin of the local coordinates (the rail's, [`PlacedRail::y_origin`]), mm.
    y_org: T,
    /// cos φ cos ψ and sin φ cos ψ.
    cc: T,
    sc: T,
    /// Lateral offset of the local positions: y_S − y_org = x1 sψ + e_y cφcψ + r cθ sφcψ +
    /// `cy_off` + (`cy` − `cy_ref`), with `cy_off` = (u_off − y_org) − u_off (1 − cφcψ) + cy
    /// computed without the ≈ 700 mm magnitudes, mm.
    cy_off: T,
    /// The value of `cy` when `cy_off` was set, mm.
    cy_ref: T,
}

impl<'a, T: Real, const N: usize> PlacedWheel<'a, T, N> {
    fn new(
        table: &'a ProfileTable<T, N>,
        setup: &TrackSetup<T>,
        pose: &WheelsetPose<T>,
        side: Side,
    ) -> Result<Self, Error> {
        table.validate()?;
        if table.kind != ProfileKind::Wheel {
            return Err(Error::BadProfile("wheel table expected"));
        }
        Ok(Self::posed(table, setup, pose, side, T::ZERO))
    }

    /// The wheel of a validated table at a checked pose (no validation).
    fn posed(
        table: &'a ProfileTable<T, N>,
        setup: &TrackSetup<T>,
        pose: &WheelsetPose<T>,
        side: Side,
        y_org: T,
    ) -> Self {
        let s: T = side.sign();
        let phi = s * pose.roll;
        let psi = s * pose.yaw;
        let (cpsi, spsi) = (math::cos(psi), math::sin(psi));
        let (cphi, sphi) = (math::cos(phi), math::sin(phi));
        let a = cpsi;
        let b = sphi * spsi;
        let norm = math::hypot(a, b);
        let u_off = setup.back_to_back * T::HALF - setup.flange_back_pos;
        let omc_phi = sphi * sphi / (T::ONE + cphi);
        let omc_psi = spsi * spsi / (T::ONE + cpsi);
        let cy = s * pose.dy;
        // u cφcψ − y_org = e_y cφcψ + (u_off − y_org) − u_off (1 − cφcψ): the difference of the
        // two ≈ 700 mm numbers is exact (Sterbenz) or nearly so
        let cy_off = (u_off - y_org) - u_off * (omc_phi + cphi * omc_psi) + cy;
        PlacedWheel {
            table,
            u_off,
            r0: setup.r0,
            cphi,
            sphi,
            cpsi,
            spsi,
            theta_norm: norm,
            // |ψ| ≤ 0.2 rad (checked), so a = cos ψ > 0.98 and norm > 0
            st0: b / norm,
            ct0: a / norm,
            cy,
            cz: T::ZERO,
            omc_phi,
            cz_off: T::ZERO,
            cz_ref: T::ZERO,
            y_org,
            cc: cphi * cpsi,
            sc: sphi * cpsi,
            cy_off,
            cy_ref: cy,
        }
    }

    /// An unplaced wheel (identity pose, right side) for storage that is placed later.
    const fn unplaced(table: &'a ProfileTable<T, N>, setup: &TrackSetup<T>) -> Self {
        PlacedWheel {
            table,
            u_off: T::ZERO,
            r0: setup.r0,
            cphi: T::ONE,
            sphi: T::ZERO,
            cpsi: T::ONE,
            spsi: T::ZERO,
            theta_norm: T::ONE,
            st0: T::ZERO,
            ct0: T::ONE,
            cy: T::ZERO,
            cz: T::ZERO,
            omc_phi: T::ZERO,
            cz_off: T::ZERO,
            cz_ref: T::ZERO,
            y_org: T::ZERO,
            cc: T::ONE,
            sc: T::ZERO,
            cy_off: T::ZERO,
            cy_ref: T::ZERO,
        }
    }

    /// Local lateral position (y_S − y_org) of the wheel point with profile coordinate `ey`,
    /// radius `r` (mm) at the lowest-point angle (sin θ, cos θ).
    #[inline]
    fn lateral(&self, ey: T, r: T, st: T, ct: T) -> T {
        r * st * self.spsi + ey * self.cc + r * ct * self.sc + self.cy_off + (self.cy - self.cy_ref)
    }

    /// The wheel lowered rigidly by `dv` (mm, downwards) from this position.
    pub fn lowered(&self, dv: T) -> Self {
        let mut w = *self;
        w.cz -= dv;
        w.cz_off -= dv;
        w.cz_ref = w.cz;
        w
    }

    /// Sets the axle height `cz` (mm) from the offset `cz_off` of the local heights: the
    /// touching placement.
    fn set_height(&mut self, cz_off: T) {
        self.cz_off = cz_off;
        self.cz = self.r0 + cz_off;
        self.cz_ref = self.cz;
    }

    /// Height z_S of the wheel point at axial position `u` (mm from the wheelset centre) with
    /// radius increase `ez` (mm) at the lowest-point angle (sin θ, cos θ):
    /// z1 + cz = u sφ − (r0 + e_z) cθ cφ + cz, evaluated as the sum of u sφ − e_z cθ cφ,
    /// r0 (1 − cθ cφ), cz_off and (cz − cz_ref), so no ≈ r0 magnitudes cancel (f32: ≈ 1e-7 mm
    /// instead of ≈ 3e-5 mm).
    #[inline]
    fn height(&self, u: T, ez: T, st: T, ct: T) -> T {
        // 1 − cos θ = sin²θ / (1 + cos θ) (θ is small: cos θ > 0)
        let omc_t = if ct > T::ZERO {
            st * st / (T::ONE + ct)
        } else {
            T::ONE - ct
        };
        let omc = omc_t + ct * self.omc_phi;
        u * self.sphi - ez * ct * self.cphi + self.r0 * omc + self.cz_off + (self.cz - self.cz_ref)
    }

    /// The lowest wheel point for profile parameter `t`.
    pub fn at(&self, t: T) -> WheelPoint<T> {
        self.at_cached(t, &mut SegmentCache::new())
    }

    /// Angle θ about the axle of the lowest point for unit tangent (cβ, sβ): (sin θ, cos θ).
    #[inline]
    fn lowest(&self, cb: T, sb: T) -> (T, T) {
        if self.spsi == T::ZERO {
            return (T::ZERO, T::ONE);
        }
        // cos ψ sin θ − sin φ sin ψ cos θ = −(sβ/cβ) cos φ sin ψ
        let num = -sb * self.cphi * self.spsi;
        let den = cb * self.theta_norm;
        let ratio = if math::abs(num) < math::abs(den) {
            num / den
        } else if num * den >= T::ZERO {
            T::ONE
        } else {
            -T::ONE
        };
        // θ = θ₀ + asin(ratio) without trigonometry: sin(θ₀ + β), cos(θ₀ + β) with
        // sin β = ratio, cos β = √(1 − ratio²) ≥ 0 (asin's range); |ratio| ≤ 1 above.
        let cr = math::sqrt(math::max(T::ONE - ratio * ratio, T::ZERO));
        (
            self.st0 * cr + self.ct0 * ratio,
            self.ct0 * cr - self.st0 * ratio,
        )
    }

    /// Position (y_S, z_S) of the lowest point for parameter `t` (cached), without the angles
    /// of [`Self::at_cached`]: what root finding on the placed curve needs.
    #[inline]
    pub fn pos_cached(&self, t: T, cache: &mut SegmentCache<T>) -> (T, T) {
        let (y, z) = self.pos_local_cached(t, cache);
        (y + self.y_org, z)
    }

    /// [`Self::pos_cached`] in local lateral coordinates (y_S − [`PlacedRail::y_origin`]).
    #[inline]
    pub(crate) fn pos_local_cached(&self, t: T, cache: &mut SegmentCache<T>) -> (T, T) {
        let e = self.table.hermite(t, cache);
        let u = e.y + self.u_off;
        let r = self.r0 + e.z;
        let (st, ct) = self.lowest(e.tc, e.ts);
        (self.lateral(e.y, r, st, ct), self.height(u, e.z, st, ct))
    }

    /// Lateral position y_S of the lowest point for parameter `t` (root finding; cached).
    pub fn y_cached(&self, t: T, cache: &mut SegmentCache<T>) -> T {
        self.y_local_cached(t, cache) + self.y_org
    }

    /// [`Self::y_cached`] in local lateral coordinates.
    #[inline]
    fn y_local_cached(&self, t: T, cache: &mut SegmentCache<T>) -> T {
        let e: HermitePoint<T> = self.table.hermite(t, cache);
        let r = self.r0 + e.z;
        let (st, ct) = self.lowest(e.tc, e.ts);
        self.lateral(e.y, r, st, ct)
    }

    /// Local lateral position y_S − y_org of the lowest point for parameter `t`, an approximation of dy_S/dt
    /// (exact without yaw; with yaw the turn of the lowest point's angle θ along the curve is left
    /// out, a relative error of order ψ²·r·κ) for Newton root finding, and the point's z_S and
    /// longitudinal position x (the values of [`Self::at_cached`]).
    #[inline]
    fn y_d_z_x_cached(&self, t: T, cache: &mut SegmentCache<T>) -> (T, T, T, T) {
        let (e, dy, dz) = self.table.hermite_d(t, cache);
        let u = e.y + self.u_off;
        let r = self.r0 + e.z;
        let (st, ct) = self.lowest(e.tc, e.ts);
        let x1 = r * st;
        let y1 = u * self.cphi + r * ct * self.sphi;
        let y = self.lateral(e.y, r, st, ct);
        let d = dz * st * self.spsi + (dy * self.cphi + dz * ct * self.sphi) * self.cpsi;
        (
            y,
            d,
            self.height(u, e.z, st, ct),
            x1 * self.cpsi - y1 * self.spsi,
        )
    }

    /// Local position (y_S − y_org, z_S) of the lowest point and its longitudinal position x
    /// for parameter `t` (cached): the values of [`Self::at_cached`] without the angles.
    #[inline]
    fn pos_x_cached(&self, t: T, cache: &mut SegmentCache<T>) -> (T, T, T) {
        let e = self.table.hermite(t, cache);
        let u = e.y + self.u_off;
        let r = self.r0 + e.z;
        let (st, ct) = self.lowest(e.tc, e.ts);
        let x1 = r * st;
        let y1 = u * self.cphi + r * ct * self.sphi;
        (
            self.lateral(e.y, r, st, ct),
            self.height(u, e.z, st, ct),
            x1 * self.cpsi - y1 * self.spsi,
        )
    }

    /// [`Self::at`] with a segment cache.
    pub fn at_cached(&self, t: T, cache: &mut SegmentCache<T>) -> WheelPoint<T> {
        let mut p = self.at_local_cached(t, cache);
        p.y += self.y_org;
        p
    }

    /// [`Self::at`] in local lateral coordinates (y_S − [`PlacedRail::y_origin`]).
    pub(crate) fn at_local(&self, t: T) -> WheelPoint<T> {
        self.at_local_cached(t, &mut SegmentCache::new())
    }

    /// [`Self::at_cached`] in local lateral coordinates.
    pub(crate) fn at_local_cached(&self, t: T, cache: &mut SegmentCache<T>) -> WheelPoint<T> {
        let e = self.table.hermite(t, cache);
        let p = CurvePoint {
            y: e.y,
            z: e.z,
            angle: math::atan2(e.ts, e.tc),
            curvature: e.curvature,
        };
        let u = p.y + self.u_off;
        let r = self.r0 + p.z;
        let (cb, sb) = (e.tc, e.ts);
        let (st, ct) = self.lowest(cb, sb);
        let x1 = r * st;
        let y1 = u * self.cphi + r * ct * self.sphi;
        // outward normal × cos β: (sθ cβ, −sβ, −cθ cβ)
        let (nx, ny, nz) = (st * cb, -sb, -ct * cb);
        let ny1 = ny * self.cphi - nz * self.sphi;
        let nz1 = ny * self.sphi + nz * self.cphi;
        let ny2 = nx * self.spsi + ny1 * self.cpsi;
        WheelPoint {
            y: self.lateral(p.y, r, st, ct),
            z: self.height(u, p.z, st, ct),
            x: x1 * self.cpsi - y1 * self.spsi,
            angle: math::atan2(ny2, -nz1),
            curvature: -p.curvature,
            radius: r,
            t,
            profile: p,
        }
    }
}

/// Golden-section maximisation of `f` on [lo, hi] (bounded iterations).
fn golden_max<T: Real, F: Fn(T) -> T>(f: F, lo: T, hi: T, iters: usize) -> T {
    let g = math::c::<T>(0.618_033_988_749_894_8);
    let (mut a, mut b) = (lo, hi);
    let mut c = b - g * (b - a);
    let mut d = a + g * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..iters {
        if fc > fd {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = f(d);
        }
    }
    (a + b) * T::HALF
}

/// Finds the curve parameter where a monotone non-decreasing function of the parameter (lateral
/// position) equals `target`, with a node pointer `k` that only moves forward. Returns the
/// parameter, or `None` if outside the curve.
/// The largest node window [lo, hi] around `start` on which `f(node)` is non-decreasing.
fn monotone_window<T: Real, F: FnMut(usize) -> T>(
    mut f: F,
    len: usize,
    start: usize,
) -> (usize, usize) {
    let start = start.min(len.saturating_sub(1));
    let (mut lo, mut hi) = (start, start);
    let (mut f_lo, mut f_hi) = (f(start), f(start));
    for _ in 0..len {
        if lo == 0 {
            break;
        }
        let v = f(lo - 1);
        if v <= f_lo {
            lo -= 1;
            f_lo = v;
        } else {
            break;
        }
    }
    for _ in 0..len {
        if hi + 1 >= len {
            break;
        }
        let v = f(hi + 1);
        if v >= f_hi {
            hi += 1;
            f_hi = v;
        } else {
            break;
        }
    }
    (lo, hi)
}

/// Height band below the flange tip (mm of radius) in which a wheel contact point past the
/// steepest point of the flank counts as riding on the flange top ([`Error::Derailed`]).
///
/// On S1002/UIC60 (1360 mm, no yaw) the rigid contact climbs the rounded flange as the shift
/// grows past flange contact (dy ≈ 7 mm, tilt 1.22 rad): 0.37 mm below the tip at dy 30 (tilt
/// 0.25 rad), 0.10 at dy 40, 0.014 at dy 50 (tilt 0.05 rad), beyond the tip at dy 100. Within
/// 0.1 mm the flange crown is nearly flat (tilt ≲ 0.13 rad) and the wheel has been lifted by its
/// flange height; climbing states below the band are still solved (a derailment simulation needs
/// them).
pub const FLANGE_TIP_BAND: f64 = 0.1;

/// Whether the wheel point at curve parameter `t` lies on the flange top or beyond the flange
/// tip: the tip is the node of largest radius increase z on the flange side of the tape circle
/// (nodes `k0..=k_tape`), the steepest flank point the node of largest |tilt| between the tip and
/// the tape circle.
fn on_flange_top<T: Real, const N: usize>(
    wheel: &PlacedWheel<'_, T, N>,
    t: T,
    k0: usize,
    k_tape: usize,
) -> bool {
    let tb = wheel.table;
    let hi = k_tape.min(tb.len.saturating_sub(1)).min(N - 1);
    if k0 >= hi {
        return false;
    }
    let mut k_tip = k0;
    for k in k0..=hi {
        if tb.z[k] > tb.z[k_tip] {
            k_tip = k;
        }
    }
    let mut k_steep = k_tip;
    for k in k_tip..=hi {
        if math::abs(tb.angle[k]) > math::abs(tb.angle[k_steep]) {
            k_steep = k;
        }
    }
    let tip = T::from_usize(k_tip);
    if t <= tip {
        return true;
    }
    if t >= T::from_usize(k_steep) {
        return false;
    }
    tb.z[k_tip] - tb.point(t).z <= math::c(FLANGE_TIP_BAND)
}

/// Moves the node bracket [k, k+1] of a curve forward (never back) until its node values
/// `fk = (f(k), f(k+1))` enclose `target`, within nodes `0..len` of a non-decreasing stretch.
/// Returns `false` if `target` lies outside the stretch.
fn advance_bracket<T: Real, F: FnMut(usize) -> T>(
    f: &mut F,
    len: usize,
    k: &mut usize,
    fk: &mut (T, T),
    target: T,
) -> bool {
    if len < 2 {
        return false;
    }
    for _ in 0..len {
        if fk.1 >= target || *k + 2 >= len {
            break;
        }
        *k += 1;
        fk.0 = fk.1;
        fk.1 = f(*k + 1);
    }
    !(target < fk.0 || target > fk.1)
}

/// Root u ∈ [0, 1] of a function with f(0) = `f0` and f(1) = `f1` of opposite signs: Newton
/// steps `f(u) → (value, derivative)` from the linear interpolation, each kept inside the
/// current sign-change bracket (a bisection step otherwise), until |f| ≤ `tol` or the step
/// stalls; at most 64 evaluations (the bisection alone reaches the resolution of f64 within
/// them). Same-sign ends return the end with the smaller |f|; a zero end is returned as is.
fn newton_bracketed<T: Real, F: FnMut(T) -> (T, T)>(mut f: F, f0: T, f1: T, tol: T) -> T {
    if f0 == T::ZERO {
        return T::ZERO;
    }
    if f1 == T::ZERO {
        return T::ONE;
    }
    if (f0 > T::ZERO) == (f1 > T::ZERO) {
        return if math::abs(f0) < math::abs(f1) {
            T::ZERO
        } else {
            T::ONE
        };
    }
    // `neg` is the bracket end where f has the sign of f0, `pos` the other one
    let (mut neg, mut pos) = (T::ZERO, T::ONE);
    let neg_sign = f0 > T::ZERO;
    let mut u = f0 / (f0 - f1);
    for _ in 0..64 {
        let (v, d) = f(u);
        if !math::is_finite(v) || math::abs(v) <= tol {
            return u;
        }
        if (v > T::ZERO) == neg_sign {
            neg = u;
        } else {
            pos = u;
        }
        let (lo, hi) = (math::min(neg, pos), math::max(neg, pos));
        let newton = u - v / d;
        let next = if d != T::ZERO && newton > lo && newton < hi {
            newton
        } else {
            (lo + hi) * T::HALF
        };
        if next == u {
            return u;
        }
        u = next;
    }
    u
}

/// z_S and tilt of a rail point (what the gap grid stores).
struct RailAt<T> {
    z: T,
    angle: T,
}

/// One wheel on its rail at a given wheelset pose: placed profiles and the vertical gap on a
/// uniform lateral grid (capacity `M` grid points), with the wheel lowered to touch.
#[derive(Clone, Debug)]
pub struct WheelRail<'a, T, const N: usize, const M: usize> {
    /// Analysed side.
    pub side: Side,
    /// Track and wheelset constants.
    pub setup: TrackSetup<T>,
    /// Wheelset pose (track frame).
    pub pose: WheelsetPose<T>,
    /// The placed rail.
    pub rail: PlacedRail<'a, T, N>,
    /// The placed wheel, touching (`cz` set so that min gap = 0).
    pub wheel: PlacedWheel<'a, T, N>,
    /// Number of grid points used.
    pub n: usize,
    /// Lateral position y_S of grid point 0, mm.
    pub y0: T,
    /// Grid step, mm.
    pub dy: T,
    /// Vertical gap f_v(y_j) ≥ 0 of the touching profiles, mm (min 0).
    pub gap: [T; M],
    /// Rail curve parameter at y_j.
    pub rail_t: [T; M],
    /// Wheel curve parameter at y_j.
    pub wheel_t: [T; M],
    /// Rail surface tilt α(y_j), rad (track-frame contact-angle sign).
    pub rail_angle: [T; M],
    /// Longitudinal position of the wheel's lowest point at y_j, mm (yaw).
    pub wheel_x: [T; M],
    /// Rigid contact point (refined argmin of the gap), y_S, mm.
    pub y_rigid: T,
    /// Raw minimum of Z_wheel − Z_rail with the wheelset centre at height 0 (= −cz), mm.
    pub raw_min: T,
    /// Grid step requested at placement, mm ([`Self::reposition`] starts from it again).
    step: T,
    /// `y0` in local lateral coordinates (y_S − `rail.y_origin()`), mm.
    y0_local: T,
    /// `y_rigid` in local lateral coordinates, mm.
    y_rigid_local: T,
}

impl<'a, T: Real, const N: usize, const M: usize> WheelRail<'a, T, N, M> {
    /// Places one wheel on its rail (single-wheel mode, roll given) and computes the touching gap
    /// on a uniform lateral grid of step `grid_step` (mm; enlarged to fit `M` points if needed)
    /// over the lateral range common to both profiles.
    ///
    /// Errors: invalid tables or inputs (`BadProfile`, `NonFinite`, `OutOfRange`), no lateral
    /// overlap of the profiles (`NoContact`), `M < 8` (`GridTooSmall`); a lateral shift the
    /// profiles do not describe: the touching point at an end of their common range
    /// (`OutOfRange("lateral shift: …")`), or on the flange top / beyond the flange tip
    /// (`Derailed`, see [`FLANGE_TIP_BAND`]).
    pub fn place(
        rail: &'a ProfileTable<T, N>,
        wheel: &'a ProfileTable<T, N>,
        setup: &TrackSetup<T>,
        pose: &WheelsetPose<T>,
        side: Side,
        grid_step: T,
    ) -> Result<Self, Error> {
        let mut g = Self::unplaced(rail, wheel, setup);
        g.place_in(rail, wheel, setup, pose, side, grid_step)?;
        Ok(g)
    }

    /// Storage for a placement that is filled later by [`Self::place_in`] (or
    /// [`Self::reposition`] after a first `place_in`): a `const fn`, so it can initialise a
    /// `static` or a long-lived workspace and the ≈ 5·M·`size_of::<T>()` bytes of the gap grid are
    /// never returned by value. It holds no valid grid (`n = 0`: [`contact_patches`] answers
    /// `NoContact`).
    ///
    /// [`contact_patches`]: super::contact_patches
    pub const fn unplaced(
        rail: &'a ProfileTable<T, N>,
        wheel: &'a ProfileTable<T, N>,
        setup: &TrackSetup<T>,
    ) -> Self {
        WheelRail {
            side: Side::Right,
            setup: *setup,
            pose: WheelsetPose {
                dy: T::ZERO,
                yaw: T::ZERO,
                roll: T::ZERO,
            },
            rail: PlacedRail::unplaced(rail),
            wheel: PlacedWheel::unplaced(wheel, setup),
            n: 0,
            y0: T::ZERO,
            dy: T::ZERO,
            gap: [T::ZERO; M],
            rail_t: [T::ZERO; M],
            wheel_t: [T::ZERO; M],
            rail_angle: [T::ZERO; M],
            wheel_x: [T::ZERO; M],
            y_rigid: T::ZERO,
            raw_min: T::ZERO,
            step: T::ZERO,
            y0_local: T::ZERO,
            y_rigid_local: T::ZERO,
        }
    }

    /// [`Self::place`] into existing storage (no large return value; the stack holds only the
    /// working variables). Same inputs, results and errors as `place`; on an error the grid is
    /// left empty (`n = 0`).
    pub fn place_in(
        &mut self,
        rail: &'a ProfileTable<T, N>,
        wheel: &'a ProfileTable<T, N>,
        setup: &TrackSetup<T>,
        pose: &WheelsetPose<T>,
        side: Side,
        grid_step: T,
    ) -> Result<(), Error> {
        self.prepare(rail, wheel, setup, grid_step)?;
        self.reposition(pose, side)
    }

    /// The pose-independent part of a placement: validates the set-up, step and tables and
    /// places the rail; leaves the grid empty (`n = 0`) for [`Self::reposition`].
    fn prepare(
        &mut self,
        rail: &'a ProfileTable<T, N>,
        wheel: &'a ProfileTable<T, N>,
        setup: &TrackSetup<T>,
        grid_step: T,
    ) -> Result<(), Error> {
        self.n = 0;
        self.step = T::ZERO;
        setup.check()?;
        crate::error::check_positive(grid_step, "grid_step")?;
        if M < 8 {
            return Err(Error::GridTooSmall("gap grid capacity M < 8"));
        }
        let prail = PlacedRail::place(rail, setup)?;
        // validates the wheel table (the pose is set by `reposition`)
        let pwheel = PlacedWheel::new(wheel, setup, &self.pose, self.side)?;
        self.setup = *setup;
        self.rail = prail;
        self.wheel = pwheel;
        self.step = grid_step;
        Ok(())
    }

    /// Moves the wheelset of a placed pair to a new pose (and side) and recomputes the touching
    /// gap grid in place, with the tables, track set-up and grid step of the last successful
    /// [`Self::place`] / [`Self::place_in`]: the per-time-step call. It skips what does not
    /// depend on the pose — the validation of the tables (borrowed immutably, so unchanged) and
    /// the placement of the rail — and gives the same result as `place` with the new pose.
    ///
    /// Errors: `NoContact` if the pair was never placed (storage from [`Self::unplaced`]), the
    /// pose errors of `place` (`NonFinite`, `OutOfRange`) and those of the grid; on an error
    /// the grid is left empty (`n = 0`).
    pub fn reposition(&mut self, pose: &WheelsetPose<T>, side: Side) -> Result<(), Error> {
        if self.step <= T::ZERO {
            return Err(Error::NoContact);
        }
        self.n = 0;
        pose.check()?;
        self.wheel = PlacedWheel::posed(self.wheel.table, &self.setup, pose, side, self.rail.ty);
        self.side = side;
        self.pose = *pose;
        self.dy = self.step;
        self.y_rigid = T::ZERO;
        self.raw_min = T::ZERO;
        let r = self.compute();
        if r.is_err() {
            self.n = 0;
        }
        r
    }

    fn compute(&mut self) -> Result<(), Error> {
        let rl = self.rail.table.len;
        let wl = self.wheel.table.len;
        let rail = self.rail;
        let wheel = self.wheel;
        // The wheel's node values need the node tangents (lowest point under yaw): a scan cache
        // of its own that only marches forward, so the Newton steps' cache is not thrashed.
        let mut cw_scan = SegmentCache::new();
        let mut fy_w = |k: usize| wheel.y_local_cached(T::from_usize(k), &mut cw_scan);
        // lateral windows on which each placed curve is monotone in y_S: around the rail top and
        // around the wheel's tape circle (y_w = 0); side faces that overhang after cant, roll or
        // yaw are cut off there
        let k_top = (T::to_f64(math::floor(rail.t_top)) as usize).min(rl - 1);
        let (rk0, rk1) = monotone_window(|k| rail.node_y_local(k), rl, k_top);
        let mut k_tape = 0usize;
        for k in 0..wl {
            if self.wheel.table.y[k.min(N - 1)] <= T::ZERO {
                k_tape = k;
            } else {
                break;
            }
        }
        let (wk0, wk1) = monotone_window(&mut fy_w, wl, k_tape);
        if rk1 <= rk0 || wk1 <= wk0 {
            return Err(Error::BadProfile(
                "profile not monotone in y near the contact",
            ));
        }
        let r_lo = rail.node_y_local(rk0);
        let r_hi = rail.node_y_local(rk1);
        let w_lo = fy_w(wk0);
        let w_hi = fy_w(wk1);
        if !(math::is_finite(w_lo) && math::is_finite(w_hi)) {
            return Err(Error::NonFinite("wheel placement"));
        }
        let lo = math::max(r_lo, w_lo);
        let hi = math::min(r_hi, w_hi);
        if !math::is_finite(hi - lo) || hi - lo <= math::c::<T>(4.0) * self.dy {
            return Err(Error::NoContact);
        }
        let mut step = self.dy;
        // Saturate before the integer conversion: a tiny finite step (e.g. 1e-300 mm) gives a
        // ratio beyond usize, and `as usize + 1` would overflow (panic in debug, n = 0 in release).
        let ratio = T::to_f64((hi - lo) / step);
        let mut n = if ratio < (M - 1) as f64 {
            ratio as usize + 1
        } else {
            M + 1
        };
        if n > M {
            n = M;
            step = (hi - lo) / T::from_usize(M - 1);
        }
        self.n = n;
        self.dy = step;
        self.y0_local = lo;
        self.y0 = lo + rail.ty;
        // Newton converges quadratically: stop at a few rounding units of the local lateral
        // coordinates and of the terms they are summed from
        let wt = wheel.table;
        let scale = math::max(math::abs(lo), math::abs(hi))
            + math::abs(wheel.cy_off)
            + math::max(
                math::abs(wt.y[wk0.min(N - 1)]),
                math::abs(wt.y[wk1.min(N - 1)]),
            );
        let tol = math::c::<T>(4.0) * T::EPSILON * scale;
        let (mut kr, mut kw) = (rk0, wk0);
        // node values of the rail: exact node coordinates (what the Hermite curve gives there)
        let mut fy_r = |k: usize| rail.node_y_local(k);
        let mut fr = (fy_r(rk0), fy_r(rk0 + 1));
        let mut cw_scan2 = SegmentCache::new();
        let mut fy_w = |k: usize| wheel.y_local_cached(T::from_usize(k), &mut cw_scan2);
        let mut fw = (fy_w(wk0), fy_w(wk0 + 1));
        let mut cr = SegmentCache::new();
        let mut cw = SegmentCache::new();
        let mut jmin = 0usize;
        let mut gmin = T::MAX;
        for j in 0..n {
            let y = lo + T::from_usize(j) * step;
            let y = math::clamp(y, lo, hi);
            // rail: Newton on the placed cubic; the last evaluation is kept for the point
            if !advance_bracket(&mut fy_r, rk1 + 1, &mut kr, &mut fr, y) {
                return Err(Error::BadProfile("rail not monotone in y"));
            }
            let tk = T::from_usize(kr);
            let mut last_r = (T::MAX, T::ZERO, T::ZERO, T::ZERO, T::ZERO);
            let u = newton_bracketed(
                |u| {
                    let t = tk + u;
                    let (py, pz, dy, dz) = rail.table.hermite_pos_d(t, &mut cr);
                    last_r = (t, py, pz, dy, dz);
                    (
                        py * rail.cos_a + pz * rail.sin_a - y,
                        dy * rail.cos_a + dz * rail.sin_a,
                    )
                },
                fr.0 - y,
                fr.1 - y,
                tol,
            );
            let tr = tk + u;
            // the rail point (z_S, tilt) as `PlacedRail::at_cached` computes it
            let (pr_z, pr_angle) = match last_r {
                (t, py, pz, dy, dz) if t == tr && dy * dy + dz * dz > T::ZERO => {
                    let norm = math::sqrt(dy * dy + dz * dz);
                    let (qy, qz) = (py, -pz);
                    (
                        qy * rail.sin_a + qz * rail.cos_a + rail.tz,
                        rail.cant - math::atan2(dz / norm, dy / norm),
                    )
                }
                _ => {
                    let p = rail.at_cached(tr, &mut cr);
                    (p.z, p.angle)
                }
            };
            // wheel: Newton on the lowest-point curve; the last evaluation gives z and x
            if !advance_bracket(&mut fy_w, wk1 + 1, &mut kw, &mut fw, y) {
                return Err(Error::BadProfile("wheel not monotone in y"));
            }
            let tk = T::from_usize(kw);
            let mut last_w = (T::MAX, T::ZERO, T::ZERO);
            let u = newton_bracketed(
                |u| {
                    let t = tk + u;
                    let (py, d, pz, px) = wheel.y_d_z_x_cached(t, &mut cw);
                    last_w = (t, pz, px);
                    (py - y, d)
                },
                fw.0 - y,
                fw.1 - y,
                tol,
            );
            let tw = tk + u;
            let (pw_z, pw_x) = if last_w.0 == tw {
                (last_w.1, last_w.2)
            } else {
                let (_, z, x) = wheel.pos_x_cached(tw, &mut cw);
                (z, x)
            };
            let pr = RailAt {
                z: pr_z,
                angle: pr_angle,
            };
            let gj = pw_z - pr.z;
            if !math::is_finite(gj) {
                return Err(Error::NonFinite("gap"));
            }
            self.gap[j] = gj;
            self.rail_t[j] = tr;
            self.wheel_t[j] = tw;
            self.rail_angle[j] = pr.angle;
            self.wheel_x[j] = pw_x;
            if gj < gmin {
                gmin = gj;
                jmin = j;
            }
        }
        // The touching point must be a true minimum of the gap inside the profiles' common
        // range: at either end of the grid the gap still falls outwards, so the contact lies
        // outside the range both profiles cover.
        if jmin == 0 || jmin + 1 >= n {
            return Err(Error::OutOfRange(
                "lateral shift: contact at the end of the profiles' common range",
            ));
        }
        if on_flange_top(&wheel, self.wheel_t[jmin], wk0, k_tape) {
            return Err(Error::Derailed);
        }
        // parabolic refinement of the minimum
        let (mut fmin, mut p) = (gmin, T::ZERO);
        if jmin > 0 && jmin + 1 < n {
            let (a, b, c) = (self.gap[jmin - 1], self.gap[jmin], self.gap[jmin + 1]);
            let den = a - T::TWO * b + c;
            if den > T::ZERO {
                p = math::clamp((a - c) / (T::TWO * den), -T::HALF, T::HALF);
                fmin = b - (a - c) * p * math::c::<T>(0.25);
            }
        }
        for j in 0..n {
            self.gap[j] = math::max(self.gap[j] - fmin, T::ZERO);
        }
        // the grid's wheel heights are z1 + r0 (local): raw minimum of z1 − z_rail is fmin − r0
        self.raw_min = fmin - self.wheel.r0;
        self.wheel.set_height(-fmin);
        self.y_rigid_local = lo + (T::from_usize(jmin) + p) * step;
        self.y_rigid = self.y_rigid_local + rail.ty;
        Ok(())
    }

    /// Lateral position y_S of grid point j, mm.
    #[inline]
    pub fn y_at(&self, j: usize) -> T {
        self.y0 + T::from_usize(j) * self.dy
    }

    /// Lateral position of grid point j in local coordinates (y_S − `rail.y_origin()`), mm.
    #[inline]
    pub(crate) fn y_local_at(&self, j: usize) -> T {
        self.y0_local + T::from_usize(j) * self.dy
    }

    /// `y_rigid` in local lateral coordinates, mm.
    #[inline]
    pub(crate) fn y_rigid_local(&self) -> T {
        self.y_rigid_local
    }

    /// Rail curve parameter at lateral position `y` (S), by bracketing from the grid and
    /// regula falsi. Clamped to the grid range.
    pub fn rail_t_at(&self, y: T) -> T {
        self.rail_t_at_local(y - self.rail.ty)
    }

    /// [`Self::rail_t_at`] at a local lateral position.
    pub(crate) fn rail_t_at_local(&self, y: T) -> T {
        let (j, _) = self.grid_index_local(y);
        let (t0, t1) = (self.rail_t[j], self.rail_t[j + 1]);
        let rail = self.rail;
        let mut c = SegmentCache::new();
        let mut f = |t: T| rail.y_local_cached(t, &mut c) - y;
        let (f0, f1) = (f(t0), f(t1));
        let u = illinois(|u| f(t0 + u * (t1 - t0)), f0, f1, 40, math::c(1e-11));
        t0 + u * (t1 - t0)
    }

    /// Wheel curve parameter at lateral position `y` (S), touching configuration.
    pub fn wheel_t_at(&self, y: T) -> T {
        self.wheel_t_at_local(y - self.rail.ty)
    }

    /// [`Self::wheel_t_at`] at a local lateral position.
    pub(crate) fn wheel_t_at_local(&self, y: T) -> T {
        let (j, _) = self.grid_index_local(y);
        let (t0, t1) = (self.wheel_t[j], self.wheel_t[j + 1]);
        let wheel = self.wheel;
        let mut c = SegmentCache::new();
        let mut f = |t: T| wheel.y_local_cached(t, &mut c) - y;
        let (f0, f1) = (f(t0), f(t1));
        let u = illinois(|u| f(t0 + u * (t1 - t0)), f0, f1, 40, math::c(1e-11));
        t0 + u * (t1 - t0)
    }

    /// Grid interval index j (0 ≤ j ≤ n−2) and local fraction for lateral position `y`.
    pub fn grid_index(&self, y: T) -> (usize, T) {
        self.grid_index_local(y - self.rail.ty)
    }

    /// [`Self::grid_index`] for a local lateral position.
    pub(crate) fn grid_index_local(&self, y: T) -> (usize, T) {
        let x = if self.dy > T::ZERO {
            (y - self.y0_local) / self.dy
        } else {
            T::ZERO
        };
        let last = self.n.saturating_sub(2);
        let x = if math::is_finite(x) {
            math::clamp(x, T::ZERO, T::from_usize(last))
        } else {
            T::ZERO
        };
        // x ∈ [0, last] here: truncation is the floor
        let j = (T::to_f64(x) as usize).min(last);
        (j, x - T::from_usize(j))
    }

    /// Linear interpolation of a grid array at lateral position `y`.
    pub fn interp(&self, arr: &[T; M], y: T) -> T {
        self.interp_local(arr, y - self.rail.ty)
    }

    /// [`Self::interp`] at a local lateral position.
    pub(crate) fn interp_local(&self, arr: &[T; M], y: T) -> T {
        let (j, u) = self.grid_index_local(y);
        arr[j] + u * (arr[j + 1] - arr[j])
    }

    /// Height of the wheelset centre (axle) in the track frame at touching, mm.
    pub fn axle_height(&self) -> T {
        self.wheel.cz
    }
}

/// Result of the two-wheel equilibrium (§7.2 step 5).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Equilibrium<T> {
    /// Roll angle about +x_T at which both wheels touch at the same axle height, rad.
    pub roll: T,
    /// Axle height at that roll, mm.
    pub axle_height: T,
    /// Height mismatch of the two wheels at the returned roll, mm.
    pub residual: T,
    /// Iterations used.
    pub iterations: usize,
    /// `true` if |residual| < 1e-9 mm (f64) / 1e-4 mm (f32) within the iteration cap.
    pub converged: bool,
}

/// Two-wheel vertical/roll equilibrium (§7.2 step 5): the roll φ for which the left and right
/// wheels touch their rails at the same axle height, for given lateral shift and yaw. Bracket
/// φ ∈ [−0.05, 0.05] rad, Illinois regula falsi, at most 60 iterations. The same tables are used
/// for both sides (right-side profiles mirrored for the left, as CONTACT does).
pub fn equilibrium_roll<T: Real, const N: usize, const M: usize>(
    rail: &ProfileTable<T, N>,
    wheel: &ProfileTable<T, N>,
    setup: &TrackSetup<T>,
    dy: T,
    yaw: T,
    grid_step: T,
) -> Result<Equilibrium<T>, Error> {
    // one placed pair, repositioned for every roll and side (the tables are validated and the
    // rail placed once; the results are those of `WheelRail::place`)
    let mut g = WheelRail::<T, N, M>::unplaced(rail, wheel, setup);
    g.prepare(rail, wheel, setup, grid_step)?;
    let mut height = |roll: T, side: Side| -> Result<T, Error> {
        g.reposition(&WheelsetPose { dy, yaw, roll }, side)?;
        Ok(g.axle_height())
    };
    let mut f = |roll: T| -> Result<T, Error> {
        Ok(height(roll, Side::Left)? - height(roll, Side::Right)?)
    };
    let (mut a, mut b) = (math::c::<T>(-0.05), math::c::<T>(0.05));
    let (mut fa, mut fb) = (f(a)?, f(b)?);
    if (fa > T::ZERO) == (fb > T::ZERO) {
        return Err(Error::OutOfRange(
            "no roll in [-0.05, 0.05] rad balances the wheels",
        ));
    }
    let tol = if T::EPSILON < math::c(1e-10) {
        math::c::<T>(1e-9)
    } else {
        math::c::<T>(1e-4)
    };
    let mut side = 0i8;
    let mut x = a;
    let mut fx = fa;
    let mut it = 0;
    for i in 0..60 {
        it = i + 1;
        x = (a * fb - b * fa) / (fb - fa);
        if !(x > a && x < b) {
            x = (a + b) * T::HALF;
        }
        fx = f(x)?;
        if math::abs(fx) < tol {
            break;
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
    let h = height(x, Side::Left)?;
    Ok(Equilibrium {
        roll: x,
        axle_height: h,
        residual: fx,
        iterations: it,
        converged: math::abs(fx) < tol,
    })
}
