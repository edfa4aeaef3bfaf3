//! STRIPES semi-Hertzian normal contact (Ayasse & Chollet 2005; methods.md §6, filter §5.3).
//!
//! # Input
//! A fine lateral sampling of one wheel's contact zone in the contact frame, one [`StripSample`] per
//! lateral position (ascending `y`): rigid normal separation `z` (mm, any offset — the minimum is
//! subtracted), longitudinal gap curvature `curv_a` = A (1/mm, > 0), unfiltered lateral gap curvature
//! `curv_b` = B (1/mm, any sign), strip width `dy` and longitudinal position `xc` of the strip's rigid
//! contact (mm). Geometry's region output converts into this (see `crate::pipeline`).
//!
//! # Model (per sample i, §6 steps 1–6)
//! B is passed through the zero-phase Boussinesq filter ([`boussinesq_filter`], §5.3) of length l₀
//! ([`L0Mode`]) and clamped to ≥ `b_min`; then m_i, n_i, r_i = Hertz coefficients of (A_i, B_f,i)
//! ([`crate::hertz::coefficients`]), Ã_i = (n_i/m_i)² B_f,i, ε_i = n_i² B_f,i/(r_i(A_i + B_f,i)),
//! h_i = max(0, e_i(δ − z_ref,i) − (z_i − z_ref,i)) with e_i per [`HMode`], a_i = √(h_i/Ã_i),
//! p_max,i = (2E*/(π n_i r_i ε_i)) h_i/a_i, N = Σ E* h_i δy_i/(n_i r_i ε_i) (E/(1−ν²) = 2E* for two
//! identical bodies). On a Hertzian gap (constant A, B, z = B y²) every mode reproduces Hertz exactly.
//!
//! # Regions and continuity (§6 item 8) — the blending law of this implementation
//! The reference level z_ref of each sample comes from **basins**: the local minima of z lying below
//! the approach δ (the rigid overlap), separated by saddles (the maximum of z between two consecutive
//! minima). Each link between neighbouring basins carries a weight
//!
//! θ = smoothstep(clamp(min(z_s − e_s δ + d_m δ, z_s − max(z_min,L, z_min,R)) / (`blend`·δ), 0, 1)),
//!
//! d_m = `merge_depth` ([`StripesConfig::merge_depth`]), i.e. θ = 0 (merged) while the saddle lies
//! more than d_m·δ deep inside the contact set of the one-region model (z_s < (e_s − d_m) δ) or
//! the saddle has no prominence, rising smoothly to 1 (separate) as the saddle rises by
//! `blend`·δ above that level (with the default d_m = `blend` = 0.25: separate from the moment the
//! saddle touches the edge of the one-region contact set; d_m = 0 was the rule before
//! 2026-12-02). With [`HMode::EpsTangent`] the prominence term z_s − z_hi (z_hi the shallower
//! minimum) is divided by `blend`·√(δ (δ − z_hi)) instead of `blend`·δ — against the geometric
//! mean of δ and that minimum's own overlap —, so that a shallow dimple far up the gap whose saddle
//! stands clearly out of contact separates (1360 mm dy 5.17 mm, 40 kN: NORM loads a tread zone
//! 10 mm beside the flange root at z ≈ 0.77 δ, which the δ scale kept half-merged, θ ≈ 0.5, and
//! out of contact; `EpsLocal`'s wedge tail makes up that area, `EpsTangent` trims the tail). Basin k then uses
//!
//! z_ref,k = min_j ( z_min,j + θ_kj δ ),  θ_kj = max of θ over the links between k and j,
//!
//! which equals the global minimum of its merged cluster at θ = 0, its own minimum at θ = 1 (since
//! z_min,k < δ) and moves continuously in between; it is transitive, so a basin that appears (a new
//! minimum/saddle pair has zero prominence, θ = 0) or enters the overlap (its contribution starts at
//! h = 0) changes nothing discontinuously. The partition is iterated (§6 item 8): pass 1 treats all
//! samples as one region, passes 2 and 3 recompute basins and θ from the previous approach (always 3
//! passes when there is more than one basin, so the result is a continuous composition). With
//! [`HMode::Eps0`], ε₀ of a basin is ε at the minimum that sets its z_ref (it can jump when that
//! minimum changes; seed-literal option only). [`L0Mode::PatchFraction`] uses one l₀ per basin from its
//! half-width w, blended the same way (w_eff,k = max over the runs of basins lo…hi containing k of
//! (1 − θ) w, θ the largest link in the run, w half the measure of the run's contact sets: edge to
//! edge for a connected set, and continuous when an island of contact appears, unlike the hull).
//! The runs reach across k on both sides: with runs from k to one side only, a basin between two
//! merged neighbours got a shorter l₀ than they did (1.342 against 1.538 mm), and when such a
//! dimple vanished the load jumped (S1002/UIC60 1360 mm, dy −6.27 mm, 260 kN, flange contact: 4.5 %
//! within 1e-10 mm of approach). Samples between two minima belong to both basins with weights
//! from their barriers to either minimum (soft zones, see `find_basins`): z_ref, the filter length
//! and the measure blend across the saddle instead of switching at its arg-max sample.
//!
//! The output **regions** (patches) are the connected components of the final contact set on the
//! samples; each gets its own evenly spaced strips ([`Stripes::layout`], ≥ [`MIN_STRIPS_PER_REGION`])
//! on which the load control is solved again (§0.5 layout).
//!
//! # The tangent curvature ([`HMode::EpsTangent`], an option)
//! The local ε_i of a sample describes a gap that is a parabola about the sample, which holds
//! near a region's deepest point but not always on its flanks, where the gap often turns straight
//! (B → 0 or concave, floored: local ε → 0.67) while it still rises steeply: a wedge. Beyond the
//! contact's natural edge the local ε carries the contact 1–1.5 mm too far (NORM, 1360 mm right
//! wheel, dy 4.05 mm, 120 kN: edges at z ≈ 0.44–0.48 δ, the local ε puts them at 0.67 δ; area
//! +10 %), and the too-long tail also fills in the area of a zone that it misses elsewhere (1360
//! mm dy 5.2 mm: the tread zone beside the flange root). `EpsTangent` uses the tangent curvature
//!
//! B_t,i = z'_i² / (4 (z_i − z_ref,i)),  B_e,i = B_f,i + ramp_i·(B_t,i − B_f,i)²/B_t,i  (B_t > B_f),
//!
//! the curvature of the parabola through the sample with the rigid gap's slope z'_i there
//! (central difference) and its vertex at the reference level. On a parabola B_t = B
//! (Hertz-exact); the quadratic blend keeps the local curvature where the two agree within a
//! factor and takes B_t where B_t ≫ B_f; ramp_i = min(1, ((z_i − z_ref,i)/(B_f,i δy_i²))²) makes it
//! continuous where z − z_ref → 0⁺ at a sample with a slope (an arg-min moving between two
//! samples, blended reference levels). With ε_t,i = ε(A_i, B_e,i),
//!
//! e_i(δ) = ε_i + w_i (ε_t,i − ε_i),  w_i = smoothstep((q_i − q₀)/(1 − q₀)),
//! q_i = (z_i − z_ref,i) / (ε_t,i (δ − z_ref,i)),
//!
//! q₀ = [`TANGENT_EDGE`], δ the common approach (w = 1 where δ ≤ z_ref,i): e_i is the local ε
//! inside the contact set that the tangent curvature would give and moves to ε_t towards and
//! beyond its edge. e_i(δ) does not decrease with δ, so N(δ) = Σ k_i δy_i (e_i(δ)(δ − z_ref,i) −
//! (z_i − z_ref,i))₊ stays continuous and non-decreasing; the load control brackets its root by
//! the piecewise-linear solves with e = ε and e = ε_t and finds it by regula falsi (Illinois) in at
//! most [`MAX_NEWTON`] steps (with e_i taken at the previous load control's approach instead, the
//! wheel's vertical approach fell with rising load in places: 1360 mm right, Manchester material,
//! dy −5.12 mm, 20.1 → 20.2 kN). Inside,
//! a concave flank keeps the local ε, which NORM confirms (1353 mm dy 6 mm, 83.3 kN: the flank's
//! strips are as long as NORM's with the local ε and 25–35 % shorter with ε_t everywhere, which
//! took the wear-weighted peak error of the seed's three cases from 8.4 % to 17.5 %). Only e_i (the
//! depth, so the extent) changes; the stiffness and p_max keep the local ε_i (with B_e in all
//! coefficients pmax was off by 300–500 %). ε_t is recomputed in each load control of the
//! partition's passes and e_i held through the coupling's fixed point (recomputed there, with the
//! lift in the gap, it fed back and the wheel solve's normal–tangential loop missed its tolerance
//! at 1360 mm dy 4.75 mm, 120 kN); every count stays fixed.
//!
//! # Inter-region coupling ([`StripesConfig::interaction`])
//! The strip-local model gives each region the elastic response of its own load only. Two regions
//! of one patch a few mm apart (tread and flange root) deform each other: the load P of one
//! lifts the surfaces at distance r by u = P/(π E* r) (Boussinesq, both bodies, E* the contact
//! modulus). NORM (the project's half-space reference) shows it on the 1360 mm tread → flange-root
//! band: the flange root's far-field lift from the tread is 0.015–0.029 mm, 18–25 % of the
//! approach, and without it STRIPES puts up to 2× NORM's load on the flange root (e.g. dy 4.55 mm,
//! 83.3 kN: 8.5 kN against NORM's 4.4 kN). With the coupling on, after the partition passes the
//! field u_i from every loaded sample j of the other basins is added to the rigid gap,
//! u_i = 1/(π E*) Σ_j w_ij F_j ⟨1/r⟩_j (F_j the sample's load, ⟨1/r⟩_j the mean of 1/r over its
//! semi-elliptic pressure along x, 4-point Gauss–Chebyshev, with the strip width as regulariser,
//! w_ij the product of the soft zone weights and the link weight θ between their basins — 0
//! within a basin and between merged basins, continuous as basins separate); each basin's
//! reference level moves with ū_k, the mean of u over its zone weighted by the squared rigid
//! overlap (continuous, unlike u at the arg-min sample), so that a uniform lift U lowers the
//! region's effective approach by U; then the load control is solved again. The partition (basins,
//! θ, zones, filter lengths) is held; the fixed point u ← u(solution(u)) is iterated (contraction
//! factor ≈ c·k, ≈ 0.2 on the band) until max |Δu| ≤ 1e-9·δ (f64) / 1e-5·δ (f32), at most
//! [`MAX_COUPLING`] steps; the steps add to `iterations`, a miss clears `converged`. When the field
//! is zero (one region, merged basins) nothing is re-solved: bit-identical to the coupling off.
//!
//! # Load control (§6 item 7)
//! N(δ) = Σ s_i (δ − t_i)₊ is continuous, piecewise linear and convex in the common approach δ. It is
//! solved exactly by Newton's method from the right end of the bracket [t_min, t_min + N/s_min]
//! (monotone on a convex function, exact once the active set is right), safeguarded by bisection,
//! at most [`MAX_NEWTON`] steps; iterations and convergence are reported.

use crate::error::{check_finite, check_positive, Error};
use crate::hertz;
use crate::math::{self, c};
use crate::{Material, Real};

/// Maximum Newton/bisection steps of one load-control solve.
pub const MAX_NEWTON: u32 = 64;
/// Region-partition passes (§6 item 8: "cap the passes: 3").
pub const MAX_PASSES: u32 = 3;
/// Fewest strips a disjoint region may get (§0.5, §6 item 8).
pub const MIN_STRIPS_PER_REGION: usize = 8;
/// Default strips per region (§0.5).
pub const DEFAULT_STRIPS_PER_REGION: usize = 32;
/// Most fixed-point steps of the inter-region elastic coupling ([`StripesConfig::interaction`]).
pub const MAX_COUPLING: u32 = 32;
/// [`HMode::EpsTangent`]: the fraction q₀ of the tangent-curvature contact depth beyond which a
/// sample's e_i moves from the local ε towards the tangent one (module docs, "The tangent
/// curvature"; 0.5 / 0.85 move the figures there by ≤ 0.7 points).
pub const TANGENT_EDGE: f64 = 0.7;

