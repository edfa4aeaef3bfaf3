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
/// beyond `ns` are empty; cells beyond `nc` lie outside the ellipse), p̂ scaled so that the
/// sampled pressure carries the Hertz load.
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
    let mut patch = StripPatch::new(strips, -h.a, dx, *mat).map_err(|e| e.to_string())?;
    // the sampled pressure carries the reported load N, so |F| ≤ μN (issue 16)
    patch.scale_to_load(h.load).map_err(|e| e.to_string())?;
    Ok(patch)
}

/// Solves an elliptic case in precision `T` with capacity `S` × `C`.
pub fn solve<T: Real, const S: usize, const C: usize>(
    args: &SolveArgs,
    keep_cells: bool,
) -> Result<Solved, String> {
    let cm = &args.common;
    let t = T::from_f64;
    if cm.tangential == Tangential::Exact {
        return solve_exact(args, keep_cells);
    }
    match cm.normal.unwrap_or(Normal::Hertz) {
        Normal::Hertz => {}
        Normal::Norm => return solve_norm::<T, S, C>(args, keep_cells),
        Normal::Stripes | Normal::Strips => {
            return Err(
                "--normal stripes|strips needs a wheel/rail gap; elliptic cases use hertz or norm"
                    .into(),
            )
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
    let mat =
        Material::<T>::identical(t(cm.e_mpa), t(cm.nu)).map_err(crate::validate::kernel_msg)?;
    let cr = Creepage {
        xi: t(cm.xi.unwrap_or(0.0)),
        eta: t(cm.eta.unwrap_or(0.0)),
        phi: t(cm.phi.unwrap_or(0.0)),
    };
    let mu = t(cm.mu);
    let speed = t(cm.speed * 1e3);
    let map = WearMap::<T>::kth();

    // The kernel call that is timed: Hertz + patch + tangential + wear.
    let run = |keep: bool, detail: bool| -> Result<_, String> {
        let h = hertz_of::<T>(args, &mat)?;
        let patch = hertz_patch::<T, S, C>(&h, &mat, cm.strips, cm.cells)?;
        let ell = Ellipse {
            a: h.a,
            b: h.b,
            p0: h.p0,
        };
        let mut sink = StatsSink::<T, S>::new(map, speed, patch.dx, keep);
        if detail {
            sink = sink.detailed();
        }
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
            Tangential::Exact => unreachable!("handled by solve_exact"),
        }
        .map_err(|e| e.to_string())?;
        Ok((h, res, sink, patch))
    };
    let time_us = median_time_us(|| {
        let _ = run(false, false);
    });
    let (h, res, sink, patch) = run(keep_cells, true)?;
    let (strips, y0) = crate::sink::kernel_strips(&patch, cm.strips, &res, &sink);
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
        strips,
        y0,
    };
    Ok(Solved {
        patch,
        cells: sink.cells,
        status: Status {
            path: "elliptic",
            converged: true,
            iterations: 0,
            warnings: vec![],
        },
        time_us,
        cell_mm,
        wear_strips,
    })
}

