//! Contact tables: the per-profile-pair part of the wheel–rail contact, solved once (offline or at
//! start-up) so that the real-time step ([`crate::step`]) only interpolates.
//!
//! # What a table holds
//! For one profile pair, track set-up, side and material, on a grid of lateral shifts dy (the
//! kernel's [`WheelsetPose::dy`], mm, +left) × vertical loads F (N, log-spaced), the converged
//! normal solution of the per-wheel solver ([`crate::wheel::solve_wheel`] with zero creepage, so
//! that Σ_k N_k cos δ_k = F) with every patch in a fixed **slot**:
//! * per node ([`NodeField`]): the wheelset roll used (0, or the two-wheel equilibrium roll of the
//!   shift, [`TableSpec::equilibrium_roll`]), the wheel centre height of the touching position,
//!   the vertical approach δ_v, and the roll mappings' equivalent shifts per roll c₁, c₂ for the
//!   patch's shape and c₁ᶠ, c₂ᶠ for its frame (below);
//! * per slot ([`SlotField`]): the load share N_k/F, the frame (contact angle, rolling radius,
//!   reference point in the track frame and in the rail file, normal approach), pmax/F^{1/3},
//!   area/F^{2/3}, the lateral span [y_lo, y_hi] (contact frame) carrying
//!   [`ST`-many](ContactTable::strips) evenly spaced strips with their half-length a_j/F^{1/3},
//!   peak pressure p̂_j/F^{1/3} and local ellipse ratio n_j/m_j (Ayasse–Chollet), resampled from
//!   the solver's own STRIPES strips, and the rail point's lateral move per change of contact
//!   angle m₁, m₂ (below).
//!
//! The load scalings are Hertz's (a, p ∝ F^{1/3}, area and approach ∝ F^{2/3}), so the stored
//! values vary slowly along the load axis; the step interpolates them linearly in ln F, the frame
//! quadratically.
//!
//! # Slots and continuity
//! Patches are assigned to slots by continuation: nodes are visited dy-major; each patch goes to
//! the slot whose reference point (rail-file y) at the neighbouring node (previous dy, same load,
//! predicted linearly from the two previous shifts — it moves up to ~12 mm per mm of shift on
//! S1002/UIC60; else same dy, previous load) is nearest, within [`crate::wheel::MATCH_MM`],
//! slots continuing a neighbouring node's patch first; a new patch takes a free slot. A slot
//! without a patch at a node has load share 0 and zero strips, and carries the frame of its
//! nearest node with a patch, so that interpolation fades a patch in and out continuously (the
//! load goes to 0, the frame does not jump). Only the slots the pair uses are stored.
//!
//! # The shift grid
//! The shift nodes are explicit and need not be evenly spaced: [`build_table`] starts from
//! [`TableSpec::n_dy`] evenly spaced nodes and bisects an interval while the exact solution at its
//! midpoint differs from the linear interpolation of its end nodes by more than
//! [`TableSpec::refine_tol`], per slot and load, in any of: pmax relative to the node's largest
//! pmax, area relative to the node's total area, load share absolute, and the creep force the
//! frame gives — the interpolated wheel arm and contact angle turned into creepage errors
//! (ξ = 1 + arm/R0, φ = ± sin δ/R0 in nominal rolling) and into a force, the smaller of linear
//! theory (G·C11·A·Δ/(μN), C11 taken as 4, μ = 0.3) and the turn of a saturated force (Δ over the
//! nominal creepage). Intervals are bisected down to the coarse spacing / 2^[`REFINE_DEPTH`],
//! up to [`TableSpec::max_dy_nodes`] nodes in all. The step locates the shift interval by a
//! binary search of a fixed [`DY_HALVINGS`] halvings (any table, any shift).
//!
//! # Roll
//! A wheelset rolled by Δθ from the table's roll turns the wheel about the axle: its profile moves
//! laterally by ≈ r Δθ (r the wheel centre's height above the contact, ≈ 460 mm) and tilts by Δθ
//! (S1002/UIC60, ±5 mrad about the equilibrium roll: the contact moves up to 19 mm and the creep
//! force by up to 150 % of μF_z without a correction). The table maps the rolled pose to the
//! node pose with the same wheel point in contact: that wheel point touches the rail where the
//! rail's contact angle is the node's turned by ∓Δθ (right/left wheel), so the equivalent shift
//! is d = dy + c₁Δθ + c₂Δθ² (≈ r + ρ cos δ per rad, ρ the rail's curvature radius: 760 mm on the
//! UIC60 crown, 480 mm in flange contact). [`build_table`] samples the rail at the angles δ ±
//! [`ROLL_FIT`] around each patch's reference point and fits m₁, m₂ (the rail point's lateral
//! move) and c₁, c₂ (load-share weighted over the slots) exactly there, then limits how fast c₁,
//! c₂ change along the shift ([`ROLL_MONOTONE`]) so that the mapping has one root. The step
//! ([`crate::step`]) finds the root by its shift search, takes the node values there and turns the
//! frame: the contact angle by ∓Δθ, the wheel's arm to the contact about the axle, the rail point
//! along the rail by m₁, m₂.
//!
//! That mapping keeps the gap exactly while the rail under the patch is one circular arc (turning
//! an arc about its centre leaves it unchanged), so it is the patch's **shape** (load share, pmax,
//! area, strips). On the tread (contact angles below 0.25 rad) the builder calibrates it by the
//! solver as it does the frame's (below): the rolled probe's area is met at the node nearest where
//! the slot's area equals it, provided pmax agrees better there too and on the way
//! (`calibrate_roll`). Over the issue-14 sweep the tread's area P95 went from 4.1 to 3.2 % and its
//! pmax maximum from 14.6 to 12.3 %. For a wide, conformal patch across the rail's arcs the rolled
//! contact's weighted reference point sits elsewhere on the wheel: on S1002/UIC60 (1360 mm, left
//! wheel, dy 4.1 mm, 50 kN, roll −4 mrad from equilibrium) the mapped rolling radius was 0.070 mm
//! and the contact angle 5.2 mrad off, enough for 8 % of μF_z in the longitudinal force at low μ.
//! The patch's **frame** (contact angle, rolling radius, reference point, rail point) therefore has
//! a second mapping, [`NodeField::FrameShiftPerRoll`], calibrated by the solver: each row is solved
//! again at ±[`ROLL_FIT`] at the pose the first mapping sends to the node (the roll probe), the
//! node whose wheel angle δ ∓ θ equals the probe contact's is where that pose belongs, and c₁ᶠ, c₂ᶠ
//! go exactly through both (`calibrate_roll`; the first mapping's where the probe's contact is on a
//! part of the wheel that touches at no node, e.g. across a contact jump). On the example at roll
//! −4 mrad the frame's rolling radius is then 0.006 mm off (was 0.070), the angle 0.9 mrad (was
//! 5.2); at −5 mrad, the end of the fitted range, still 0.065 mm and 3.7 mrad. Over the issue-14
//! sweep the tread force's P95 went from 2.5 to 1.3 % of μF_z. The step finds both roots.
//!
//! # Yaw
//! The table is built at yaw 0. A yawed wheel touches the rail with the lowest points of its rows,
//! which lead on the profile's slope; in the track's cross-section it acts as a wheel of profile
//! radius r(1 + ψ² r'²/2): even in ψ, second order, nothing on the tread, up to 0.17 mm across a
//! flange patch at 10 mrad, where the loaded patch turns towards the flank (contact angle +22 mrad,
//! area −9 % at 150 kN). [`build_table`] solves every node again at yaw [`YAW_FIT`] and stores
//! per slot k = (v(ψ) − v(0))/ψ² of the contact angle, load share, rolling radius, pmax and area
//! ([`SlotField::YawAngle`] …); the step adds k ψ². The lead of the contact point along x is the
//! step's (first order, [`crate::step`]).
//!
//! # Bytes (format version [`VERSION`])
//! A table is plain bytes (a rig keeps it in flash and the step reads it in place): a header of
//! [`HEADER_BYTES`] bytes, then the `n_dy` shift nodes (mm, `T`, strictly increasing, the first
//! = dy_min and the last = dy_max of the header), then the payload of `T` values, little-endian,
//! node-major (dy outer, load inner), each node [`NODE_FIXED`] values then `K` slots of
//! [`SLOT_FIXED`] + 3·`ST` values. `K` is the number of slots the profile pair used
//! ([`BuildReport::slots_used`]), not the build's capacity: unused slots are not stored.
//! Header fields, little-endian at fixed offsets: magic `b"WRCTABLE"` (0), version u32 (8),
//! bytes per value u32 (12: 4 = f32, 8 = f64), n_dy u32 (16: shift nodes, the length of the node
//! array), n_load u32 (20), slots K u32 (24), strips ST u32 (28), side u32 (32: 0 left, 1 right),
//! equilibrium roll u32 (36), then f64: dy_min (40), dy_max (48), f_min (56), f_max (64), E* (72),
//! ν (80), back-to-back (88), gauge (96), then u64 checksums (FNV-1a 64): rail profile (104),
//! wheel profile (112), node array and payload (120: every byte after the header).
//! [`ContactTable::from_bytes`] checks every field, the length, the nodes (finite, strictly
//! increasing, ends equal to dy_min and dy_max) and the checksum before use; a wrong, truncated or
//! damaged table is [`Error::BadTable`], never a panic. Tables of format versions 1 (evenly
//! spaced shifts, no node array), 2 (every slot of the build's capacity stored, no roll
//! mapping), 3 (no yaw coefficients) and 4 (one roll mapping for shape and frame) are rejected
//! with [`Error::BadTable`]`("format version 1: rebuild the table")` (resp. `2`, `3`, `4`): rebuild them
//! (`wrc table`), they are derived data.

#![allow(clippy::neg_cmp_op_on_partial_ord)] // NaN must count as "not positive"

use crate::error::{check_finite, check_positive, Error};
use crate::geometry::{equilibrium_roll, Side, TrackSetup, WheelRail, WheelsetPose};
use crate::math;
use crate::patch::Creepage;
use crate::profile::{illinois, ProfileTable};
use crate::wheel::{resolve_patch_strips, solve_wheel, WheelConfig, WheelWorkspace, MATCH_MM};
use crate::{Material, Real};
use core::marker::PhantomData;

