//! The wheel/rail tangential study of issues 6 and 7: the six simplified models (FASTSIM and
//! FaStrip × Kik–Piotrowski, Linder, Ayasse–Chollet) on the kernel's STRIPES pressure and on NORM
//! pressure, against Kalker's exact steady rolling (TANG, [`crate::tang`]) on NORM pressure.
//!
//! Per patch of a solved case ([`crate::wheelrail::PatchCase`]: the kernel's frame, creepages,
//! patch load, STRIPES samples and NORM solution at the same load):
//! * [`on_stripes`]: the kernel's per-patch pipeline (`pipeline::solve_patch`, default
//!   `PipelineConfig::recommended` with the model's adaptation and method) on the kernel's own
//!   STRIPES samples: exactly what the kernel computes.
//! * [`on_norm`]: the same kernel models on NORM's pressure
//!   ([`crate::wheelrail::tangential_on_norm`], the project's one NORM-pressure path): every NORM
//!   grid row with contact is a strip (a_j, x_c,j from its contact run, p̂_j = 2f_j/(πa_j)), the
//!   cells are NORM's elements, the pressure is NORM's per element
//!   ([`wrc_kernel::patch::CellPressure`]). Regions = maximal runs of consecutive rows with contact.
//!   The adaptation is applied per region as in the kernel ([`wrc_kernel::adapt::apply`]); for
//!   Ayasse–Chollet the local ellipse of each row comes from the gap samples: lateral curvature B
//!   filtered with the zero-phase Boussinesq filter with l₀ = 0.25·(half the region's NORM width)
//!   (`PatchFraction(0.25)` of methods.md §5.3, evaluated on the NORM contact set as §5.3 says for
//!   NORM pressure), clamped at 1e-6/mm, n/m from Hertz(A, B_f), Ã = (n/m)²B_f.
//! * [`reference`]: TANG on NORM's grid and pressure (μ = the case's, default tolerance).
//!
//! Wear ([`crate::wear_ref`], the same KTH law as the kernel): depth per strip per passage,
//! Σ_i k p |s| δx / H over the strip's slipping cells. The models' and the reference's strips sit at
//! different y; [`wear_error`] compares their depth profiles by linear interpolation onto the
//! reference rows.
//!
//! Error measures ([`Measures`], methods.md §10.11): forces normalised by μF_n of the patch (the
//! reference's F_n = NORM's = the kernel's patch load), components x, y and resultant: eq. 31 as
//! published (relative), floored (denominator max(|F_exact|, 0.1 μF_n)), absolute |ΔF|/(μF_n);
//! |ΔM_z|/(μF_n c) with c = √(A_c/π), A_c = NORM's contact area.

use crate::tang::{Creepage as TCreepage, ElementState, TangOptions, TangSolution, TangSolver};
use crate::wear_ref::{self, WearMap as RefWearMap};
use crate::wheelrail::{tangential_on_norm, PatchCase};
use wrc_kernel::adapt::{AcFlexLength, Adaptation, KpBeta, Method};
use wrc_kernel::patch::{CellOut, CellSink};
use wrc_kernel::pipeline::{
    solve_patch, solve_patch_strip_model, DefaultWorkspace, PipelineConfig,
};
use wrc_kernel::ritz::{RitzConfig, RitzStrips};
use wrc_kernel::{Error, Material};

pub use crate::wheelrail::{NORM_CELLS, NORM_STRIPS};

/// The six simplified models, in table order.
pub const MODELS: [Model; 6] = [
    Model::new(Method::Fastsim, Approach::Kp),
    Model::new(Method::Fastsim, Approach::Linder),
    Model::new(Method::Fastsim, Approach::Ac),
    Model::new(Method::Fastrip, Approach::Kp),
    Model::new(Method::Fastrip, Approach::Linder),
    Model::new(Method::Fastrip, Approach::Ac),
];

