//! The default per-patch pipeline: STRIPES normal contact → non-elliptic adaptation → FASTSIM or
//! FaStrip → KTH wear, on a caller-owned, const-constructible [`Workspace`].
//!
//! Input: the fine lateral samples of one contact patch in its contact frame ([`StripSample`], see
//! [`samples_from_arrays`] for the adapter from geometry's per-patch arrays), the patch's normal
//! load and creepages. Each region (connected component of the STRIPES contact set) gets its own
//! strips (32 by default, ≥ 8) and cells (32 along x), its own adaptation and tangential solve; the
//! totals are summed. Per-cell results go only to the caller's [`CellSink`] (strip index = the
//! global strip index of [`StripSet`]); wear per strip accumulates in the workspace.
//!
//! **Neck blend** (continuity where regions merge or split): when a region of STRIPES' fine
//! solution has a neck (strip depth at a local minimum below ¼ of the lower neighbouring peak),
//! the patch is solved both as is and with that region split at the neck, and the results are
//! blended with a weight that is 1 when the neck closes (the split layout then equals the
//! two-region layout) and 0 at the ratio ¼ (see `neck`). Without it the per-region strip layout
//! changes at once at a merge (32 + 32 strips → 32) and pmax, area and forces jump (up to 2.5 %
//! on the S1002/UIC60 sweep). In the blend zone the tangential solve runs twice; the cells sent
//! to the sink, the workspace's strips and wear, strip indices and cell counts are those of the
//! layout with the larger weight, the forces, loads, areas and pressures the blend.
//!
//! Defaults ([`PipelineConfig::recommended`]): STRIPES `EpsLocal` + `PatchFraction(0.25)` (evidence in
//! [`StripesConfig::recommended`]; the spec suggested `EpsSmoothed(2 mm)`)
//! (methods.md §6 item 11 and the Manchester evidence), Ayasse–Chollet `StripA` reference ellipses with FaStrip (§5.3), FaStrip's
//! `Contact5` large-spin rule and μp_n slip zone (§4.2), 32 strips × 32 cells per region (§0.5).

use crate::adapt::{self, Adaptation, LocalEllipse, Method};
use crate::error::{check_positive, Error};
use crate::math::{self, c};
use crate::patch::{CellOut, CellSink, Creepage, SemiEllipticStrips, Totals, TractionBound};
use crate::ritz::{RitzConfig, RitzStrips};
use crate::stripes::{StripSample, StripSet, Stripes, StripesConfig, StripesSolution};
use crate::wear::{StripWear, WearMap};
use crate::{Material, Real};

/// Pipeline options.
#[derive(Clone, Copy, Debug)]
pub struct PipelineConfig<T> {
    /// STRIPES options.
    pub stripes: StripesConfig<T>,
    /// Flexibility / reference-ellipse approach.
    pub adapt: Adaptation<T>,
    /// Tangential method.
    pub method: Method,
    /// FASTSIM traction bound; `None` = the approach's default (§3.2).
    pub bound: Option<TractionBound<T>>,
    /// Strips per region (≥ 8).
    pub strips_per_region: usize,
    /// Coefficient of friction μ.
    pub mu: T,
    /// Rolling speed V, mm/s (for the wear map's sliding velocity).
    pub speed: T,
    /// Wear map.
    pub wear: WearMap<T>,
}

impl<T: Real> PipelineConfig<T> {
    /// The kernel's defaults (module docs) with friction `mu` and speed `speed` (mm/s).
    pub fn recommended(mu: T, speed: T) -> Self {
        Self {
            stripes: StripesConfig::recommended(),
            adapt: Adaptation::recommended(),
            method: Method::Fastrip,
            bound: None,
            strips_per_region: crate::stripes::DEFAULT_STRIPS_PER_REGION,
            mu,
            speed,
            wear: WearMap::kth(),
        }
    }
}

/// Per-region result.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct RegionResult<T> {
    /// Lateral limits of the region, mm (contact frame).
    pub y_lo: T,
    /// Upper lateral limit, mm.
    pub y_hi: T,
    /// First global strip index and number of strips.
    pub first: usize,
    /// Number of strips.
    pub count: usize,
    /// Normal force, N.
    pub load: T,
    /// Peak pressure, MPa.
    pub pmax: T,
    /// Contact area, mm².
    pub area: T,
    /// Tangential totals (F_x, F_y on the wheel, N; M_z about the frame origin, N·mm; cell counts).
    pub totals: Totals<T>,
    /// Largest strip wear depth per passage, mm.
    pub wear_max: T,
}

