//! Wheel/rail case sets and the NORM reference on the kernel's contact patches (issues 4 and 6).
//!
//! * [`sweep_cases`]: the S1002/UIC60 lateral-shift sweep of issue 6 (An et al. 2019): right and
//!   left wheel, back-to-back 1353 and 1360 mm, shift dy = −3…6 mm **towards the analysed wheel**
//!   in 1 mm steps, yaw 1.2 × dy mrad (same sense), the two-wheel equilibrium roll (methods.md §7.2
//!   step 5, as `tests/pipeline_sweep.rs`), the given vertical wheel loads: 2 × 2 × 10 = 40
//!   cases per load, 120 for the loads 40, 83.3 and 120 kN ([`SWEEP_LOADS`]).
//!   [`transition_cases`] adds shifts between the integer ones where the contact changes character
//!   (patches or regions appear, split or merge), found by bisection on the kernel's own solve.
//! * [`mbench_rows`]: the 42 Manchester rows of CONTACT's exact solutions
//!   (`contact_reference/mbench_a22_exact.csv`, 10 kN), one reader for every test.
//! * [`solve_case`]: the kernel's per-wheel solve (`wrc_kernel::wheel::solve_wheel`, f64) and,
//!   for every contact patch it reports, Kalker's NORM ([`crate::norm`]) on the same patch's gap,
//!   load-controlled to the same patch normal load: STRIPES against the exact half-space solution
//!   with geometry, frame, load split and creepages held equal.
//!
//! # The NORM gap of a patch (methods.md §7.3, §9.1)
//! The geometry is evaluated again at the vertical approach δ_v of the kernel's patches with
//! [`GAP_SAMPLES`] samples per patch (`contact_patches`; the frame does not depend on the sample
//! count, and each recomputed frame is checked to equal the kernel's). Per sample s: the normal
//! separation f_n(s), the longitudinal curvature A(s) and the rigid-contact offset x_c(s) (yaw).
//! NORM takes h(x, s) = f_n(s) + A(s)(x − x_c(s))² at the element centres, with f_n interpolated
//! by a cubic (Catmull–Rom) and A, x_c linearly between samples (norm_mbench uses the same gap with
//! linear f_n).
//!
//! # Grid (choice, documented)
//! * Element size δ = δx = δy = min([`NormGridOptions::max_element`] (0.2 mm, CONTACT's grid in
//!   the runs), min(a_c, b_c)/[`NormGridOptions::per_semi_axis`] (15)), not below
//!   [`NormGridOptions::min_element`] (0.04 mm). a_c, b_c are contact semi-axis estimates from
//!   the rigid overlap at the kernel's approach δ₀ (a contact patch is ≈ 1/√2 of the overlap on a
//!   Hertzian gap): a_c = √(δ₀/A₀)/√2 at the deepest sample, b_c = half the lateral width of the
//!   widest overlap run/√2. NORM's Hertz error at 15 elements per semi-axis is ≈ 0.5 % in p0
//!   (methods.md §9.1 table: 1 % at 10, 0.3 % at 20). The 0.2 mm cap keeps large tread patches at
//!   CONTACT's resolution.
//! * Extent: the rows where f_n(s) < `level`·δ₀ and, per row, |x − x_c| < √((level·δ₀ − f_n)/A),
//!   one element more on every side, level = 1.25 (NORM's contact set lies inside {h < δ_NORM},
//!   and δ_NORM differs from STRIPES' δ₀ by a few per cent). If the solution touches the grid's
//!   outer ring, the level is raised by 1.5× and the solve repeated (at most 3 times).
//! * Area = number of contact elements × δ², as CONTACT reports it (ncon·δxδy); pmax = largest
//!   element pressure.
//!
//! For the tangential study: [`PatchCase::norm`] carries the NORM pressure per element and per
//! strip (grid row) with its contact runs, [`PatchCase::creepage`] the creepages the kernel used,
//! [`PatchCase::stripes_samples`] the kernel's own STRIPES input (to rerun other pipeline
//! configurations on exactly the kernel's samples).

use crate::data::data_file;
use crate::norm::{self, Control, Grid, NormSolution};
use crate::profiles::{self, SmoothOptions};
use std::path::Path;
use wrc_kernel::adapt::{self, Adaptation, LocalEllipse, Method};
use wrc_kernel::geometry::{
    contact_patches, equilibrium_roll, Patch, PatchFrame, PatchOptions, Patches, Side, TrackSetup,
    WheelRail, WheelsetPose,
};
use wrc_kernel::patch::{CellPressure, CellSink, Creepage, Strip, StripPatch};
use wrc_kernel::pipeline::PatchResult;
use wrc_kernel::profile::ProfileTable;
use wrc_kernel::stripes::{boussinesq_filter, StripSample};
use wrc_kernel::wheel::{solve_wheel, DefaultWheelWorkspace, WheelConfig, WheelResult};
use wrc_kernel::{Error, Material, Real};

/// Profile-table capacity used by the sweep (nodes).
pub const NODES: usize = 2048;
/// A profile table of the shipped Manchester pair.
pub type Table = ProfileTable<f64, NODES>;
/// Samples per patch of the NORM gap (geometry re-evaluated at the solved vertical approach).
pub const GAP_SAMPLES: usize = 256;
/// Patch capacity of the default wheel workspace.
pub const PATCHES: usize = 4;
/// Region capacity of the default pipeline.
pub const REGIONS: usize = 4;

/// Vertical loads of the issue-6 sweep, N.
pub const SWEEP_LOADS: [f64; 3] = [40_000.0, 83_300.0, 120_000.0];
/// Friction coefficient of the sweep.
pub const SWEEP_MU: f64 = 0.3;
/// Rolling speed of the sweep, mm/s (100 km/h, as `tests/pipeline_sweep.rs`).
pub const SWEEP_SPEED: f64 = 100.0 / 3.6 * 1000.0;
/// Nominal rolling radius, mm.
pub const R0: f64 = 460.0;