/// Format magic.
pub const MAGIC: [u8; 8] = *b"WRCTABLE";
/// Format version of the byte layout.
pub const VERSION: u32 = 5;
/// Most shift nodes of a table.
pub const MAX_DY_NODES: usize = 4096;
/// Halvings of the step's binary search for the shift interval: ⌈log₂ [`MAX_DY_NODES`]⌉, the
/// same for every table and shift.
pub const DY_HALVINGS: u32 = 12;
/// Most bisections of one coarse shift interval by [`build_table`]'s refinement (the finest
/// spacing is the coarse one / 2^`REFINE_DEPTH`).
pub const REFINE_DEPTH: usize = 5;
/// Shift rows of scratch [`build_table`] needs (`ROW_BUFFERS`·`K`·`n_load` [`TableSlot`]s).
pub const ROW_BUFFERS: usize = 3;
/// Header size, bytes.
pub const HEADER_BYTES: usize = 128;
/// Values per node before the slots (see [`NodeField`]).
pub const NODE_FIXED: usize = 7;
/// Values per node and load the build keeps besides the node's ([`NodeField`]): the roll
/// probe's wheel angle, slot, area/F^{2/3} and pmax/F^{1/3} at Δθ = +[`ROLL_FIT`] and
/// −[`ROLL_FIT`] (`calibrate_roll`).
const ROLL_PROBE: usize = 8;
/// A build row's values per load node: the node's and the roll probe's.
const ROW_FIXED: usize = NODE_FIXED + ROLL_PROBE;
/// Values per slot before the strips (see [`SlotField`]).
pub const SLOT_FIXED: usize = 19;
/// Roll offset (rad) at which [`build_table`] samples the rail to fit the roll mapping's
/// quadratics ([`NodeField::ShiftPerRoll`], [`SlotField::RailShift`]): exact at 0 and ±this.
pub const ROLL_FIT: f64 = 0.005;
/// Yaw angle (rad) at which [`build_table`] solves each node again to fit yaw's effect on the gap
/// ([`SlotField::YawAngle`] …), k = (v(ψ) − v(0))/ψ². In the flange patch of
/// [`SlotField::YawAngle`] the solver's change follows ψ² within 5 % from 2.5 to 10 mrad; fitted
/// at 10 mrad instead the issue-14 sweep's worst force was 24.3 % of μF_z (21.7 % at 5 mrad). The
/// step holds ψ at 2 × this (10 mrad, the range measured) beyond.
pub const YAW_FIT: f64 = 0.005;

/// The per-node fixed values, in their order in the payload.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(usize)]
pub enum NodeField {
    /// Wheelset roll of the node, rad (0, or the two-wheel equilibrium roll of its shift).
    Roll = 0,
    /// Wheel centre height at touching, mm (track frame).
    CentreHeight,
    /// Vertical approach δ_v / F^{2/3}, mm·N^{−2/3}.
    Approach,
    /// Equivalent shift per roll c₁, mm/rad: a pose rolled by Δθ from the node's roll touches
    /// with the node's wheel points at the shift dy + c₁ Δθ + c₂ Δθ² (module docs, "Roll");
    /// load-share weighted over the slots (≈ r + ρ cos δ: r the wheel centre's height above the
    /// reference point, ρ the rail's curvature radius there); on the tread calibrated by the
    /// converged solver's area and pmax at roll ±[`ROLL_FIT`] (`calibrate_roll`). The patch's
    /// shape (load share, pmax, area, strips, approach) is read there.
    ShiftPerRoll,
    /// Its quadratic coefficient c₂, mm/rad².
    ShiftPerRoll2,
    /// The frame's equivalent shift per roll c₁ᶠ, mm/rad: the node whose contact has the rolled
    /// pose's wheel point (the same wheel angle δ ∓ θ, so the same rolling radius and contact
    /// angle), calibrated by the converged solver at roll ±[`ROLL_FIT`] (module docs, "Roll";
    /// format version 5). [`NodeField::ShiftPerRoll`] keeps the gap's (the patch's shape).
    FrameShiftPerRoll,
    /// Its quadratic coefficient c₂ᶠ, mm/rad².
    FrameShiftPerRoll2,
}

/// The per-slot fixed values, in their order in the payload.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(usize)]
pub enum SlotField {
    /// N_k / F (dimensionless).
    Share = 0,
    /// Contact angle δ_k, rad.
    Angle,
    /// Rolling radius, mm.
    RollingRadius,
    /// Reference point x in the track frame, mm.
    XRef,
    /// Reference point y in the track frame, mm.
    YRefTrack,
    /// Reference point z in the track frame, mm.
    ZRefTrack,
    /// Reference point y in the rail file, mm.
    YRefRail,
    /// Normal approach / F^{2/3}, mm·N^{−2/3}.
    Approach,
    /// pmax / F^{1/3}, MPa·N^{−1/3}.
    Pmax,
    /// Area / F^{2/3}, mm²·N^{−2/3}.
    Area,
    /// Lower end of the strips' span (contact frame), mm.
    YLo,
    /// Upper end of the strips' span, mm.
    YHi,
    /// Lateral move (track frame, mm) of the rail point whose contact angle is δ + Δδ, per
    /// Δδ: m₁ in Δy = m₁ Δδ + m₂ Δδ², mm/rad (≈ ±ρ cos δ, ρ the rail's curvature radius).
    RailShift,
    /// Its quadratic coefficient m₂, mm/rad².
    RailShift2,
    /// Yaw's effect on the gap: the contact angle at yaw ψ is δ + k ψ², this k (rad/rad²). A yawed
    /// wheel touches the rail with its lowest points, which lead on the profile's slope: in the
    /// track's cross-section it acts as a wheel of profile radius r(y)(1 + ψ² r'(y)²/2), a change
    /// even in ψ and second order, small on the tread but up to 0.17 mm across a flange patch
    /// (r' = tan α up to 2.7), where it turns a loaded patch's angle by up to 22 mrad at 10 mrad
    /// (S1002/UIC60, 1360 mm, left wheel, dy 6.49 mm, F_z 150 kN). Fitted by the builder at yaw [`YAW_FIT`], as the
    /// four that follow (format version 4).
    YawAngle,
    /// The load share's k (N_k/F per rad²; 0 for an absent patch).
    YawShare,
    /// The rolling radius's k, mm/rad².
    YawRollingRadius,
    /// pmax/F^{1/3}'s k (0 for an absent patch).
    YawPmax,
    /// Area/F^{2/3}'s k (0 for an absent patch).
    YawArea,
}

/// The slot values that are 0 where the slot has no patch (it keeps a neighbour's frame for
/// continuity, but carries no load): load share, pmax, area and their yaw coefficients.
const ABSENT_ZERO: [SlotField; 6] = [
    SlotField::Share,
    SlotField::Pmax,
    SlotField::Area,
    SlotField::YawShare,
    SlotField::YawPmax,
    SlotField::YawArea,
];

/// Grid and set-up of a table build.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TableSpec<T> {
    /// Lowest lateral shift, mm (kernel convention: +left).
    pub dy_min: T,
    /// Highest lateral shift, mm.
    pub dy_max: T,
    /// Coarse shift nodes (≥ 2), evenly spaced; [`TableSpec::refine_tol`] adds nodes between them.
    pub n_dy: usize,
    /// Lowest vertical load, N.
    pub f_min: T,
    /// Highest vertical load, N.
    pub f_max: T,
    /// Load nodes (≥ 2), evenly spaced in ln F.
    pub n_load: usize,
    /// Placement grid step, mm (as [`WheelRail::place`]).
    pub grid_step: T,
    /// Build every shift at the two-wheel equilibrium roll ([`equilibrium_roll`], yaw 0) instead
    /// of roll 0.
    pub equilibrium_roll: bool,
    /// Refinement tolerance of the shift grid (module docs; 0: the coarse grid only): an interval
    /// is bisected while its midpoint's pmax, area or load share differs from the interpolation
    /// by more than this (relative to the node's pmax and area, absolute for the share).
    pub refine_tol: T,
    /// Most shift nodes after refinement (≤ [`MAX_DY_NODES`]; below `n_dy`: `n_dy`). Refinement
    /// stops when it is reached (the remaining coarse nodes are always kept).
    pub max_dy_nodes: usize,
}

impl<T: Real> TableSpec<T> {
    /// Vertical load of load node `j` (N): `n_load` nodes log-spaced from `f_min` to `f_max`.
    fn load_node(&self, j: usize) -> T {
        let uj = T::from_usize(j) / T::from_usize(self.n_load - 1);
        math::exp(math::ln(self.f_min) * (T::ONE - uj) + math::ln(self.f_max) * uj)
    }

    /// Most shift nodes a build of this spec can produce: max(`n_dy`, `max_dy_nodes`) when
    /// refining, else `n_dy`.
    pub fn dy_capacity(&self) -> usize {
        if self.refine_tol > T::ZERO {
            self.n_dy.max(self.max_dy_nodes)
        } else {
            self.n_dy
        }
    }

    /// Bytes of output buffer a build of this spec needs with `k` slots of `st` strips
    /// ([`table_bytes`] at [`TableSpec::dy_capacity`] nodes; the table itself is
    /// [`BuildReport::bytes`] long).
    pub fn capacity_bytes(&self, k: usize, st: usize) -> usize {
        table_bytes::<T>(self.dy_capacity(), self.n_load, k, st)
            + self.dy_capacity() * self.n_load * ROLL_PROBE * T::BYTES
    }
}

/// Validated header of a table.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TableHeader {
    /// Bytes per value (4: f32, 8: f64).
    pub value_bytes: usize,
    /// Shift nodes (the length of the node array).
    pub n_dy: usize,
    /// Load nodes.
    pub n_load: usize,
    /// Slots per node.
    pub slots: usize,
    /// Strips per slot.
    pub strips: usize,
    /// Side.
    pub side: Side,
    /// Built at the equilibrium roll.
    pub equilibrium_roll: bool,
    /// Lowest shift, mm.
    pub dy_min: f64,
    /// Highest shift, mm.
    pub dy_max: f64,
    /// Lowest load, N.
    pub f_min: f64,
    /// Highest load, N.
    pub f_max: f64,
    /// Contact modulus E*, MPa.
    pub e_star: f64,
    /// Poisson ratio ν.
    pub nu: f64,
    /// Back-to-back distance, mm.
    pub back_to_back: f64,
    /// Gauge, mm.
    pub gauge: f64,
    /// FNV-1a checksum of the rail profile table.
    pub rail_checksum: u64,
    /// FNV-1a checksum of the wheel profile table.
    pub wheel_checksum: u64,
    /// FNV-1a checksum of the payload.
    pub payload_checksum: u64,
}

impl TableHeader {
    /// Values per node.
    pub fn node_values(&self) -> usize {
        NODE_FIXED + self.slots * (SLOT_FIXED + 3 * self.strips)
    }
    /// Total size of the table, bytes.
    pub fn total_bytes(&self) -> usize {
        HEADER_BYTES
            + self.n_dy * self.value_bytes
            + self.n_dy * self.n_load * self.node_values() * self.value_bytes
    }
}

/// Size in bytes of a table with `n_dy` shift × `n_load` load nodes, `k` slots and `st` strips
/// in precision `T` (header, node array, payload).
pub fn table_bytes<T: Real>(n_dy: usize, n_load: usize, k: usize, st: usize) -> usize {
    HEADER_BYTES
        + n_dy * T::BYTES
        + n_dy * n_load * (NODE_FIXED + k * (SLOT_FIXED + 3 * st)) * T::BYTES
}