/// One fine lateral sample of the rigid gap in the contact frame (input of [`Stripes::solve`]).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct StripSample<T> {
    /// Lateral position y in the contact plane, mm (strictly ascending over the samples).
    pub y: T,
    /// Width the sample represents, mm (> 0).
    pub dy: T,
    /// Rigid normal separation of the undeformed profiles, mm (any offset).
    pub z: T,
    /// Longitudinal gap curvature A = cos δ/(2R), 1/mm (> 0).
    pub curv_a: T,
    /// Lateral gap curvature B (unfiltered, in the contact plane), 1/mm (any sign).
    pub curv_b: T,
    /// Longitudinal position of the strip's rigid contact x_c, mm (0 without yaw).
    pub xc: T,
}

/// Strip-depth mode `h_mode` (§6 step 3).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum HMode<T> {
    /// Seed literal: e_i = ε₀ of the region's deepest strip.
    Eps0,
    /// e_i = local ε_i.
    EpsLocal,
    /// e_i = ε_i passed through the zero-phase filter with this length l_ε (mm).
    EpsSmoothed(T),
    /// e_i = filter(B_f ε)/filter(B_f) with length l_ε (mm): the smoothing of `EpsSmoothed`
    /// weighted by the filtered lateral curvature, so that flat or concave samples (B_f clamped to
    /// `b_min`, whose ε ≈ 0.82 has no Hertzian meaning) do not raise e_i of a neighbouring curved
    /// region. Equal to `EpsSmoothed` where B_f is constant (Hertz-exact).
    EpsWeighted(T),
    /// e_i = ε of (A_i, B_e,i): the local ε where the gap is locally a parabola about the region's
    /// reference level, a smaller one where it is a wedge (module docs, "The tangent curvature").
    EpsTangent,
}

/// Curvature-filter length `l0_mode` (§6 item 9, §5.3).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum L0Mode<T> {
    /// No filter (l₀ = 0; B is only clamped).
    Off,
    /// l₀ = semi-width b of the Hertz ellipse at the deepest sample under the target load.
    HertzB,
    /// l₀ = f·w per basin, w = half the measure of its contact set in an unfiltered pass.
    PatchFraction(T),
}

/// STRIPES options.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct StripesConfig<T> {
    /// Strip-depth mode.
    pub h_mode: HMode<T>,
    /// Curvature-filter length.
    pub l0_mode: L0Mode<T>,
    /// Blending depth as a fraction of the approach δ (dimensionless, ≥ 0; 0 = hard switch).
    pub blend: T,
    /// Lower clamp of the filtered lateral curvature, 1/mm (§5.3: 1e-6).
    pub b_min: T,
    /// Curvature floor relative to A (dimensionless, ≥ 0): the Hertz quantities of a sample are
    /// evaluated at B_eff = [`effective_curvature`]`(B_f, b₀)`, b₀ = max(`b_min`, `b_floor`·A),
    /// a C¹ soft clamp that equals B_f for B_f ≥ 2b₀ (Hertz-exact there). 0 = the hard clamp
    /// max(B_f, `b_min`) of §5.3 (up to B_f < 2·`b_min`).
    ///
    /// Default 0.1 ([`StripesConfig::recommended`]). Evidence: continuity — with the hard clamp
    /// the per-wheel solve (S1002/UIC60 1360 mm, 83.3 kN) stepped within 0.001 mm of shift (dy
    /// 4.002→4.003 pmax −0.30 %, area +0.33 %; 5.873→5.874 area +0.44 % and a non-converged load
    /// loop); with 0.1 these steps are continuous under 8×8×8 refinement (host-tests
    /// `wheel_continuity`). Accuracy — against NORM on the issue-6 sweep the worst area error falls
    /// from +24 % to +13.9 % (no case beyond 20 %), on the tread → flange-root band the mean area
    /// error from 9.5 % to 6.9 % (`stripes_norm_sweep variants`); against CONTACT the
    /// default's pmax max is 3.7 % (5.3 % documented before the floor). A Hertzian gap
    /// (B ≥ 0.2·A) is unchanged. 0 reproduces §5.3's hard clamp.
    pub b_floor: T,
    /// Inter-region elastic coupling (see [`Stripes::solve`], "Inter-region coupling" in the
    /// module docs): the far-field normal displacement that the load of each separated basin
    /// causes at the strips of the others (Boussinesq, both bodies: u = P/(π E* r)) is added to
    /// their rigid gap, solved by a bounded fixed-point iteration inside the load control. Acts
    /// only between basins whose link weight θ > 0 (regions the partition keeps apart); a single
    /// region, or basins merged by the partition, are bit-identical to `false`.
    ///
    /// Default `true` ([`StripesConfig::recommended`], together with `merge_depth` 0.25; it was
    /// `false` before, see below). What it fixes:
    /// on two separated Hertzian bumps the approach rises by the far field P/(π E* L) within
    /// 0.14 % (host-tests `stripes_interaction`); on the 1360 mm tread → flange-root band, where
    /// NORM, STRIPES and the coupled STRIPES have two regions and STRIPES overloads the flange
    /// root (8 cases), the flange root's share of the patch load comes to NORM's (mean error 3.9
    /// → 0.7 percentage points; `stripes_norm_sweep` band test, asserted). Against NORM
    /// (`stripes_norm_sweep variants`, per wheel, |error| mean / max %; and as the wheel default):
    ///
    /// | variant (all as the wheel default) | band (57) pmax / area | sweep (120) pmax / area | transitions pmax / area | A-2.2 (42) pmax / area |
    /// |---|---|---|---|---|
    /// | `EpsLocal`, coupling off, `merge_depth` 0 (default until 2026-12-02) | 8.95 / 42.7, 6.92 / 17.7 | 2.33 / 15.6, 3.49 / 13.9 | 0.63 / 1.2, 4.22 / 6.8 | 0.48 / 3.7, 2.11 / 12.8 |
    /// | `EpsLocal`, coupling on, `merge_depth` 0 | 7.0 / 42.7, 6.3 / 17.7 | 2.32 / 15.6, 3.47 / 13.9 | —, 5.9 / 9.1 | 0.48 / 4.3, 2.01 / 10.7 |
    /// | `EpsLocal`, coupling off, `merge_depth` 0.25 | 4.70 / 29.7, 6.25 / 13.0 | — | — | — |
    /// | `EpsWeighted(1)`, coupling off, `merge_depth` 0 | — | 2.43 / 14.2, 2.55 / 9.0 | 3.51 / 8.2, 15.0 / 36.3 | 0.50 / 4.2, 1.96 / 11.0 |
    /// | `EpsWeighted(1)`, coupling on, `merge_depth` 0 | 2.9 / 15.6, 1.6 / 6.7 (re-solve) | 2.47 / 14.2, 2.55 / 9.0 | 3.94 / 8.2, 15.8 / 37.0 | 0.57 / 4.6, 1.95 / 11.0 |
    /// | **`EpsLocal`, coupling on, `merge_depth` 0.25 (default)** | **3.07 / 17.8, 4.74 / 10.6** | **2.11 / 14.2, 3.26 / 10.3** | **0.79 / 1.3, 5.98 / 9.2** | **0.40 / 2.9, 1.90 / 10.8** |
    /// | `EpsTangent` (option), coupling on, `merge_depth` 0.25, prominence scale √(δ δ_s) | 3.23 / 17.5, 1.56 / 7.8 | 2.19 / 14.0, 2.47 / 9.2 | 1.04 / 1.1, 0.49 / 1.0 | 0.35 / 2.3, 1.58 / 10.8 |
    ///
    /// (The transition shifts are found per variant by bisecting where the kernel's contact
    /// signature changes, so each row has its own set.) With `merge_depth` 0 the band's worst
    /// pmax cases were not two-region cases: STRIPES' contact set bridged the concave valley
    /// between tread and flange root (floored curvature, local ε ≈ 0.67), the partition then
    /// merged the basins (θ = 0) and gave the flange root the tread's reference level — no
    /// far-field term changes that, so the coupling alone helped little. The default's
    /// `merge_depth` keeps the two basins apart while the saddle is at the edge of the contact
    /// set (see its docs); then the coupling acts on them and brings the flange root's load share
    /// to NORM's (`stripes_norm_sweep` band test, asserted). Why not `EpsWeighted(1 mm)`: it loses
    /// area wherever a strongly curved region borders a concave zone, also with the coupling off
    /// (1360 mm dy 5.31 mm 83.3 kN, flange root only: area 44 against NORM's 67 mm²): it gives the
    /// floored samples there the flange root's ε ≈ 0.30…0.37, so they leave the contact set,
    /// whereas NORM keeps them in contact up to z ≈ 0.47 δ (`EpsLocal`'s floored ε 0.67 keeps
    /// them, area −5 %). The wheel load loop now brackets its root (`wheel`), so a steep stretch
    /// of δ(N) (dy 4.6198633 mm, 83.3 kN: dδ/dN ×13 over 2 N) no longer stops it, and the filter
    /// length uses the soft measure ([`StripesConfig::soft_measure`]) whose slope stays bounded
    /// where the floored valley closes. Against CONTACT's exact solutions (`tests/wheel.rs`,
    /// per-wheel solve) the worst pmax error is 2.85 % (3.66 % with the former default), the worst
    /// approach error 6.09 %; `stripes_mbench` (kernel geometry at CONTACT's approach): pmax
    /// mean / max 0.9 / 2.9 % (0.9 / 3.7 % before).
    pub interaction: bool,
    /// Merge depth d_m of the basin partition as a fraction of the approach δ (dimensionless,
    /// ≥ 0): two neighbouring basins are merged (θ = 0, one reference level) only while their
    /// saddle lies more than d_m·δ inside the contact set of the one-region model, and kept
    /// apart (θ = 1) once it has risen a further `blend`·δ (module docs, "Regions and
    /// continuity"). 0 = the former rule (merged as soon as the saddle is in that contact set).
    ///
    /// Default 0.25 (= `blend`: separate from the moment the saddle touches the contact edge),
    /// on evidence (2026-12-02, `stripes_norm_sweep`, S1002/UIC60 1360 mm tread → flange-root
    /// band): where the floored curvature of the concave valley between tread and flange root
    /// (ε ≈ 0.67) puts the saddle just inside the one-region contact set, NORM has either two
    /// regions or one bridged by a film of ≈ 16 MPa (dy 4.70 mm, 120 kN), and in both the flange
    /// root carries its own Hertzian peak (2076 MPa at dy 4.70, 120 kN). With d_m = 0 STRIPES
    /// merged the basins and measured the flange root's depth from the tread's minimum:
    /// h = ε δ − z = 0.316·0.0877 − 0.021 = 0.0067 mm at dy 4.75 mm, 83.3 kN, pmax 1090 against
    /// NORM's 2014 MPa (−43 % per wheel); from its own minimum h ≈ 0.021 mm, pmax ≈ 2000 MPa.
    /// Band, per wheel |Δ| mean / max: pmax 8.95 / 42.7 → 3.07 / 17.8 % (10 → 0 cases beyond
    /// 20 %), area 6.92 / 17.7 → 4.74 / 10.6 % (with the coupling; d_m 0.25 alone 4.70 / 29.7 %,
    /// two beyond 20 %, the rest is the missing far field). A single basin is unaffected.
    pub merge_depth: T,
    /// Depth scale of the soft contact-set measure behind [`L0Mode::PatchFraction`], as a fraction
    /// of the approach δ (dimensionless, ≥ 0; 0 = the plain measure of {h > 0}, the rule before
    /// 2026-12-02): each basin's measure is ∫ min(1, h/h_ref) ω dy, h_ref = `soft_measure`·δ.
    ///
    /// Default 0.005. Why: the plain measure is continuous, but its slope is unbounded where a gap
    /// of the contact set closes at a flat saddle; with `merge_depth` 0.25 and the coupling the
    /// per-wheel solve (1360 mm, 83.3 kN) then raised both basins' l₀ by 3.4 % within 3e-5 mm of
    /// shift at dy 4.61985 mm (the floored valley closing in the unfiltered pass), an area step
    /// that `wheel_continuity` flags as a jump. With h_ref the slope is bounded by δy/(2 h_ref).
    /// 0.005 is the value at which the whole per-wheel continuity test passes (0.02 moved the
    /// flange basin's l₀ by −17 % and made the layout's neck onset at dy 5.8819 mm steep enough
    /// to be flagged); a Hertzian gap (constant B) does not depend on l₀.
    pub soft_measure: T,
}

