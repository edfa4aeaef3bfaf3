//! The real-time step (`wrc_kernel::step`) against the exact references on the issue-6 sweep
//! (issue 14: "against NORM, the STRIPES targets of the sweep still hold; the FaStrip-AC figures
//! do not get worse by more than 0.3 points"): S1002/UIC60, back-to-back 1353 mm, right wheel,
//! dy −3 … 6 mm towards the wheel, yaw 1.2·dy mrad, equilibrium roll, 40 / 83.3 / 120 kN, on the
//! examples' table (`wrc_host_tests::realtime`, 3 slots × 16 strips, 0.25 mm shift nodes).
//!
//! * Normal: per wheel, pmax = max over slots/patches, area = sum, against NORM at the same patch
//!   loads (`wheelrail::solve_sweep_case`), beside the converged solver's (STRIPES) errors.
//! * Tangential (83.3 kN): per wheel F_x, F_y of the step and of the converged solver's default
//!   pipeline (FaStrip-AC) against TANG on NORM pressure, normalised by μF_n; eq. 31 floored
//!   (denominator ≥ 0.1 μF_n) as in the wheel/rail study.
//!
//! Asserted: pmax and area through the step within the issue-17 normal targets (mean ≤ 3 %, each
//! ≤ 10 %) and within 0.5 points of STRIPES' own mean error; the step's forces within 1 % of μF_n
//! of the converged solver's on every case. Measured (3 × 10 cases): step pmax 1.83 / 5.49 %,
//! area 2.72 / 8.04 % (STRIPES 1.73 / 5.43, 2.56 / 7.14 %); forces against TANG, floored eq. 31:
//! step 2.56 %, converged pipeline 2.26 % (+0.30 points, see the end of the test).

use wrc_host_tests::realtime::{s1002_uic60_table, standard_spec};
use wrc_host_tests::tangstudy::reference;
use wrc_host_tests::wheelrail::{
    solve_sweep_case, sweep_case, tables, NormGridOptions, R0, SWEEP_LOADS, SWEEP_MU, SWEEP_SPEED,
};
use wrc_kernel::geometry::{Kinematics, Side};
use wrc_kernel::step::{step, StepInput};
use wrc_kernel::table::ContactTable;
use wrc_kernel::Material;

const K: usize = 3;
const ST: usize = 16;

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len().max(1) as f64
}

fn max(v: &[f64]) -> f64 {
    v.iter().copied().fold(0.0, f64::max)
}

