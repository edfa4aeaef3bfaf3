//! The real-time step (`wrc_kernel::step`) against the exact references on the issue-6 sweep
//! (issue 14: "against NORM, the STRIPES targets of the sweep, the tread → flange-root band and
//! Manchester A-2.2 still hold; the FaStrip-AC figures do not get worse by more than 0.3 points"):
//! S1002/UIC60, the four tables of `wrc_host_tests::realtime::CASES` (back-to-back 1353 and
//! 1360 mm, right and left wheel, flange to flange), dy −3 … 6 mm towards the wheel, yaw
//! 1.2·dy mrad, equilibrium roll, 40 / 83.3 / 120 kN (120 cases), and the tread → flange-root band
//! (1360 mm right wheel, dy 4.05 … 4.95 mm, 57 cases).
//!
//! * Normal: per wheel, pmax = max over slots/patches, area = sum, against NORM at the same patch
//!   loads (`wheelrail::solve_sweep_case`), beside the converged solver's (STRIPES) errors.
//! * Tangential (83.3 kN): per wheel F_x, F_y of the step and of the converged solver's default
//!   pipeline (FaStrip-AC) against TANG on NORM pressure, normalised by μF_n; eq. 31 floored
//!   (denominator ≥ 0.1 μF_n) as in the wheel/rail study.
//!
//! Asserted: on the sweep and on the band, pmax and area through the step within 0.5 points of
//! STRIPES' own mean error and within 2 points of its worst case (the table adds little to the
//! normal model's error). Measured: sweep pmax 2.12 / 11.09 %, area 3.38 / 10.11 % (STRIPES
//! 2.11 / 14.16, 3.26 / 10.30 %); band pmax 3.24 / 14.25 %, area 4.69 / 10.20 % (STRIPES 3.07 /
//! 17.80, 4.74 / 10.53 %). Manchester A-2.2 (10 kN, below these tables' 15 kN) runs on tables of its
//! own (`step_against_norm_on_manchester_a22`): pmax 0.43 / 2.86 %, area 1.72 / 11.08 % (STRIPES
//! 0.40 / 2.86, 1.89 / 10.74 %), yaw up to 24 mrad. Forces against TANG: FaStrip-AC's floored
//! eq. 31 through the step within 0.3 points of the converged pipeline's (measured +0.19).

