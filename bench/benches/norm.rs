//! NORM reference (methods.md §9.1) timing: load-controlled Hertz solves (a = 8, b = 4 mm, 82 kN,
//! G = 82 000 MPa, ν = 0.28) on 64 × 64 and 128 × 128 grids over ±1.1a × ±1.1b, with the influence
//! spectrum set up beforehand (`solve`) and including the set-up (`setup+solve`).
//!
//! Run: `cargo bench -p wrc-bench --bench norm`. Iteration counts are printed before the timings,
//! followed by the process CPU time per solve (user + system from /proc/self/stat on Linux): on a
//! shared machine the wall-clock figures of criterion include waiting for a core.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;
use wrc_host_tests::norm::{Control, Grid, Norm, Options, Window};
use wrc_kernel::Material;

/// Hertz gap A x² + B y² of the a = 8, b = 4 mm, 82 kN case (methods.md §10.1).
const A: f64 = 0.846_419_467_532_808e-3;
const B: f64 = 2.406_161_741_852_433e-3;
const N: f64 = 82_000.0;

fn bench_norm(c: &mut Criterion) {
    let mat = Material::from_g_nu(82_000.0, 0.28).expect("valid material");
    let opts = Options::default();
    let mut group = c.benchmark_group("norm_load_control");
    group.sample_size(20);
    for m in [64usize, 128] {
        let grid = Grid::covering(Window::centred(8.8, 4.4), m, m).expect("valid grid");
        let gap = grid.sample(|x, y| A * x * x + B * y * y);
        let mut op = Norm::new(grid, mat).expect("valid operator");
        let s = op.solve(&gap, Control::Load(N), &opts).expect("solves");
        println!(
            "{m}x{m}: {} iterations, converged {}, p_max {:.2} MPa, approach {:.6} mm, {} contact elements",
            s.iterations, s.converged, s.p_max, s.approach, s.n_contact
        );
        group.bench_with_input(BenchmarkId::new("solve", m), &m, |b, _| {
            b.iter(|| {
                op.solve(black_box(&gap), Control::Load(N), &opts)
                    .expect("solves")
            })
        });
        group.bench_with_input(BenchmarkId::new("setup+solve", m), &m, |b, _| {
            b.iter(|| {
                Norm::new(grid, mat)
                    .expect("valid operator")
                    .solve(black_box(&gap), Control::Load(N), &opts)
                    .expect("solves")
            })
        });
    }
    group.finish();
}

/// CPU time of this process (user + system), s; `None` where /proc/self/stat is unavailable.
fn cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // Fields after the parenthesised command name; utime and stime are fields 14 and 15.
    let rest = &stat[stat.rfind(')')? + 2..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks: f64 = f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?;
    // USER_HZ is 100 on Linux.
    Some(ticks / 100.0)
}

/// Prints CPU time per load-controlled solve (operator prebuilt), averaged over ≥ 3 s of CPU.
fn cpu_time_report(_c: &mut Criterion) {
    let mat = Material::from_g_nu(82_000.0, 0.28).expect("valid material");
    let opts = Options::default();
    for m in [64usize, 128] {
        let grid = Grid::covering(Window::centred(8.8, 4.4), m, m).expect("valid grid");
        let gap = grid.sample(|x, y| A * x * x + B * y * y);
        let mut op = Norm::new(grid, mat).expect("valid operator");
        let Some(t0) = cpu_seconds() else {
            return;
        };
        let mut count = 0u32;
        let mut t1 = t0;
        while t1 - t0 < 3.0 {
            black_box(
                op.solve(black_box(&gap), Control::Load(N), &opts)
                    .expect("solves"),
            );
            count += 1;
            t1 = cpu_seconds().unwrap_or(t0 + 10.0);
        }
        println!(
            "{m}x{m}: CPU time per solve {:.2} ms ({count} solves)",
            1e3 * (t1 - t0) / f64::from(count)
        );
    }
}

criterion_group!(benches, bench_norm, cpu_time_report);
criterion_main!(benches);
