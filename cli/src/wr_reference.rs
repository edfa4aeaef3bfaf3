//! Wheel/rail cases with the host reference normal models (cli.md, issues 4 and 6):
//!
//! * `--normal norm`: the kernel's per-wheel solve gives the patches, their frames, creepages and
//!   normal loads (geometry and load split in f64); on every patch Kalker's NORM
//!   (`wrc_host_tests::wheelrail::solve_case`: the patch's gap re-evaluated with 256 samples,
//!   δ ≤ 0.2 mm, load-controlled to the patch load), then FASTSIM or FaStrip (`--tangential`)
//!   with the `--flex` approach on NORM's pressure
//!   (`wrc_host_tests::wheelrail::tangential_on_norm`, precision `--precision`).
//! * `--normal hertz`: the same patches and loads; per patch one Hertz ellipse from the patch's
//!   curvatures A, B at its reference point (s = 0 of the patch's gap; B must be convex there),
//!   then FASTSIM (parabolic bound) or FaStrip on the Hertz strips (`--strips` × `--cells`),
//!   `--flex hertz` only (as for elliptic cases).
//!
//! Per patch the JSON reports the reference model's approach, pmax, area and extents, the patch
//! load as `fn_n` (NORM: its own Σ p δxδy), and the tangential results; the kernel's frame and
//! creepages. `time_us` is the median time of the reference computation (normal + tangential of
//! every patch, geometry and load split excluded).

use crate::args::{Flex, SolveArgs, Tangential};
use crate::doc::{sort_by_x, y0_strip, Creepage as DocCreepage, Patch, Status, StripOut, Y0Cell};
use crate::sink::StatsSink;
use crate::timing::median_time_us;
use crate::wheelrail::{adaptation, prepare, Solved};
use wrc_host_tests::wheelrail::{
    gap_sample_at, norm_on_gap, solve_kernel_case, tangential_on_norm, KernelPatch,
    NormGridOptions, NORM_STRIPS,
};
use wrc_kernel::adapt::Method;
use wrc_kernel::fastrip::{fastrip, FastripSettings};
use wrc_kernel::fastsim::{fastsim, FastsimSettings};
use wrc_kernel::geometry::WheelRail;
use wrc_kernel::patch::{Creepage, Ellipse, SemiEllipticStrips, TractionBound};
use wrc_kernel::wear::WearMap;
use wrc_kernel::{hertz, Material, Real};

/// The kernel's wheel solve in f64 (patches, frames, loads, creepages, gaps).
fn kernel_patches(args: &SolveArgs) -> Result<(Vec<KernelPatch>, bool, Material<f64>), String> {
    let p = prepare::<f64>(args)?;
    let geom =
        WheelRail::<f64, 2048, 2048>::place(&p.rail, &p.wheel, &p.setup, &p.pose, p.side, 0.05)
            .map_err(|e| format!("geometry: {e}"))?;
    let (res, kps) =
        solve_kernel_case(&geom, args.wr.fz, &p.mat, &p.cfg).map_err(|e| e.to_string())?;
    Ok((kps, res.converged, p.mat))
}

fn method(t: Tangential) -> Result<Method, String> {
    match t {
        Tangential::Fastsim => Ok(Method::Fastsim),
        Tangential::Fastrip => Ok(Method::Fastrip),
        Tangential::Exact => {
            Err("--tangential exact is not available for wheel/rail cases in this build".into())
        }
    }
}

fn doc_patch(kp: &KernelPatch) -> Patch {
    Patch {
        y_ref_mm: kp.frame.y_ref_rail,
        z_ref_mm: kp.frame.z_ref_rail,
        contact_angle_rad: kp.frame.angle,
        creepage: DocCreepage {
            xi: kp.creepage.xi,
            eta: kp.creepage.eta,
            phi_per_mm: kp.creepage.phi,
        },
        ..Patch::default()
    }
}