/// C¹ soft clamp of the filtered lateral curvature B_f (1/mm) at the floor `b0` (1/mm, > 0):
/// b₀ for B_f ≤ 0, b₀ + B_f²/(4b₀) for 0 < B_f < 2b₀, B_f for B_f ≥ 2b₀ (continuous with a
/// continuous slope 0…1).
///
/// Why (continuity in the shift, §6 item 8): the Hertz quantities of a sample depend on ln(B/A)
/// as B/A → 0 (ε = 0.82 at B/A = 1e-3, 0.69 at 0.07, 0.50 at 1; strip stiffness and Ã alike). With
/// the hard clamp max(B_f, 1e-6) a sample whose filtered curvature crosses zero inside the contact
/// set (the edge of a concave zone) changes its ε by ≈ 0.13 while B_f moves by 7e-5 1/mm, i.e. in
/// ≈ 5e-4 mm of wheelset shift: the strip depth h = ε(δ − z_ref) − (z − z_ref) of that sample, the
/// approach, pmax and area then step (S1002/UIC60 1360 mm 83.3 kN: area +0.44 % at dy 5.873→5.874,
/// pmax −0.30 % at 4.002→4.003). A floor b₀ proportional to A bounds dε/dB_f by ≈ |dε/dln B|/b₀.
pub fn effective_curvature<T: Real>(bf: T, b0: T) -> T {
    if bf <= T::ZERO {
        b0
    } else if bf < T::TWO * b0 {
        b0 + bf * bf / (c::<T>(4.0) * b0)
    } else {
        bf
    }
}

impl<T: Real> StripesConfig<T> {
    /// The kernel's default, chosen on evidence: `EpsLocal` + `PatchFraction(0.25)`, blending depth
    /// 0.25·δ, B_f ≥ 1e-6 1/mm, curvature floor `b_floor` 0.1 (soft clamp at 0.1·A), inter-region
    /// coupling on with merge depth 0.25 and soft measure 0.005 (since 2026-12-02; evidence in
    /// [`StripesConfig::interaction`] and [`StripesConfig::merge_depth`]: tread → flange-root band
    /// pmax 8.95 / 42.7 → 3.07 / 17.8 %, sweep 2.33 / 15.6 → 2.11 / 14.2 %, A-2.2 against NORM
    /// 0.48 / 3.7 → 0.40 / 2.9 %).
    ///
    /// [`HMode::EpsTangent`] (module docs, "The tangent curvature") is closer to NORM on the area
    /// and on the transition shifts (per wheel, mean / max %, both wheels, `stripes_norm_sweep`
    /// with the wheel solve under each):
    ///
    /// | set | `EpsLocal` (default) pmax / area | `EpsTangent` pmax / area |
    /// |---|---|---|
    /// | sweep (120) | 2.11 / 14.2, 3.26 / 10.3 | 2.19 / 14.0, 2.47 / 9.2 |
    /// | band (57) | 3.07 / 17.8, 4.74 / 10.6 | 3.23 / 17.5, 1.56 / 7.8 |
    /// | transition shifts | 0.79 / 1.3, 5.98 / 9.2 | 1.04 / 1.1, 0.49 / 1.0 |
    /// | Manchester A-2.2 (42) | 0.40 / 2.9, 1.90 / 10.8 | 0.35 / 2.3, 1.58 / 10.8 |
    ///
    /// and the FaStrip-AC wear-weighted peak error of the seed's three cases is 8.4 % on it
    /// (8.9 % on the default; `wheelrail_tangential`). It is not the default because the
    /// real-time tables built on it interpolate it worse (host-tests `realtime_step`, the step
    /// against the converged solver: area max 1.9 → 3.9 %; issue-14 sweep: tread N max 3.6 %,
    /// guarded at 1 %) and one node of the Manchester table (right wheel, 5–20 kN) did not
    /// converge (`realtime_norm`). The latter is not the option's own: a scan of that wheel
    /// (dy −12…2 mm by 0.02 mm, 5–20 kN, 3505 wheel solves) misses once in either mode, near
    /// dy −5 mm (`EpsLocal` at 16.25 kN, between the table's load nodes; `EpsTangent` at one).
    /// Without the edge weight (w = 1: ε_t wherever
    /// B_t > B_f) the band was at 2.40 / 11.8, 1.24 / 6.0 and the sweep at 2.46 / 13.8,
    /// 2.29 / 8.5, but concave flanks inside the contact lost extent that NORM gives them
    /// (1353 mm dy 6 mm; that wear error went from 8.4 to 17.5 %).
    ///
    /// The tables below were measured before the coupling.
    ///
    /// Evidence (host-tests `stripes_mbench`, out-of-sample for the spec's prototype: CONTACT's exact
    /// solutions of the 42 Manchester cases, 10 kN, left and right wheel, kernel geometry at
    /// CONTACT's approach, 32 strips per region, `b_floor` 0.1; |error| mean / max %, cases > 10 %):
    ///
    /// | variant | pmax | > 10 % | area | > 10 % |
    /// |---|---|---|---|---|
    /// | `EpsLocal` + `PatchFraction(0.25)` (**default**) | 0.9 / 3.7 | 0 | 3.2 / 10.7 | 1 |
    /// | `EpsSmoothed(2)` + `PatchFraction(0.25)` (spec §6 item 11) | 1.4 / 8.2 | 0 | 4.1 / 37.6 | 2 |
    /// | `EpsWeighted(1)` + `PatchFraction(0.25)` | 1.0 / 4.2 | 0 | 3.1 / 10.1 | 1 |
    /// | `EpsLocal`, l₀ = 0 | 1.1 / 11.7 | 1 | 3.1 / 12.7 | 1 |
    /// | `Eps0` + `HertzB` (seed literal) | 2.0 / 11.6 | 1 | 4.4 / 29.3 | 3 |
    ///
    /// (Documented before the curvature floor: default 1.0 / 5.3, 0, 3.6 / 10.5, 1.) The spec's
    /// `EpsSmoothed(2 mm)` misses the two-region case right y_ws = 5 mm (tread + flange root):
    /// smoothing ε across the concave gap between the regions (where the floored B gives ε ≈ 0.8)
    /// raises e_i of the flange-root region, which then takes the whole load at an approach below
    /// the tread region's rigid overlap. The spec's prototype preferred `EpsSmoothed` over
    /// `EpsLocal` **without** filter on its (in-sample) 20 cases; `EpsLocal` with the patch-scaled
    /// filter was not in that study.
    ///
    /// Against NORM (host-tests `stripes_norm_sweep`, test `variants`: the kernel's own wheel
    /// solve and patch samples, NORM at the same patch load; per wheel, |error| mean / max %;
    /// 2026-12-01, with the pipeline's neck blend):
    ///
    /// | variant | sweep (60 right-wheel cases) pmax / area | 1360 dy 4.05…4.95 band (57) pmax / area | A-2.2 (42) pmax / area |
    /// |---|---|---|---|
    /// | `EpsLocal` + `PatchFraction(0.25)`, `b_floor` 0.1 (**default**) | 2.3 / 15.6, 3.5 / 13.9 | 9.0 / 42.7, 6.9 / 17.7 | 0.5 / 3.7, 2.1 / 12.8 |
    /// | the same, `b_floor` 0 (hard clamp) | 2.7 / 11.6, 4.4 / 24.0 | 9.1 / 42.4, 9.5 / 25.0 | 0.5 / 5.5, 2.5 / 14.1 |
    /// | `EpsWeighted(0.5)`, `b_floor` 0.1 | 2.3 / 15.2, 3.0 / 12.8 | 8.1 / 37.8, 4.6 / 14.3 | 0.5 / 4.5, 1.8 / 10.4 |
    /// | `EpsWeighted(0.5)`, `b_floor` 0 | 2.5 / 10.5, 3.0 / 9.7 | 6.4 / 33.5, 2.3 / 7.2 | 0.7 / 7.3, 2.0 / 11.1 |
    /// | `EpsWeighted(1)`, `b_floor` 0.1 | 2.4 / 14.2, 2.6 / 8.9 | 6.6 / 35.9, 1.5 / 4.4 | 0.5 / 4.2, 1.9 / 10.1 |
    /// | `EpsSmoothed(2)`, `b_floor` 0.1 | 2.8 / 9.6, 3.1 / 11.4 | 10.1 / 50.0, 4.2 / 12.9 | 0.9 / 5.5, 2.7 / 30.3 |
    ///
    /// With the curvature floor the default meets the issue-6 targets on the whole sweep (120
    /// cases, both wheels: pmax 2.33 / 15.6 %, area 3.49 / 13.9 %, none beyond 20 %; the former
    /// miss 1360 dy = 5 mm 40 kN, area +23.6 % with the hard clamp, is +11.2 %), on the transition
    /// shifts and on A-2.2 (and, since 2026-12-02, with the coupling and `merge_depth`, on the
    /// band too). `EpsWeighted(0.5…1 mm)` is better on the band's area but not the
    /// default: with 0.5 mm (hard clamp) the per-wheel solve's approach on the plateau case
    /// y_ws = 0 rose from 5 % to 8.9 % above CONTACT's (reference point 0.19 mm off,
    /// `tests/wheel.rs`), and with 1 mm it loses area where a curved region borders a concave
    /// zone (transition shifts, see [`StripesConfig::interaction`]). None of the variants of the
    /// table met the targets on the tread → flange-root band (1360 mm, dy ≈ 4.5–5): there STRIPES
    /// merged the basins across the concave valley and ignored the elastic interaction of the two
    /// regions — fixed by `merge_depth` and `interaction`.
    pub fn recommended() -> Self {
        Self {
            h_mode: HMode::EpsLocal,
            l0_mode: L0Mode::PatchFraction(c(0.25)),
            blend: c(0.25),
            b_min: c(1e-6),
            b_floor: c(0.1),
            interaction: true,
            merge_depth: c(0.25),
            soft_measure: c(0.005),
        }
    }
    /// The spec's recommended set (§6 item 11): `EpsSmoothed(2 mm)` + `PatchFraction(0.25)`.
    pub fn spec_recommended() -> Self {
        Self {
            h_mode: HMode::EpsSmoothed(c(2.0)),
            ..Self::recommended()
        }
    }
    /// Seed B literal set: `Eps0` + `HertzB`.
    pub fn seed_literal() -> Self {
        Self {
            h_mode: HMode::Eps0,
            l0_mode: L0Mode::HertzB,
            ..Self::recommended()
        }
    }
}

/// Zero-phase Boussinesq curvature filter (§5.3, eq. 25): the one-sided recursion
/// B_f,k = B_f,k−1 + (1 − exp(−3Δs/(2l₀)))(B_k − B_f,k−1), started at B_f = B at the first point,
/// run forward and backward and averaged. `s` = positions (mm, ascending), `l0` (mm); l₀ ≤ 0 copies.
/// `out` receives the result; lengths are the shortest of the three slices.
pub fn boussinesq_filter<T: Real>(s: &[T], b: &[T], l0: T, out: &mut [T]) {
    let n = s.len().min(b.len()).min(out.len());
    if n == 0 {
        return;
    }
    if l0 <= T::ZERO {
        out[..n].copy_from_slice(&b[..n]);
        return;
    }
    let k = c::<T>(-1.5) / l0;
    let mut last_ds = -T::ONE;
    let mut w = T::ZERO;
    let mut f = b[0];
    out[0] = f;
    for i in 1..n {
        let ds = s[i] - s[i - 1];
        if ds != last_ds {
            w = T::ONE - math::exp(k * ds);
            last_ds = ds;
        }
        f += w * (b[i] - f);
        out[i] = f;
    }
    let mut f = b[n - 1];
    out[n - 1] = T::HALF * (out[n - 1] + f);
    for i in (0..n - 1).rev() {
        let ds = s[i + 1] - s[i];
        if ds != last_ds {
            w = T::ONE - math::exp(k * ds);
            last_ds = ds;
        }
        f += w * (b[i] - f);
        out[i] = T::HALF * (out[i] + f);
    }
}