use wrc_host_tests::realtime::CASES;
use wrc_host_tests::tangstudy::reference;
use wrc_host_tests::wheelrail::{
    solve_sweep_case, sweep_case, tables, NormGridOptions, SweepCase, Table, R0, SWEEP_LOADS,
    SWEEP_MU, SWEEP_SPEED,
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

/// One sweep or band case through the step on `t` and through the converged solver, against
/// NORM (normal) and, at 83.3 kN, TANG on NORM (forces); pushes the errors into `acc`.
fn case(t: &ContactTable<'_, f64>, w: &Table, r: &Table, c: &SweepCase, acc: &mut Acc) {
    let mat = Material::<f64>::steel();
    let load = c.load;
    let (sp, sa, kp, ka) = (&mut acc.sp, &mut acc.sa, &mut acc.kp, &mut acc.ka);
    let (ft_step, ft_pipe, ft_vs_pipe) = (&mut acc.ft_step, &mut acc.ft_pipe, &mut acc.ft_vs_pipe);
    let cs = solve_sweep_case(w, r, c, &NormGridOptions::default()).unwrap();
    let rt = step::<f64, K, ST>(
        t,
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
        return;
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

/// Errors of one set of cases (per wheel): pmax and area of the step (`sp`, `sa`) and of STRIPES
/// (`kp`, `ka`) against NORM; floored eq. 31 of the step and the pipeline against TANG; the
/// step's |ΔF| against the pipeline, of μF_n.
#[derive(Default)]
struct Acc {
    sp: Vec<f64>,
    sa: Vec<f64>,
    kp: Vec<f64>,
    ka: Vec<f64>,
    ft_step: Vec<f64>,
    ft_pipe: Vec<f64>,
    ft_vs_pipe: Vec<f64>,
}

#[test]
fn step_against_norm_and_tang_on_the_sweep() {
    let (w, r) = tables().unwrap();
    let mut all = Acc::default();
    let mut band = Acc::default();
    for cs in CASES {
        let (bytes, _) = cs.table::<f64, K, ST>(&cs.spec()).unwrap();
        let t = ContactTable::<f64>::from_bytes(&bytes).unwrap();
        for load in SWEEP_LOADS {
            for dy in -3..=6 {
                let c = sweep_case(&w, &r, cs.side, cs.back_to_back, dy as f64, load).unwrap();
                case(&t, &w, &r, &c, &mut all);
            }
        }
        // the tread → flange-root band: 1360 mm, right wheel, dy 4.05 … 4.95 mm
        if cs.back_to_back == 1360.0 && cs.side == Side::Right {
            for load in SWEEP_LOADS {
                for k in 1..20 {
                    let dy = 4.0 + 0.05 * k as f64;
                    let c = sweep_case(&w, &r, Side::Right, 1360.0, dy, load).unwrap();
                    case(&t, &w, &r, &c, &mut band);
                }
            }
        }
    }
    let (sp, sa, kp, ka) = (&all.sp, &all.sa, &all.kp, &all.ka);
    let (ft_step, ft_pipe, ft_vs_pipe) = (&all.ft_step, &all.ft_pipe, &all.ft_vs_pipe);
    let pc = |x: f64| 100.0 * x;
    println!(
        "against NORM, per wheel, mean / max %: step pmax {:.2} / {:.2}, area {:.2} / {:.2}; STRIPES pmax {:.2} / {:.2}, area {:.2} / {:.2} ({} cases)",
        pc(mean(sp)),
        pc(max(sp)),
        pc(mean(sa)),
        pc(max(sa)),
        pc(mean(kp)),
        pc(max(kp)),
        pc(mean(ka)),
        pc(max(ka)),
        sp.len()
    );
    println!(
        "against TANG (83.3 kN), floored eq. 31 mean over F_x, F_y: step {:.3} %, pipeline {:.3} %",
        pc(mean(ft_step)),
        pc(mean(ft_pipe))
    );
    let (bp, ba, bkp, bka) = (&band.sp, &band.sa, &band.kp, &band.ka);
    println!(
        "band (1360 R, dy 4.05 … 4.95): step pmax {:.2} / {:.2}, area {:.2} / {:.2}; STRIPES pmax {:.2} / {:.2}, area {:.2} / {:.2} ({} cases)",
        pc(mean(bp)),
        pc(max(bp)),
        pc(mean(ba)),
        pc(max(ba)),
        pc(mean(bkp)),
        pc(max(bkp)),
        pc(mean(bka)),
        pc(max(bka)),
        bp.len()
    );
    println!(
        "step vs pipeline, |ΔF| of μF_n: max {:.3} % (sweep), {:.3} % (band)",
        pc(max(ft_vs_pipe)),
        pc(max(&band.ft_vs_pipe))
    );
    // Through the step the normal errors are STRIPES' own plus the table's interpolation: the
    // step stays within 0.5 points of STRIPES' mean and within 2 points of its worst case on
    // the sweep and the band (the issue-14 requirement: "the STRIPES targets still hold").
    for (name, (s1, s2, k1, k2)) in [("sweep", (sp, sa, kp, ka)), ("band", (bp, ba, bkp, bka))] {
        assert!(mean(s1) <= mean(k1) + 0.005, "{name} pmax: step vs STRIPES");
        assert!(mean(s2) <= mean(k2) + 0.005, "{name} area: step vs STRIPES");
        assert!(
            max(s1) <= max(k1) + 0.02,
            "{name} pmax max: step vs STRIPES"
        );
        assert!(
            max(s2) <= max(k2) + 0.02,
            "{name} area max: step vs STRIPES"
        );
    }
    // Issue 14: "the FaStrip-AC figures do not get worse by more than 0.3 points". Measured
    // +0.18 points (floored eq. 31, 2.53 % against 2.35 %, four tables) with 16 slip-zone
    // intervals in the closed form (`fastrip::SLIP_STEPS`; with 8: +0.30 points, 2.65 %); most
    // of it from the 1360 mm two-region states (dy 4.95 … 5.0 mm: tread and flange root in one
    // slot whose 16 strips span both regions and the gap between them).
    let extra = mean(ft_step) - mean(ft_pipe);
    println!(
        "FaStrip-AC against TANG through the step: {:+.3} points over the pipeline",
        pc(extra)
    );
    assert!(extra <= 0.003, "{:+.3} points > 0.3", pc(extra));
}

/// Manchester through the step (issue 14: "against NORM … Manchester still hold"):
/// the 42 rows of CONTACT's exact solutions (S1002/UIC60, 1360 mm, right and left wheel, y_ws
/// 0 … 10 mm with yaw 2.4 mrad per mm and CONTACT's roll, F_z 10 kN, G = 82 GPa, ν = 0.28) on a
/// table per wheel built for them: CONTACT's material, the rows' shifts with 1 mm margin, F
/// 5 … 20 kN in 3 log-spaced loads (the sweep's tables start at 15 kN), equilibrium roll (the
/// rows' roll differs from the free wheelset's equilibrium roll, mapped by the step). Per wheel, pmax and area
/// against NORM at the converged solver's patch loads, both under the step's inputs (nominal
/// rolling at CONTACT's 2000 mm/s, μ 0.3), beside the converged solver's (STRIPES) own errors; asserted as the sweep: within 0.5 points of STRIPES' mean error
/// and 2 points of its worst case.
#[test]
fn step_against_norm_on_manchester_a22() {
    use wrc_host_tests::realtime::Case;
    use wrc_host_tests::wheelrail::{mbench_material, mbench_rows, solve_case, NODES};
    use wrc_kernel::geometry::equilibrium_roll;
    use wrc_kernel::table::TableSpec;
    use wrc_kernel::wheel::WheelConfig;
    let (w, r) = tables().unwrap();
    let rows = mbench_rows().unwrap();
    let mat = mbench_material();
    let mut acc = Acc::default();
    let mut in_range = vec![];
    let mut roll_span = 0.0f64;
    for side in [Side::Right, Side::Left] {
        let mine: Vec<_> = rows.iter().filter(|row| row.side == side).collect();
        let dys: Vec<f64> = mine.iter().map(|row| row.pose().dy).collect();
        let (lo, hi) = (
            dys.iter().copied().fold(f64::INFINITY, f64::min).floor() - 1.0,
            dys.iter().copied().fold(f64::NEG_INFINITY, f64::max).ceil() + 1.0,
        );
        let spec = TableSpec {
            dy_min: lo,
            dy_max: hi,
            n_dy: ((hi - lo) / 0.5).round() as usize + 1,
            f_min: 5_000.0,
            f_max: 20_000.0,
            n_load: 3,
            ..Case {
                back_to_back: 1360.0,
                side,
            }
            .spec()
        };
        let case = Case {
            back_to_back: 1360.0,
            side,
        };
        let (bytes, rep) = case.table_of::<f64, K, ST>(&spec, &mat).unwrap();
        assert_eq!(rep.not_converged, 0, "{side:?}: table nodes not converged");
        let t = ContactTable::<f64>::from_bytes(&bytes).unwrap();
        for row in mine {
            // the converged solver and NORM under the step's own inputs: nominal rolling at
            // V = 2000 mm/s, μ 0.3 (`solve_mbench_row` prescribes CONTACT's creepages instead,
            // whose pitch rate is set for zero net moment: in flange contact the F_y sin δ
            // coupling then gives other patch loads)
            let cfg = WheelConfig::recommended(0.3, 2000.0, R0);
            let cs = solve_case(
                &row.place(&w, &r).unwrap(),
                row.fz,
                &mat,
                &cfg,
                &NormGridOptions::default(),
            )
            .unwrap();
            let rt = step::<f64, K, ST>(
                &t,
                &StepInput {
                    pose: row.pose(),
                    fz: row.fz,
                    kinematics: Kinematics::nominal(2000.0, R0),
                    mu: 0.3,
                },
            )
            .unwrap();
            let eq = equilibrium_roll::<f64, NODES, NODES>(
                &r,
                &w,
                &case.setup(),
                row.pose().dy,
                0.0,
                0.05,
            )
            .unwrap()
            .roll;
            roll_span = roll_span.max((row.pose().roll - eq).abs());
            let np = cs.patches.iter().map(|p| p.norm.p_max).fold(0.0, f64::max);
            let na: f64 = cs.patches.iter().map(|p| p.norm.area).sum();
            let kpm = cs.patches.iter().map(|p| p.kernel.pmax).fold(0.0, f64::max);
            let kar: f64 = cs.patches.iter().map(|p| p.kernel.area).sum();
            let rpm = rt.slots.iter().map(|s| s.pmax).fold(0.0, f64::max);
            let rar: f64 = rt.slots.iter().map(|s| s.area).sum();
            // the yaw range is ±10 mrad; turns 2.4 mrad per mm (up to 24 mrad)
            in_range.push(row.yaw.abs() <= 0.010 + 1e-12);
            acc.sp.push((rpm / np - 1.0).abs());
            acc.sa.push((rar / na - 1.0).abs());
            acc.kp.push((kpm / np - 1.0).abs());
            acc.ka.push((kar / na - 1.0).abs());
            println!(
                "{}: pmax step {:+.1} % STRIPES {:+.1} %, area step {:+.1} % STRIPES {:+.1} % (NORM {np:.0} MPa, {na:.1} mm²)",
                row.label(),
                100.0 * (rpm / np - 1.0),
                100.0 * (kpm / np - 1.0),
                100.0 * (rar / na - 1.0),
                100.0 * (kar / na - 1.0)
            );
        }
    }
    let (sp, sa, kp, ka) = (&acc.sp, &acc.sa, &acc.kp, &acc.ka);
    let pc = |x: f64| 100.0 * x;
    println!(
        "Manchester A-2.2 against NORM, per wheel, mean / max %: step pmax {:.2} / {:.2}, area {:.2} / {:.2}; STRIPES pmax {:.2} / {:.2}, area {:.2} / {:.2} ({} cases; roll off the table's up to {:.2} mrad)",
        pc(mean(sp)),
        pc(max(sp)),
        pc(mean(sa)),
        pc(max(sa)),
        pc(mean(kp)),
        pc(max(kp)),
        pc(mean(ka)),
        pc(max(ka)),
        sp.len(),
        1e3 * roll_span
    );
    assert_eq!(sp.len(), 42);
    // all rows: the means within 0.5 points of STRIPES' (as the sweep and the band)
    assert!(mean(sp) <= mean(kp) + 0.005, "pmax: step vs STRIPES");
    assert!(mean(sa) <= mean(ka) + 0.005, "area: step vs STRIPES");
    // rows within the yaw range (|ψ| ≤ 10 mrad, 18 of 42): every case within 2 points
    // of STRIPES' worst
    let within = |v: &[f64]| -> Vec<f64> {
        v.iter()
            .zip(&in_range)
            .filter(|(_, &k)| k)
            .map(|(x, _)| *x)
            .collect()
    };
    let (isp, isa, ikp, ika) = (within(sp), within(sa), within(kp), within(ka));
    println!(
        "|yaw| ≤ 10 mrad ({} rows): step pmax max {:.2} %, area max {:.2} %; STRIPES {:.2} / {:.2} %",
        isp.len(),
        pc(max(&isp)),
        pc(max(&isa)),
        pc(max(&ikp)),
        pc(max(&ika))
    );
    assert!(max(&isp) <= max(&ikp) + 0.02, "pmax max: step vs STRIPES");
    assert!(max(&isa) <= max(&ika) + 0.02, "area max: step vs STRIPES");
    // all rows, yaw up to 24 mrad (the table's yaw coefficients, the yaw held at 10 mrad beyond):
    // within 2 points of STRIPES' worst too (R y_ws 5.0, ψ = 12 mrad, flange root: area −1.5 %;
    // −22.6 % before the table held yaw's effect on the gap)
    assert!(
        max(sp) <= max(kp) + 0.02,
        "pmax max (all rows): step vs STRIPES"
    );
    assert!(
        max(sa) <= max(ka) + 0.02,
        "area max (all rows): step vs STRIPES"
    );
}
