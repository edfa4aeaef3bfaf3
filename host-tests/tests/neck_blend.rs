//! The pipeline's neck blend (`pipeline::solve_patch`, module docs): where STRIPES regions
//! appear or merge, the patch's pmax, area, approach and forces are continuous in the load.
//!
//! Gap: two parabolic valleys (radius 300 mm, centres ±4 mm, the left one 0.5 µm higher) joined
//! by a smooth ridge (soft minimum z = −s ln(e^(−z₁/s) + e^(−z₂/s)), s = 0.5 µm; B by central
//! differences), A = 1/460 mm⁻¹, 128 samples over ±12 mm, steel, ξ = 1e-3, η = 5e-4, μ 0.3, loads
//! 1 kN · 1.12^k. Every change of the region count is bisected to 1e-9 relative in the load;
//! across that bracket each quantity must change by less than 1e-4 of its size, and the load
//! steps of 1e-4 just below and above must be alike (within 3×).
//!
//! Measured (2026-12-01) at the merge (56.4 kN): with the blend the changes across the bracket
//! are 3.8e-6 (pmax), 3.3e-6 (area), 7.7e-6 (approach), 1.1e-5 (F_x), 3.3e-5 (F_y) — against
//! 3e-5…7e-5 over a load step of 1e-4; with the blend off (`NECK_RATIO` 0) the per-region layout
//! jumps by 2.9e-4, 6.8e-4, 5.5e-4, 7.6e-4 and 6.2e-4, which this test rejects. (The blend's
//! residual is below the 1e-4 bound but not zero; its origin is not traced.)

use wrc_kernel::patch::Creepage;
use wrc_kernel::pipeline::{solve_patch, DefaultWorkspace, PipelineConfig};
use wrc_kernel::stripes::StripSample;
use wrc_kernel::Material;

fn samples() -> Vec<StripSample<f64>> {
    let n = 128;
    let (y0, y1) = (-12.0, 12.0);
    let dy = (y1 - y0) / (n - 1) as f64;
    let s = 5e-4;
    let z = |y: f64| {
        let z1 = (y + 4.0) * (y + 4.0) / 600.0 + 5e-4;
        let z2 = (y - 4.0) * (y - 4.0) / 600.0;
        -s * ((-z1 / s).exp() + (-z2 / s).exp()).ln()
    };
    let h = 1e-4;
    (0..n)
        .map(|i| {
            let y = y0 + dy * i as f64;
            StripSample {
                y,
                dy,
                z: z(y),
                curv_a: 1.0 / 460.0,
                curv_b: (z(y + h) - 2.0 * z(y) + z(y - h)) / (h * h),
                xc: 0.0,
            }
        })
        .collect()
}

struct Out {
    regions: usize,
    q: [f64; 5],
}

fn solve(s: &[StripSample<f64>], load: f64, ws: &mut DefaultWorkspace<f64>) -> Out {
    let cfg = PipelineConfig::<f64>::recommended(0.3, 2000.0);
    let cr = Creepage {
        xi: 1e-3,
        eta: 5e-4,
        phi: 0.0,
    };
    let r = solve_patch(s, load, &cr, &Material::steel(), &cfg, ws, &mut ()).unwrap();
    assert!(r.converged);
    Out {
        regions: r.regions.len(),
        q: [r.pmax, r.area, r.approach, r.totals.fx, r.totals.fy],
    }
}

#[test]
fn region_changes_are_continuous_in_the_load() {
    let s = samples();
    let mut ws = Box::new(DefaultWorkspace::<f64>::new());
    let names = ["pmax", "area", "approach", "Fx", "Fy"];
    // scan the load; every change of the region count is bisected to 1e-9 relative
    let loads: Vec<f64> = (0..40).map(|k| 1_000.0 * 1.12f64.powi(k)).collect();
    let counts: Vec<usize> = loads
        .iter()
        .map(|&l| solve(&s, l, &mut ws).regions)
        .collect();
    println!("region counts {counts:?}");
    let mut changes = vec![];
    for k in 1..loads.len() {
        if counts[k] == counts[k - 1] {
            continue;
        }
        let (mut lo, mut hi) = (loads[k - 1], loads[k]);
        let c_lo = counts[k - 1];
        while hi / lo - 1.0 > 1e-9 {
            let mid = 0.5 * (lo + hi);
            if solve(&s, mid, &mut ws).regions == c_lo {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let (a, b) = (solve(&s, lo, &mut ws), solve(&s, hi, &mut ws));
        let below = solve(&s, lo * (1.0 - 1e-4), &mut ws);
        let above = solve(&s, hi * (1.0 + 1e-4), &mut ws);
        changes.push((a.regions, b.regions));
        for (k, name) in names.iter().enumerate() {
            let size = a.q[k].abs();
            let jump = (b.q[k] - a.q[k]).abs() / size;
            let d_below = (a.q[k] - below.q[k]).abs() / size;
            let d_above = (above.q[k] - b.q[k]).abs() / size;
            println!(
                "{}→{} regions at {lo:.3} N: {} jump {jump:.2e}, steps of 1e-4 below/above \
                 {d_below:.2e} / {d_above:.2e}",
                a.regions, b.regions, name
            );
            assert!(
                jump < 1e-4,
                "{} jumps by {jump:.2e} at {}→{} regions",
                name,
                a.regions,
                b.regions
            );
            assert!(
                d_above <= 3.0 * d_below + 1e-6 && d_below <= 3.0 * d_above + 1e-6,
                "{}: steps below/above {d_below:.2e} / {d_above:.2e}",
                name
            );
        }
    }
    // the case exercises at least one merge
    assert!(changes.iter().any(|(a, b)| b < a), "{changes:?}");
}
