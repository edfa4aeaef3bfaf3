//! One wheel from its wheelset state: geometry → load split over the patches → per-patch pipeline
//! (STRIPES → adaptation → FASTSIM/FaStrip → KTH wear), the way a vehicle-dynamics code calls the
//! kernel every time step.
//!
//! Input: a placed wheel/rail pair ([`WheelRail`]: profiles, track set-up, lateral shift, yaw, roll,
//! side), the **vertical** wheel load F_z (N, along z_T) and the wheelset kinematics (or prescribed
//! creepages). Output: every contact patch with its frame (reference point, contact angle,
//! rolling radius), creepages, normal load, STRIPES/tangential results and wear.
//!
//! This is the kernel's one per-wheel pipeline. [`solve_wheel`] prescribes the **vertical** wheel
//! load, as a vehicle model knows it, and splits it over every patch. [`solve_wheel_normal`] is
//! the same solver in its second load mode: the **normal** load of the main (heaviest) patch is
//! prescribed and only that patch is solved (the set-up of seed A and of single-patch studies).
//!
//! ## What is precomputed, and what a caller redoes
//! * Per profile pair (once, when the profiles change): the [`crate::profile::ProfileTable`]s
//!   (host preprocessing or const data; node positions, tangent angles, curvatures).
//! * Per wheelset pose and side (once per time step and wheel): [`WheelRail::place`] — placed
//!   profiles and the vertical gap on the lateral grid. Redo it whenever the pose, the track
//!   set-up or a profile changes; it borrows the tables, so a profile change needs a new placement.
//! * Per call (inside [`solve_wheel`]): contact patches at each vertical approach of the load
//!   loop (reused when the approach does not change: the first pass of every coupling round and
//!   of the final split), STRIPES, adaptation, FaStrip, wear. The workspace carries nothing
//!   from one call to the next that changes the result (load guesses are reset per call), so
//!   calls are deterministic and independent of their order.
//! * Across time steps (opt-in, [`solve_wheel_warm`]): a small caller-owned [`WheelState`] per
//!   wheel carries the previous call's solution into the next one — see "Warm start" below.
//!
//! ## Example
//! ```no_run
//! use wrc_kernel::geometry::{Side, TrackSetup, WheelRail, WheelsetPose};
//! use wrc_kernel::profile::ProfileTable;
//! use wrc_kernel::wheel::{solve_wheel, DefaultWheelWorkspace, WheelConfig};
//! use wrc_kernel::Material;
//!
//! fn step(
//!     rail: &ProfileTable<f32, 2048>,
//!     wheel: &ProfileTable<f32, 2048>,
//!     ws: &mut DefaultWheelWorkspace<f32>,
//!     dy_mm: f32,
//!     yaw_rad: f32,
//!     fz_n: f32,
//! ) -> Result<(f32, f32), wrc_kernel::Error> {
//!     let pose = WheelsetPose { dy: dy_mm, yaw: yaw_rad, roll: 0.0 };
//!     let geom = WheelRail::<f32, 2048, 2048>::place(
//!         rail, wheel, &TrackSetup::standard(), &pose, Side::Right, 0.05)?;
//!     let mat = Material::<f32>::steel();
//!     let cfg = WheelConfig::recommended(0.3, 55_555.6, 460.0);
//!     let res = solve_wheel(&geom, fz_n, &mat, &cfg, ws, &mut ())?;
//!     let (mut fx, mut fy) = (0.0, 0.0);
//!     for p in &res.patches {
//!         fx += p.result.totals.fx;
//!         fy += p.result.totals.fy;
//!     }
//!     Ok((fx, fy))
//! }
//! ```
//!
//! ## Load split (methods.md §6 item 8, §7.2)
//! All patches share the wheel's rigid vertical displacement δ_v. At a given δ_v the geometry
//! gives each patch its frame and its own normal approach a_k (the interpenetration of its samples,
//! i.e. δ_v projected on the patch normal, including the weighted reference of §7.2 evaluated at
//! that approach — the frame/approach fixed point is thereby solved together with the load).
//! Each patch's normal load N_k is the STRIPES load whose approach equals a_k (STRIPES is
//! load-controlled; the inverse is found by a safeguarded secant on (ln N, ln δ), where the
//! relation is nearly linear, N ∝ δ^{3/2} for Hertz), warm-started per patch from its last solve
//! of the call (its load, approach and local exponent). δ_v then solves
//! **Σ_k N_k(δ_v) cos δ_k = F_z** (the vertical components; the vertical components of the
//! tangential forces are neglected, as in seed A and CONTACT's load control on F_z·n), by the
//! same secant in (ln F, ln δ_v), its exponent kept within 0.5…4 except between two passes on
//! either side of F_z, where it interpolates unclamped (where a region merges the local exponent
//! reaches 8, and the clamped step cycled between two approaches: S1002/UIC60 1360 mm, dy
//! −5.42 mm, 62 kN, `tests/wheel.rs`). Once passes on both sides are known, a secant step out of
//! their bracket, and every step after [`BISECT_AFTER`] passes, bisects the bracket instead: the
//! loop then converges wherever F(δ_v) is continuous, and where it jumps over F_z it ends at the
//! jump, flagged `converged: false` (measured on a STRIPES load jump since removed — 1360 mm, dy
//! ∓6.27 mm, 260 kN, flange contact, 4.5 % within 1e-10 mm of approach: the loop ended 1.6 % above
//! F_z, where the secant alone had wandered up to 8 % off).
//!
//! The vertical load also carries the vertical component of each patch's lateral creep force:
//! with e_y = n × e_x, **F_z = Σ_k (N_k cos δ_k + F_y,k e_y,z)**, e_y,z = −sin δ_k (right wheel),
//! +sin δ_k (left wheel) — at flange contact (δ ≈ 60°, full slip) this term is a third of F_z
//! (CONTACT's A-2.2 right wheel at y_ws = 6.5 mm: N cos δ = 6179 N, F_y sin δ = 3822 N). It is
//! coupled through the ratios r_k = F_y,k/N_k of the previous tangential solve: the load loop
//! solves Σ N_k (cos δ_k + r_k e_y,z) = F_z, the tangential solve updates r_k, until the ratios
//! change by less than 1e-5 (at most [`MAX_COUPLING`] rounds; a fixed point with contraction
//! μ tan δ < 1 in full slip, exact in one round when the ratio is load-independent).
//!
//! Where the tangential solution jumps with the load there is no fixed point: FaStrip and FASTSIM
//! sum over a fixed cell grid, and a cell entering a strip at its leading edge restarts the
//! strip's direction march (S1002/UIC60 1360 mm, dy ±5.3 mm, 62.5 kN, full slip: F_y/N_k
//! −0.04019 → −0.04036 between N_k = 64765.5 and 64766 N). The ratios then alternated between
//! the two sides for every round (a 2-cycle, flagged `converged: false`). When a round changes
//! the ratios by more than half the previous round's change from round 2 on ([`RELAX_AFTER`]),
//! the coupling relaxes: each later round moves the ratios by half the step of the one before
//! (r_k ← r_k + ω(r_k,new − r_k), ω = ½, ¼, …), which ends inside the jump; the vertical balance
//! with the final forces then holds to about N_k |Δr_k| sin δ_k (2.2 N of 62.5 kN there, in 5
//! rounds).
//! A contracting fixed point is never relaxed (its changes shrink by far more than half a round).
//!
//! ## Warm start across time steps ([`solve_wheel_warm`], [`WheelState`])
//! A vehicle-dynamics code or HIL rig calls the solver every time step with a pose and load that
//! change only slightly. [`solve_wheel`] starts every call cold (δ_v = 0.05 mm, load loop exponent
//! 1.5, no load guesses, coupling ratios r_k = 0); [`solve_wheel_warm`] starts from a
//! [`WheelState`] that the previous call of the same wheel left behind:
//! * δ_v starts at the previous δ_v scaled by the load change along the previous local exponent
//!   p of F(δ_v), δ_v,load = δ_v,prev (F_z / F_z,prev)^{1/p}, times the pose's share of the
//!   change extrapolated from the previous call: that call's drift d = ln(δ_v / δ_v,load) per
//!   mm of its lateral-shift increment Δy (when |Δy| > [`DRIFT_DY_MM`]; otherwise d per step),
//!   δ_v = δ_v,load · exp(d/Δy_prev · Δy), the exponent clamped to ±[`MAX_DRIFT`]. A smooth
//!   motion changes δ_v mostly through the pose (on the hunting series below the load-only
//!   start missed F_z by up to 2 %); the drift term leaves the second difference. The first
//!   secant step of the load loop uses p;
//! * the patches found at that δ_v are matched to the previous call's patch slots by the lateral
//!   position of their reference point (`y_ref_rail`, nearest first, each previous slot used
//!   once, at most [`MATCH_MM`] apart; the geometry may reorder, split, merge, add or drop
//!   patches between calls). A matched patch inherits its slot's load, inverse-STRIPES state
//!   (last load, approach and local exponent) and coupling ratio r_k; an unmatched patch starts
//!   cold;
//! * before round 0 the ratios are predicted at the new pose: each patch's load at the warm
//!   δ_v (inverse STRIPES, warm from its slot), all loads scaled by F_z / F(δ_v,warm) (the
//!   balance to first order), and the tangential solve at those loads gives r_k. The pose
//!   change (creepages, contact angle, radius) moves r_k by 3e-5…2e-4 per step on the ramp
//!   below; the prediction leaves mostly < 1e-5 for round 0, so
//! * the coupling loop may stop after round 0 when the ratios are already consistent (every
//!   ratio changes by less than 1e-5 in that round, the same test later rounds use); a cold call
//!   starts from r = 0 and always needs round 1 to see a change;
//! * within a warm call a patch slot asked again for the approach of its last load, bit for bit
//!   (the same patch at the same δ_v: the first pass of every split), returns that load without
//!   a STRIPES solve (a cold call re-solves it, as it always did);
//! * into a sink that takes no cells ([`WheelSink::CELLS`] false, e.g. `()`), a warm call runs
//!   its coupling rounds with the full per-patch pipeline (wear included) instead of the
//!   forces-only one and keeps the results; when the final load split leaves the patches and
//!   every load unchanged, bit for bit, the kept results are the final ones and the patches are
//!   not solved again (the same bits: the same computation on the same inputs). A sink that
//!   takes the cells always gets them from one final solve per patch.
//!
//! Every loop keeps its bound and its tolerance, so a warm result satisfies the same
//! conditions as a cold one and `converged` means the same. The two are different points within
//! those tolerances, not the same bits. The result, and the state left behind, are a pure
//! function of (inputs, state in): a call with a cold state ([`WheelState::new`], or after
//! [`WheelState::reset`]) is bit-identical to [`solve_wheel`]. The state is written only by a
//! successful, converged call; a call that errs or does not converge leaves the state cold, so
//! the next call starts cold.
//!
//! Measured (host, f64, S1002/UIC60 1360 mm right wheel, equilibrium roll, 83.3 kN, μ 0.3,
//! 100 km/h, placement grid 0.05 mm; `cargo run --release -p wrc-bench --example wheel_series`,
//! instructions by callgrind per call as that example's docs say; 2026-12-02, all columns from
//! the same build settings). Median / max per call; "warm before" is the warm start without the
//! drift term and without kept round results (commit 4d9a4f2), "realtime" the warm call with
//! [`WheelConfig::realtime`]:
//!
//! | series | cold | warm before | **warm** | realtime (warm) |
//! |---|---|---|---|---|
//! | ramp: dy −3…6 mm in 0.01–0.05 mm steps, yaw 1.2·dy mrad (301 calls): instructions | 10.73 M / 31.75 M | 5.12 M / 16.20 M | **4.07 M / 15.99 M** | 2.82 M / 9.82 M |
//! | geometry passes · STRIPES solves of the split · coupling rounds | 8/15 · 20/66 · 3/3 | 3/8 · 7/25 · 1/3 | 3/8 · 6/25 · 1/3 | 2/5 · 4/15 · 1/3 |
//! | hunting: dy = 4 sin(2π t/1 s) at 1 kHz, F_z ±10 % (1000 calls): instructions | 8.79 M / 14.19 M | 4.20 M / 11.69 M | **2.96 M / 11.69 M** | 2.39 M / 7.24 M |
//! | geometry passes · STRIPES solves of the split · coupling rounds | 7/9 · 17/25 · 3/3 | 3/7 · 6/17 · 1/3 | 2/7 · 4/17 · 1/3 | 2/4 · 3/10 · 1/3 |
//!
//! (Mean instructions per call, ramp / hunting: cold 11.36 / 8.96 M, warm before 5.74 / 4.37 M,
//! warm 4.53 / 3.38 M, realtime 3.04 / 2.29 M.) The table was measured on commit 77cad77
//! (before the STRIPES default of baa065d). The worst calls are the steps where a contact
//! region appears or splits (a new, cold patch slot: up to 3 coupling rounds and 25 STRIPES
//! solves); they set the worst case to 3.9 × (ramp) and 4.0 × (hunting) the warm median.
//!
//! With the STRIPES default of baa065d (inter-region elastic coupling on, `merge_depth` 0.25;
//! measured on 061784c, same example): ramp cold 11.42 M / 1828 M (mean 53.8 M), warm
//! 4.27 M / 299 M (mean 21.3 M); hunting cold 8.99 M / 96.9 M (mean 11.3 M), warm 3.00 M /
//! 40.1 M (mean 4.23 M). The medians hardly move; the maxima are the steps with a tread and a
//! flange-root region at once (ramp dy 4.5…5.3 mm: host time 20–360 ms per cold call and
//! 10–110 ms per warm one, i.e. roughly 5 ms per coupled STRIPES solve against ≈ 26 µs for one
//! without the coupling; the cold call at dy 5.01 mm takes 28 geometry passes and 136 STRIPES
//! solves), so the worst case is now set by the coupled STRIPES solve, not by the load loop.
//!
//! Warm − cold differences (median / max over the steps, per patch): ramp |ΔF|/(μF_z) 1.1e-7 /
//! 9.0e-7, |ΔN|/F_z 1.7e-7 / 9.6e-7, |Δpmax|/pmax 5.5e-8 / 4.1e-7, |Δarea|/area 1.2e-7 / 4.5e-6,
//! |Δδ_v|/δ_v 1.1e-7 / 7.2e-7; hunting (1000 calls) 5.3e-8 / 7.0e-7, 1.5e-7 / 1.3e-6, 4.9e-8 /
//! 4.6e-7, 1.1e-7 / 8.9e-7, 9.8e-8 / 8.3e-7. Every call converged, warm and cold, with the same
//! patches. These are the differences of two points that each meet the tolerances (1e-6 on the
//! load balance and the approaches, 1e-5 on the coupling ratios); `tests/wheel_warm.rs` derives
//! the bound |ΔF|/(μF_z) ≤ 2.1e-4 from them and asserts it. The warm maxima are the steps
//! where a region appears or splits (a new, cold patch slot).
//!
//! The inner loop (the STRIPES load whose approach equals the patch's geometric approach) is a
//! secant in (ln δ, ln N) safeguarded by the bracket of the root seen so far (false position,
//! Illinois, when the secant leaves it or keeps one end twice): δ(N) is monotone but can be steep
//! over a short load range (S1002/UIC60 1360 mm, 83.3 kN, dy 4.6198633 mm: dδ/dN ×13 over 2 N of
//! 81 kN, where a basin's filter length and the inter-region coupling change quickly), on which the
//! plain secant used up its 16 solves.
//!
//! Bounds: at most [`MAX_OUTER`] geometry passes and [`MAX_INNER`] STRIPES solves per patch and
//! pass; the result reports the passes used and whether both loops met their tolerances
//! (`converged`); a non-converged result is still the last consistent state (finite), flagged.
//! Comparisons are written as `!(x > 0)` on purpose where NaN must count as "not positive".

