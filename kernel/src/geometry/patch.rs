//! Contact regions and patches at a given approach: reference point and contact angle
//! (methods.md §7.2 step 6), and the per-patch plain-data samples that normal solvers consume
//! (STRIPES in the kernel, NORM on the host), §7.3, §7.5.
//!
//! # What a call computes
//! [`contact_patches`] takes the touching geometry ([`WheelRail`]) and a **vertical approach**
//! δ_v (mm; the wheel is lowered rigidly by δ_v from the touching position — one number for all
//! patches of the wheel, so tread and flange patches share the wheel's rigid displacement):
//! 1. Regions: connected runs of grid rows with overlap g_j = δ_v − f_v(y_j) > 0.
//! 2. Patches: neighbouring regions whose overlap extents are at most `d_comb` apart (lateral
//!    distance in the side frame), or at most `d_sep` apart with own weighted angles differing by
//!    at most `a_sep`, are combined into one patch (weights add; the rows in between carry no
//!    weight). This is our reading of CONTACT's D_COMB / D_SEP / A_SEP (defaults 4 mm, 8 mm,
//!    90°, as in `mbench_a22`); it reproduces CONTACT's single patch at y_ws = 5 mm (right
//!    wheel), where a tread remnant 6.7 mm from the flange-root region is included.
//! 3. Reference point and angle per patch (`ReferenceRule`):
//!    * `Weighted` (default, CONTACT's rule): w_j = g_j^{5/2} (∝ ∫(g_j − k x²)₊² dx);
//!      y_ref = Σ w y / Σ w, δ = Σ w α(y_j) / Σ w with α the rail tilt; x_ref = Σ w x_j / Σ w.
//!    * `WeightedLinear`: w_j = g_j^{3/2} (CONTACT's linear gap weighting).
//!    * `Argmin`: the deepest point of the patch (parabola-refined), α there.
//! 4. **Angle turning between patches** (continuity rule): the final angle of patch k is
//!    δ_k' = (W_k δ_k + Σ_m c_km W_m δ_m) / (W_k + Σ_m c_km W_m), with c_km = 1 for patches at
//!    most `d_sep` apart, falling linearly to 0 at `d_turn`, 0 beyond (W = Σ w of a patch). For
//!    two patches this turns both to their combined weighted angle when close (CONTACT: d_comb =
//!    4, d_sep = 8, d_turn = 12 mm), so angles do not jump when patches merge, and a new patch,
//!    which appears with zero weight, does not move its neighbour's angle.
//!    Why outputs are continuous in the lateral shift at a fixed approach: the weights g^{5/2}
//!    vanish with the overlap, so a row (or a whole region) enters and leaves with zero weight;
//!    the combined patch's centre and angle are the weighted means of its parts; the turning
//!    factor is continuous in the distance. What is not continuous by nature: the number of
//!    patches, and a patch's own reference point when two patches are combined (at d = d_comb,
//!    where both already share one angle, the two reference points are replaced by their weighted
//!    mean). Weight-averaged quantities (Σ W y_ref / Σ W, Σ W δ / Σ W) are continuous throughout.
//! 5. Samples in the patch's contact frame (see [`PatchSamples`]) by the chosen
//!    [`Correspondence`], in the loaded configuration (wheel lowered by δ_v).
//!
//! The weighted frame depends on the approach, and the approach on the normal solution (§7.2): a
//! normal solver iterates δ_v and calls [`contact_patches`] again; [`patches_at_normal_approach`]
//! does this for a prescribed normal approach of the main patch (used by the Manchester tests with
//! the approach printed by CONTACT).
//!
//! # Contact frame of a patch (§0.2)
//! Origin at the reference point on the rail surface; normal n into the wheel, tilted by the
//! patch angle δ towards the track centre; x = rolling direction (track x); y = n × x, which
//! points to the left in the track: towards the field side for the left wheel and towards the
//! track centre (flange) for the right wheel. The sample coordinate `s` is this y (mm).
//!
//! # Yaw
//! The gap uses the wheel's lowest point per lateral row (see `placement`), so yaw moves the
//! contact laterally and vertically as it should; the longitudinal curvature A uses the
//! body-of-revolution formula cos δ/(2R) without the small yaw correction. The longitudinal
//! position of each sample's rigid contact (the lowest wheel point) is reported as `x_c(s)`
//! relative to `x_ref`, so a solver can shift its strips (h ≈ f_n + A (x − x_c)² − δ); the
//! remaining yaw asymmetry of the gap in x (An et al., ref. 33) is not modelled.

use super::isosceles;
use super::placement::WheelRail;
use crate::profile::{illinois, SegmentCache};
use crate::{math, Error, Real};
use core::cell::Cell;

/// How the patch reference point and contact angle are chosen (§7.2 step 6).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum ReferenceRule {
    /// Overlap-weighted centre and angle, w = g^{5/2} (CONTACT's rule, default).
    Weighted,
    /// Overlap-weighted with w = g^{3/2} (CONTACT's linear gap weighting option).
    WeightedLinear,
    /// Deepest point of the patch and the tilt there (seed A; rigid contact point).
    Argmin,
}

