//! The statistical Hertzian test matrix of methods.md §10.10 (3220 cases = 5 ellipses × 4 spin
//! levels × 7 creepage directions × 23 creepage magnitudes): the kernel's FASTSIM and FaStrip
//! against the TANG exact steady-rolling reference.
//!
//! Run: `cargo run --release -p wrc-host-tests --bin study-hertz [-- options]`
//!
//! Options: `--coarse N` (reference coarse grid, elements per semi-axis, default 10), `--fine N`
//! (default 20 = 2·coarse; must be 2·coarse), `--threads T` (default 2), `--out PATH` (default
//! `out/hertz_matrix.csv`), `--check-convergence` (instead of the matrix: a subset solved also at
//! 2·fine to measure the reference's own error), `--quick` (subsample for iteration: directions
//! −60°, 0°, 30°, 90° and every other magnitude, 960 cases), `--reference CSV` (read the reference
//! forces of an earlier run's CSV and solve only the models: seconds instead of 23 minutes; output
//! `out/hertz_matrix_models.csv`).
//!
//! Reference: TANG on Hertz pressure at element centres (rescaled to F_n) on two grids with
//! n and 2n elements per semi-axis over ±1.1a × ±1.1b, Richardson-extrapolated (2·fine − coarse):
//! TANG's discretisation error is first order in δx (Carter, Kalker linear and CONTACT tests in
//! `tests/tang.rs`). Each creep curve is warm-started from its previous magnitude.
//! Models (kernel, f64, 32 strips × 32 cells over ±1.1a × ±1.1b, the kernel default grid of §0.5):
//! see [`MODEL_NAMES`].
//! Errors: |ΔF|/(μF_n) = |(ΔF_x, ΔF_y)|/(μF_n); |ΔM_z|/(μF_n c), c = √(ab).

use std::f64::consts::PI;
use std::io::Write;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;
use wrc_host_tests::table::Table;
use wrc_host_tests::tang::{hertz_pressure, richardson, Creepage, Grid, TangOptions, TangSolver};
use wrc_kernel::fastrip::{fastrip, FastripSettings, LargeSpin, SpinInX};
use wrc_kernel::fastsim::{fastsim, FastsimSettings, SlipRule};
use wrc_kernel::hertz::curvatures_from_semi_axes;
use wrc_kernel::patch::{self, GridExtent, HertzPressure, StripPatch, TractionBound};
use wrc_kernel::Material;

const G: f64 = 82_000.0;
const NU: f64 = 0.28;
const MU: f64 = 0.3;
const FN: f64 = 82_000.0;
const ELLIPSES: [(f64, f64); 5] = [(0.2, 4.0), (0.5, 6.0), (1.0, 9.0), (2.0, 12.0), (5.0, 20.0)];
const SPIN: [f64; 4] = [0.0, 0.5, 1.0, 2.0];
const ALPHA_DEG: [f64; 7] = [-90.0, -60.0, -30.0, 0.0, 30.0, 60.0, 90.0];
const MAG: [f64; 23] = [
    0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.7, 0.9, 1.1, 1.4, 1.7, 2.0, 2.5, 3.0, 3.5, 4.0, 5.0, 6.0, 7.0,
    8.0, 9.0, 10.0, 12.0,
];
const KS: usize = 32;

/// Forces normalised: (F_x/(μF_n), F_y/(μF_n), M_z/(μF_n c)).
type F3 = [f64; 3];

struct Row {
    ab: f64,
    a: f64,
    b: f64,
    s: f64,
    alpha: f64,
    m: f64,
    cr: Creepage,
    coarse: F3,
    fine: F3,
    extra: Option<F3>,
    reference: F3,
    sweeps: (usize, usize),
    converged: bool,
    t_ref: f64,
    models: Vec<F3>,
}

