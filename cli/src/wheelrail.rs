//! Wheel/rail cases: `wrc solve --wheel FILE --rail FILE --dy … --fz …` through the kernel's
//! per-wheel solve (`wrc_kernel::wheel`): geometry, load split over the patches, STRIPES, the
//! chosen adaptation and tangential model, KTH wear.

use crate::args::{Flex, Normal, Side as ArgSide, SolveArgs, Tangential};
use crate::doc::{Creepage as DocCreepage, Patch, Status, StripOut, Y0Cell};
use crate::sink::{PlotCell, StatsSink};
use crate::timing::median_time_us;
use std::path::Path;
use wrc_host_tests::profiles::{
    build_table, build_table_from_text, read_profile, SmoothOptions, S1002_NAME, S1002_PRW,
    UIC60_NAME, UIC60_PRR,
};
use wrc_kernel::adapt::{AcFlexLength, Adaptation, KpBeta, Method};
use wrc_kernel::geometry::{Side, TrackSetup, WheelRail, WheelsetPose};
use wrc_kernel::patch::{CellOut, CellSink, Creepage};
use wrc_kernel::pipeline::{solve_patch, solve_patch_strip_model};
use wrc_kernel::profile::{ProfileKind, ProfileTable};
use wrc_kernel::ritz::{RitzConfig, RitzStrips};
use wrc_kernel::stripes::StripSample;
use wrc_kernel::wheel::{
    solve_wheel, solve_wheel_strip_model, WheelConfig, WheelSink, WheelWorkspace,
};
use wrc_kernel::{Material, Real};

/// Profile capacity (nodes) of the command line.
pub(crate) const NODES: usize = 2048;

/// Everything a solved wheel/rail case reports.
pub struct Solved {
    /// Patches for the JSON document.
    pub patches: Vec<Patch>,
    /// Cells of the first patch for plots (empty unless requested).
    pub cells: Vec<PlotCell>,
    /// Status.
    pub status: Status,
    /// Kernel time, µs (wheel solve with the wheel already placed).
    pub time_us: f64,
    /// Cell size (x, y) of the first patch's first region, mm.
    pub cell_mm: (f64, f64),
    /// (y, wear µm) per strip of the first patch.
    pub wear_strips: Vec<(f64, f64)>,
}

/// Builds the table of a profile: the file given on the command line, or the built-in Manchester
/// S1002 wheel / UIC60 rail (`data/profiles/`, compiled into the binary so that `wrc` works from any
/// directory and after `cargo install`).
pub(crate) fn table<T: Real>(
    path: Option<&Path>,
    kind: ProfileKind,
) -> Result<Box<ProfileTable<T, NODES>>, String> {
    let opts = SmoothOptions::default();
    match path {
        Some(p) => {
            let raw = read_profile(p, Some(kind)).map_err(|e| e.to_string())?;
            crate::orientation::check(&raw.points, kind)
                .map_err(|e| format!("{}: {e}", p.display()))?;
            build_table::<T, NODES>(p, Some(kind), &opts)
        }
        None => {
            let (text, name) = match kind {
                ProfileKind::Wheel => (S1002_PRW, S1002_NAME),
                ProfileKind::Rail => (UIC60_PRR, UIC60_NAME),
            };
            build_table_from_text::<T, NODES>(text, Path::new(name), Some(kind), &opts)
        }
    }
    .map_err(|e| e.to_string())
}

/// The profile as reported in the JSON inputs: the file given, or the built-in profile's name and
/// its source in the repository.
pub fn profile_name(path: Option<&Path>, wheel: bool) -> String {
    match path {
        Some(p) => p.display().to_string(),
        None if wheel => format!("built-in S1002 (data/profiles/{S1002_NAME})"),
        None => format!("built-in UIC60 (data/profiles/{UIC60_NAME})"),
    }
}

