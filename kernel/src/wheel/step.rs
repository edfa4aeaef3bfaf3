//! The real-time per-wheel step: one wheel's contact from a contact table ([`crate::table`]) at a
//! fixed cost — no data-dependent iteration anywhere.
//!
//! Per call, top-down:
//! 1. **Cell of the table**: the shift interval by a binary search of a fixed [`DY_HALVINGS`]
//!    halvings among the table's (not necessarily evenly spaced) shift nodes, twice per call, for
//!    the roots of the roll mappings h(d) = d − dy − c₁Δθ − c₂Δθ², Δθ = roll − node roll
//!    ([`crate::table`] "Roll"; at the table's roll d = dy): the patch's shape (load share, pmax,
//!    area, strips: the node pose with the same gap) and its frame (contact angle, rolling radius,
//!    reference point, rail point, centre height: the node with the rolled contact's wheel point);
//!    the load then locates the cells (linear in dy, linear in ln F, the frame a cubic in ln F
//!    through four load nodes, `frame_weights`); a shift or load outside the table is
//!    `OutOfRange`, never extrapolated.
//! 2. **Vertical balance** (fixed [`BALANCE_STEPS`] steps): the table's load coordinate F (the
//!    load at which Σ_k N_k cos δ_k = F) solves F · Σ_k s_k(F)(cos δ_k(F) + r_k e_k(F)) = F_z,
//!    s_k = N_k/F the slot's load share, e_k = ∓ sin δ_k (right/left wheel) the vertical
//!    component of the lateral axis and r_k = F_y,k/N_k the creep-force ratio of the previous
//!    round. The shares depend weakly on F, so the fixed-point steps F ← F_z/Σ(…) converge
//!    fast (contraction |d ln Σ/d ln F| ≪ 1).
//! 3. **Slots at F**: every slot's frame turned by the roll relative to the node's (contact
//!    angle ∓Δθ, the wheel's arm to the contact about the axle, the rail point along the rail),
//!    yaw's effect on the gap added as k ψ² to the contact angle, load share, rolling radius,
//!    pmax and area ([`crate::table`] "Yaw"; also in step 2), load N_k = s_k F and its `ST`
//!    strips (a_j, p̂_j scaled by F^{1/3}, p̂ rescaled so the strips carry N_k exactly,
//!    Kalker's C_ij at the local ellipse n_j/m_j: Ayasse–Chollet).
//! 4. **Creepages** from the kinematics at each slot's frame ([`creepages_trig`]), the frame's
//!    reference point moved along x by the pose's yaw (first order; the table is built at yaw 0).
//!    Contact angle, yaw and roll enter through their sines and cosines by series
//!    ([`math::sin_cos_small`]): no library trigonometry per call.
//! 5. **FaStrip forces per strip in closed form** ([`strip_forces`](crate::fastrip::strip_forces)), the slot's strips side by
//!    side ([`strip_forces_lanes`]: [`LANES`] at once on 64-bit hosts, same results).
//!
//! **Two entry points, one computation.** The normal–tangential coupling (steps 2–5, through
//! r_k) runs [`COLD_ROUNDS`] = 2 rounds from r_k = 0 in [`step`], for a single state or the first
//! step of a loop; [`step_from`], the step of a time loop, runs one round from the ratios of the
//! wheel's previous result. A third round moves the forces by at most 1.6e-3 of μF_z, and along
//! 1 kHz series the one-step lag of [`step_from`] stays below 0.3 % of μF_z (host-tests
//! `realtime_loop`).
//!
//! **Constant cost.** Every loop runs over the table's slots and strips and the fixed counts
//! above, and every branch that would skip work is evaluated and discarded instead: a slot
//! without a patch here runs on stand-in strips under stand-in creepages, an empty strip on a
//! stand-in strip, and [`strip_forces`](crate::fastrip::strip_forces) computes both adhesion forms and one full slip zone for
//! every strip. The worst of the firmware sweep's 1024 states then costs 2–7 % more than the
//! median (libm's own branches and the Kalker table's two forms) instead of 25–45 %: the worst
//! case is the typical case, and a table with more slots costs proportionally more.
//!
//! What it neglects against [`crate::wheel::solve_wheel`] (its table was built by it): yaw's
//! effect on the strips' shapes and beyond second order, the part of a roll other than the table's that the roll mapping
//! does not hold (it keeps the node's wheel point and patch; where the contact jumps or the rail's
//! curvature changes under the patch the rolled contact differs), the cell grid of FaStrip
//! (closed form, see [`strip_forces`](crate::fastrip::strip_forces) for the differences), and interpolation between nodes.
//! Measured against the converged solver in host-tests `realtime_step`.

#![allow(clippy::neg_cmp_op_on_partial_ord)] // NaN must count as "not positive"

use crate::error::{check_finite, check_positive, Error};
use crate::fastrip::{fastrip, strip_forces_lanes, FastripSettings, LANES};
use crate::geometry::{creepages_trig, Kinematics, PatchFrame, PoseTrig, Side, WheelsetPose};
use crate::kalker;
use crate::kalker::KalkerCoefficients;
use crate::math::{self, c};
use crate::patch::{CellSink, Flexibilities, SemiEllipticStrips, StripPatch};
use crate::patch::{Creepage, Strip};
use crate::table::{ContactTable, NodeField, SlotField, DY_HALVINGS, SLOT_FIXED, YAW_FIT};
use crate::wear::{StripWear, WearMap};
use crate::wheel::pipeline::RegionSink;
use crate::{Material, Real};

