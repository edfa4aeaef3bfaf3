//! Host time of the default pipeline.
//!
//! Run: `cargo bench -p wrc-bench --bench pipeline`.
//! * `pipeline_f64_hertz_gap`, `pipeline_f64_double_well`: `pipeline::solve_patch` on synthetic
//!   240-sample gaps (STRIPES + AC + FaStrip + wear).
//! * `wheel_sweep`: `wheel::solve_wheel_normal` (normal load of the main patch prescribed:
//!   patches at the weighted frame, load/approach fixed point, AC, FaStrip, wear; the wheel
//!   pre-placed — `WheelRail::place` is timed separately as
//!   `place_0.2mm`) on the S1002/UIC60 sweep (1353/1360, right wheel, dy −3…6, 83.3 kN); the
//!   per-case median and the maximum over cases are printed after a separate timing loop.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use std::time::Instant;
use wrc_host_tests::profiles::{self, SmoothOptions};
use wrc_kernel::geometry::*;
use wrc_kernel::patch::Creepage;
use wrc_kernel::pipeline::{solve_patch, DefaultWorkspace, PipelineConfig};
use wrc_kernel::stripes::StripSample;
use wrc_kernel::wheel::{solve_wheel_normal, WheelConfig, WheelWorkspace};
use wrc_kernel::Material;

fn synthetic(two: bool) -> Vec<StripSample<f64>> {
    let n = 240;
    let dy = 30.0 / n as f64;
    (0..n)
        .map(|i| {
            let y = -15.0 + (i as f64 + 0.5) * dy;
            let (z, b) = if two {
                let k = 1.2e-5;
                let u = y * y - 64.0;
                (k * u * u + 2e-4 * y, k * (6.0 * y * y - 128.0))
            } else {
                (0.0025 * y * y, 0.0025)
            };
            StripSample {
                y,
                dy,
                z,
                curv_a: 0.00108,
                curv_b: b,
                xc: 0.0,
            }
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let mat = Material::<f64>::steel();
    let cfg = PipelineConfig::recommended(0.3, 27_778.0);
    let cr = Creepage {
        xi: 0.001,
        eta: 0.0008,
        phi: 2e-4,
    };
    let mut ws = Box::new(DefaultWorkspace::<f64>::new());
    for (name, two) in [("hertz_gap", false), ("double_well", true)] {
        let s = synthetic(two);
        c.bench_function(&format!("pipeline_f64_{name}"), |b| {
            b.iter(|| {
                solve_patch(black_box(&s), 83_300.0, &cr, &mat, &cfg, &mut ws, &mut ()).unwrap()
            })
        });
    }
    // Sweep.
    let (w, r) = profiles::manchester_tables::<f64>(&SmoothOptions::default()).unwrap();
    let v = 100.0 / 3.6 * 1000.0;
    let mut cfg = WheelConfig::recommended(0.3, v, 460.0);
    cfg.patches.samples = 256;
    let mut geoms = vec![];
    for b2b in [1353.0, 1360.0] {
        let setup = TrackSetup {
            back_to_back: b2b,
            ..TrackSetup::<f64>::standard()
        };
        for dy in -3..=6 {
            let p0 = WheelsetPose::from_contact(dy as f64, 1.2e-3 * dy as f64, 0.0);
            geoms.push((setup, p0));
        }
    }
    let placed: Vec<_> = geoms
        .iter()
        .map(|(s, p)| WheelRail::<f64, 2048, 2048>::place(&r, &w, s, p, Side::Right, 0.2).unwrap())
        .collect();
    let mut wws = Box::new(WheelWorkspace::<f64, 4, 256, 256, 4, 32, 32, 128>::new());
    c.bench_function("wheel_sweep_20_cases", |b| {
        b.iter(|| {
            for g in &placed {
                black_box(solve_wheel_normal(g, 83_300.0, &mat, &cfg, &mut wws, &mut ()).unwrap());
            }
        })
    });
    let (s0, p0) = geoms[5];
    c.bench_function("place_0.2mm", |b| {
        b.iter(|| WheelRail::<f64, 2048, 2048>::place(&r, &w, &s0, &p0, Side::Right, 0.2).unwrap())
    });
    // Per-case median and maximum over the sweep.
    let mut med = vec![];
    for g in &placed {
        let mut t = vec![];
        for _ in 0..31 {
            let t0 = Instant::now();
            black_box(solve_wheel_normal(g, 83_300.0, &mat, &cfg, &mut wws, &mut ()).unwrap());
            t.push(t0.elapsed().as_secs_f64());
        }
        t.sort_by(|a, b| a.partial_cmp(b).unwrap());
        med.push(t[15]);
    }
    let mut sorted = med.clone();
    sorted.sort_by(|a, b| a.partial_cmp(b).unwrap());
    println!(
        "solve_wheel_normal per call over the sweep: median of case medians {:.1} µs, max case median {:.1} µs (ratio {:.2})",
        1e6 * sorted[sorted.len() / 2],
        1e6 * sorted[sorted.len() - 1],
        sorted[sorted.len() - 1] / sorted[sorted.len() / 2]
    );
}

criterion_group!(benches, bench);
criterion_main!(benches);
