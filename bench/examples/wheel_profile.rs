//! Runs the per-wheel default pipeline (placement at 0.05 mm + `wheel::solve_wheel`, 83.3 kN
//! vertical load) once over the 40 cases of the issue-6 sweep, for a profiler:
//! `valgrind --tool=callgrind target/release/examples/wheel_profile` (deterministic counts).
//!
//! `wheel_profile <reps> <file>` also writes one line per case and patch (case, patch, N, Fx, Fy,
//! Mz, pmax, area, δ_v, geometry calls, STRIPES solves, coupling rounds, converged) to `file`, for
//! comparing two versions of the solver.

use std::fmt::Write as _;
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
    let mut args = std::env::args().skip(1);
    let reps: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(1);
    let dump = args.next();
    let mut out = String::new();
    let mut sum = 0.0;
    let (mut calls, mut solves) = (0, 0);
    for _ in 0..reps {
        out.clear();
        for (i, c) in cases.iter().enumerate() {
            let g = WheelRail::<f64, 2048, 2048>::place(r, w, &c.setup, &c.pose, c.side, 0.05)
                .expect("placement");
            let res = solve_wheel(&g, 83_300.0, &mat, &cfg, &mut ws, &mut ()).expect("wheel");
            calls += res.geometry_calls;
            solves += res.stripes_solves;
            for (k, p) in res.patches.iter().enumerate() {
                sum += p.result.totals.fy.abs() + p.result.pmax;
                let t = &p.result.totals;
                writeln!(
                    out,
                    "{i} {k} {:.12e} {:.12e} {:.12e} {:.12e} {:.12e} {:.12e} {:.12e} {} {} {} {}",
                    p.load,
                    t.fx,
                    t.fy,
                    t.mz,
                    p.result.pmax,
                    p.result.area,
                    res.vertical_approach,
                    res.geometry_calls,
                    res.stripes_solves,
                    res.coupling_rounds,
                    res.converged
                )
                .expect("string");
            }
        }
    }
    if let Some(f) = dump {
        std::fs::write(f, &out).expect("write dump");
    }
    println!("Σ (|Fy| + pmax) = {sum:.9}; contact_patches calls {calls}, STRIPES solves {solves}");
}