/// More regions than a [`PatchResult`] holds (the strip set has more than `NR`).
const REGIONS_FULL: Error = Error::OutOfRange("regions exceed the result's capacity");

/// Result of one patch.
#[derive(Clone, Debug, PartialEq)]
pub struct PatchResult<T, const NR: usize> {
    /// The contact regions, in the order of the strip set (at most `NR`).
    pub regions: heapless::Vec<RegionResult<T>, NR>,
    /// Sum over regions.
    pub totals: Totals<T>,
    /// Normal approach of the STRIPES solution (from the deepest sample), mm.
    pub approach: T,
    /// Total contact area, mm².
    pub area: T,
    /// Peak pressure, MPa.
    pub pmax: T,
    /// STRIPES load-control steps (fine passes + strip re-solve).
    pub iterations: u32,
    /// All STRIPES solves converged.
    pub converged: bool,
}

/// Caller-owned workspace: `NS` fine samples, `NR` regions, `S` strips and `C` cells per region,
/// `SS` strips in total (≥ NR·8; `S·NR` to give every region its full count).
#[derive(Clone, Debug)]
pub struct Workspace<
    T,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
> {
    /// STRIPES solver state.
    pub stripes: Stripes<T, NS, 8, NR>,
    /// Strips of the last call.
    pub set: StripSet<T, SS, NR>,
    /// Wear per strip of the last call (global strip index).
    pub wear: StripWear<T, SS>,
    local: [LocalEllipse<T>; S],
}

/// The default workspace: 256 samples, 4 regions, 32 strips × 32 cells per region.
pub type DefaultWorkspace<T> = Workspace<T, 256, 4, 32, 32, 128>;

impl<
        T: Real,
        const NS: usize,
        const NR: usize,
        const S: usize,
        const C: usize,
        const SS: usize,
    > Workspace<T, NS, NR, S, C, SS>
{
    /// Empty workspace (const: can live in a `static`).
    pub const fn new() -> Self {
        Self {
            stripes: Stripes::new(),
            set: StripSet::new(),
            wear: StripWear::new(),
            local: [LocalEllipse {
                n_over_m: T::ZERO,
                a_tilde: T::ZERO,
            }; S],
        }
    }
}

impl<
        T: Real,
        const NS: usize,
        const NR: usize,
        const S: usize,
        const C: usize,
        const SS: usize,
    > Default for Workspace<T, NS, NR, S, C, SS>
{
    fn default() -> Self {
        Self::new()
    }
}

/// Forwards cells with the strip index offset by `first` and accumulates the wear of slipping
/// cells (if `WEAR`) at strip `wear_first + j` (the per-patch pipeline and the real-time step's
/// cells, [`crate::step::step_cells`]).
pub(crate) struct RegionSink<'a, T, K, const SS: usize, const WEAR: bool> {
    pub(crate) inner: &'a mut K,
    pub(crate) wear: &'a mut StripWear<T, SS>,
    pub(crate) map: &'a WearMap<T>,
    pub(crate) first: usize,
    pub(crate) wear_first: usize,
    pub(crate) speed: T,
    pub(crate) dx: T,
}

impl<T: Real, K: CellSink<T>, const SS: usize, const WEAR: bool> CellSink<T>
    for RegionSink<'_, T, K, SS, WEAR>
{
    #[inline]
    fn cell(&mut self, j: usize, i: usize, out: &CellOut<T>) {
        if WEAR && out.slip {
            let s = math::hypot_fast(out.sx, out.sy);
            self.wear.add_cell(
                self.map,
                self.wear_first + j,
                out.pn,
                s,
                self.speed,
                self.dx,
            );
        }
        self.inner.cell(self.first + j, i, out);
    }
}

/// Converts geometry's per-patch arrays (sample coordinate s_i, width, normal separation f_n,
/// curvatures A, B) into STRIPES samples in `out`; returns the count. x_c = 0 (yaw's longitudinal
/// asymmetry is not modelled, methods.md §7.3).
pub fn samples_from_arrays<T: Real>(
    s: impl Fn(usize) -> T,
    width: &[T],
    f_n: &[T],
    a_long: &[T],
    b_lat: &[T],
    n: usize,
    out: &mut [StripSample<T>],
) -> Result<usize, Error> {
    let n = n
        .min(width.len())
        .min(f_n.len())
        .min(a_long.len())
        .min(b_lat.len());
    if n > out.len() {
        return Err(Error::OutOfRange("samples exceed capacity"));
    }
    for i in 0..n {
        out[i] = StripSample {
            y: s(i),
            dy: width[i],
            z: f_n[i],
            curv_a: a_long[i],
            curv_b: b_lat[i],
            xc: T::ZERO,
        };
    }
    Ok(n)
}