/// How points of the facing profiles are paired for the normal separation (§7.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Correspondence {
    /// Contact-plane projection: equal tangential coordinate s, separation along the normal.
    Projection,
    /// Isosceles pairs (seed B): tangents and segment AB form an isosceles triangle;
    /// s = tangential coordinate of the pair's midpoint, separation ±|AB|.
    Isosceles,
}

/// Options of [`contact_patches`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct PatchOptions<T> {
    /// Reference rule (default `Weighted`).
    pub reference: ReferenceRule,
    /// Correspondence for the samples (default `Projection`).
    pub correspondence: Correspondence,
    /// Regions at most this far apart are combined into one patch, mm (default 4).
    pub d_comb: T,
    /// Patches at most this far apart share their combined angle, mm (default 8).
    pub d_sep: T,
    /// Beyond this distance patch angles are independent, mm (default 12; > d_sep).
    pub d_turn: T,
    /// Regions between `d_comb` and `d_sep` apart are combined if their own weighted angles
    /// differ by at most this, rad (default π/2, CONTACT's A_SEP = 90°).
    pub a_sep: T,
    /// Number of samples per patch (≤ the capacity S; default 64).
    pub samples: usize,
    /// Sampled range beyond the overlap on each side, as a fraction of the overlap width
    /// (default 0.25).
    pub margin: T,
    /// Minimum sampled range beyond the overlap on each side, mm (default 0.5).
    pub min_margin: T,
}

impl<T: Real> Default for PatchOptions<T> {
    fn default() -> Self {
        PatchOptions {
            reference: ReferenceRule::Weighted,
            correspondence: Correspondence::Projection,
            d_comb: math::c(4.0),
            d_sep: math::c(8.0),
            d_turn: math::c(12.0),
            a_sep: T::PI * T::HALF,
            samples: 64,
            margin: math::c(0.25),
            min_margin: math::c(0.5),
        }
    }
}

/// Reference point, frame and summary of one contact patch.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct PatchFrame<T> {
    /// Reference point, lateral position in the **rail profile file's own coordinates**, mm
    /// (cli.md `y_ref_mm`; for the shipped files positive towards the field side).
    pub y_ref_rail: T,
    /// Reference point, vertical position in the rail profile file's coordinates (down), mm.
    pub z_ref_rail: T,
    /// Wheel point paired with the reference point (s = 0), wheel profile file coordinates, mm.
    pub y_ref_wheel: T,
    /// Wheel point paired with the reference point, z in the wheel file (radius increase), mm.
    pub z_ref_wheel: T,
    /// Reference point in the track frame T: x (longitudinal; nonzero with yaw), mm.
    pub x_ref: T,
    /// Reference point in the track frame T: y (to the left), mm.
    pub y_ref_track: T,
    /// Reference point in the track frame T: z (up), mm (at the touching wheel position).
    pub z_ref_track: T,
    /// Contact angle δ of the patch (tilt of the normal towards the track centre, track frame,
    /// includes the roll), rad.
    pub angle: T,
    /// Contact angle before turning towards neighbouring patches, rad.
    pub angle_own: T,
    /// Rolling radius: distance from the axle of the wheel point paired with the reference
    /// point, mm.
    pub rolling_radius: T,
    /// Total weight Σ w of the patch (units mm^{5/2} for `Weighted`), for blending.
    pub weight: T,
    /// Vertical approach δ_v used, mm.
    pub approach_vertical: T,
    /// Normal approach of this patch at δ_v: the largest interpenetration along the patch
    /// normal (= −min separation of the correspondence, the minimum refined on the continuous
    /// curves around the deepest sample, so independent of the sample density), mm.
    pub approach: T,
    /// Lateral extent of the overlap in the side frame S (y_S from, to), mm.
    pub overlap_y: [T; 2],
    /// Extent of the overlap in the sample coordinate s (from, to), mm.
    pub overlap_s: [T; 2],
    /// Number of connected overlap regions combined into this patch.
    pub components: usize,
}