/// A short profile name for plot titles: the file name, or S1002/UIC60 for the built-ins.
pub fn profile_short(path: Option<&Path>, wheel: bool) -> String {
    match path {
        Some(p) => p
            .file_name()
            .map(|f| f.to_string_lossy().into_owned())
            .unwrap_or_else(|| p.display().to_string()),
        None if wheel => "S1002".into(),
        None => "UIC60".into(),
    }
}

/// Per-patch statistics from the cells.
struct Stats {
    patch: usize,
    keep: bool,
    speed: f64,
    per: Vec<PatchStats>,
    cells: Vec<PlotCell>,
    /// Relative slip |s| of each kept cell (for its wear once the cell length is known).
    slips: Vec<f64>,
    /// Last cell of the first patch (strip j, cell i, x) and the cell length δx found from
    /// consecutive cells of one strip.
    last: Option<(usize, usize, f64)>,
    cell_dx: f64,
}

#[derive(Clone, Default)]
struct PatchStats {
    area: f64,
    stick: f64,
    x: [f64; 2],
    y: [f64; 2],
    dx: f64,
}

impl<T: Real> CellSink<T> for Stats {
    fn cell(&mut self, j: usize, i: usize, o: &CellOut<T>) {
        while self.per.len() <= self.patch {
            self.per.push(PatchStats {
                x: [f64::MAX, f64::MIN],
                y: [f64::MAX, f64::MIN],
                ..Default::default()
            });
        }
        let p = &mut self.per[self.patch];
        let a = o.area.to_f64();
        p.area += a;
        if !o.slip {
            p.stick += a;
        }
        let (x, y) = (o.x.to_f64(), o.y.to_f64());
        if p.dx == 0.0 {
            p.dx = a; // area of the first cell, turned into δy below
        }
        p.x = [p.x[0].min(x), p.x[1].max(x)];
        p.y = [p.y[0].min(y), p.y[1].max(y)];
        if self.patch == 0 {
            if let Some((lj, li, lx)) = self.last {
                if lj == j && i > li && self.cell_dx == 0.0 {
                    self.cell_dx = (x - lx).abs() / (i - li) as f64;
                }
            }
            self.last = Some((j, i, x));
        }
        if self.keep && self.patch == 0 {
            let s = o.sx.to_f64().hypot(o.sy.to_f64());
            self.slips.push(s);
            self.cells.push(PlotCell {
                x,
                y,
                pn: o.pn.to_f64(),
                px: o.px.to_f64(),
                py: o.py.to_f64(),
                slip: o.slip,
                vs: s * self.speed * 1e-3,
                wear_um: 0.0,
            });
        }
    }
}

impl<T: Real> WheelSink<T> for Stats {
    fn begin_patch(&mut self, k: usize) {
        self.patch = k;
    }
}

/// Profiles, track set-up, pose, side, material and kernel configuration of a wheel/rail case.
pub(crate) struct Prepared<T> {
    pub(crate) wheel: Box<ProfileTable<T, NODES>>,
    pub(crate) rail: Box<ProfileTable<T, NODES>>,
    pub(crate) setup: TrackSetup<T>,
    pub(crate) pose: WheelsetPose<T>,
    pub(crate) side: Side,
    pub(crate) mat: Material<T>,
    pub(crate) cfg: WheelConfig<T>,
    pub(crate) speed: f64,
}

