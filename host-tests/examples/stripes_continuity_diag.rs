//! Diagnostics of the STRIPES continuity study (what `tests/wheel_continuity.rs` asserts), one
//! subcommand each, parameters from environment variables:
//! `DYS=5.873,5.874 cargo run -p wrc-host-tests --release --example stripes_continuity_diag -- conv`
//! (per-wheel solve), `debug_jump` (STRIPES alone on the kernel's samples, `LOAD`, `OFF`, `SAMPLES`),
//! `dump_samples` (`DY`), `load_scan` (`DY L0 L1 M`, optional `B2B LOADN`), `unfiltered_runs`
//! (`DY LOADS`), `eps_curve`, `fine_regions` (`FROM TO STEP`, optional `B2B LOADN BFLOOR`: per-wheel
//! solve, per region N, F_x, pmax, area), `sliver_scan` (`DV0 DV1 M BFLOOR`, optional `NLS ONLY0`:
//! regions that carry no load after the strip re-solve, Manchester rows). `INTER=0|1` sets
//! `StripesConfig::interaction` in `debug_jump`, `fine_regions` and (for the wheel solve)
//! `unfiltered_runs`.
#![allow(clippy::needless_range_loop)]
use wrc_host_tests::wheelrail::*;
use wrc_kernel::geometry::Side;
use wrc_kernel::stripes::{L0Mode, StripSet, Stripes, StripesConfig};
use wrc_kernel::Material;

fn debug_jump() {
    let (w, r) = tables().unwrap();
    let dys: Vec<f64> = std::env::var("DYS")
        .unwrap()
        .split(',')
        .map(|s| s.parse().unwrap())
        .collect();
    let fixed_load: Option<f64> = std::env::var("LOAD").ok().map(|s| s.parse().unwrap());
    let off = std::env::var("OFF").is_ok();
    let mat = Material::steel();
    for dy in dys {
        let c = sweep_case(&w, &r, Side::Right, 1360.0, dy, 83_300.0).unwrap();
        let g = c.place(&w, &r).unwrap();
        let (res, kps) = solve_kernel_case(&g, 83_300.0, &mat, &c.config()).unwrap();
        let kp = &kps[0];
        let load = fixed_load.unwrap_or(kp.load);
        let mut cfg = StripesConfig::<f64>::recommended();
        if off {
            cfg.l0_mode = L0Mode::Off;
        }
        if let Ok(v) = std::env::var("INTER") {
            cfg.interaction = v == "1";
        }
        let mut st = Box::new(Stripes::<f64, 128, 8, 4>::new());
        let s = &kp.stripes_samples;
        let sol = st.solve(s, load, &mat, &cfg).unwrap();
        let mut set = Box::new(StripSet::<f64, 32, 4>::new());
        st.layout(&sol, s, load, 32, &mut set).unwrap();
        println!("dy {dy:.4} conv {} wheel pmax {:.4} area {:.4} load {:.3} n {} | sol d {:.6e} pmax {:.4} area {:.4} nb {} passes {} regs {} | set pmax {:.4} area {:.4} d {:.6e}",
            res.converged, kp.kernel.pmax, kp.kernel.area, kp.load, s.len(), sol.delta, sol.pmax, sol.area, sol.basins, sol.passes, sol.n_regions, set.total_pmax, set.total_area, set.delta);
        for k in 0..sol.basins {
            println!("   basin {k} {:?}", st.basin_info(k));
        }
        for q in 0..sol.n_regions {
            let rg = sol.regions[q];
            println!(
                "   reg {q} y {:.5}..{:.5} first {} count {} area {:.4} pmax {:.4}",
                rg.y_lo, rg.y_hi, rg.first, rg.count, rg.area, rg.pmax
            );
        }
        if std::env::var("SAMPLES").is_ok() {
            for i in 0..s.len() {
                if st.depth(i) > 0.0
                    || (i > 0 && st.depth(i - 1) > 0.0)
                    || (i + 1 < s.len() && st.depth(i + 1) > 0.0)
                {
                    println!(
                        "     i {i} y {:.5} z {:.6e} B {:.5e} Bf {:.5e} eps {:.6} h {:.5e} a {:.5}",
                        s[i].y,
                        s[i].z,
                        s[i].curv_b,
                        st.filtered_curvature(i),
                        st.eps_local(i),
                        st.depth(i),
                        st.half_length(i)
                    );
                }
            }
        }
    }
}

