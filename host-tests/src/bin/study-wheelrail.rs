//! The wheel/rail tangential study of issues 6 and 7 (methods.md §10.11): the six simplified models
//! (FASTSIM, FaStrip × KP, Linder, AC) on the kernel's STRIPES pressure and on NORM pressure, against
//! Kalker's exact steady rolling (TANG) on NORM pressure, for every patch of the S1002/UIC60 sweep
//! (right and left wheel, back-to-back 1353 and 1360 mm, dy −3…6 mm, loads 40, 83.3, 120 kN) and
//! of the Manchester rows.
//!
//! Run: `cargo run --release -p wrc-host-tests --bin study-wheelrail [-- options]`
//!
//! Options: `--quick` (83.3 kN only, no Manchester rows), `--no-mbench`, `--threads T` (2),
//! `--out DIR` (`out/wheelrail`), `--normal strips` (the kernel's pressure from the strip model,
//! `wrc_kernel::ritz`, instead of STRIPES; the tables keep the label "STRIPES" for the kernel's).
//!
//! Writes `DIR/tangential.csv` (one row per patch: reference and every model on both pressures,
//! forces normalised by μF_n and M_z by μF_n c, wear-profile errors), `DIR/y0_dy{0,-2,6}.csv` and
//! `.svg` (traction and slip along the strip nearest y = 0, 1353 mm right wheel 83.3 kN) and prints
//! the measures per model, pressure and set (`tangstudy` module docs for the definitions).

use std::io::Write;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;
use wrc_host_tests::tangstudy::{
    on_kernel, on_norm, reference, wear_error, CellRec, Compared, Measures, Run, WearCmp, MODELS,
};
use wrc_host_tests::wheelrail::{
    mbench_material, mbench_rows, solve_mbench_row, solve_sweep_case, sweep_cases, tables,
    CaseSolution, NormGridOptions, SWEEP_LOADS, SWEEP_MU, SWEEP_SPEED,
};
use wrc_kernel::geometry::Side;
use wrc_kernel::Material;

/// One model on a patch: (on STRIPES, on NORM) comparisons and wear-profile comparisons.
type ModelCmp = (Compared, Compared, WearCmp, WearCmp);

/// One compared patch.
struct Row {
    label: String,
    set: &'static str,
    b2b: f64,
    side: Side,
    dy: f64,
    load: f64,
    patch: usize,
    fn_: f64,
    area: f64,
    creep: [f64; 3],
    exact: [f64; 3],
    converged: bool,
    sweeps: usize,
    t_ref: f64,
    /// Per model: (STRIPES, NORM) comparisons and wear errors (max, integral).
    models: Vec<ModelCmp>,
    profiles: Option<Vec<Profile>>,
}

/// One source's profiles for the figures: name, cells of the strip nearest y = 0, wear per strip.
type Profile = (String, Vec<CellRec>, Vec<(f64, f64)>);

/// The seed's rolling speed for its Figs. 15–16 (200 km/h, mm/s); the sweep itself runs at
/// [`SWEEP_SPEED`].
const FIGURE_SPEED: f64 = 200.0 / 3.6 * 1000.0;

enum Case {
    Sweep(Box<wrc_host_tests::wheelrail::SweepCase>),
    Mbench(Box<wrc_host_tests::wheelrail::MbenchRow>),
}

fn y0_cells(cells: &[CellRec]) -> Vec<CellRec> {
    let y = cells
        .iter()
        .map(|c| c.y)
        .min_by(|a, b| a.abs().total_cmp(&b.abs()))
        .unwrap_or(0.0);
    let mut v: Vec<CellRec> = cells.iter().filter(|c| c.y == y).copied().collect();
    v.sort_by(|a, b| a.x.total_cmp(&b.x));
    v
}