/// Runs the pipeline on one patch: `samples` (fine lateral samples in the contact frame), normal
/// load `load` (N), creepages `cr`; every contact cell goes to `sink` (`&mut ()` for none).
///
/// Errors: those of STRIPES, the adaptation and the tangential solver; `NonFinite("wear depth")`
/// if the wear map overflows (the cells already sent to `sink` stay sent).
#[inline(never)]
#[allow(clippy::too_many_arguments)]
pub fn solve_patch<
    T: Real,
    K: CellSink<T>,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
>(
    samples: &[StripSample<T>],
    load: T,
    cr: &Creepage<T>,
    mat: &Material<T>,
    cfg: &PipelineConfig<T>,
    ws: &mut Workspace<T, NS, NR, S, C, SS>,
    sink: &mut K,
) -> Result<PatchResult<T, NR>, Error> {
    solve_patch_impl::<T, K, NS, NR, S, C, SS, true>(samples, load, cr, mat, cfg, ws, sink)
}

/// [`solve_patch`] for the forces only: no cells leave, and the wear is not computed (every
/// region's `wear_max` is 0, the workspace's wear stays cleared). Everything else — STRIPES, the
/// adaptation, the tangential solve, the totals — is the same computation, bit for bit. For
/// iterations that use only the totals (e.g. the normal–tangential coupling rounds of a wheel
/// solve), where the per-cell wear of every slipping cell would be wasted work.
///
/// Errors: as [`solve_patch`] except the wear-depth overflow.
#[inline(never)]
pub fn solve_patch_forces<
    T: Real,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
>(
    samples: &[StripSample<T>],
    load: T,
    cr: &Creepage<T>,
    mat: &Material<T>,
    cfg: &PipelineConfig<T>,
    ws: &mut Workspace<T, NS, NR, S, C, SS>,
) -> Result<PatchResult<T, NR>, Error> {
    solve_patch_impl::<T, (), NS, NR, S, C, SS, false>(samples, load, cr, mat, cfg, ws, &mut ())
}

/// [`solve_patch`] with the strip model ([`crate::ritz`]) as the normal solve: STRIPES first
/// (its contact set, approach and local Hertz quantities start the strip model), then the strip
/// model's loads and half-lengths on the caller's `rz` (capacity `RN` strips), laid out on the
/// pipeline's strips ([`RitzStrips::layout`]) for the adaptation, the tangential solve and the
/// wear. `PatchResult::approach` is the strip model's, `iterations` adds its active-set steps.
/// No neck blend: the strip model's load varies continuously across a neck.
///
/// Errors: those of [`solve_patch`] and of [`RitzStrips::solve`] / [`RitzStrips::layout`].
#[inline(never)]
#[allow(clippy::too_many_arguments)]
pub fn solve_patch_strip_model<
    T: Real,
    K: CellSink<T>,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
    const RN: usize,
>(
    samples: &[StripSample<T>],
    load: T,
    cr: &Creepage<T>,
    mat: &Material<T>,
    cfg: &PipelineConfig<T>,
    rcfg: &RitzConfig<T>,
    ws: &mut Workspace<T, NS, NR, S, C, SS>,
    rz: &mut RitzStrips<T, RN>,
    sink: &mut K,
) -> Result<PatchResult<T, NR>, Error> {
    check_inputs(cfg, cr)?;
    let sol: StripesSolution<T, NR> = ws.stripes.solve(samples, load, mat, &cfg.stripes)?;
    let rs = rz.solve(samples, &ws.stripes, &sol, load, mat, rcfg)?;
    let per = cfg.strips_per_region.min(S);
    rz.layout(samples, &ws.stripes, &rs, per, &mut ws.set)?;
    tangential_on_set::<T, K, NS, NR, S, C, SS, true>(
        sol.iterations,
        sol.converged,
        cr,
        mat,
        cfg,
        ws,
        sink,
    )
}

#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn solve_patch_impl<
    T: Real,
    K: CellSink<T>,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
    const WEAR: bool,