fn dump_samples() {
    let (w, r) = tables().unwrap();
    let dy: f64 = std::env::var("DY").unwrap().parse().unwrap();
    let mat = Material::steel();
    let b2b: f64 = std::env::var("B2B")
        .map(|s| s.parse().unwrap())
        .unwrap_or(1360.0);
    let fz: f64 = std::env::var("LOADN")
        .map(|s| s.parse().unwrap())
        .unwrap_or(83_300.0);
    let c = sweep_case(&w, &r, Side::Right, b2b, dy, fz).unwrap();
    let g = c.place(&w, &r).unwrap();
    let (_res, kps) = solve_kernel_case(&g, fz, &mat, &c.config()).unwrap();
    let cfg = StripesConfig::<f64>::recommended();
    let mut st = Box::new(Stripes::<f64, 128, 8, 4>::new());
    let s = &kps[0].stripes_samples;
    let _sol = st.solve(s, 83345.0, &mat, &cfg).unwrap();
    for i in 0..s.len() {
        println!(
            "{i} {:.6} {:.6} {:.8e} {:.6e} {:.6e} {:.6e} {:.6e}",
            s[i].y,
            s[i].dy,
            s[i].z,
            s[i].curv_a,
            s[i].curv_b,
            st.filtered_curvature(i),
            st.depth(i)
        );
    }
}

fn eps_curve() {
    let a = 1.028e-3;
    let e_star = Material::<f64>::steel().e_star;
    for k in 0..=24 {
        let b = 1e-6 * 10f64.powf(k as f64 / 6.0);
        let h = wrc_kernel::hertz::coefficients(a, b).unwrap();
        let eps = h.n * h.n * b / (h.r * (a + b));
        println!(
            "B {b:.3e} eps {eps:.5} kst {:.4e} at {:.4e}",
            e_star / (h.n * h.r * eps),
            (h.n / h.m).powi(2) * b
        );
    }
}

fn conv() {
    let (w, r) = tables().unwrap();
    let dys: Vec<f64> = std::env::var("DYS")
        .unwrap()
        .split(',')
        .map(|s| s.parse().unwrap())
        .collect();
    let mut ws = Box::new(wrc_kernel::wheel::DefaultWheelWorkspace::<f64>::new());
    for dy in dys {
        let c = sweep_case(&w, &r, Side::Right, 1360.0, dy, 83_300.0).unwrap();
        let g = c.place(&w, &r).unwrap();
        let res = wrc_kernel::wheel::solve_wheel(
            &g,
            83_300.0,
            &Material::steel(),
            &c.config(),
            &mut ws,
            &mut (),
        )
        .unwrap();
        let ps: Vec<_> = res.patches.iter().collect();
        println!(
            "dy {dy:.4} conv {} it {} rounds {} solves {} vload {:.4} dv {:.6e} | {}",
            res.converged,
            res.iterations,
            res.coupling_rounds,
            res.stripes_solves,
            res.vertical_load,
            res.vertical_approach,
            ps.iter()
                .map(|p| format!(
                    "[N {:.2} pmax {:.3} area {:.4} regs {} conv {}]",
                    p.load,
                    p.result.pmax,
                    p.result.area,
                    p.result.regions.len(),
                    p.result.converged
                ))
                .collect::<Vec<_>>()
                .join(" ")
        );
    }
}