/// Fixed-point steps of the vertical balance per round.
pub const BALANCE_STEPS: u32 = 4;
/// Normal–tangential coupling rounds of [`step`] (no previous step); [`step_from`] runs one.
pub const COLD_ROUNDS: u32 = 2;

/// One slot (contact patch) of a step result.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SlotResult<T> {
    /// Normal load N_k, N (0: the slot carries no patch here).
    pub load: T,
    /// Contact angle δ_k, rad.
    pub angle: T,
    /// Rolling radius, mm.
    pub rolling_radius: T,
    /// Reference point, lateral position in the rail file, mm.
    pub y_ref_rail: T,
    /// Reference point, longitudinal position in the track frame, mm (moved by the pose's yaw).
    pub x_ref: T,
    /// Reference point, lateral position in the track frame, mm.
    pub y_ref_track: T,
    /// Reference point, vertical position in the track frame, mm.
    pub z_ref_track: T,
    /// Creepages used.
    pub creepage: Creepage<T>,
    /// Longitudinal creep force on the wheel (patch frame), N.
    pub fx: T,
    /// Lateral creep force on the wheel (patch frame), N.
    pub fy: T,
    /// Spin moment about the reference point, N·mm.
    pub mz: T,
    /// Peak pressure, MPa.
    pub pmax: T,
    /// Contact area, mm².
    pub area: T,
}

/// Result of [`step`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepResult<T, const K: usize> {
    /// Slots, in the table's order.
    pub slots: [SlotResult<T>; K],
    /// Vertical approach δ_v, mm.
    pub vertical_approach: T,
    /// Σ_k (N_k cos δ_k + F_y,k e_k) reached with the last round's forces, N.
    pub vertical_load: T,
}

/// Inputs of [`step`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepInput<T> {
    /// Wheelset pose (kernel convention: dy +left mm, yaw and roll rad).
    pub pose: WheelsetPose<T>,
    /// Vertical wheel load F_z, N (> 0).
    pub fz: T,
    /// Wheelset kinematics.
    pub kinematics: Kinematics<T>,
    /// Coefficient of friction μ (> 0).
    pub mu: T,
}

/// Shift interval of the table at dy: nodes `i`, `i` + 1 and the weight of `i` + 1; the
/// interpolated shift `dy` and roll `roll` of the table there.
#[derive(Clone, Copy)]
struct Shift<T> {
    i: usize,
    f: T,
    dy: T,
    roll: T,
}