#[allow(clippy::too_many_arguments)]
fn compare(
    cs: &CaseSolution,
    mat: &Material<f64>,
    mu: f64,
    speed: f64,
    label: &str,
    set: &'static str,
    (b2b, side, dy, load): (f64, Side, f64, f64),
    keep_profiles: bool,
) -> Result<Vec<Row>, String> {
    let mut out = vec![];
    for (k, pc) in cs.patches.iter().enumerate() {
        let t0 = Instant::now();
        let (ex, sol) = reference(pc, mat, mu, speed);
        let t_ref = t0.elapsed().as_secs_f64();
        let area = pc.norm.area;
        let ce = Compared::new(&ex, &ex, mu, area).exact;
        let mut models = vec![];
        for m in MODELS {
            let run = |r: Result<Run, wrc_kernel::Error>| {
                r.map_err(|e| {
                    format!(
                        "{label} patch {k} {} (NORM grid {} x {}): {e}",
                        m.name(),
                        pc.norm.grid.mx,
                        pc.norm.grid.my
                    )
                })
            };
            let a = run(on_kernel(pc, m, mat, mu, speed, strip_model()))?;
            let b = run(on_norm(pc, m, mat, mu, speed))?;
            models.push((
                Compared::new(&a, &ex, mu, area),
                Compared::new(&b, &ex, mu, area),
                wear_error(&a.wear, &ex.wear),
                wear_error(&b.wear, &ex.wear),
            ));
        }
        // The figures: the same patch at the seed's speed (the wear map depends on V|s|).
        let profiles = if keep_profiles {
            let v = FIGURE_SPEED;
            let (exf, _) = reference(pc, mat, mu, v);
            let mut prof = vec![(
                "exact (TANG on NORM)".to_string(),
                y0_cells(&exf.cells),
                exf.wear,
            )];
            for m in MODELS {
                for (pname, r) in [
                    ("STRIPES", on_kernel(pc, m, mat, mu, v, strip_model())),
                    ("NORM", on_norm(pc, m, mat, mu, v)),
                ] {
                    let r = r.map_err(|e| format!("{label} patch {k} {}: {e}", m.name()))?;
                    prof.push((format!("{} {pname}", m.name()), y0_cells(&r.cells), r.wear));
                }
            }
            Some(prof)
        } else {
            None
        };
        out.push(Row {
            label: label.to_string(),
            set,
            b2b,
            side,
            dy,
            load,
            patch: k,
            fn_: ex.fn_,
            area,
            creep: [pc.creepage.xi, pc.creepage.eta, pc.creepage.phi],
            exact: ce,
            converged: sol.converged,
            sweeps: sol.sweeps,
            t_ref,
            models,
            profiles,
        });
    }
    Ok(out)
}

/// `--normal strips`: the kernel's pressure from the strip model (`ritz`) instead of STRIPES.
static STRIP_MODEL: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

fn strip_model() -> bool {
    STRIP_MODEL.load(Ordering::Relaxed)
}

