//! Runs the per-wheel default pipeline (placement at 0.05 mm + `wheel::solve_wheel`, 83.3 kN
//! vertical load) once over the 40 cases of the issue-6 sweep, for a profiler:
//! `valgrind --tool=callgrind target/release/examples/wheel_profile` (deterministic counts).

use wrc_kernel::geometry::WheelRail;
use wrc_kernel::wheel::{solve_wheel, DefaultWheelWorkspace, WheelConfig};
use wrc_kernel::Material;

fn main() {
    let pair = wrc_bench::tables::<f64>();
    let cases = wrc_bench::sweep(&pair);
    let (w, r) = &pair;
    let mat = Material::<f64>::steel();
    let v = 100.0 / 3.6 * 1000.0;
    let cfg = WheelConfig::recommended(0.3, v, 460.0);
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let reps: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1);
    let mut sum = 0.0;
    let (mut calls, mut solves) = (0, 0);
    for _ in 0..reps {
        for c in &cases {
            let g = WheelRail::<f64, 2048, 2048>::place(r, w, &c.setup, &c.pose, c.side, 0.05)
                .expect("placement");
            let res = solve_wheel(&g, 83_300.0, &mat, &cfg, &mut ws, &mut ()).expect("wheel");
            calls += res.geometry_calls;
            solves += res.stripes_solves;
            for p in res.patches[..res.n].iter().flatten() {
                sum += p.result.totals.fy.abs() + p.result.pmax;
            }
        }
    }
    println!("Σ (|Fy| + pmax) = {sum:.9}; contact_patches calls {calls}, STRIPES solves {solves}");
}