/// `--normal norm` on a wheel/rail case (module docs).
pub fn solve_norm<T: Real>(args: &SolveArgs, keep: bool) -> Result<Solved, String> {
    let cm = &args.common;
    let m = method(cm.tangential)?;
    let adapt = adaptation::<T>(cm.flex);
    let (kps, kernel_ok, mat) = kernel_patches(args)?;
    let speed = cm.speed * 1e3;
    let opts = NormGridOptions::default();
    let run = |keep: bool, detail: bool| -> Result<_, String> {
        let mut out = vec![];
        for (k, kp) in kps.iter().enumerate() {
            let (grid, sol) = norm_on_gap(&kp.gap, kp.load, kp.frame.approach, &mat, &opts)
                .map_err(|e| format!("NORM on patch {k}: {e}"))?;
            let (tan, sinks) = tangential_on_norm::<T, _>(
                &sol,
                &kp.gap,
                &kp.creepage,
                &mat,
                &adapt,
                m,
                cm.mu,
                |_| {
                    let s = StatsSink::<T, NORM_STRIPS>::new(
                        WearMap::kth(),
                        T::from_f64(speed),
                        T::from_f64(grid.dx),
                        keep && k == 0,
                    );
                    if detail {
                        s.detailed()
                    } else {
                        s
                    }
                },
            )
            .map_err(|e| format!("tangential on NORM pressure, patch {k}: {e}"))?;
            out.push((grid, sol, tan, sinks));
        }
        Ok(out)
    };
    let time_us = median_time_us(|| {
        let _ = run(false, false);
    });
    let solved = run(keep, true)?;
    let mut patches = vec![];
    let mut cells = vec![];
    // the per-strip wear of NORM's rows is per region in the sinks; the plots show the cells' wear
    let wear_strips = vec![];
    let mut iterations = 0u32;
    let mut converged = kernel_ok;
    let mut warnings = vec![];
    let mut cell_mm = (0.2, 0.2);
    for (k, (kp, (grid, sol, tan, sinks))) in kps.iter().zip(solved).enumerate() {
        let (mut area, mut stick, mut wear) = (0.0f64, 0.0f64, 0.0f64);
        for s in &sinks {
            area += s.area;
            stick += s.stick_area;
            wear = wear.max(s.wear.max_depth(NORM_STRIPS).to_f64());
        }
        iterations += sol.iterations as u32;
        converged &= sol.converged;
        if sol.touches_boundary {
            warnings.push(format!("patch {k}: NORM contact reaches the grid boundary"));
        }
        let (ex, ey) = (
            sol.extent_x.unwrap_or((0.0, 0.0)),
            sol.extent_y.unwrap_or((0.0, 0.0)),
        );
        let (strips, y0) = norm_strips(&sol, &sinks);
        if k == 0 {
            cell_mm = (grid.dx, grid.dy);
            for s in sinks {
                cells.extend(s.cells);
            }
        }
        patches.push(Patch {
            approach_mm: sol.approach,
            fn_n: sol.force,
            fx_n: tan.fx,
            fy_n: tan.fy,
            mz_nmm: tan.mz,
            pmax_mpa: sol.p_max,
            area_mm2: sol.area,
            x_extent_mm: [ex.0, ex.1],
            y_extent_mm: [ey.0, ey.1],
            stick_area_fraction: if area > 0.0 { stick / area } else { 0.0 },
            wear_depth_max_um: wear * 1e3,
            strips,
            y0,
            ..doc_patch(kp)
        });
    }
    if !kernel_ok {
        warnings.push("the kernel's load or frame iteration did not reach its tolerance".into());
    }
    Ok(Solved {
        patches,
        cells,
        status: Status {
            path: "converged",
            converged,
            iterations,
            warnings,
        },
        time_us,
        cell_mm,
        wear_strips,
    })
}

/// `strips` and `y0` of the kernel's tangential solve on NORM's pressure: one strip per NORM
/// row and contact run (the kernel strips of `tangential_on_norm`, one detailed sink per row
/// region); half-length of the run, normal load and forces from the kernel's totals of the
/// strip's cells, wear from the sink's per-strip KTH wear. `y0`: the cells of the grid row
/// through y = 0 (all its runs).
fn norm_strips<T: Real>(
    sol: &wrc_host_tests::norm::NormSolution,
    sinks: &[StatsSink<T, NORM_STRIPS>],
) -> (Vec<StripOut>, Vec<Y0Cell>) {
    let g = &sol.grid;
    let mut rows: Vec<(StripOut, &[Y0Cell])> = vec![];
    for s in sinks {
        for (j, r) in s.rows.iter().enumerate().filter(|(_, r)| r.seen) {
            let row = ((r.y - g.y0) / g.dy - 0.5).round().max(0.0) as usize;
            let half = sol
                .strips
                .get(row)
                .and_then(|st| {
                    st.runs
                        .iter()
                        .find(|run| run.i_first <= r.i_first && r.i_first <= run.i_last)
                })
                .map(|run| 0.5 * (run.x_lead - run.x_trail))
                .unwrap_or(0.0);
            rows.push((
                StripOut {
                    y_mm: r.y,
                    half_length_mm: half,
                    width_mm: g.dy,
                    fn_n: r.totals.fn_.to_f64(),
                    fx_n: r.totals.fx.to_f64(),
                    fy_n: r.totals.fy.to_f64(),
                    wear_depth_um: s.wear.depth[j].to_f64() * 1e3,
                },
                &r.cells,
            ));
        }
    }
    rows.sort_by(|a, b| a.0.y_mm.total_cmp(&b.0.y_mm));
    let mut y0 = vec![];
    if let Some(k) = y0_strip(rows.iter().map(|r| (r.0.y_mm, g.dy))) {
        let yk = rows[k].0.y_mm;
        for r in rows.iter().filter(|r| r.0.y_mm == yk) {
            y0.extend_from_slice(r.1);
        }
    }
    sort_by_x(&mut y0);
    (rows.into_iter().map(|r| r.0).collect(), y0)
}