fn main() {
    let mut quick = false;
    let mut mbench = true;
    let mut threads = 2usize;
    let mut out = String::from("out/wheelrail");
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut k = 0;
    while k < args.len() {
        match args[k].as_str() {
            "--quick" => {
                quick = true;
                mbench = false;
            }
            "--no-mbench" => mbench = false,
            "--threads" => {
                k += 1;
                threads = args[k].parse().expect("--threads T");
            }
            "--out" => {
                k += 1;
                out = args[k].clone();
            }
            "--normal" => {
                k += 1;
                match args[k].as_str() {
                    "stripes" => STRIP_MODEL.store(false, Ordering::Relaxed),
                    "strips" => STRIP_MODEL.store(true, Ordering::Relaxed),
                    o => panic!("--normal stripes|strips, not {o}"),
                }
            }
            o => panic!("unknown option {o} (see the module docs)"),
        }
        k += 1;
    }
    std::fs::create_dir_all(&out).expect("output directory");
    let loads: Vec<f64> = if quick {
        vec![83_300.0]
    } else {
        SWEEP_LOADS.to_vec()
    };
    let mut cases: Vec<Case> = sweep_cases(&loads)
        .expect("sweep cases")
        .into_iter()
        .map(|c| Case::Sweep(Box::new(c)))
        .collect();
    if mbench {
        cases.extend(
            mbench_rows()
                .expect("mbench rows")
                .into_iter()
                .map(|r| Case::Mbench(Box::new(r))),
        );
    }
    let (w, r) = tables().expect("profiles");
    let t0 = Instant::now();
    let next = AtomicUsize::new(0);
    let rows: Mutex<Vec<Row>> = Mutex::new(vec![]);
    let failures: Mutex<Vec<String>> = Mutex::new(vec![]);
    std::thread::scope(|sc| {
        for _ in 0..threads.max(1) {
            sc.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::SeqCst);
                let Some(c) = cases.get(i) else { break };
                let nopt = NormGridOptions::default();
                let res = match c {
                    Case::Sweep(c) => solve_sweep_case(&w, &r, c, &nopt).map(|cs| {
                        let keep = c.back_to_back == 1353.0
                            && c.side == Side::Right
                            && c.load == 83_300.0
                            && [0.0, -2.0, 6.0].contains(&c.dy);
                        let set = if c.back_to_back == 1353.0 {
                            "1353"
                        } else {
                            "1360"
                        };
                        compare(
                            &cs,
                            &Material::steel(),
                            SWEEP_MU,
                            SWEEP_SPEED,
                            &c.label,
                            set,
                            (c.back_to_back, c.side, c.dy, c.load),
                            keep,
                        )
                    }),
                    Case::Mbench(m) => solve_mbench_row(&w, &r, m, &nopt).map(|cs| {
                        compare(
                            &cs,
                            &mbench_material(),
                            0.3,
                            2000.0,
                            &m.label(),
                            "mbench",
                            (1360.0, m.side, m.y_ws, m.fz),
                            false,
                        )
                    }),
                };
                match res.map_err(|e| e.to_string()).and_then(|r| r) {
                    Ok(v) => {
                        let mut g = rows.lock().unwrap();
                        g.extend(v);
                        eprintln!("[{:6.0} s] {} rows", t0.elapsed().as_secs_f64(), g.len());
                    }
                    Err(e) => failures.lock().unwrap().push(format!("case {i}: {e}")),
                }
            });
        }
    });
    let mut rows = rows.into_inner().unwrap();
    rows.sort_by(|a, b| a.label.cmp(&b.label).then(a.patch.cmp(&b.patch)));
    let failures = failures.into_inner().unwrap();
    write_csv(&rows, &format!("{out}/tangential.csv"));
    write_profiles(&rows, &out);
    summarise(&rows, &failures, t0.elapsed().as_secs_f64());
}

fn write_csv(rows: &[Row], path: &str) {
    let mut f = std::fs::File::create(path).expect("csv");
    write!(f, "label,set,b2b,side,dy,load,patch,fn,area,xi,eta,phi,ref_fx,ref_fy,ref_mz,converged,sweeps,t_ref_s,ref_wear_max_mm,ref_wear_int_mm2").unwrap();
    for m in MODELS {
        for p in ["stripes", "norm"] {
            let n = format!("{}_{p}", m.name());
            write!(f, ",{n}_fx,{n}_fy,{n}_mz,{n}_wear_max,{n}_wear_int").unwrap();
        }
    }
    writeln!(f).unwrap();
    for r in rows {
        write!(
            f,
            "{},{},{},{:?},{},{},{},{:.2},{:.4},{:e},{:e},{:e},{:.6},{:.6},{:.6},{},{},{:.3},{:e},{:e}",
            r.label,
            r.set,
            r.b2b,
            r.side,
            r.dy,
            r.load,
            r.patch,
            r.fn_,
            r.area,
            r.creep[0],
            r.creep[1],
            r.creep[2],
            r.exact[0],
            r.exact[1],
            r.exact[2],
            r.converged,
            r.sweeps,
            r.t_ref,
            r.models[0].2.rmax,
            r.models[0].2.rint
        )
        .unwrap();
        for (a, b, wa, wb) in &r.models {
            for (c, w) in [(a, wa.ratios()), (b, wb.ratios())] {
                write!(
                    f,
                    ",{:.6},{:.6},{:.6},{:.4},{:.4}",
                    c.model[0], c.model[1], c.model[2], w.0, w.1
                )
                .unwrap();
            }
        }
        writeln!(f).unwrap();
    }
    println!("CSV: {path}");
}