/// FNV-1a 64-bit over `bytes`, continuing from `h` (start with [`FNV_OFFSET`]).
pub fn fnv1a(mut h: u64, bytes: &[u8]) -> u64 {
    for &b in bytes {
        h ^= b as u64;
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

/// FNV-1a 64-bit offset basis.
pub const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;

/// Checksum of a profile table: its node count and every node's y, z in f64 bits.
pub fn profile_checksum<T: Real, const N: usize>(p: &ProfileTable<T, N>) -> u64 {
    let mut h = fnv1a(FNV_OFFSET, &(p.len as u64).to_le_bytes());
    for i in 0..p.len.min(N) {
        h = fnv1a(h, &p.y[i].to_f64().to_le_bytes());
        h = fnv1a(h, &p.z[i].to_f64().to_le_bytes());
    }
    h
}

/// A validated contact table borrowed from its bytes (flash, a static, or a host buffer).
#[derive(Clone, Copy, Debug)]
pub struct ContactTable<'a, T> {
    /// The header.
    pub header: TableHeader,
    nodes: &'a [u8],
    payload: &'a [u8],
    node_values: usize,
    _t: PhantomData<T>,
}

fn u32_at(b: &[u8], o: usize) -> u32 {
    let mut w = [0u8; 4];
    w.copy_from_slice(&b[o..o + 4]);
    u32::from_le_bytes(w)
}
fn u64_at(b: &[u8], o: usize) -> u64 {
    let mut w = [0u8; 8];
    w.copy_from_slice(&b[o..o + 8]);
    u64::from_le_bytes(w)
}
fn f64_at(b: &[u8], o: usize) -> f64 {
    f64::from_bits(u64_at(b, o))
}

impl<'a, T: Real> ContactTable<'a, T> {
    /// Validates `bytes` (magic, version, precision = `T`, counts, grid, length, checksum, shift
    /// nodes) and borrows them.
    ///
    /// Errors: [`Error::BadTable`] naming the first check that failed.
    pub fn from_bytes(bytes: &'a [u8]) -> Result<Self, Error> {
        Self::parse(bytes, true)
    }

    /// As [`ContactTable::from_bytes`] but without the checksum and the node check: every header
    /// field and the length are checked (O(1)), the node array and payload are not read. For bytes that were verified
    /// once with [`ContactTable::from_bytes`] (at start-up) and kept unchanged since, so that a
    /// per-step caller (the C interface) need not hash the whole table on every call. A damaged
    /// payload read this way gives wrong numbers, never a panic (reads are bounds-checked).
    ///
    /// Errors: [`Error::BadTable`] naming the first check that failed.
    pub fn from_verified_bytes(bytes: &'a [u8]) -> Result<Self, Error> {
        Self::parse(bytes, false)
    }

    fn parse(bytes: &'a [u8], checksum: bool) -> Result<Self, Error> {
        if bytes.len() < HEADER_BYTES {
            return Err(Error::BadTable("shorter than the header"));
        }
        if bytes[..8] != MAGIC {
            return Err(Error::BadTable("magic"));
        }
        match u32_at(bytes, 8) {
            VERSION => {}
            1 => return Err(Error::BadTable("format version 1: rebuild the table")),
            2 => return Err(Error::BadTable("format version 2: rebuild the table")),
            3 => return Err(Error::BadTable("format version 3: rebuild the table")),
            4 => return Err(Error::BadTable("format version 4: rebuild the table")),
            _ => return Err(Error::BadTable("format version")),
        }
        let vb = u32_at(bytes, 12) as usize;
        if vb != T::BYTES {
            return Err(Error::BadTable("precision differs from the caller's"));
        }
        let h = TableHeader {
            value_bytes: vb,
            n_dy: u32_at(bytes, 16) as usize,
            n_load: u32_at(bytes, 20) as usize,
            slots: u32_at(bytes, 24) as usize,
            strips: u32_at(bytes, 28) as usize,
            side: match u32_at(bytes, 32) {
                0 => Side::Left,
                1 => Side::Right,
                _ => return Err(Error::BadTable("side")),
            },
            equilibrium_roll: match u32_at(bytes, 36) {
                0 => false,
                1 => true,
                _ => return Err(Error::BadTable("roll flag")),
            },
            dy_min: f64_at(bytes, 40),
            dy_max: f64_at(bytes, 48),
            f_min: f64_at(bytes, 56),
            f_max: f64_at(bytes, 64),
            e_star: f64_at(bytes, 72),
            nu: f64_at(bytes, 80),
            back_to_back: f64_at(bytes, 88),
            gauge: f64_at(bytes, 96),
            rail_checksum: u64_at(bytes, 104),
            wheel_checksum: u64_at(bytes, 112),
            payload_checksum: u64_at(bytes, 120),
        };
        let counts_ok = (2..=MAX_DY_NODES).contains(&h.n_dy)
            && (2..=256).contains(&h.n_load)
            && (1..=16).contains(&h.slots)
            && (2..=256).contains(&h.strips);
        if !counts_ok {
            return Err(Error::BadTable("counts"));
        }
        let grid_ok = h.dy_min.is_finite()
            && h.dy_max.is_finite()
            && h.dy_max > h.dy_min
            && h.f_min.is_finite()
            && h.f_max.is_finite()
            && h.f_min > 0.0
            && h.f_max > h.f_min
            && h.e_star.is_finite()
            && h.e_star > 0.0
            && h.nu.is_finite();
        if !grid_ok {
            return Err(Error::BadTable("grid"));
        }
        if bytes.len() != h.total_bytes() {
            return Err(Error::BadTable("length"));
        }
        let (nodes, payload) = bytes[HEADER_BYTES..].split_at(h.n_dy * T::BYTES);
        if checksum && fnv1a(FNV_OFFSET, &bytes[HEADER_BYTES..]) != h.payload_checksum {
            return Err(Error::BadTable("payload checksum"));
        }
        let t = Self {
            header: h,
            nodes,
            payload,
            node_values: h.node_values(),
            _t: PhantomData,
        };
        if checksum {
            // the node array: finite, strictly increasing, from dy_min to dy_max
            let mut last = t.dy_node(0);
            let mut ok = T::is_finite(last) && last == T::from_f64(h.dy_min);
            for i in 1..h.n_dy {
                let d = t.dy_node(i);
                ok &= T::is_finite(d) && d > last;
                last = d;
            }
            if !ok || last != T::from_f64(h.dy_max) {
                return Err(Error::BadTable("shift nodes"));
            }
        }
        Ok(t)
    }

    /// Slots per node.
    pub fn slots(&self) -> usize {
        self.header.slots
    }

    /// Strips per slot.
    pub fn strips(&self) -> usize {
        self.header.strips
    }

    /// Value `v` of node (`i` shift, `j` load). Indices beyond the grid read as 0 (never
    /// reached by the step, which clamps its cell).
    #[inline]
    pub fn value(&self, i: usize, j: usize, v: usize) -> T {
        let n = (i * self.header.n_load + j) * self.node_values + v;
        let o = n * T::BYTES;
        match self.payload.get(o..o + T::BYTES) {
            Some(b) => T::read_le(b),
            None => T::ZERO,
        }
    }

    /// Offset of slot `k`'s first value within a node.
    #[inline]
    pub fn slot_offset(&self, k: usize) -> usize {
        NODE_FIXED + k * (SLOT_FIXED + 3 * self.header.strips)
    }

    /// Shift of node `i`, mm, from the node array (beyond it: 0).
    #[inline]
    pub fn dy_node(&self, i: usize) -> T {
        let o = i * T::BYTES;
        match self.nodes.get(o..o + T::BYTES) {
            Some(b) => T::read_le(b),
            None => T::ZERO,
        }
    }

    /// Load of node `j`, N.
    pub fn load_node(&self, j: usize) -> T {
        let h = &self.header;
        let u = j as f64 / (h.n_load - 1) as f64;
        T::from_f64(libm::exp(
            libm::log(h.f_min) * (1.0 - u) + libm::log(h.f_max) * u,
        ))
    }
}

/// What a table build did.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BuildReport {
    /// Nodes solved (the table's and the refinement's trial midpoints and re-solves).
    pub nodes: usize,
    /// Shift nodes of the table.
    pub dy_nodes: usize,
    /// Nodes whose solve did not meet its tolerances (their result is stored, flagged here).
    pub not_converged: usize,
    /// Most patches seen at one node.
    pub max_patches: usize,
    /// Most slots in use over the table.
    pub slots_used: usize,
    /// Bytes written.
    pub bytes: usize,
}

/// Writer of the payload values of one node.
struct NodeWriter<'b> {
    out: &'b mut [u8],
    pos: usize,
}

impl NodeWriter<'_> {
    fn put<T: Real>(&mut self, x: T) -> Result<(), Error> {
        let end = self.pos + T::BYTES;
        let dst = self
            .out
            .get_mut(self.pos..end)
            .ok_or(Error::BadTable("output buffer too small"))?;
        x.write_le(dst);
        self.pos = end;
        Ok(())
    }
}

/// Scratch slot of a table build (one per slot and load node of a shift row; a build needs
/// [`ROW_BUFFERS`] rows, `ROW_BUFFERS`·`K`·`n_load` of them).
#[derive(Clone, Copy, Debug)]
pub struct TableSlot<T, const ST: usize> {
    present: bool,
    /// The slot's rail-file y at the previous shift node, if it had a patch there (continuation
    /// by linear prediction).
    before: Option<T>,
    fixed: [T; SLOT_FIXED],
    a: [T; ST],
    p: [T; ST],
    g: [T; ST],
}

impl<T: Real, const ST: usize> TableSlot<T, ST> {
    /// Empty scratch slot.
    pub const EMPTY: Self = Self {
        present: false,
        before: None,
        fixed: [T::ZERO; SLOT_FIXED],
        a: [T::ZERO; ST],
        p: [T::ZERO; ST],
        g: [T::ONE; ST],
    };
}

/// Builds the contact table of (`rail`, `wheel`, `setup`, `side`, `mat`) on `spec`'s grid with
/// the solver configuration `cfg` (its pipeline and patch options; its creepage is replaced by
/// zero) into `out`, which must hold at least [`TableSpec::capacity_bytes`] bytes: the table is
/// its first [`BuildReport::bytes`] bytes, the bytes after it up to the capacity are overwritten
/// (build scratch), the rest is left untouched. `K` slots of `ST` strips; `rows` is scratch for
/// [`ROW_BUFFERS`] shift rows of `spec.n_load` nodes (`ROW_BUFFERS`·`K`·`n_load`
/// [`TableSlot`]s: pass at least that many), `ws` the solver's workspace.
///
/// The shift grid: the `n_dy` evenly spaced coarse nodes, each coarse interval bisected while
/// the midpoint's exact solution differs from the interpolation of the interval's ends by more
/// than `spec.refine_tol` (module docs), at most [`REFINE_DEPTH`] levels, up to
/// `spec.max_dy_nodes` nodes. Rows are visited in increasing dy: a trial midpoint is solved
/// with the slots continued from the last accepted row, as the row would be if it were kept.
///
/// Deterministic: the same inputs give the same bytes on every machine with IEEE arithmetic of
/// `T` (the solve is).
///
/// Errors: those of the geometry and the solver at a node (a shift or load where the profiles
/// give no contact is an error: choose the grid inside the profiles' range), `OutOfRange` for
/// a grid that is too small or too large, a negative or NaN tolerance or a row scratch that is
/// too short, `TooManyRegions` when more than `K` slots would be needed, [`Error::BadTable`]
/// when `out` is too small.
#[allow(clippy::too_many_arguments)]
pub fn build_table<
    T: Real,
    const N: usize,
    const M: usize,
    const K: usize,
    const ST: usize,
    const WK: usize,
    const NP: usize,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