/// One case of the issue-6 sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepCase {
    /// Analysed wheel.
    pub side: Side,
    /// Back-to-back distance, mm.
    pub back_to_back: f64,
    /// Lateral shift towards the analysed wheel, mm (An et al.: the flange approaches its rail).
    pub dy: f64,
    /// Yaw 1.2 × dy mrad, in rad, same sense as `dy`.
    pub yaw: f64,
    /// Wheelset pose in the kernel's track frame (y left, methods.md §7.1): CONTACT's
    /// y_ws = ±dy (+ right wheel), yaw = 1.2e-3·y_ws, and the two-wheel equilibrium roll.
    pub pose: WheelsetPose<f64>,
    /// Vertical wheel load F_z, N.
    pub load: f64,
    /// Short label, e.g. `1353 R dy+3.00 83.3kN`.
    pub label: String,
}

impl SweepCase {
    /// Track set-up: the Manchester/CONTACT standard with this case's back-to-back distance.
    pub fn setup(&self) -> TrackSetup<f64> {
        TrackSetup {
            back_to_back: self.back_to_back,
            ..TrackSetup::standard()
        }
    }

    /// The kernel's wheel configuration for the sweep (recommended pipeline, μ = 0.3, 100 km/h,
    /// nominal kinematics with R0 = 460 mm).
    pub fn config(&self) -> WheelConfig<f64> {
        WheelConfig::recommended(SWEEP_MU, SWEEP_SPEED, R0)
    }

    /// Places the wheel on its rail (grid step 0.05 mm).
    pub fn place<'a>(
        &self,
        wheel: &'a Table,
        rail: &'a Table,
    ) -> Result<WheelRail<'a, f64, NODES, NODES>, Error> {
        WheelRail::place(rail, wheel, &self.setup(), &self.pose, self.side, 0.05)
    }
}

/// The Manchester S1002 / UIC60 tables (default smoothing), (wheel, rail).
pub fn tables() -> Result<(Box<Table>, Box<Table>), String> {
    profiles::manchester_tables::<f64>(&SmoothOptions::default()).map_err(|e| e.to_string())
}

/// One sweep case at shift `dy` (mm, towards the analysed wheel) with its equilibrium roll.
pub fn sweep_case(
    wheel: &Table,
    rail: &Table,
    side: Side,
    back_to_back: f64,
    dy: f64,
    load: f64,
) -> Result<SweepCase, Error> {
    let setup = TrackSetup {
        back_to_back,
        ..TrackSetup::<f64>::standard()
    };
    // CONTACT's y_ws is towards the right wheel
    let y_c = if side == Side::Right { dy } else { -dy };
    let p0 = WheelsetPose::from_contact(y_c, 1.2e-3 * y_c, 0.0);
    let eq = equilibrium_roll::<f64, NODES, NODES>(rail, wheel, &setup, p0.dy, p0.yaw, 0.2)?;
    let s = if side == Side::Right { 'R' } else { 'L' };
    Ok(SweepCase {
        side,
        back_to_back,
        dy,
        yaw: 1.2e-3 * dy,
        pose: WheelsetPose {
            roll: eq.roll,
            ..p0
        },
        load,
        label: format!("{back_to_back:.0} {s} dy{dy:+.2} {:.1}kN", load / 1000.0),
    })
}

/// The issue-6 sweep: for each load, b2b ∈ {1353, 1360} × dy ∈ {−3, …, 6} × side ∈ {right,
/// left} (40 cases per load; 120 with [`SWEEP_LOADS`]), in that nesting order (load innermost).
pub fn sweep_cases(loads: &[f64]) -> Result<Vec<SweepCase>, String> {
    let (w, r) = tables()?;
    let mut out = vec![];
    for b2b in [1353.0, 1360.0] {
        for dy in -3..=6 {
            for side in [Side::Right, Side::Left] {
                for &load in loads {
                    out.push(
                        sweep_case(&w, &r, side, b2b, dy as f64, load)
                            .map_err(|e| format!("b2b {b2b} dy {dy} {side:?}: {e}"))?,
                    );
                }
            }
        }
    }
    Ok(out)
}

/// A coarse signature of a solved wheel: number of patches and regions per patch.
pub fn contact_signature(res: &WheelResult<f64, PATCHES, REGIONS>) -> Vec<usize> {
    res.patches.iter().map(|p| p.result.regions.len()).collect()
}