fn write_profiles(rows: &[Row], dir: &str) {
    for r in rows.iter().filter(|r| r.profiles.is_some() && r.patch == 0) {
        let prof = r.profiles.as_ref().unwrap();
        let path = format!("{dir}/y0_dy{}.csv", r.dy);
        let mut f = std::fs::File::create(&path).expect("csv");
        writeln!(f, "source,y_mm,x_mm,pn_mpa,px_mpa,py_mpa,slip,s").unwrap();
        for (name, cells, _) in prof {
            for c in cells {
                writeln!(
                    f,
                    "{name},{:.4},{:.4},{:.3},{:.4},{:.4},{},{:e}",
                    c.y, c.x, c.pn, c.px, c.py, c.slip, c.s
                )
                .unwrap();
            }
        }
        let wpath = format!("{dir}/wear_dy{}.csv", r.dy);
        let mut f = std::fs::File::create(&wpath).expect("csv");
        writeln!(f, "source,y_mm,wear_depth_um").unwrap();
        for (name, _, wear) in prof {
            for (y, d) in wear {
                writeln!(f, "{name},{y:.4},{:e}", 1e3 * d).unwrap();
            }
        }
        let svg = format!("{dir}/y0_dy{}.svg", r.dy);
        let title = format!("{}, yaw {:.1} mrad, 200 km/h", r.label, 1.2 * r.dy);
        match plot_profile(&svg, &title, prof) {
            Ok(()) => println!("profiles: {path}, {wpath}, {svg}"),
            Err(e) => println!("profiles: {path}, {wpath} (no plot: {e})"),
        }
    }
}