/// Result of one load-control solve.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LoadControl<T> {
    /// Common approach δ, mm.
    pub delta: T,
    /// Newton/bisection steps used.
    pub iterations: u32,
    /// |N(δ) − N| ≤ tolerance reached.
    pub converged: bool,
}

/// Solves Σ s_i (δ − t_i)₊ = `target` for δ (s_i > 0), exactly up to rounding (see module docs).
/// `term(i)` returns (s_i, t_i). Relative tolerance 1e-12 (f64) / 4e-6 (f32). `hint`: an optional
/// starting approach (e.g. the previous pass's), used to shrink the bracket.
pub fn solve_piecewise_linear<T: Real>(
    n: usize,
    target: T,
    hint: Option<T>,
    term: impl Fn(usize) -> (T, T),
) -> Result<LoadControl<T>, Error> {
    check_positive(target, "N")?;
    let mut t_min = T::MAX;
    let mut s_at_min = T::ZERO;
    for i in 0..n {
        let (s, t) = term(i);
        if s > T::ZERO && t < t_min {
            t_min = t;
            s_at_min = s;
        }
    }
    if s_at_min <= T::ZERO || !math::is_finite(t_min) {
        return Err(Error::NoContact);
    }
    let eval = |d: T| -> (T, T) {
        let mut f = T::ZERO;
        let mut slope = T::ZERO;
        for i in 0..n {
            let (s, t) = term(i);
            if s > T::ZERO && d > t {
                f += s * (d - t);
                slope += s;
            }
        }
        (f, slope)
    };
    let tol = load_tolerance(target);
    let mut lo = t_min;
    let mut hi = t_min + target / s_at_min;
    let mut iterations = 0;
    if let Some(h) = hint {
        if h > lo && h < hi {
            iterations += 1;
            let (f, _) = eval(h);
            if f >= target {
                hi = h;
            } else {
                lo = h;
            }
        }
    }
    let mut d = hi;
    let mut converged = false;
    for _ in 0..MAX_NEWTON {
        iterations += 1;
        let (f, slope) = eval(d);
        let r = f - target;
        if math::abs(r) <= tol {
            converged = true;
            break;
        }
        if r > T::ZERO {
            hi = d;
        } else {
            lo = d;
        }
        let mut next = if slope > T::ZERO { d - r / slope } else { lo };
        if !(next > lo && next < hi) {
            next = T::HALF * (lo + hi);
        }
        if next == d {
            converged = true;
            break;
        }
        d = next;
    }
    Ok(LoadControl {
        delta: d,
        iterations,
        converged,
    })
}

/// A basin (local minimum of z below δ) of the fine samples.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
struct Basin<T> {
    /// Sample index of the minimum.
    imin: usize,
    /// z at the minimum (normalised), mm.
    zmin: T,
    /// Saddle height to the next basin (z max between the two minima), mm.
    saddle: T,
    /// Sample index of that saddle (last sample of this basin's zone).
    isaddle: usize,
    /// Blending weight θ of the link to the next basin.
    theta: T,
    /// Reference level, mm.
    zref: T,
    /// ε₀ for `Eps0`.
    eps0: T,
    /// Measure (total lateral length) of the basin zone's contact set (for `PatchFraction`), mm.
    len: T,
    /// Inter-region coupling: the basin's mean displacement ū_k that shifts its minimum, mm.
    ushift: T,
}

/// Summary of one output region (connected component of the contact set).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct RegionSummary<T> {
    /// Lateral limits of the contact set (interpolated edges), mm.
    pub y_lo: T,
    /// Upper lateral limit, mm.
    pub y_hi: T,
    /// Normal force carried by the region, N.
    pub load: T,
    /// Largest strip peak pressure, MPa.
    pub pmax: T,
    /// Contact area Σ 2 a_i δy_i, mm².
    pub area: T,
    /// Longest strip half-length, mm.
    pub a_max: T,
    /// First sample index and one past the last (fine solution) or first strip and count (layout).
    pub first: usize,
    /// Number of samples (fine) or strips (layout).
    pub count: usize,
}

/// Result of [`Stripes::solve`] on the fine samples.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct StripesSolution<T, const NR: usize> {
    /// Common approach δ measured from the deepest sample, mm.
    pub delta: T,
    /// Offset subtracted from the input z (the minimum), mm.
    pub z_offset: T,
    /// Load-control steps, summed over all passes.
    pub iterations: u32,
    /// Every load-control solve converged.
    pub converged: bool,
    /// Partition passes of the final (filtered) solve.
    pub passes: u32,
    /// Number of basins in the final partition.
    pub basins: usize,
    /// Total normal force Σ over samples, N.
    pub load: T,
    /// Largest peak pressure, MPa.
    pub pmax: T,
    /// Total contact area, mm².
    pub area: T,
    /// Output regions (connected components of the contact set).
    pub regions: [RegionSummary<T>; NR],
    /// Number of valid entries in `regions`.
    pub n_regions: usize,
}

/// Per-strip STRIPES result on the evenly spaced strips of each region ([`Stripes::layout`]).
#[derive(Clone, Debug, PartialEq)]
pub struct StripSet<T, const S: usize, const NR: usize> {
    /// Strip centre y_j, mm.
    pub y: [T; S],
    /// Strip width δy_j, mm.
    pub dy: [T; S],
    /// Strip half-length a_j, mm (0 if the strip is out of contact).
    pub a: [T; S],
    /// Strip centre x_c,j, mm.
    pub xc: [T; S],
    /// Strip peak pressure p_max,j, MPa (semi-elliptic along x).
    pub pmax: [T; S],
    /// Strip depth h_j, mm.
    pub h: [T; S],
    /// Longitudinal curvature A_j, 1/mm.
    pub curv_a: [T; S],
    /// Filtered lateral curvature B_f,j, 1/mm.
    pub curv_bf: [T; S],
    /// Local Hertz axis ratio n_j/m_j (= b/a of the local ellipse, §5.3).
    pub n_over_m: [T; S],
    /// Shape-corrected longitudinal curvature Ã_j = (n_j/m_j)² B_f,j, 1/mm (a_j = √(h_j/Ã_j)).
    pub a_tilde: [T; S],
    /// Strip stiffness E*/(n_j r_j ε_j), MPa: strip load per unit width = stiffness · h_j.
    pub stiffness: [T; S],
    /// Region index of the strip.
    pub region: [u8; S],
    /// Number of valid strips.
    pub n_strips: usize,
    /// Per-region summary; `first`/`count` index the strips.
    pub regions: [RegionSummary<T>; NR],
    /// Number of regions.
    pub n_regions: usize,
    /// Approach of the strip re-solve, mm (relative to the deepest sample).
    pub delta: T,
    /// Total normal force, N.
    pub total_load: T,
    /// Largest strip peak pressure, MPa.
    pub total_pmax: T,
    /// Total contact area Σ 2 a_j δy_j, mm².
    pub total_area: T,
    /// Load-control steps of the strip re-solve.
    pub iterations: u32,
    /// The strip re-solve converged.
    pub converged: bool,
}

impl<T: Real, const S: usize, const NR: usize> StripSet<T, S, NR> {
    /// Empty set (const, for statics).
    pub const fn new() -> Self {
        Self {
            y: [T::ZERO; S],
            dy: [T::ZERO; S],
            a: [T::ZERO; S],
            xc: [T::ZERO; S],
            pmax: [T::ZERO; S],
            h: [T::ZERO; S],
            curv_a: [T::ZERO; S],
            curv_bf: [T::ZERO; S],
            n_over_m: [T::ZERO; S],
            a_tilde: [T::ZERO; S],
            stiffness: [T::ZERO; S],
            region: [0; S],
            n_strips: 0,
            regions: [RegionSummary {
                y_lo: T::ZERO,
                y_hi: T::ZERO,
                load: T::ZERO,
                pmax: T::ZERO,
                area: T::ZERO,
                a_max: T::ZERO,
                first: 0,
                count: 0,
            }; NR],
            n_regions: 0,
            delta: T::ZERO,
            total_load: T::ZERO,
            total_pmax: T::ZERO,
            total_area: T::ZERO,
            iterations: 0,
            converged: false,
        }
    }

    /// Semi-elliptic pressure of strip `j` at longitudinal position x (mm), MPa.
    pub fn pressure(&self, j: usize, x: T) -> T {
        if j >= self.n_strips || self.a[j] <= T::ZERO {
            return T::ZERO;
        }
        let u = (x - self.xc[j]) / self.a[j];
        let s = T::ONE - u * u;
        if s > T::ZERO {
            self.pmax[j] * math::sqrt(s)
        } else {
            T::ZERO
        }
    }
}

impl<T: Real, const S: usize, const NR: usize> Default for StripSet<T, S, NR> {
    fn default() -> Self {
        Self::new()
    }
}

/// STRIPES solver with its caller-owned workspace: `NS` fine samples, `NB` basins, `NR` regions.
#[derive(Clone, Debug)]
pub struct Stripes<T, const NS: usize, const NB: usize, const NR: usize> {
    y: [T; NS],
    z: [T; NS],
    bf: [T; NS],
    eps: [T; NS],
    e: [T; NS],
    at: [T; NS],
    kst: [T; NS],
    nm: [T; NS],
    zref: [T; NS],
    hu: [T; NS],
    tmp: [T; NS],
    zone: [u8; NS],
    /// Weight of basin zone+1 in sample i (soft zone boundary at the saddle, see `find_basins`).
    sw: [T; NS],
    /// Inter-region displacement added to the rigid gap (0 unless the coupling acts), mm.
    uz: [T; NS],
    /// Next iterate of `uz`.
    un: [T; NS],
    l0: [T; NB],
    l0_global: T,
    n: usize,
    delta_last: T,
    basins: [Basin<T>; NB],
    nb: usize,
    e_star: T,
    /// [`HMode::EpsTangent`]: the partition's load controls solve e_i(δ) with the approach.
    tangent: bool,
    /// [`HMode::EpsTangent`]: ε_t,i of the tangent curvature (= ε_i where it does not apply).
    et: [T; NS],
}

impl<T: Real, const NS: usize, const NB: usize, const NR: usize> Default
    for Stripes<T, NS, NB, NR>
{
    fn default() -> Self {
        Self::new()
    }
}

/// Which depth factors a piecewise-linear load control uses.
#[derive(Clone, Copy)]
enum DepthFactor {
    /// e_i as set by the mode.
    Current,
    /// The local ε_i.
    Local,
    /// ε_t,i of [`HMode::EpsTangent`].
    Tangent,
}

/// Hertz m, n, r of (A, B): the table where it covers the ratio, else the root solve.
fn mnr<T: Real>(a: T, b: T) -> Result<(T, T, T), Error> {
    match crate::hertz_table::mnr(a, b) {
        Some(v) => Ok(v),
        None => hertz::coefficients(a, b).map(|h| (h.m, h.n, h.r)),
    }
}

/// Residual tolerance of the load controls: 1e-12 (f64) / 4e-6 (f32) of the load.
fn load_tolerance<T: Real>(load: T) -> T {
    let rel = if T::EPSILON < c(1e-10) {
        c::<T>(1e-12)
    } else {
        c::<T>(4e-6)
    };
    rel * load
}

fn smoothstep<T: Real>(u: T) -> T {
    let u = math::clamp(u, T::ZERO, T::ONE);
    u * u * (c::<T>(3.0) - T::TWO * u)
}

impl<T: Real, const NS: usize, const NB: usize, const NR: usize> Stripes<T, NS, NB, NR> {
    const CAPACITY_OK: () = assert!(NS >= 2 && NB >= 1 && NB <= 255 && NR >= 1);