#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod pipeline;
pub mod step;

use crate::error::{check_positive, Error};
use crate::geometry::{
    contact_patches, creepages, Kinematics, PatchFrame, PatchOptions, Patches, WheelRail,
};
use crate::math;
use crate::patch::{CellOut, CellSink, Creepage};
use crate::pipeline::{
    solve_patch, solve_patch_forces, solve_patch_strip_model, PatchResult, PipelineConfig,
    Workspace,
};
use crate::ritz::{RitzConfig, RitzStrips};
use crate::stripes::StripSample;
use crate::{Material, Real};

/// Maximum geometry passes (outer load loop on δ_v).
pub const MAX_OUTER: u32 = 30;
/// Passes of the load loop after which it bisects the bracket of δ_v instead of taking the
/// secant (the secant converges in 3–8 passes where F(δ_v) is smooth).
pub const BISECT_AFTER: u32 = 12;
/// Maximum STRIPES solves per patch and pass (inverse load control).
pub const MAX_INNER: u32 = 16;
/// Maximum rounds of the normal–tangential coupling through the vertical load (module docs,
/// "Vertical balance": enough for [`RELAX_AFTER`] and then a ratio jump of 1e-3 halved below the
/// 1e-5 test).
pub const MAX_COUPLING: u32 = 12;
/// First coupling round that may start the relaxation (module docs): round 0 starts from r = 0
/// (cold) and round 1 is the first to compare with a previous change.
pub const RELAX_AFTER: u32 = 2;
/// Largest lateral distance (mm, rail profile coordinates) between a patch's reference point and
/// a patch slot of the previous call for [`solve_wheel_warm`] to treat them as the same patch.
/// Between time steps a reference point moves by about the lateral-shift increment (hundredths
/// of a mm at 1 kHz); distinct patches of one wheel lie further apart than their own widths (≥ 5
/// mm on the tread). A wrong match only costs iterations: every loop still converges to its
/// tolerance from the inherited guess.
pub const MATCH_MM: f64 = 3.0;
/// Largest drift |ln(δ_v / δ_v,load)| that [`solve_wheel_warm`] carries into the next call's
/// start (module docs, "Warm start"): 0.25, a 28 % change of δ_v from the pose alone in one
/// step, far beyond what a time step of a smooth motion gives (≤ 2 % on the hunting series).
pub const MAX_DRIFT: f64 = 0.25;
/// Smallest lateral-shift increment (mm) between two warm calls over which [`solve_wheel_warm`]
/// divides the drift of δ_v to carry it per mm of shift (module docs, "Warm start"); below it
/// the drift is carried per step.
pub const DRIFT_DY_MM: f64 = 1e-3;
/// Strips per contact region of [`WheelConfig::realtime`] (the default is 32).
///
/// Measured cost in accuracy (2026-12-02):
/// * FaStrip alone on the Hertzian matrix against TANG (3220 cases,
///   `bench/examples/realtime_grid.rs`), |ΔF|/(μF_n) median / P95 / max: 16 strips × 32 cells
///   0.38 / 4.47 / 13.64 % against 0.43 / 4.46 / 13.75 % with 32 × 32 (the cell count, not the
///   strip count, limits it);
/// * the whole preset (16 strips, tolerance [`REALTIME_TOL`]) run warm along the series of
///   `bench/examples/wheel_series.rs` (module docs) against the default run cold
///   (`wheel_series compare <series> realtime`), per patch, median / max over the steps: ramp
///   |ΔF|/(μF_z) 7.3e-4 / 5.6e-3, |ΔN|/F_z 2.0e-5 / 2.4e-4, |Δpmax|/pmax 2.5e-3 / 0.107,
///   |Δarea|/area 1.9e-3 / 3.8e-2; hunting 1.3e-3 / 5.8e-3, 3.0e-5 / 1.5e-4, 1.7e-3 / 2.9e-2,
///   2.0e-3 / 3.7e-3; the same patches in every step. The force differences are those of the
///   strip count (with 32 strips and tolerance 1e-4 they are ≤ 1.5e-4); the peak pressure of a
///   narrow flange region is the most sensitive figure (the 10.7 % step of the ramp).
///
/// Saving: module docs, "Warm start" (instructions per call).
pub const REALTIME_STRIPS_PER_REGION: usize = 16;
/// Load/approach tolerance of [`WheelConfig::realtime`] (relative; the recommended f64 value is
/// 1e-6). See [`REALTIME_STRIPS_PER_REGION`].
pub const REALTIME_TOL: f64 = 1e-4;