/// Shifts between the integer sweep shifts where the contact changes character: for each side,
/// b2b and load, and each pair of neighbouring integer shifts whose [`contact_signature`]s differ,
/// the bracket is bisected `depth` times and the shifts on both sides of the final bracket are
/// returned as extra cases (rounded to 1e-3 mm). Cost: `depth` wheel solves per change.
pub fn transition_cases(loads: &[f64], depth: u32) -> Result<Vec<SweepCase>, String> {
    let (w, r) = tables()?;
    let mut out = vec![];
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let mut sig = |c: &SweepCase| -> Result<Vec<usize>, String> {
        let g = c.place(&w, &r).map_err(|e| e.to_string())?;
        let res = solve_wheel(
            &g,
            c.load,
            &Material::steel(),
            &c.config(),
            &mut ws,
            &mut (),
        )
        .map_err(|e| format!("{}: {e}", c.label))?;
        Ok(contact_signature(&res))
    };
    for b2b in [1353.0, 1360.0] {
        for side in [Side::Right, Side::Left] {
            for &load in loads {
                let mk = |dy: f64| {
                    sweep_case(&w, &r, side, b2b, dy, load).map_err(|e| format!("dy {dy}: {e}"))
                };
                let mut prev = mk(-3.0)?;
                let mut prev_sig = sig(&prev)?;
                for dy in -2..=6 {
                    let cur = mk(dy as f64)?;
                    let cur_sig = sig(&cur)?;
                    if cur_sig != prev_sig {
                        let (mut lo, mut hi) = (prev.dy, cur.dy);
                        let lo_sig = prev_sig.clone();
                        for _ in 0..depth {
                            let mid = 0.5 * (lo + hi);
                            if sig(&mk(mid)?)? == lo_sig {
                                lo = mid;
                            } else {
                                hi = mid;
                            }
                        }
                        for v in [lo, hi] {
                            let v = (v * 1000.0).round() / 1000.0;
                            if v.fract() != 0.0 {
                                out.push(mk(v)?);
                            }
                        }
                    }
                    prev = cur;
                    prev_sig = cur_sig;
                }
            }
        }
    }
    Ok(out)
}

/// One row of CONTACT's exact Manchester solutions (`mbench_a22_exact.csv`), values as
/// printed by CONTACT (its module-1 frame and signs, methods.md §0.2, §10.9).
#[derive(Clone, Debug, PartialEq)]
pub struct MbenchRow {
    /// Case number in the file.
    pub case: usize,
    /// Wheel side.
    pub side: Side,
    /// Lateral wheelset shift y_ws (CONTACT: to the right), mm.
    pub y_ws: f64,
    /// Yaw (CONTACT sense), rad.
    pub yaw: f64,
    /// Roll, rad.
    pub roll: f64,
    /// Vertical wheel load FZ_tr, N.
    pub fz: f64,
    /// Contact reference y in the rail profile (CONTACT's lateral sense), mm.
    pub ycp_r: f64,
    /// Wheel-profile z of the contact reference, mm.
    pub zcp_w: f64,
    /// Contact angle in the track frame (CONTACT's sign), rad.
    pub delta: f64,
    /// Longitudinal creepage (CONTACT sign).
    pub cksi: f64,
    /// Lateral creepage.
    pub ceta: f64,
    /// Spin creepage, 1/mm.
    pub cphi: f64,
    /// Normal force, N.
    pub fn_: f64,
    /// Longitudinal force on the rail (CONTACT sign), N.
    pub fx: f64,
    /// Lateral force in the contact plane, N.
    pub fs: f64,
    /// Spin moment, N·mm.
    pub mn: f64,
    /// Normal approach, mm.
    pub approach: f64,
    /// Maximum pressure, MPa.
    pub pmax: f64,
    /// Number of contact elements (0.2 × 0.2 mm).
    pub ncon: usize,
}

impl MbenchRow {
    /// Contact area ncon · 0.04 mm².
    pub fn area(&self) -> f64 {
        0.04 * self.ncon as f64
    }

    /// CONTACT's creepages in the kernel convention (§0.2: ξ_K = −ξ_C, η_K = η_C, φ_K = φ_C).
    pub fn creepage(&self) -> Creepage<f64> {
        Creepage {
            xi: -self.cksi,
            eta: self.ceta,
            phi: self.cphi,
        }
    }

    /// Longitudinal force on the wheel (§0.2: −FX), N.
    pub fn fx_wheel(&self) -> f64 {
        -self.fx
    }

    /// Wheelset pose in the kernel frame.
    pub fn pose(&self) -> WheelsetPose<f64> {
        WheelsetPose::from_contact(self.y_ws, self.yaw, self.roll)
    }

    /// Places the wheel (Manchester set-up, grid step 0.05 mm).
    pub fn place<'a>(
        &self,
        wheel: &'a Table,
        rail: &'a Table,
    ) -> Result<WheelRail<'a, f64, NODES, NODES>, Error> {
        WheelRail::place(
            rail,
            wheel,
            &TrackSetup::standard(),
            &self.pose(),
            self.side,
            0.05,
        )
    }

    /// Short label, e.g. `mbench R y_ws 5.0`.
    pub fn label(&self) -> String {
        let s = if self.side == Side::Right { 'R' } else { 'L' };
        format!("mbench {s} y_ws {:.1}", self.y_ws)
    }
}

/// CONTACT's material in the runs: G = 82 000 MPa, ν = 0.28.
pub fn mbench_material() -> Material<f64> {
    Material {
        g: 82_000.0,
        nu: 0.28,
        e_star: 82_000.0 / 0.72,
    }
}

/// Reads the 42 rows of `contact_reference/mbench_a22_exact.csv`.
pub fn mbench_rows() -> std::io::Result<Vec<MbenchRow>> {
    mbench_rows_from(&data_file("contact_reference/mbench_a22_exact.csv"))
}