/// Plain-data samples of one patch on a uniform grid of the tangential coordinate s (mm) of the
/// patch's contact frame, cell-centred: s_i = s0 + (i + ½)·ds, i < n. For the STRIPES normal
/// solver (one sample = one strip candidate) and the NORM reference (h = f_n + A x² on its grid).
///
/// All values at the touching-plus-δ_v configuration of the call; f_n is normalised so that its
/// minimum is 0 and `PatchFrame::approach` is the corresponding normal approach, i.e. the rigid
/// interpenetration at the sample is `approach − f_n(s)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PatchSamples<T, const S: usize> {
    /// Number of valid samples.
    pub n: usize,
    /// Start of the sampled range, mm (the first sample sits at s0 + ds/2).
    pub s0: T,
    /// Sample spacing in s, mm.
    pub ds: T,
    /// Correspondence used.
    pub correspondence: Correspondence,
    /// Normal separation f_n(s) ≥ 0 of the undeformed profiles, min 0, mm.
    pub f_n: [T; S],
    /// Longitudinal gap curvature A(s) = cos δ(s) / (2 R(s)), 1/mm.
    pub a_long: [T; S],
    /// Lateral gap curvature B(s) = ½(κ_wheel + κ_rail) of the cross-section (normal section),
    /// convex positive, unfiltered, 1/mm (negative where the gap is conformal).
    pub b_lat: [T; S],
    /// Local contact angle δ(s) (wheel tilt at the paired point, track frame), rad.
    pub angle: [T; S],
    /// Rolling radius R(s) at the paired wheel point, mm.
    pub radius: [T; S],
    /// Strip width represented by the sample, mm (= ds for the projection; the arc-length
    /// increment of the pair midpoints for isosceles pairs, seed B eq. 16).
    pub width: [T; S],
    /// Lateral position y_S (side frame) of the rail point of the pair, mm (for plots/mapping).
    pub y_rail: [T; S],
    /// Longitudinal position of the strip's rigid contact relative to the reference point,
    /// x_c(s) = x(wheel's lowest point at the paired point) − x_ref, mm (0 without yaw). With yaw
    /// the undeformed distance is h(x, s) ≈ f_n(s) + A(s)(x − x_c(s))² − δ to first order.
    pub x_c: [T; S],
}

impl<T: Real, const S: usize> PatchSamples<T, S> {
    /// Empty samples.
    pub fn empty() -> Self {
        PatchSamples {
            n: 0,
            s0: T::ZERO,
            ds: T::ZERO,
            correspondence: Correspondence::Projection,
            f_n: [T::ZERO; S],
            a_long: [T::ZERO; S],
            b_lat: [T::ZERO; S],
            angle: [T::ZERO; S],
            radius: [T::ZERO; S],
            width: [T::ZERO; S],
            y_rail: [T::ZERO; S],
            x_c: [T::ZERO; S],
        }
    }

    /// Tangential coordinate of sample i, mm.
    #[inline]
    pub fn s(&self, i: usize) -> T {
        self.s0 + (T::from_usize(i) + T::HALF) * self.ds
    }
}

/// One contact patch: frame + samples.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Patch<T, const S: usize> {
    /// Reference point, angle, radius, approach.
    pub frame: PatchFrame<T>,
    /// Samples in the contact frame.
    pub samples: PatchSamples<T, S>,
}

impl<T: Real, const S: usize> Patch<T, S> {
    /// An empty patch.
    pub fn empty() -> Self {
        Patch {
            frame: PatchFrame {
                y_ref_rail: T::ZERO,
                z_ref_rail: T::ZERO,
                y_ref_wheel: T::ZERO,
                z_ref_wheel: T::ZERO,
                x_ref: T::ZERO,
                y_ref_track: T::ZERO,
                z_ref_track: T::ZERO,
                angle: T::ZERO,
                angle_own: T::ZERO,
                rolling_radius: T::ZERO,
                weight: T::ZERO,
                approach_vertical: T::ZERO,
                approach: T::ZERO,
                overlap_y: [T::ZERO; 2],
                overlap_s: [T::ZERO; 2],
                components: 0,
            },
            samples: PatchSamples::empty(),
        }
    }
}

/// Up to `K` patches of one wheel, ordered by increasing y_S (from the track centre outwards).
///
/// A count and a fixed array rather than a `heapless::Vec` (as the results use): the patches are
/// filled in place, sample by sample, in the caller's workspace, and a `Patch` is large (4,200 B
/// in f32, 8,368 B in f64 with 128 samples), so building one on the stack to push it would add
/// that much stack on the target for nothing.
#[derive(Clone, Debug)]
pub struct Patches<T, const K: usize, const S: usize> {
    /// Number of valid patches.
    pub len: usize,
    /// The patches (`items[..len]`).
    pub items: [Patch<T, S>; K],
}

impl<T: Real, const K: usize, const S: usize> Patches<T, K, S> {
    /// No patches.
    pub fn new() -> Self {
        Patches {
            len: 0,
            items: [Patch::empty(); K],
        }
    }

    /// The valid patches.
    pub fn as_slice(&self) -> &[Patch<T, S>] {
        &self.items[..self.len.min(K)]
    }

    /// Index of the patch with the largest weight (the main patch).
    pub fn main_index(&self) -> Option<usize> {
        let mut best: Option<(usize, T)> = None;
        for (i, p) in self.as_slice().iter().enumerate() {
            match best {
                Some((_, w)) if w >= p.frame.weight => {}
                _ => best = Some((i, p.frame.weight)),
            }
        }
        best.map(|b| b.0)
    }
}

impl<T: Real, const K: usize, const S: usize> Default for Patches<T, K, S> {
    fn default() -> Self {
        Self::new()
    }
}