/// Three panels: tangential traction |p_t| along the strip nearest y = 0 (with μp_n of the
/// reference), slip velocity along it (m/s), wear depth per strip (µm per passage) against y.
fn plot_profile(path: &str, title: &str, prof: &[Profile]) -> Result<(), String> {
    use plotters::prelude::*;
    let font = std::env::var("WRC_FONT")
        .unwrap_or_else(|_| "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf".into());
    let bytes = std::fs::read(&font).map_err(|e| format!("font {font}: {e}"))?;
    let leaked: &'static [u8] = Box::leak(bytes.into_boxed_slice());
    plotters::style::register_font("sans-serif", FontStyle::Normal, leaked)
        .map_err(|_| "font".to_string())?;
    let err = |e: &dyn std::fmt::Debug| format!("{e:?}");
    let root = SVGBackend::new(path, (1000, 1050)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let keep = [
        "exact (TANG on NORM)",
        "FaStrip-AC STRIPES",
        "FaStrip-AC NORM",
        "FASTSIM-AC STRIPES",
        "FASTSIM-AC NORM",
    ];
    let sel: Vec<&Profile> = keep
        .iter()
        .filter_map(|k| prof.iter().find(|p| p.0 == *k))
        .collect();
    let colours = [BLACK, RED, BLUE, GREEN, MAGENTA];
    let v_m_s = FIGURE_SPEED * 1e-3;
    let areas = root.split_evenly((3, 1));
    // Panels 1 and 2: along x.
    let (mut x0, mut x1) = (f64::MAX, f64::MIN);
    let (mut t1, mut s1) = (0.0f64, 0.0f64);
    for (_, c, _) in &sel {
        for q in c.iter() {
            x0 = x0.min(q.x);
            x1 = x1.max(q.x);
            t1 = t1.max(q.px.hypot(q.py)).max(SWEEP_MU * q.pn);
            s1 = s1.max(q.s * v_m_s);
        }
    }
    if x0 >= x1 {
        return Ok(());
    }
    for (panel, area) in areas.iter().enumerate().take(2) {
        let (ymax, caption) = if panel == 0 {
            (t1, format!("{title}: |p_t| along y ≈ 0 (MPa); dashed μp_n"))
        } else {
            (s1, "slip velocity along y ≈ 0 (m/s)".to_string())
        };
        let mut ch = ChartBuilder::on(area)
            .caption(caption, ("sans-serif", 17))
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, 0.0..ymax * 1.08 + 1e-12)
            .map_err(|e| err(&e))?;
        ch.configure_mesh()
            .x_desc("x, mm (rolling direction)")
            .draw()
            .map_err(|e| err(&e))?;
        for (k, (name, cells, _)) in sel.iter().enumerate() {
            let col = colours[k % colours.len()];
            let pts: Vec<(f64, f64)> = cells
                .iter()
                .map(|c| {
                    (
                        c.x,
                        if panel == 0 {
                            c.px.hypot(c.py)
                        } else {
                            c.s * v_m_s
                        },
                    )
                })
                .collect();
            ch.draw_series(LineSeries::new(pts, col.stroke_width(2)))
                .map_err(|e| err(&e))?
                .label(name.as_str())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], col));
            if panel == 0 && k == 0 {
                let bound: Vec<(f64, f64)> = cells.iter().map(|c| (c.x, SWEEP_MU * c.pn)).collect();
                ch.draw_series(DashedLineSeries::new(bound, 6, 4, BLACK.stroke_width(1)))
                    .map_err(|e| err(&e))?;
            }
        }
        ch.configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(|e| err(&e))?;
    }
    // Panel 3: wear per strip against y.
    let (mut y0, mut y1, mut w1) = (f64::MAX, f64::MIN, 0.0f64);
    for (_, _, w) in &sel {
        for &(y, d) in w.iter() {
            y0 = y0.min(y);
            y1 = y1.max(y);
            w1 = w1.max(1e3 * d);
        }
    }
    if y0 < y1 {
        let mut ch = ChartBuilder::on(&areas[2])
            .caption(
                "wear depth per strip and passage (µm), KTH map",
                ("sans-serif", 17),
            )
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(60)
            .build_cartesian_2d(y0..y1, 0.0..w1 * 1.08 + 1e-15)
            .map_err(|e| err(&e))?;
        ch.configure_mesh()
            .x_desc("y, mm (contact-local, lateral)")
            .draw()
            .map_err(|e| err(&e))?;
        for (k, (name, _, wear)) in sel.iter().enumerate() {
            let col = colours[k % colours.len()];
            let pts: Vec<(f64, f64)> = wear.iter().map(|&(y, d)| (y, 1e3 * d)).collect();
            ch.draw_series(LineSeries::new(pts, col.stroke_width(2)))
                .map_err(|e| err(&e))?
                .label(name.as_str())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], col));
        }
        ch.configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(|e| err(&e))?;
    }
    root.present().map_err(|e| err(&e))?;
    Ok(())
}

