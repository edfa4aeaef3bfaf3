//! Elliptic (Hertzian) cases: `wrc solve --ellipse A,B | --curvatures A,B  --fn N | --approach MM`.

use crate::args::{Flex, Normal, SolveArgs, Tangential};
use crate::doc::{Creepage as DocCreepage, Patch, Status};
use crate::sink::{PlotCell, StatsSink};
use crate::timing::median_time_us;
use wrc_kernel::fastrip::{fastrip, FastripSettings};
use wrc_kernel::fastsim::{fastsim, FastsimSettings};
use wrc_kernel::hertz::{self, HertzSolution};
use wrc_kernel::patch::{Creepage, Ellipse, Strip, StripPatch, TractionBound};
use wrc_kernel::wear::WearMap;
use wrc_kernel::{Material, Real};

/// Everything a solved elliptic case reports.
pub struct Solved {
    /// The patch for the JSON document.
    pub patch: Patch,
    /// Cells for plots (empty unless requested).
    pub cells: Vec<PlotCell>,
    /// Status.
    pub status: Status,
    /// Kernel time, µs.
    pub time_us: f64,
    /// Cell size along x and y, mm (plots).
    pub cell_mm: (f64, f64),
    /// (y, wear depth µm) per non-empty strip (plots).
    pub wear_strips: Vec<(f64, f64)>,
}

/// The Hertz solution of the case (f64 or f32).
fn hertz_of<T: Real>(args: &SolveArgs, mat: &Material<T>) -> Result<HertzSolution<T>, String> {
    let t = T::from_f64;
    match (args.ellipse, args.curvatures, args.fn_n, args.approach) {
        (Some([a, b]), None, Some(n), None) => {
            hertz::curvatures_from_semi_axes(t(a), t(b), t(n), mat).map_err(|e| e.to_string())
        }
        (Some(_), None, None, Some(_)) => {
            Err("--ellipse needs --fn (the semi-axes fix the load only with curvatures)".into())
        }
        (None, Some([ca, cb]), Some(n), None) => {
            hertz::from_load(t(ca), t(cb), t(n), mat).map_err(|e| e.to_string())
        }
        (None, Some([ca, cb]), None, Some(d)) => {
            hertz::from_approach(t(ca), t(cb), t(d), mat).map_err(|e| e.to_string())
        }
        _ => Err(
            "an elliptic case needs --ellipse A,B or --curvatures A,B and --fn N or --approach MM"
                .into(),
        ),
    }
}

/// A Hertz patch with `ns` strips and `nc` cells used out of the capacity `S` × `C` (the strips
/// beyond `ns` are empty; cells beyond `nc` lie outside the ellipse).
pub fn hertz_patch<T: Real, const S: usize, const C: usize>(
    h: &HertzSolution<T>,
    mat: &Material<T>,
    ns: usize,
    nc: usize,
) -> Result<StripPatch<T, S, C>, String> {
    if ns > S || nc > C || ns < wrc_kernel::patch::MIN_STRIPS || nc < wrc_kernel::patch::MIN_CELLS {
        return Err(format!(
            "grid {ns} strips x {nc} cells outside the supported range {}..={S} x {}..={C}",
            wrc_kernel::patch::MIN_STRIPS,
            wrc_kernel::patch::MIN_CELLS
        ));
    }
    let template = Strip::default()
        .with_reference(h.a, h.b, mat)
        .map_err(|e| e.to_string())?;
    let dy = T::TWO * h.b / T::from_usize(ns);
    let mut strips = [template; S];
    let half = T::from_usize(ns) * T::HALF;
    for (j, s) in strips.iter_mut().enumerate() {
        let y = (T::from_usize(j) + T::HALF - half) * dy;
        let q = T::ONE - (y / h.b) * (y / h.b);
        let root = if j < ns && q > T::ZERO {
            wrc_kernel::math::sqrt(q)
        } else {
            T::ZERO
        };
        s.y = y;
        s.dy = dy;
        s.a = h.a * root;
        s.xc = T::ZERO;
        s.p_hat = if root > T::ZERO { h.p0 * root } else { h.p0 };
    }
    let dx = T::TWO * h.a / T::from_usize(nc);
    StripPatch::new(strips, -h.a, dx, *mat).map_err(|e| e.to_string())
}