/// Reads rows from a CSV file of the same layout (comment lines start with `#`).
pub fn mbench_rows_from(path: &Path) -> std::io::Result<Vec<MbenchRow>> {
    use std::io::{Error as IoError, ErrorKind};
    let bad = |m: String| IoError::new(ErrorKind::InvalidData, m);
    let text = std::fs::read_to_string(path)?;
    let mut lines = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty());
    let head: Vec<&str> = lines
        .next()
        .ok_or_else(|| bad("no header".into()))?
        .split(',')
        .map(str::trim)
        .collect();
    let col = |n: &str| {
        head.iter()
            .position(|h| *h == n)
            .ok_or_else(|| bad(format!("column {n} missing")))
    };
    let mut out = vec![];
    for l in lines {
        let f: Vec<&str> = l.split(',').map(str::trim).collect();
        let field = |n: &str| -> std::io::Result<&str> {
            f.get(col(n)?)
                .copied()
                .ok_or_else(|| bad(format!("short line: {l}")))
        };
        let g = |n: &str| -> std::io::Result<f64> {
            field(n)?
                .parse::<f64>()
                .map_err(|e| bad(format!("{n}: {e}")))
        };
        out.push(MbenchRow {
            case: g("case")? as usize,
            side: match field("side")? {
                "left" => Side::Left,
                "right" => Side::Right,
                s => return Err(bad(format!("side {s}"))),
            },
            y_ws: g("y_ws")?,
            yaw: g("yaw_ws")?,
            roll: g("roll_ws")?,
            fz: g("FZ_tr")?,
            ycp_r: g("ycp_r")?,
            zcp_w: g("zcp_w")?,
            delta: g("deltcp_tr")?,
            cksi: g("cksi")?,
            ceta: g("ceta")?,
            cphi: g("cphi")?,
            fn_: g("FN")?,
            fx: g("FX")?,
            fs: g("FS")?,
            mn: g("MN")?,
            approach: g("approach")?,
            pmax: g("pmax")?,
            ncon: g("ncon")? as usize,
        });
    }
    Ok(out)
}

/// One lateral sample of a patch's gap (methods.md §7.3), contact frame of the patch.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GapSample {
    /// Lateral coordinate s, mm.
    pub s: f64,
    /// Normal separation f_n(s) ≥ 0 (min 0 over the patch), mm.
    pub f_n: f64,
    /// Longitudinal gap curvature A(s), 1/mm.
    pub a_long: f64,
    /// Lateral gap curvature B(s) (unfiltered), 1/mm.
    pub b_lat: f64,
    /// Longitudinal offset of the strip's rigid contact x_c(s), mm.
    pub x_c: f64,
}

/// Grid options of the NORM solve per patch (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormGridOptions {
    /// Largest element size, mm (default 0.2).
    pub max_element: f64,
    /// Smallest element size, mm (default 0.04).
    pub min_element: f64,
    /// Elements per estimated contact semi-axis (default 15).
    pub per_semi_axis: f64,
    /// Gap level of the grid extent relative to the kernel's approach (default 1.25).
    pub level: f64,
    /// Solver options (default: CG, tol 1e-10).
    pub solver: norm::Options,
}

impl Default for NormGridOptions {
    fn default() -> Self {
        Self {
            max_element: 0.2,
            min_element: 0.04,
            per_semi_axis: 15.0,
            level: 1.25,
            solver: norm::Options::default(),
        }
    }
}

/// Kernel and NORM solution of one patch.
#[derive(Clone, Debug)]
pub struct PatchCase {
    /// The kernel's frame of the patch (reference point, contact angle, approach, …).
    pub frame: PatchFrame<f64>,
    /// Creepages the kernel used.
    pub creepage: Creepage<f64>,
    /// Patch normal load of the kernel's load split, N (NORM is solved to the same load).
    pub load: f64,
    /// The kernel's pipeline result (STRIPES pmax, area, regions, tangential totals, wear).
    pub kernel: PatchResult<f64, REGIONS>,
    /// The STRIPES input the kernel used (its own samples of the patch).
    pub stripes_samples: Vec<StripSample<f64>>,
    /// The gap samples NORM used ([`GAP_SAMPLES`] per patch).
    pub gap: Vec<GapSample>,
    /// NORM grid.
    pub grid: Grid,
    /// NORM solution (pressure per element, strips with runs, approach, pmax, area).
    pub norm: NormSolution,
}

impl PatchCase {
    /// STRIPES pmax relative to NORM's, minus 1.
    pub fn dpmax(&self) -> f64 {
        self.kernel.pmax / self.norm.p_max - 1.0
    }

    /// STRIPES area relative to NORM's, minus 1.
    pub fn darea(&self) -> f64 {
        self.kernel.area / self.norm.area - 1.0
    }

    /// NORM's undeformed gap h(x, s) at a point of the patch's contact frame, mm.
    pub fn gap_at(&self, x: f64, s: f64) -> f64 {
        gap_at(&self.gap, x, s)
    }
}

/// Result of [`solve_case`].
#[derive(Clone, Debug)]
pub struct CaseSolution {
    /// The kernel's wheel result.
    pub wheel: WheelResult<f64, PATCHES, REGIONS>,
    /// Every patch of the wheel result, in its order.
    pub patches: Vec<PatchCase>,
}

impl CaseSolution {
    /// Index of the heaviest patch (largest normal load).
    pub fn main(&self) -> usize {
        let mut best = 0;
        for (k, p) in self.patches.iter().enumerate() {
            if p.load > self.patches[best].load {
                best = k;
            }
        }
        best
    }
}

/// Cubic (Catmull–Rom) interpolation of f_n, linear A and x_c at s (clamped to the samples).
fn interp(sm: &[GapSample], s: f64) -> (f64, f64, f64) {
    let n = sm.len();
    if n == 0 {
        return (f64::INFINITY, 1.0, 0.0);
    }
    if s <= sm[0].s {
        return (sm[0].f_n, sm[0].a_long, sm[0].x_c);
    }
    if s >= sm[n - 1].s {
        return (sm[n - 1].f_n, sm[n - 1].a_long, sm[n - 1].x_c);
    }
    let i = sm
        .partition_point(|p| p.s <= s)
        .saturating_sub(1)
        .min(n - 2);
    let (a, b) = (sm[i], sm[i + 1]);
    let t = (s - a.s) / (b.s - a.s);
    let fa = if i > 0 {
        sm[i - 1].f_n
    } else {
        2.0 * a.f_n - b.f_n
    };
    let fb = if i + 2 < n {
        sm[i + 2].f_n
    } else {
        2.0 * b.f_n - a.f_n
    };
    let (p0, p1, p2, p3) = (fa, a.f_n, b.f_n, fb);
    let f = 0.5
        * (2.0 * p1
            + (-p0 + p2) * t
            + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * t * t
            + (-p0 + 3.0 * p1 - 3.0 * p2 + p3) * t * t * t);
    (
        f,
        a.a_long + t * (b.a_long - a.a_long),
        a.x_c + t * (b.x_c - a.x_c),
    )
}