    /// Empty workspace (const: can live in a `static`).
    pub const fn new() -> Self {
        #[allow(clippy::let_unit_value)]
        let _ = Self::CAPACITY_OK;
        let b = Basin {
            imin: 0,
            zmin: T::ZERO,
            saddle: T::ZERO,
            isaddle: 0,
            theta: T::ZERO,
            zref: T::ZERO,
            eps0: T::ZERO,
            len: T::ZERO,
            ushift: T::ZERO,
        };
        Self {
            y: [T::ZERO; NS],
            z: [T::ZERO; NS],
            bf: [T::ZERO; NS],
            eps: [T::ZERO; NS],
            e: [T::ZERO; NS],
            at: [T::ZERO; NS],
            kst: [T::ZERO; NS],
            nm: [T::ZERO; NS],
            zref: [T::ZERO; NS],
            hu: [T::ZERO; NS],
            tmp: [T::ZERO; NS],
            zone: [0; NS],
            sw: [T::ZERO; NS],
            uz: [T::ZERO; NS],
            un: [T::ZERO; NS],
            l0: [T::ZERO; NB],
            l0_global: T::ZERO,
            n: 0,
            delta_last: T::ZERO,
            basins: [b; NB],
            nb: 0,
            e_star: T::ZERO,
            tangent: false,
            et: [T::ZERO; NS],
        }
    }

    /// Number of samples of the last solve.
    pub fn len(&self) -> usize {
        self.n
    }
    /// `true` before the first successful solve.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }
    /// Strip depth h_i of sample i (mm) of the last solve (0 outside).
    pub fn depth(&self, i: usize) -> T {
        if i < self.n {
            math::max(self.hu[i], T::ZERO)
        } else {
            T::ZERO
        }
    }
    /// Half-length a_i of sample i (mm) of the last solve.
    pub fn half_length(&self, i: usize) -> T {
        let h = self.depth(i);
        if h > T::ZERO {
            math::sqrt(h / self.at[i])
        } else {
            T::ZERO
        }
    }
    /// Peak pressure p_max,i of sample i (MPa) of the last solve.
    pub fn peak_pressure(&self, i: usize) -> T {
        let h = self.depth(i);
        if h > T::ZERO {
            c::<T>(2.0 / core::f64::consts::PI) * self.kst[i] * math::sqrt(h * self.at[i])
        } else {
            T::ZERO
        }
    }
    /// Filtered lateral curvature B_f,i (1/mm) of the last solve.
    pub fn filtered_curvature(&self, i: usize) -> T {
        if i < self.n {
            self.bf[i]
        } else {
            T::ZERO
        }
    }
    /// Debug view of the basins of the last solve: (index of minimum, z_min, θ, z_ref, l₀).
    pub fn basin_info(&self, k: usize) -> Option<(usize, T, T, T, T)> {
        if k < self.nb {
            let b = self.basins[k];
            Some((b.imin, b.zmin, b.theta, b.zref, self.l0[k]))
        } else {
            None
        }
    }
    /// Local ε_i of the last solve.
    pub fn eps_local(&self, i: usize) -> T {
        if i < self.n {
            self.eps[i]
        } else {
            T::ZERO
        }
    }

    /// Solves the normal problem for total load `load` (N) on `samples` (see module docs).
    ///
    /// Errors: too few/many samples, non-finite or non-ascending input, A ≤ 0, load ≤ 0, no contact,
    /// and errors of the Hertz coefficients.
    pub fn solve(
        &mut self,
        samples: &[StripSample<T>],
        load: T,
        mat: &Material<T>,
        cfg: &StripesConfig<T>,
    ) -> Result<StripesSolution<T, NR>, Error> {
        let n = samples.len();
        if n < 2 {
            return Err(Error::GridTooSmall("samples"));
        }
        if n > NS {
            return Err(Error::OutOfRange("samples exceed capacity"));
        }
        check_positive(load, "N")?;
        check_positive(mat.e_star, "E*")?;
        check_finite(cfg.blend, "blend")?;
        if cfg.blend < T::ZERO {
            return Err(Error::OutOfRange("blend"));
        }
        check_positive(cfg.b_min, "b_min")?;
        check_finite(cfg.b_floor, "b_floor")?;
        if cfg.b_floor < T::ZERO {
            return Err(Error::OutOfRange("b_floor"));
        }
        check_finite(cfg.soft_measure, "soft_measure")?;
        if cfg.soft_measure < T::ZERO {
            return Err(Error::OutOfRange("soft_measure"));
        }
        check_finite(cfg.merge_depth, "merge_depth")?;
        if cfg.merge_depth < T::ZERO {
            return Err(Error::OutOfRange("merge_depth"));
        }
        match cfg.h_mode {
            HMode::EpsSmoothed(l) | HMode::EpsWeighted(l) => {
                check_positive(l, "l_eps")?;
            }
            HMode::Eps0 | HMode::EpsLocal | HMode::EpsTangent => {}
        }
        self.tangent = matches!(cfg.h_mode, HMode::EpsTangent);
        if let L0Mode::PatchFraction(f) = cfg.l0_mode {
            check_positive(f, "l0 fraction")?;
        }
        let mut zmin = T::MAX;
        for (i, s) in samples.iter().enumerate() {
            check_finite(s.y, "y")?;
            check_positive(s.dy, "dy")?;
            check_finite(s.z, "z")?;
            check_positive(s.curv_a, "A")?;
            check_finite(s.curv_b, "B")?;
            check_finite(s.xc, "xc")?;
            if i > 0 && s.y <= samples[i - 1].y {
                return Err(Error::OutOfRange("y not ascending"));
            }
            if s.z < zmin {
                zmin = s.z;
            }
        }
        self.n = n;
        self.delta_last = T::ZERO;
        self.e_star = mat.e_star;
        for (i, s) in samples.iter().enumerate() {
            self.y[i] = s.y;
            self.z[i] = s.z - zmin;
            self.uz[i] = T::ZERO;
        }
        let mut iterations = 0;
        let mut converged = true;
        // Filter lengths: one global length, or one per basin of an unfiltered pass.
        self.l0_global = T::ZERO;
        self.nb = 0;
        match cfg.l0_mode {
            L0Mode::Off => {}
            L0Mode::HertzB => {
                let mut ideep = 0;
                for i in 0..n {
                    if self.z[i] < self.z[ideep] {
                        ideep = i;
                    }
                }
                let s = samples[ideep];
                let bb =
                    effective_curvature(s.curv_b, math::max(cfg.b_min, cfg.b_floor * s.curv_a));
                let hz = hertz::from_load(s.curv_a, bb, load, mat)?;
                self.l0_global = hz.b;
            }
            L0Mode::PatchFraction(f) => {
                // Unfiltered pass → w per basin.
                self.coefficients(samples, cfg, false)?;
                let (it, conv, _) = self.passes(samples, load, cfg)?;
                iterations += it;
                converged &= conv;
                self.basin_extents(samples, cfg.soft_measure);
                let nb = self.nb;
                // w_eff,k = max over the runs of basins lo…hi that contain k of (1 − θ) w,
                // θ the largest link in the run, w half its measure (module docs): each run's
                // value, grown one basin at a time, goes to every basin in it
                self.l0[..nb].fill(T::ZERO);
                for lo in 0..nb {
                    let (mut theta, mut len) = (T::ZERO, T::ZERO);
                    for hi in lo..nb {
                        if hi > lo {
                            theta = math::max(theta, self.basins[hi - 1].theta);
                        }
                        len += self.basins[hi].len;
                        let w = (T::ONE - theta) * T::HALF * len;
                        for l in &mut self.l0[lo..=hi] {
                            *l = math::max(*l, w);
                        }
                    }
                }
                for l in &mut self.l0[..nb] {
                    *l = f * *l;
                }
            }
        }
        // Filtered pass.
        let per_basin = matches!(cfg.l0_mode, L0Mode::PatchFraction(_));
        self.coefficients(samples, cfg, per_basin)?;
        let (it, conv, passes) = self.passes(samples, load, cfg)?;
        iterations += it;
        converged &= conv;
        if cfg.interaction && self.nb >= 2 {
            let (it, conv) = self.couple(samples, load, cfg)?;
            iterations += it;
            converged &= conv;
        }
        // Outputs on the fine samples.
        let mut sol = StripesSolution {
            delta: self.delta_last,
            z_offset: zmin,
            iterations,
            converged,
            passes,
            basins: self.nb,
            load: T::ZERO,
            pmax: T::ZERO,
            area: T::ZERO,
            regions: [RegionSummary::default(); NR],
            n_regions: 0,
        };
        let mut i = 0;
        let mut guard = 0;
        while i < n && guard <= n {
            guard += 1;
            if self.hu[i] <= T::ZERO {
                i += 1;
                continue;
            }
            let first = i;
            let mut reg = RegionSummary {
                first,
                ..RegionSummary::default()
            };
            while i < n && self.hu[i] > T::ZERO {
                let a = self.half_length(i);
                let p = self.peak_pressure(i);
                let dy = samples[i].dy;
                reg.load += self.kst[i] * self.hu[i] * dy;
                reg.area += T::TWO * a * dy;
                reg.pmax = math::max(reg.pmax, p);
                reg.a_max = math::max(reg.a_max, a);
                i += 1;
            }
            reg.count = i - first;
            reg.y_lo = self.edge_left(first, samples);
            reg.y_hi = self.edge_right(i - 1, samples);
            if sol.n_regions >= NR {
                return Err(Error::TooManyRegions);
            }
            sol.load += reg.load;
            sol.area += reg.area;
            sol.pmax = math::max(sol.pmax, reg.pmax);
            sol.regions[sol.n_regions] = reg;
            sol.n_regions += 1;
        }
        if sol.n_regions == 0 {
            return Err(Error::NoContact);
        }
        Ok(sol)
    }

    fn edge_left(&self, i: usize, samples: &[StripSample<T>]) -> T {
        if i == 0 {
            return self.y[0] - T::HALF * samples[0].dy;
        }
        let (h0, h1) = (self.hu[i - 1], self.hu[i]);
        let t = h1 / (h1 - h0);
        self.y[i] - t * (self.y[i] - self.y[i - 1])
    }

    fn edge_right(&self, i: usize, samples: &[StripSample<T>]) -> T {
        let n = self.n;
        if i + 1 >= n {
            return self.y[n - 1] + T::HALF * samples[n - 1].dy;
        }
        let (h0, h1) = (self.hu[i], self.hu[i + 1]);
        let t = h0 / (h0 - h1);
        self.y[i] + t * (self.y[i + 1] - self.y[i])
    }

    /// Filters B (one global l₀, or per basin zone of the previous pass when `per_basin`), then the
    /// per-sample Hertz quantities and e_i.
    fn coefficients(
        &mut self,
        samples: &[StripSample<T>],
        cfg: &StripesConfig<T>,
        per_basin: bool,
    ) -> Result<(), Error> {
        let n = self.n;
        for (t, s) in self.tmp.iter_mut().zip(samples.iter()) {
            *t = s.curv_b;
        }
        if per_basin {
            let mut last = -T::ONE;
            self.bf[..n].fill(T::ZERO);
            for k in 0..self.nb {
                let l = self.l0[k];
                if l != last {
                    boussinesq_filter(&self.y[..n], &self.tmp[..n], l, &mut self.eps[..n]);
                    last = l;
                }
                // soft zones: sample i takes (1 − s_i) of its zone's filter and s_i of the next's
                for i in 0..n {
                    let w = self.zone_weight(i, k);
                    if w > T::ZERO {
                        self.bf[i] += w * self.eps[i];
                    }
                }
            }
        } else {
            boussinesq_filter(
                &self.y[..n],
                &self.tmp[..n],
                self.l0_global,
                &mut self.bf[..n],
            );
        }
        for (i, s) in samples.iter().enumerate().take(n) {
            let a = s.curv_a;
            let b = effective_curvature(self.bf[i], math::max(cfg.b_min, cfg.b_floor * a));
            self.bf[i] = b;
            let (m, nn, r) = mnr(a, b)?;
            let ratio = nn / m;
            self.nm[i] = ratio;
            self.at[i] = ratio * ratio * b;
            let eps = nn * nn * b / (r * (a + b));
            self.eps[i] = eps;
            self.kst[i] = self.e_star / (nn * r * eps);
        }
        match cfg.h_mode {
            HMode::EpsSmoothed(l) => {
                boussinesq_filter(&self.y[..n], &self.eps[..n], l, &mut self.e[..n]);
            }
            HMode::EpsWeighted(l) => {
                for i in 0..n {
                    self.tmp[i] = self.bf[i] * self.eps[i];
                }
                boussinesq_filter(&self.y[..n], &self.tmp[..n], l, &mut self.e[..n]);
                boussinesq_filter(&self.y[..n], &self.bf[..n], l, &mut self.hu[..n]);
                for i in 0..n {
                    self.e[i] = if self.hu[i] > T::ZERO {
                        self.e[i] / self.hu[i]
                    } else {
                        self.eps[i]
                    };
                }
            }
            HMode::EpsLocal | HMode::Eps0 | HMode::EpsTangent => {
                self.e[..n].copy_from_slice(&self.eps[..n]);
            }
        }
        Ok(())
    }