/// Internal per-patch accumulation.
#[derive(Clone, Copy)]
struct Acc<T> {
    j0: usize,
    j1: usize,
    y_lo: T,
    y_hi: T,
    comps: usize,
    w: T,
    wy: T,
    wa: T,
    wx: T,
    y_ref: T,
    angle: T,
}

/// Capacity for overlap runs before combining.
const RUNS: usize = 32;

/// Adds the weights of rows j0..=j1 (only rows with positive overlap count).
fn accumulate<T: Real, const N: usize, const M: usize>(
    geom: &WheelRail<'_, T, N, M>,
    dv: T,
    rule: ReferenceRule,
    a: &mut Acc<T>,
) {
    for jj in a.j0..=a.j1 {
        let g = dv - geom.gap[jj];
        if g <= T::ZERO {
            continue;
        }
        let w = match rule {
            ReferenceRule::WeightedLinear => g * math::sqrt(g),
            _ => g * g * math::sqrt(g),
        };
        a.w += w;
        a.wy += w * geom.y_local_at(jj);
        a.wa += w * geom.rail_angle[jj];
        a.wx += w * geom.wheel_x[jj];
    }
}

/// Weighted angle of an accumulation (0 if it has no weight).
fn own_angle<T: Real>(a: &Acc<T>) -> T {
    if a.w > T::ZERO {
        a.wa / a.w
    } else {
        T::ZERO
    }
}

/// Lateral position (S) where the overlap crosses zero between grid rows a and b (one has g>0).
fn crossing<T: Real, const N: usize, const M: usize>(
    g: &WheelRail<'_, T, N, M>,
    dv: T,
    a: usize,
    b: usize,
) -> T {
    let ga = dv - g.gap[a];
    let gb = dv - g.gap[b];
    let den = ga - gb;
    let u = if den != T::ZERO { ga / den } else { T::HALF };
    let (ya, yb) = (g.y_local_at(a), g.y_local_at(b));
    ya + math::clamp(u, T::ZERO, T::ONE) * (yb - ya)
}

/// Payload of the `OutOfRange` error of [`contact_patches`] when a patch reaches past the end of
/// a profile (the approach, i.e. the load, is too large for the profiles' range).
pub const LOAD_BEYOND_PROFILES: &str =
    "approach: the contact patch reaches past the profiles' range (load too large)";