/// The models compared, by name (CSV column prefix):
/// * FASTSIM canonical (`SlipRule::Clip`, seed A / CONTACT) with the `Parabolic` and the `Elliptic`
///   bound; `…_coulomb`: Coulomb's law on FASTSIM's slip in the slipping cells
///   (`SlipRule::Coulomb`); `…_rigid`: on the rigid slip (`SlipRule::CoulombRigidSlip`);
/// * FaStrip: `fastrip_spec` = `FastripSettings::spec_clip` (the defaults before this study: `Clip`
///   direction pass, no bound check); `fastrip_coulomb`, `fastrip_rigid`: the same with the
///   direction pass's slip rule changed; `fastrip_rigid_fullslip`: plus `LargeSpin::FullSlip`;
///   `fastrip_lateral` = `FastripSettings::new` with the published spin weight in X_j
///   (`SpinInX::Lateral`, the default until 2026-12-02); `fastrip_spin_rigid`: with
///   `SpinInX::RigidSlip`; `fastrip` = `FastripSettings::new`, the kernel default (rigid-slip
///   Coulomb direction pass, `Contact5`, `BoundCheck::Strip`, `SpinInX::Linear`).
const MODEL_NAMES: [&str; 12] = [
    "fastsim_parabolic",
    "fastsim_elliptic",
    "fastsim_parabolic_coulomb",
    "fastsim_parabolic_rigid",
    "fastsim_elliptic_rigid",
    "fastrip_spec",
    "fastrip_coulomb",
    "fastrip_rigid",
    "fastrip_rigid_fullslip",
    "fastrip_lateral",
    "fastrip_spin_rigid",
    "fastrip",
];

fn kernel_models(a: f64, b: f64, cr: Creepage, c: f64) -> Vec<F3> {
    let mat = Material::from_g_nu(G, NU).expect("material");
    let (patch, ell): (StripPatch<f64, KS, KS>, _) =
        StripPatch::hertz(a, b, FN, &mat, GridExtent::contact()).expect("patch");
    let pr = HertzPressure(ell);
    let kc = patch::Creepage {
        xi: cr.xi,
        eta: cr.eta,
        phi: cr.phi,
    };
    let norm = |t: &patch::Totals<f64>| [t.fx / (MU * FN), t.fy / (MU * FN), t.mz / (MU * FN * c)];
    let fs = |bound: TractionBound<f64>, slip: SlipRule| {
        let set = FastsimSettings::with_slip(MU, bound, slip);
        norm(
            &fastsim(&patch, &pr, &kc, &set, &mut ())
                .expect("fastsim")
                .total,
        )
    };
    let fr = |set: FastripSettings<f64>| {
        norm(
            &fastrip(&patch, &pr, &kc, &set, &mut ())
                .expect("fastrip")
                .total,
        )
    };
    let spec = FastripSettings::spec_clip(MU);
    let dir = |slip| FastsimSettings::with_slip(MU, TractionBound::Elliptic, slip);
    let (par, ellb) = (TractionBound::Parabolic(ell), TractionBound::Elliptic);
    MODEL_NAMES
        .iter()
        .map(|name| match *name {
            "fastsim_parabolic" => fs(par, SlipRule::Clip),
            "fastsim_elliptic" => fs(ellb, SlipRule::Clip),
            "fastsim_parabolic_coulomb" => fs(par, SlipRule::Coulomb),
            "fastsim_parabolic_rigid" => fs(par, SlipRule::CoulombRigidSlip),
            "fastsim_elliptic_rigid" => fs(ellb, SlipRule::CoulombRigidSlip),
            "fastrip_spec" => fr(spec),
            "fastrip_coulomb" => fr(FastripSettings {
                direction: dir(SlipRule::Coulomb),
                ..spec
            }),
            "fastrip_rigid" => fr(FastripSettings {
                direction: dir(SlipRule::CoulombRigidSlip),
                ..spec
            }),
            "fastrip_rigid_fullslip" => fr(FastripSettings {
                direction: dir(SlipRule::CoulombRigidSlip),
                large_spin: LargeSpin::FullSlip,
                ..spec
            }),
            "fastrip_lateral" => fr(FastripSettings {
                spin_in_x: SpinInX::Lateral,
                ..FastripSettings::new(MU)
            }),
            "fastrip_spin_rigid" => fr(FastripSettings {
                spin_in_x: SpinInX::RigidSlip,
                ..FastripSettings::new(MU)
            }),
            "fastrip" => fr(FastripSettings::new(MU)),
            other => unreachable!("model {other}"),
        })
        .collect()
}