fn load_scan() {
    let (w, r) = tables().unwrap();
    let dy: f64 = std::env::var("DY").unwrap().parse().unwrap();
    let (l0, l1, m): (f64, f64, usize) = (
        std::env::var("L0").unwrap().parse().unwrap(),
        std::env::var("L1").unwrap().parse().unwrap(),
        std::env::var("M").unwrap().parse().unwrap(),
    );
    let mat = Material::steel();
    let b2b: f64 = std::env::var("B2B")
        .map(|s| s.parse().unwrap())
        .unwrap_or(1360.0);
    let fz: f64 = std::env::var("LOADN")
        .map(|s| s.parse().unwrap())
        .unwrap_or(83_300.0);
    let c = sweep_case(&w, &r, Side::Right, b2b, dy, fz).unwrap();
    let g = c.place(&w, &r).unwrap();
    let (_res, kps) = solve_kernel_case(&g, fz, &mat, &c.config()).unwrap();
    let cfg = StripesConfig::<f64>::recommended();
    let mut st = Box::new(Stripes::<f64, 128, 8, 4>::new());
    let s = &kps[0].stripes_samples;
    for k in 0..=m {
        let load = l0 + (l1 - l0) * k as f64 / m as f64;
        let sol = st.solve(s, load, &mat, &cfg).unwrap();
        let b: Vec<String> = (0..sol.basins)
            .map(|q| {
                let x = st.basin_info(q).unwrap();
                format!(
                    "({} {:.3e} th {:.4} zr {:.3e} l0 {:.4})",
                    x.0, x.1, x.2, x.3, x.4
                )
            })
            .collect();
        println!(
            "N {load:.2} d {:.8e} area {:.4} pmax {:.3} regs {} passes {} {}",
            sol.delta,
            sol.area,
            sol.pmax,
            sol.n_regions,
            sol.passes,
            b.join(" ")
        );
    }
}

fn unfiltered_runs() {
    let (w, r) = tables().unwrap();
    let dy: f64 = std::env::var("DY").unwrap().parse().unwrap();
    let loads: Vec<f64> = std::env::var("LOADS")
        .unwrap()
        .split(',')
        .map(|s| s.parse().unwrap())
        .collect();
    let mat = Material::steel();
    let c = sweep_case(&w, &r, Side::Right, 1360.0, dy, 83_300.0).unwrap();
    let g = c.place(&w, &r).unwrap();
    let inter = std::env::var("INTER").map_or(true, |v| v == "1");
    let mut wc = c.config();
    wc.pipeline.stripes.interaction = inter;
    let (_res, kps) = solve_kernel_case(&g, 83_300.0, &mat, &wc).unwrap();
    let mut cfg = StripesConfig::<f64>::recommended();
    cfg.l0_mode = L0Mode::Off;
    cfg.interaction = false;
    let mut st = Box::new(Stripes::<f64, 128, 8, 4>::new());
    let s = &kps[0].stripes_samples;
    for load in loads {
        let load = if load > 0.0 { load } else { kps[0].load };
        let sol = st.solve(s, load, &mat, &cfg).unwrap();
        let b: Vec<String> = (0..sol.basins)
            .map(|q| {
                let x = st.basin_info(q).unwrap();
                format!("({} y {:.3} th {:.4})", x.0, s[x.0].y, x.2)
            })
            .collect();
        let rg: Vec<String> = (0..sol.n_regions)
            .map(|q| {
                format!(
                    "[{:.4}..{:.4} i{}+{}]",
                    sol.regions[q].y_lo,
                    sol.regions[q].y_hi,
                    sol.regions[q].first,
                    sol.regions[q].count
                )
            })
            .collect();
        println!(
            "N {load} d {:.6e} {} | {}",
            sol.delta,
            b.join(" "),
            rg.join(" ")
        );
    }
}