/// Options of [`solve_wheel`].
#[derive(Clone, Copy, Debug)]
pub struct WheelConfig<T> {
    /// The per-patch pipeline.
    pub pipeline: PipelineConfig<T>,
    /// Geometry patch options (reference rule, correspondence, samples per patch, …).
    pub patches: PatchOptions<T>,
    /// Wheelset kinematics for the creepages (ignored where `creepage` is set).
    pub kinematics: Kinematics<T>,
    /// Prescribed creepages for every patch instead of the kinematics (`None`: kinematics).
    pub creepage: Option<Creepage<T>>,
    /// Relative tolerance on the vertical load and on each patch's approach (default 1e-6 in
    /// f64, 1e-3 in f32: f32 geometry resolves track coordinates of ~700 mm to ~5e-5 mm, a few
    /// 1e-4 of a typical approach, so the load found at a given vertical approach is only that
    /// repeatable; the old prescribed-normal-load fixed point stopped at 1e-3 on the approach).
    pub tol: T,
}

impl<T: Real> WheelConfig<T> {
    /// The kernel's defaults: recommended pipeline with friction `mu`, speed `speed` (mm/s),
    /// nominal rolling (Ω = V/R0) with radius `r0` (mm), weighted reference, projection.
    pub fn recommended(mu: T, speed: T, r0: T) -> Self {
        Self {
            pipeline: PipelineConfig::recommended(mu, speed),
            patches: PatchOptions {
                samples: 128,
                ..PatchOptions::default()
            },
            kinematics: Kinematics::nominal(speed, r0),
            creepage: None,
            tol: if T::EPSILON < math::c(1e-10) {
                math::c(1e-6)
            } else {
                math::c(1e-3)
            },
        }
    }

    /// The real-time preset: [`Self::recommended`] with [`REALTIME_STRIPS_PER_REGION`] (16)
    /// strips per contact region instead of [`crate::stripes::DEFAULT_STRIPS_PER_REGION`] (32)
    /// and the load/approach tolerance [`REALTIME_TOL`] (1e-4) where the recommended one is
    /// tighter (f64: 1e-6; f32 keeps its 1e-3); cells per strip, samples per patch and every
    /// model choice unchanged. Measured cost in accuracy and saving: [`REALTIME_STRIPS_PER_REGION`].
    pub fn realtime(mu: T, speed: T, r0: T) -> Self {
        let mut c = Self::recommended(mu, speed, r0);
        c.pipeline.strips_per_region = REALTIME_STRIPS_PER_REGION;
        c.tol = math::max(c.tol, math::c(REALTIME_TOL));
        c
    }
}

/// One patch of the wheel.
#[derive(Clone, Debug, PartialEq)]
pub struct WheelPatch<T, const NR: usize> {
    /// Frame: reference point, contact angle, rolling radius, approach.
    pub frame: PatchFrame<T>,
    /// Creepages used.
    pub creepage: Creepage<T>,
    /// Normal load N_k, N.
    pub load: T,
    /// Pipeline result (regions, forces on the wheel in the patch frame, pmax, area, wear).
    pub result: PatchResult<T, NR>,
}

/// Result of [`solve_wheel`].
#[derive(Clone, Debug, PartialEq)]
pub struct WheelResult<T, const K: usize, const NR: usize> {
    /// The loaded patches, ordered as the geometry orders them (at most `K`).
    pub patches: heapless::Vec<WheelPatch<T, NR>, K>,
    /// Rigid vertical approach δ_v of the wheel, mm.
    pub vertical_approach: T,
    /// Σ N_k cos δ_k reached, N.
    pub vertical_load: T,
    /// Passes of the load loop, over all coupling rounds.
    pub iterations: u32,
    /// [`contact_patches`] evaluations (≤ `iterations`: a pass at the vertical approach of the
    /// previous pass — the first pass of every coupling round and of the final split — reuses
    /// its patches).
    pub geometry_calls: u32,
    /// Normal–tangential coupling rounds used (≤ [`MAX_COUPLING`]).
    pub coupling_rounds: u32,
    /// STRIPES load-control solves of the load split (inverse load control, all passes).
    pub stripes_solves: u32,
    /// Load and approach tolerances met in every loop, and every STRIPES solve converged.
    pub converged: bool,
}

/// Receives the cells of every patch; `begin_patch(k)` announces patch k.
pub trait WheelSink<T>: CellSink<T> {
    /// Whether the sink uses the cells (default `true`). A sink that ignores them (`()`) lets a
    /// warm call ([`solve_wheel_warm`]) keep the full per-patch results of its last coupling
    /// round and skip re-solving the patches at the end when the final load split left every
    /// load unchanged (module docs, "Warm start"); the result is the same, bit for bit.
    const CELLS: bool = true;
    /// Cells that follow belong to patch `k`.
    fn begin_patch(&mut self, _k: usize) {}
}

impl<T> WheelSink<T> for () {
    const CELLS: bool = false;
}

/// Caller-owned storage of [`solve_wheel`] (const-constructible: can live in a `static`).
/// `K` patches of `NP` geometry samples; the pipeline workspace parameters as
/// [`Workspace`].
pub struct WheelWorkspace<
    T,
    const K: usize,
    const NP: usize,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