/// Non-elliptic adaptation (methods.md §5), with the kernel's defaults for each.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Approach {
    /// Kik–Piotrowski (β = L/W).
    Kp,
    /// Linder.
    Linder,
    /// Ayasse–Chollet (`StripA`).
    Ac,
}

impl Approach {
    /// The kernel's adaptation value.
    pub fn adaptation(self) -> Adaptation<f64> {
        match self {
            Approach::Kp => Adaptation::KikPiotrowski(KpBeta::LOverW),
            Approach::Linder => Adaptation::Linder,
            Approach::Ac => Adaptation::AyasseChollet(AcFlexLength::StripA),
        }
    }
}

/// One of the six models.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Model {
    /// FASTSIM or FaStrip.
    pub method: Method,
    /// Adaptation.
    pub approach: Approach,
}

impl Model {
    /// A model.
    pub const fn new(method: Method, approach: Approach) -> Self {
        Self { method, approach }
    }

    /// Name, e.g. `FaStrip-AC`.
    pub fn name(&self) -> String {
        let m = match self.method {
            Method::Fastsim => "FASTSIM",
            Method::Fastrip => "FaStrip",
        };
        let a = match self.approach {
            Approach::Kp => "KP",
            Approach::Linder => "Linder",
            Approach::Ac => "AC",
        };
        format!("{m}-{a}")
    }
}

/// One contact cell of a model or of the reference.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CellRec {
    /// x, mm.
    pub x: f64,
    /// y, mm.
    pub y: f64,
    /// Pressure, MPa.
    pub pn: f64,
    /// Traction on the wheel, MPa.
    pub px: f64,
    /// Traction on the wheel, MPa.
    pub py: f64,
    /// In slip.
    pub slip: bool,
    /// |s| (dimensionless).
    pub s: f64,
}

/// Totals, cells and wear profile of one solve.
#[derive(Clone, Debug, Default)]
pub struct Run {
    /// F_x on the wheel, N.
    pub fx: f64,
    /// F_y, N.
    pub fy: f64,
    /// M_z about the frame origin, N·mm.
    pub mz: f64,
    /// F_n, N.
    pub fn_: f64,
    /// Contact cells.
    pub cells: Vec<CellRec>,
    /// (y, wear depth per passage, mm) per strip, ascending y.
    pub wear: Vec<(f64, f64)>,
    /// Converged (reference: TANG's flag; models: always).
    pub converged: bool,
    /// Gauss–Seidel sweeps (reference only).
    pub sweeps: usize,
}

struct Cells(Vec<CellRec>);

impl CellSink<f64> for Cells {
    fn cell(&mut self, _j: usize, _i: usize, o: &CellOut<f64>) {
        self.0.push(CellRec {
            x: o.x,
            y: o.y,
            pn: o.pn,
            px: o.px,
            py: o.py,
            slip: o.slip,
            s: o.sx.hypot(o.sy),
        });
    }
}

/// Wear per strip of a cell list: cells grouped by y (exact equality: cells of one strip share
/// its y), cell length `dx_of(y)`, KTH law at speed `speed` (mm/s).
fn wear_profile(cells: &[CellRec], speed: f64, dx_of: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
    let map = RefWearMap::default();
    let mut out: Vec<(f64, f64)> = vec![];
    let mut sorted: Vec<&CellRec> = cells.iter().collect();
    sorted.sort_by(|a, b| a.y.total_cmp(&b.y));
    for c in sorted {
        let dz = if c.slip {
            map.element_depth(c.pn, c.s, speed, dx_of(c.y))
        } else {
            0.0
        };
        match out.last_mut() {
            Some(l) if l.0 == c.y => l.1 += dz,
            _ => out.push((c.y, dz)),
        }
    }
    out
}

fn totals(cells: &[CellRec], area_of: impl Fn(&CellRec) -> f64) -> (f64, f64, f64, f64) {
    let (mut fx, mut fy, mut mz, mut fnn) = (0.0, 0.0, 0.0, 0.0);
    for c in cells {
        let a = area_of(c);
        fx += a * c.px;
        fy += a * c.py;
        mz += a * (c.x * c.py - c.y * c.px);
        fnn += a * c.pn;
    }
    (fx, fy, mz, fnn)
}

