//! Diagnostics of the STRIPES continuity study (wheel_continuity open item), all `#[ignore]`d:
//! `DYS=5.873,5.874 cargo test -p wrc-host-tests --release --test stripes_continuity_diag conv -- --ignored --nocapture`
//! (per-wheel solve), `debug_jump` (STRIPES alone on the kernel's samples, `LOAD`, `OFF`, `SAMPLES`),
//! `dump_samples` (`DY`), `load_scan` (`DY L0 L1 M`), `unfiltered_runs` (`DY LOADS`), `eps_curve`.
#![allow(clippy::needless_range_loop)]
use wrc_host_tests::wheelrail::*;
use wrc_kernel::geometry::Side;
use wrc_kernel::stripes::{L0Mode, StripSet, Stripes, StripesConfig};
use wrc_kernel::Material;

#[test]
#[ignore]
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

#[test]
#[ignore]
fn dump_samples() {
    let (w, r) = tables().unwrap();
    let dy: f64 = std::env::var("DY").unwrap().parse().unwrap();
    let mat = Material::steel();
    let c = sweep_case(&w, &r, Side::Right, 1360.0, dy, 83_300.0).unwrap();
    let g = c.place(&w, &r).unwrap();
    let (_res, kps) = solve_kernel_case(&g, 83_300.0, &mat, &c.config()).unwrap();
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

#[test]
#[ignore]
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

#[test]
#[ignore]
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
        let ps: Vec<_> = res.patches[..res.n].iter().flatten().collect();
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
                    p.load, p.result.pmax, p.result.area, p.result.n_regions, p.result.converged
                ))
                .collect::<Vec<_>>()
                .join(" ")
        );
    }
}

#[test]
#[ignore]
fn load_scan() {
    let (w, r) = tables().unwrap();
    let dy: f64 = std::env::var("DY").unwrap().parse().unwrap();
    let (l0, l1, m): (f64, f64, usize) = (
        std::env::var("L0").unwrap().parse().unwrap(),
        std::env::var("L1").unwrap().parse().unwrap(),
        std::env::var("M").unwrap().parse().unwrap(),
    );
    let mat = Material::steel();
    let c = sweep_case(&w, &r, Side::Right, 1360.0, dy, 83_300.0).unwrap();
    let g = c.place(&w, &r).unwrap();
    let (_res, kps) = solve_kernel_case(&g, 83_300.0, &mat, &c.config()).unwrap();
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

#[test]
#[ignore]
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
    let (_res, kps) = solve_kernel_case(&g, 83_300.0, &mat, &c.config()).unwrap();
    let mut cfg = StripesConfig::<f64>::recommended();
    cfg.l0_mode = L0Mode::Off;
    let mut st = Box::new(Stripes::<f64, 128, 8, 4>::new());
    let s = &kps[0].stripes_samples;
    for load in loads {
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

#[test]
#[ignore]
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
        let ps: Vec<_> = res.patches[..res.n].iter().flatten().collect();
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
                    p.result.n_regions
                ))
                .collect::<Vec<_>>()
                .join(" ")
        );
    }
}