pub(crate) fn prepare<T: Real>(args: &SolveArgs) -> Result<Prepared<T>, String> {
    let cm = &args.common;
    let wr = &args.wr;
    let t = T::from_f64;
    let wheel = table::<T>(wr.wheel.as_deref(), ProfileKind::Wheel)?;
    let rail = table::<T>(wr.rail.as_deref(), ProfileKind::Rail)?;
    let mut setup = TrackSetup::<T>::standard();
    setup.gauge = t(wr.gauge);
    setup.gauge_depth = t(wr.gauge_depth);
    setup.back_to_back = t(wr.back_to_back.unwrap_or(1360.0));
    setup.cant = t(wr.cant);
    setup.r0 = t(wr.r0);
    // --dy and --yaw are taken towards the analysed wheel (An et al. 2019, methods.md §7.1):
    // the kernel's named constructor for that convention (CONTACT's y_ws for the right wheel).
    let side = match wr.side {
        ArgSide::Left => Side::Left,
        ArgSide::Right => Side::Right,
    };
    let pose = WheelsetPose::towards_wheel(side, t(wr.dy), t(wr.yaw * 1e-3), t(wr.roll * 1e-3));
    let mat =
        Material::<T>::identical(t(cm.e_mpa), t(cm.nu)).map_err(crate::validate::kernel_msg)?;
    let speed = cm.speed * 1e3;
    let mut cfg = WheelConfig::recommended(t(cm.mu), t(speed), t(wr.r0));
    cfg.creepage = match (cm.xi, cm.eta, cm.phi) {
        (None, None, None) => None,
        (Some(xi), Some(eta), Some(phi)) => Some(Creepage {
            xi: t(xi),
            eta: t(eta),
            phi: t(phi),
        }),
        _ => return Err("give all of --xi, --eta, --phi or none (kinematic creepages)".into()),
    };
    Ok(Prepared {
        wheel,
        rail,
        setup,
        pose,
        side,
        mat,
        cfg,
        speed,
    })
}

/// The flexibility approach of `--flex` (default Ayasse–Chollet).
pub(crate) fn adaptation<T: Real>(flex: Option<Flex>) -> Adaptation<T> {
    match flex.unwrap_or(Flex::Ac) {
        Flex::Hertz => Adaptation::Hertz,
        Flex::Kp => Adaptation::KikPiotrowski(KpBeta::LOverW),
        Flex::Linder => Adaptation::Linder,
        Flex::Ac => Adaptation::AyasseChollet(AcFlexLength::StripA),
    }
}

/// Solves a wheel/rail case in the precision (`--precision`) and with the cells per strip
/// (`--cells`: 16, 32 or 64, checked by `validate`) that `args` asks for.
pub fn solve_as_asked(args: &SolveArgs, keep: bool) -> Result<Solved, String> {
    use crate::args::Precision;
    match (args.common.precision, args.common.cells) {
        (Precision::F64, 16) => solve::<f64, 16>(args, keep),
        (Precision::F64, 32) => solve::<f64, 32>(args, keep),
        (Precision::F64, _) => solve::<f64, 64>(args, keep),
        (Precision::F32, 16) => solve::<f32, 16>(args, keep),
        (Precision::F32, 32) => solve::<f32, 32>(args, keep),
        (Precision::F32, _) => solve::<f32, 64>(args, keep),
    }
}