/// A model on the kernel's STRIPES pressure: `pipeline::solve_patch` on the patch's own samples,
/// load and creepages, with μ `mu`, speed `speed` (mm/s) and material `mat`.
pub fn on_stripes(
    pc: &PatchCase,
    model: Model,
    mat: &Material<f64>,
    mu: f64,
    speed: f64,
) -> Result<Run, Error> {
    on_kernel(pc, model, mat, mu, speed, false)
}

/// Strip capacity of the strip-model runs ([`on_kernel`]).
pub const STRIP_MODEL_STRIPS: usize = 160;

/// A model on the kernel's pressure: STRIPES (`strip_model` false, = [`on_stripes`]) or the
/// strip model after it (`pipeline::solve_patch_strip_model`, `RitzConfig::recommended`).
pub fn on_kernel(
    pc: &PatchCase,
    model: Model,
    mat: &Material<f64>,
    mu: f64,
    speed: f64,
    strip_model: bool,
) -> Result<Run, Error> {
    let mut cfg = PipelineConfig::recommended(mu, speed);
    cfg.adapt = model.approach.adaptation();
    cfg.method = model.method;
    let mut ws = Box::new(DefaultWorkspace::<f64>::new());
    let mut sink = Cells(vec![]);
    let r = if strip_model {
        let mut rz = Box::new(RitzStrips::<f64, STRIP_MODEL_STRIPS>::new());
        solve_patch_strip_model(
            &pc.stripes_samples,
            pc.load,
            &pc.creepage,
            mat,
            &cfg,
            &RitzConfig::recommended(),
            &mut ws,
            &mut rz,
            &mut sink,
        )?
    } else {
        solve_patch(
            &pc.stripes_samples,
            pc.load,
            &pc.creepage,
            mat,
            &cfg,
            &mut ws,
            &mut sink,
        )?
    };
    let mut wear: Vec<(f64, f64)> = (0..ws.set.n_strips)
        .map(|j| (ws.set.y[j], ws.wear.depth[j]))
        .collect();
    wear.sort_by(|a, b| a.0.total_cmp(&b.0));
    Ok(Run {
        fx: r.totals.fx,
        fy: r.totals.fy,
        mz: r.totals.mz,
        fn_: r.totals.fn_,
        cells: sink.0,
        wear,
        converged: r.converged,
        sweeps: 0,
    })
}

/// Linear interpolation of (s, value) samples at `s` (clamped).
fn lerp(xs: &[f64], vs: &[f64], s: f64) -> f64 {
    let n = xs.len();
    if n == 0 {
        return 0.0;
    }
    if s <= xs[0] {
        return vs[0];
    }
    if s >= xs[n - 1] {
        return vs[n - 1];
    }
    let k = xs.partition_point(|&x| x <= s).clamp(1, n - 1);
    let t = (s - xs[k - 1]) / (xs[k] - xs[k - 1]);
    vs[k - 1] + t * (vs[k] - vs[k - 1])
}

/// A model on NORM's pressure (module docs), μ `mu`, speed `speed` (mm/s): the project's one
/// NORM-pressure path, [`crate::wheelrail::tangential_on_norm`] in f64, with the cells collected
/// for the traction, slip and wear comparisons.
///
/// Errors: `OutOfRange` if the NORM grid exceeds [`NORM_STRIPS`] × [`NORM_CELLS`]; the kernel's
/// errors.
pub fn on_norm(
    pc: &PatchCase,
    model: Model,
    mat: &Material<f64>,
    mu: f64,
    speed: f64,
) -> Result<Run, Error> {
    let g = &pc.norm.grid;
    let (_, sinks) = tangential_on_norm::<f64, Cells>(
        &pc.norm,
        &pc.gap,
        &pc.creepage,
        mat,
        &model.approach.adaptation(),
        model.method,
        mu,
        |_| Cells(vec![]),
    )?;
    let cells: Vec<CellRec> = sinks.into_iter().flat_map(|c| c.0).collect();
    let (fx, fy, mz, fnn) = totals(&cells, |_| g.dx * g.dy);
    let wear = wear_profile(&cells, speed, |_| g.dx);
    Ok(Run {
        fx,
        fy,
        mz,
        fn_: fnn,
        cells,
        wear,
        converged: true,
        sweeps: 0,
    })
}