>(
    rail: &ProfileTable<T, N>,
    wheel: &ProfileTable<T, N>,
    setup: &TrackSetup<T>,
    side: Side,
    mat: &Material<T>,
    cfg: &WheelConfig<T>,
    spec: &TableSpec<T>,
    rows: &mut [TableSlot<T, ST>],
    ws: &mut WheelWorkspace<T, WK, NP, NS, NR, S, C, SS>,
    out: &mut [u8],
) -> Result<BuildReport, Error> {
    check_finite(spec.dy_min, "dy_min")?;
    check_finite(spec.dy_max, "dy_max")?;
    check_positive(spec.f_min, "f_min")?;
    check_positive(spec.f_max, "f_max")?;
    check_positive(spec.grid_step, "grid_step")?;
    if !(spec.dy_max > spec.dy_min) || !(spec.f_max > spec.f_min) {
        return Err(Error::OutOfRange("table grid"));
    }
    if spec.n_dy < 2 || spec.n_load < 2 || spec.n_dy > MAX_DY_NODES || spec.n_load > 256 {
        return Err(Error::OutOfRange("table node counts"));
    }
    if !(spec.refine_tol >= T::ZERO) || !T::is_finite(spec.refine_tol) {
        return Err(Error::OutOfRange("refine_tol"));
    }
    let cap = spec.dy_capacity();
    if cap > MAX_DY_NODES {
        return Err(Error::OutOfRange("max_dy_nodes"));
    }
    if ST < 2 || K == 0 || K > 16 || ST > 256 {
        return Err(Error::OutOfRange("table slots or strips"));
    }
    let nl = spec.n_load;
    let row = K * nl;
    if rows.len() < ROW_BUFFERS * row {
        return Err(Error::OutOfRange("row scratch"));
    }
    if out.len() < spec.capacity_bytes(K, ST) {
        return Err(Error::BadTable("output buffer too small"));
    }
    let mut c = *cfg;
    c.creepage = Some(Creepage {
        xi: T::ZERO,
        eta: T::ZERO,
        phi: T::ZERO,
    });
    let mut rep = BuildReport::default();
    let (prev, rest) = rows.split_at_mut(row);
    let (cand, rest) = rest.split_at_mut(row);
    let mid = &mut rest[..row];
    for s in prev.iter_mut() {
        *s = TableSlot::EMPTY;
    }
    let node_bytes = (NODE_FIXED + K * (SLOT_FIXED + 3 * ST)) * T::BYTES;
    // rows are written after room for `cap` nodes and moved behind the node array at the end
    let rows_at = HEADER_BYTES + cap * T::BYTES;
    // the roll probes after the rows (TableSpec::capacity_bytes)
    let probe_at = table_bytes::<T>(cap, nl, K, ST);
    let mut geom = WheelRail::<T, N, M>::unplaced(rail, wheel, setup);
    let mut ctx = RowSolve {
        rail,
        wheel,
        setup,
        side,
        mat,
        cfg: &c,
        spec,
        rep: &mut rep,
    };
    // last rail-file y of every slot seen anywhere (slot identity for re-appearing patches)
    let mut last_y: [Option<T>; K] = [None; K];
    let mut fx_c = [[T::ZERO; ROW_FIXED]; 256];
    let mut fx_m = [[T::ZERO; ROW_FIXED]; 256];
    // the creepage criterion's linear-theory force per creepage, over μ = 0.3 (module docs):
    // G·C·A/(μN) with C = 4 (Kalker's C11 ≈ 3.4 … 5), per unit A/N
    let lin = (mat.g * math::c::<T>(4.0 / 0.3), setup.r0);
    let coarse = |i: usize| {
        if i == 0 {
            spec.dy_min
        } else if i + 1 == spec.n_dy {
            spec.dy_max
        } else {
            let u = T::from_usize(i) / T::from_usize(spec.n_dy - 1);
            spec.dy_min + (spec.dy_max - spec.dy_min) * u
        }
    };
    // the first row
    let stats = ctx.row(
        &mut geom,
        ws,
        spec.dy_min,
        prev,
        T::ZERO,
        cand,
        &mut fx_c,
        &mut last_y,
    )?;
    write_row::<T, K, ST>(
        out,
        rows_at,
        node_bytes,
        0,
        spec.dy_min,
        &fx_c,
        cand,
        nl,
        probe_at,
    )?;
    ctx.commit(stats);
    prev.copy_from_slice(cand);
    let mut fx_p = fx_c;
    let mut n = 1usize;
    // shifts of the last two accepted rows (the slots' linear prediction)
    let (mut dl, mut dll) = (spec.dy_min, spec.dy_min);
    let ratio = |d: T, dl: T, dll: T, n: usize| {
        if n >= 2 {
            (d - dl) / (dl - dll)
        } else {
            T::ZERO
        }
    };
    // the finest interval refinement makes: the coarse spacing / 2^REFINE_DEPTH (with room for
    // rounding)
    let finest = (spec.dy_max - spec.dy_min)
        / T::from_usize(spec.n_dy - 1)
        / T::from_usize(1 << REFINE_DEPTH)
        * math::c(1.5);
    // pending right ends: the coarse node, then midpoints (at most REFINE_DEPTH)
    let mut stack = [T::ZERO; REFINE_DEPTH + 1];
    for i in 1..spec.n_dy {
        stack[0] = coarse(i);
        let mut sp = 1usize;
        // whether `cand` holds the row of stack[sp − 1] continued from the accepted row
        let mut cand_ok = false;
        let mut ly_c = last_y;
        let mut st_c = (0, 0);
        while sp > 0 {
            let r = stack[sp - 1];
            if !cand_ok {
                ly_c = last_y;
                st_c = ctx.row(
                    &mut geom,
                    ws,
                    r,
                    prev,
                    ratio(r, dl, dll, n),
                    cand,
                    &mut fx_c,
                    &mut ly_c,
                )?;
            }
            let m = (dl + r) * T::HALF;
            // nodes if m is added: accepted, pending, the coarse ones after i, m
            let room = n + sp + (spec.n_dy - 1 - i) < cap;
            // the interval's depth below its coarse interval (the stack holds pending right
            // ends, not levels: after a midpoint is accepted its right neighbour's interval is
            // as fine as the midpoint's)
            let deep = r - dl <= finest;
            if spec.refine_tol > T::ZERO && sp <= REFINE_DEPTH && !deep && room && m > dl && m < r {
                let mut ly_m = last_y;
                let st_m = ctx.row(
                    &mut geom,
                    ws,
                    m,
                    prev,
                    ratio(m, dl, dll, n),
                    mid,
                    &mut fx_m,
                    &mut ly_m,
                )?;
                let w = (m - dl) / (r - dl);
                let rows = [(&*prev, &fx_p), (&*cand, &fx_c), (&*mid, &fx_m)];
                let loads = (spec.f_min, spec.f_max);
                if interp_error::<T, K, ST>(rows, w, nl, loads, lin) > spec.refine_tol {
                    stack[sp] = m;
                    sp += 1;
                    cand.swap_with_slice(mid);
                    core::mem::swap(&mut fx_c, &mut fx_m);
                    ly_c = ly_m;
                    st_c = st_m;
                    cand_ok = true;
                    continue;
                }
            }
            // accept the candidate row at r
            write_row::<T, K, ST>(out, rows_at, node_bytes, n, r, &fx_c, cand, nl, probe_at)?;
            ctx.commit(st_c);
            last_y = ly_c;
            prev.copy_from_slice(cand);
            fx_p = fx_c;
            dll = dl;
            dl = r;
            n += 1;
            sp -= 1;
            cand_ok = false;
        }
    }
    let body = HEADER_BYTES + n * T::BYTES;
    out.copy_within(rows_at..rows_at + n * nl * node_bytes, body);
    // Slots that were empty at the start of the table (a patch appearing at a later shift) got
    // no frame in their first rows: copy it back from the first row where the slot exists.
    backfill_frames::<T, K, ST>(
        &mut out[body..body + n * nl * node_bytes],
        n,
        nl,
        node_bytes,
    )?;
    // Only the slots used are stored (slots are taken lowest first, so they are 0 … used − 1):
    // every node is moved down to its compact place (never behind its source).
    let used = rep.slots_used.clamp(1, K);
    let compact = (NODE_FIXED + used * (SLOT_FIXED + 3 * ST)) * T::BYTES;
    for q in 1..n * nl {
        out.copy_within(
            body + q * node_bytes..body + q * node_bytes + compact,
            body + q * compact,
        );
    }
    let total = table_bytes::<T>(n, nl, used, ST);
    {
        let (table, rest) = out.split_at_mut(probe_at);
        calibrate_roll::<T>(
            &mut table[HEADER_BYTES..total],
            &rest[..n * nl * ROLL_PROBE * T::BYTES],
            n,
            nl,
            compact,
            ST,
            side,
        );
    }
    limit_roll_slopes::<T>(&mut out[HEADER_BYTES..total], n, nl, compact);
    let checksum = fnv1a(FNV_OFFSET, &out[HEADER_BYTES..total]);
    let hdr = &mut out[..HEADER_BYTES];
    hdr.fill(0);
    hdr[..8].copy_from_slice(&MAGIC);
    let mut put32 = |o: usize, v: u32| hdr[o..o + 4].copy_from_slice(&v.to_le_bytes());
    put32(8, VERSION);
    put32(12, T::BYTES as u32);
    put32(16, n as u32);
    put32(20, nl as u32);
    put32(24, used as u32);
    put32(28, ST as u32);
    put32(32, matches!(side, Side::Right) as u32);
    put32(36, spec.equilibrium_roll as u32);
    let mut put64 = |o: usize, v: u64| hdr[o..o + 8].copy_from_slice(&v.to_le_bytes());
    put64(40, spec.dy_min.to_f64().to_bits());
    put64(48, spec.dy_max.to_f64().to_bits());
    put64(56, spec.f_min.to_f64().to_bits());
    put64(64, spec.f_max.to_f64().to_bits());
    put64(72, mat.e_star.to_f64().to_bits());
    put64(80, mat.nu.to_f64().to_bits());
    put64(88, setup.back_to_back.to_f64().to_bits());
    put64(96, setup.gauge.to_f64().to_bits());
    put64(104, profile_checksum(rail));
    put64(112, profile_checksum(wheel));
    put64(120, checksum);
    rep.bytes = total;
    rep.dy_nodes = n;
    Ok(rep)
}