/// Solves an elliptic case in precision `T` with capacity `S` × `C`.
pub fn solve<T: Real, const S: usize, const C: usize>(
    args: &SolveArgs,
    keep_cells: bool,
) -> Result<Solved, String> {
    let cm = &args.common;
    let t = T::from_f64;
    match cm.normal.unwrap_or(Normal::Hertz) {
        Normal::Hertz => {}
        other => {
            return Err(format!(
                "--normal {other:?} is not available for elliptic cases in this build"
            ))
        }
    }
    match cm.flex.unwrap_or(Flex::Hertz) {
        Flex::Hertz => {}
        other => {
            return Err(format!(
                "--flex {other:?} needs a non-elliptic patch; elliptic cases use --flex hertz"
            ))
        }
    }
    let mat = Material::<T>::identical(t(cm.e_mpa), t(cm.nu)).map_err(|e| e.to_string())?;
    let cr = Creepage {
        xi: t(cm.xi.unwrap_or(0.0)),
        eta: t(cm.eta.unwrap_or(0.0)),
        phi: t(cm.phi.unwrap_or(0.0)),
    };
    let mu = t(cm.mu);
    let speed = t(cm.speed * 1e3);
    let map = WearMap::<T>::kth();

    // The kernel call that is timed: Hertz + patch + tangential + wear.
    let run = |keep: bool| -> Result<_, String> {
        let h = hertz_of::<T>(args, &mat)?;
        let patch = hertz_patch::<T, S, C>(&h, &mat, cm.strips, cm.cells)?;
        let ell = Ellipse {
            a: h.a,
            b: h.b,
            p0: h.p0,
        };
        let mut sink = StatsSink::<T, S>::new(map, speed, patch.dx, keep);
        let pressure = wrc_kernel::patch::SemiEllipticStrips;
        let res = match cm.tangential {
            Tangential::Fastsim => {
                let set = FastsimSettings::canonical(mu, TractionBound::Parabolic(ell));
                fastsim(&patch, &pressure, &cr, &set, &mut sink)
            }
            Tangential::Fastrip => {
                let set = FastripSettings::new(mu);
                fastrip(&patch, &pressure, &cr, &set, &mut sink)
            }
            Tangential::Exact => {
                return Err("--tangential exact is not available in this build".into())
            }
        }
        .map_err(|e| e.to_string())?;
        Ok((h, res, sink, patch))
    };
    let time_us = median_time_us(|| {
        let _ = run(false);
    });
    let (h, res, sink, patch) = run(keep_cells)?;
    let wear_strips: Vec<(f64, f64)> = patch
        .strips
        .iter()
        .zip(sink.wear.depth.iter())
        .filter(|(s, _)| s.a > T::ZERO)
        .map(|(s, d)| (s.y.to_f64(), d.to_f64() * 1e3))
        .collect();
    let cell_mm = (patch.dx.to_f64(), patch.strips[0].dy.to_f64());
    let n = sink.wear.max_depth(S);
    let patch = Patch {
        y_ref_mm: 0.0,
        z_ref_mm: 0.0,
        contact_angle_rad: 0.0,
        creepage: DocCreepage {
            xi: cr.xi.to_f64(),
            eta: cr.eta.to_f64(),
            phi_per_mm: cr.phi.to_f64(),
        },
        approach_mm: h.delta.to_f64(),
        fn_n: h.load.to_f64(),
        fx_n: res.total.fx.to_f64(),
        fy_n: res.total.fy.to_f64(),
        mz_nmm: res.total.mz.to_f64(),
        pmax_mpa: h.p0.to_f64(),
        area_mm2: core::f64::consts::PI * h.a.to_f64() * h.b.to_f64(),
        x_extent_mm: [-h.a.to_f64(), h.a.to_f64()],
        y_extent_mm: [-h.b.to_f64(), h.b.to_f64()],
        stick_area_fraction: if sink.area > 0.0 {
            sink.stick_area / sink.area
        } else {
            0.0
        },
        wear_depth_max_um: n.to_f64() * 1e3,
    };
    Ok(Solved {
        patch,
        cells: sink.cells,
        status: Status {
            converged: true,
            iterations: 0,
            warnings: vec![],
        },
        time_us,
        cell_mm,
        wear_strips,
    })
}