/// Contact patches of one wheel at vertical approach `dv` (mm, > 0). See the module docs.
///
/// Errors: `NoContact` if `dv ≤ 0` (the wheel is lifted or only touches) or no row overlaps;
/// `OutOfRange(`[`LOAD_BEYOND_PROFILES`]`)` if a patch's samples reach past a profile's end;
/// `TooManyRegions` if more than `K` patches remain after combining; `OutOfRange("samples")` if
/// `opts.samples` is not in 4..=S; `NonFinite` for non-finite inputs.
pub fn contact_patches<T: Real, const N: usize, const M: usize, const K: usize, const S: usize>(
    geom: &WheelRail<'_, T, N, M>,
    dv: T,
    opts: &PatchOptions<T>,
    out: &mut Patches<T, K, S>,
) -> Result<(), Error> {
    out.len = 0;
    crate::error::check_finite(dv, "approach")?;
    if opts.samples < 4 || opts.samples > S {
        return Err(Error::OutOfRange("samples"));
    }
    if !(opts.d_comb >= T::ZERO && opts.d_sep >= opts.d_comb && opts.d_turn > opts.d_sep) {
        return Err(Error::OutOfRange(
            "patch distances: need 0 <= d_comb <= d_sep < d_turn",
        ));
    }
    if dv <= T::ZERO {
        return Err(Error::NoContact);
    }
    let n = geom.n;
    let empty = Acc {
        j0: 0,
        j1: 0,
        y_lo: T::ZERO,
        y_hi: T::ZERO,
        comps: 0,
        w: T::ZERO,
        wy: T::ZERO,
        wa: T::ZERO,
        wx: T::ZERO,
        y_ref: T::ZERO,
        angle: T::ZERO,
    };
    // 1: runs of overlapping rows with their own weights (at most RUNS before combining)
    let mut runs = [empty; RUNS];
    let mut nr = 0usize;
    let mut j = 0usize;
    for _ in 0..n {
        if j >= n {
            break;
        }
        if dv - geom.gap[j] <= T::ZERO {
            j += 1;
            continue;
        }
        let j0 = j;
        let mut j1 = j;
        for _ in 0..n {
            if j1 + 1 < n && dv - geom.gap[j1 + 1] > T::ZERO {
                j1 += 1;
            } else {
                break;
            }
        }
        if nr >= RUNS {
            return Err(Error::TooManyRegions);
        }
        let y_lo = if j0 > 0 {
            crossing(geom, dv, j0 - 1, j0)
        } else {
            geom.y_local_at(0)
        };
        let y_hi = if j1 + 1 < n {
            crossing(geom, dv, j1, j1 + 1)
        } else {
            geom.y_local_at(n - 1)
        };
        let mut a = Acc {
            j0,
            j1,
            y_lo,
            y_hi,
            comps: 1,
            ..empty
        };
        accumulate(geom, dv, opts.reference, &mut a);
        runs[nr] = a;
        nr += 1;
        j = j1 + 1;
    }
    if nr == 0 {
        return Err(Error::NoContact);
    }
    // 2: combine runs into patches: distance ≤ d_comb, or ≤ d_sep with own angles ≤ a_sep apart
    let mut acc = [empty; K];
    let mut np = 0usize;
    for r in runs.iter().take(nr) {
        if np > 0 {
            let last = &mut acc[np - 1];
            let d = r.y_lo - last.y_hi;
            let close_angles = math::abs(own_angle(last) - own_angle(r)) <= opts.a_sep;
            if d <= opts.d_comb || (d <= opts.d_sep && close_angles) {
                last.j1 = r.j1;
                last.y_hi = r.y_hi;
                last.comps += r.comps;
                last.w += r.w;
                last.wy += r.wy;
                last.wa += r.wa;
                last.wx += r.wx;
                continue;
            }
        }
        if np >= K {
            return Err(Error::TooManyRegions);
        }
        acc[np] = *r;
        np += 1;
    }
    // 3: own reference point and angle
    for a in acc.iter_mut().take(np) {
        if a.w > T::ZERO && opts.reference != ReferenceRule::Argmin {
            a.y_ref = a.wy / a.w;
            a.angle = a.wa / a.w;
        } else {
            let mut jmin = a.j0;
            for jj in a.j0..=a.j1 {
                if geom.gap[jj] < geom.gap[jmin] {
                    jmin = jj;
                }
            }
            let mut p = T::ZERO;
            if jmin > 0 && jmin + 1 < n {
                let (ga, gb, gc) = (geom.gap[jmin - 1], geom.gap[jmin], geom.gap[jmin + 1]);
                let den = ga - T::TWO * gb + gc;
                if den > T::ZERO {
                    p = math::clamp((ga - gc) / (T::TWO * den), -T::HALF, T::HALF);
                }
            }
            a.y_ref = geom.y_local_at(jmin) + p * geom.dy;
            a.angle = geom.interp_local(&geom.rail_angle, a.y_ref);
        }
    }
    // 4: turning
    let mut turned = [T::ZERO; K];
    for k in 0..np {
        let mut num = acc[k].w * acc[k].angle;
        let mut den = acc[k].w;
        for m in 0..np {
            if m == k {
                continue;
            }
            let d = if m < k {
                acc[k].y_lo - acc[m].y_hi
            } else {
                acc[m].y_lo - acc[k].y_hi
            };
            let c = if d <= opts.d_sep {
                T::ONE
            } else if d >= opts.d_turn {
                T::ZERO
            } else {
                (opts.d_turn - d) / (opts.d_turn - opts.d_sep)
            };
            num += c * acc[m].w * acc[m].angle;
            den += c * acc[m].w;
        }
        turned[k] = if den > T::ZERO {
            num / den
        } else {
            acc[k].angle
        };
    }
    // 5: frames and samples
    for k in 0..np {
        let a = acc[k];
        let x_ref = if a.w > T::ZERO { a.wx / a.w } else { T::ZERO };
        let p = &mut out.items[k];
        build_patch(geom, dv, a.y_ref, turned[k], a.angle, opts, p)?;
        p.frame.weight = a.w;
        p.frame.x_ref = x_ref;
        let org = geom.rail.y_origin();
        p.frame.overlap_y = [a.y_lo + org, a.y_hi + org];
        p.frame.components = a.comps;
        // overlap extent in s
        let s_a = frame_s(geom, &p.frame, a.y_lo);
        let s_b = frame_s(geom, &p.frame, a.y_hi);
        p.frame.overlap_s = [math::min(s_a, s_b), math::max(s_a, s_b)];
        let w = p.frame.overlap_s[1] - p.frame.overlap_s[0];
        let m = math::max(opts.margin * w, opts.min_margin);
        let s_lo = p.frame.overlap_s[0] - m;
        let s_hi = p.frame.overlap_s[1] + m;
        // The overlap exists, so wheel and rail touch: a sample outside either profile means
        // the patch (overlap plus margin) reaches past a profile's end — the approach, i.e. the
        // load, is too large for the profiles' range, not a missing contact.
        sample_patch(
            geom,
            &mut p.frame,
            s_lo,
            s_hi,
            opts.samples,
            opts.correspondence,
            &mut p.samples,
        )
        .map_err(|e| match e {
            Error::NoContact => Error::OutOfRange(LOAD_BEYOND_PROFILES),
            e => e,
        })?;
        out.len = k + 1;
    }
    Ok(())
}