> {
    /// Geometry patches of the last pass.
    pub patches: Patches<T, K, NP>,
    /// STRIPES samples of one patch.
    pub samples: [StripSample<T>; NP],
    /// The per-patch pipeline workspace.
    pub pipeline: Workspace<T, NS, NR, S, C, SS>,
    loads: [T; K],
    ratio: [T; K],
    /// Warm start of each patch slot's inverse STRIPES solve (valid within one call only).
    inverse: [InverseState<T>; K],
    solves: u32,
    geometry_calls: u32,
    /// Local exponent of F(δ_v) of the last secant step (first step of the next split).
    exponent: T,
    /// δ_v of the patches in `patches` (valid within one `solve_wheel` call only).
    patches_dv: Option<T>,
    /// Warm call: a patch slot asked again for the approach of its last load reuses it.
    reuse: bool,
    /// Per patch: the full pipeline result of the last coupling round and the load it was
    /// solved at (warm calls into a sink without cells only; valid within one call).
    full: [Option<(T, PatchResult<T, NR>)>; K],
}

/// The default wheel workspace: 4 patches of 128 samples, the default pipeline workspace.
pub type DefaultWheelWorkspace<T> = WheelWorkspace<T, 4, 128, 256, 4, 32, 32, 128>;

impl<
        T: Real,
        const K: usize,
        const NP: usize,
        const NS: usize,
        const NR: usize,
        const S: usize,
        const C: usize,
        const SS: usize,
    > WheelWorkspace<T, K, NP, NS, NR, S, C, SS>
{
    /// Empty workspace.
    pub fn new() -> Self {
        Self {
            patches: Patches::new(),
            samples: [StripSample::default(); NP],
            pipeline: Workspace::new(),
            loads: [T::ZERO; K],
            ratio: [T::ZERO; K],
            inverse: [InverseState::cold(); K],
            solves: 0,
            geometry_calls: 0,
            exponent: math::c(1.5),
            patches_dv: None,
            reuse: false,
            full: [const { None }; K],
        }
    }
}

impl<
        T: Real,
        const K: usize,
        const NP: usize,
        const NS: usize,
        const NR: usize,
        const S: usize,
        const C: usize,
        const SS: usize,
    > Default for WheelWorkspace<T, K, NP, NS, NR, S, C, SS>
{
    fn default() -> Self {
        Self::new()
    }
}

/// Re-runs the per-patch pipeline (forces only, creepages of `cfg`) on patch `k` of the geometry
/// that the last [`solve_wheel`] call with this workspace left in `ws.patches`, at normal load
/// `load` (N): afterwards `ws.pipeline.set` holds that patch's STRIPES strips (the contact
/// tables of [`crate::table`] resample them). The same computation as the call's own final
/// solve of that patch, so the same strips.
///
/// Errors: `OutOfRange("patch")` for `k` beyond the patches of the last call, otherwise those of
/// [`solve_patch_forces`].
pub fn resolve_patch_strips<
    T: Real,
    const K: usize,
    const NP: usize,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
>(
    ws: &mut WheelWorkspace<T, K, NP, NS, NR, S, C, SS>,
    k: usize,
    load: T,
    mat: &Material<T>,
    cfg: &WheelConfig<T>,
) -> Result<PatchResult<T, NR>, Error> {
    if k >= ws.patches.len.min(K) {
        return Err(Error::OutOfRange("patch"));
    }
    let n = samples_of(&ws.patches, k, &mut ws.samples);
    let cr = cfg.creepage.unwrap_or(Creepage {
        xi: T::ZERO,
        eta: T::ZERO,
        phi: T::ZERO,
    });
    solve_patch_forces(
        &ws.samples[..n],
        load,
        &cr,
        mat,
        &cfg.pipeline,
        &mut ws.pipeline,
    )
}

/// Fills `out` with the STRIPES samples of patch `k`; returns the count.
fn samples_of<T: Real, const K: usize, const NP: usize>(
    ps: &Patches<T, K, NP>,
    k: usize,
    out: &mut [StripSample<T>; NP],
) -> usize {
    let s = &ps.items[k].samples;
    let n = s.n.min(NP);
    for (i, o) in out.iter_mut().enumerate().take(n) {
        *o = StripSample {
            y: s.s(i),
            dy: s.width[i],
            z: s.f_n[i],
            curv_a: s.a_long[i],
            curv_b: s.b_lat[i],
            xc: s.x_c[i],
        };
    }
    n
}

/// Secant step in log–log coordinates towards `target` for a monotone power-law-like
/// relation y(x): from the points (x0, y0), (x1, y1) (or a single point with exponent `p0`).
/// Returns the next x and the exponent used.
fn loglog_step<T: Real>(x0: T, y0: T, x1: T, y1: T, target: T, p0: T) -> (T, T) {
    let (lx1, ly1) = (math::ln(x1), math::ln(y1));
    let (mut p, mut step_p) = (p0, p0);
    if x0 > T::ZERO && y0 > T::ZERO && x0 != x1 {
        let s = (ly1 - math::ln(y0)) / (lx1 - math::ln(x0));
        // keep the local exponent physical (contact stiffening: between 0.5 and 4) …
        if math::is_finite(s) {
            p = math::clamp(s, math::c(0.5), math::c(4.0));
            // … except between two points on either side of the target: the secant then
            // interpolates, and a locally steeper relation (a region merging: 8 at S1002/UIC60
            // 1360 mm, dy −5.42 mm, 62 kN) does not send the clamped step back and forth
            let brackets = (y0 - target) * (y1 - target) < T::ZERO;
            step_p = if brackets && s > T::ZERO { s } else { p };
        }
    }
    let step = math::clamp(
        (math::ln(target) - ly1) / step_p,
        math::c(-3.0),
        math::c(3.0),
    );
    (x1 * math::exp(step), p)
}

/// Last STRIPES solve of a patch slot: load N (N), its approach δ (mm) and the local exponent
/// d ln N / d ln δ of the last secant (the warm start of the next inverse solve of the slot).
#[derive(Clone, Copy, Debug)]
struct InverseState<T> {
    n: T,
    delta: T,
    exponent: T,
    /// Approach (mm) of the last load returned (0: none) …
    a: T,
    /// … that load (N) …
    n_at_a: T,
    /// … and whether its STRIPES solve converged.
    ok: bool,
}

impl<T: Real> InverseState<T> {
    const fn cold() -> Self {
        InverseState {
            n: T::ZERO,
            delta: T::ZERO,
            exponent: T::ZERO,
            a: T::ZERO,
            n_at_a: T::ZERO,
            ok: false,
        }
    }
}

/// One patch slot of a [`WheelState`].
#[derive(Clone, Copy, Debug)]
struct SlotState<T> {
    /// Reference point of the patch, lateral, rail profile coordinates, mm.
    y_ref: T,
    /// Normal load N_k, N.
    load: T,
    /// Coupling ratio r_k = F_y,k / N_k.
    ratio: T,
    /// Last inverse STRIPES solve of the slot.
    inverse: InverseState<T>,
}

impl<T: Real> SlotState<T> {
    const fn cold() -> Self {
        SlotState {
            y_ref: T::ZERO,
            load: T::ZERO,
            ratio: T::ZERO,
            inverse: InverseState::cold(),
        }
    }
}

/// The solution of one wheel carried from one call of [`solve_wheel_warm`] to the next (see the
/// module docs, "Warm start"): δ_v, the load-loop exponent, the load target, the drift of δ_v
/// with the lateral shift it came with, and per patch slot
/// (up to `K`) the reference point, load, inverse-STRIPES state and coupling ratio.
///
/// Small (a few dozen numbers) and plain data: keep one per wheel, next to the wheel's other
/// simulation states, while the large [`WheelWorkspace`] may be shared by all wheels. A state
/// belongs to one wheel (side, profiles, track set-up): starting another wheel from it is still
/// correct (every loop converges to its tolerances) but no faster.
#[derive(Clone, Copy, Debug)]
pub struct WheelState<T, const K: usize> {
    warm: bool,
    /// Load target of the last call (F_z, or N of the main patch), N.
    target: T,
    /// δ_v of the last call, mm.
    dv: T,
    /// Local exponent d ln F / d ln δ_v of the last secant step of the load loop.
    exponent: T,
    /// ln(δ_v / δ_v,load) of the last call: how far its δ_v moved from the start predicted by
    /// the load change alone (the pose's share of the change), 0 after a cold call.
    drift: T,
    /// Lateral shift of the wheelset (pose `dy`, mm) of the last call.
    pose_dy: T,
    /// d ln δ_v / d(dy) from the last call's drift and shift increment (1/mm), if that
    /// increment was large enough to divide by.
    drift_rate: Option<T>,
    /// Patch slots (`slots[..n]`).
    slots: [SlotState<T>; K],
    n: usize,
}

