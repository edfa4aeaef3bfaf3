//! Continuity of the per-wheel solve in the lateral shift on real geometry (issue 6, methods.md §6
//! item 8): S1002/UIC60, right wheel, back-to-back 1360 mm, 83.3 kN, yaw 1.2·dy mrad, equilibrium
//! roll, the kernel's default `wheel::solve_wheel` (f64), in **0.01 mm steps** over windows
//! where the contact changes character (found with `wheelrail::transition_cases` on the sweep and
//! listed below): STRIPES regions appear or split at the gauge corner (dy ≈ 3.98 and 4.75 mm) and
//! at the flange root (dy ≈ 5.88 mm), and the flange-root contact sets in (dy ≈ 4.5 mm).
//!
//! Quantities per wheel: Σ N_k, Σ F_x,k, Σ F_y,k (patch frames; one patch in these windows),
//! pmax (max over patches), area (sum over patches).
//!
//! Measure (what a smooth function allows): with the step differences Δ_i = q(dy_i+1) − q(dy_i),
//! a jump shows as an isolated step far larger than its neighbours, while a smooth q has
//! Δ_i/Δ_i±1 = 1 + O(h q''/q'). Asserted for every interior step:
//! **|Δ_i| ≤ 3·max(|Δ_i−1|, |Δ_i+1|) + 1e-4·S_q**, with S_q the quantity's scale (F_z for
//! forces, the window's largest pmax and area); the floor covers turning points where Δ → 0.
//! A step discontinuity of more than 0.01 % of the scale therefore fails. The largest ratio and
//! the largest step relative to S_q are printed per window.
//!
//! Result (2026-12-01): the forces (Σ N, Σ F_x, Σ F_y) pass in every window (worst |Δ|/bound 0.61)
//! and are asserted in the test command. pmax and area do **not**: STRIPES has small jumps where
//! its fine solution's region edges move by more than the shift (at 0.001 mm resolution:
//! dy 4.002→4.003 pmax −3.9 MPa (−0.30 %), area +0.34 mm² (+0.33 %), a region edge moving
//! 0.013 mm; dy 5.873→5.874 area +0.25 mm² (+0.44 %) in one region with a steady strip count;
//! dy 4.480→4.481 a flange-root region's edge moving 0.22 mm, area +0.55 mm²). They are asserted
//! in the ignored test `pmax_and_area_are_continuous_in_the_shift` (fails; open item), not
//! hidden by a looser bound. Localised at dy 5.873→5.874: STRIPES alone on the kernel's samples
//! (same load) shows the jump in its approach (Δδ = −5.4e-5 mm in 0.0005 mm of shift against
//! −1e-5 mm in the neighbouring steps) with the default curvature filter `PatchFraction(0.25)`,
//! and a smooth approach with the filter off (`L0Mode::Off`), with one basin and a continuous
//! filter length in both; the mechanism inside the filtered pass is not yet found. The wheel
//! solve misses its tolerance at that shift (`converged = false`).

use wrc_host_tests::wheelrail::*;
use wrc_kernel::geometry::Side;
use wrc_kernel::wheel::{solve_wheel, DefaultWheelWorkspace};
use wrc_kernel::Material;

/// (b2b, first shift, steps of 0.01 mm)
const WINDOWS: [(f64, f64, usize); 4] = [
    (1360.0, 3.88, 20),
    (1360.0, 4.45, 20),
    (1360.0, 4.68, 20),
    (1360.0, 5.80, 20),
];
const LOAD: f64 = 83_300.0;

/// Forces: asserted (test command).
#[test]
fn wheel_forces_are_continuous_in_the_shift() {
    continuity(&[0, 1, 2]);
}

/// pmax and area: open item (see the module docs):
/// `cargo test -p wrc-host-tests --release --test wheel_continuity -- --ignored --nocapture`.
#[test]
#[ignore]
fn pmax_and_area_are_continuous_in_the_shift() {
    continuity(&[3, 4]);
}

fn continuity(checked: &[usize]) {
    let (w, r) = tables().unwrap();
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let names = ["N", "Fx", "Fy", "pmax", "area"];
    let mut fails = vec![];
    for (b2b, from, steps) in WINDOWS {
        let mut rows: Vec<[f64; 5]> = vec![];
        let mut sig = vec![];
        for k in 0..=steps {
            let dy = from + 0.01 * k as f64;
            let c = sweep_case(&w, &r, Side::Right, b2b, dy, LOAD).unwrap();
            let g = c.place(&w, &r).unwrap();
            let res =
                solve_wheel(&g, LOAD, &Material::steel(), &c.config(), &mut ws, &mut ()).unwrap();
            assert!(res.converged, "{}", c.label);
            let ps: Vec<_> = res.patches[..res.n].iter().flatten().collect();
            sig.push(contact_signature(&res));
            rows.push([
                ps.iter().map(|p| p.load).sum(),
                ps.iter().map(|p| p.result.totals.fx).sum(),
                ps.iter().map(|p| p.result.totals.fy).sum(),
                ps.iter().map(|p| p.result.pmax).fold(0.0, f64::max),
                ps.iter().map(|p| p.result.area).sum(),
            ]);
        }
        let scale = [
            LOAD,
            LOAD,
            LOAD,
            rows.iter().map(|q| q[3]).fold(0.0, f64::max),
            rows.iter().map(|q| q[4]).fold(0.0, f64::max),
        ];
        let changes: Vec<String> = sig
            .windows(2)
            .enumerate()
            .filter(|(_, s)| s[0] != s[1])
            .map(|(i, s)| format!("{:.2}: {:?}→{:?}", from + 0.01 * (i + 1) as f64, s[0], s[1]))
            .collect();
        let mut line = format!(
            "b2b {b2b} dy {from:.2}…{:.2} changes {changes:?}:",
            from + 0.01 * steps as f64
        );
        for q in 0..5 {
            let d: Vec<f64> = rows.windows(2).map(|p| p[1][q] - p[0][q]).collect();
            let mut worst_ratio = 0.0f64;
            for i in 1..d.len() - 1 {
                let nb = d[i - 1].abs().max(d[i + 1].abs());
                let bound = 3.0 * nb + 1e-4 * scale[q];
                worst_ratio = worst_ratio.max(d[i].abs() / bound);
                if d[i].abs() > bound && checked.contains(&q) {
                    fails.push(format!(
                        "b2b {b2b} dy {:.2}→{:.2}: Δ{} {:.4e} vs neighbours {:.4e}, {:.4e}",
                        from + 0.01 * i as f64,
                        from + 0.01 * (i + 1) as f64,
                        names[q],
                        d[i],
                        d[i - 1],
                        d[i + 1]
                    ));
                }
            }
            let maxstep = d.iter().map(|x| x.abs()).fold(0.0, f64::max) / scale[q];
            line += &format!(
                " {} max step {:.2e}·S, worst |Δ|/bound {:.2};",
                names[q], maxstep, worst_ratio
            );
        }
        println!("{line}");
    }
    assert!(fails.is_empty(), "{fails:#?}");
}