fn forces_fine() {
    let (w, r) = tables().unwrap();
    let dys: Vec<f64> = std::env::var("DYS")
        .unwrap()
        .split(',')
        .map(|s| s.parse().unwrap())
        .collect();
    let mut ws = Box::new(wrc_kernel::wheel::DefaultWheelWorkspace::<f64>::new());
    for dy in dys {
        let c = sweep_case(&w, &r, Side::Right, 1360.0, dy, 83_300.0).unwrap();
        let g = c.place(&w, &r).unwrap();
        let res = wrc_kernel::wheel::solve_wheel(
            &g,
            83_300.0,
            &Material::steel(),
            &c.config(),
            &mut ws,
            &mut (),
        )
        .unwrap();
        let ps: Vec<_> = res.patches.iter().collect();
        println!(
            "dy {dy:.4} conv {} | {}",
            res.converged,
            ps.iter()
                .map(|p| format!(
                    "[N {:.2} fx {:.3} fy {:.3} pmax {:.3} area {:.4} regs {}]",
                    p.load,
                    p.result.totals.fx,
                    p.result.totals.fy,
                    p.result.pmax,
                    p.result.area,
                    p.result.regions.len()
                ))
                .collect::<Vec<_>>()
                .join(" ")
        );
    }
}

/// Fine scan per region: `FROM TO STEP` (mm), per-wheel solve, prints per patch/region
/// N, Fx, Fy, pmax, area, y-range.
fn fine_regions() {
    let (w, r) = tables().unwrap();
    let from: f64 = std::env::var("FROM").unwrap().parse().unwrap();
    let to: f64 = std::env::var("TO").unwrap().parse().unwrap();
    let step: f64 = std::env::var("STEP").unwrap().parse().unwrap();
    let b2b: f64 = std::env::var("B2B")
        .map(|s| s.parse().unwrap())
        .unwrap_or(1360.0);
    let load: f64 = std::env::var("LOADN")
        .map(|s| s.parse().unwrap())
        .unwrap_or(83_300.0);
    let mut ws = Box::new(wrc_kernel::wheel::WheelWorkspace::<
        f64,
        4,
        128,
        256,
        4,
        128,
        32,
        512,
    >::new());
    let n = ((to - from) / step).round() as usize;
    for k in 0..=n {
        let dy = from + step * k as f64;
        let c = sweep_case(&w, &r, Side::Right, b2b, dy, load).unwrap();
        let g = c.place(&w, &r).unwrap();
        let mut cfg = c.config();
        if let Ok(v) = std::env::var("INTER") {
            cfg.pipeline.stripes.interaction = v == "1";
        }
        if let Ok(b) = std::env::var("BFLOOR") {
            cfg.pipeline.stripes.b_floor = b.parse().unwrap();
        }
        if let Ok(b) = std::env::var("STRIPS") {
            cfg.pipeline.strips_per_region = b.parse().unwrap();
        }
        let res =
            wrc_kernel::wheel::solve_wheel(&g, load, &Material::steel(), &cfg, &mut ws, &mut ())
                .unwrap();
        let ps: Vec<_> = res.patches.iter().collect();
        let tot = |f: &dyn Fn(&wrc_kernel::wheel::WheelPatch<f64, 4>) -> f64| -> f64 {
            ps.iter().map(|p| f(p)).sum()
        };
        println!(
            "dy {dy:.5} conv {} it {} rounds {} solves {} vload {:.4} pconv {:?} N {:.3} Fx {:.3} Fy {:.3} pmax {:.3} area {:.4} | {}",
            res.converged,
            res.iterations,
            res.coupling_rounds,
            res.stripes_solves,
            res.vertical_load,
            ps.iter().map(|p| (p.result.converged, p.result.iterations)).collect::<Vec<_>>(),
            tot(&|p| p.load),
            tot(&|p| p.result.totals.fx),
            tot(&|p| p.result.totals.fy),
            ps.iter().map(|p| p.result.pmax).fold(0.0, f64::max),
            tot(&|p| p.result.area),
            ps.iter()
                .map(|p| p.result.regions[..p.result.regions.len()]
                    .iter()
                    .map(|g| format!(
                        "({:.3}..{:.3} n{} N {:.1} pm {:.2} A {:.3} fx {:.1})",
                        g.y_lo, g.y_hi, g.count, g.load, g.pmax, g.area, g.totals.fx
                    ))
                    .collect::<Vec<_>>()
                    .join(" "))
                .collect::<Vec<_>>()
                .join(" || ")
        );
    }
}