/// TANG on NORM's grid and pressure (the reference), μ `mu`, speed `speed` (mm/s).
pub fn reference(pc: &PatchCase, mat: &Material<f64>, mu: f64, speed: f64) -> (Run, TangSolution) {
    let (grid, pn) = crate::tang::from_norm(&pc.norm);
    let cr = TCreepage {
        xi: pc.creepage.xi,
        eta: pc.creepage.eta,
        phi: pc.creepage.phi,
    };
    let sol =
        TangSolver::new(grid, mat.g, mat.nu).solve(&pn, mu, cr, &TangOptions::default(), None);
    let mut cells = vec![];
    for j in 0..grid.my {
        for i in 0..grid.mx {
            let k = grid.idx(i, j);
            if sol.state[k] == ElementState::Exterior {
                continue;
            }
            cells.push(CellRec {
                x: grid.x(i),
                y: grid.y(j),
                pn: pn[k],
                px: sol.px[k],
                py: sol.py[k],
                slip: sol.state[k] == ElementState::Slip,
                s: sol.sx[k].hypot(sol.sy[k]),
            });
        }
    }
    let depth = wear_ref::strip_wear(&RefWearMap::default(), &sol, &pn, speed);
    let wear = (0..grid.my)
        .filter(|&j| (0..grid.mx).any(|i| sol.state[grid.idx(i, j)] != ElementState::Exterior))
        .map(|j| (grid.y(j), depth[j]))
        .collect();
    let run = Run {
        fx: sol.fx,
        fy: sol.fy,
        mz: sol.mz,
        fn_: sol.fn_,
        cells,
        wear,
        converged: sol.converged,
        sweeps: sol.sweeps,
    };
    (run, sol)
}

/// A model's wear profile against the reference's, in absolute terms so that errors can be
/// weighted over patches (per-patch ratios are dominated by centred states whose wear is ~10⁻⁴ of
/// the others).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct WearCmp {
    /// max over the reference rows of |Δdepth|, mm.
    pub dmax: f64,
    /// max reference depth, mm.
    pub rmax: f64,
    /// |∫model depth dy − ∫reference depth dy|, mm².
    pub dint: f64,
    /// ∫reference depth dy, mm².
    pub rint: f64,
}

impl WearCmp {
    /// Per-patch ratios (max |Δdepth| / max depth, |Δ∫| / ∫); (NaN, NaN) if the reference does
    /// not wear.
    pub fn ratios(&self) -> (f64, f64) {
        if self.rmax > 0.0 && self.rint > 0.0 {
            (self.dmax / self.rmax, self.dint / self.rint)
        } else {
            (f64::NAN, f64::NAN)
        }
    }
}