/// Solves a wheel/rail case in precision `T` with `C` cells per strip.
pub fn solve<T: Real, const C: usize>(args: &SolveArgs, keep: bool) -> Result<Solved, String> {
    let cm = &args.common;
    let t = T::from_f64;
    if cm.tangential == Tangential::Exact {
        return solve_exact(args, keep);
    }
    let strip_model = args.normal() == Normal::Strips;
    match args.normal() {
        Normal::Stripes | Normal::Strips => {}
        Normal::Norm => return crate::wr_reference::solve_norm::<T>(args, keep),
        Normal::Hertz => return crate::wr_reference::solve_hertz::<T, C>(args, keep),
    }
    if cm.strips < 8 || cm.strips > 32 {
        return Err("--strips per region must be within 8..=32 for wheel/rail cases".into());
    }
    let Prepared {
        wheel,
        rail,
        setup,
        pose,
        side,
        mat,
        mut cfg,
        speed,
    } = prepare::<T>(args)?;
    let geom = WheelRail::<T, NODES, NODES>::place(&rail, &wheel, &setup, &pose, side, t(0.05))
        .map_err(|e| format!("geometry: {e}"))?;
    cfg.pipeline.strips_per_region = cm.strips;
    cfg.pipeline.method = match cm.tangential {
        Tangential::Fastsim => Method::Fastsim,
        Tangential::Fastrip => Method::Fastrip,
        Tangential::Exact => unreachable!("handled by solve_exact"),
    };
    cfg.pipeline.adapt = adaptation(cm.flex);
    let mut ws = Box::new(Ws::<T, C>::new());
    let mut rz = Box::new(RitzStrips::<T, RITZ_STRIPS>::new());
    let rcfg = RitzConfig::recommended();
    let fz = t(args.wr.fz);
    // the strip model (0.1–1 s per patch) is timed on its one run below
    let mut time_us = if strip_model {
        0.0
    } else {
        median_time_us(|| {
            let _ = solve_wheel(&geom, fz, &mat, &cfg, &mut ws, &mut ());
        })
    };
    let mut stats = Stats {
        patch: 0,
        keep,
        speed,
        per: vec![],
        cells: vec![],
        slips: vec![],
        last: None,
        cell_dx: 0.0,
    };
    let res = if strip_model {
        let t0 = std::time::Instant::now();
        let r = solve_wheel_strip_model(&geom, fz, &mat, &cfg, &rcfg, &mut ws, &mut rz, &mut stats);
        time_us = t0.elapsed().as_secs_f64() * 1e6;
        r
    } else {
        solve_wheel(&geom, fz, &mat, &cfg, &mut ws, &mut stats)
    }
    .map_err(|e| e.to_string())?;
    let mut warnings = vec![];
    let rzm = if strip_model {
        Some((&mut *rz, &rcfg))
    } else {
        None
    };
    let per_patch = patch_strips(&res, &mat, &cfg, &mut ws, rzm, &mut warnings)?;
    let mut patches = vec![];
    for (k, (p, (strips, y0))) in res.patches.iter().zip(per_patch).enumerate() {
        let st = stats.per.get(k).cloned().unwrap_or_default();
        let r = &p.result;
        let mut wear = 0.0f64;
        for reg in r.regions.iter() {
            wear = wear.max(reg.wear_max.to_f64());
        }
        patches.push(Patch {
            y_ref_mm: p.frame.y_ref_rail.to_f64(),
            z_ref_mm: p.frame.z_ref_rail.to_f64(),
            contact_angle_rad: p.frame.angle.to_f64(),
            creepage: DocCreepage {
                xi: p.creepage.xi.to_f64(),
                eta: p.creepage.eta.to_f64(),
                phi_per_mm: p.creepage.phi.to_f64(),
            },
            approach_mm: r.approach.to_f64(),
            fn_n: p.load.to_f64(),
            fx_n: r.totals.fx.to_f64(),
            fy_n: r.totals.fy.to_f64(),
            mz_nmm: r.totals.mz.to_f64(),
            pmax_mpa: r.pmax.to_f64(),
            area_mm2: r.area.to_f64(),
            x_extent_mm: if st.area > 0.0 { st.x } else { [0.0, 0.0] },
            y_extent_mm: if st.area > 0.0 { st.y } else { [0.0, 0.0] },
            stick_area_fraction: if st.area > 0.0 {
                st.stick / st.area
            } else {
                0.0
            },
            wear_depth_max_um: wear * 1e3,
            strips,
            y0,
        });
    }
    // plots: first patch; strip wear from the pipeline workspace belongs to the last patch solved,
    // so it is reported only for single-patch cases
    let wear_strips = if res.patches.len() == 1 {
        let set = &ws.pipeline.set;
        (0..set.n_strips)
            .map(|j| (set.y[j].to_f64(), ws.pipeline.wear.depth[j].to_f64() * 1e3))
            .collect()
    } else {
        vec![]
    };
    let cell_mm = stats
        .per
        .first()
        .map(|p| {
            let (x0, x1) = (p.x[0], p.x[1]);
            let dx = if stats.cell_dx > 0.0 {
                stats.cell_dx
            } else {
                ((x1 - x0) / (C as f64 - 1.0)).max(1e-6)
            };
            (dx, p.dx / dx)
        })
        .unwrap_or((0.1, 0.1));
    // wear of each plotted cell: the kernel's KTH map on the cell's pressure and slip over δx
    let map = wrc_kernel::wear::WearMap::<f64>::kth();
    for (c, &s) in stats.cells.iter_mut().zip(&stats.slips) {
        c.wear_um = if c.slip {
            map.cell_depth(c.pn, s, speed, cell_mm.0).0 * 1e3
        } else {
            0.0
        };
    }
    if !res.converged {
        warnings.push("the load or frame iteration did not reach its tolerance".to_string());
    }
    Ok(Solved {
        patches,
        cells: stats.cells,
        status: Status {
            path: "converged",
            converged: res.converged,
            iterations: res.iterations,
            warnings,
        },
        time_us,
        cell_mm,
        wear_strips,
    })
}