/// Largest interpolation error of the rows `(l, r, m)` (left end, right end, midpoint, each its
/// slots and node values) at the midpoint's weight `w`, over the loads and slots: pmax relative
/// to the node's largest pmax, area relative to the node's total area, load share absolute, and
/// the creepage criterion (module docs): the creepage error Δ = (|Δa| + √(A/π)|Δ sin δ|)/R0
/// (a = z_ref − cz the wheel's arm to the reference point: ξ = 1 + a/R0 in nominal rolling,
/// φ = ± sin δ/R0) as a force, min(G·C/μ·A/N·Δ, Δ/c₀): linear theory, or a turn of the
/// saturated force by Δ over the nominal creepage c₀ = |1 + a/R0| + √(A/π)|sin δ|/R0; A and N
/// the midpoint slot's area and load, `lin` = (G·C/μ, R0); `loads` = (f_min, f_max) of the
/// log-spaced load nodes.
#[allow(clippy::type_complexity)]
fn interp_error<T: Real, const K: usize, const ST: usize>(
    rows: [(&[TableSlot<T, ST>], &[[T; ROW_FIXED]; 256]); 3],
    w: T,
    nl: usize,
    loads: (T, T),
    lin: (T, T),
) -> T {
    let (lin, r0) = lin;
    let [(l, fl), (r, fr), (m, fm)] = rows;
    let cz = NodeField::CentreHeight as usize;
    let mut e = T::ZERO;
    for j in 0..nl {
        let v = |s: &[TableSlot<T, ST>], k: usize, f: SlotField| s[j * K + k].fixed[f as usize];
        let (mut pref, mut aref) = (T::ZERO, T::ZERO);
        for k in 0..K {
            pref = math::max(pref, v(m, k, SlotField::Pmax));
            aref += v(m, k, SlotField::Area);
        }
        for k in 0..K {
            let d = |f: SlotField| {
                let (a, b) = (v(l, k, f), v(r, k, f));
                math::abs(a + (b - a) * w - v(m, k, f))
            };
            e = math::max(e, d(SlotField::Share));
            if pref > T::ZERO {
                e = math::max(e, d(SlotField::Pmax) / pref);
            }
            if aref > T::ZERO {
                e = math::max(e, d(SlotField::Area) / aref);
            }
            // the creepages the frame gives (the stored area and share are per F^{2/3}, per F)
            let share = v(m, k, SlotField::Share);
            if m[j * K + k].present && share > T::ZERO {
                let arm = |s: &[TableSlot<T, ST>], f: &[[T; ROW_FIXED]; 256]| {
                    v(s, k, SlotField::ZRefTrack) - f[j][cz]
                };
                let (al, ar) = (arm(l, fl), arm(r, fr));
                let d_arm = math::abs(al + (ar - al) * w - arm(m, fm));
                let sin = |s: &[TableSlot<T, ST>]| math::sin(v(s, k, SlotField::Angle));
                let (sl, sr) = (sin(l), sin(r));
                let d_sin = math::abs(sl + (sr - sl) * w - sin(m));
                // A/N = (area F^{2/3})/(share F), √(A/π) = √(area/π) F^{1/3} (the stored area
                // and share are per F^{2/3} and per F)
                let uj = T::from_usize(j) / T::from_usize(nl - 1);
                let f13 = math::cbrt(math::exp(
                    math::ln(loads.0) * (T::ONE - uj) + math::ln(loads.1) * uj,
                ));
                let area = v(m, k, SlotField::Area);
                let sq = math::sqrt(area / T::PI) * f13;
                let delta = (d_arm + sq * d_sin) / r0;
                let c0 = math::abs(T::ONE + arm(m, fm) / r0) + sq * math::abs(sin(m)) / r0;
                let e_lin = lin * area / (share * f13) * delta;
                let e_sat = if c0 > T::ZERO { delta / c0 } else { e_lin };
                e = math::max(e, math::min(e_lin, e_sat));
            }
        }
    }
    e
}

/// Writes shift row `idx` (node dy and the row's `nl` nodes) of a build: the node into the node
/// array, the row at `rows_at` + `idx`·`nl`·`node_bytes`, its roll probe at `probe_at` +
/// `idx`·`nl`·[`ROLL_PROBE`] values.
#[allow(clippy::too_many_arguments)]
fn write_row<T: Real, const K: usize, const ST: usize>(
    out: &mut [u8],
    rows_at: usize,
    node_bytes: usize,
    idx: usize,
    dy: T,
    fixed: &[[T; ROW_FIXED]; 256],
    cur: &[TableSlot<T, ST>],
    nl: usize,
    probe_at: usize,
) -> Result<(), Error> {
    let o = HEADER_BYTES + idx * T::BYTES;
    NodeWriter { out, pos: o }.put(dy)?;
    for j in 0..nl {
        let base = rows_at + (idx * nl + j) * node_bytes;
        let dst = out
            .get_mut(base..base + node_bytes)
            .ok_or(Error::BadTable("output buffer too small"))?;
        let mut w = NodeWriter { out: dst, pos: 0 };
        for &v in &fixed[j][..NODE_FIXED] {
            w.put(v)?;
        }
        for k in 0..K {
            let s = &cur[j * K + k];
            for v in s.fixed {
                w.put(v)?;
            }
            for v in s.a {
                w.put(v)?;
            }
            for v in s.p {
                w.put(v)?;
            }
            for v in s.g {
                w.put(v)?;
            }
        }
    }
    let probe = probe_at + (idx * nl) * ROLL_PROBE * T::BYTES;
    let dst = out
        .get_mut(probe..probe + nl * ROLL_PROBE * T::BYTES)
        .ok_or(Error::BadTable("output buffer too small"))?;
    let mut w = NodeWriter { out: dst, pos: 0 };
    for f in fixed.iter().take(nl) {
        for &v in &f[NODE_FIXED..] {
            w.put(v)?;
        }
    }
    Ok(())
}

/// What one shift row of a build needs besides its scratch.
struct RowSolve<'r, T, const N: usize> {
    rail: &'r ProfileTable<T, N>,
    wheel: &'r ProfileTable<T, N>,
    setup: &'r TrackSetup<T>,
    side: Side,
    mat: &'r Material<T>,
    cfg: &'r WheelConfig<T>,
    spec: &'r TableSpec<T>,
    rep: &'r mut BuildReport,
}

impl<'r, T: Real, const N: usize> RowSolve<'r, T, N> {
    /// Counts an accepted row's (most patches at a node, slots used).
    fn commit(&mut self, (patches, slots): (usize, usize)) {
        self.rep.max_patches = self.rep.max_patches.max(patches);
        self.rep.slots_used = self.rep.slots_used.max(slots);
    }

