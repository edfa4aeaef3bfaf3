//! The per-wheel solve (kernel `wheel`): geometry + load split + pipeline from the wheelset state
//! and the vertical load, against CONTACT's exact Manchester solutions (10 kN,
//! `mbench_a22_exact.csv`; methods.md §10.9).
//!
//! What is compared: the normal force of the patch (CONTACT's FN), its normal approach, pmax and
//! the reference point; the kernel finds its own load split and frame from F_z = 10 kN, so this
//! tests geometry, STRIPES and the load loop end to end.

use wrc_host_tests::profiles;
use wrc_host_tests::wheelrail::{mbench_rows, MbenchRow as Row};
use wrc_kernel::geometry::*;
use wrc_kernel::wheel::{solve_wheel, DefaultWheelWorkspace, WheelConfig, WheelResult};
use wrc_kernel::Material;

fn rows() -> Vec<Row> {
    mbench_rows().expect("mbench_a22_exact.csv")
}

#[test]
fn manchester_wheel_solve_matches_contact() {
    let (wheel, rail) =
        profiles::manchester_tables::<f64>(&profiles::SmoothOptions::default()).unwrap();
    let mat = Material::<f64>::from_g_nu(82_000.0, 0.28).unwrap();
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let mut cfg = WheelConfig::recommended(0.3, 2000.0, 460.0);
    cfg.tol = 1e-7;
    let mut worst = (0.0f64, 0.0f64, 0.0f64);
    println!("side  y_ws   FN_ref    FN      dFN%  appr_ref  appr   d%    pmax_ref pmax  d%   it");
    for r in rows() {
        let pose = WheelsetPose::from_contact(r.y_ws, r.yaw, r.roll);
        let geom = WheelRail::<f64, 2048, 2048>::place(
            &rail,
            &wheel,
            &TrackSetup::standard(),
            &pose,
            r.side,
            0.05,
        )
        .unwrap();
        cfg.creepage = Some(r.creepage());
        let res = solve_wheel(&geom, 10_000.0, &mat, &cfg, &mut ws, &mut ()).unwrap();
        assert!(res.converged, "y_ws {} {:?}", r.y_ws, r.side);
        assert!((res.vertical_load - 10_000.0).abs() < 1e-3);
        let fn_: f64 = res.patches.iter().map(|p| p.load).sum();
        let main = res
            .patches
            .iter()
            .max_by(|a, b| a.load.total_cmp(&b.load))
            .unwrap();
        let e_fn = (fn_ / r.fn_ - 1.0) * 100.0;
        let e_ap = (main.frame.approach / r.approach - 1.0) * 100.0;
        let e_pm = (main.result.pmax / r.pmax - 1.0) * 100.0;
        println!(
            "{:5} {:5.1} {:8.1} {:8.1} {:6.2} {:8.5} {:8.5} {:6.2} {:7.0} {:7.0} {:6.2} {:2} {:8.3} {:8.3}",
            format!("{:?}", r.side), r.y_ws, r.fn_, fn_, e_fn, r.approach, main.frame.approach, e_ap,
            r.pmax, main.result.pmax, e_pm, res.iterations, r.ycp_r, main.frame.y_ref_rail
        );
        // the weighted reference point at the kernel's own approach (CONTACT prints y_r in its
        // own lateral sense: mirrored for the left rail)
        let y_ref = main.frame.y_ref_rail * if r.side == Side::Left { -1.0 } else { 1.0 };
        if (r.y_ws - 0.5).abs() > 1e-9 || r.side == Side::Left {
            assert!(
                (y_ref - r.ycp_r).abs() < 0.15,
                "y_ref {y_ref} vs {}",
                r.ycp_r
            );
        }
        worst.0 = worst.0.max(e_fn.abs());
        worst.1 = worst.1.max(e_ap.abs());
        worst.2 = worst.2.max(e_pm.abs());
    }
    println!(
        "worst |dFN| {:.2} %, |d approach| {:.2} %, |d pmax| {:.2} %",
        worst.0, worst.1, worst.2
    );
    // Tolerances (measured worst in brackets, 2026-12-01; with the default of 2026-12-02 —
    // inter-region coupling, `merge_depth` 0.25 — pmax 2.85 %, approach 6.09 %, FN 0.06 %):
    // FN follows from the vertical balance
    // with CONTACT's creepages; what remains is FaStrip's F_y against the exact one in the
    // F_y sin δ term at flange contact (0.98 %, right y_ws = 7). pmax is STRIPES against the exact
    // half-space solution (5.13 %, y_ws = 0, where STRIPES' approach is 5 % high). The approach
    // is the hardest: the plateau gap of right y_ws = 0.5 (two basins merged by STRIPES) is 9.5 %
    // off; every other case is within 5.2 %.
    assert!(worst.0 < 1.5, "normal force {:.2} %", worst.0);
    assert!(worst.2 < 6.0, "pmax {:.2} %", worst.2);
    assert!(worst.1 < 10.0, "approach {:.2} %", worst.1);
}