/// The undeformed gap h(x, s) = f_n(s) + A(s)(x − x_c(s))² from gap samples, mm.
pub fn gap_at(sm: &[GapSample], x: f64, s: f64) -> f64 {
    let (f, a, xc) = interp(sm, s);
    f + a * (x - xc) * (x - xc)
}

/// Element size for a patch: see the module docs.
fn element_size(sm: &[GapSample], approach: f64, o: &NormGridOptions) -> f64 {
    // deepest sample → longitudinal semi-axis estimate
    let deep = sm
        .iter()
        .min_by(|a, b| a.f_n.total_cmp(&b.f_n))
        .copied()
        .unwrap_or(GapSample {
            s: 0.0,
            f_n: 0.0,
            a_long: 1.0,
            b_lat: 0.0,
            x_c: 0.0,
        });
    let a_c = ((approach - deep.f_n).max(0.0) / deep.a_long).sqrt() / 2f64.sqrt();
    // widest overlap run → lateral semi-axis estimate
    let (mut widest, mut start): (f64, Option<f64>) = (0.0, None);
    for p in sm {
        let inside = p.f_n < approach;
        match (inside, start) {
            (true, None) => start = Some(p.s),
            (false, Some(s0)) => {
                widest = widest.max(p.s - s0);
                start = None;
            }
            _ => {}
        }
    }
    if let (Some(s0), Some(last)) = (start, sm.last()) {
        widest = widest.max(last.s - s0);
    }
    let b_c = 0.5 * widest / 2f64.sqrt();
    let d = a_c.min(b_c) / o.per_semi_axis;
    if d.is_finite() && d > 0.0 {
        d.clamp(o.min_element, o.max_element)
    } else {
        o.max_element
    }
}

/// The NORM grid over {h < level} of a patch.
fn grid_for(sm: &[GapSample], level: f64, d: f64) -> Result<Grid, Error> {
    let (mut ylo, mut yhi, mut xlo, mut xhi) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for p in sm.iter().filter(|p| p.f_n < level) {
        let hx = ((level - p.f_n) / p.a_long).sqrt();
        ylo = ylo.min(p.s);
        yhi = yhi.max(p.s);
        xlo = xlo.min(p.x_c - hx);
        xhi = xhi.max(p.x_c + hx);
    }
    if ylo > yhi {
        return Err(Error::NoContact);
    }
    // half a sample spacing beyond the extreme samples inside, plus one element each side
    let ds = if sm.len() > 1 { sm[1].s - sm[0].s } else { d };
    let (ylo, yhi) = (ylo - 0.5 * ds - d, yhi + 0.5 * ds + d);
    let (xlo, xhi) = (xlo - d, xhi + d);
    let mx = ((xhi - xlo) / d).ceil() as usize;
    let my = ((yhi - ylo) / d).ceil() as usize;
    Grid::centred(mx, my, d, d, 0.5 * (xlo + xhi), 0.5 * (ylo + yhi))
}

/// NORM on one patch's gap samples, load-controlled to `load` (N), with the kernel's approach
/// `approach` (mm) as the estimate that sizes the grid. Returns the grid and the solution.
///
/// Errors: those of [`norm::solve`]; `NoContact` if no sample is below the level;
/// `OutOfRange("NORM grid")` if the patch still touches the grid boundary after 3 enlargements
/// or the solve does not converge.
pub fn norm_on_gap(
    sm: &[GapSample],
    load: f64,
    approach: f64,
    mat: &Material<f64>,
    o: &NormGridOptions,
) -> Result<(Grid, NormSolution), Error> {
    let d = element_size(sm, approach, o);
    let mut level = o.level * approach;
    for _ in 0..4 {
        let grid = grid_for(sm, level, d)?;
        let h = grid.sample(|x, y| gap_at(sm, x, y));
        let s = norm::solve(&grid, &h, mat, Control::Load(load), &o.solver)?;
        if !s.converged {
            return Err(Error::OutOfRange("NORM grid: solve did not converge"));
        }
        if !s.touches_boundary {
            return Ok((grid, s));
        }
        level *= 1.5;
    }
    Err(Error::OutOfRange("NORM grid: patch touches the boundary"))
}

/// Gap samples of a geometry patch.
fn gap_samples<const S: usize>(p: &Patch<f64, S>) -> Vec<GapSample> {
    let s = &p.samples;
    (0..s.n)
        .map(|i| GapSample {
            s: s.s(i),
            f_n: s.f_n[i],
            a_long: s.a_long[i],
            b_lat: s.b_lat[i],
            x_c: s.x_c[i],
        })
        .collect()
}

/// Same frame up to rounding (the frame is computed from the geometry grid, not the samples).
fn same_frame(a: &PatchFrame<f64>, b: &PatchFrame<f64>) -> bool {
    (a.y_ref_rail - b.y_ref_rail).abs() <= 1e-9
        && (a.angle - b.angle).abs() <= 1e-12
        && (a.approach - b.approach).abs() <= 1e-12
}