    /// Solves the row at shift `dy` into `cur` and `fixed`, its slots continued from the
    /// accepted row `prev` (a slot present at `prev` and at the row before it is predicted
    /// linearly: y + (y − y_before)·`ratio`, `ratio` = (dy − dy_prev)/(dy_prev − dy_before)).
    /// Returns (most patches at a node, slots used).
    #[allow(clippy::too_many_arguments)]
    fn row<
        const M: usize,
        const K: usize,
        const ST: usize,
        const WK: usize,
        const NP: usize,
        const NS: usize,
        const NR: usize,
        const S: usize,
        const C: usize,
        const SS: usize,
    >(
        &mut self,
        geom: &mut WheelRail<'r, T, N, M>,
        ws: &mut WheelWorkspace<T, WK, NP, NS, NR, S, C, SS>,
        dy: T,
        prev: &[TableSlot<T, ST>],
        ratio: T,
        cur: &mut [TableSlot<T, ST>],
        fixed: &mut [[T; ROW_FIXED]; 256],
        last_y: &mut [Option<T>; K],
    ) -> Result<(usize, usize), Error> {
        let spec = self.spec;
        let nl = spec.n_load;
        let (rail, wheel, setup, mat, c) = (self.rail, self.wheel, self.setup, self.mat, self.cfg);
        let roll = if spec.equilibrium_roll {
            equilibrium_roll::<T, N, M>(rail, wheel, setup, dy, T::ZERO, spec.grid_step)?.roll
        } else {
            T::ZERO
        };
        let pose = WheelsetPose {
            dy,
            yaw: T::ZERO,
            roll,
        };
        geom.place_in(rail, wheel, setup, &pose, self.side, spec.grid_step)?;
        let (mut max_patches, mut slots_used) = (0usize, 0usize);
        for j in 0..nl {
            let f = spec.load_node(j);
            let res = solve_wheel(geom, f, mat, c, ws, &mut ())?;
            self.rep.nodes += 1;
            if !res.converged {
                self.rep.not_converged += 1;
            }
            max_patches = max_patches.max(res.patches.len());
            let f13 = math::cbrt(f);
            let f23 = f13 * f13;
            fixed[j] = [
                roll,
                geom.wheel.cz,
                res.vertical_approach / f23,
                T::ZERO,
                T::ZERO,
                T::ZERO,
                T::ZERO,
                T::ZERO,
                -T::ONE,
                T::ZERO,
                T::ZERO,
                T::ZERO,
                -T::ONE,
                T::ZERO,
                T::ZERO,
            ];
            // the equivalent shift per roll, load-share weighted over the patches
            let (mut c1_sum, mut c2_sum, mut s_sum) = (T::ZERO, T::ZERO, T::ZERO);
            // candidates: previous shift, same load (predicted linearly from the two previous
            // shifts where the slot had a patch at both: the reference point can move several mm
            // per mm of shift); else same shift, previous load; else last
            let mut cand: [Option<T>; K] = [None; K];
            // whether the candidate continues a patch of the neighbouring node (preferred over a
            // slot's last position elsewhere in the table)
            let mut live = [false; K];
            for k in 0..K {
                let p = &prev[j * K + k];
                live[k] = p.present || (j > 0 && cur[(j - 1) * K + k].present);
                cand[k] = if p.present {
                    let y = p.fixed[SlotField::YRefRail as usize];
                    Some(match p.before {
                        Some(yb) => y + (y - yb) * ratio,
                        None => y,
                    })
                } else if j > 0 && cur[(j - 1) * K + k].present {
                    Some(cur[(j - 1) * K + k].fixed[SlotField::YRefRail as usize])
                } else {
                    last_y[k]
                };
            }
            for s in cur[j * K..(j + 1) * K].iter_mut() {
                *s = TableSlot::EMPTY;
            }
            let mut taken = [false; K];
            for (q, wp) in res.patches.iter().enumerate() {
                if !(wp.load > T::ZERO) {
                    continue;
                }
                let y = wp.frame.y_ref_rail;
                // nearest free candidate within MATCH_MM continuing a neighbouring node's patch,
                // else the nearest within MATCH_MM of a slot's last position, else the first free
                // slot never used, else the first free slot
                let mut best: Option<(usize, T)> = None;
                for want_live in [true, false] {
                    if best.is_some() {
                        break;
                    }
                    for k in 0..K {
                        if taken[k] || live[k] != want_live {
                            continue;
                        }
                        if let Some(yc) = cand[k] {
                            let d = math::abs(yc - y);
                            if d <= math::c(MATCH_MM) && best.is_none_or(|(_, b)| d < b) {
                                best = Some((k, d));
                            }
                        }
                    }
                }
                let k = match best {
                    Some((k, _)) => k,
                    None => (0..K)
                        .find(|&k| !taken[k] && cand[k].is_none())
                        .or_else(|| (0..K).find(|&k| !taken[k]))
                        .ok_or(Error::TooManyRegions)?,
                };
                taken[k] = true;
                last_y[k] = Some(y);
                slots_used = slots_used.max(k + 1);
                let mut slot = TableSlot::EMPTY;
                slot.present = true;
                let pk = &prev[j * K + k];
                slot.before = pk.present.then(|| pk.fixed[SlotField::YRefRail as usize]);
                let fr = &wp.frame;
                slot.fixed[SlotField::Share as usize] = wp.load / f;
                slot.fixed[SlotField::Angle as usize] = fr.angle;
                slot.fixed[SlotField::RollingRadius as usize] = fr.rolling_radius;
                slot.fixed[SlotField::XRef as usize] = fr.x_ref;
                slot.fixed[SlotField::YRefTrack as usize] = fr.y_ref_track;
                slot.fixed[SlotField::ZRefTrack as usize] = fr.z_ref_track;
                slot.fixed[SlotField::YRefRail as usize] = fr.y_ref_rail;
                slot.fixed[SlotField::Approach as usize] = fr.approach / f23;
                slot.fixed[SlotField::Pmax as usize] = wp.result.pmax / f13;
                slot.fixed[SlotField::Area as usize] = wp.result.area / f23;
                // the roll mapping: the rail points at contact angles δ ± h (lateral moves in
                // the track frame, y_T = σ y_S), and the shift that keeps the node's wheel point
                // in contact at roll ± h
                let sigma = self.side.sign::<T>();
                let h = math::c::<T>(ROLL_FIT);
                let y_s = sigma * fr.y_ref_track;
                let m_p = sigma * rail_move(geom, y_s, h);
                let m_m = sigma * rail_move(geom, y_s, -h);
                slot.fixed[SlotField::RailShift as usize] = (m_p - m_m) / (h + h);
                slot.fixed[SlotField::RailShift2 as usize] = (m_p + m_m) / (T::TWO * h * h);
                let (rv, vy) = (geom.wheel.cz - fr.z_ref_track, fr.y_ref_track - dy);
                // the angle turns by −Δθ on the right wheel, +Δθ on the left
                let (m_at_p, m_at_m) = match self.side {
                    Side::Right => (m_m, m_p),
                    Side::Left => (m_p, m_m),
                };
                let g = |m: T, th: T| m - rv * math::sin(th) + vy * (T::ONE - math::cos(th));
                let (g_p, g_m) = (g(m_at_p, h), g(m_at_m, -h));
                let share = wp.load / f;
                c1_sum -= share * (g_p - g_m) / (h + h);
                c2_sum -= share * (g_p + g_m) / (T::TWO * h * h);
                s_sum += share;
                resolve_patch_strips(ws, q, wp.load, mat, c)?;
                resample(&ws.pipeline.set, wp.load, &mut slot)?;
                for v in slot.a.iter_mut() {
                    *v /= f13;
                }
                for v in slot.p.iter_mut() {
                    *v /= f13;
                }
                cur[j * K + k] = slot;
            }
            if s_sum > T::ZERO {
                let (c1, c2) = (c1_sum / s_sum, c2_sum / s_sum);
                fixed[j][NodeField::ShiftPerRoll as usize] = c1;
                fixed[j][NodeField::ShiftPerRoll2 as usize] = c2;
                // the frame's until calibrate_roll finds better
                fixed[j][NodeField::FrameShiftPerRoll as usize] = c1;
                fixed[j][NodeField::FrameShiftPerRoll2 as usize] = c2;
            }
        }
        // yaw's effect on the gap: every load again at yaw YAW_FIT (same shift and roll, zero
        // creepage), each slot's patch matched by its reference point on the rail (nearest within
        // MATCH_MM); a slot without a match, or a row whose yawed solve fails, keeps k = 0
        let psi = math::c::<T>(YAW_FIT);
        let yawed = WheelsetPose { dy, yaw: psi, roll };
        if geom
            .place_in(rail, wheel, setup, &yawed, self.side, spec.grid_step)
            .is_ok()
        {
            let psi2 = psi * psi;
            for j in 0..nl {
                if !cur[j * K..(j + 1) * K].iter().any(|s| s.present) {
                    continue;
                }
                let f = spec.load_node(j);
                let Ok(res) = solve_wheel(geom, f, mat, c, ws, &mut ()) else {
                    continue;
                };
                let f13 = math::cbrt(f);
                let f23 = f13 * f13;
                for k in 0..K {
                    let slot = &mut cur[j * K + k];
                    if !slot.present {
                        continue;
                    }
                    let y = slot.fixed[SlotField::YRefRail as usize];
                    let loaded = res
                        .patches
                        .iter()
                        .map(|wp| (wp.load > T::ZERO).then_some(wp.frame.y_ref_rail));
                    let Some(q) = nearest_within_match(loaded, y) else {
                        continue;
                    };
                    let wp = &res.patches[q];
                    let fx = &mut slot.fixed;
                    let k_of = |v: T, v0: T| (v - v0) / psi2;
                    fx[SlotField::YawAngle as usize] =
                        k_of(wp.frame.angle, fx[SlotField::Angle as usize]);
                    fx[SlotField::YawShare as usize] =
                        k_of(wp.load / f, fx[SlotField::Share as usize]);
                    fx[SlotField::YawRollingRadius as usize] = k_of(
                        wp.frame.rolling_radius,
                        fx[SlotField::RollingRadius as usize],
                    );
                    fx[SlotField::YawPmax as usize] =
                        k_of(wp.result.pmax / f13, fx[SlotField::Pmax as usize]);
                    fx[SlotField::YawArea as usize] =
                        k_of(wp.result.area / f23, fx[SlotField::Area as usize]);
                }
            }
        }
        self.roll_probe::<M, K, ST, WK, NP, NS, NR, S, C, SS>(geom, ws, dy, roll, cur, fixed);
        // empty slots carry the frame of their nearest present node of this row (continuity)
        for k in 0..K {
            for j in 0..nl {
                if cur[j * K + k].present {
                    continue;
                }
                let mut src: Option<usize> = None;
                for dj in 1..nl {
                    if j >= dj && cur[(j - dj) * K + k].present {
                        src = Some(j - dj);
                        break;
                    }
                    if j + dj < nl && cur[(j + dj) * K + k].present {
                        src = Some(j + dj);
                        break;
                    }
                }
                let from = match src {
                    Some(js) => Some(cur[js * K + k]),
                    None if prev[j * K + k].fixed[SlotField::RollingRadius as usize] != T::ZERO => {
                        Some(prev[j * K + k])
                    }
                    None => None,
                };
                if let Some(s) = from {
                    let e = &mut cur[j * K + k];
                    e.fixed = s.fixed;
                    for f in ABSENT_ZERO {
                        e.fixed[f as usize] = T::ZERO;
                    }
                    e.g = s.g;
                }
            }
        }
        Ok((max_patches, slots_used))
    }

    /// The roll probe of a row (`calibrate_roll`): every load again at the rolls `roll` ±
    /// [`ROLL_FIT`], each at the shift the roll mapping's own c₁, c₂ send to this node (dy −
    /// c₁Δθ − c₂Δθ²); the most loaded patch's wheel angle (contact angle less the turn, δ ∓ θ)
    /// and the slot it continues (reference point on the rail nearest the mapped one within
    /// [`MATCH_MM`]) go into `fixed[j][NODE_FIXED..]` as (angle, slot) at +, then at −; a slot of
    /// −1 where the rolled placement or solve fails or no slot matches.
    #[allow(clippy::too_many_arguments)]
    fn roll_probe<
        const M: usize,
        const K: usize,
        const ST: usize,
        const WK: usize,
        const NP: usize,
        const NS: usize,
        const NR: usize,
        const S: usize,
        const C: usize,
        const SS: usize,
    >(
        &mut self,
        geom: &mut WheelRail<'r, T, N, M>,
        ws: &mut WheelWorkspace<T, WK, NP, NS, NR, S, C, SS>,
        dy: T,
        roll: T,
        cur: &[TableSlot<T, ST>],
        fixed: &mut [[T; ROW_FIXED]; 256],
    ) {
        let spec = self.spec;
        let (rail, wheel, setup, mat, c) = (self.rail, self.wheel, self.setup, self.mat, self.cfg);
        let h = math::c::<T>(ROLL_FIT);
        let sigma = self.side.sign::<T>();
        for j in 0..spec.n_load {
            if !cur[j * K..(j + 1) * K].iter().any(|s| s.present) {
                continue;
            }
            let f = spec.load_node(j);
            let f13 = math::cbrt(f);
            let (c1, c2) = (
                fixed[j][NodeField::ShiftPerRoll as usize],
                fixed[j][NodeField::ShiftPerRoll2 as usize],
            );
            for (q, d_roll) in [h, -h].into_iter().enumerate() {
                let pose = WheelsetPose {
                    dy: dy - d_roll * (c1 + c2 * d_roll),
                    yaw: T::ZERO,
                    roll: roll + d_roll,
                };
                if geom
                    .place_in(rail, wheel, setup, &pose, self.side, spec.grid_step)
                    .is_err()
                {
                    continue;
                }
                let Ok(res) = solve_wheel(geom, f, mat, c, ws, &mut ()) else {
                    continue;
                };
                let mut top: Option<usize> = None;
                for (p, wp) in res.patches.iter().enumerate() {
                    if wp.load > T::ZERO && top.is_none_or(|t| wp.load > res.patches[t].load) {
                        top = Some(p);
                    }
                }
                let Some(p) = top else {
                    continue;
                };
                let wp = &res.patches[p];
                // the contact angle turns by −Δθ on the right wheel, +Δθ on the left
                let d_angle = sigma * d_roll;
                // the slots' reference points turned with the wheel (as the step turns them)
                let mapped = cur[j * K..(j + 1) * K].iter().map(|sl| {
                    let fx = &sl.fixed;
                    let dy_rail = d_angle
                        * (fx[SlotField::RailShift as usize]
                            + d_angle * fx[SlotField::RailShift2 as usize]);
                    sl.present
                        .then_some(fx[SlotField::YRefRail as usize] + sigma * dy_rail)
                });
                let best = nearest_within_match(mapped, wp.frame.y_ref_rail);
                if let Some(k) = best {
                    let pr = &mut fixed[j][NODE_FIXED + 4 * q..NODE_FIXED + 4 * q + 4];
                    pr[0] = wp.frame.angle - sigma * pose.roll;
                    pr[1] = T::from_usize(k);
                    pr[2] = wp.result.area / (f13 * f13);
                    pr[3] = wp.result.pmax / f13;
                }
            }
        }
    }
}

/// The index of the candidate reference point (rail-file y, mm; `None`: no candidate) nearest
/// `y` within [`MATCH_MM`], the first of equals: how the builder matches a re-solved patch to a
/// slot (yaw's coefficients, the roll probes).
fn nearest_within_match<T: Real>(ys: impl Iterator<Item = Option<T>>, y: T) -> Option<usize> {
    let mut best: Option<(T, usize)> = None;
    for (i, yc) in ys.enumerate() {
        let Some(yc) = yc else {
            continue;
        };
        let d = math::abs(yc - y);
        if d <= math::c(MATCH_MM) && best.is_none_or(|(b, _)| d < b) {
            best = Some((d, i));
        }
    }
    best.map(|(_, i)| i)
}

/// Shift (mm) within which [`calibrate_roll`] looks for the node whose wheel angle a roll
/// probe's contact has: beyond the largest equivalent shift at [`ROLL_FIT`] (≈ 700 mm/rad · 5
/// mrad on S1002/UIC60).
const CALIBRATE_WINDOW: f64 = 4.0;