/// Frame geometry in S (lateral positions local: y_S − `rail.y_origin()`): reference point P, tangent t̂ = (cos δ, sin δ), normal
/// n̂ = (−sin δ, cos δ), and the sign σ with s = σ (p − P)·t̂.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FrameS<T> {
    pub py: T,
    pub pz: T,
    pub c: T,
    pub sn: T,
    pub sigma: T,
}

impl<T: Real> FrameS<T> {
    pub(crate) fn new<const N: usize, const M: usize>(
        geom: &WheelRail<'_, T, N, M>,
        f: &PatchFrame<T>,
    ) -> Self {
        let sigma: T = geom.side.sign();
        // the reference point from its rail-profile coordinates: local lateral position (no
        // ≈ 700 mm track coordinate rounded in), z_S as in `f.z_ref_track`
        let (py, pz) = geom.rail.local_of_profile(f.y_ref_rail, f.z_ref_rail);
        FrameS {
            py,
            pz,
            c: math::cos(f.angle),
            sn: math::sin(f.angle),
            sigma,
        }
    }
    /// Tangential coordinate s of a point (y, z) in S.
    #[inline]
    pub(crate) fn s(&self, y: T, z: T) -> T {
        self.sigma * ((y - self.py) * self.c + (z - self.pz) * self.sn)
    }
    /// Normal coordinate of a point (y, z) in S (positive into the wheel).
    #[inline]
    pub(crate) fn n(&self, y: T, z: T) -> T {
        -(y - self.py) * self.sn + (z - self.pz) * self.c
    }
}

fn frame_s<T: Real, const N: usize, const M: usize>(
    geom: &WheelRail<'_, T, N, M>,
    f: &PatchFrame<T>,
    y: T,
) -> T {
    let fr = FrameS::new(geom, f);
    let p = geom.rail.at_local(geom.rail_t_at_local(y));
    fr.s(p.y, p.z)
}

fn build_patch<T: Real, const N: usize, const M: usize, const S: usize>(
    geom: &WheelRail<'_, T, N, M>,
    dv: T,
    y_ref: T,
    angle: T,
    angle_own: T,
    _opts: &PatchOptions<T>,
    p: &mut Patch<T, S>,
) -> Result<(), Error> {
    let tr = geom.rail_t_at_local(y_ref);
    let rp = geom.rail.at_local(tr);
    let sigma: T = geom.side.sign();
    let f = &mut p.frame;
    f.y_ref_rail = rp.profile.y;
    f.z_ref_rail = rp.profile.z;
    f.y_ref_track = sigma * (rp.y + geom.rail.y_origin());
    f.z_ref_track = rp.z;
    f.angle = angle;
    f.angle_own = angle_own;
    f.approach_vertical = dv;
    Ok(())
}

/// Curve parameter t (rail or wheel) at which the tangential coordinate of the point equals `s`,
/// starting the bracket search from `t_hint`. `pos(t)` returns (y, z) in S.
pub(crate) fn solve_s<T: Real, F: Fn(T) -> (T, T)>(
    pos: &F,
    fr: &FrameS<T>,
    len: usize,
    t_hint: T,
    s: T,
) -> Option<T> {
    solve_s_nodes(pos, fr, len, t_hint, s, &Cell::new(NodeS::new()))
}

/// Tangential coordinates s(t_k) of the last few curve nodes evaluated in one frame (a small
/// direct-mapped cache): consecutive root searches on one curve in one frame (the samples of a
/// patch, the minimum's refinement) bracket in the same or neighbouring segments, and a node's
/// s does not depend on the target. Valid for one curve and one [`FrameS`] only.
#[derive(Clone, Copy, Debug)]
pub(crate) struct NodeS<T> {
    k: [usize; 4],
    s: [T; 4],
}

impl<T: Real> NodeS<T> {
    pub(crate) fn new() -> Self {
        NodeS {
            k: [usize::MAX; 4],
            s: [T::ZERO; 4],
        }
    }
}

/// [`solve_s`] with a node cache `nodes` (same curve and frame in every call with one cache).
/// The values are those of [`solve_s`]: a node's s is exactly what a fresh evaluation gives.
pub(crate) fn solve_s_nodes<T: Real, F: Fn(T) -> (T, T)>(
    pos: &F,
    fr: &FrameS<T>,
    len: usize,
    t_hint: T,
    s: T,
    nodes: &Cell<NodeS<T>>,
) -> Option<T> {
    if len < 2 {
        return None;
    }
    let f = |t: T| {
        let (y, z) = pos(t);
        fr.s(y, z) - s
    };
    let node = |k: usize| {
        let mut c = nodes.get();
        let slot = k & 3;
        let sk = if c.k[slot] == k {
            c.s[slot]
        } else {
            let (y, z) = pos(T::from_usize(k));
            let v = fr.s(y, z);
            c.k[slot] = k;
            c.s[slot] = v;
            nodes.set(c);
            v
        };
        sk - s
    };
    // s increases along the curve when σ = +1 (tangent roughly along +y), decreases when σ = −1
    let dir_up = fr.sigma > T::ZERO;
    let last = len - 1;
    // clamped to [0, last − 1] first: truncation is then the floor
    let mut k =
        (T::to_f64(math::clamp(t_hint, T::ZERO, T::from_usize(last - 1))) as usize).min(last - 1);
    let mut fa = node(k);
    let mut fb = node(k + 1);
    for _ in 0..len {
        let (inc_a, inc_b) = if dir_up { (fa, fb) } else { (-fa, -fb) };
        if inc_a <= T::ZERO && inc_b >= T::ZERO {
            let tk = T::from_usize(k);
            let u = illinois(|u| f(tk + u), fa, fb, 40, math::c(1e-11));
            return Some(tk + u);
        }
        if inc_b < T::ZERO {
            if k + 2 > last {
                return None;
            }
            k += 1;
            fa = fb;
            fb = node(k + 1);
        } else {
            if k == 0 {
                return None;
            }
            k -= 1;
            fb = fa;
            fa = node(k);
        }
    }
    None
}