/// One patch of the kernel's wheel solve with its gap (no NORM): see [`solve_kernel_case`].
#[derive(Clone, Debug)]
pub struct KernelPatch {
    /// The kernel's frame of the patch.
    pub frame: PatchFrame<f64>,
    /// Creepages the kernel used.
    pub creepage: Creepage<f64>,
    /// Patch normal load of the kernel's load split, N.
    pub load: f64,
    /// The kernel's pipeline result.
    pub kernel: PatchResult<f64, REGIONS>,
    /// The STRIPES input the kernel used.
    pub stripes_samples: Vec<StripSample<f64>>,
    /// The patch's gap re-evaluated with [`GAP_SAMPLES`] samples at the solved approach.
    pub gap: Vec<GapSample>,
}

/// The kernel's wheel solve (f64, `cfg`) on a placed wheel with vertical load `fz` (N), and for
/// every patch it reports: the kernel's STRIPES samples and the gap re-evaluated with
/// [`GAP_SAMPLES`] samples at the solved vertical approach (module docs).
///
/// Errors: the kernel's errors (a non-converged kernel result is not an error: the flag is in the
/// returned `WheelResult::converged`); `OutOfRange("frame")` if a recomputed patch frame does not
/// match the kernel's (the kernel's last geometry pass was not at its returned approach).
pub fn solve_kernel_case(
    geom: &WheelRail<'_, f64, NODES, NODES>,
    fz: f64,
    mat: &Material<f64>,
    cfg: &WheelConfig<f64>,
) -> Result<(WheelResult<f64, PATCHES, REGIONS>, Vec<KernelPatch>), Error> {
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let wheel = solve_wheel(geom, fz, mat, cfg, &mut ws, &mut ())?;
    // the kernel's STRIPES samples of the final geometry pass, by frame
    let kernel_patches: Vec<(PatchFrame<f64>, Vec<StripSample<f64>>)> = ws
        .patches
        .as_slice()
        .iter()
        .map(|p| {
            let s = &p.samples;
            let v = (0..s.n)
                .map(|i| StripSample {
                    y: s.s(i),
                    dy: s.width[i],
                    z: s.f_n[i],
                    curv_a: s.a_long[i],
                    curv_b: s.b_lat[i],
                    xc: s.x_c[i],
                })
                .collect();
            (p.frame, v)
        })
        .collect();
    let mut fine = Box::new(Patches::<f64, PATCHES, GAP_SAMPLES>::new());
    let opts = PatchOptions {
        samples: GAP_SAMPLES,
        ..cfg.patches
    };
    // the vertical approach of the kernel's last geometry pass (the frames' own; the returned
    // `vertical_approach` can be the next iterate when the load loop stops on its pass cap)
    let dv = wheel
        .patches
        .iter()
        .map(|p| p.frame.approach_vertical)
        .next()
        .unwrap_or(wheel.vertical_approach);
    contact_patches(geom, dv, &opts, &mut fine)?;
    let mut patches = vec![];
    for wp in wheel.patches.iter() {
        let fp = fine
            .as_slice()
            .iter()
            .find(|p| same_frame(&p.frame, &wp.frame))
            .ok_or(Error::OutOfRange("frame"))?;
        let stripes_samples = kernel_patches
            .iter()
            .find(|(f, _)| same_frame(f, &wp.frame))
            .map(|(_, v)| v.clone())
            .ok_or(Error::OutOfRange("frame"))?;
        patches.push(KernelPatch {
            frame: wp.frame,
            creepage: wp.creepage,
            load: wp.load,
            kernel: wp.result.clone(),
            stripes_samples,
            gap: gap_samples(fp),
        });
    }
    Ok((wheel, patches))
}

/// The kernel's wheel solve (f64, `cfg`) on a placed wheel with vertical load `fz` (N), then NORM
/// on every patch it reports, load-controlled to that patch's normal load (module docs).
///
/// Errors: those of [`solve_kernel_case`] and of [`norm_on_gap`].
pub fn solve_case(
    geom: &WheelRail<'_, f64, NODES, NODES>,
    fz: f64,
    mat: &Material<f64>,
    cfg: &WheelConfig<f64>,
    norm_opts: &NormGridOptions,
) -> Result<CaseSolution, Error> {
    let (wheel, kps) = solve_kernel_case(geom, fz, mat, cfg)?;
    let mut patches = vec![];
    for kp in kps {
        let (grid, sol) = norm_on_gap(&kp.gap, kp.load, kp.frame.approach, mat, norm_opts)?;
        patches.push(PatchCase {
            frame: kp.frame,
            creepage: kp.creepage,
            load: kp.load,
            kernel: kp.kernel,
            stripes_samples: kp.stripes_samples,
            gap: kp.gap,
            grid,
            norm: sol,
        });
    }
    Ok(CaseSolution { wheel, patches })
}

/// Interpolated gap sample (f_n cubic, A, B, x_c linear) at lateral position `s`, e.g. the
/// patch's reference point s = 0 for a Hertz ellipse.
pub fn gap_sample_at(sm: &[GapSample], s: f64) -> GapSample {
    let (f_n, a_long, x_c) = interp(sm, s);
    let b_lat = if sm.is_empty() {
        0.0
    } else if s <= sm[0].s {
        sm[0].b_lat
    } else if s >= sm[sm.len() - 1].s {
        sm[sm.len() - 1].b_lat
    } else {
        let i = sm
            .partition_point(|p| p.s <= s)
            .saturating_sub(1)
            .min(sm.len() - 2);
        let t = (s - sm[i].s) / (sm[i + 1].s - sm[i].s);
        sm[i].b_lat + t * (sm[i + 1].b_lat - sm[i].b_lat)
    };
    GapSample {
        s,
        f_n,
        a_long,
        b_lat,
        x_c,
    }
}