/// Locates the table's shift interval for the pose by a binary search of a fixed
/// [`DY_HALVINGS`] halvings (⌈log₂⌉ of the largest node count: every table and shift takes the
/// same count). Roll mapping (module docs): the table point (d, θ(d)) equivalent to the pose
/// (dy, θ) is the root of h(d) = d − dy − c₁(d) Δθ − c₂(d) Δθ², Δθ = θ − θ(d), c₁, c₂ the
/// node's equivalent shift per roll, the node fields (c₁, c₂) given: the shape's or the
/// frame's (at the load nodes around `fz`, linear in ln F), θ(d) its roll; h is searched at the
/// nodes, linear between them. A pose at the table's roll is located at its dy. Both dy and the
/// root must lie inside the table.
fn shift<T: Real>(
    t: &ContactTable<'_, T>,
    pose: &WheelsetPose<T>,
    lz: &LoadCoord<T>,
    (c1_v, c2_v): (NodeField, NodeField),
) -> Result<Shift<T>, Error> {
    let h = &t.header;
    let n = h.n_dy;
    // the load nodes around fz (clamped to the table)
    let (j, fj) = (lz.j, lz.fj);
    let roll_v = NodeField::Roll as usize;
    let at_f = |i: usize, v: usize| t.value(i, j, v) * (T::ONE - fj) + t.value(i, j + 1, v) * fj;
    let hd = |i: usize| {
        let (c1, c2) = (at_f(i, c1_v as usize), at_f(i, c2_v as usize));
        let d = pose.roll - t.value(i, 0, roll_v);
        t.dy_node(i) - pose.dy - d * (c1 + c2 * d)
    };
    // the shift itself and its equivalent at the table's roll both inside the table
    let (h0, h1) = (hd(0), hd(n - 1));
    let inside = pose.dy >= t.dy_node(0) && pose.dy <= t.dy_node(n - 1);
    if !(inside && h0 <= T::ZERO && h1 >= T::ZERO) {
        return Err(Error::OutOfRange("lateral shift outside the contact table"));
    }
    // invariant: h(lo) ≤ 0, and h(hi) > 0 or hi = n − 1; lo < hi
    let (mut lo, mut hi) = (0usize, n - 1);
    for _ in 0..DY_HALVINGS {
        let mid = (lo + hi) / 2;
        if hd(mid) <= T::ZERO {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let i = lo.min(n - 2);
    let (a, b) = (hd(i), hd(i + 1));
    let f = if b > a {
        math::clamp(-a / (b - a), T::ZERO, T::ONE)
    } else {
        T::ZERO
    };
    let lerp = |x: T, y: T| x + (y - x) * f;
    Ok(Shift {
        i,
        f,
        dy: lerp(t.dy_node(i), t.dy_node(i + 1)),
        roll: lerp(t.value(i, 0, roll_v), t.value(i + 1, 0, roll_v)),
    })
}

/// Corner weights of the table cell at (dy, F): bilinear (`w`, load nodes `j`, `j` + 1) and,
/// for the frame, linear in dy × the frame's load weights (`q`, load nodes `j2` … `j2` + 3,
/// [`LoadCoord`]).
#[derive(Clone, Copy)]
struct Cell<T> {
    i: usize,
    j: usize,
    w: [T; 4],
    j2: usize,
    q: [T; 8],
}

/// Where a load F lies on the table's load axis: nodes `j`, `j` + 1 and the weight `fj` of
/// `j` + 1 (linear in ln F), and the frame's weights `l` of the load nodes `j2` … `j2` + 3
/// ([`frame_weights`]). The shape's and the frame's cells at one F share it (one logarithm).
#[derive(Clone, Copy)]
struct LoadCoord<T> {
    j: usize,
    fj: T,
    j2: usize,
    l: [T; 4],
}

/// Lagrange weights of the quadratic through nodes 0, 1, 2 at `s`.
#[inline]
fn quadratic_weights<T: Real>(s: T) -> [T; 3] {
    let (s1, s2) = (s - T::ONE, s - T::TWO);
    [s1 * s2 * T::HALF, -s * s2, s * s1 * T::HALF]
}

/// The frame's interpolation in ln F on the load interval `j` (`n` load nodes, weight `t` of
/// node `j` + 1): the quadratic through nodes j − 1 … j + 1 and the one through j … j + 2,
/// blended linearly across the interval ((1 − t) and t; at the first and last interval the one
/// that exists; 3 nodes: the one quadratic; 2: linear). Both quadratics pass through nodes j and
/// j + 1, so the blend is continuous with a continuous slope (a cubic through four nodes). A
/// single quadratic through the three nodes nearest F, switching at the midpoint between nodes,
/// made the frame jump there: the real-time step's forces jumped by 1.24 % of μF_z (S1002/UIC60
/// 1353 mm, dy −9.8 mm, yaw 2.03 mrad, where the second round's load crossed a midpoint). Returns
/// the first node `j2` and the weights of nodes `j2` … `j2` + 3 (0 beyond the table's nodes).
fn frame_weights<T: Real>(n: usize, j: usize, t: T) -> (usize, [T; 4]) {
    let mut l = [T::ZERO; 4];
    if n < 3 {
        l[0] = T::ONE - t;
        l[1] = t;
        return (0, l);
    }
    let j2 = j.saturating_sub(1).min(n.saturating_sub(4));
    // the quadratic through j − 1 … j + 1 (where j ≥ 1) at 1 + t, through j … j + 2 (where
    // j + 2 < n) at t
    let (lower, upper) = (j >= 1, j + 2 < n);
    let (wl, wu) = match (lower, upper) {
        (true, true) => (T::ONE - t, t),
        (true, false) => (T::ONE, T::ZERO),
        _ => (T::ZERO, T::ONE),
    };
    if lower {
        for (m, w) in quadratic_weights(T::ONE + t).into_iter().enumerate() {
            l[j - 1 - j2 + m] += wl * w;
        }
    }
    if upper {
        for (m, w) in quadratic_weights(t).into_iter().enumerate() {
            l[j - j2 + m] += wu * w;
        }
    }
    (j2, l)
}

/// The [`LoadCoord`] of `f`: `OutOfRange` outside the table's loads unless `clamped`, which
/// takes the nearest end instead (the roll mappings' coefficients at F_z).
fn load_coord<T: Real>(
    t: &ContactTable<'_, T>,
    f: T,
    clamped: bool,
) -> Result<LoadCoord<T>, Error> {
    let h = &t.header;
    let (f0, f1) = (T::from_f64(h.f_min), T::from_f64(h.f_max));
    let f = if clamped {
        math::clamp(f, f0, f1)
    } else if !(f >= f0 && f <= f1) {
        return Err(Error::OutOfRange("load outside the contact table"));
    } else {
        f
    };
    let uj = math::ln(f / f0) / math::ln(f1 / f0) * T::from_usize(h.n_load - 1);
    let j = math::clamp(math::floor(uj), T::ZERO, T::from_usize(h.n_load - 2));
    let fj = uj - j;
    let j = j.to_f64() as usize;
    let (j2, l) = frame_weights(h.n_load, j, fj);
    Ok(LoadCoord { j, fj, j2, l })
}

/// The cell of shift interval `s` at the load coordinate `lc`.
fn cell<T: Real>(s: &Shift<T>, lc: &LoadCoord<T>) -> Cell<T> {
    let (fi, fj, l) = (s.f, lc.fj, lc.l);
    let g = T::ONE - fi;
    Cell {
        i: s.i,
        j: lc.j,
        w: [g * (T::ONE - fj), g * fj, fi * (T::ONE - fj), fi * fj],
        j2: lc.j2,
        q: [
            g * l[0],
            g * l[1],
            g * l[2],
            g * l[3],
            fi * l[0],
            fi * l[1],
            fi * l[2],
            fi * l[3],
        ],
    }
}

#[inline]
fn at<T: Real>(t: &ContactTable<'_, T>, c: &Cell<T>, v: usize) -> T {
    c.w[0] * t.value(c.i, c.j, v)
        + c.w[1] * t.value(c.i, c.j + 1, v)
        + c.w[2] * t.value(c.i + 1, c.j, v)
        + c.w[3] * t.value(c.i + 1, c.j + 1, v)
}

/// Value `v` at the cell with the frame's weights (a cubic in ln F, [`frame_weights`]): the
/// frame moves smoothly but not linearly with the load (the reference point of a conformal
/// patch). A load node beyond the table's (weight 0) reads its last.
#[inline]
fn at_frame<T: Real>(t: &ContactTable<'_, T>, c: &Cell<T>, v: usize) -> T {
    let last = t.header.n_load - 1;
    let mut x = T::ZERO;
    for (m, &q) in c.q.iter().enumerate() {
        x += q * t.value(c.i + m / 4, (c.j2 + m % 4).min(last), v);
    }
    x
}

/// A slot's value `v` at yaw ψ (`psi2` = ψ²) with its yaw coefficient `k` (table "Yaw"), floored
/// at 0 (load share, pmax, area), interpolated bilinearly as [`at`].
#[inline]
fn at_yawed<T: Real>(
    t: &ContactTable<'_, T>,
    c: &Cell<T>,
    o: usize,
    v: SlotField,
    k: SlotField,
    psi2: T,
) -> T {
    math::max(
        at(t, c, o + v as usize) + psi2 * at(t, c, o + k as usize),
        T::ZERO,
    )
}

/// A slot's contact angle at yaw ψ (`psi2` = ψ²) as the table holds it (before the roll's turn),
/// interpolated as the frame ([`at_frame`]).
#[inline]
fn angle_yawed<T: Real>(t: &ContactTable<'_, T>, c: &Cell<T>, o: usize, psi2: T) -> T {
    at_frame(t, c, o + SlotField::Angle as usize)
        + psi2 * at_frame(t, c, o + SlotField::YawAngle as usize)
}

/// cos δ + r e, the vertical load per unit normal load of a patch at the contact angle δ
/// (`sc` = (sin δ, cos δ)) with the creep-force ratio r = F_y/N: e = ∓ sin δ (right/left wheel)
/// is the vertical component of the patch's lateral axis (module docs).
#[inline]
fn vertical<T: Real>(side: Side, sc: (T, T), r: T) -> T {
    match side {
        Side::Right => sc.1 - r * sc.0,
        Side::Left => sc.1 + r * sc.0,
    }
}

/// The creepages of a slot's stand-in evaluation (no patch): in partial slip with spin, as a
/// loaded tread patch.
fn stand_in_creepage<T: Real>() -> Creepage<T> {
    Creepage {
        xi: c(-1e-3),
        eta: c(1e-3),
        phi: c(1e-4),
    }
}

/// The stand-in for an empty strip `q` (a strip of a 10 mm circle at 1000 MPa with Kalker's
/// coefficients of a circle at ν = 0.25): evaluated and discarded so that the step's cost does
/// not depend on how many strips carry load.
fn stand_in_strip<T: Real>(q: usize) -> Strip<T> {
    Strip {
        y: c::<T>(-5.0) + T::from_usize(q) * c::<T>(0.625),
        dy: c(0.625),
        a: c(5.0),
        xc: T::ZERO,
        p_hat: c(1000.0),
        c11: c(4.12),
        c22: c(3.67),
        c23: c(1.47),
        c33: c(1.01),
        sqrt_b_over_a: T::ONE,
        ..Strip::default()
    }
}

/// One real-time step of one wheel from `table` with no previous step to start from (the first
/// call of a loop, or a single state): [`COLD_ROUNDS`] rounds of the normal–tangential coupling,
/// the first from r_k = 0. `K` ≥ the table's slots, `ST` ≥ its strips. See the module docs.
///
/// Errors: `NonFinite`/`NonPositive` for bad inputs (F_z, μ, pose, kinematics), `OutOfRange`
/// for a shift or a load outside the table or capacities below the table's, and the creepage
/// errors.
pub fn step<T: Real, const K: usize, const ST: usize>(
    table: &ContactTable<'_, T>,
    input: &StepInput<T>,
) -> Result<StepResult<T, K>, Error> {
    evaluate::<T, K, ST, ()>(table, input, [T::ZERO; K], COLD_ROUNDS, &mut ())
}

/// The step of a time loop: one round of the normal–tangential coupling, with the creep-force
/// ratios r_k = F_y,k/N_k of `previous`, this wheel's result of the previous time step (from
/// [`step`] or [`step_from`] on the same table). At a fixed state this gives exactly the result
/// of [`step`] when `previous` is [`step`]'s first round; along a time series the ratios lag by
/// one step (host-tests `realtime_loop`: below 0.3 % of μF_z at 1 kHz for hunting at 3 Hz over
/// tread and flange and for a 50 % load step). Its cost is one round: half of [`step`]'s.
///
/// Errors: as [`step`], and `NonFinite("previous step result")` for a previous result with a
/// non-finite or negative load or a non-finite lateral force.
pub fn step_from<T: Real, const K: usize, const ST: usize>(
    table: &ContactTable<'_, T>,
    input: &StepInput<T>,
    previous: &StepResult<T, K>,
) -> Result<StepResult<T, K>, Error> {
    evaluate::<T, K, ST, ()>(table, input, ratios(previous)?, 1, &mut ())
}

/// The creep-force ratios r_k = F_y,k/N_k of a previous result (0 for an empty slot).
fn ratios<T: Real, const K: usize>(previous: &StepResult<T, K>) -> Result<[T; K], Error> {
    let mut ratio = [T::ZERO; K];
    for (r, s) in ratio.iter_mut().zip(previous.slots.iter()) {
        if !(s.load >= T::ZERO) || !math::is_finite(s.load) || !math::is_finite(s.fy) {
            return Err(Error::NonFinite("previous step result"));
        }
        // |F_y| ≤ μ N for every step result; the clamp keeps a foreign value in range
        *r = if s.load > T::ZERO {
            math::clamp(s.fy / s.load, -T::ONE, T::ONE)
        } else {
            T::ZERO
        };
    }
    Ok(ratio)
}

/// Wear of a step with cells ([`step_cells`]), KTH map ([`WearMap::kth`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepWear<T, const K: usize, const ST: usize> {
    /// Wear depth per strip per passage, mm: `depth[k][j]` of slot k's strip j (0 for an empty
    /// slot or strip).
    pub depth: [[T; ST]; K],
    /// Largest strip depth of each slot, mm.
    pub max: [T; K],
}

/// The step with per-cell fields and wear: the result of [`step`] (no `previous`) or
/// [`step_from`] (with one), the same numbers, and in its last round the cell FaStrip
/// ([`fastrip`] with [`FastripSettings::new`], the strips' Ayasse–Chollet flexibilities) on each
/// loaded slot's strips, on `C` cells per strip over the slot's longest strip: every contact
/// cell goes to `sink` with strip index k·`ST` + j (slot k, strip j), and the KTH wear of the
/// slipping cells per strip is returned. The forces stay the closed form's; those of the cells
/// differ from them as the cell FaStrip from [`strip_forces`](crate::fastrip::strip_forces) (within 0.14 % of μN on Hertz
/// patches at 400 cells per strip, more at coarse grids).
///
/// Its cost is the step's plus the cell FaStrip's on ST × C cells per slot (BENCHMARKS.md);
/// fixed trip counts, but the cells do data-dependent work (slip cells).
///
/// Errors: as [`step`] / [`step_from`], and those of the cell FaStrip and the wear map.
pub fn step_cells<T: Real, const K: usize, const ST: usize, const C: usize, S: CellSink<T>>(
    table: &ContactTable<'_, T>,
    input: &StepInput<T>,
    previous: Option<&StepResult<T, K>>,
    sink: &mut S,
) -> Result<(StepResult<T, K>, StepWear<T, K, ST>), Error> {
    let mut cells = Cells::<T, S, K, ST, C> {
        sink,
        map: WearMap::kth(),
        wear: StepWear {
            depth: [[T::ZERO; ST]; K],
            max: [T::ZERO; K],
        },
    };
    let r = match previous {
        None => evaluate::<T, K, ST, _>(table, input, [T::ZERO; K], COLD_ROUNDS, &mut cells)?,
        Some(p) => evaluate::<T, K, ST, _>(table, input, ratios(p)?, 1, &mut cells)?,
    };
    Ok((r, cells.wear))
}

/// What the last round does with a loaded slot's strips besides their closed-form forces.
trait SlotFields<T, const ST: usize> {
    /// Whether [`SlotFields::slot`] runs (false: the forces-only step keeps no strips).
    const ACTIVE: bool;
    /// Slot `k`'s loaded strips (empty ones a = 0), its load N (N), creepages, μ, material and
    /// the rolling speed (mm/s).
    #[allow(clippy::too_many_arguments)]
    fn slot(
        &mut self,
        k: usize,
        strips: &[Strip<T>; ST],
        load: T,
        cr: &Creepage<T>,
        mu: T,
        mat: &Material<T>,
        speed: T,
    ) -> Result<(), Error>;
}

/// The forces-only step.
impl<T, const ST: usize> SlotFields<T, ST> for () {
    const ACTIVE: bool = false;
    fn slot(
        &mut self,
        _: usize,
        _: &[Strip<T>; ST],
        _: T,
        _: &Creepage<T>,
        _: T,
        _: &Material<T>,
        _: T,
    ) -> Result<(), Error> {
        Ok(())
    }
}

/// The cell FaStrip and wear of [`step_cells`].
struct Cells<'a, T, S, const K: usize, const ST: usize, const C: usize> {
    sink: &'a mut S,
    map: WearMap<T>,
    wear: StepWear<T, K, ST>,
}