struct Level {
    n: usize,
    solver: TangSolver,
    pn: Vec<f64>,
}

fn level(a: f64, b: f64, n: usize) -> Level {
    let grid = Grid::hertz(a, b, n, 1.1);
    Level {
        n,
        pn: hertz_pressure(&grid, a, b, FN, true),
        solver: TangSolver::new(grid, G, NU),
    }
}

fn pct(v: &mut [f64], q: f64) -> f64 {
    v.sort_by(|x, y| x.partial_cmp(y).unwrap());
    if v.is_empty() {
        return f64::NAN;
    }
    let pos = q * (v.len() - 1) as f64;
    let (lo, hi) = (pos.floor() as usize, pos.ceil() as usize);
    v[lo] + (pos - lo as f64) * (v[hi] - v[lo])
}

fn main() {
    let mut coarse_n = 10usize;
    let mut fine_n = 0usize;
    let mut threads = 2usize;
    let mut out = String::from("out/hertz_matrix.csv");
    let mut check = false;
    let mut quick = false;
    let mut reference: Option<String> = None;
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut k = 0;
    while k < args.len() {
        let val = |k: usize| args.get(k + 1).cloned().expect("option value");
        match args[k].as_str() {
            "--coarse" => {
                coarse_n = val(k).parse().expect("--coarse N");
                k += 1;
            }
            "--fine" => {
                fine_n = val(k).parse().expect("--fine N");
                k += 1;
            }
            "--threads" => {
                threads = val(k).parse().expect("--threads T");
                k += 1;
            }
            "--out" => {
                out = val(k);
                k += 1;
            }
            "--check-convergence" => check = true,
            "--quick" => quick = true,
            "--reference" => {
                reference = Some(val(k));
                k += 1;
            }
            other => panic!("unknown option {other} (see the module docs)"),
        }
        k += 1;
    }
    if fine_n == 0 {
        fine_n = 2 * coarse_n;
    }
    assert_eq!(fine_n, 2 * coarse_n, "Richardson needs fine = 2·coarse");
    if check && out == "out/hertz_matrix.csv" {
        out = String::from("out/hertz_convergence.csv");
    }

    // Work items: one creep curve (ellipse, spin, direction) each.
    let mut items = Vec::new();
    for (ie, _) in ELLIPSES.iter().enumerate() {
        for (is, _) in SPIN.iter().enumerate() {
            for (ia, _) in ALPHA_DEG.iter().enumerate() {
                if check && !(is == 2 && ia == 4 && ie % 2 == 0) {
                    continue;
                }
                if quick && ![1, 3, 4, 6].contains(&ia) {
                    continue;
                }
                items.push((ie, is, ia));
            }
        }
    }
    let t0 = Instant::now();
    if let Some(path) = &reference {
        let rows = reuse_reference(path);
        if out == "out/hertz_matrix.csv" {
            out = String::from("out/hertz_matrix_models.csv");
        }
        write_and_summarise(rows, &out, false, coarse_n, fine_n, threads, t0);
        return;
    }
    let next = AtomicUsize::new(0);
    let rows: Mutex<Vec<Row>> = Mutex::new(Vec::new());
    std::thread::scope(|sc| {
        for _ in 0..threads.max(1) {
            sc.spawn(|| {
                let mut cache: Option<(usize, Level, Level, Option<Level>)> = None;
                loop {
                    let w = next.fetch_add(1, Ordering::SeqCst);
                    let Some(&(ie, is, ia)) = items.get(w) else {
                        break;
                    };
                    let (ab, a) = ELLIPSES[ie];
                    let b = a / ab;
                    if cache.as_ref().map(|c| c.0) != Some(ie) {
                        cache = Some((
                            ie,
                            level(a, b, coarse_n),
                            level(a, b, fine_n),
                            if check {
                                Some(level(a, b, 2 * fine_n))
                            } else {
                                None
                            },
                        ));
                    }
                    let (_, lc, lf, lx) = cache.as_ref().unwrap();
                    let mat = Material::from_g_nu(G, NU).unwrap();
                    let hz = curvatures_from_semi_axes(a, b, FN, &mat).expect("hertz");
                    let rho = 2.0 / (hz.curv_a + hz.curv_b);
                    let c = (a * b).sqrt();
                    let s = SPIN[is];
                    let al = ALPHA_DEG[ia] * PI / 180.0;
                    let opts = TangOptions {
                        tol: 1e-6,
                        max_sweeps: 3000,
                    };
                    let mut warm: Vec<Option<(Vec<f64>, Vec<f64>)>> = vec![None, None, None];
                    let mut local = Vec::new();
                    for (im, &m) in MAG.iter().enumerate() {
                        if quick && im % 2 == 1 {
                            continue;
                        }
                        let cr = Creepage {
                            xi: m * MU * al.cos() * c / rho,
                            eta: m * MU * al.sin() * c / rho,
                            phi: MU * s / rho,
                        };
                        let tr = Instant::now();
                        let mut res = Vec::new();
                        let mut conv = true;
                        let mut sweeps = Vec::new();
                        for (li, lv) in [Some(lc), Some(lf), lx.as_ref()].into_iter().enumerate() {
                            let Some(lv) = lv else {
                                continue;
                            };
                            let init = warm[li].as_ref().map(|(x, y)| (x.as_slice(), y.as_slice()));
                            let sol = lv.solver.solve(&lv.pn, MU, cr, &opts, init);
                            conv &= sol.converged;
                            sweeps.push(sol.sweeps);
                            res.push([
                                sol.fx / (MU * FN),
                                sol.fy / (MU * FN),
                                sol.mz / (MU * FN * c),
                            ]);
                            warm[li] = Some((sol.px, sol.py));
                            let _ = lv.n;
                        }
                        let t_ref = tr.elapsed().as_secs_f64();
                        let reference = [0, 1, 2].map(|q| richardson(res[0][q], res[1][q]));
                        local.push(Row {
                            ab,
                            a,
                            b,
                            s,
                            alpha: ALPHA_DEG[ia],
                            m,
                            cr,
                            coarse: res[0],
                            fine: res[1],
                            extra: res.get(2).copied(),
                            reference,
                            sweeps: (sweeps[0], sweeps[1]),
                            converged: conv,
                            t_ref,
                            models: kernel_models(a, b, cr, c),
                        });
                    }
                    let done = {
                        let mut r = rows.lock().unwrap();
                        r.extend(local);
                        r.len()
                    };
                    eprintln!(
                        "[{:7.1} s] curve a/b={ab} s={s} α={}° done ({done} cases)",
                        t0.elapsed().as_secs_f64(),
                        ALPHA_DEG[ia]
                    );
                }
            });
        }
    });
    let rows = rows.into_inner().unwrap();
    write_and_summarise(rows, &out, check, coarse_n, fine_n, threads, t0);
}