/// Strip capacity of the strip model (`--normal strips`).
const RITZ_STRIPS: usize = 160;

/// The kernel's wheel workspace of the command line (`C` cells per strip).
type Ws<T, const C: usize> = WheelWorkspace<T, 4, 128, 256, 4, 32, C, 128>;

/// One patch's strips and the cells of its strip through y = 0.
type PatchStrips = (Vec<StripOut>, Vec<Y0Cell>);

/// `strips` and `y0` of every patch of `res`: each patch is run once more through the kernel's
/// pipeline (`wrc_kernel::pipeline::solve_patch`, with `--normal strips`
/// `solve_patch_strip_model`: the computation of the wheel solve's final
/// solve of that patch, on its geometry samples, load and creepages that `ws` and `res` hold),
/// into a detailed sink; then the workspace holds that patch's strips (centre y_j,
/// half-length a_j, strip load (π/2) p̂_j a_j δy_j) and its per-strip KTH wear, and the sink the
/// per-strip totals of the cells (F_x, F_y) and the cells of the strip through y = 0. A re-run
/// whose totals differ from the wheel solve's (not expected) and a patch in the neck blend (whose
/// totals and wear are a blend of two strip layouts while the strips are the dominant layout's)
/// are reported in `warnings`.
fn patch_strips<T: Real, const C: usize>(
    res: &wrc_kernel::wheel::WheelResult<T, 4, 4>,
    mat: &Material<T>,
    cfg: &WheelConfig<T>,
    ws: &mut Ws<T, C>,
    mut strip_model: Option<(&mut RitzStrips<T, RITZ_STRIPS>, &RitzConfig<T>)>,
    warnings: &mut Vec<String>,
) -> Result<Vec<PatchStrips>, String> {
    let mut out = vec![];
    let mut next = 0usize;
    for (m, p) in res.patches.iter().enumerate() {
        let np = ws.patches.len.min(4);
        let Some(k) = (next..np).find(|&k| ws.patches.items[k].frame == p.frame) else {
            warnings.push(format!("patch {m}: geometry patch not found; no strips"));
            out.push((vec![], vec![]));
            continue;
        };
        next = k + 1;
        let g = &ws.patches.items[k].samples;
        let samples: Vec<StripSample<T>> = (0..g.n.min(128))
            .map(|i| StripSample {
                y: g.s(i),
                dy: g.width[i],
                z: g.f_n[i],
                curv_a: g.a_long[i],
                curv_b: g.b_lat[i],
                xc: g.x_c[i],
            })
            .collect();
        let mut sink = StatsSink::<T, 128>::new(
            wrc_kernel::wear::WearMap::kth(),
            cfg.pipeline.speed,
            T::ONE,
            false,
        )
        .detailed();
        let r = match strip_model.as_mut() {
            Some((rz, rcfg)) => solve_patch_strip_model(
                &samples,
                p.load,
                &p.creepage,
                mat,
                &cfg.pipeline,
                rcfg,
                &mut ws.pipeline,
                rz,
                &mut sink,
            ),
            None => solve_patch(
                &samples,
                p.load,
                &p.creepage,
                mat,
                &cfg.pipeline,
                &mut ws.pipeline,
                &mut sink,
            ),
        }
        .map_err(|e| format!("patch {m}: {e}"))?;
        if r.totals != p.result.totals {
            warnings.push(format!(
                "patch {m}: the per-strip re-run differs from the wheel solve; strips approximate"
            ));
        }
        let set = &ws.pipeline.set;
        let mut rows: Vec<(StripOut, usize)> = (0..set.n_strips)
            .filter(|&j| set.a[j] > T::ZERO)
            .map(|j| {
                let t = sink.rows.get(j).map(|r| r.totals).unwrap_or_default();
                (
                    StripOut {
                        y_mm: set.y[j].to_f64(),
                        half_length_mm: set.a[j].to_f64(),
                        width_mm: set.dy[j].to_f64(),
                        // (π/2) p̂_j a_j δy_j: the strip's semi-elliptic load (for STRIPES
                        // equal to stiffness·h_j·δy_j)
                        fn_n: (set.pmax[j] * set.a[j] * set.dy[j]).to_f64()
                            * std::f64::consts::FRAC_PI_2,
                        fx_n: t.fx.to_f64(),
                        fy_n: t.fy.to_f64(),
                        wear_depth_um: ws.pipeline.wear.depth[j].to_f64() * 1e3,
                    },
                    j,
                )
            })
            .collect();
        rows.sort_by(|a, b| a.0.y_mm.total_cmp(&b.0.y_mm));
        let (sx, sy) = rows
            .iter()
            .fold((0.0, 0.0), |a, r| (a.0 + r.0.fx_n, a.1 + r.0.fy_n));
        let (tx, ty) = (p.result.totals.fx.to_f64(), p.result.totals.fy.to_f64());
        let scale = tx.hypot(ty).max(1e-9 * p.load.to_f64());
        if (sx - tx).hypot(sy - ty) > 1e-6 * scale {
            warnings.push(format!(
                "patch {m}: in the neck blend of two strip layouts; its strips are the dominant \
                 layout's and do not sum to the blended totals"
            ));
        }
        let mut y0 = crate::doc::y0_strip(rows.iter().map(|r| (r.0.y_mm, set.dy[r.1].to_f64())))
            .and_then(|q| sink.rows.get(rows[q].1))
            .map(|r| r.cells.clone())
            .unwrap_or_default();
        crate::doc::sort_by_x(&mut y0);
        out.push((rows.into_iter().map(|r| r.0).collect(), y0));
    }
    Ok(out)
}