impl<T: Real, S: CellSink<T>, const K: usize, const ST: usize, const C: usize> SlotFields<T, ST>
    for Cells<'_, T, S, K, ST, C>
{
    const ACTIVE: bool = true;
    fn slot(
        &mut self,
        k: usize,
        strips: &[Strip<T>; ST],
        load: T,
        cr: &Creepage<T>,
        mu: T,
        mat: &Material<T>,
        speed: T,
    ) -> Result<(), Error> {
        let mut st = *strips;
        let mut amax = T::ZERO;
        for s in st.iter_mut() {
            if s.a > T::ZERO {
                amax = math::max(amax, s.a);
                // the closed form's flexibilities (Kalker's at the strip's own ellipse), explicit
                let b = s.a * s.sqrt_b_over_a * s.sqrt_b_over_a;
                let kc = KalkerCoefficients {
                    c11: s.c11,
                    c22: s.c22,
                    c23: s.c23,
                    c33: s.c33,
                };
                s.flex = Flexibilities::kalker(s.a, b, mat.g, &kc);
            }
        }
        if !(amax > T::ZERO) || k >= K {
            return Ok(());
        }
        let dx = T::TWO * amax / T::from_usize(C);
        let mut patch = StripPatch::<T, ST, C>::new(st, -amax, dx, *mat)?;
        patch.scale_to_load(load)?;
        let mut w = StripWear::<T, ST>::new();
        let mut rs = RegionSink::<T, S, ST, true> {
            inner: &mut *self.sink,
            wear: &mut w,
            map: &self.map,
            first: k * ST,
            wear_first: 0,
            speed,
            dx,
        };
        fastrip(
            &patch,
            &SemiEllipticStrips,
            cr,
            &FastripSettings::new(mu),
            &mut rs,
        )?;
        for d in w.depth.iter() {
            if !math::is_finite(*d) {
                return Err(Error::NonFinite("wear depth"));
            }
        }
        self.wear.depth[k] = w.depth;
        self.wear.max[k] = w.max_depth(ST);
        Ok(())
    }
}