fn summarise(rows: &[Row], failures: &[String], wall: f64) {
    let nconv = rows.iter().filter(|r| r.converged).count();
    let tmax = rows.iter().map(|r| r.t_ref).fold(0.0, f64::max);
    let tmean = rows.iter().map(|r| r.t_ref).sum::<f64>() / rows.len().max(1) as f64;
    println!(
        "{} patches, TANG converged in {nconv}; TANG time per patch mean {tmean:.2} s, max {tmax:.2} s; wall {wall:.0} s; {} case failures",
        rows.len(),
        failures.len()
    );
    for f in failures {
        println!("  failure: {f}");
    }
    type Sel = Box<dyn Fn(&Row) -> bool>;
    let sets: Vec<(&str, Sel)> = vec![
        ("1353", Box::new(|r: &Row| r.set == "1353")),
        (
            "1353 R 83.3kN (seed A)",
            Box::new(|r: &Row| r.set == "1353" && r.side == Side::Right && r.load == 83_300.0),
        ),
        ("1360", Box::new(|r: &Row| r.set == "1360")),
        (
            "1360 w/o dy=0",
            Box::new(|r: &Row| r.set == "1360" && r.dy != 0.0),
        ),
        ("sweep (1353+1360)", Box::new(|r: &Row| r.set != "mbench")),
        ("mbench A-2.2", Box::new(|r: &Row| r.set == "mbench")),
        ("all", Box::new(|_: &Row| true)),
    ];
    println!("\nMeasures in % (eq31 published / floored / mean |ΔF| / max |ΔF| of μFn / mean |ΔMz| / max |ΔMz| of μFn c)");
    for (sname, sel) in &sets {
        let sub: Vec<&Row> = rows.iter().filter(|r| sel(r)).collect();
        if sub.is_empty() {
            continue;
        }
        println!("\n{sname} ({} patches)", sub.len());
        println!(
            "  {:<16} {:>8} {:>8} {:>8} {:>8} {:>8} {:>8} | {:>8} {:>8} {:>8} {:>8} {:>8} {:>8}",
            "model",
            "S eq31",
            "S floor",
            "S mean",
            "S max",
            "S Mz",
            "S Mzmax",
            "N eq31",
            "N floor",
            "N mean",
            "N max",
            "N Mz",
            "N Mzmax"
        );
        for (mi, m) in MODELS.iter().enumerate() {
            let ms = Measures::of(&sub.iter().map(|r| r.models[mi].0).collect::<Vec<_>>());
            let mn = Measures::of(&sub.iter().map(|r| r.models[mi].1).collect::<Vec<_>>());
            let p = |x: f64| 100.0 * x;
            println!(
                "  {:<16} {:8.2} {:8.2} {:8.2} {:8.2} {:8.2} {:8.2} | {:8.2} {:8.2} {:8.2} {:8.2} {:8.2} {:8.2}",
                m.name(),
                p(ms.eq31),
                p(ms.floored),
                p(ms.abs_mean),
                p(ms.abs_max),
                p(ms.mz_mean),
                p(ms.mz_max),
                p(mn.eq31),
                p(mn.floored),
                p(mn.abs_mean),
                p(mn.abs_max),
                p(mn.mz_mean),
                p(mn.mz_max)
            );
        }
    }
    println!("\nWear profile vs TANG (patches where the reference wears), peak = max|Δdepth| vs max depth, integral = |Δ∫depth dy| vs ∫depth dy, %:");
    println!("  wear-weighted = Σ|Δ| / Σ reference over patches; median and plain mean of the per-patch ratios");
    println!(
        "  {:<16} {:>8} | {:>9} {:>9} | {:>9} {:>9} | {:>9} {:>9}",
        "model", "pressure", "wtd peak", "wtd int", "med peak", "med int", "mean peak", "mean int"
    );
    for (mi, m) in MODELS.iter().enumerate() {
        for (pi, pname) in ["STRIPES", "NORM"].iter().enumerate() {
            let s = WearStats::of(rows.iter().map(|r| {
                if pi == 0 {
                    r.models[mi].2
                } else {
                    r.models[mi].3
                }
            }));
            println!(
                "  {:<16} {:>8} | {:9.1} {:9.1} | {:9.1} {:9.1} | {:9.1} {:9.1}   ({} patches)",
                m.name(),
                pname,
                s.weighted.0,
                s.weighted.1,
                s.median.0,
                s.median.1,
                s.mean.0,
                s.mean.1,
                s.n
            );
        }
    }
    let fa = WearStats::of(rows.iter().map(|r| r.models[5].2));
    let chk = |b: bool| if b { "met" } else { "MISSED" };
    println!("\nIssue-17 wear targets, FaStrip-AC (default pipeline on STRIPES pressure) vs TANG on NORM:");
    println!(
        "  wear-weighted integral ≤ 6 %: {:.1} % {}; peak ≤ 10 %: {:.1} % {}",
        fa.weighted.1,
        chk(fa.weighted.1 <= 6.0),
        fa.weighted.0,
        chk(fa.weighted.0 <= 10.0)
    );
    println!(
        "  median integral ≤ 8 %: {:.1} % {}; peak ≤ 15 %: {:.1} % {}",
        fa.median.1,
        chk(fa.median.1 <= 8.0),
        fa.median.0,
        chk(fa.median.0 <= 15.0)
    );
    // Issue-7 targets for the default pipeline (FaStrip-AC on STRIPES) and FaStrip-AC on NORM.
    let fa = 5;
    let m = |s: &str| -> (Measures, Measures) {
        let (_, sel) = sets.iter().find(|(n, _)| *n == s).unwrap();
        let sub: Vec<&Row> = rows.iter().filter(|r| sel(r)).collect();
        (
            Measures::of(&sub.iter().map(|r| r.models[fa].0).collect::<Vec<_>>()),
            Measures::of(&sub.iter().map(|r| r.models[fa].1).collect::<Vec<_>>()),
        )
    };
    let (s1353, n1353) = m("1353");
    let (sall, nall) = m("all");
    println!("\nIssue-7 targets, FaStrip-AC (default pipeline on STRIPES pressure):");
    println!(
        "  eq. 31 on 1353 ≤ 4 %: {:.2} % {}",
        100.0 * s1353.eq31,
        chk(s1353.eq31 <= 0.04)
    );
    println!(
        "  floored eq. 31, all ≤ 3 %: {:.2} % {}",
        100.0 * sall.floored,
        chk(sall.floored <= 0.03)
    );
    println!(
        "  mean |ΔF| ≤ 1.5 %: {:.2} % {}; max |ΔF| ≤ 5 %: {:.2} % {}",
        100.0 * sall.abs_mean,
        chk(sall.abs_mean <= 0.015),
        100.0 * sall.abs_max,
        chk(sall.abs_max <= 0.05)
    );
    println!(
        "  |ΔMz| ≤ 10 % of μFn c: max {:.2} % {}",
        100.0 * sall.mz_max,
        chk(sall.mz_max <= 0.10)
    );
    println!(
        "  FaStrip-AC on NORM pressure, eq. 31 ≤ 3 %: 1353 {:.2} % {}, floored all {:.2} % {}",
        100.0 * n1353.eq31,
        chk(n1353.eq31 <= 0.03),
        100.0 * nall.floored,
        chk(nall.floored <= 0.03)
    );
}