    /// ε_t,i of [`HMode::EpsTangent`] from the rigid gap and the reference levels (module docs,
    /// "The tangent curvature"); ε_t,i = ε_i where B_t ≤ B_f.
    #[allow(clippy::neg_cmp_op_on_partial_ord)] // NaN must count as "not greater": local ε
    fn tangent_eps(&mut self, samples: &[StripSample<T>]) -> Result<(), Error> {
        let n = self.n;
        for (i, smp) in samples.iter().enumerate().take(n) {
            self.et[i] = self.eps[i];
            let lvl = self.z[i] + self.uz[i] - self.zref[i];
            if lvl <= T::ZERO {
                continue;
            }
            let (l, r) = (i.saturating_sub(1), (i + 1).min(n - 1));
            let slope = (self.z[r] - self.z[l]) / (self.y[r] - self.y[l]);
            let (a, bf) = (smp.curv_a, self.bf[i]);
            let bt = slope * slope / (c::<T>(4.0) * lvl);
            if !(bt > bf) {
                continue;
            }
            let scale = bf * smp.dy * smp.dy;
            let ramp = if lvl < scale {
                let q = lvl / scale;
                q * q
            } else {
                T::ONE
            };
            let b = math::min(bf + (bt - bf) * (bt - bf) / bt * ramp, c::<T>(1e4) * a);
            if !(b > bf) {
                continue;
            }
            let (_, nn, rr) = mnr(a, b)?;
            self.et[i] = math::min(nn * nn * b / (rr * (a + b)), self.eps[i]);
        }
        Ok(())
    }

    /// e_i(δ) of [`HMode::EpsTangent`] at the common approach `delta`: the local ε inside the
    /// contact set that ε_t gives, ε_t towards and beyond its edge (non-decreasing in δ).
    #[allow(clippy::neg_cmp_op_on_partial_ord)] // NaN must count as "not smaller": local ε
    fn tangent_weighted(&self, i: usize, delta: T) -> T {
        let (el, et) = (self.eps[i], self.et[i]);
        if !(et < el) {
            return el;
        }
        let lvl = self.z[i] + self.uz[i] - self.zref[i];
        let span = delta - self.zref[i];
        let w = if span > T::ZERO {
            let q = lvl / (et * span);
            smoothstep((q - c::<T>(TANGENT_EDGE)) / (T::ONE - c::<T>(TANGENT_EDGE)))
        } else {
            T::ONE
        };
        el + w * (et - el)
    }

    /// Load control of [`HMode::EpsTangent`] with e_i(δ): N(δ) = Σ k_i δy_i (e_i(δ)(δ − z_ref,i)
    /// − (g_i − z_ref,i))₊ is continuous and non-decreasing (e_i(δ) is), bracketed by the
    /// piecewise-linear solves with e = ε (smallest δ) and e = ε_t (largest δ), then solved by
    /// regula falsi (Illinois) in at most [`MAX_NEWTON`] steps. Leaves e_i(δ) in `e`.
    #[allow(clippy::neg_cmp_op_on_partial_ord)] // NaN must stop the iteration
    fn load_control_tangent(
        &mut self,
        samples: &[StripSample<T>],
        load: T,
    ) -> Result<LoadControl<T>, Error> {
        let n = self.n;
        self.tangent_eps(samples)?;
        let mut iterations = 0;
        let mut bracket = [T::ZERO; 2];
        for (b, e) in bracket
            .iter_mut()
            .zip([DepthFactor::Local, DepthFactor::Tangent])
        {
            let lc = self.linear_solve(samples, load, None, e)?;
            iterations += lc.iterations;
            *b = lc.delta;
        }
        let residual = |st: &Self, d: T| {
            let mut f = -load;
            for (i, smp) in samples.iter().enumerate().take(n) {
                let h = st.tangent_weighted(i, d) * (d - st.zref[i])
                    - (st.z[i] + st.uz[i] - st.zref[i]);
                if h > T::ZERO {
                    f += st.kst[i] * smp.dy * h;
                }
            }
            f
        };
        let tol = load_tolerance(load);
        let (mut lo, mut hi) = (bracket[0], bracket[1]);
        let (mut flo, mut fhi) = (residual(self, lo), residual(self, hi));
        let mut delta = if math::abs(flo) <= math::abs(fhi) {
            lo
        } else {
            hi
        };
        let mut converged = math::abs(flo) <= tol || math::abs(fhi) <= tol;
        let mut side = 0i8;
        for _ in 0..MAX_NEWTON {
            if converged || !(hi > lo) || !(flo < T::ZERO && fhi > T::ZERO) {
                break;
            }
            iterations += 1;
            let mut d = lo - flo * (hi - lo) / (fhi - flo);
            if !(d > lo && d < hi) {
                d = T::HALF * (lo + hi);
            }
            let f = residual(self, d);
            delta = d;
            if math::abs(f) <= tol {
                converged = true;
            } else if f < T::ZERO {
                lo = d;
                flo = f;
                if side == -1 {
                    fhi = T::HALF * fhi;
                }
                side = -1;
            } else {
                hi = d;
                fhi = f;
                if side == 1 {
                    flo = T::HALF * flo;
                }
                side = 1;
            }
        }
        for i in 0..n {
            self.e[i] = self.tangent_weighted(i, delta);
        }
        self.set_depths(delta);
        Ok(LoadControl {
            delta,
            iterations,
            converged,
        })
    }

    /// Load control of the partition's passes: [`Self::load_control`], or with
    /// [`HMode::EpsTangent`] the one that solves e_i(δ) with the approach.
    fn pass_load_control(
        &mut self,
        samples: &[StripSample<T>],
        load: T,
    ) -> Result<LoadControl<T>, Error> {
        if self.tangent {
            self.load_control_tangent(samples, load)
        } else {
            self.load_control(samples, load)
        }
    }

    /// Load control with the current z_ref, e (held: also in the coupling's fixed point, for
    /// every mode); stores the unclipped depths in `hu`.
    fn load_control(
        &mut self,
        samples: &[StripSample<T>],
        load: T,
    ) -> Result<LoadControl<T>, Error> {
        let hint = if self.delta_last > T::ZERO {
            Some(self.delta_last)
        } else {
            None
        };
        let lc = self.linear_solve(samples, load, hint, DepthFactor::Current)?;
        self.set_depths(lc.delta);
        Ok(lc)
    }

    /// The piecewise-linear load control (§6 step 7) with the depth factors `e`.
    fn linear_solve(
        &mut self,
        samples: &[StripSample<T>],
        load: T,
        hint: Option<T>,
        factor: DepthFactor,
    ) -> Result<LoadControl<T>, Error> {
        let n = self.n;
        for (i, smp) in samples.iter().enumerate().take(n) {
            let ei = match factor {
                DepthFactor::Current => self.e[i],
                DepthFactor::Local => self.eps[i],
                DepthFactor::Tangent => self.et[i],
            };
            self.tmp[i] = self.kst[i] * smp.dy * ei;
            self.hu[i] = self.zref[i] + (self.z[i] + self.uz[i] - self.zref[i]) / ei;
        }
        let (sv, tv) = (&self.tmp, &self.hu);
        solve_piecewise_linear(n, load, hint, |i| (sv[i], tv[i]))
    }

    /// The unclipped depths `hu` at the approach `delta` with the current e; `delta_last`.
    fn set_depths(&mut self, delta: T) {
        for i in 0..self.n {
            self.hu[i] =
                self.e[i] * (delta - self.zref[i]) - (self.z[i] + self.uz[i] - self.zref[i]);
        }
        self.delta_last = delta;
    }

    /// The iterated partition of §6 item 8 (module docs). Returns (iterations, converged, passes).
    fn passes(
        &mut self,
        samples: &[StripSample<T>],
        load: T,
        cfg: &StripesConfig<T>,
    ) -> Result<(u32, bool, u32), Error> {
        let n = self.n;
        // Pass 1: one region, z_ref = 0 (global minimum), ε₀ of the deepest sample.
        let mut ideep = 0;
        for i in 0..n {
            if self.z[i] < self.z[ideep] {
                ideep = i;
            }
        }
        let eps_deep = self.eps[ideep];
        self.zref[..n].fill(T::ZERO);
        self.zone[..n].fill(0);
        self.sw[..n].fill(T::ZERO);
        if matches!(cfg.h_mode, HMode::Eps0) {
            self.e[..n].fill(eps_deep);
        }
        let lc = self.pass_load_control(samples, load)?;
        let mut iterations = lc.iterations;
        let mut converged = lc.converged;
        let mut passes = 1;
        for pass in 2..=MAX_PASSES {
            let delta = self.delta_last;
            self.find_basins(delta, cfg, eps_deep);
            if self.nb <= 1 && pass == 2 {
                break;
            }
            self.assign_ref(delta, cfg);
            let lc = self.pass_load_control(samples, load)?;
            iterations += lc.iterations;
            converged &= lc.converged;
            passes = pass;
        }
        Ok((iterations, converged, passes))
    }

    /// Soft zone weight ω_i(k) of sample `i` in basin `k`: 1 − s_i in its own zone, s_i in the
    /// next one, 0 elsewhere (see `find_basins`).
    #[inline]
    fn zone_weight(&self, i: usize, k: usize) -> T {
        let z = usize::from(self.zone[i]);
        if z == k {
            T::ONE - self.sw[i]
        } else if z + 1 == k {
            self.sw[i]
        } else {
            T::ZERO
        }
    }

    /// Link weight between basins `k` and `l`: 0 for the same basin, else the largest θ of the
    /// links between them (as in `assign_ref`).
    fn theta_between(&self, k: usize, l: usize) -> T {
        if k == l {
            return T::ZERO;
        }
        let (lo, hi) = if k < l { (k, l) } else { (l, k) };
        let mut theta = T::ZERO;
        for q in lo..hi.min(self.nb) {
            theta = math::max(theta, self.basins[q].theta);
        }
        theta
    }