impl<T: Real, const K: usize> WheelState<T, K> {
    /// A cold state: the next call of [`solve_wheel_warm`] is bit-identical to [`solve_wheel`].
    pub const fn new() -> Self {
        WheelState {
            warm: false,
            target: T::ZERO,
            dv: T::ZERO,
            exponent: T::ZERO,
            drift: T::ZERO,
            pose_dy: T::ZERO,
            drift_rate: None,
            slots: [SlotState::cold(); K],
            n: 0,
        }
    }

    /// Forgets the previous solution (the next call starts cold), e.g. after a jump of the pose
    /// or a profile change.
    pub fn reset(&mut self) {
        *self = Self::new();
    }

    /// Whether the state carries a previous solution (a converged call since the last reset).
    pub fn is_warm(&self) -> bool {
        self.warm
    }

    /// δ_v of the previous call (mm), if warm.
    pub fn vertical_approach(&self) -> Option<T> {
        if self.warm {
            Some(self.dv)
        } else {
            None
        }
    }

    /// Number of patch slots carried.
    pub fn patches(&self) -> usize {
        self.n
    }

    /// Patch slot `k` as (reference point `y_ref_rail` in mm, normal load N_k in N, coupling
    /// ratio F_y,k/N_k), if carried.
    pub fn patch(&self, k: usize) -> Option<(T, T, T)> {
        if self.warm && k < self.n.min(K) {
            let s = &self.slots[k];
            Some((s.y_ref, s.load, s.ratio))
        } else {
            None
        }
    }

    /// δ_v to start from for the target `target`: (start, δ_v,load, load-loop exponent), where
    /// δ_v,load is the previous δ_v scaled by the load change along the exponent and the start
    /// adds the previous call's drift (the pose's share, extrapolated over one step); `None` if
    /// cold or not usable.
    fn start(&self, target: T, pose_dy: T) -> Option<(T, T, T)> {
        if !self.warm {
            return None;
        }
        let p = self.exponent;
        if !(p > T::ZERO) || !(self.dv > T::ZERO) || !(self.target > T::ZERO) {
            return None;
        }
        let p = math::clamp(p, math::c(0.5), math::c(4.0));
        let step = math::clamp(
            math::ln(target / self.target) / p,
            math::c(-3.0),
            math::c(3.0),
        );
        let dv_load = self.dv * math::exp(step);
        let drift = match self.drift_rate {
            Some(r) => r * (pose_dy - self.pose_dy),
            None => self.drift,
        };
        let drift = if math::is_finite(drift) {
            math::clamp(drift, -math::c::<T>(MAX_DRIFT), math::c(MAX_DRIFT))
        } else {
            T::ZERO
        };
        let dv = dv_load * math::exp(drift);
        if dv > T::ZERO && math::is_finite(dv) && dv_load > T::ZERO && math::is_finite(dv_load) {
            Some((dv, dv_load, p))
        } else {
            None
        }
    }
}

impl<T: Real, const K: usize> Default for WheelState<T, K> {
    fn default() -> Self {
        Self::new()
    }
}

/// STRIPES load whose approach equals `a` (mm) on `samples` (relative tolerance `cfg.tol`, then
/// one secant step to `a` itself); returns (load, converged, solves). `state` is the slot's last solve (warm start: the first guess
/// follows the slot's last local exponent from its last point, and that point is the secant's
/// first point); it is updated with every solve. With `reuse` (warm calls only: the cold path
/// keeps its bits), a slot asked again for the approach of its last answer, bit for bit (the
/// same patch at the same δ_v), returns that answer without a solve.
#[allow(clippy::too_many_arguments)]
fn load_for_approach<
    T: Real,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
>(
    samples: &[StripSample<T>],
    a: T,
    guess: T,
    state: &mut InverseState<T>,
    mat: &Material<T>,
    cfg: &WheelConfig<T>,
    ws: &mut Workspace<T, NS, NR, S, C, SS>,
    reuse: bool,
) -> Result<(T, bool, u32), Error> {
    if reuse && state.a == a && state.n_at_a > T::ZERO {
        return Ok((state.n_at_a, state.ok, 0));
    }
    state.a = T::ZERO;
    let warm = state.n > T::ZERO && state.delta > T::ZERO && state.exponent > T::ZERO;
    let (mut n0, mut d0) = if warm {
        (state.n, state.delta)
    } else {
        (T::ZERO, T::ZERO)
    };
    let mut n1 = if warm {
        let step = math::clamp(
            state.exponent * (math::ln(a) - math::ln(state.delta)),
            math::c(-4.0),
            math::c(4.0),
        );
        state.n * math::exp(step)
    } else {
        guess
    };
    // Bracket of the root in (ln N, ln δ − ln a): the largest load seen below the approach and
    // the smallest above it. δ(N) is monotone but can be steep over a short load range (a
    // basin's filter length or its inter-region coupling changing quickly, e.g. S1002/UIC60
    // 1360 mm dy 4.6198633 mm: dδ/dN ×13 over 2 N of 81 kN), where the unsafeguarded secant
    // keeps stepping across it; a secant step outside the bracket is replaced by the
    // false-position step on the bracket (Illinois: the end kept twice has its residual halved).
    let mut lo: Option<(T, T)> = None;
    let mut hi: Option<(T, T)> = None;
    let mut kept_lo = 0u32;
    let mut kept_hi = 0u32;
    for it in 0..MAX_INNER {
        let sol = ws.stripes.solve(samples, n1, mat, &cfg.pipeline.stripes)?;
        let d1 = sol.delta;
        if !(d1 > T::ZERO) || !math::is_finite(d1) {
            return Err(Error::NonFinite("stripes approach"));
        }
        let r1 = math::ln(d1) - math::ln(a);
        if r1 < T::ZERO {
            if lo.is_none_or(|(n, _)| n1 > n) {
                lo = Some((n1, r1));
            }
            kept_hi += 1;
            kept_lo = 0;
        } else {
            if hi.is_none_or(|(n, _)| n1 < n) {
                hi = Some((n1, r1));
            }
            kept_lo += 1;
            kept_hi = 0;
        }
        if math::abs(d1 - a) <= cfg.tol * a {
            state.n = n1;
            state.delta = d1;
            // the load at `a` itself (one more secant step, no solve): N(a) continuous in `a`
            // far below the tolerance, so the load loop on δ_v does not see a staircase
            let (n, p) = loglog_step_inverse(d0, n0, d1, n1, a);
            state.exponent = p;
            state.a = a;
            state.n_at_a = n;
            state.ok = sol.converged;
            return Ok((n, sol.converged, it + 1));
        }
        // N as a function of δ: secant in (ln δ, ln N), exponent 1.5 (Hertz) for the first step.
        let (mut next, p) = loglog_step_inverse(d0, n0, d1, n1, a);
        state.exponent = p;
        if let (Some((nl, rl)), Some((nh, rh))) = (lo, hi) {
            if !(next > nl && next < nh) || kept_lo >= 2 || kept_hi >= 2 {
                let half = |r: T, kept: u32| if kept >= 2 { r * T::HALF } else { r };
                let (rl, rh) = (half(rl, kept_lo), half(rh, kept_hi));
                let (xl, xh) = (math::ln(nl), math::ln(nh));
                let x = if rh > rl {
                    xl - rl * (xh - xl) / (rh - rl)
                } else {
                    T::HALF * (xl + xh)
                };
                next = math::exp(x);
                if !(next > nl && next < nh) {
                    next = math::exp(T::HALF * (xl + xh));
                }
            }
        }
        n0 = n1;
        d0 = d1;
        n1 = next;
    }
    state.n = n0;
    state.delta = d0;
    Ok((n1, false, MAX_INNER))
}

/// The inverse relation N(δ): secant on (ln δ, ln N) from the last two solves, exponent 1.5
/// (Hertz) for the first step.
/// Returns the next load and the exponent used.
fn loglog_step_inverse<T: Real>(d0: T, n0: T, d1: T, n1: T, a: T) -> (T, T) {
    let mut p = math::c::<T>(1.5);
    if d0 > T::ZERO && n0 > T::ZERO && d0 != d1 {
        let s = (math::ln(n1) - math::ln(n0)) / (math::ln(d1) - math::ln(d0));
        if math::is_finite(s) {
            p = math::clamp(s, math::c(0.25), math::c(4.0));
        }
    }
    let step = math::clamp(
        p * (math::ln(a) - math::ln(d1)),
        math::c(-4.0),
        math::c(4.0),
    );
    (n1 * math::exp(step), p)
}