/// Wear profile error of `model` against `reference` (both (y, depth) ascending): the model's
/// depth interpolated linearly onto the reference's rows (0 outside its strips); integrals by the
/// rows' midpoint widths ((y_{k+1} − y_{k−1})/2, the end rows their inner half-spacing).
pub fn wear_error(model: &[(f64, f64)], reference: &[(f64, f64)]) -> WearCmp {
    let ys: Vec<f64> = model.iter().map(|w| w.0).collect();
    let ds: Vec<f64> = model.iter().map(|w| w.1).collect();
    let (ylo, yhi) = match (ys.first(), ys.last()) {
        (Some(&a), Some(&b)) => (a, b),
        _ => (f64::MAX, f64::MIN),
    };
    let n = reference.len();
    let width = |k: usize| -> f64 {
        if n < 2 {
            return 1.0;
        }
        let lo = if k == 0 {
            reference[0].0
        } else {
            0.5 * (reference[k - 1].0 + reference[k].0)
        };
        let hi = if k + 1 == n {
            reference[n - 1].0
        } else {
            0.5 * (reference[k].0 + reference[k + 1].0)
        };
        let h = hi - lo;
        // end rows: their inner half-spacing counted twice (a full row width)
        if k == 0 || k + 1 == n {
            2.0 * h
        } else {
            h
        }
    };
    let mut w = WearCmp::default();
    let (mut sr, mut sm) = (0.0, 0.0);
    for (k, &(y, d)) in reference.iter().enumerate() {
        let m = if y < ylo || y > yhi {
            0.0
        } else {
            lerp(&ys, &ds, y)
        };
        w.dmax = w.dmax.max((m - d).abs());
        w.rmax = w.rmax.max(d);
        let h = width(k);
        sr += d * h;
        sm += m * h;
    }
    w.rint = sr;
    w.dint = (sm - sr).abs();
    w
}

/// One patch compared: forces normalised by μF_n (x, y, M_z/(μF_n c)) of a model and the
/// reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Compared {
    /// Model (F_x, F_y)/(μF_n) and M_z/(μF_n c).
    pub model: [f64; 3],
    /// Reference, same normalisation.
    pub exact: [f64; 3],
}

impl Compared {
    /// From runs: normalisation by μF_n of the reference (= the patch load) and c = √(A_c/π).
    pub fn new(model: &Run, exact: &Run, mu: f64, area: f64) -> Self {
        let f = mu * exact.fn_;
        let c = (area / std::f64::consts::PI).sqrt();
        Self {
            model: [model.fx / f, model.fy / f, model.mz / (f * c)],
            exact: [exact.fx / f, exact.fy / f, exact.mz / (f * c)],
        }
    }

    fn comps(v: &[f64; 3]) -> [f64; 3] {
        [v[0], v[1], v[0].hypot(v[1])]
    }
}

/// The error measures of methods.md §10.11 over a set of compared patches.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Measures {
    /// Number of patches.
    pub n: usize,
    /// eq. 31 as published, mean of |ΔF_j|/|F_j,exact| over patches and components (x, y,
    /// resultant); components with F_exact = 0 exactly are skipped.
    pub eq31: f64,
    /// Floored eq. 31 (denominator max(|F_exact|, 0.1)).
    pub floored: f64,
    /// Mean |ΔF_j|/(μF_n) over patches and components.
    pub abs_mean: f64,
    /// Max |ΔF_j|/(μF_n).
    pub abs_max: f64,
    /// Mean |ΔM_z|/(μF_n c).
    pub mz_mean: f64,
    /// Max |ΔM_z|/(μF_n c).
    pub mz_max: f64,
}

impl Measures {
    /// Measures over `set`.
    pub fn of(set: &[Compared]) -> Self {
        let mut m = Measures {
            n: set.len(),
            ..Default::default()
        };
        if set.is_empty() {
            return m;
        }
        let (mut ne, mut na) = (0usize, 0usize);
        for c in set {
            let (a, e) = (Compared::comps(&c.model), Compared::comps(&c.exact));
            for j in 0..3 {
                let d = (a[j] - e[j]).abs();
                if e[j] != 0.0 {
                    m.eq31 += d / e[j].abs();
                    ne += 1;
                }
                m.floored += d / e[j].abs().max(0.1);
                m.abs_mean += d;
                m.abs_max = m.abs_max.max(d);
                na += 1;
            }
            let dm = (c.model[2] - c.exact[2]).abs();
            m.mz_mean += dm;
            m.mz_max = m.mz_max.max(dm);
        }
        m.eq31 /= ne.max(1) as f64;
        m.floored /= na as f64;
        m.abs_mean /= na as f64;
        m.mz_mean /= set.len() as f64;
        m
    }
}