>(
    samples: &[StripSample<T>],
    load: T,
    cr: &Creepage<T>,
    mat: &Material<T>,
    cfg: &PipelineConfig<T>,
    ws: &mut Workspace<T, NS, NR, S, C, SS>,
    sink: &mut K,
) -> Result<PatchResult<T, NR>, Error> {
    check_inputs(cfg, cr)?;
    let sol: StripesSolution<T, NR> = ws.stripes.solve(samples, load, mat, &cfg.stripes)?;
    // Neck blend (continuity where regions merge or split, see `neck`): near a neck the patch is
    // solved on both layouts, the one with the larger weight last and with the caller's sink.
    if let Some((ri, ys, w)) = neck(&ws.stripes, &sol, samples) {
        let mut alt = sol;
        alt.n_regions = sol.n_regions + 1;
        for q in (ri + 1..sol.n_regions).rev() {
            alt.regions[q + 1] = sol.regions[q];
        }
        alt.regions[ri].y_hi = ys;
        alt.regions[ri + 1] = sol.regions[ri];
        alt.regions[ri + 1].y_lo = ys;
        let (m, a) = if w >= c::<T>(0.5) {
            let m = layout_and_tangential::<T, _, NS, NR, S, C, SS, WEAR>(
                &sol,
                samples,
                load,
                cr,
                mat,
                cfg,
                ws,
                &mut (),
            )?;
            let a = layout_and_tangential::<T, _, NS, NR, S, C, SS, WEAR>(
                &alt, samples, load, cr, mat, cfg, ws, sink,
            )?;
            (m, a)
        } else {
            let a = layout_and_tangential::<T, _, NS, NR, S, C, SS, WEAR>(
                &alt,
                samples,
                load,
                cr,
                mat,
                cfg,
                ws,
                &mut (),
            )?;
            let m = layout_and_tangential::<T, _, NS, NR, S, C, SS, WEAR>(
                &sol, samples, load, cr, mat, cfg, ws, sink,
            )?;
            (m, a)
        };
        return Ok(blend(&m, &a, ri, w));
    }
    layout_and_tangential::<T, _, NS, NR, S, C, SS, WEAR>(
        &sol, samples, load, cr, mat, cfg, ws, sink,
    )
}

/// The per-patch inputs both solves check before STRIPES: μ and speed positive, finite
/// creepages, a valid wear map.
fn check_inputs<T: Real>(cfg: &PipelineConfig<T>, cr: &Creepage<T>) -> Result<(), Error> {
    check_positive(cfg.mu, "mu")?;
    check_positive(cfg.speed, "speed")?;
    cr.check()?;
    cfg.wear.validate()
}

/// Below this neck ratio r = h_neck / min(left peak, right peak) of the fine solution's strip
/// depth, a region is also solved split at its neck and the results are blended.
const NECK_RATIO: f64 = 0.25;