/// e_y,z of a patch: the vertical component of its lateral axis (−sin δ right, +sin δ left).
fn ey_z<T: Real, const N: usize, const M: usize>(geom: &WheelRail<'_, T, N, M>, angle: T) -> T {
    match geom.side {
        crate::geometry::Side::Left => math::sin(angle),
        crate::geometry::Side::Right => -math::sin(angle),
    }
}

/// The load loop: δ_v such that Σ N_k (cos δ_k + r_k e_y,z) = `fz` with the ratios in
/// `ws.ratio`; leaves the patches and loads of the last pass in `ws`. Returns
/// (δ_v, vertical load reached, passes, converged).
fn split_load<
    T: Real,
    const N: usize,
    const M: usize,
    const K: usize,
    const NP: usize,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
>(
    geom: &WheelRail<'_, T, N, M>,
    target: Target<T>,
    dv_start: T,
    mat: &Material<T>,
    cfg: &WheelConfig<T>,
    ws: &mut WheelWorkspace<T, K, NP, NS, NR, S, C, SS>,
) -> Result<(T, T, u32, bool), Error> {
    let (fz, main_only) = match target {
        Target::Vertical(f) => (f, false),
        Target::MainNormal(n) => (n, true),
    };
    let mut dv = dv_start;
    let (mut dv0, mut f0) = (T::ZERO, T::ZERO);
    let mut fsum = T::ZERO;
    // the approaches known to give too little (lo) and too much (hi) vertical load
    let (mut lo, mut hi) = (T::ZERO, T::MAX);
    for pass in 0..MAX_OUTER {
        // the patches depend only on (geom, δ_v, options), fixed within one call
        if ws.patches_dv != Some(dv) {
            ws.patches_dv = None;
            contact_patches(geom, dv, &cfg.patches, &mut ws.patches)?;
            ws.patches_dv = Some(dv);
            ws.geometry_calls += 1;
        }
        fsum = T::ZERO;
        let mut inner_ok = true;
        let np = ws.patches.len.min(K);
        let main = ws.patches.main_index();
        for k in 0..np {
            let frame = ws.patches.items[k].frame;
            let a = frame.approach;
            if main_only && Some(k) != main {
                ws.loads[k] = T::ZERO;
                continue;
            }
            // the previous pass's load of this patch slot is the best first guess
            let guess = if ws.loads[k] > T::ZERO {
                ws.loads[k]
            } else {
                fz
            };
            ws.loads[k] = T::ZERO;
            if !(a > T::ZERO) {
                continue;
            }
            let n = samples_of(&ws.patches, k, &mut ws.samples);
            match load_for_approach(
                &ws.samples[..n],
                a,
                guess,
                &mut ws.inverse[k],
                mat,
                cfg,
                &mut ws.pipeline,
                ws.reuse,
            ) {
                Ok((nk, ok, it)) => {
                    ws.solves += it;
                    ws.loads[k] = nk;
                    inner_ok &= ok;
                    fsum += if main_only {
                        nk
                    } else {
                        nk * (math::cos(frame.angle) + ws.ratio[k] * ey_z(geom, frame.angle))
                    };
                }
                // a sliver of a patch too small for STRIPES carries no load
                Err(Error::NoContact) | Err(Error::GridTooSmall(_)) => {}
                Err(e) => return Err(e),
            }
        }
        if !(fsum > T::ZERO) {
            // not yet in contact (or no upward load): press further
            dv *= T::TWO;
            if dv > math::c(5.0) {
                return Err(Error::NoContact);
            }
            continue;
        }
        if math::abs(fsum - fz) <= cfg.tol * fz {
            return Ok((dv, fsum, pass + 1, inner_ok));
        }
        // first step of a split: the local exponent of the previous split (coupling rounds move
        // the balance only slightly), 1.5 (Hertz) at the start of a call
        let (mut next, p) = loglog_step(dv0, f0, dv, fsum, fz, ws.exponent);
        ws.exponent = p;
        if fsum < fz {
            lo = math::max(lo, dv);
        } else {
            hi = math::min(hi, dv);
        }
        // safeguard: a step out of the bracket, or any step once the secant has had
        // BISECT_AFTER passes, bisects the bracket (geometric mean), so that the loop converges
        // wherever F(δ_v) is continuous and ends at the jump where it is not
        let bracketed = lo > T::ZERO && hi < T::MAX;
        if bracketed && (pass + 1 >= BISECT_AFTER || !(next > lo && next < hi)) {
            next = math::sqrt(lo * hi);
        }
        dv0 = dv;
        f0 = fsum;
        dv = next;
    }
    Ok((dv, fsum, MAX_OUTER, false))
}

/// What the load loop balances.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Target<T> {
    /// Σ_k N_k (cos δ_k + r_k e_y,z) = F_z over all patches.
    Vertical(T),
    /// N of the main (heaviest) patch; other patches carry no load and are not solved.
    MainNormal(T),
}

/// Solves one wheel: finds δ_v with Σ_k (N_k cos δ_k + F_y,k e_y,z) = `fz` (N), then runs the
/// pipeline on every patch, sending its cells to `sink` (after `sink.begin_patch(k)`). See the
/// module docs.
///
/// Errors: `NonPositive("fz")`, `NoContact` when no δ_v up to 5 mm brings the profiles into
/// contact, `OutOfRange(`[`crate::geometry::LOAD_BEYOND_PROFILES`]`)` when the load presses the
/// patch past a profile's end, and the errors of geometry (e.g. `Derailed`), STRIPES and the
/// pipeline.
#[allow(clippy::too_many_arguments)]
pub fn solve_wheel<
    T: Real,
    W: WheelSink<T>,
    const N: usize,
    const M: usize,
    const K: usize,
    const NP: usize,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
>(
    geom: &WheelRail<'_, T, N, M>,
    fz: T,
    mat: &Material<T>,
    cfg: &WheelConfig<T>,
    ws: &mut WheelWorkspace<T, K, NP, NS, NR, S, C, SS>,
    sink: &mut W,
) -> Result<WheelResult<T, K, NR>, Error> {
    check_positive(fz, "fz")?;
    solve(geom, Target::Vertical(fz), mat, cfg, ws, None, sink)
}

/// [`solve_wheel`] with the strip model ([`crate::ritz`]) as the final normal solve of every
/// patch: the load split, the approach and the normal–tangential coupling are
/// [`solve_wheel`]'s (STRIPES), then each patch is solved again at its load and creepages by
/// [`crate::pipeline::solve_patch_strip_model`] on the caller's `rz` (capacity `RN` strips),
/// whose cells go to `sink` and whose result replaces the patch's. `converged` also requires
/// every strip-model solve to converge.
///
/// Why only the final solve: the strip model costs 0.1–1 s per patch on the host (STRIPES'
/// pipeline ≈ 0.3 ms), and what it is for is the distribution of each patch's load (pmax and
/// area against NORM: module docs of [`crate::ritz`]). The load split and the vertical approach
/// stay STRIPES'; each patch's `result.approach` is the strip model's, which can differ from
/// STRIPES' (by more than 20 % on the wide two-basin gap of `tests/ritz_hertz.rs`), so a split
/// driven by it could move load between patches — not yet measured.
///
/// Errors: as [`solve_wheel`] and [`crate::pipeline::solve_patch_strip_model`].
#[allow(clippy::too_many_arguments)]
pub fn solve_wheel_strip_model<
    T: Real,
    W: WheelSink<T>,
    const N: usize,
    const M: usize,
    const K: usize,
    const NP: usize,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
    const RN: usize,
>(
    geom: &WheelRail<'_, T, N, M>,
    fz: T,
    mat: &Material<T>,
    cfg: &WheelConfig<T>,
    rcfg: &RitzConfig<T>,
    ws: &mut WheelWorkspace<T, K, NP, NS, NR, S, C, SS>,
    rz: &mut RitzStrips<T, RN>,
    sink: &mut W,
) -> Result<WheelResult<T, K, NR>, Error> {
    let mut res = solve_wheel(geom, fz, mat, cfg, ws, &mut ())?;
    // the result's patches are the geometry's patches with a positive load, in order
    let np = ws.patches.len.min(K);
    let mut out = 0usize;
    for k in 0..np {
        if !(ws.loads[k] > T::ZERO) {
            continue;
        }
        let Some(wp) = res.patches.get(out) else {
            break;
        };
        let (load, cr) = (wp.load, wp.creepage);
        let n = samples_of(&ws.patches, k, &mut ws.samples);
        sink.begin_patch(out);
        let r = solve_patch_strip_model(
            &ws.samples[..n],
            load,
            &cr,
            mat,
            &cfg.pipeline,
            rcfg,
            &mut ws.pipeline,
            rz,
            &mut Forward(sink),
        )?;
        res.converged &= r.converged;
        res.patches[out].result = r;
        out += 1;
    }
    Ok(res)
}

