//! Host time of the default pipeline per patch (STRIPES + AC + FaStrip + wear).
//!
//! Run: `cargo bench -p wrc-bench --bench pipeline`. Synthetic cases: a Hertzian gap and a
//! two-region double well (240 samples).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use wrc_kernel::patch::Creepage;
use wrc_kernel::pipeline::{solve_patch, DefaultWorkspace, PipelineConfig};
use wrc_kernel::stripes::StripSample;
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
}

criterion_group!(benches, bench);
criterion_main!(benches);