    /// The inter-region displacement field of the current solution into `un` (mm); returns
    /// `false` if it is identically zero (no pair of loaded samples in separated basins).
    ///
    /// u_i = 1/(π E*) Σ_j w_ij F_j ⟨1/r⟩_j: F_j = stiffness·h_j·δy_j the load of contact sample j,
    /// ⟨1/r⟩_j the mean of 1/r over its semi-elliptic pressure along x (four-point Gauss–Chebyshev
    /// rule of the second kind on [x_c,j − a_j, x_c,j + a_j]) seen from (x_c,i, y_i), with
    /// r² = Δx² + Δy² + δy_j²/4 (the strip's width as a regularisation; only strips in other
    /// basins count, normally ≥ one saddle apart), and w_ij = Σ ω_i(k) ω_j(l) θ_kl over the soft
    /// zone weights ω (1 − s, s of the zone and the next) — 0 for samples of one basin or of
    /// merged basins (θ = 0), the full far field between basins the partition keeps apart
    /// (θ = 1), continuous in between.
    #[allow(clippy::needless_range_loop)] // indexes several per-sample arrays
    fn interaction_field(&mut self, samples: &[StripSample<T>]) -> bool {
        let n = self.n;
        let nb = self.nb;
        self.un[..n].fill(T::ZERO);
        if nb < 2 {
            return false;
        }
        // Gauss–Chebyshev (2nd kind), 4 nodes: t_k = cos(kπ/5), weights sin²(kπ/5)·2/5 (Σ = 1).
        let t1 = c::<T>(0.809_016_994_374_947_4);
        let t2 = c::<T>(0.309_016_994_374_947_4);
        let w1 = c::<T>(0.138_196_601_125_010_5);
        let w2 = c::<T>(0.361_803_398_874_989_5);
        let nodes = [(t1, w1), (t2, w2), (-t2, w2), (-t1, w1)];
        let quarter = c::<T>(0.25);
        // θ between every pair of basins, once per field (the pair loop below used it n² times).
        let mut th = [[T::ZERO; NB]; NB];
        for (k, row) in th.iter_mut().enumerate().take(nb) {
            for (l, v) in row.iter_mut().enumerate().take(nb) {
                *v = self.theta_between(k, l);
            }
        }
        let mut any = false;
        for j in 0..n {
            let h = self.hu[j];
            if h <= T::ZERO {
                continue;
            }
            let sj = samples[j];
            let f = self.kst[j] * h * sj.dy;
            let a = math::sqrt(h / self.at[j]);
            let kj = usize::from(self.zone[j]).min(nb - 1);
            let kj1 = (kj + 1).min(nb - 1);
            let (wj0, wj1) = (T::ONE - self.sw[j], self.sw[j]);
            // w_ij = ω_i(k)·thj[k] + ω_i(k+1)·thj[k+1], thj[k] = ω_j(l)θ_kl + ω_j(l+1)θ_k,l+1
            let mut thj = [T::ZERO; NB];
            for (k, v) in thj.iter_mut().enumerate().take(nb) {
                *v = wj0 * th[k][kj] + wj1 * th[k][kj1];
            }
            let reg = quarter * sj.dy * sj.dy;
            for i in 0..n {
                if i == j {
                    continue;
                }
                let ki = usize::from(self.zone[i]).min(nb - 1);
                let ki1 = (ki + 1).min(nb - 1);
                let (wi0, wi1) = (T::ONE - self.sw[i], self.sw[i]);
                let w = wi0 * thj[ki] + wi1 * thj[ki1];
                if w <= T::ZERO {
                    continue;
                }
                let dy = self.y[i] - self.y[j];
                let d2 = dy * dy + reg;
                let dx0 = sj.xc - samples[i].xc;
                let mut g = T::ZERO;
                for &(t, wt) in &nodes {
                    let dx = dx0 + a * t;
                    g += wt / math::sqrt(dx * dx + d2);
                }
                self.un[i] += w * f * g;
                any = true;
            }
        }
        if any {
            let k = T::ONE / (T::PI * self.e_star);
            for v in &mut self.un[..n] {
                *v *= k;
            }
        }
        any
    }

    /// ū_k of every basin: the mean of u over the basin's soft zone weighted by
    /// ω_i(k)·((δ − z_i)₊)²·δy_i (its rigid overlap squared, a load-like weight that is positive
    /// at the basin's minimum and continuous in the data; the value at the arg-min sample would
    /// jump when the minimum moves to the next sample).
    #[allow(clippy::needless_range_loop)] // indexes several per-sample arrays
    fn basin_shifts(&mut self, samples: &[StripSample<T>], delta: T) {
        let nb = self.nb;
        for k in 0..nb {
            let mut num = T::ZERO;
            let mut den = T::ZERO;
            for i in 0..self.n {
                let w = self.zone_weight(i, k);
                let o = delta - self.z[i];
                if w > T::ZERO && o > T::ZERO {
                    let wt = w * o * o * samples[i].dy;
                    num += wt * self.uz[i];
                    den += wt;
                }
            }
            self.basins[k].ushift = if den > T::ZERO { num / den } else { T::ZERO };
        }
    }

    /// Inter-region coupling (module docs): fixed-point iteration u ← field(solution(u)) with the
    /// partition (basins, θ, zones, filter) of the last pass held; each step re-solves the load
    /// control with the reference levels of z + u. Stops when max |Δu| ≤ tol·δ (1e-9 in f64,
    /// 1e-5 in f32) or after [`MAX_COUPLING`] steps. Returns (load-control steps, converged);
    /// (0, true) without any step if the field is zero (bit-identical to no coupling).
    fn couple(
        &mut self,
        samples: &[StripSample<T>],
        load: T,
        cfg: &StripesConfig<T>,
    ) -> Result<(u32, bool), Error> {
        let n = self.n;
        let rel = if T::EPSILON < c(1e-10) {
            c::<T>(1e-9)
        } else {
            c::<T>(1e-5)
        };
        let mut iterations = 0;
        for _ in 0..MAX_COUPLING {
            if !self.interaction_field(samples) && iterations == 0 {
                return Ok((0, true));
            }
            let mut diff = T::ZERO;
            for i in 0..n {
                diff = math::max(diff, math::abs(self.un[i] - self.uz[i]));
            }
            if diff <= rel * math::abs(self.delta_last) {
                return Ok((iterations, true));
            }
            self.uz[..n].copy_from_slice(&self.un[..n]);
            let delta = self.delta_last;
            self.basin_shifts(samples, delta);
            self.assign_ref(delta, cfg);
            let lc = self.load_control(samples, load)?;
            iterations += lc.iterations;
            if !lc.converged {
                return Ok((iterations, false));
            }
        }
        Ok((iterations, false))
    }

    /// Basins (local minima of z below δ), their saddles, zones and link weights θ.
    fn find_basins(&mut self, delta: T, cfg: &StripesConfig<T>, eps_deep: T) {
        let n = self.n;
        let mut nb = 0usize;
        let mut run_max = -T::MAX;
        let mut run_idx = 0usize;
        for i in 0..n {
            let left_ok = i == 0 || self.z[i] < self.z[i - 1];
            let right_ok = i + 1 == n || self.z[i] <= self.z[i + 1];
            if left_ok && right_ok && self.z[i] < delta {
                if nb > 0 {
                    let prev = &mut self.basins[nb - 1];
                    prev.saddle = run_max;
                    prev.isaddle = run_idx;
                }
                if nb == NB {
                    // Capacity: merge the weakest link among the NB − 1 links and this new one.
                    self.merge_weakest(nb);
                    nb -= 1;
                }
                self.basins[nb] = Basin {
                    imin: i,
                    zmin: self.z[i],
                    saddle: T::MAX,
                    isaddle: n - 1,
                    ..Basin::default()
                };
                nb += 1;
                run_max = -T::MAX;
                run_idx = i;
            } else if self.z[i] > run_max || nb == 0 {
                run_max = self.z[i];
                run_idx = i;
            }
        }
        if nb == 0 {
            // Cannot happen (the global minimum lies below δ > 0); keep one basin for safety.
            self.basins[0] = Basin {
                imin: 0,
                zmin: T::ZERO,
                saddle: T::MAX,
                isaddle: n - 1,
                ..Basin::default()
            };
            nb = 1;
        }
        self.nb = nb;
        // Soft zones (continuous in the data): sample i between the minima of basins k and k+1
        // gets zone k and the weight s_i of basin k+1 from its barriers to either minimum,
        // B_L = max z on [imin_k, i], B_R = max z on [i, imin_k+1]:
        // s_i = clamp(½ + (B_L − B_R)/(2w), 0, 1), w = min(`blend`·δ, prominence of the link) —
        // ½ at the saddle, 0/1 once the sample lies w below the saddle on its side (so at the
        // latest at the minima). A hard watershed (the saddle's arg-max
        // sample) would switch a sample's z_ref and filter length when the arg-max moves by one
        // sample (a jump of the strip depth by (1 − e)(z_ref,k+1 − z_ref,k)).
        for i in 0..n {
            self.zone[i] = 0;
            self.sw[i] = T::ZERO;
        }
        for k in 0..nb {
            let b = self.basins[k];
            let lo = if k == 0 { 0 } else { b.imin };
            let hi = if k + 1 < nb {
                self.basins[k + 1].imin.min(n - 1)
            } else {
                n - 1
            };
            for i in lo..=hi {
                self.zone[i] = k as u8;
                self.sw[i] = T::ZERO;
            }
            if k + 1 < nb && hi > b.imin {
                let prominence = b.saddle - math::max(b.zmin, self.basins[k + 1].zmin);
                let wz = math::min(cfg.blend * delta, prominence);
                // B_R into sw (right to left), then B_L and s (left to right)
                let mut br = -T::MAX;
                for i in (b.imin..=hi).rev() {
                    br = math::max(br, self.z[i]);
                    self.sw[i] = br;
                }
                let mut bl = -T::MAX;
                for i in b.imin..=hi {
                    bl = math::max(bl, self.z[i]);
                    let d = bl - self.sw[i];
                    self.sw[i] = if wz > T::ZERO {
                        math::clamp(T::HALF + d / (T::TWO * wz), T::ZERO, T::ONE)
                    } else if d > T::ZERO {
                        T::ONE
                    } else if d < T::ZERO {
                        T::ZERO
                    } else {
                        T::HALF
                    };
                }
            }
            if k + 1 < nb {
                let nxt = self.basins[k + 1];
                // How far the link's least-covered sample lies outside the one-region contact set:
                // max over the samples between the minima of z_i − e_i δ (continuous in the data,
                // unlike the value at the arg-max of z).
                let mut out_of_contact = -T::MAX;
                for i in b.imin..=nxt.imin.min(n - 1) {
                    let e_i = match cfg.h_mode {
                        HMode::Eps0 => eps_deep,
                        _ => self.e[i],
                    };
                    out_of_contact = math::max(out_of_contact, self.z[i] - e_i * delta);
                }
                let prominence = b.saddle - math::max(b.zmin, nxt.zmin);
                let m = math::min(out_of_contact + cfg.merge_depth * delta, prominence);
                let scale = cfg.blend * delta;
                // EpsTangent: the prominence against the shallower basin's own overlap (module
                // docs, "Regions and continuity")
                let u = if self.tangent {
                    let shallow = math::max(delta - math::max(b.zmin, nxt.zmin), T::ZERO);
                    let pscale = cfg.blend * math::sqrt(shallow * delta);
                    if pscale > T::ZERO {
                        math::min(
                            (out_of_contact + cfg.merge_depth * delta) / scale,
                            prominence / pscale,
                        )
                    } else {
                        T::ONE
                    }
                } else {
                    m / scale
                };
                self.basins[k].theta = if m <= T::ZERO {
                    T::ZERO
                } else if scale <= T::ZERO {
                    T::ONE
                } else {
                    smoothstep(u)
                };
            } else {
                self.basins[k].theta = T::ONE;
            }
        }
    }

    /// Merges the weakest link among basins 0..=nb (basin nb is the pending new one, described by
    /// the saddle stored in basin nb−1). Keeps the lower minimum.
    fn merge_weakest(&mut self, nb: usize) {
        // links 0..nb−1 are between basin k and k+1 (k+1 == nb means the pending basin, whose min is
        // not stored; treat its prominence as the saddle minus the left min only).
        let mut weakest = 0;
        let mut wp = T::MAX;
        for k in 0..nb.saturating_sub(1) {
            let p = self.basins[k].saddle - math::max(self.basins[k].zmin, self.basins[k + 1].zmin);
            if p < wp {
                wp = p;
                weakest = k;
            }
        }
        // Merge basins `weakest` and `weakest+1`.
        let (l, r) = (self.basins[weakest], self.basins[weakest + 1]);
        let mut m = if l.zmin <= r.zmin { l } else { r };
        // Right link of the merged basin: r's link (to the next), widened if the minimum is l's.
        if l.zmin <= r.zmin {
            if self.basins[weakest].saddle >= r.saddle {
                m.saddle = l.saddle;
                m.isaddle = l.isaddle;
            } else {
                m.saddle = r.saddle;
                m.isaddle = r.isaddle;
            }
        } else {
            m.saddle = r.saddle;
            m.isaddle = r.isaddle;
            // Left link (stored in basin weakest−1) widens to include l's saddle.
            if weakest > 0 && l.saddle > self.basins[weakest - 1].saddle {
                self.basins[weakest - 1].saddle = l.saddle;
                self.basins[weakest - 1].isaddle = l.isaddle;
            }
        }
        self.basins[weakest] = m;
        for k in weakest + 1..nb - 1 {
            self.basins[k] = self.basins[k + 1];
        }
    }