/// [`solve_wheel`] warm-started from `state`, the solution the previous call of this wheel left
/// behind (module docs, "Warm start"); on return `state` holds this call's solution (or is cold
/// if the call failed or did not converge). With a cold `state` the result is bit-identical to
/// [`solve_wheel`]; with a warm one it agrees with it within the loop tolerances.
///
/// Errors: as [`solve_wheel`].
#[allow(clippy::too_many_arguments)]
pub fn solve_wheel_warm<
    T: Real,
    W: WheelSink<T>,
    const N: usize,
    const M: usize,
    const K: usize,
    const NP: usize,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
>(
    geom: &WheelRail<'_, T, N, M>,
    fz: T,
    mat: &Material<T>,
    cfg: &WheelConfig<T>,
    ws: &mut WheelWorkspace<T, K, NP, NS, NR, S, C, SS>,
    state: &mut WheelState<T, K>,
    sink: &mut W,
) -> Result<WheelResult<T, K, NR>, Error> {
    let out = match check_positive(fz, "fz") {
        Ok(_) => solve(geom, Target::Vertical(fz), mat, cfg, ws, Some(state), sink),
        Err(e) => Err(e),
    };
    if !matches!(out, Ok(ref r) if r.converged) {
        state.reset();
    }
    out
}

/// The second load mode of the per-wheel solver: the **normal** load `n` (N) of the main
/// (heaviest-weight) patch is prescribed; its frame and approach are solved together with the
/// load (the main patch's STRIPES approach equals its geometric approach at the vertical approach
/// found), and only that patch is solved (`res.patches.len() == 1`; other patches the geometry
/// finds carry no load — `ws.patches.len` tells how many there were). No normal–tangential coupling (the normal
/// load is given): `coupling_rounds` is 1. `vertical_load` reports N cos δ of the main patch.
///
/// Errors: `NonPositive("N")`, otherwise as [`solve_wheel`].
#[allow(clippy::too_many_arguments)]
pub fn solve_wheel_normal<
    T: Real,
    W: WheelSink<T>,
    const N: usize,
    const M: usize,
    const K: usize,
    const NP: usize,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
>(
    geom: &WheelRail<'_, T, N, M>,
    n: T,
    mat: &Material<T>,
    cfg: &WheelConfig<T>,
    ws: &mut WheelWorkspace<T, K, NP, NS, NR, S, C, SS>,
    sink: &mut W,
) -> Result<WheelResult<T, K, NR>, Error> {
    check_positive(n, "N")?;
    solve(geom, Target::MainNormal(n), mat, cfg, ws, None, sink)
}

#[allow(clippy::too_many_arguments)]
fn solve<
    T: Real,
    W: WheelSink<T>,
    const N: usize,
    const M: usize,
    const K: usize,
    const NP: usize,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
>(
    geom: &WheelRail<'_, T, N, M>,
    target: Target<T>,
    mat: &Material<T>,
    cfg: &WheelConfig<T>,
    ws: &mut WheelWorkspace<T, K, NP, NS, NR, S, C, SS>,
    state: Option<&mut WheelState<T, K>>,
    sink: &mut W,
) -> Result<WheelResult<T, K, NR>, Error> {
    check_positive(cfg.tol, "tol")?;
    let main_only = matches!(target, Target::MainNormal(_));
    let target_value = match target {
        Target::Vertical(f) | Target::MainNormal(f) => f,
    };
    ws.ratio = [T::ZERO; K];
    ws.loads = [T::ZERO; K];
    ws.inverse = [InverseState::cold(); K];
    ws.solves = 0;
    ws.geometry_calls = 0;
    ws.exponent = math::c(1.5);
    ws.patches_dv = None;
    ws.reuse = false;
    ws.full = [const { None }; K];
    let mut dv = math::c::<T>(0.05);
    // warm start: δ_v scaled by the load change, the patches there matched to the state's slots
    let mut warm = false;
    let warm_start = state
        .as_deref()
        .and_then(|st| st.start(target_value, geom.pose.dy).map(|s| (st, s)));
    let mut dv_load = T::ZERO;
    if let Some((st, (dv_w, dv_l, p))) = warm_start {
        dv = dv_w;
        dv_load = dv_l;
        ws.exponent = p;
        contact_patches(geom, dv, &cfg.patches, &mut ws.patches)?;
        ws.patches_dv = Some(dv);
        ws.geometry_calls += 1;
        inherit(st, ws);
        warm = true;
        ws.reuse = true;
        if !main_only {
            predict_ratios(geom, target_value, mat, cfg, ws)?;
        }
    }
    let mut passes = 0;
    let mut ok = false;
    let mut vload = T::ZERO;
    let mut coupled = false;
    let mut rounds = 0;
    // geometry evaluations when the kept full results of the last round were computed
    let mut full_geometry: Option<u32> = None;
    // relaxation of the ratio update (module docs): 1 until the changes stop contracting
    let mut omega = T::ONE;
    let mut last_change = T::MAX;
    for round in 0..MAX_COUPLING {
        rounds = round + 1;
        let (d, f, p, c) = split_load(geom, target, dv, mat, cfg, ws)?;
        dv = d;
        vload = f;
        passes += p;
        ok = c;
        if main_only {
            // the normal load is given: no coupling through the vertical balance
            coupled = true;
            break;
        }
        // tangential forces of every patch at these loads → new ratios
        let mut change = T::ZERO;
        let mut raw = [T::ZERO; K];
        let np = ws.patches.len.min(K);
        // a warm call into a sink without cells keeps the full results of its rounds: the last
        // round's are the final ones when the final split leaves the loads unchanged
        let keep = warm && !W::CELLS;
        let geometry_at_round = ws.geometry_calls;
        ws.full = [const { None }; K];
        #[allow(clippy::needless_range_loop)] // k indexes the patches, loads, ratios and results
        for k in 0..np {
            let nk = ws.loads[k];
            if !(nk > T::ZERO) {
                continue;
            }
            let cr = patch_creepage(geom, &ws.patches.items[k].frame, cfg)?;
            let n = samples_of(&ws.patches, k, &mut ws.samples);
            // the full solve (with wear) when kept; its forces are those of the forces-only
            // solve, bit for bit, which an error of the wear stage falls back to (the final
            // solve then reports it, as without keeping)
            let full = if keep {
                solve_patch(
                    &ws.samples[..n],
                    nk,
                    &cr,
                    mat,
                    &cfg.pipeline,
                    &mut ws.pipeline,
                    &mut (),
                )
                .ok()
            } else {
                None
            };
            let r = match full {
                Some(r) => {
                    ws.full[k] = Some((nk, r.clone()));
                    r
                }
                // only the totals are used here: no cells, no wear (same forces, bit for bit)
                None => solve_patch_forces(
                    &ws.samples[..n],
                    nk,
                    &cr,
                    mat,
                    &cfg.pipeline,
                    &mut ws.pipeline,
                )?,
            };
            raw[k] = r.totals.fy / nk;
            change = math::max(change, math::abs(raw[k] - ws.ratio[k]));
        }
        // not contracting (a jump in the tangential solution): halve the step from now on
        if omega < T::ONE || (round >= RELAX_AFTER && change > T::HALF * last_change) {
            omega = T::HALF * omega;
        }
        last_change = change;
        for ((r, &new), &nk) in ws.ratio.iter_mut().zip(&raw).zip(&ws.loads).take(np) {
            if nk > T::ZERO {
                *r = if omega < T::ONE {
                    *r + omega * (new - *r)
                } else {
                    new
                };
            }
        }
        change = omega * change;
        // a cold round 0 starts from r = 0 and cannot see a change; a warm one can
        if (round > 0 || warm) && change < math::c(1e-5) {
            coupled = true;
            full_geometry = Some(geometry_at_round);
            break;
        }
    }
    // Final pass at the converged ratios: the load split is consistent with the ratios used.
    if !main_only {
        let (d, f, p, c) = split_load(geom, target, dv, mat, cfg, ws)?;
        dv = d;
        vload = if f > T::ZERO { f } else { vload };
        passes += p;
        ok &= c;
    }
    let mut res = WheelResult {
        patches: heapless::Vec::new(),
        vertical_approach: dv,
        vertical_load: vload,
        iterations: passes,
        geometry_calls: ws.geometry_calls,
        coupling_rounds: rounds,
        stripes_solves: ws.solves,
        converged: ok && coupled,
    };
    let np = ws.patches.len.min(K);
    for k in 0..np {
        let nk = ws.loads[k];
        if !(nk > T::ZERO) {
            continue;
        }
        let frame = ws.patches.items[k].frame;
        let cr = patch_creepage(geom, &frame, cfg)?;
        sink.begin_patch(res.patches.len());
        // the last round's full result if it was solved on these patches at this very load
        let kept = match &ws.full[k] {
            Some((n_kept, r))
                if full_geometry == Some(ws.geometry_calls) && *n_kept == nk && !W::CELLS =>
            {
                Some(r.clone())
            }
            _ => None,
        };
        let r = match kept {
            Some(r) => r,
            None => {
                let n = samples_of(&ws.patches, k, &mut ws.samples);
                solve_patch(
                    &ws.samples[..n],
                    nk,
                    &cr,
                    mat,
                    &cfg.pipeline,
                    &mut ws.pipeline,
                    &mut Forward(sink),
                )?
            }
        };
        res.converged &= r.converged;
        // at most K patches: k < np ≤ K, one push per k
        let _ = res.patches.push(WheelPatch {
            frame,
            creepage: cr,
            load: nk,
            result: r,
        });
    }
    if res.patches.is_empty() {
        return Err(Error::NoContact);
    }
    if main_only {
        res.vertical_load = res
            .patches
            .iter()
            .map(|p| p.load * math::cos(p.frame.angle))
            .fold(T::ZERO, |a, b| a + b);
    }
    if let Some(st) = state {
        st.warm = true;
        st.target = target_value;
        st.dv = dv;
        st.exponent = ws.exponent;
        // the pose's share of this call's change of δ_v (0 after a cold call)
        let drift = if warm && dv > T::ZERO && dv_load > T::ZERO {
            math::ln(dv / dv_load)
        } else {
            T::ZERO
        };
        st.drift = if math::is_finite(drift) {
            math::clamp(drift, -math::c::<T>(MAX_DRIFT), math::c(MAX_DRIFT))
        } else {
            T::ZERO
        };
        let ddy = geom.pose.dy - st.pose_dy;
        st.drift_rate = if warm && math::abs(ddy) > math::c(DRIFT_DY_MM) {
            Some(st.drift / ddy)
        } else {
            None
        };
        st.pose_dy = geom.pose.dy;
        st.n = np;
        for (k, slot) in st.slots.iter_mut().enumerate() {
            *slot = if k < np {
                SlotState {
                    y_ref: ws.patches.items[k].frame.y_ref_rail,
                    load: ws.loads[k],
                    ratio: ws.ratio[k],
                    inverse: ws.inverse[k],
                }
            } else {
                SlotState::cold()
            };
        }
    }
    Ok(res)
}

