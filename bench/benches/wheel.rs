//! Host time of the default pipeline **per wheel** (issue 6, Performance): placement of the wheel on
//! its rail (gap grid 0.05 mm) + `wheel::solve_wheel` (load split over all patches, STRIPES → AC →
//! FaStrip → KTH wear, normal–tangential coupling) at a vertical load of 83.3 kN, V = 100 km/h,
//! μ 0.3, on the 40 geometry cases of the S1002/UIC60 sweep (`wrc_bench::sweep`).
//!
//! Run: `cargo bench -p wrc-bench --bench wheel`. Prints
//! * per call (placement + solve): median over all calls, the largest per-case median and the
//!   largest single call, each with its ratio to the median;
//! * the breakdown per call (medians over the cases): placement, one `contact_patches`, one
//!   STRIPES solve, the strip layout, the AC adaptation, FaStrip (without and with the wear sink:
//!   the difference is the wear), and the counts that multiply them (geometry passes, STRIPES
//!   solves of the load split, coupling rounds, patches);
//!
//! Then criterion's own statistics for one tread case and one flange case.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use std::time::Instant;
use wrc_kernel::adapt::{region_patch, solve_tangential};
use wrc_kernel::geometry::{contact_patches, Patches, WheelRail};
use wrc_kernel::patch::{CellOut, CellSink, SemiEllipticStrips};
use wrc_kernel::pipeline::DefaultWorkspace;
use wrc_kernel::stripes::StripSample;
use wrc_kernel::wear::StripWear;
use wrc_kernel::wheel::{solve_wheel, DefaultWheelWorkspace, WheelConfig};
use wrc_kernel::Material;

const FZ: f64 = 83_300.0;
const GRID: f64 = 0.05;

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

/// Median time of `f` over `reps` calls, s.
fn time<R>(reps: usize, mut f: impl FnMut() -> R) -> f64 {
    let mut t: Vec<f64> = (0..reps)
        .map(|_| {
            let t0 = Instant::now();
            black_box(f());
            t0.elapsed().as_secs_f64()
        })
        .collect();
    median(&mut t)
}

struct Wear<'a> {
    w: &'a mut StripWear<f64, 128>,
    map: wrc_kernel::wear::WearMap<f64>,
    v: f64,
    dx: f64,
}

impl CellSink<f64> for Wear<'_> {
    fn cell(&mut self, j: usize, _i: usize, out: &CellOut<f64>) {
        if out.slip {
            let s = (out.sx * out.sx + out.sy * out.sy).sqrt();
            self.w.add_cell(&self.map, j, out.pn, s, self.v, self.dx);
        }
    }
}