/// Wear-profile statistics over patches, % ((peak, integral) pairs).
struct WearStats {
    n: usize,
    weighted: (f64, f64),
    median: (f64, f64),
    mean: (f64, f64),
}

impl WearStats {
    fn of(it: impl Iterator<Item = WearCmp>) -> Self {
        let v: Vec<WearCmp> = it.filter(|w| w.rmax > 0.0 && w.rint > 0.0).collect();
        let n = v.len();
        let sum = |f: &dyn Fn(&WearCmp) -> f64| v.iter().map(f).sum::<f64>();
        let pct = |a: f64, b: f64| if b > 0.0 { 100.0 * a / b } else { f64::NAN };
        let weighted = (
            pct(sum(&|w| w.dmax), sum(&|w| w.rmax)),
            pct(sum(&|w| w.dint), sum(&|w| w.rint)),
        );
        let med = |f: &dyn Fn(&WearCmp) -> f64| {
            let mut x: Vec<f64> = v.iter().map(f).collect();
            x.sort_by(f64::total_cmp);
            if x.is_empty() {
                f64::NAN
            } else if x.len() % 2 == 1 {
                100.0 * x[x.len() / 2]
            } else {
                50.0 * (x[x.len() / 2 - 1] + x[x.len() / 2])
            }
        };
        let median = (med(&|w| w.ratios().0), med(&|w| w.ratios().1));
        let mean = (
            100.0 * sum(&|w| w.ratios().0) / n.max(1) as f64,
            100.0 * sum(&|w| w.ratios().1) / n.max(1) as f64,
        );
        Self {
            n,
            weighted,
            median,
            mean,
        }
    }
}