/// Calibrates the roll mappings by the solver (module docs, "Roll"): a row's roll probe solved
/// the pose the geometric c₁, c₂ send to node i (dy_i − c₁Δθ − c₂Δθ², roll θ_i ± h).
///
/// - Frame ([`NodeField::FrameShiftPerRoll`]): the node whose wheel angle (δ ∓ θ, in the
///   probe's slot, linear between nodes) equals the probe contact's is where that pose really
///   belongs, d*; the equivalent shift at ±h is then e = d* − (dy_i − c₁Δθ − c₂Δθ²) with Δθ =
///   θ_i ± h − θ(d*), and c₁ᶠ, c₂ᶠ are refitted exactly through both.
/// - Shape ([`NodeField::ShiftPerRoll`], on the tread only: both angles below
///   [`SHAPE_CALIBRATE_ANGLE`]): d* is where the slot's area equals the probe's (ln area linear
///   between nodes), taken only where the misfit |Δ ln area| + |Δ ln pmax| there and at every
///   node between node i and d* is below the geometric mapping's at node i (a pmax peak on the
///   way would be met at other rolls); c₁, c₂ refitted the same way.
///
/// Where either probe failed or no node within [`CALIBRATE_WINDOW`] qualifies (a contact on a
/// part of the wheel that touches at no node of this roll), the geometric coefficients stay.
/// `body` is the node array and payload, `probe` the rows' probes.
#[allow(clippy::too_many_arguments)]
fn calibrate_roll<T: Real>(
    body: &mut [u8],
    probe: &[u8],
    ny: usize,
    nl: usize,
    node_bytes: usize,
    st: usize,
    side: Side,
) {
    let (nodes, payload) = body.split_at_mut(ny * T::BYTES);
    let dy = |i: usize| T::read_le(&nodes[i * T::BYTES..(i + 1) * T::BYTES]);
    let slot_bytes = (SLOT_FIXED + 3 * st) * T::BYTES;
    let node_v = |p: &[u8], i: usize, j: usize, f: NodeField| {
        let o = (i * nl + j) * node_bytes + f as usize * T::BYTES;
        T::read_le(&p[o..o + T::BYTES])
    };
    let slot_v = |p: &[u8], i: usize, j: usize, k: usize, f: SlotField| {
        let o = (i * nl + j) * node_bytes + NODE_FIXED * T::BYTES + k * slot_bytes;
        let o = o + f as usize * T::BYTES;
        T::read_le(&p[o..o + T::BYTES])
    };
    let probe_v = |i: usize, j: usize, m: usize| {
        let o = ((i * nl + j) * ROLL_PROBE + m) * T::BYTES;
        T::read_le(&probe[o..o + T::BYTES])
    };
    let sigma = side.sign::<T>();
    let h = math::c::<T>(ROLL_FIT);
    let window = math::c::<T>(CALIBRATE_WINDOW);
    // the wheel angle of slot k at node i (None where the slot has no patch)
    let wheel_angle = |p: &[u8], i: usize, j: usize, k: usize| {
        (slot_v(p, i, j, k, SlotField::Share) > T::ZERO).then(|| {
            slot_v(p, i, j, k, SlotField::Angle) - sigma * node_v(p, i, j, NodeField::Roll)
        })
    };
    // the shift nearest node i (within the window) where `v` (slot k, linear between nodes)
    // equals `target`: (shift, node roll there, interval, weight)
    let crossing =
        |p: &[u8], i: usize, j: usize, target: T, v: &dyn Fn(&[u8], usize) -> Option<T>| {
            let mut best: Option<(T, T, usize, T)> = None;
            for i0 in 0..ny - 1 {
                let (d0, d1) = (dy(i0), dy(i0 + 1));
                if d1 < dy(i) - window || d0 > dy(i) + window {
                    continue;
                }
                let (Some(a0), Some(a1)) = (v(p, i0), v(p, i0 + 1)) else {
                    continue;
                };
                let (f0, f1) = (a0 - target, a1 - target);
                if (f0 <= T::ZERO) == (f1 <= T::ZERO) && f0 != T::ZERO {
                    continue;
                }
                let u = if f1 != f0 { f0 / (f0 - f1) } else { T::ZERO };
                let d = d0 + (d1 - d0) * u;
                let roll_d = node_v(p, i0, j, NodeField::Roll) * (T::ONE - u)
                    + node_v(p, i0 + 1, j, NodeField::Roll) * u;
                let dist = math::abs(d - dy(i));
                if dist <= window && best.is_none_or(|(b, ..)| dist < math::abs(b - dy(i))) {
                    best = Some((d, roll_d, i0, u));
                }
            }
            best
        };
    for j in 0..nl {
        for i in 0..ny {
            let c1 = node_v(payload, i, j, NodeField::ShiftPerRoll);
            let c2 = node_v(payload, i, j, NodeField::ShiftPerRoll2);
            let th = node_v(payload, i, j, NodeField::Roll);
            // (frame, shape) points (Δθ, e) at +h and −h
            let mut fit: [[Option<(T, T)>; 2]; 2] = [[None; 2]; 2];
            for (q, d_roll) in [h, -h].into_iter().enumerate() {
                let k = probe_v(i, j, 4 * q + 1);
                if !(k >= T::ZERO) {
                    continue;
                }
                let k = k.to_f64() as usize;
                let pose_dy = dy(i) - d_roll * (c1 + c2 * d_roll);
                let alpha = probe_v(i, j, 4 * q);
                let angle = |p: &[u8], i0: usize| wheel_angle(p, i0, j, k);
                if let Some((d, roll_d, ..)) = crossing(payload, i, j, alpha, &angle) {
                    fit[0][q] = Some((th + d_roll - roll_d, d - pose_dy));
                }
                // the shape (tread only): the area's crossing, taken only where pmax agrees
                // better too — the misfit |Δ ln area| + |Δ ln pmax| below the gap mapping's at
                // node i — there and at every node on the way (a pmax peak on the way would be
                // met at other rolls)
                let tread = math::abs(alpha) < math::c(SHAPE_CALIBRATE_ANGLE)
                    && math::abs(slot_v(payload, i, j, k, SlotField::Angle))
                        < math::c(SHAPE_CALIBRATE_ANGLE);
                let (area, pmax) = (probe_v(i, j, 4 * q + 2), probe_v(i, j, 4 * q + 3));
                let ln_of = |m: usize, f: SlotField| {
                    let a = slot_v(payload, m, j, k, f);
                    (a > T::ZERO).then(|| math::ln(a))
                };
                let misfit = |m: usize, la: T, lp: T| {
                    Some(
                        math::abs(ln_of(m, SlotField::Area)? - la)
                            + math::abs(ln_of(m, SlotField::Pmax)? - lp),
                    )
                };
                fit[1][q] = 'shape: {
                    if !(tread && area > T::ZERO && pmax > T::ZERO) {
                        break 'shape None;
                    }
                    let (la, lp) = (math::ln(area), math::ln(pmax));
                    let Some(gap) = misfit(i, la, lp) else {
                        break 'shape None;
                    };
                    let ln_area = |_: &[u8], m: usize| ln_of(m, SlotField::Area);
                    let Some((d, roll_d, i0, u)) = crossing(payload, i, j, la, &ln_area) else {
                        break 'shape None;
                    };
                    let (Some(p0), Some(p1)) =
                        (ln_of(i0, SlotField::Pmax), ln_of(i0 + 1, SlotField::Pmax))
                    else {
                        break 'shape None;
                    };
                    let (lo, hi) = if i0 < i { (i0 + 1, i) } else { (i + 1, i0) };
                    let path =
                        (lo..=hi).all(|m| m == i || misfit(m, la, lp).is_some_and(|e| e <= gap));
                    (path && math::abs(p0 + (p1 - p0) * u - lp) < gap)
                        .then_some((th + d_roll - roll_d, d - pose_dy))
                };
            }
            let fields = [
                (NodeField::FrameShiftPerRoll, NodeField::FrameShiftPerRoll2),
                (NodeField::ShiftPerRoll, NodeField::ShiftPerRoll2),
            ];
            for (pts, (f1, f2)) in fit.into_iter().zip(fields) {
                let [Some((xp, ep)), Some((xm, em))] = pts else {
                    continue;
                };
                // e = c₁ x + c₂ x² through (x₊, e₊) and (x₋, e₋)
                if xp > T::ZERO && xm < T::ZERO {
                    let c2 = (ep / xp - em / xm) / (xp - xm);
                    let c1 = ep / xp - c2 * xp;
                    let o = |f: NodeField| (i * nl + j) * node_bytes + f as usize * T::BYTES;
                    let o1 = o(f1);
                    c1.write_le(&mut payload[o1..o1 + T::BYTES]);
                    let o2 = o(f2);
                    c2.write_le(&mut payload[o2..o2 + T::BYTES]);
                }
            }
        }
    }
}

/// Contact angle (rad) below which `calibrate_roll` calibrates the shape's roll mapping (the
/// node's and the rolled probe's): the tread, where a roll moves the contact along one part of
/// the wheel. At the S1002/UIC60 flange root and flange the probe's area is met across contact
/// jumps, and calibrating there made the issue-14 sweep's flange-root table force P95 5.9 %
/// (3.5 % with the geometric mapping) and its area P95 15 % (10 %). The gate is not sharp: at 0.2
/// and 0.3 rad the sweep's tread and flange-root figures move by at most 0.3 points (tread force
/// max 5.3–5.9 %).
const SHAPE_CALIBRATE_ANGLE: f64 = 0.25;

/// Roll offset (rad) up to which the roll mapping's h(d) = d − dy − c₁Δθ − c₂Δθ² is kept
/// strictly increasing in d (a unique, continuous root): [`build_table`] limits how fast c₁ and c₂
/// may change along the shift (`limit_roll_slopes`).
pub const ROLL_MONOTONE: f64 = 0.006;

/// Limits the change of the roll mapping's coefficients between shift nodes, per load node, to
/// |Δc₁| ≤ 0.45 Δd/[`ROLL_MONOTONE`] and |Δc₂| ≤ 0.45 Δd/[`ROLL_MONOTONE`]², so that h(d)
/// rises by at least a tenth of Δd between nodes for every |Δθ| ≤ [`ROLL_MONOTONE`] (the node
/// roll rises with d and only adds to it); coefficients already within the limit are kept. A
/// jump of c₁ (the reference point crossing from one rail arc to the next, e.g. 475 → 540 mm/rad
/// at the S1002/UIC60 flange root within 0.06 mm) folded h and made the mapping jump between
/// roots. [`ROLL_RELAX`] sweeps move both ends of every pair beyond the limit towards each other
/// (spreading a jump evenly to both sides), then a forward and a backward clamp to the
/// neighbour's ± limit make every pair satisfy it (in place). `body` is the node array and
/// payload, `node_bytes` the stored node size.
fn limit_roll_slopes<T: Real>(body: &mut [u8], ny: usize, nl: usize, node_bytes: usize) {
    let (nodes, payload) = body.split_at_mut(ny * T::BYTES);
    let dy = |i: usize| T::read_le(&nodes[i * T::BYTES..(i + 1) * T::BYTES]);
    let m = math::c::<T>(ROLL_MONOTONE);
    let k = math::c::<T>(0.45);
    for (field, lip) in [
        (NodeField::ShiftPerRoll, k / m),
        (NodeField::ShiftPerRoll2, k / (m * m)),
        (NodeField::FrameShiftPerRoll, k / m),
        (NodeField::FrameShiftPerRoll2, k / (m * m)),
    ] {
        for j in 0..nl {
            let o = |i: usize| (i * nl + j) * node_bytes + field as usize * T::BYTES;
            let get = |p: &[u8], i: usize| T::read_le(&p[o(i)..o(i) + T::BYTES]);
            let put = |p: &mut [u8], i: usize, v: T| v.write_le(&mut p[o(i)..o(i) + T::BYTES]);
            for _ in 0..ROLL_RELAX {
                for i in 1..ny {
                    let step = lip * (dy(i) - dy(i - 1));
                    let (a, b) = (get(payload, i - 1), get(payload, i));
                    let excess = math::abs(b - a) - step;
                    if excess > T::ZERO {
                        let half = if b > a { excess } else { -excess } * T::HALF;
                        put(payload, i - 1, a + half);
                        put(payload, i, b - half);
                    }
                }
            }
            for i in 1..ny {
                let step = lip * (dy(i) - dy(i - 1));
                let prev = get(payload, i - 1);
                put(
                    payload,
                    i,
                    math::clamp(get(payload, i), prev - step, prev + step),
                );
            }
            for i in (0..ny.saturating_sub(1)).rev() {
                let step = lip * (dy(i + 1) - dy(i));
                let next = get(payload, i + 1);
                put(
                    payload,
                    i,
                    math::clamp(get(payload, i), next - step, next + step),
                );
            }
        }
    }
}