    /// z_ref,k = min_j (z_min,j + θ_kj δ); ε₀ (for `Eps0`) of the minimiser; per-sample copies.
    fn assign_ref(&mut self, delta: T, cfg: &StripesConfig<T>) {
        let nb = self.nb;
        for k in 0..nb {
            let mut best = self.basins[k].zmin + self.basins[k].ushift;
            let mut jbest = k;
            // to the right
            let mut theta = T::ZERO;
            for j in k + 1..nb {
                theta = math::max(theta, self.basins[j - 1].theta);
                let v = self.basins[j].zmin + self.basins[j].ushift + theta * delta;
                if v < best {
                    best = v;
                    jbest = j;
                }
            }
            let mut theta = T::ZERO;
            for j in (0..k).rev() {
                theta = math::max(theta, self.basins[j].theta);
                let v = self.basins[j].zmin + self.basins[j].ushift + theta * delta;
                if v < best {
                    best = v;
                    jbest = j;
                }
            }
            self.basins[k].zref = best;
            self.basins[k].eps0 = self.eps[self.basins[jbest].imin];
        }
        let eps0_mode = matches!(cfg.h_mode, HMode::Eps0);
        for i in 0..self.n {
            let k = usize::from(self.zone[i]).min(nb - 1);
            let b = self.basins[k];
            let b1 = self.basins[(k + 1).min(nb - 1)];
            let s = self.sw[i];
            self.zref[i] = b.zref + s * (b1.zref - b.zref);
            if eps0_mode {
                self.e[i] = b.eps0 + s * (b1.eps0 - b.eps0);
            }
        }
    }

    /// Soft measure of each basin zone's contact set (for [`L0Mode::PatchFraction`]):
    /// len_k = ∫ φ(h(y)) ω_k(y) dy with φ(h) = min(1, h/h_ref), h_ref = `soft`·δ
    /// ([`StripesConfig::soft_measure`]), over
    /// the samples with h and the soft zone weights ω_k interpolated linearly in y (trapezoid per
    /// interval between samples; an interval with one end out of contact ends at the interpolated
    /// edge, where φ = 0; the outer half-widths of the first and last sample count fully).
    ///
    /// Why soft: the plain measure of {h > 0} is continuous but has an unbounded slope where a gap
    /// of the contact set closes at a flat saddle (the edges move by δy/h_i per unit change of the
    /// neighbour's h, h_i the small depth beside the gap) — S1002/UIC60 1360 mm, 83.3 kN,
    /// `interaction` on: both basins' l₀ rose 3.4 % within 3e-5 mm of shift at dy 4.61985 mm as
    /// the floored valley closed, an area step the per-wheel continuity test flags as a jump, and
    /// the wheel load loop missed its tolerance there. With φ the slope is bounded by
    /// δy/(2 h_ref). Where h ≥ h_ref the measure is unchanged; a Hertzian gap has a constant B,
    /// so its filter (and result) does not depend on l₀.
    fn basin_extents(&mut self, samples: &[StripSample<T>], soft: T) {
        let nb = self.nb;
        for k in 0..nb {
            self.basins[k].len = T::ZERO;
        }
        let n = self.n;
        if n == 0 {
            return;
        }
        let href = soft * math::abs(self.delta_last);
        let phi = |h: T| -> T {
            if h <= T::ZERO {
                T::ZERO
            } else if h >= href {
                T::ONE
            } else {
                h / href
            }
        };
        // φ at an interpolated edge: 0 (soft), 1 with `soft` = 0 (the plain measure, edge to edge)
        let phi_edge = if href > T::ZERO { T::ZERO } else { T::ONE };
        // adds w·ω_m to the basins of sample m
        let add = |basins: &mut [Basin<T>], zone: &[u8], sw: &[T], m: usize, w: T| {
            let k = usize::from(zone[m]).min(nb - 1);
            let k1 = (k + 1).min(nb - 1);
            let s = sw[m];
            basins[k].len += w * (T::ONE - s);
            basins[k1].len += w * s;
        };
        if self.hu[0] > T::ZERO {
            let w = T::HALF * samples[0].dy * phi(self.hu[0]);
            add(&mut self.basins, &self.zone, &self.sw, 0, w);
        }
        if self.hu[n - 1] > T::ZERO {
            let w = T::HALF * samples[n - 1].dy * phi(self.hu[n - 1]);
            add(&mut self.basins, &self.zone, &self.sw, n - 1, w);
        }
        for i in 0..n - 1 {
            let (h0, h1) = (self.hu[i], self.hu[i + 1]);
            let dy = self.y[i + 1] - self.y[i];
            if h0 > T::ZERO && h1 > T::ZERO {
                let (w0, w1) = (T::HALF * dy * phi(h0), T::HALF * dy * phi(h1));
                add(&mut self.basins, &self.zone, &self.sw, i, w0);
                add(&mut self.basins, &self.zone, &self.sw, i + 1, w1);
            } else if h0 > T::ZERO || h1 > T::ZERO {
                // the contact end (i or i + 1) to the edge at fraction t of the interval from it;
                // trapezoid of φ·ω: ½·t·δy·φ_end·ω_end (φ = 0 at the edge)
                let (m, hm, ho) = if h0 > T::ZERO {
                    (i, h0, h1)
                } else {
                    (i + 1, h1, h0)
                };
                let t = hm / (hm - ho);
                let w = T::HALF * t * dy * (phi(hm) + phi_edge);
                add(&mut self.basins, &self.zone, &self.sw, m, w);
            }
        }
    }

    /// Lays out evenly spaced strips over each region of `sol` (`per_region` each, at least
    /// [`MIN_STRIPS_PER_REGION`]; fewer per region if the capacity `S` is short, error if it cannot
    /// hold the minimum), interpolates the sample quantities linearly and solves the load control
    /// again on the strips (same partition and reference levels).
    pub fn layout<const S: usize>(
        &self,
        sol: &StripesSolution<T, NR>,
        samples: &[StripSample<T>],
        load: T,
        per_region: usize,
        out: &mut StripSet<T, S, NR>,
    ) -> Result<(), Error> {
        let nr = sol.n_regions;
        if nr == 0 || self.n < 2 || samples.len() != self.n {
            return Err(Error::NoContact);
        }
        // `sol` has public fields: a region count beyond its array is a typed error, not an
        // out-of-bounds index.
        if nr > NR {
            return Err(Error::TooManyRegions);
        }
        if per_region < MIN_STRIPS_PER_REGION {
            return Err(Error::GridTooSmall("strips per region"));
        }
        let per = per_region.min(S / nr);
        if per < MIN_STRIPS_PER_REGION {
            return Err(Error::GridTooSmall("strip capacity"));
        }
        let mut j = 0usize;
        for r in 0..nr {
            let reg = sol.regions[r];
            let width = reg.y_hi - reg.y_lo;
            let dy = width / T::from_usize(per);
            out.regions[r] = RegionSummary {
                y_lo: reg.y_lo,
                y_hi: reg.y_hi,
                first: j,
                count: per,
                ..RegionSummary::default()
            };
            let mut i = 0usize; // bracket search start (samples ascending)
            for q in 0..per {
                let y = reg.y_lo + (T::from_usize(q) + T::HALF) * dy;
                let (i0, i1, t) = self.bracket(y, &mut i);
                let lerp = |v: &[T; NS]| v[i0] + t * (v[i1] - v[i0]);
                out.y[j] = y;
                out.dy[j] = dy;
                out.xc[j] = samples[i0].xc + t * (samples[i1].xc - samples[i0].xc);
                out.curv_a[j] = samples[i0].curv_a + t * (samples[i1].curv_a - samples[i0].curv_a);
                out.curv_bf[j] = lerp(&self.bf);
                out.n_over_m[j] = lerp(&self.nm);
                out.stiffness[j] = lerp(&self.kst);
                out.a_tilde[j] = lerp(&self.at);
                out.region[j] = r as u8;
                // temporaries for the re-solve: store in h (z), pmax (zref), a (e) until solved
                out.h[j] = lerp(&self.z) + lerp(&self.uz);
                out.pmax[j] = lerp(&self.zref);
                out.a[j] = lerp(&self.e);
                j += 1;
            }
        }
        out.n_strips = j;
        out.n_regions = nr;
        // Re-solve on the strips.
        let lc = {
            let (z, zref, e, dyv) = (&out.h, &out.pmax, &out.a, &out.dy);
            let kst = &out.stiffness;
            solve_piecewise_linear(j, load, None, |q| {
                (kst[q] * dyv[q] * e[q], zref[q] + (z[q] - zref[q]) / e[q])
            })?
        };
        out.delta = lc.delta;
        out.iterations = lc.iterations;
        out.converged = lc.converged;
        out.total_load = T::ZERO;
        out.total_area = T::ZERO;
        out.total_pmax = T::ZERO;
        let two_over_pi = c::<T>(2.0 / core::f64::consts::PI);
        for q in 0..j {
            let (kst, at) = (out.stiffness[q], out.a_tilde[q]);
            let (z, zref, e) = (out.h[q], out.pmax[q], out.a[q]);
            let h = math::max(e * (lc.delta - zref) - (z - zref), T::ZERO);
            out.h[q] = h;
            if h > T::ZERO {
                out.a[q] = math::sqrt(h / at);
                out.pmax[q] = two_over_pi * kst * math::sqrt(h * at);
            } else {
                out.a[q] = T::ZERO;
                out.pmax[q] = T::ZERO;
            }
            let r = usize::from(out.region[q]);
            let f = kst * h * out.dy[q];
            let area = T::TWO * out.a[q] * out.dy[q];
            let reg = &mut out.regions[r];
            reg.load += f;
            reg.area += area;
            reg.pmax = math::max(reg.pmax, out.pmax[q]);
            reg.a_max = math::max(reg.a_max, out.a[q]);
            out.total_load += f;
            out.total_area += area;
            out.total_pmax = math::max(out.total_pmax, out.pmax[q]);
        }
        Ok(())
    }

    /// Interpolation bracket of lateral position `y` among the last solve's samples (n ≥ 2): the
    /// samples (i0, i1 = i0 + 1) around it and the weight t of i1, clamped to [0, 1] at the ends.
    /// The search runs forward from `i` (ascending `y` between calls).
    fn bracket(&self, y: T, i: &mut usize) -> (usize, usize, T) {
        while *i + 2 < self.n && self.y[*i + 1] < y {
            *i += 1;
        }
        let (i0, i1) = (*i, *i + 1);
        let t = math::clamp(
            (y - self.y[i0]) / (self.y[i1] - self.y[i0]),
            T::ZERO,
            T::ONE,
        );
        (i0, i1, t)
    }

    /// The last solve's local quantities at lateral position `y` (linear between samples,
    /// clamped at the ends): (B_f, n/m, Ã, strip stiffness). `i` is the bracket search start
    /// (samples ascending; pass 0 or the previous call's value for ascending `y`).
    pub(crate) fn local_at(&self, y: T, i: &mut usize) -> (T, T, T, T) {
        if self.n < 2 {
            return (T::ZERO, T::ONE, T::ZERO, T::ZERO);
        }
        if *i + 1 >= self.n || self.y[*i] >= y {
            *i = 0;
        }
        let (i0, i1, t) = self.bracket(y, i);
        let lerp = |v: &[T; NS]| v[i0] + t * (v[i1] - v[i0]);
        (
            lerp(&self.bf),
            lerp(&self.nm),
            lerp(&self.at),
            lerp(&self.kst),
        )
    }
}