/// `--normal hertz` on a wheel/rail case (module docs).
pub fn solve_hertz<T: Real, const C: usize>(
    args: &SolveArgs,
    keep: bool,
) -> Result<Solved, String> {
    const S: usize = 64;
    let cm = &args.common;
    let t = T::from_f64;
    match cm.flex.unwrap_or(Flex::Hertz) {
        Flex::Hertz => {}
        other => {
            return Err(format!(
                "--flex {other:?} needs a non-elliptic patch; --normal hertz uses --flex hertz"
            ))
        }
    }
    if cm.strips > S || cm.cells > C {
        return Err(format!(
            "--strips at most {S} and --cells at most {C} with --normal hertz"
        ));
    }
    let m = method(cm.tangential)?;
    let (kps, kernel_ok, mat64) = kernel_patches(args)?;
    let mat = Material {
        g: t(mat64.g),
        nu: t(mat64.nu),
        e_star: t(mat64.e_star),
    };
    let mu = t(cm.mu);
    let speed = t(cm.speed * 1e3);
    // one ellipse per patch from A, B at the reference point
    let mut ellipses = vec![];
    for (k, kp) in kps.iter().enumerate() {
        let g = gap_sample_at(&kp.gap, 0.0);
        if g.b_lat.is_nan() || g.b_lat <= 0.0 {
            return Err(format!(
                "patch {k}: lateral curvature at the reference point is not convex (B = {:.3e} 1/mm): no Hertz ellipse",
                g.b_lat
            ));
        }
        let h = hertz::from_load(t(g.a_long), t(g.b_lat), t(kp.load), &mat)
            .map_err(|e| format!("patch {k}: {e}"))?;
        ellipses.push(h);
    }
    let run = |keep: bool, detail: bool| -> Result<_, String> {
        let mut out = vec![];
        for (k, h) in ellipses.iter().enumerate() {
            let kp = &kps[k];
            let patch = crate::elliptic::hertz_patch::<T, S, C>(h, &mat, cm.strips, cm.cells)?;
            let cr = Creepage {
                xi: t(kp.creepage.xi),
                eta: t(kp.creepage.eta),
                phi: t(kp.creepage.phi),
            };
            let mut sink = StatsSink::<T, S>::new(WearMap::kth(), speed, patch.dx, keep && k == 0);
            if detail {
                sink = sink.detailed();
            }
            let res = match m {
                Method::Fastsim => fastsim(
                    &patch,
                    &SemiEllipticStrips,
                    &cr,
                    &FastsimSettings::canonical(
                        mu,
                        TractionBound::Parabolic(Ellipse {
                            a: h.a,
                            b: h.b,
                            p0: h.p0,
                        }),
                    ),
                    &mut sink,
                ),
                Method::Fastrip => fastrip(
                    &patch,
                    &SemiEllipticStrips,
                    &cr,
                    &FastripSettings::new(mu),
                    &mut sink,
                ),
            }
            .map_err(|e| format!("patch {k}: {e}"))?;
            out.push((patch, res, sink));
        }
        Ok(out)
    };
    let time_us = median_time_us(|| {
        let _ = run(false, false);
    });
    let solved = run(keep, true)?;
    let mut patches = vec![];
    let mut cells = vec![];
    let mut wear_strips = vec![];
    let mut cell_mm = (0.1, 0.1);
    for (k, ((kp, h), (patch, res, sink))) in kps.iter().zip(&ellipses).zip(solved).enumerate() {
        let (a, b) = (h.a.to_f64(), h.b.to_f64());
        if k == 0 {
            cell_mm = (patch.dx.to_f64(), patch.strips[0].dy.to_f64());
            wear_strips = patch
                .strips
                .iter()
                .zip(sink.wear.depth.iter())
                .filter(|(s, _)| s.a > T::ZERO)
                .map(|(s, d)| (s.y.to_f64(), d.to_f64() * 1e3))
                .collect();
        }
        let (strips, y0) = crate::sink::kernel_strips(&patch, cm.strips, &res, &sink);
        patches.push(Patch {
            approach_mm: h.delta.to_f64(),
            fn_n: h.load.to_f64(),
            fx_n: res.total.fx.to_f64(),
            fy_n: res.total.fy.to_f64(),
            mz_nmm: res.total.mz.to_f64(),
            pmax_mpa: h.p0.to_f64(),
            area_mm2: std::f64::consts::PI * a * b,
            x_extent_mm: [-a, a],
            y_extent_mm: [-b, b],
            stick_area_fraction: if sink.area > 0.0 {
                sink.stick_area / sink.area
            } else {
                0.0
            },
            wear_depth_max_um: sink.wear.max_depth(S).to_f64() * 1e3,
            strips,
            y0,
            ..doc_patch(kp)
        });
        cells.extend(sink.cells);
    }
    let mut warnings = vec![];
    if !kernel_ok {
        warnings.push("the kernel's load or frame iteration did not reach its tolerance".into());
    }
    Ok(Solved {
        patches,
        cells,
        status: Status {
            path: "converged",
            converged: kernel_ok,
            iterations: 0,
            warnings,
        },
        time_us,
        cell_mm,
        wear_strips,
    })
}