/// Scan for a sliver region (zero load after the re-solve): Manchester right y_ws = 0,
/// δ_v from `DV0` to `DV1` in `M` steps, load `NL`, `EpsWeighted(0.5)`, `BFLOOR`.
fn sliver_scan() {
    use wrc_kernel::geometry::{contact_patches, PatchOptions, Patches};
    use wrc_kernel::pipeline::{solve_patch, DefaultWorkspace, PipelineConfig};
    use wrc_kernel::stripes::{HMode, StripSample};
    let env = |k: &str| std::env::var(k).unwrap().parse::<f64>().unwrap();
    let (w, r) = tables().unwrap();
    let m = env("M") as usize;
    for row in mbench_rows().unwrap() {
        let g = row.place(&w, &r).unwrap();
        for hm in [
            HMode::EpsWeighted(0.5),
            HMode::EpsLocal,
            HMode::Eps0,
            HMode::EpsSmoothed(2.0),
        ] {
            for k in 0..=m {
                let dv = env("DV0") + (env("DV1") - env("DV0")) * k as f64 / m as f64;
                let mut ps = Box::new(Patches::<f64, 4, 128>::new());
                let opts = PatchOptions {
                    samples: 128,
                    ..PatchOptions::default()
                };
                if contact_patches(&g, dv, &opts, &mut ps).is_err() || ps.len == 0 {
                    continue;
                }
                let s = &ps.as_slice()[0].samples;
                let st: Vec<StripSample<f64>> = (0..s.n)
                    .map(|i| StripSample {
                        y: s.s(i),
                        dy: s.width[i],
                        z: s.f_n[i],
                        curv_a: s.a_long[i],
                        curv_b: s.b_lat[i],
                        xc: s.x_c[i],
                    })
                    .collect();
                let mut cfg = PipelineConfig::<f64>::recommended(0.3, 2000.0);
                cfg.stripes = StripesConfig {
                    h_mode: hm,
                    b_floor: env("BFLOOR"),
                    ..StripesConfig::recommended()
                };
                let mut ws = Box::new(DefaultWorkspace::<f64>::new());
                let nls: Vec<f64> = std::env::var("NLS")
                    .map(|v| v.split(',').map(|x| x.parse().unwrap()).collect())
                    .unwrap_or(vec![5_000.0, 10_004.4, 20_000.0]);
                let only0 = std::env::var("ONLY0").is_ok();
                for nl in nls {
                    let res = solve_patch(
                        &st,
                        nl,
                        &row.creepage(),
                        &mbench_material(),
                        &cfg,
                        &mut ws,
                        &mut (),
                    );
                    match res {
                        Ok(res) if only0 && !res.regions.iter().any(|r| r.load == 0.0) => {}
                        Ok(res) => println!(
                            "{} {hm:?} dv {dv:.6} N {nl} regions {} loads {:?}",
                            row.label(),
                            res.regions.len(),
                            res.regions[..res.regions.len()]
                                .iter()
                                .map(|r| r.load)
                                .collect::<Vec<_>>()
                        ),
                        Err(e) => println!("dv {dv:.6} N {nl} err {e:?}"),
                    }
                }
            }
        }
    }
}

fn main() {
    let which = std::env::args().nth(1).unwrap_or_default();
    match which.as_str() {
        "debug_jump" => debug_jump(),
        "dump_samples" => dump_samples(),
        "eps_curve" => eps_curve(),
        "conv" => conv(),
        "load_scan" => load_scan(),
        "unfiltered_runs" => unfiltered_runs(),
        "forces_fine" => forces_fine(),
        "fine_regions" => fine_regions(),
        "sliver_scan" => sliver_scan(),
        _ => {
            eprintln!(
                "usage: stripes_continuity_diag <{}>",
                [
                    "debug_jump",
                    "dump_samples",
                    "eps_curve",
                    "conv",
                    "load_scan",
                    "unfiltered_runs",
                    "forces_fine",
                    "fine_regions",
                    "sliver_scan"
                ]
                .join("|")
            );
            std::process::exit(2);
        }
    }
}