/// Fills `out` with `n` samples of the patch `frame` over s ∈ [s_lo, s_hi] (mm) by the given
/// correspondence, and sets `frame.approach`, `frame.rolling_radius` and the wheel reference
/// point. A normal solver may call this again with its own range and density.
///
/// Errors: `OutOfRange` if `n` is not in 4..=S or the range is empty; `NoContact` if a sample
/// falls outside either profile.
pub fn sample_patch<T: Real, const N: usize, const M: usize, const S: usize>(
    geom: &WheelRail<'_, T, N, M>,
    frame: &mut PatchFrame<T>,
    s_lo: T,
    s_hi: T,
    n: usize,
    corr: Correspondence,
    out: &mut PatchSamples<T, S>,
) -> Result<(), Error> {
    if n < 4 || n > S {
        return Err(Error::OutOfRange("samples"));
    }
    if !math::is_finite(s_hi - s_lo) || s_hi <= s_lo {
        return Err(Error::OutOfRange("sample range"));
    }
    let fr = FrameS::new(geom, frame);
    let wheel = geom.wheel.lowered(frame.approach_vertical);
    let rail = geom.rail;
    // Position-only evaluations with segment caches (root finding stays in one segment most of
    // the time: the node tangents' trigonometry is then computed once per segment).
    let rcache = Cell::new(SegmentCache::new());
    let wcache = Cell::new(SegmentCache::new());
    let rpos = |t: T| {
        let mut c = rcache.get();
        let p = rail.pos_local_cached(t, &mut c);
        rcache.set(c);
        p
    };
    let wpos = |t: T| {
        let mut c = wcache.get();
        let p = wheel.pos_local_cached(t, &mut c);
        wcache.set(c);
        p
    };
    let y_ref_s = fr.py;
    let tr_ref = geom.rail_t_at_local(y_ref_s);
    let tw_ref = geom.wheel_t_at_local(y_ref_s);
    // rolling radius and wheel reference point: projection pair at s = 0
    // node caches of the root searches in this frame (one per curve)
    let rnodes = Cell::new(NodeS::new());
    let wnodes = Cell::new(NodeS::new());
    let tw0 = solve_s_nodes(&wpos, &fr, wheel.table.len, tw_ref, T::ZERO, &wnodes)
        .ok_or(Error::NoContact)?;
    let w0 = wheel.at(tw0);
    frame.rolling_radius = w0.radius;
    frame.y_ref_wheel = w0.profile.y;
    frame.z_ref_wheel = w0.profile.z;
    out.n = n;
    out.s0 = s_lo;
    out.ds = (s_hi - s_lo) / T::from_usize(n);
    out.correspondence = corr;
    // Curve parameters of the deepest sample: the hints of the minimum's refinement below (a
    // root search walks node by node from its hint; the reference point can be many nodes away).
    let hint_r = Cell::new(tr_ref);
    let hint_w = Cell::new(tw_ref);
    match corr {
        Correspondence::Projection => {
            let (mut tr, mut tw) = (tr_ref, tw_ref);
            let mut best = T::MAX;
            for i in 0..n {
                let s = out.s(i);
                tr = solve_s_nodes(&rpos, &fr, rail.table.len, tr, s, &rnodes)
                    .ok_or(Error::NoContact)?;
                tw = solve_s_nodes(&wpos, &fr, wheel.table.len, tw, s, &wnodes)
                    .ok_or(Error::NoContact)?;
                // the points with the root searches' caches: they ended in these segments
                let mut c = rcache.get();
                let rp = rail.at_local_cached(tr, &mut c);
                rcache.set(c);
                let mut c = wcache.get();
                let wp = wheel.at_local_cached(tw, &mut c);
                wcache.set(c);
                out.f_n[i] = fr.n(wp.y, wp.z) - fr.n(rp.y, rp.z);
                out.angle[i] = wp.angle;
                out.radius[i] = wp.radius;
                out.a_long[i] = math::cos(wp.angle) / (T::TWO * wp.radius);
                out.b_lat[i] = T::HALF * (wp.curvature + rp.curvature);
                out.width[i] = out.ds;
                out.y_rail[i] = rp.y + rail.y_origin();
                out.x_c[i] = wp.x - frame.x_ref;
                if i == 0 || out.f_n[i] < best {
                    best = out.f_n[i];
                    hint_r.set(tr);
                    hint_w.set(tw);
                }
            }
        }
        Correspondence::Isosceles => {
            isosceles::sample_isosceles(&rail, &wheel, &fr, tr_ref, tw_ref, frame.x_ref, out)?;
        }
    }
    // normalise: min f_n = 0 (continuous minimum), approach = −min separation
    let mut imin = 0;
    for i in 1..n {
        if out.f_n[i] < out.f_n[imin] {
            imin = i;
        }
    }
    let mut fmin = out.f_n[imin];
    // refine the minimum of the continuous separation on [s_{i−1}, s_{i+1}] (golden section,
    // 24 steps), so the approach does not depend on the sample density: the bracket shrinks to
    // 0.618^24 ≈ 1e-5 of 2 ds, and the separation is quadratic there, so the minimum's value
    // is off by ≤ ½ f''·(1e-5 ds)² — about 1e-11 mm at ds = 0.5 mm and |f''| = 1/mm
    let lo = out.s(imin.saturating_sub(1));
    let hi = out.s((imin + 1).min(n - 1));
    let sep_at = |s: T| -> Option<T> {
        match corr {
            Correspondence::Projection => {
                let tr = solve_s_nodes(&rpos, &fr, rail.table.len, hint_r.get(), s, &rnodes)?;
                let tw = solve_s_nodes(&wpos, &fr, wheel.table.len, hint_w.get(), s, &wnodes)?;
                hint_r.set(tr);
                hint_w.set(tw);
                let (rp, wp) = (rpos(tr), wpos(tw));
                Some(fr.n(wp.0, wp.1) - fr.n(rp.0, rp.1))
            }
            Correspondence::Isosceles => {
                isosceles::separation_at(&rail, &wheel, &fr, tr_ref, tw_ref, s)
            }
        }
    };
    if hi > lo {
        let g = math::c::<T>(0.618_033_988_749_894_8);
        let (mut a, mut b) = (lo, hi);
        let mut c = b - g * (b - a);
        let mut d = a + g * (b - a);
        let (mut fc, mut fd) = (sep_at(c), sep_at(d));
        for _ in 0..24 {
            match (fc, fd) {
                (Some(vc), Some(vd)) => {
                    if vc < vd {
                        b = d;
                        d = c;
                        fd = fc;
                        c = b - g * (b - a);
                        fc = sep_at(c);
                    } else {
                        a = c;
                        c = d;
                        fc = fd;
                        d = a + g * (b - a);
                        fd = sep_at(d);
                    }
                }
                _ => break,
            }
        }
        if let Some(v) = sep_at((a + b) * T::HALF) {
            fmin = math::min(fmin, v);
        }
    }
    for i in 0..n {
        let v = out.f_n[i] - fmin;
        if !math::is_finite(v) {
            return Err(Error::NonFinite("normal separation"));
        }
        out.f_n[i] = math::max(v, T::ZERO);
    }
    frame.approach = -fmin;
    Ok(())
}