fn bench(c: &mut Criterion) {
    let pair = wrc_bench::tables::<f64>();
    let (w, r) = (&*pair.0, &*pair.1);
    let cases = wrc_bench::sweep(&pair);
    let mat = Material::<f64>::steel();
    let v = 100.0 / 3.6 * 1000.0;
    let cfg = WheelConfig::recommended(0.3, v, 460.0);
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let call = |ws: &mut DefaultWheelWorkspace<f64>, k: usize| {
        let cs = &cases[k];
        let g = WheelRail::<f64, 2048, 2048>::place(r, w, &cs.setup, &cs.pose, cs.side, GRID)
            .expect("placement");
        solve_wheel(&g, FZ, &mat, &cfg, ws, &mut ()).expect("wheel")
    };
    // ---- per call ----
    let reps = 5;
    let mut all = vec![];
    let mut case_med = vec![];
    for k in 0..cases.len() {
        let mut t: Vec<f64> = (0..reps)
            .map(|_| {
                let t0 = Instant::now();
                black_box(call(&mut ws, k));
                t0.elapsed().as_secs_f64()
            })
            .collect();
        all.extend_from_slice(&t);
        case_med.push(median(&mut t));
    }
    let med = median(&mut all.clone());
    let max_case = case_med.iter().cloned().fold(0.0, f64::max);
    let max_call = all.iter().cloned().fold(0.0, f64::max);
    println!(
        "per wheel (placement {GRID} mm + wheel::solve_wheel, {} cases × {reps}): median {:.1} µs; \
         max case median {:.1} µs ({:.2} × median); max call {:.1} µs ({:.2} × median)",
        cases.len(),
        1e6 * med,
        1e6 * max_case,
        max_case / med,
        1e6 * max_call,
        max_call / med
    );
    // ---- breakdown ----
    let mut t_place = vec![];
    let mut t_cp = vec![];
    let mut t_st = vec![];
    let mut t_lay = vec![];
    let mut t_ac = vec![];
    let mut t_fs = vec![];
    let mut t_wear = vec![];
    let mut t_solve = vec![];
    let (mut passes, mut solves, mut rounds, mut npatch) = (vec![], vec![], vec![], vec![]);
    let mut patches = Box::new(Patches::<f64, 4, 128>::new());
    let mut pw = Box::new(DefaultWorkspace::<f64>::new());
    let mut wear = Box::new(StripWear::<f64, 128>::new());
    let mut samples = vec![StripSample::<f64>::default(); 128];
    for (k, cs) in cases.iter().enumerate() {
        t_place.push(time(reps, || {
            WheelRail::<f64, 2048, 2048>::place(r, w, &cs.setup, &cs.pose, cs.side, GRID)
                .expect("placement")
        }));
        let g = WheelRail::<f64, 2048, 2048>::place(r, w, &cs.setup, &cs.pose, cs.side, GRID)
            .expect("placement");
        let res = solve_wheel(&g, FZ, &mat, &cfg, &mut ws, &mut ()).expect("wheel");
        t_solve.push(time(reps, || {
            solve_wheel(&g, FZ, &mat, &cfg, &mut ws, &mut ()).expect("wheel")
        }));
        passes.push(res.geometry_calls as f64);
        solves.push(res.stripes_solves as f64);
        rounds.push(res.coupling_rounds as f64);
        npatch.push(res.patches.len() as f64);
        let dv = res.vertical_approach;
        t_cp.push(time(reps, || {
            contact_patches(&g, dv, &cfg.patches, &mut patches).expect("patches")
        }));
        contact_patches(&g, dv, &cfg.patches, &mut patches).expect("patches");
        // the heaviest patch
        let (kp, p) = res
            .patches
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.load.total_cmp(&b.1.load))
            .expect("a patch");
        let _ = kp;
        let mut kk = 0;
        for (i, it) in patches.as_slice().iter().enumerate() {
            if (it.frame.y_ref_rail - p.frame.y_ref_rail).abs() < 1e-9 {
                kk = i;
            }
        }
        let sm = &patches.items[kk].samples;
        for (i, o) in samples.iter_mut().enumerate().take(sm.n) {
            *o = StripSample {
                y: sm.s(i),
                dy: sm.width[i],
                z: sm.f_n[i],
                curv_a: sm.a_long[i],
                curv_b: sm.b_lat[i],
                xc: sm.x_c[i],
            };
        }
        let smp = &samples[..sm.n];
        let pc = &cfg.pipeline;
        t_st.push(time(reps, || {
            pw.stripes
                .solve(smp, p.load, &mat, &pc.stripes)
                .expect("stripes")
        }));
        let sol = pw
            .stripes
            .solve(smp, p.load, &mat, &pc.stripes)
            .expect("stripes");
        t_lay.push(time(reps, || {
            pw.stripes
                .layout(&sol, smp, p.load, pc.strips_per_region, &mut pw.set)
                .expect("layout")
        }));
        pw.stripes
            .layout(&sol, smp, p.load, pc.strips_per_region, &mut pw.set)
            .expect("layout");
        let mut local = [wrc_kernel::adapt::LocalEllipse::<f64>::default(); 32];
        let (mut ac, mut fs, mut fw) = (0.0, 0.0, 0.0);
        let bound = pc.adapt.default_bound();
        for reg in 0..pw.set.n_regions {
            let set = &pw.set;
            ac += time(reps, || {
                region_patch::<f64, 32, 32, 128, 4>(set, reg, &pc.adapt, &mat, &mut local)
                    .expect("AC")
            });
            let patch = region_patch::<f64, 32, 32, 128, 4>(set, reg, &pc.adapt, &mat, &mut local)
                .expect("AC");
            fs += time(reps, || {
                solve_tangential(
                    &patch,
                    &SemiEllipticStrips,
                    &p.creepage,
                    pc.method,
                    bound,
                    pc.mu,
                    &mut (),
                )
                .expect("fastrip")
            });
            fw += time(reps, || {
                let mut sink = Wear {
                    w: &mut wear,
                    map: pc.wear,
                    v,
                    dx: patch.dx,
                };
                solve_tangential(
                    &patch,
                    &SemiEllipticStrips,
                    &p.creepage,
                    pc.method,
                    bound,
                    pc.mu,
                    &mut sink,
                )
                .expect("fastrip")
            });
        }
        t_ac.push(ac);
        t_fs.push(fs);
        t_wear.push(fw - fs);
        let _ = k;
    }
    let us = |v: &mut Vec<f64>| 1e6 * median(v);
    let mx = |v: &[f64]| v.iter().cloned().fold(0.0, f64::max);
    println!(
        "breakdown (medians over the cases, µs): placement {:.1}; solve_wheel {:.1} (max {:.1}); \
         contact_patches ×1 {:.1}; STRIPES solve ×1 {:.1}; layout {:.1}; AC {:.1}; FaStrip {:.1}; wear {:.1}",
        us(&mut t_place),
        us(&mut t_solve.clone()),
        1e6 * mx(&t_solve),
        us(&mut t_cp),
        us(&mut t_st),
        us(&mut t_lay),
        us(&mut t_ac),
        us(&mut t_fs),
        us(&mut t_wear)
    );
    println!(
        "counts per call (median / max): contact_patches calls {} / {}; STRIPES solves of the load split {} / {}; \
         coupling rounds {} / {}; patches {} / {}",
        median(&mut passes.clone()),
        mx(&passes),
        median(&mut solves.clone()),
        mx(&solves),
        median(&mut rounds.clone()),
        mx(&rounds),
        median(&mut npatch.clone()),
        mx(&npatch)
    );
    // ---- criterion: one tread case (dy = 0, right, 1360) and one flange case (dy = 6) ----
    for (name, dy) in [("tread_dy0", 0.0), ("flange_dy6", 6.0)] {
        let k = cases
            .iter()
            .position(|cs| {
                cs.dy == dy
                    && cs.side == wrc_kernel::geometry::Side::Right
                    && cs.setup.back_to_back == 1360.0
            })
            .expect("case");
        c.bench_function(&format!("wheel_{name}"), |b| b.iter(|| call(&mut ws, k)));
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench
}
criterion_main!(benches);