/// Rows of an earlier run's CSV (`--reference`): the reference forces and creepages are read back,
/// the models are solved again (so a model change is measured in seconds, not 23 minutes).
fn reuse_reference(path: &str) -> Vec<Row> {
    let t = Table::read(std::path::Path::new(path));
    let f = |r: usize, c: &str| t.f64(r, c).unwrap_or_else(|| panic!("{path}: bad {c}"));
    (0..t.rows.len())
        .map(|r| {
            let (a, b) = (f(r, "a"), f(r, "b"));
            let cr = Creepage {
                xi: f(r, "xi"),
                eta: f(r, "eta"),
                phi: f(r, "phi"),
            };
            let c = (a * b).sqrt();
            let g3 = |p: &str| {
                [
                    f(r, &format!("{p}_fx")),
                    f(r, &format!("{p}_fy")),
                    f(r, &format!("{p}_mz")),
                ]
            };
            Row {
                ab: f(r, "a_over_b"),
                a,
                b,
                s: f(r, "spin_s"),
                alpha: f(r, "alpha_deg"),
                m: f(r, "m"),
                cr,
                coarse: g3("coarse"),
                fine: g3("fine"),
                extra: None,
                reference: g3("ref"),
                sweeps: (f(r, "sweeps_coarse") as usize, f(r, "sweeps_fine") as usize),
                converged: t.str(r, "converged") == "true",
                t_ref: f(r, "t_ref_s"),
                models: kernel_models(a, b, cr, c),
            }
        })
        .collect()
}