/// Warm-start predictor of the coupling ratios: at the patches in `ws.patches` (the new pose at
/// the warm δ_v), each patch's load for its approach (inverse STRIPES, warm from its slot) and
/// the ratio r_k = F_y,k/N_k of the tangential solve at that load. The ratios then carry the
/// pose change (creepages, contact angle, radius) into round 0 of the coupling, which can thereby
/// meet its test; the loads found are reused by the first pass of the load loop.
fn predict_ratios<
    T: Real,
    const N: usize,
    const M: usize,
    const K: usize,
    const NP: usize,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
>(
    geom: &WheelRail<'_, T, N, M>,
    fz: T,
    mat: &Material<T>,
    cfg: &WheelConfig<T>,
    ws: &mut WheelWorkspace<T, K, NP, NS, NR, S, C, SS>,
) -> Result<(), Error> {
    let np = ws.patches.len.min(K);
    let mut fsum = T::ZERO;
    for k in 0..np {
        let frame = ws.patches.items[k].frame;
        let a = frame.approach;
        let guess = if ws.loads[k] > T::ZERO {
            ws.loads[k]
        } else {
            fz
        };
        ws.loads[k] = T::ZERO;
        if !(a > T::ZERO) {
            continue;
        }
        let n = samples_of(&ws.patches, k, &mut ws.samples);
        let nk = match load_for_approach(
            &ws.samples[..n],
            a,
            guess,
            &mut ws.inverse[k],
            mat,
            cfg,
            &mut ws.pipeline,
            true,
        ) {
            Ok((nk, _, it)) => {
                ws.solves += it;
                nk
            }
            Err(Error::NoContact) | Err(Error::GridTooSmall(_)) => continue,
            Err(e) => return Err(e),
        };
        if !(nk > T::ZERO) {
            continue;
        }
        ws.loads[k] = nk;
        fsum += nk * (math::cos(frame.angle) + ws.ratio[k] * ey_z(geom, frame.angle));
    }
    // the loads of the balance to first order: all scaled by F_z / F(δ_v,warm)
    let scale = if fsum > T::ZERO && math::is_finite(fsum) {
        math::clamp(fz / fsum, math::c(0.5), math::c(2.0))
    } else {
        T::ONE
    };
    for k in 0..np {
        let nk = ws.loads[k] * scale;
        if !(nk > T::ZERO) {
            continue;
        }
        let frame = ws.patches.items[k].frame;
        let cr = patch_creepage(geom, &frame, cfg)?;
        let n = samples_of(&ws.patches, k, &mut ws.samples);
        let r = solve_patch_forces(
            &ws.samples[..n],
            nk,
            &cr,
            mat,
            &cfg.pipeline,
            &mut ws.pipeline,
        )?;
        ws.ratio[k] = r.totals.fy / nk;
    }
    Ok(())
}

/// Gives each patch in `ws.patches` the load, inverse-STRIPES state and coupling ratio of the
/// nearest slot of `st` (reference points at most [`MATCH_MM`] apart, nearest pairs first, each
/// slot used once); unmatched patches stay cold.
fn inherit<
    T: Real,
    const K: usize,
    const NP: usize,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
>(
    st: &WheelState<T, K>,
    ws: &mut WheelWorkspace<T, K, NP, NS, NR, S, C, SS>,
) {
    let np = ws.patches.len.min(K);
    let ns = st.n.min(K);
    let mut new_used = [false; K];
    let mut old_used = [false; K];
    let limit = math::c::<T>(MATCH_MM);
    // at most min(np, ns) ≤ K pairs; each round takes the globally nearest free pair
    for _ in 0..K {
        let mut best: Option<(usize, usize, T)> = None;
        for (k, (item, &used_k)) in ws.patches.items[..np].iter().zip(&new_used).enumerate() {
            if used_k {
                continue;
            }
            let y = item.frame.y_ref_rail;
            for (j, (slot, &used_j)) in st.slots[..ns].iter().zip(&old_used).enumerate() {
                if used_j {
                    continue;
                }
                let d = math::abs(y - slot.y_ref);
                if !(d <= limit) {
                    continue;
                }
                match best {
                    Some((_, _, b)) if b <= d => {}
                    _ => best = Some((k, j, d)),
                }
            }
        }
        let Some((k, j, _)) = best else {
            break;
        };
        new_used[k] = true;
        old_used[j] = true;
        let s = &st.slots[j];
        let finite = math::is_finite(s.load) && math::is_finite(s.ratio);
        if finite && s.load > T::ZERO {
            ws.loads[k] = s.load;
            ws.ratio[k] = s.ratio;
            ws.inverse[k] = s.inverse;
        }
    }
}

/// Creepages of a patch: prescribed, or from the kinematics at its reference point.
fn patch_creepage<T: Real, const N: usize, const M: usize>(
    geom: &WheelRail<'_, T, N, M>,
    frame: &PatchFrame<T>,
    cfg: &WheelConfig<T>,
) -> Result<Creepage<T>, Error> {
    match cfg.creepage {
        Some(c) => Ok(c),
        None => {
            let c = creepages(geom, frame, &cfg.kinematics)?;
            Ok(Creepage {
                xi: c.xi,
                eta: c.eta,
                phi: c.phi,
            })
        }
    }
}

/// Forwards cells to a wheel sink.
struct Forward<'a, W>(&'a mut W);

impl<T, W: WheelSink<T>> CellSink<T> for Forward<'_, W> {
    #[inline]
    fn cell(&mut self, j: usize, i: usize, out: &CellOut<T>) {
        self.0.cell(j, i, out);
    }
}