#[test]
fn step_against_norm_and_tang_on_the_sweep() {
    let (bytes, _) = s1002_uic60_table::<f64, K, ST>(&standard_spec()).unwrap();
    let t = ContactTable::<f64>::from_bytes(&bytes).unwrap();
    let (w, r) = tables().unwrap();
    let mat = Material::<f64>::steel();
    let (mut sp, mut sa, mut kp, mut ka) = (vec![], vec![], vec![], vec![]);
    let (mut ft_step, mut ft_pipe, mut ft_vs_pipe) = (vec![], vec![], vec![]);
    for load in SWEEP_LOADS {
        for dy in -3..=6 {
            let c = sweep_case(&w, &r, Side::Right, 1353.0, dy as f64, load).unwrap();
            let cs = solve_sweep_case(&w, &r, &c, &NormGridOptions::default()).unwrap();
            let rt = step::<f64, K, ST>(
                &t,
                &StepInput {
                    pose: c.pose,
                    fz: c.load,
                    kinematics: Kinematics::nominal(SWEEP_SPEED, R0),
                    mu: SWEEP_MU,
                },
            )
            .unwrap();
            let np = cs.patches.iter().map(|p| p.norm.p_max).fold(0.0, f64::max);
            let na: f64 = cs.patches.iter().map(|p| p.norm.area).sum();
            let kpm = cs.patches.iter().map(|p| p.kernel.pmax).fold(0.0, f64::max);
            let kar: f64 = cs.patches.iter().map(|p| p.kernel.area).sum();
            let rpm = rt.slots.iter().map(|s| s.pmax).fold(0.0, f64::max);
            let rar: f64 = rt.slots.iter().map(|s| s.area).sum();
            sp.push((rpm / np - 1.0).abs());
            sa.push((rar / na - 1.0).abs());
            kp.push((kpm / np - 1.0).abs());
            ka.push((kar / na - 1.0).abs());
            println!(
                "{}: pmax step {:+.1} % STRIPES {:+.1} %, area step {:+.1} % STRIPES {:+.1} % (NORM {np:.0} MPa, {na:.1} mm²)",
                c.label,
                100.0 * (rpm / np - 1.0),
                100.0 * (kpm / np - 1.0),
                100.0 * (rar / na - 1.0),
                100.0 * (kar / na - 1.0)
            );
            if load != 83_300.0 {
                continue;
            }
            // Forces per wheel (the sweep's patches at these shifts are single patches).
            let (mut ex, mut ey, mut px, mut py, mut fnn) = (0.0, 0.0, 0.0, 0.0, 0.0);
            for pc in &cs.patches {
                let (e, _) = reference(pc, &mat, SWEEP_MU, SWEEP_SPEED);
                ex += e.fx;
                ey += e.fy;
                fnn += e.fn_;
                px += pc.kernel.totals.fx;
                py += pc.kernel.totals.fy;
            }
            let (sx, sy): (f64, f64) = rt
                .slots
                .iter()
                .fold((0.0, 0.0), |a, s| (a.0 + s.fx, a.1 + s.fy));
            let f = SWEEP_MU * fnn;
            let floored = |a: f64, e: f64| (a - e).abs() / f / (e.abs() / f).max(0.1);
            for (a, e) in [(sx, ex), (sy, ey)] {
                ft_step.push(floored(a, e));
            }
            for (a, e) in [(px, ex), (py, ey)] {
                ft_pipe.push(floored(a, e));
            }
            ft_vs_pipe.push((sx - px).hypot(sy - py) / f);
            println!(
                "    forces /μFn: TANG ({:+.4}, {:+.4}) step ({:+.4}, {:+.4}) pipeline ({:+.4}, {:+.4}); {} patch(es), {} loaded slot(s)",
                ex / f,
                ey / f,
                sx / f,
                sy / f,
                px / f,
                py / f,
                cs.patches.len(),
                rt.slots.iter().filter(|s| s.load > 0.0).count()
            );
        }
    }
    let pc = |x: f64| 100.0 * x;
    println!(
        "against NORM, per wheel, mean / max %: step pmax {:.2} / {:.2}, area {:.2} / {:.2}; STRIPES pmax {:.2} / {:.2}, area {:.2} / {:.2} ({} cases)",
        pc(mean(&sp)),
        pc(max(&sp)),
        pc(mean(&sa)),
        pc(max(&sa)),
        pc(mean(&kp)),
        pc(max(&kp)),
        pc(mean(&ka)),
        pc(max(&ka)),
        sp.len()
    );
    println!(
        "against TANG (83.3 kN), floored eq. 31 mean over F_x, F_y: step {:.3} %, pipeline {:.3} %",
        pc(mean(&ft_step)),
        pc(mean(&ft_pipe))
    );
    // The issue-17 normal targets (mean ≤ 3 %, every case ≤ 10 %) hold through the step, and the
    // table's interpolation adds little to STRIPES' own error (measured: +0.10 / +0.16 points).
    assert!(mean(&sp) <= 0.03 && max(&sp) <= 0.10, "pmax");
    assert!(mean(&sa) <= 0.03 && max(&sa) <= 0.10, "area");
    assert!(mean(&sp) <= mean(&kp) + 0.005, "pmax: step vs STRIPES");
    assert!(mean(&sa) <= mean(&ka) + 0.005, "area: step vs STRIPES");
    // Issue 14's accuracy requirement against the converged solver, per wheel: |ΔF| ≤ 1 % of μF_n.
    assert!(
        max(&ft_vs_pipe) <= 0.01,
        "step vs pipeline {}",
        max(&ft_vs_pipe)
    );
    // Reported, not asserted (open in issue 14): "the FaStrip-AC figures do not get worse by
    // more than 0.3 points" measures +0.30 points here (2.556 % against 2.256 %), nearly all
    // from the flange contact at dy = 6 mm (F_x 0.1872 against the cell FaStrip's 0.1910 μF_n),
    // where the closed-form strips differ from the cell FaStrip at large spin.
}