/// `--normal norm`: Kalker's boundary-element NORM (host reference, `wrc_host_tests::norm`) on the
/// gap A x² + B y² over CONTACT's ±1.1a × ±1.1b grid of `--cells` × `--strips` elements, then the
/// kernel's FASTSIM/FaStrip on the NORM pressure (bound μ p_n, Kalker flexibilities of the Hertz
/// ellipse; each grid row is a strip with its contact run).
fn solve_norm<T: Real, const S: usize, const C: usize>(
    args: &SolveArgs,
    keep_cells: bool,
) -> Result<Solved, String> {
    use wrc_host_tests::norm::{Control, Grid, Norm, Options};
    use wrc_kernel::patch::CellPressure;
    let cm = &args.common;
    let t = T::from_f64;
    let (ns, nc) = (cm.strips, cm.cells);
    if ns > S || nc > C || ns < 4 || nc < 4 {
        return Err(format!("grid {ns} x {nc} outside 4..={S} x 4..={C}"));
    }
    let mat64 = Material::<f64>::identical(cm.e_mpa, cm.nu).map_err(crate::validate::kernel_msg)?;
    let h = hertz_of::<f64>(args, &mat64)?;
    let (ca, cb) = (h.curv_a, h.curv_b);
    let control = if args.approach.is_some() {
        Control::Penetration(h.delta)
    } else {
        Control::Load(h.load)
    };
    let mut sol = None;
    let time_us = median_time_us(|| {
        let r = Grid::new(
            nc,
            ns,
            2.2 * h.a / nc as f64,
            2.2 * h.b / ns as f64,
            -1.1 * h.a,
            -1.1 * h.b,
        )
        .and_then(|g| {
            let gap = g.sample(|x, y| ca * x * x + cb * y * y);
            Norm::new(g, mat64)?.solve(&gap, control, &Options::default())
        });
        sol = Some(r);
    });
    let sol = sol
        .ok_or("NORM did not run")?
        .map_err(|e| format!("NORM: {e}"))?;
    let g = sol.grid;
    // kernel strips from the NORM rows
    let mat =
        Material::<T>::identical(t(cm.e_mpa), t(cm.nu)).map_err(crate::validate::kernel_msg)?;
    let template = Strip::default()
        .with_reference(t(h.a), t(h.b), &mat)
        .map_err(|e| e.to_string())?;
    let mut strips = [template; S];
    let mut pn = [[T::ZERO; C]; S];
    for (j, s) in strips.iter_mut().enumerate() {
        s.y = t(g.y0 + (j as f64 + 0.5) * g.dy);
        s.dy = t(g.dy);
        s.a = T::ZERO;
        s.p_hat = T::ONE;
        if j >= g.my {
            continue;
        }
        let st = &sol.strips[j];
        if let Some(run) = st.runs.first() {
            if st.runs.len() > 1 {
                return Err("NORM row with several contact runs: not an elliptic patch".into());
            }
            let a = 0.5 * (run.x_lead - run.x_trail);
            s.a = t(a);
            s.xc = t(0.5 * (run.x_lead + run.x_trail));
            s.p_hat = t(2.0 * run.force_per_width / (std::f64::consts::PI * a));
        }
        for (i, v) in pn[j].iter_mut().enumerate().take(g.mx) {
            *v = t(sol.p(i, j));
        }
    }
    let patch =
        StripPatch::<T, S, C>::new(strips, t(g.x0), t(g.dx), mat).map_err(|e| e.to_string())?;
    let cr = Creepage {
        xi: t(cm.xi.unwrap_or(0.0)),
        eta: t(cm.eta.unwrap_or(0.0)),
        phi: t(cm.phi.unwrap_or(0.0)),
    };
    let mu = t(cm.mu);
    let mut sink =
        StatsSink::<T, S>::new(WearMap::kth(), t(cm.speed * 1e3), patch.dx, keep_cells).detailed();
    let pressure = CellPressure(&pn);
    let res = match cm.tangential {
        Tangential::Fastsim => fastsim(
            &patch,
            &pressure,
            &cr,
            &FastsimSettings::canonical(mu, TractionBound::Elliptic),
            &mut sink,
        ),
        Tangential::Fastrip => {
            fastrip(&patch, &pressure, &cr, &FastripSettings::new(mu), &mut sink)
        }
        Tangential::Exact => unreachable!("handled by solve_exact"),
    }
    .map_err(|e| e.to_string())?;
    let wear_strips: Vec<(f64, f64)> = patch
        .strips
        .iter()
        .zip(sink.wear.depth.iter())
        .filter(|(s, _)| s.a > T::ZERO)
        .map(|(s, d)| (s.y.to_f64(), d.to_f64() * 1e3))
        .collect();
    let (strips, y0) = crate::sink::kernel_strips(&patch, g.my, &res, &sink);
    let (ex, ey) = (
        sol.extent_x.unwrap_or((0.0, 0.0)),
        sol.extent_y.unwrap_or((0.0, 0.0)),
    );
    let patch_doc = Patch {
        y_ref_mm: 0.0,
        z_ref_mm: 0.0,
        contact_angle_rad: 0.0,
        creepage: DocCreepage {
            xi: cr.xi.to_f64(),
            eta: cr.eta.to_f64(),
            phi_per_mm: cr.phi.to_f64(),
        },
        approach_mm: sol.approach,
        fn_n: sol.force,
        fx_n: res.total.fx.to_f64(),
        fy_n: res.total.fy.to_f64(),
        mz_nmm: res.total.mz.to_f64(),
        pmax_mpa: sol.p_max,
        area_mm2: sol.area,
        x_extent_mm: [ex.0, ex.1],
        y_extent_mm: [ey.0, ey.1],
        stick_area_fraction: if sink.area > 0.0 {
            sink.stick_area / sink.area
        } else {
            0.0
        },
        wear_depth_max_um: sink.wear.max_depth(S).to_f64() * 1e3,
        strips,
        y0,
    };
    let mut warnings = vec![];
    if sol.touches_boundary {
        warnings.push("NORM contact reaches the grid boundary".to_string());
    }
    Ok(Solved {
        patch: patch_doc,
        cells: sink.cells,
        status: Status {
            path: "elliptic",
            converged: sol.converged,
            iterations: sol.iterations as u32,
            warnings,
        },
        time_us,
        cell_mm: (g.dx, g.dy),
        wear_strips,
    })
}