/// The most pronounced neck of the fine solution's regions, if any below [`NECK_RATIO`] and there
/// is room for one more region: (region index, split position y_s (mm), weight w of the split
/// layout).
///
/// Why: the strips are laid out evenly per connected region (`Stripes::layout`), so where two
/// regions merge or one splits the layout changes at once (32 + 32 strips → 32) while the fine
/// solution is continuous; pmax, area and forces then jump (S1002/UIC60 1360 mm 83.3 kN,
/// dy 4.6126→4.6138: pmax −2.5 %, area −0.75 %, F_x +58 N). Near a neck the patch is solved on
/// both layouts and blended with w = 1 − s(r/[`NECK_RATIO`]), s(x) = 3x² − 2x³, where for each
/// sample i inside the region r_i = h_i / min(L_i, R_i) (L_i, R_i: largest depth on its left and
/// right within the region; r_i = 1 on a flank) and r = min r_i — continuous in the data, 0 when
/// the region is about to split or has just merged, so that the split layout then coincides with
/// the two-region layout. The split position is the weighted centroid y_s = Σ ω_i y_i / Σ ω_i,
/// ω_i = max(0, 1 − r_i/(2r)), also continuous, and → the sample where the contact breaks as
/// r → 0. One neck per patch (the smallest r); none when the region capacity `NR` is full.
fn neck<T: Real, const NS: usize, const NR: usize>(
    st: &Stripes<T, NS, 8, NR>,
    sol: &StripesSolution<T, NR>,
    samples: &[StripSample<T>],
) -> Option<(usize, T, T)> {
    if sol.n_regions >= NR {
        return None;
    }
    let r0 = c::<T>(NECK_RATIO);
    let n = samples.len();
    // r_i for the interior samples of [lo, hi]: with the region's peak at p, L_i ≤ R_i = peak
    // left of p and R_i ≤ L_i right of it, so two running maxima give min(L_i, R_i) in O(n).
    let each = |lo: usize, hi: usize, f: &mut dyn FnMut(usize, T)| {
        let mut p = lo;
        for i in lo..=hi {
            if st.depth(i) > st.depth(p) {
                p = i;
            }
        }
        let mut run = T::ZERO;
        for i in lo..p {
            let h = st.depth(i);
            run = math::max(run, h);
            if i > lo && run > T::ZERO {
                f(i, h / run);
            }
        }
        run = T::ZERO;
        for i in (p + 1..=hi).rev() {
            let h = st.depth(i);
            run = math::max(run, h);
            if i < hi && run > T::ZERO {
                f(i, h / run);
            }
        }
    };
    let mut best: Option<(usize, T)> = None;
    for (k, reg) in sol.regions[..sol.n_regions].iter().enumerate() {
        if reg.count < 3 || reg.first + reg.count > n {
            continue;
        }
        each(reg.first, reg.first + reg.count - 1, &mut |_, r| {
            if r < r0 && best.is_none_or(|(_, b)| r < b) {
                best = Some((k, r));
            }
        });
    }
    let (k, r) = best?;
    let reg = sol.regions[k];
    let (mut sw, mut swy) = (T::ZERO, T::ZERO);
    each(reg.first, reg.first + reg.count - 1, &mut |i, ri| {
        let om = if r > T::ZERO {
            math::max(T::ZERO, T::ONE - ri / (T::TWO * r))
        } else if ri <= T::ZERO {
            T::ONE
        } else {
            T::ZERO
        };
        sw += om;
        swy += om * samples[i].y;
    });
    if sw <= T::ZERO || !math::is_finite(sw) {
        return None;
    }
    let ys = swy / sw;
    if !(ys > reg.y_lo && ys < reg.y_hi) {
        return None;
    }
    let x = r / r0;
    let w = T::ONE - x * x * (c::<T>(3.0) - T::TWO * x);
    if w > T::ZERO {
        Some((k, ys, w))
    } else {
        None
    }
}

/// (1 − w)·merged + w·split, the split layout's regions `ri`, `ri`+1 combined into region `ri`;
/// strip indices, cell counts and iterations from the layout with the larger weight (the one
/// whose strips and cells the workspace and the sink hold).
fn blend<T: Real, const NR: usize>(
    m: &PatchResult<T, NR>,
    a: &PatchResult<T, NR>,
    ri: usize,
    w: T,
) -> PatchResult<T, NR> {
    let v = T::ONE - w;
    let mix = |x: T, y: T| v * x + w * y;
    let mix_t = |x: &Totals<T>, y: &Totals<T>, dominant_split: bool| Totals {
        fx: mix(x.fx, y.fx),
        fy: mix(x.fy, y.fy),
        mz: mix(x.mz, y.mz),
        fn_: mix(x.fn_, y.fn_),
        n_contact: if dominant_split {
            y.n_contact
        } else {
            x.n_contact
        },
        n_slip: if dominant_split { y.n_slip } else { x.n_slip },
    };
    let split = w >= c::<T>(0.5);
    let mut out = m.clone();
    for q in 0..m.regions.len() {
        let mq = m.regions[q];
        let aq = if q < ri {
            a.regions[q]
        } else if q == ri {
            let (p0, p1) = (a.regions[ri], a.regions[ri + 1]);
            let mut t = p0.totals;
            t.merge(&p1.totals);
            RegionResult {
                y_lo: p0.y_lo,
                y_hi: p1.y_hi,
                first: p0.first,
                count: p0.count + p1.count,
                load: p0.load + p1.load,
                pmax: math::max(p0.pmax, p1.pmax),
                area: p0.area + p1.area,
                totals: t,
                wear_max: math::max(p0.wear_max, p1.wear_max),
            }
        } else {
            a.regions[q + 1]
        };
        let d = if split { aq } else { mq };
        out.regions[q] = RegionResult {
            y_lo: mq.y_lo,
            y_hi: mq.y_hi,
            first: d.first,
            count: d.count,
            load: mix(mq.load, aq.load),
            pmax: mix(mq.pmax, aq.pmax),
            area: mix(mq.area, aq.area),
            totals: mix_t(&mq.totals, &aq.totals, split),
            wear_max: mix(mq.wear_max, aq.wear_max),
        };
    }
    out.totals = mix_t(&m.totals, &a.totals, split);
    out.approach = mix(m.approach, a.approach);
    out.area = mix(m.area, a.area);
    out.pmax = mix(m.pmax, a.pmax);
    out.iterations = m.iterations + a.iterations;
    out.converged = m.converged && a.converged;
    out
}