/// Strip capacity of [`tangential_on_norm`] (NORM rows with contact, runs counted separately).
pub const NORM_STRIPS: usize = 384;
/// Cell capacity of [`tangential_on_norm`] (NORM columns).
pub const NORM_CELLS: usize = 768;

/// Regions of a NORM solution: maximal runs of consecutive grid rows with contact, as (first row,
/// last row).
pub fn norm_row_regions(sol: &NormSolution) -> Vec<(usize, usize)> {
    let mut out = vec![];
    let mut start: Option<usize> = None;
    for j in 0..sol.grid.my {
        let on = sol.strips.get(j).is_some_and(|s| !s.runs.is_empty());
        match (on, start) {
            (true, None) => start = Some(j),
            (false, Some(s)) => {
                out.push((s, j - 1));
                start = None;
            }
            _ => {}
        }
    }
    if let Some(s) = start {
        out.push((s, sol.grid.my - 1));
    }
    out
}

/// Totals of [`tangential_on_norm`], kernel precision converted to f64.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NormTangential {
    /// F_x on the wheel, patch frame, N.
    pub fx: f64,
    /// F_y on the wheel, patch frame, N.
    pub fy: f64,
    /// M_z about the patch frame origin, N·mm.
    pub mz: f64,
    /// Normal force seen by the tangential solver (Σ p δxδy), N.
    pub fn_: f64,
    /// Regions (row runs of NORM's contact set).
    pub regions: usize,
}

/// The kernel's FASTSIM or FaStrip (`method`) with the flexibility approach `adapt` on NORM's
/// pressure of one patch, in precision `T`: each NORM row region becomes one kernel strip patch
/// (one strip per grid row and contact run, the NORM element pressures as cell pressures, cells =
/// NORM columns); Ayasse–Chollet's local ellipses come from the patch's gap curvatures (A, B)
/// with B filtered by the §5.3 filter of length 0.25 × the region's half-width (the kernel's
/// `PatchFraction(0.25)` on STRIPES) and clamped to ≥ 1e-6 1/mm. FASTSIM uses the approach's
/// default bound ([`Adaptation::default_bound`]), FaStrip its defaults. `sink_for(region)` gives
/// the cell sink of each region (strip indices restart at 0 in every region).
///
/// Errors: `OutOfRange` if the NORM grid exceeds [`NORM_STRIPS`] × [`NORM_CELLS`]; the kernel's.
#[allow(clippy::too_many_arguments)]
pub fn tangential_on_norm<T: Real, K: CellSink<T>>(
    norm: &NormSolution,
    gap: &[GapSample],
    creepage: &Creepage<f64>,
    mat: &Material<f64>,
    adapt: &Adaptation<T>,
    method: Method,
    mu: f64,
    mut sink_for: impl FnMut(usize) -> K,
) -> Result<(NormTangential, Vec<K>), Error> {
    let t = T::from_f64;
    let g = &norm.grid;
    if g.mx > NORM_CELLS {
        return Err(Error::OutOfRange("NORM grid columns exceed NORM_CELLS"));
    }
    let matt = Material {
        g: t(mat.g),
        nu: t(mat.nu),
        e_star: t(mat.e_star),
    };
    let cr = Creepage {
        xi: t(creepage.xi),
        eta: t(creepage.eta),
        phi: t(creepage.phi),
    };
    let mut pn: Box<[[T; NORM_CELLS]; NORM_STRIPS]> = vec![[T::ZERO; NORM_CELLS]; NORM_STRIPS]
        .into_boxed_slice()
        .try_into()
        .map_err(|_| Error::OutOfRange("capacity"))?;
    let bound = adapt.default_bound();
    let mut out = NormTangential::default();
    let mut sinks = vec![];
    // gap arrays for the AC curvature filter
    let gs: Vec<f64> = gap.iter().map(|p| p.s).collect();
    let gb: Vec<f64> = gap.iter().map(|p| p.b_lat).collect();
    for (k, (r0, r1)) in norm_row_regions(norm).into_iter().enumerate() {
        let mut strips = [Strip::<T>::default(); NORM_STRIPS];
        let mut ys = vec![];
        let mut n = 0;
        for j in r0..=r1 {
            for run in &norm.strips[j].runs {
                if n >= NORM_STRIPS {
                    return Err(Error::OutOfRange("NORM strips exceed NORM_STRIPS"));
                }
                let a = 0.5 * (run.x_lead - run.x_trail);
                strips[n] = Strip {
                    y: t(g.y(j)),
                    dy: t(g.dy),
                    a: t(a),
                    xc: t(0.5 * (run.x_lead + run.x_trail)),
                    p_hat: t(2.0 * run.force_per_width / (std::f64::consts::PI * a)),
                    ..Strip::default()
                };
                for (i, v) in pn[n].iter_mut().enumerate() {
                    *v = if i >= run.i_first && i <= run.i_last && i < g.mx {
                        t(norm.p(i, j).max(0.0))
                    } else {
                        T::ZERO
                    };
                }
                ys.push(g.y(j));
                n += 1;
            }
        }
        for s in strips.iter_mut().skip(n) {
            s.dy = t(g.dy);
        }
        for row in pn.iter_mut().skip(n) {
            row.iter_mut().for_each(|v| *v = T::ZERO);
        }
        let (y_lo, y_hi) = (g.y(r0) - 0.5 * g.dy, g.y(r1) + 0.5 * g.dy);
        let local: Vec<LocalEllipse<T>> = match adapt {
            Adaptation::AyasseChollet(_) => {
                let mut bf = vec![0.0; gs.len()];
                boussinesq_filter(&gs, &gb, 0.25 * 0.5 * (y_hi - y_lo), &mut bf);
                let filtered: Vec<GapSample> = gap
                    .iter()
                    .zip(&bf)
                    .map(|(p, b)| GapSample { b_lat: *b, ..*p })
                    .collect();
                ys.iter()
                    .map(|&y| {
                        let q = gap_sample_at(&filtered, y);
                        let bb = q.b_lat.max(1e-6);
                        let h = wrc_kernel::hertz::coefficients(q.a_long, bb)?;
                        let nm = h.n / h.m;
                        Ok(LocalEllipse {
                            n_over_m: t(nm),
                            a_tilde: t(nm * nm * bb),
                        })
                    })
                    .collect::<Result<_, Error>>()?
            }
            _ => vec![],
        };
        let mut patch = StripPatch::<T, NORM_STRIPS, NORM_CELLS> {
            strips,
            x0: t(g.x0),
            dx: t(g.dx),
            mat: matt,
        };
        adapt::apply(&mut patch, n, t(y_lo), t(y_hi), &local, adapt)?;
        patch.validate()?;
        let mut sink = sink_for(k);
        let r = adapt::solve_tangential(
            &patch,
            &CellPressure(&pn),
            &cr,
            method,
            bound,
            t(mu),
            &mut sink,
        )?;
        sinks.push(sink);
        out.fx += r.total.fx.to_f64();
        out.fy += r.total.fy.to_f64();
        out.mz += r.total.mz.to_f64();
        out.fn_ += r.total.fn_.to_f64();
        out.regions += 1;
    }
    Ok((out, sinks))
}