#[allow(clippy::too_many_arguments)]
fn write_and_summarise(
    mut rows: Vec<Row>,
    out: &str,
    check: bool,
    coarse_n: usize,
    fine_n: usize,
    threads: usize,
    t0: Instant,
) {
    rows.sort_by(|x, y| {
        (x.ab, x.s, x.alpha, x.m)
            .partial_cmp(&(y.ab, y.s, y.alpha, y.m))
            .unwrap()
    });
    let wall = t0.elapsed().as_secs_f64();

    // CSV.
    if let Some(dir) = std::path::Path::new(&out).parent() {
        std::fs::create_dir_all(dir).ok();
    }
    let mut f = std::fs::File::create(out).expect("output file");
    write!(
        f,
        "a_over_b,a,b,spin_s,alpha_deg,m,xi,eta,phi,ref_fx,ref_fy,ref_mz,coarse_fx,coarse_fy,coarse_mz,fine_fx,fine_fy,fine_mz,"
    )
    .unwrap();
    if check {
        write!(f, "fine2_fx,fine2_fy,fine2_mz,").unwrap();
    }
    for n in MODEL_NAMES {
        write!(f, "{n}_fx,{n}_fy,{n}_mz,{n}_dF,{n}_dMz,").unwrap();
    }
    writeln!(f, "sweeps_coarse,sweeps_fine,converged,t_ref_s").unwrap();
    for r in &rows {
        write!(
            f,
            "{},{},{},{},{},{},{:e},{:e},{:e},",
            r.ab, r.a, r.b, r.s, r.alpha, r.m, r.cr.xi, r.cr.eta, r.cr.phi
        )
        .unwrap();
        for v in r.reference.iter().chain(&r.coarse).chain(&r.fine) {
            write!(f, "{v:.6},").unwrap();
        }
        if let Some(x) = r.extra {
            for v in x {
                write!(f, "{v:.6},").unwrap();
            }
        }
        for mo in &r.models {
            let df = (mo[0] - r.reference[0]).hypot(mo[1] - r.reference[1]);
            let dm = (mo[2] - r.reference[2]).abs();
            write!(f, "{:.6},{:.6},{:.6},{df:.6},{dm:.6},", mo[0], mo[1], mo[2]).unwrap();
        }
        writeln!(
            f,
            "{},{},{},{:.4}",
            r.sweeps.0, r.sweeps.1, r.converged, r.t_ref
        )
        .unwrap();
    }

    let nconv = rows.iter().filter(|r| r.converged).count();
    let tref: Vec<f64> = rows.iter().map(|r| r.t_ref).collect();
    let mut sw: Vec<f64> = rows.iter().map(|r| r.sweeps.1 as f64).collect();
    println!(
        "{} cases, reference grids n = {coarse_n}/{fine_n} per semi-axis (Richardson), {} converged; wall {wall:.0} s on {threads} threads; reference time per case mean {:.3} s, max {:.2} s; fine-grid sweeps median {:.0}, max {:.0}",
        rows.len(),
        nconv,
        tref.iter().sum::<f64>() / tref.len() as f64,
        tref.iter().cloned().fold(0.0, f64::max),
        pct(&mut sw.clone(), 0.5),
        pct(&mut sw, 1.0),
    );
    println!("CSV: {out}");
    if check {
        // Reference quality: Richardson(n, 2n) against the finest grid and Richardson(2n, 4n).
        let mut d_rich = Vec::new();
        let mut d_fine = Vec::new();
        let mut d_r2 = Vec::new();
        for r in &rows {
            let x = r.extra.unwrap();
            let r2 = [0, 1].map(|q| richardson(r.fine[q], x[q]));
            d_rich.push((r.reference[0] - r2[0]).hypot(r.reference[1] - r2[1]));
            d_fine.push((r.fine[0] - r2[0]).hypot(r.fine[1] - r2[1]));
            d_r2.push((x[0] - r2[0]).hypot(x[1] - r2[1]));
        }
        println!(
            "|F(n,2n Richardson) − F(2n,4n Richardson)|/(μFn): median {:.4}, max {:.4}",
            pct(&mut d_rich.clone(), 0.5),
            pct(&mut d_rich, 1.0)
        );
        println!(
            "|F(2n) − F(2n,4n Richardson)|/(μFn): median {:.4}, max {:.4};  |F(4n) − R(2n,4n)|: median {:.4}, max {:.4}",
            pct(&mut d_fine.clone(), 0.5),
            pct(&mut d_fine, 1.0),
            pct(&mut d_r2.clone(), 0.5),
            pct(&mut d_r2, 1.0)
        );
    }
    // Summary tables.
    for (mi, name) in MODEL_NAMES.iter().enumerate() {
        let mut all: Vec<f64> = Vec::new();
        let mut allm: Vec<f64> = Vec::new();
        let detail = matches!(
            *name,
            "fastsim_parabolic" | "fastrip_spec" | "fastrip_lateral" | "fastrip"
        );
        if detail {
            println!(
                "\n{name}: |ΔF|/(μFn) in % (median / P95 / max) and |ΔMz|/(μFn c) median / P95"
            );
            println!("  a/b   spin   median    P95     max   | Mz med   P95");
        }
        for &(ab, _) in ELLIPSES.iter() {
            for &s in SPIN.iter() {
                let sel: Vec<&Row> = rows.iter().filter(|r| r.ab == ab && r.s == s).collect();
                if sel.is_empty() {
                    continue;
                }
                let mut d: Vec<f64> = sel
                    .iter()
                    .map(|r| {
                        (r.models[mi][0] - r.reference[0]).hypot(r.models[mi][1] - r.reference[1])
                    })
                    .collect();
                let mut dm: Vec<f64> = sel
                    .iter()
                    .map(|r| (r.models[mi][2] - r.reference[2]).abs())
                    .collect();
                all.extend(&d);
                allm.extend(&dm);
                if !detail {
                    continue;
                }
                println!(
                    "  {ab:<4}  {s:<4}  {:6.2}  {:6.2}  {:6.2}   | {:6.2} {:6.2}",
                    100.0 * pct(&mut d.clone(), 0.5),
                    100.0 * pct(&mut d.clone(), 0.95),
                    100.0 * pct(&mut d, 1.0),
                    100.0 * pct(&mut dm.clone(), 0.5),
                    100.0 * pct(&mut dm, 0.95),
                );
            }
        }
        println!(
            "{name:>26} ALL ({} cases): |ΔF| median {:.2} %, P95 {:.2} %, max {:.2} %; |ΔMz|/(μFn c) median {:.2} %, P95 {:.2} %",
            all.len(),
            100.0 * pct(&mut all.clone(), 0.5),
            100.0 * pct(&mut all.clone(), 0.95),
            100.0 * pct(&mut all, 1.0),
            100.0 * pct(&mut allm.clone(), 0.5),
            100.0 * pct(&mut allm, 0.95),
        );
    }
}