/// `--tangential exact` on a wheel/rail case: the kernel's per-wheel solve (f64, the chosen
/// adaptation, kinematic or given creepages) fixes the patches, their frames, loads and creepages;
/// then, per patch, NORM on the patch's gap at the kernel's patch load and TANG (Kalker's exact
/// steady rolling) on NORM's pressure (`wrc_host_tests::wheelrail::solve_case`,
/// `wrc_host_tests::tangstudy::reference`). The reported normal fields are NORM's, the tangential
/// ones TANG's, wear the KTH law on TANG's slip.
fn solve_exact(args: &SolveArgs, keep: bool) -> Result<Solved, String> {
    use wrc_host_tests::tangstudy::reference;
    use wrc_host_tests::wheelrail::{solve_case, NormGridOptions};
    let cm = &args.common;
    if cm.normal.unwrap_or(Normal::Norm) != Normal::Norm {
        return Err(
            "--tangential exact runs on NORM pressure: use --normal norm (or omit it)".into(),
        );
    }
    let p = prepare::<f64>(args)?;
    let geom =
        WheelRail::<f64, NODES, NODES>::place(&p.rail, &p.wheel, &p.setup, &p.pose, p.side, 0.05)
            .map_err(|e| format!("geometry: {e}"))?;
    let (mat, mut cfg, speed) = (p.mat, p.cfg, p.speed);
    cfg.pipeline.adapt = adaptation(cm.flex);
    let t0 = std::time::Instant::now();
    let cs = solve_case(&geom, args.wr.fz, &mat, &cfg, &NormGridOptions::default())
        .map_err(|e| e.to_string())?;
    let mut patches = vec![];
    let mut cells = vec![];
    let mut wear_strips = vec![];
    let mut cell_mm = (0.1, 0.1);
    let mut converged = cs.wheel.converged;
    let mut sweeps = 0u32;
    let mut warnings = vec![];
    if !cs.wheel.converged {
        warnings
            .push("the kernel's load or frame iteration did not reach its tolerance".to_string());
    }
    for (k, pc) in cs.patches.iter().enumerate() {
        let (run, sol) = reference(pc, &mat, cm.mu, speed);
        converged &= sol.converged;
        sweeps = sweeps.max(sol.sweeps as u32);
        if !sol.converged {
            warnings.push(format!(
                "patch {k}: TANG did not converge in {} sweeps",
                sol.sweeps
            ));
        }
        let n = &pc.norm;
        let (ex, ey) = (
            n.extent_x.unwrap_or((0.0, 0.0)),
            n.extent_y.unwrap_or((0.0, 0.0)),
        );
        let stick = run.cells.iter().filter(|c| !c.slip).count();
        let (_, pn) = wrc_host_tests::tang::from_norm(n);
        let (strips, y0) =
            crate::exact::tang_strips(&sol, &pn, speed, &crate::exact::norm_half_lengths(n));
        let wear_max = strips.iter().map(|s| s.wear_depth_um).fold(0.0, f64::max);
        patches.push(Patch {
            y_ref_mm: pc.frame.y_ref_rail,
            z_ref_mm: pc.frame.z_ref_rail,
            contact_angle_rad: pc.frame.angle,
            creepage: DocCreepage {
                xi: pc.creepage.xi,
                eta: pc.creepage.eta,
                phi_per_mm: pc.creepage.phi,
            },
            approach_mm: n.approach,
            fn_n: run.fn_,
            fx_n: run.fx,
            fy_n: run.fy,
            mz_nmm: run.mz,
            pmax_mpa: n.p_max,
            area_mm2: n.area,
            x_extent_mm: [ex.0, ex.1],
            y_extent_mm: [ey.0, ey.1],
            stick_area_fraction: if run.cells.is_empty() {
                0.0
            } else {
                stick as f64 / run.cells.len() as f64
            },
            wear_depth_max_um: wear_max,
            strips,
            y0,
        });
        if k == 0 {
            cell_mm = (n.grid.dx, n.grid.dy);
            wear_strips = run.wear.iter().map(|w| (w.0, w.1 * 1e3)).collect();
            if keep {
                let map = wrc_host_tests::wear_ref::WearMap::default();
                cells = run
                    .cells
                    .iter()
                    .map(|c| PlotCell {
                        x: c.x,
                        y: c.y,
                        pn: c.pn,
                        px: c.px,
                        py: c.py,
                        slip: c.slip,
                        vs: c.s * speed * 1e-3,
                        wear_um: if c.slip {
                            map.element_depth(c.pn, c.s, speed, n.grid.dx) * 1e3
                        } else {
                            0.0
                        },
                    })
                    .collect();
            }
        }
    }
    Ok(Solved {
        patches,
        cells,
        status: Status {
            path: "converged",
            converged,
            iterations: sweeps,
            warnings,
        },
        time_us: t0.elapsed().as_secs_f64() * 1e6,
        cell_mm,
        wear_strips,
    })
}