/// `--tangential exact` on an elliptic case: TANG (host reference, f64) on the Hertz pressure at
/// the element centres (`--normal hertz`) or on NORM's pressure (`--normal norm`), grid
/// `--cells` × `--strips` over ±1.1a × ±1.1b (see [`crate::exact`]).
fn solve_exact(args: &SolveArgs, keep_cells: bool) -> Result<Solved, String> {
    use crate::exact::{self, NormalFields};
    use wrc_host_tests::norm::{Control, Grid as NGrid, Norm, Options};
    let cm = &args.common;
    if cm.flex.unwrap_or(Flex::Hertz) != Flex::Hertz {
        return Err("--flex applies to the simplified models, not to --tangential exact".into());
    }
    let (nx, ny) = (cm.cells, cm.strips);
    if nx < 4 || ny < 4 {
        return Err(format!(
            "grid {ny} x {nx} too small for TANG (at least 4 x 4)"
        ));
    }
    let mat = Material::<f64>::identical(cm.e_mpa, cm.nu).map_err(crate::validate::kernel_msg)?;
    let h = hertz_of::<f64>(args, &mat)?;
    let cr = wrc_host_tests::tang::Creepage {
        xi: cm.xi.unwrap_or(0.0),
        eta: cm.eta.unwrap_or(0.0),
        phi: cm.phi.unwrap_or(0.0),
    };
    let mut warnings = vec![];
    if cm.precision == crate::args::Precision::F32 {
        warnings.push("--tangential exact runs in f64 (host reference)".to_string());
    }
    let (grid, pn, normal, half, norm_status) =
        match cm.normal.unwrap_or(Normal::Hertz) {
            Normal::Hertz => {
                let g = exact::elliptic_grid(h.a, h.b, nx, ny);
                let pn = exact::hertz_on(&g, h.a, h.b, h.load);
                let nf = NormalFields {
                    approach_mm: h.delta,
                    pmax_mpa: h.p0,
                    area_mm2: std::f64::consts::PI * h.a * h.b,
                    x_extent_mm: [-h.a, h.a],
                    y_extent_mm: [-h.b, h.b],
                };
                let half = exact::hertz_half_lengths(&g, h.a, h.b);
                (g, pn, nf, half, None)
            }
            Normal::Norm => {
                let control = if args.approach.is_some() {
                    Control::Penetration(h.delta)
                } else {
                    Control::Load(h.load)
                };
                let (ca, cb) = (h.curv_a, h.curv_b);
                let g = NGrid::new(
                    nx,
                    ny,
                    2.2 * h.a / nx as f64,
                    2.2 * h.b / ny as f64,
                    -1.1 * h.a,
                    -1.1 * h.b,
                )
                .map_err(|e| format!("NORM: {e}"))?;
                let gap = g.sample(|x, y| ca * x * x + cb * y * y);
                let sol = Norm::new(g, mat)
                    .and_then(|mut n| n.solve(&gap, control, &Options::default()))
                    .map_err(|e| format!("NORM: {e}"))?;
                if sol.touches_boundary {
                    warnings.push("NORM contact reaches the grid boundary".to_string());
                }
                let (ex, ey) = (
                    sol.extent_x.unwrap_or((0.0, 0.0)),
                    sol.extent_y.unwrap_or((0.0, 0.0)),
                );
                let nf = NormalFields {
                    approach_mm: sol.approach,
                    pmax_mpa: sol.p_max,
                    area_mm2: sol.area,
                    x_extent_mm: [ex.0, ex.1],
                    y_extent_mm: [ey.0, ey.1],
                };
                let (tg, pn) = wrc_host_tests::tang::from_norm(&sol);
                let half = exact::norm_half_lengths(&sol);
                (tg, pn, nf, half, Some(sol.converged))
            }
            Normal::Stripes | Normal::Strips => return Err(
                "--normal stripes|strips needs a wheel/rail gap; elliptic cases use hertz or norm"
                    .into(),
            ),
        };
    let ep = exact::solve(
        grid,
        &pn,
        cr,
        cm.mu,
        &mat,
        cm.speed * 1e3,
        normal,
        &half,
        keep_cells,
    );
    let mut status = ep.status;
    if norm_status == Some(false) {
        status.converged = false;
        warnings.push("NORM did not converge".to_string());
    }
    status.warnings.extend(warnings);
    Ok(Solved {
        patch: ep.patch,
        cells: ep.cells,
        status,
        time_us: ep.time_us,
        cell_mm: (grid.dx, grid.dy),
        wear_strips: ep.wear_strips,
    })
}