/// Strip layout of `sol`, adaptation and tangential solve per region, wear (if `WEAR`).
#[allow(clippy::too_many_arguments)]
fn layout_and_tangential<
    T: Real,
    K: CellSink<T>,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
    const WEAR: bool,
>(
    sol: &StripesSolution<T, NR>,
    samples: &[StripSample<T>],
    load: T,
    cr: &Creepage<T>,
    mat: &Material<T>,
    cfg: &PipelineConfig<T>,
    ws: &mut Workspace<T, NS, NR, S, C, SS>,
    sink: &mut K,
) -> Result<PatchResult<T, NR>, Error> {
    let per = cfg.strips_per_region.min(S);
    ws.stripes.layout(sol, samples, load, per, &mut ws.set)?;
    tangential_on_set::<T, K, NS, NR, S, C, SS, WEAR>(
        sol.iterations,
        sol.converged,
        cr,
        mat,
        cfg,
        ws,
        sink,
    )
}

/// Adaptation, tangential solve and wear (if `WEAR`) per region of the strips in `ws.set`;
/// `iterations`/`converged` of the normal solve that produced them are added to the set's own.
#[allow(clippy::too_many_arguments)]
fn tangential_on_set<
    T: Real,
    K: CellSink<T>,
    const NS: usize,
    const NR: usize,
    const S: usize,
    const C: usize,
    const SS: usize,
    const WEAR: bool,
>(
    iterations: u32,
    converged: bool,
    cr: &Creepage<T>,
    mat: &Material<T>,
    cfg: &PipelineConfig<T>,
    ws: &mut Workspace<T, NS, NR, S, C, SS>,
    sink: &mut K,
) -> Result<PatchResult<T, NR>, Error> {
    ws.wear.clear();
    let bound = cfg.bound.unwrap_or(cfg.adapt.default_bound());
    let mut res = PatchResult {
        regions: heapless::Vec::new(),
        totals: Totals::default(),
        approach: ws.set.delta,
        area: ws.set.total_area,
        pmax: ws.set.total_pmax,
        iterations: iterations + ws.set.iterations,
        converged: converged && ws.set.converged,
    };
    for r in 0..ws.set.n_regions {
        let reg = ws.set.regions[r];
        // the region's place in the strip set; the rest 0 until solved
        let placed = RegionResult {
            y_lo: reg.y_lo,
            y_hi: reg.y_hi,
            first: reg.first,
            count: reg.count,
            ..RegionResult::default()
        };
        // A sliver region of the fine solution (e.g. one sample wide at the edge of the overlap)
        // can lose its contact in the re-solve on the evenly spaced strips: it carries nothing,
        // and the rest of the patch is solved as usual (no NoContact for the whole patch).
        if reg.load <= T::ZERO {
            res.regions.push(placed).map_err(|_| REGIONS_FULL)?;
            continue;
        }
        let patch =
            adapt::region_patch::<T, S, C, SS, NR>(&ws.set, r, &cfg.adapt, mat, &mut ws.local)?;
        let mut rs = RegionSink::<T, K, SS, WEAR> {
            inner: sink,
            wear: &mut ws.wear,
            map: &cfg.wear,
            first: reg.first,
            wear_first: reg.first,
            speed: cfg.speed,
            dx: patch.dx,
        };
        let t = adapt::solve_tangential(
            &patch,
            &SemiEllipticStrips,
            cr,
            cfg.method,
            bound,
            cfg.mu,
            &mut rs,
        )?;
        let mut wmax = T::ZERO;
        for j in reg.first..reg.first + reg.count {
            if let Some(d) = ws.wear.depth.get(j) {
                // A wear map that validates (finite, positive entries) can still overflow
                // k·p·|s|·δx/H (e.g. k = 1e307 with H = 1e-6): a typed error, not ∞/NaN wear.
                if !math::is_finite(*d) {
                    return Err(Error::NonFinite("wear depth"));
                }
                wmax = math::max(wmax, *d);
            }
        }
        res.regions
            .push(RegionResult {
                load: reg.load,
                pmax: reg.pmax,
                area: reg.area,
                totals: t.total,
                wear_max: wmax,
                ..placed
            })
            .map_err(|_| REGIONS_FULL)?;
        res.totals.merge(&t.total);
    }
    Ok(res)
}