/// `solve_wheel` cold on the built-in S1002/UIC60 pair: `case` at shift `dy` (yaw 0, equilibrium
/// roll), F_z `fz`, the table builder's configuration (μ 0.3, 100 km/h), with zero creepage as at
/// the tables' nodes when `zero_creepage`.
fn solve_case(
    case: wrc_host_tests::realtime::Case,
    dy: f64,
    fz: f64,
    zero_creepage: bool,
) -> WheelResult<f64, 4, 4> {
    use wrc_host_tests::wheelrail::{tables, NODES};
    let (w, r) = tables().unwrap();
    let mut cfg = WheelConfig::recommended(0.3, 100.0 / 3.6 * 1000.0, 460.0);
    if zero_creepage {
        cfg.creepage = Some(wrc_kernel::patch::Creepage {
            xi: 0.0,
            eta: 0.0,
            phi: 0.0,
        });
    }
    let setup = case.setup::<f64>();
    let roll = equilibrium_roll::<f64, NODES, NODES>(&r, &w, &setup, dy, 0.0, 0.05)
        .unwrap()
        .roll;
    let pose = WheelsetPose { dy, yaw: 0.0, roll };
    let geom =
        WheelRail::<f64, NODES, NODES>::place(&r, &w, &setup, &pose, case.side, 0.05).unwrap();
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    solve_wheel(&geom, fz, &Material::steel(), &cfg, &mut ws, &mut ()).unwrap()
}

/// The normal–tangential coupling where the tangential solution jumps with the load (kernel
/// `wheel` docs, "Vertical balance"): S1002/UIC60 1360 mm, both wheels at |dy| 5.3 mm, equilibrium
/// roll, F_z 62.5 kN, the table builder's configuration (μ 0.3, 100 km/h). F_y/N of the patch
/// jumps from −0.04019 to −0.04036 between N = 64765.5 and 64766 N (a cell entering a strip of
/// the FaStrip grid, full slip); the ratios alternated between the two sides for all rounds
/// (`converged: false`). Relaxed, the coupling ends inside the jump: converged in 5 rounds, and
/// the vertical balance with the final forces holds to 2.2 N (asserted: 5 N); the final forces
/// are the model's own at the final load.
#[test]
fn coupling_ends_inside_a_jump_of_the_tangential_solution() {
    use wrc_host_tests::realtime::CASES;
    for (case, dy) in [(CASES[2], -5.3), (CASES[3], 5.3)] {
        let fz = 62_500.0;
        let s = solve_case(case, dy, fz, false);
        assert!(
            s.converged,
            "{} dy {dy}: rounds {}",
            case.label(),
            s.coupling_rounds
        );
        let sign = match case.side {
            Side::Right => -1.0,
            Side::Left => 1.0,
        };
        let vertical: f64 = s
            .patches
            .iter()
            .map(|p| p.load * p.frame.angle.cos() + sign * p.result.totals.fy * p.frame.angle.sin())
            .sum();
        assert!(
            (vertical - fz).abs() <= 5.0,
            "{} dy {dy}: vertical balance {vertical} N against {fz} N",
            case.label()
        );
        eprintln!(
            "{} dy {dy}: rounds {} vertical balance off by {:.2} N",
            case.label(),
            s.coupling_rounds,
            vertical - fz
        );
    }
}

/// The load loop where the vertical load rises steeply with the approach (kernel `wheel`,
/// `loglog_step`): S1002/UIC60 1360 mm right wheel, dy −5.42 mm, equilibrium roll, zero
/// creepage, F_z 62,266.9 N. There F(δ_v) has a local exponent of 8 (a region merging) and the
/// secant's exponent was clamped to 4: the approach alternated between 0.11382 and 0.11386 mm
/// (F 62,188 and 62,345 N) for all 30 passes (`converged: false`). Between two points on
/// either side of the target the secant now interpolates unclamped.
#[test]
fn load_loop_converges_where_the_load_rises_steeply() {
    let fz = 62_266.9;
    let s = solve_case(wrc_host_tests::realtime::CASES[2], -5.42, fz, true);
    assert!(s.converged, "passes {}", s.iterations);
    assert!(
        (s.vertical_load - fz).abs() <= 1e-6 * fz,
        "{}",
        s.vertical_load
    );
    assert!(s.iterations < 30, "passes {}", s.iterations);
}

/// A flange-contact state where STRIPES' load jumped (kernel `stripes`, `PatchFraction` l₀ over the
/// runs of basins on both sides): S1002/UIC60 1360 mm right wheel, dy −6.27216 mm (a node of the
/// 1360 mm table), zero creepage, F_z 260 kN. A dimple basin between two merged neighbours had a
/// shorter filter length than they (1.342 against 1.538 mm); when it vanished (δ_v 0.60366710388
/// → 0.60366710403 mm) the patch load jumped from 455.8 to 475.8 kN, no δ_v met F_z and the load
/// loop's secant wandered between 241 and 280 kN (`converged: false`; with its bracket it ended
/// at the jump, 1.6 % above F_z). Now it converges.
#[test]
fn flange_contact_node_converges() {
    let fz = 260_000.0;
    let s = solve_case(
        wrc_host_tests::realtime::CASES[2],
        -6.272159090909092,
        fz,
        true,
    );
    assert!(s.converged, "passes {}", s.iterations);
    assert!(
        (s.vertical_load - fz).abs() <= 1e-6 * fz,
        "{}",
        s.vertical_load
    );
}