/// Symmetric relaxation sweeps of the build's limit on the roll mapping's coefficients
/// ([`ROLL_MONOTONE`]) before its final clamp.
pub const ROLL_RELAX: usize = 64;

/// Lateral move (side frame S, mm) from the rail point at `y_s` to the nearby rail point whose
/// surface angle is larger by `da` (rad): bracketed by node steps (at most 400 nodes either
/// way), then regula falsi. Where the angle is not reached (a straight or concave stretch) the
/// move of a 1000 mm radius (the rail flatter than that counts as that curved).
fn rail_move<T: Real, const N: usize, const M: usize>(
    geom: &WheelRail<'_, T, N, M>,
    y_s: T,
    da: T,
) -> T {
    let rail = &geom.rail;
    let t0 = geom.rail_t_at(y_s);
    let p0 = rail.at(t0);
    let target = p0.angle + da;
    let fallback = {
        // a 1000 mm arc: dy_S = ρ·d(sin α) ≈ ρ cos α · da, sign from the surface's turn
        let sgn = if rail.at(t0 + T::ONE).angle >= p0.angle {
            T::ONE
        } else {
            -T::ONE
        };
        let dy_dt = rail.at(t0 + T::ONE).y - p0.y;
        let dir = if dy_dt >= T::ZERO { T::ONE } else { -T::ONE };
        math::c::<T>(1000.0) * math::cos(p0.angle) * da * sgn * dir
    };
    let len = T::from_usize(rail.table.len.saturating_sub(1));
    // direction of t in which the angle moves towards the target
    let a1 = rail.at(math::min(t0 + T::ONE, len)).angle;
    let up = (a1 >= p0.angle) == (da >= T::ZERO);
    let step = if up { T::ONE } else { -T::ONE };
    let (mut ta, mut fa) = (t0, p0.angle - target);
    for _ in 0..400 {
        let tb = ta + step;
        if !(tb >= T::ZERO && tb <= len) {
            return fallback;
        }
        let fb = rail.at(tb).angle - target;
        if (fa <= T::ZERO) != (fb <= T::ZERO) {
            let u = illinois(
                |u| rail.at(ta + u * (tb - ta)).angle - target,
                fa,
                fb,
                60,
                math::c(1e-12),
            );
            return rail.at(ta + u * (tb - ta)).y - p0.y;
        }
        ta = tb;
        fa = fb;
    }
    fallback
}

/// Copies, for every slot of every node that has no frame yet (all fixed values 0), the frame of
/// the nearest later shift row at the same load where the slot has one.
fn backfill_frames<T: Real, const K: usize, const ST: usize>(
    payload: &mut [u8],
    ny: usize,
    nl: usize,
    node_bytes: usize,
) -> Result<(), Error> {
    let slot_bytes = (SLOT_FIXED + 3 * ST) * T::BYTES;
    let frame_bytes = SLOT_FIXED * T::BYTES;
    let read = |p: &[u8], o: usize| T::read_le(&p[o..o + T::BYTES]);
    for k in 0..K {
        for j in 0..nl {
            for i in 0..ny {
                let at =
                    |i: usize| (i * nl + j) * node_bytes + NODE_FIXED * T::BYTES + k * slot_bytes;
                let o = at(i);
                // rolling radius is > 0 for every frame that was written
                let rr = read(payload, o + SlotField::RollingRadius as usize * T::BYTES);
                if rr != T::ZERO {
                    continue;
                }
                let src = (i + 1..ny).find(|&q| {
                    read(
                        payload,
                        at(q) + SlotField::RollingRadius as usize * T::BYTES,
                    ) != T::ZERO
                });
                if let Some(q) = src {
                    let so = at(q);
                    let mut frame = [0u8; SLOT_FIXED * 8];
                    frame[..frame_bytes].copy_from_slice(&payload[so..so + frame_bytes]);
                    payload[o..o + frame_bytes].copy_from_slice(&frame[..frame_bytes]);
                    let zero = |p: &mut [u8], f: SlotField| {
                        let oo = o + f as usize * T::BYTES;
                        T::ZERO.write_le(&mut p[oo..oo + T::BYTES]);
                    };
                    for f in ABSENT_ZERO {
                        zero(payload, f);
                    }
                    // the ratios n/m too (strips stay empty)
                    let go = o + (SLOT_FIXED + 2 * ST) * T::BYTES;
                    let sgo = so + (SLOT_FIXED + 2 * ST) * T::BYTES;
                    let mut g = [0u8; 256 * 8];
                    let gb = ST * T::BYTES;
                    g[..gb].copy_from_slice(&payload[sgo..sgo + gb]);
                    payload[go..go + gb].copy_from_slice(&g[..gb]);
                }
            }
        }
    }
    Ok(())
}

/// Resamples the solver's strips (`set`, per region evenly spaced) onto `ST` evenly spaced
/// strips over [min y_lo, max y_hi] of the regions: a_j and p̂_j linearly between the strip
/// centres of the region that contains y, going to 0 at the region's ends; outside every region
/// a_j = 0. n/m likewise (held constant beyond the outer centres). p̂ is then scaled so that the
/// strips carry `load`: Σ (π/2) a_j p̂_j δy = N.
fn resample<T: Real, const SS: usize, const NR: usize, const ST: usize>(
    set: &crate::stripes::StripSet<T, SS, NR>,
    load: T,
    slot: &mut TableSlot<T, ST>,
) -> Result<(), Error> {
    let nreg = set.n_regions.min(NR);
    if nreg == 0 {
        return Err(Error::NoContact);
    }
    let mut ylo = T::MAX;
    let mut yhi = -T::MAX;
    for r in &set.regions[..nreg] {
        ylo = math::min(ylo, r.y_lo);
        yhi = math::max(yhi, r.y_hi);
    }
    if !(yhi > ylo) {
        return Err(Error::NoContact);
    }
    slot.fixed[SlotField::YLo as usize] = ylo;
    slot.fixed[SlotField::YHi as usize] = yhi;
    let w = (yhi - ylo) / T::from_usize(ST);
    let mut sum = T::ZERO;
    for q in 0..ST {
        let y = ylo + (T::from_usize(q) + T::HALF) * w;
        let (mut a, mut p, mut g) = (T::ZERO, T::ZERO, T::ONE);
        for r in &set.regions[..nreg] {
            if !(y >= r.y_lo && y <= r.y_hi) || r.count == 0 {
                continue;
            }
            let (f, n) = (r.first, r.count);
            if f + n > set.n_strips.min(SS) {
                return Err(Error::OutOfRange("strip index"));
            }
            // piecewise linear through (y_lo, 0), the centres, (y_hi, 0)
            let lerp = |y0: T, v0: T, y1: T, v1: T| {
                if y1 > y0 {
                    v0 + (v1 - v0) * (y - y0) / (y1 - y0)
                } else {
                    v0
                }
            };
            if y <= set.y[f] {
                a = lerp(r.y_lo, T::ZERO, set.y[f], set.a[f]);
                p = lerp(r.y_lo, T::ZERO, set.y[f], set.pmax[f]);
                g = set.n_over_m[f];
            } else if y >= set.y[f + n - 1] {
                let l = f + n - 1;
                a = lerp(set.y[l], set.a[l], r.y_hi, T::ZERO);
                p = lerp(set.y[l], set.pmax[l], r.y_hi, T::ZERO);
                g = set.n_over_m[l];
            } else {
                for m in f..f + n - 1 {
                    if y >= set.y[m] && y <= set.y[m + 1] {
                        a = lerp(set.y[m], set.a[m], set.y[m + 1], set.a[m + 1]);
                        p = lerp(set.y[m], set.pmax[m], set.y[m + 1], set.pmax[m + 1]);
                        g = lerp(set.y[m], set.n_over_m[m], set.y[m + 1], set.n_over_m[m + 1]);
                        break;
                    }
                }
            }
            break;
        }
        if !(g > T::ZERO) {
            g = T::ONE;
        }
        slot.a[q] = math::max(a, T::ZERO);
        slot.p[q] = math::max(p, T::ZERO);
        slot.g[q] = g;
        sum += slot.a[q] * slot.p[q];
    }
    let strips_load = T::PI * T::HALF * sum * w;
    if !(strips_load > T::ZERO) {
        return Err(Error::GridTooSmall("table strips"));
    }
    let s = load / strips_load;
    for p in slot.p.iter_mut() {
        *p *= s;
    }
    Ok(())
}

/// Writes the f32 copy of the f64 table `src` into `out` (at least [`table_bytes`]`::<f32>` of
/// its grid): the same header with 4 bytes per value, every node and payload value rounded to
/// f32, the checksum recomputed. An f32 table made this way carries the f64 solve rounded once,
/// instead of the solve in f32 ([`build_table`] in f32); the grid (shift nodes included) is the
/// f64 build's. Returns the bytes written.
///
/// Errors: those of [`ContactTable::from_bytes`] for `src` (as f64), [`Error::BadTable`] when
/// `out` is too small.
pub fn narrow_to_f32(src: &[u8], out: &mut [u8]) -> Result<usize, Error> {
    let t = ContactTable::<f64>::from_bytes(src)?;
    let h = t.header;
    let total = table_bytes::<f32>(h.n_dy, h.n_load, h.slots, h.strips);
    let out = out
        .get_mut(..total)
        .ok_or(Error::BadTable("output buffer too small"))?;
    out[..HEADER_BYTES].copy_from_slice(&src[..HEADER_BYTES]);
    out[12..16].copy_from_slice(&4u32.to_le_bytes());
    for (d, s) in out[HEADER_BYTES..]
        .chunks_exact_mut(4)
        .zip(src[HEADER_BYTES..].chunks_exact(8))
    {
        let mut w = [0u8; 8];
        w.copy_from_slice(s);
        d.copy_from_slice(&(f64::from_le_bytes(w) as f32).to_le_bytes());
    }
    let checksum = fnv1a(FNV_OFFSET, &out[HEADER_BYTES..]);
    out[120..128].copy_from_slice(&checksum.to_le_bytes());
    // the rounded nodes must still be a valid grid
    ContactTable::<f32>::from_bytes(out)?;
    Ok(total)
}