/// Patches at a prescribed **normal** approach `dn` of the main (heaviest) patch: iterates the
/// vertical approach δ_v ← δ_v + (dn − approach)/cos δ until |Δ| < 1e-9 mm (at most 12 passes),
/// starting from δ_v = dn / cos α(y_rigid). Returns (passes, converged).
pub fn patches_at_normal_approach<
    T: Real,
    const N: usize,
    const M: usize,
    const K: usize,
    const S: usize,
>(
    geom: &WheelRail<'_, T, N, M>,
    dn: T,
    opts: &PatchOptions<T>,
    out: &mut Patches<T, K, S>,
) -> Result<(usize, bool), Error> {
    crate::error::check_positive(dn, "normal approach")?;
    let a0 = geom.interp_local(&geom.rail_angle, geom.y_rigid_local());
    let mut dv = dn / math::max(math::cos(a0), math::c(0.05));
    let tol = if T::EPSILON < math::c(1e-10) {
        math::c::<T>(1e-9)
    } else {
        math::c::<T>(1e-5)
    };
    for pass in 0..12 {
        contact_patches(geom, dv, opts, out)?;
        let k = out.main_index().ok_or(Error::NoContact)?;
        let f = out.items[k].frame;
        let delta = (dn - f.approach) / math::max(math::cos(f.angle), math::c(0.05));
        if math::abs(delta) < tol {
            return Ok((pass + 1, true));
        }
        dv += delta;
        if dv <= T::ZERO {
            dv = tol;
        }
    }
    contact_patches(geom, dv, opts, out)?;
    Ok((13, false))
}