/// The band's cases in table order (load, then shift): 1360 mm, right wheel, dy = 4.05…4.95 mm
/// by 0.05 mm, at each of [`SWEEP_LOADS`].
pub fn band_cases(w: &Table, r: &Table) -> Vec<SweepCase> {
    let mut v = vec![];
    for load in SWEEP_LOADS {
        for k in 1..20 {
            let dy = 4.0 + 0.05 * k as f64;
            v.push(sweep_case(w, r, Side::Right, 1360.0, dy, load).unwrap());
        }
    }
    v
}

/// [`solve_case`] for a sweep case (steel, the sweep's configuration).
pub fn solve_sweep_case(
    wheel: &Table,
    rail: &Table,
    case: &SweepCase,
    norm_opts: &NormGridOptions,
) -> Result<CaseSolution, Error> {
    let g = case.place(wheel, rail)?;
    solve_case(&g, case.load, &Material::steel(), &case.config(), norm_opts)
}

/// [`solve_case`] for a Manchester row: F_z from the file (10 kN), CONTACT's material and
/// creepages (prescribed, so the load split sees CONTACT's F_y sin δ coupling), V = 2000 mm/s.
pub fn solve_mbench_row(
    wheel: &Table,
    rail: &Table,
    row: &MbenchRow,
    norm_opts: &NormGridOptions,
) -> Result<CaseSolution, Error> {
    let g = row.place(wheel, rail)?;
    let mut cfg = WheelConfig::recommended(0.3, 2000.0, R0);
    cfg.creepage = Some(row.creepage());
    solve_case(&g, row.fz, &mbench_material(), &cfg, norm_opts)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn catmull_rom_reproduces_a_cubic_inside() {
        // Catmull–Rom reproduces quadratics exactly on uniform samples
        let sm: Vec<GapSample> = (0..20)
            .map(|i| {
                let s = i as f64 * 0.1;
                GapSample {
                    s,
                    f_n: 0.3 * s * s - 0.2 * s + 0.05,
                    a_long: 1e-3,
                    b_lat: 0.3,
                    x_c: 0.0,
                }
            })
            .collect();
        for k in 0..50 {
            let s = 0.1 + k as f64 * 0.033;
            let (f, a, _) = interp(&sm, s);
            assert!((f - (0.3 * s * s - 0.2 * s + 0.05)).abs() < 1e-14, "{s}");
            assert_eq!(a, 1e-3);
        }
    }

    /// solve_case on a Manchester tread case: NORM carries the kernel's patch load, its approach
    /// and pmax agree with CONTACT's exact solution within NORM's validated 2 % (issue 4), the
    /// recomputed gap has the kernel's frame, and the kernel's samples are returned.
    #[test]
    fn solve_case_on_a_manchester_tread_case() {
        let (w, r) = tables().unwrap();
        let rows = mbench_rows().unwrap();
        let row = rows
            .iter()
            .find(|r| r.side == Side::Left && r.y_ws == 2.0)
            .unwrap();
        let sol = solve_mbench_row(&w, &r, row, &NormGridOptions::default()).unwrap();
        assert!(sol.wheel.converged);
        assert_eq!(sol.patches.len(), 1);
        let p = &sol.patches[0];
        assert!((p.norm.force / p.load - 1.0).abs() < 1e-9);
        assert!((p.load / row.fn_ - 1.0).abs() < 0.02);
        assert!((p.norm.approach / row.approach - 1.0).abs() < 0.02);
        assert!((p.norm.p_max / row.pmax - 1.0).abs() < 0.02);
        assert!(p.grid.dx <= 0.2 && p.grid.dx >= 0.04);
        assert_eq!(p.gap.len(), GAP_SAMPLES);
        assert!(!p.stripes_samples.is_empty());
        // f_n is normalised to min 0 on the geometry's own grid: the samples come within a
        // tiny fraction of the approach of it
        let fmin = p.gap.iter().map(|g| g.f_n).fold(f64::MAX, f64::min);
        assert!(fmin >= 0.0 && fmin < 1e-3 * p.frame.approach, "{fmin}");
    }

    #[test]
    fn mbench_rows_read() {
        let rows = mbench_rows().unwrap();
        assert_eq!(rows.len(), 42);
        assert!(rows.iter().all(|r| r.fz == 10_000.0 && r.ncon > 0));
    }
}