/// The step's computation (module docs) with the initial ratios `ratio` and `rounds` rounds.
fn evaluate<T: Real, const K: usize, const ST: usize, F: SlotFields<T, ST>>(
    table: &ContactTable<'_, T>,
    input: &StepInput<T>,
    mut ratio: [T; K],
    rounds: u32,
    fields: &mut F,
) -> Result<StepResult<T, K>, Error> {
    let fz = check_positive(input.fz, "fz")?;
    let mu = check_positive(input.mu, "mu")?;
    let pose = input.pose;
    check_finite(pose.dy, "dy")?;
    check_finite(pose.yaw, "yaw")?;
    if !(math::abs(pose.yaw) <= c::<T>(0.1)) {
        return Err(Error::OutOfRange("yaw beyond 0.1 rad"));
    }
    check_finite(pose.roll, "roll")?;
    if !(math::abs(pose.roll) <= c::<T>(0.1)) {
        return Err(Error::OutOfRange("roll beyond 0.1 rad"));
    }
    let h = table.header;
    if h.slots > K || h.strips > ST {
        return Err(Error::OutOfRange(
            "step capacity below the table's slots or strips",
        ));
    }
    let nu = T::from_f64(h.nu);
    let e_star = T::from_f64(h.e_star);
    let mat = Material {
        g: e_star * (T::ONE - nu),
        nu,
        e_star,
    };
    let side = h.side;
    let ks = h.slots;
    let st = h.strips;
    let mut out = StepResult {
        slots: [SlotResult::default(); K],
        vertical_approach: T::ZERO,
        vertical_load: T::ZERO,
    };
    let (f_lo, f_hi) = (T::from_f64(h.f_min), T::from_f64(h.f_max));
    // the pose's trigonometry once per call, by series (no library call)
    let trig = PoseTrig {
        yaw: math::sin_cos_small(pose.yaw),
        roll: math::sin_cos_small(pose.roll),
    };
    let sin_yaw = trig.yaw.0;
    // yaw's effect on the gap, k ψ² per slot field (table "Yaw"), ψ held at 2 YAW_FIT beyond
    let psi_max = c::<T>(2.0 * YAW_FIT);
    let psi = math::clamp(pose.yaw, -psi_max, psi_max);
    let psi2 = psi * psi;
    // 1. the shift interval (the same for every round and balance step) and the roll relative
    // to the table's there: the wheel turns by it about the axle, the contact normal with it
    // (the patch's shape, "sh", at the root of the gap's mapping; its frame, "shf", at the
    // root of the frame's: the node with the rolled pose's wheel point)
    let lz = load_coord(table, fz, true)?;
    let sh = shift(
        table,
        &pose,
        &lz,
        (NodeField::ShiftPerRoll, NodeField::ShiftPerRoll2),
    )?;
    let shf = shift(
        table,
        &pose,
        &lz,
        (NodeField::FrameShiftPerRoll, NodeField::FrameShiftPerRoll2),
    )?;
    let d_roll = pose.roll - shf.roll;
    let (sin_r, cos_r) = math::sin_cos_small(d_roll);
    // the contact angle turns with the wheel: + left, − right (normal (∓ sin δ, cos δ))
    let (d_angle, n_sign) = match side {
        Side::Right => (-d_roll, T::ONE),
        Side::Left => (d_roll, -T::ONE),
    };
    for round in 0..rounds {
        let last = round + 1 == rounds;
        // 2. vertical balance
        let mut f = math::clamp(fz, f_lo, f_hi);
        for _ in 0..BALANCE_STEPS {
            let lc = load_coord(table, f, false)?;
            let (c, cf) = (cell(&sh, &lc), cell(&shf, &lc));
            let mut sum = T::ZERO;
            for (k, r) in ratio.iter().enumerate().take(ks) {
                let o = table.slot_offset(k);
                let share = at_yawed(table, &c, o, SlotField::Share, SlotField::YawShare, psi2);
                // (a slot without a patch here adds exactly 0)
                let ang = angle_yawed(table, &cf, o, psi2) + d_angle;
                sum += share * vertical(side, math::sin_cos_small(ang), *r);
            }
            if !(sum > T::ZERO) {
                return Err(Error::NoContact);
            }
            f = fz / sum;
            if !(f >= f_lo && f <= f_hi) {
                return Err(Error::OutOfRange("load outside the contact table"));
            }
        }
        // 3.–5. slots at F
        // the patch's shape (load share, pmax, area, strips) at the gap's root `c`, its frame
        // (angle, rolling radius, reference point, rail point) at the frame's root `cf`
        let lc = load_coord(table, f, false)?;
        let (c, cf) = (cell(&sh, &lc), cell(&shf, &lc));
        let f13 = math::cbrt(f);
        let f23 = f13 * f13;
        let cz = at_frame(table, &cf, NodeField::CentreHeight as usize);
        let dv = at_frame(table, &c, NodeField::Approach as usize) * f23;
        out.vertical_approach = dv;
        let mut vload = T::ZERO;
        for (k, slot) in out.slots.iter_mut().enumerate().take(ks) {
            let o = table.slot_offset(k);
            let fld = |q: SlotField| at(table, &c, o + q as usize);
            let frm = |q: SlotField| at_frame(table, &cf, o + q as usize);
            let yawed = |v: SlotField, k: SlotField| at_yawed(table, &c, o, v, k, psi2);
            let load = yawed(SlotField::Share, SlotField::YawShare) * f;
            let angle_t = angle_yawed(table, &cf, o, psi2);
            let angle = angle_t + d_angle;
            // 3a. Roll relative to the table's (module docs): the same wheel point, the rail
            // point turned about the rail's centre of curvature, the wheel's arm to it about the
            // axle
            let (y_t, z_t) = (frm(SlotField::YRefTrack), frm(SlotField::ZRefTrack));
            let (ay, az) = (y_t - shf.dy, z_t - cz);
            let (ay, az) = (ay * cos_r - az * sin_r, ay * sin_r + az * cos_r);
            let (s_t, c_t) = math::sin_cos_small(angle_t);
            // sin, cos of angle = angle_t + d_angle, d_angle = −n_sign · d_roll
            let (s_a, c_a) = (
                s_t * cos_r - n_sign * c_t * sin_r,
                c_t * cos_r + n_sign * s_t * sin_r,
            );
            // the rail point at the turned angle: lateral by the table's fit, vertical along the
            // surface (slope −n_sign tan of the mean angle)
            let rail_shift = |q: SlotField| at(table, &cf, o + q as usize);
            let dy_rail = d_angle
                * (rail_shift(SlotField::RailShift) + d_angle * rail_shift(SlotField::RailShift2));
            let z_ref = z_t - dy_rail * n_sign * (s_t + s_a) / (c_t + c_a);
            let cz_k = z_ref - az;
            *slot = SlotResult {
                load,
                angle,
                rolling_radius: frm(SlotField::RollingRadius)
                    + psi2 * frm(SlotField::YawRollingRadius),
                y_ref_rail: frm(SlotField::YRefRail) + side.sign::<T>() * dy_rail,
                x_ref: frm(SlotField::XRef),
                y_ref_track: pose.dy + ay,
                z_ref_track: z_ref,
                pmax: yawed(SlotField::Pmax, SlotField::YawPmax) * f13,
                area: yawed(SlotField::Area, SlotField::YawArea) * f23,
                ..SlotResult::default()
            };
            // A slot without a patch here (or whose strips carry nothing) is evaluated all the
            // same, on stand-in strips under stand-in creepages, and its result discarded: the
            // step's cost does not depend on the number of patches.
            let mut loaded = load > T::ZERO;
            // 4a. Yaw moves the contact point along x (the table is built at yaw 0): the wheel
            // turns about the wheelset centre, x ← x − sin ψ (y_ref − dy), and its contact
            // locus leads by −ψ σ R tan δ (σ = +1 right, −1 left wheel). Measured against the
            // converged geometry (S1002/UIC60, dy 0 … −7.5 mm, ψ ±3 and −10 mrad): the shift is
            // 2.25 mm at 3 mrad, this form within 0.5 % of it; without it η is off by
            // ψ (r_y/R) sin δ, 16 % of η in flange contact.
            let sc = (s_a, c_a);
            let cr = if loaded {
                let lead = match side {
                    Side::Right => slot.rolling_radius * s_a / c_a,
                    Side::Left => -slot.rolling_radius * s_a / c_a,
                };
                let x_ref = slot.x_ref - sin_yaw * (slot.y_ref_track - pose.dy) - pose.yaw * lead;
                slot.x_ref = x_ref;
                let frame = PatchFrame {
                    y_ref_rail: slot.y_ref_rail,
                    z_ref_rail: T::ZERO,
                    y_ref_wheel: T::ZERO,
                    z_ref_wheel: T::ZERO,
                    x_ref,
                    y_ref_track: slot.y_ref_track,
                    z_ref_track: slot.z_ref_track,
                    angle,
                    angle_own: angle,
                    rolling_radius: slot.rolling_radius,
                    weight: T::ZERO,
                    approach_vertical: dv,
                    approach: at_frame(table, &c, o + SlotField::Approach as usize) * f23,
                    overlap_y: [T::ZERO; 2],
                    overlap_s: [T::ZERO; 2],
                    components: 1,
                };
                let cr = creepages_trig(&pose, &trig, side, cz_k, &frame, sc, &input.kinematics)?;
                Creepage {
                    xi: cr.xi,
                    eta: cr.eta,
                    phi: cr.phi,
                }
            } else {
                stand_in_creepage()
            };
            // strips: a, p̂ at F, p̂ rescaled to the slot load
            let (ylo, yhi) = (fld(SlotField::YLo), fld(SlotField::YHi));
            let w = (yhi - ylo) / T::from_usize(st);
            let base = o + SLOT_FIXED;
            let mut strips = [(T::ZERO, T::ZERO); ST];
            let mut sum = T::ZERO;
            for (q, s) in strips.iter_mut().enumerate().take(st) {
                let a = at(table, &c, base + q) * f13;
                let p = at(table, &c, base + st + q) * f13;
                *s = (a, p);
                sum += a * p;
            }
            let carried = T::PI * T::HALF * sum * w;
            loaded = loaded && carried > T::ZERO && w > T::ZERO;
            let scale = if loaded { load / carried } else { T::ZERO };
            let (mut fx, mut fy, mut mz) = (T::ZERO, T::ZERO, T::ZERO);
            // the loaded strips, for the cell fields of the last round (empty: a = 0)
            let mut kept = [Strip::default(); ST];
            // the slot's strips in groups of `fastrip::LANES` side by side (1 on the
            // microcontrollers; on 64-bit hosts a last partial group is completed by stand-ins,
            // discarded): strip q, or a stand-in where it carries nothing
            let mut q0 = 0;
            while q0 < st {
                let mut real = [false; LANES];
                let mut group = [Strip::default(); LANES];
                for (l, (s, r)) in group.iter_mut().zip(real.iter_mut()).enumerate() {
                    let q = q0 + l;
                    if q >= st {
                        *s = stand_in_strip(q);
                        continue;
                    }
                    let (a, p) = strips[q];
                    let g = at(table, &c, base + 2 * st + q);
                    let kc = kalker::coefficients(T::ONE / math::max(g, math::c(1e-3)), nu)?;
                    *r = loaded && a > T::ZERO && p > T::ZERO;
                    *s = if *r {
                        Strip {
                            y: ylo + (T::from_usize(q) + T::HALF) * w,
                            dy: w,
                            a,
                            xc: T::ZERO,
                            p_hat: p * scale,
                            c11: kc.c11,
                            c22: kc.c22,
                            c23: kc.c23,
                            c33: kc.c33,
                            sqrt_b_over_a: math::sqrt(g),
                            ..Strip::default()
                        }
                    } else {
                        stand_in_strip(q)
                    };
                }
                let forces =
                    core::hint::black_box(strip_forces_lanes(&group, &cr, mu, mat.g, mat.nu)?);
                for l in 0..LANES {
                    if real[l] {
                        let (sx, sy, sm) = forces[l];
                        fx += sx;
                        fy += sy;
                        mz += sm;
                        if F::ACTIVE {
                            kept[q0 + l] = group[l];
                        }
                    }
                }
                q0 += LANES;
            }
            if F::ACTIVE && last && loaded {
                fields.slot(k, &kept, load, &cr, mu, &mat, input.kinematics.speed)?;
            }
            if loaded {
                slot.creepage = cr;
                slot.fx = fx;
                slot.fy = fy;
                slot.mz = mz;
                ratio[k] = fy / load;
                vload += load * vertical(side, sc, ratio[k]);
            } else {
                ratio[k] = T::ZERO;
            }
        }
        out.vertical_load = vload;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::frame_weights;

    /// The frame's load weights: a partition of unity that reproduces a quadratic exactly,
    /// interpolates the nodes, and is continuous with a continuous slope across every load node
    /// (no switch at the midpoints between nodes).
    #[test]
    fn frame_weights_are_a_continuous_cubic_through_the_nodes() {
        for n in 2..=7usize {
            let eval = |u: f64, y: &dyn Fn(f64) -> f64| {
                let j = (u.floor() as usize).min(n - 2);
                let (j2, l) = frame_weights(n, j, u - j as f64);
                (0..4)
                    .map(|m| l[m] * if j2 + m < n { y((j2 + m) as f64) } else { 0.0 })
                    .sum::<f64>()
            };
            let quad = |x: f64| 0.3 - 1.7 * x + 0.45 * x * x;
            let max_u = (n - 1) as f64;
            let mut last = eval(0.0, &quad);
            for k in 1..=1000 {
                let u = max_u * k as f64 / 1000.0;
                let j = (u.floor() as usize).min(n - 2);
                let (_, l) = frame_weights(n, j, u - j as f64);
                assert!((l.iter().sum::<f64>() - 1.0).abs() < 1e-12);
                let v = eval(u, &quad);
                // a quadratic is reproduced (linear only with two nodes)
                if n >= 3 {
                    assert!(
                        (v - quad(u)).abs() < 1e-12,
                        "n {n} u {u}: {v} vs {}",
                        quad(u)
                    );
                }
                // continuous: a step of max_u/1000 moves a value of slope below 4 (|−1.7 + 0.9 u|
                // for u ≤ 6) by less than 4 max_u/1000
                assert!((v - last).abs() < 4.0 * max_u / 1000.0, "n {n} u {u}");
                last = v;
            }
            // continuity and slope continuity at interior nodes on data that no quadratic fits,
            // and continuity at the midpoints between nodes (where a quadratic through the three
            // nodes nearest F switched its nodes)
            let rough = |x: f64| [1.0, 4.0, -2.0, 3.0, 0.5, 7.0, -1.0][x as usize];
            for k in 0..n - 1 {
                let u = k as f64 + 0.5;
                let (a, b) = (eval(u - 1e-9, &rough), eval(u + 1e-9, &rough));
                assert!((a - b).abs() < 1e-6, "n {n} midpoint {u}: {a} vs {b}");
            }
            for node in 1..n - 1 {
                let u = node as f64;
                let (a, b) = (eval(u - 1e-9, &rough), eval(u + 1e-9, &rough));
                assert!((a - rough(u)).abs() < 1e-6 && (b - rough(u)).abs() < 1e-6);
                let h = 1e-5;
                let left = (eval(u - h, &rough) - eval(u - 2.0 * h, &rough)) / h;
                let right = (eval(u + 2.0 * h, &rough) - eval(u + h, &rough)) / h;
                if n >= 3 {
                    assert!(
                        (left - right).abs() < 1e-3,
                        "n {n} node {node}: {left} vs {right}"
                    );
                }
            }
        }
    }
}
