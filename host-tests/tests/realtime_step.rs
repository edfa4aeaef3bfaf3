//! The real-time step (`wrc_kernel::step`) on contact tables (`wrc_kernel::table`) against the
//! converged per-wheel solver they were built from (issue 14): S1002/UIC60, both wheels,
//! back-to-back 1353 and 1360 mm, tables at the equilibrium roll over the shift from flange to
//! flange (`wrc_host_tests::realtime::Case`).
//!
//! * The issue-14 sweep: 300 states per configuration (1200), the shift from flange to flange,
//!   yaw ±10 mrad, roll ±5 mrad about the equilibrium roll, F_z 20–150 kN, μ 0.1–0.5, kinematic
//!   creepages with lateral velocity and yaw rate; median / P95 / max per configuration, per
//!   contact region and overall, the closed form's own part separated.
//! * The earlier sweeps (1353 mm right wheel, dy −7.9 … 3.9 mm, equilibrium roll, μ 0.3, nominal
//!   rolling, yaw ±3 and ±10 mrad) with their assertions unchanged.
//! * Continuity along the shift, the yaw and the roll; the byte format's checks (a damaged,
//!   truncated or foreign table is `BadTable`), bad inputs, determinism.

use std::sync::OnceLock;
use wrc_host_tests::realtime::{
    compare, states, stats, Case, Errors, StateRanges, CASES, STANDARD,
};
use wrc_host_tests::wheelrail::{tables, NODES, R0, SWEEP_SPEED};
use wrc_kernel::geometry::{equilibrium_roll, Kinematics, Side, WheelRail, WheelsetPose};
use wrc_kernel::step::{step, StepInput, StepResult};
use wrc_kernel::table::{
    fnv1a, narrow_to_f32, BuildReport, ContactTable, FNV_OFFSET, HEADER_BYTES, VERSION,
};
use wrc_kernel::wheel::{solve_wheel, DefaultWheelWorkspace, WheelConfig};
use wrc_kernel::{Error, Material};

const K: usize = 3;
const ST: usize = 16;
const MU: f64 = 0.3;
const GRID: f64 = 0.05;
/// States of the earlier accuracy sweeps against the converged solver.
const STATES: usize = 1000;
/// States per configuration of the issue-14 sweep.
const STATES_PER_CASE: usize = 300;

/// The four configurations' tables ([`CASES`] on their [`Case::spec`]), built once (two at a
/// time) for every test of this binary.
fn case_tables() -> &'static [(Vec<u8>, BuildReport)] {
    static T: OnceLock<Vec<(Vec<u8>, BuildReport)>> = OnceLock::new();
    T.get_or_init(|| {
        let build = |c: &Case| {
            let (b, rep) = c.table::<f64, K, ST>(&c.spec()).unwrap();
            eprintln!("table {}: {rep:?}", c.label());
            // every node's per-wheel solve converges (the 1360 mm tables had one node that did
            // not, dy ∓6.27 mm at 260 kN: a STRIPES load jump, `tests/wheel.rs`)
            assert_eq!(rep.not_converged, 0, "table {}: {rep:?}", c.label());
            (b, rep)
        };
        let mut out = Vec::new();
        for pair in CASES.chunks(2) {
            std::thread::scope(|sc| {
                let h: Vec<_> = pair.iter().map(|c| sc.spawn(move || build(c))).collect();
                for x in h {
                    out.push(x.join().unwrap());
                }
            });
        }
        out
    })
}

/// The 1353 mm right-wheel table (the examples' standard).
fn build() -> Vec<u8> {
    assert_eq!(CASES[0], STANDARD);
    case_tables()[0].0.clone()
}

fn setup() -> wrc_kernel::geometry::TrackSetup<f64> {
    STANDARD.setup()
}

fn input(dy: f64, fz: f64, pose: WheelsetPose<f64>) -> StepInput<f64> {
    let _ = dy;
    StepInput {
        pose,
        fz,
        kinematics: Kinematics::nominal(SWEEP_SPEED, R0),
        mu: MU,
    }
}

fn totals(r: &StepResult<f64, K>) -> (f64, f64, f64) {
    let (mut fx, mut fy, mut n) = (0.0, 0.0, 0.0);
    for s in &r.slots {
        fx += s.fx;
        fy += s.fy;
        n += s.load;
    }
    (fx, fy, n)
}

/// Median / P95 / max of |ΔF|/(μF_z), |ΔN|/F_z, |Δpmax|/pmax and |Δarea|/area of the real-time
/// step against the converged solver over `STATES` quasi-random states: dy −7.9 … 3.9 mm (the
/// table's −8 … 4 mm), F_z 25 … 150 kN, yaw uniform in ±`yaw_amp` rad, the equilibrium roll.
type Stats = (f64, f64, f64);
fn sweep(yaw_amp: f64) -> [Stats; 4] {
    let (w, r) = tables().unwrap();
    let bytes = build();
    let t = ContactTable::<f64>::from_bytes(&bytes).unwrap();
    let mat = Material::<f64>::steel();
    let cfg = WheelConfig::recommended(MU, SWEEP_SPEED, R0);
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let (mut df, mut dn, mut dp, mut da) = (vec![], vec![], vec![], vec![]);
    let mut worst = (0.0, String::new());
    let mut worst_p = (0.0, String::new());
    for q in 0..STATES {
        // deterministic quasi-random states (golden-ratio sequences)
        let u = (q as f64 * 0.618_033_988_75 + 0.1).fract();
        let v = (q as f64 * 0.754_877_666_2 + 0.3).fract();
        let wy = (q as f64 * 0.569_840_290_998 + 0.5).fract();
        let dy = -7.9 + 11.8 * u;
        let fz = 25_000.0 + 125_000.0 * v;
        let yaw = yaw_amp * (2.0 * wy - 1.0);
        let roll = equilibrium_roll::<f64, NODES, NODES>(&r, &w, &setup(), dy, 0.0, GRID)
            .unwrap()
            .roll;
        let pose = WheelsetPose { dy, yaw, roll };
        let geom =
            WheelRail::<f64, NODES, NODES>::place(&r, &w, &setup(), &pose, Side::Right, GRID)
                .unwrap();
        let refr = solve_wheel(&geom, fz, &mat, &cfg, &mut ws, &mut ()).unwrap();
        let rt = step::<f64, K, ST>(&t, &input(dy, fz, pose)).unwrap();
        let (mut fx, mut fy, mut n) = (0.0, 0.0, 0.0);
        let (mut pm, mut ar) = (0.0f64, 0.0);
        for p in refr.patches.iter() {
            fx += p.result.totals.fx;
            fy += p.result.totals.fy;
            n += p.load;
            pm = pm.max(p.result.pmax);
            ar += p.result.area;
        }
        let (gx, gy, gn) = totals(&rt);
        let gp = rt.slots.iter().map(|s| s.pmax).fold(0.0, f64::max);
        let ga: f64 = rt.slots.iter().map(|s| s.area).sum();
        let e_f = ((gx - fx).powi(2) + (gy - fy).powi(2)).sqrt() / (MU * fz);
        df.push(e_f);
        dn.push((gn - n).abs() / fz);
        dp.push((gp - pm).abs() / pm);
        da.push((ga - ar).abs() / ar);
        if dp[dp.len() - 1] > worst_p.0 {
            worst_p = (
                dp[dp.len() - 1],
                format!("dy {dy:+.3} yaw {yaw:+.4} fz {fz:.0}: pmax ref {pm:.1} rt {gp:.1}"),
            );
        }
        if e_f > worst.0 {
            worst = (
                e_f,
                format!("dy {dy:+.3} yaw {yaw:+.4} fz {fz:.0}: F ref ({fx:.0},{fy:.0}) rt ({gx:.0},{gy:.0})"),
            );
        }
    }
    let stat = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        (v[v.len() / 2], v[v.len() * 95 / 100], v[v.len() - 1])
    };
    let out = [stat(&mut df), stat(&mut dn), stat(&mut dp), stat(&mut da)];
    eprintln!(
        "yaw ±{yaw_amp}: |dF|/(mu Fz) median/P95/max {:?}\n|dN|/Fz {:?}\npmax {:?}\narea {:?}\nworst force: {}\nworst pmax: {}",
        out[0], out[1], out[2], out[3], worst.1, worst_p.1
    );
    out
}

/// The earlier sweep (1353 mm right wheel, dy −7.9 … 3.9 mm, the equilibrium roll, μ 0.3,
/// nominal rolling), 1000 states with yaw within ±3 mrad, its assertions kept: |ΔN|/F_z ≤ 0.5 %,
/// area ≤ 3 % and pmax ≤ 3 % on every state, force at P95 ≤ 1 % of μF_z, force max ≤ 2 %.
/// Measured on the table over both flanges (168 shift nodes over 23.6 mm; before: 71 over 12 mm):
/// N max 0.04 %, area max 1.9 %, pmax max 2.7 % (dy −3.313 mm, 84 kN: pmax/F^{1/3} has a kink in
/// the load between the load nodes there), force P95 0.80 % (0.69 % on the 12 mm table), max
/// 1.58 % at the flange root (dy −6.16 mm, 122 kN; 1.41 % before: the strips' interpolation in
/// the load, not the shift nodes — 288 shift nodes leave it). A slot mismatch (a patch changing
/// slot between nodes) gave 5.1 % and pmax 50 % before the slots were continued by prediction.
#[test]
fn realtime_step_against_the_converged_solver() {
    let [sf, sn, sp, sa] = sweep(0.003);
    assert!(sn.2 <= 0.005, "normal load {sn:?}");
    assert!(sa.2 <= 0.03, "area {sa:?}");
    assert!(sf.1 <= 0.01, "force P95 {sf:?}");
    assert!(sp.1 <= 0.03, "pmax P95 {sp:?}");
    assert!(sf.2 <= 0.02, "force max {sf:?}");
    assert!(sp.2 <= 0.03, "pmax max {sp:?}");
}

/// The same at yaw within ±10 mrad (curving): the table is built at yaw 0, the step moves the
/// contact point with yaw (first order) but not the gap, which yaw changes at second order
/// (pmax and area by ≤ 3 % on the tread at ±10 mrad, up to 12 and 24 % in flange contact).
/// Measured: N max 0.04 %, area max 2.1 %, force P95 0.68 %, max 1.38 %, pmax P95 0.55 %, max
/// 3.9 % at dy −3.44 mm, 46 kN, yaw −7.2 mrad (8.7 % on the first, evenly spaced grid), asserted
/// at 4 %. Before the slip zone's direction field was integrated L-stably, large creepage on
/// lightly loaded strips gave 0.77 μN in full slip (force max 23 %).
#[test]
fn realtime_step_at_large_yaw() {
    let [sf, sn, sp, sa] = sweep(0.01);
    assert!(sn.2 <= 0.005, "normal load {sn:?}");
    assert!(sa.2 <= 0.03, "area {sa:?}");
    assert!(sf.1 <= 0.01, "force P95 {sf:?}");
    assert!(sp.1 <= 0.03, "pmax P95 {sp:?}");
    assert!(sf.2 <= 0.02, "force max {sf:?}");
    assert!(sp.2 <= 0.04, "pmax max {sp:?}");
}

/// Median / P95 / max of the four quantities over `e`, and of the step's force against the
/// closed form on the converged solver's strips (the table's part) and of the closed form's own.
fn summary(e: &[&Errors]) -> [(f64, f64, f64); 8] {
    let pick = |f: fn(&Errors) -> f64| stats(&mut e.iter().map(|x| f(x)).collect::<Vec<_>>());
    [
        pick(|x| x.force),
        pick(|x| x.normal),
        pick(|x| x.pmax),
        pick(|x| x.area),
        pick(|x| x.table_force),
        pick(|x| x.closed_form),
        pick(|x| x.settled_force),
        pick(|x| x.settled_normal),
    ]
}

fn show(name: &str, n: usize, s: &[(f64, f64, f64); 8]) {
    let f = |t: (f64, f64, f64)| {
        format!(
            "{:.2} / {:.2} / {:.2}",
            100.0 * t.0,
            100.0 * t.1,
            100.0 * t.2
        )
    };
    eprintln!(
        "| {name} | {n} | {} | {} | {} | {} | {} | {} | {} | {} |",
        f(s[0]),
        f(s[1]),
        f(s[2]),
        f(s[3]),
        f(s[4]),
        f(s[5]),
        f(s[6]),
        f(s[7])
    );
}

/// Contact regions of the report, by the converged solver's contact angle of the most loaded
/// patch: tread (< 0.25 rad), flange root (0.25 … 0.8 rad), flange (≥ 0.8 rad).
const REGIONS: [(&str, f64, f64); 3] = [
    ("tread", 0.0, 0.25),
    ("flange root", 0.25, 0.8),
    ("flange", 0.8, 10.0),
];

/// Issue 14's sweep: 300 states per configuration (1353 and 1360 mm, right and left wheel;
/// 1200 in all) from flange to flange (0.5 mm beyond each flange contact), yaw ±10 mrad, roll
/// ±5 mrad about the equilibrium roll, F_z 20–150 kN, μ 0.1–0.5, kinematic creepages with
/// lateral velocity ±100 mm/s and yaw rate ±0.02 rad/s, against the converged solver at the same
/// pose, kinematics and μ. Reported (median / P95 / max, % — of μF_z for forces, F_z for N):
/// per configuration, per contact region and overall, with the force split into the table's part
/// (the step against the closed-form strip forces on the converged solver's own strips) and the
/// closed form's own (those against the solver's cell FaStrip), and the time loop's settled
/// result (`realtime::SETTLE` = 4 `step_from` after the cold step: the coupling at its fixed point).
///
/// Measured (docs/realtime.md; all 1200 states inside the tables), on the tread (1067 states,
/// contact angle < 0.25 rad) median / P95 / max: force 0.10 / 2.53 / 8.4 % of μF_z (the
/// table's part 0.11 / 2.44 / 8.3 %), N 0.00 / 0.08 / 0.64 % of F_z, pmax 0.17 / 2.32 / 14.9 %,
/// area 0.43 / 4.17 / 12.8 %: on target at the median, N and pmax also at P95; the rest is roll
/// about the equilibrium roll that the roll mapping does not hold (with the roll at equilibrium
/// the table's force part has P95 0.8 %, area 1.1 %). Flange root (60) and flange (73): force
/// median 1.13 and 1.46 %, max 5.3 and 28.8 %; the closed form's own part median 0.62 and 1.05
/// %; the flange maxima are yawed and rolled states whose loaded contact angle the roll mapping
/// misses, through the vertical balance also N's (flange max 26 % of F_z). Asserted: every
/// state inside its table, the targets where met (tread medians, N and pmax P95 on the tread,
/// overall medians), the other measured values as guards.
#[test]
fn issue14_sweep_both_wheels_both_back_to_backs() {
    let mut all: Vec<Errors> = Vec::new();
    let mut failed: Vec<String> = Vec::new();
    eprintln!(
        "| configuration | states | force | N | pmax | area | force: table | force: closed form | force: settled | N: settled |"
    );
    eprintln!("|---|---|---|---|---|---|---|---|---|---|");
    for (c, case) in CASES.iter().enumerate() {
        let st = states(case, &StateRanges::issue14(case), STATES_PER_CASE, 0).unwrap();
        let res = compare::<K, ST>(&case_tables()[c].0, case, &st);
        let mut ok = Vec::new();
        for r in res {
            match r {
                Ok(e) => ok.push(e),
                Err(e) => failed.push(e),
            }
        }
        let refs: Vec<&Errors> = ok.iter().collect();
        show(&case.label(), refs.len(), &summary(&refs));
        for (name, lo, hi) in REGIONS {
            let sub: Vec<&Errors> = ok
                .iter()
                .filter(|e| e.angle >= lo && e.angle < hi)
                .collect();
            show(
                &format!("{} {name}", case.label()),
                sub.len(),
                &summary(&sub),
            );
        }
        all.extend(ok);
    }
    let refs: Vec<&Errors> = all.iter().collect();
    let overall = summary(&refs);
    show("all", refs.len(), &overall);
    let mut by_region = Vec::new();
    for (name, lo, hi) in REGIONS {
        let sub: Vec<&Errors> = all
            .iter()
            .filter(|e| e.angle >= lo && e.angle < hi)
            .collect();
        let s = summary(&sub);
        show(&format!("all {name}"), sub.len(), &s);
        by_region.push(s);
    }
    for (what, key) in [
        ("force", 0usize),
        ("force: table", 4),
        ("pmax", 2),
        ("area", 3),
    ] {
        let mut v: Vec<&Errors> = all.iter().collect();
        let f = |e: &Errors| {
            [
                e.force,
                e.normal,
                e.pmax,
                e.area,
                e.table_force,
                e.closed_form,
            ][key]
        };
        v.sort_by(|a, b| f(b).total_cmp(&f(a)));
        for e in v.iter().filter(|e| e.angle < 0.25).take(3) {
            eprintln!("worst tread {what} {:.2} %: {}", 100.0 * f(e), e.label);
        }
    }
    {
        let mut v: Vec<&Errors> = all.iter().filter(|e| e.angle >= 0.8).collect();
        v.sort_by(|a, b| b.pmax.total_cmp(&a.pmax));
        for e in v.iter().take(2) {
            eprintln!("worst flange pmax {:.2} %: {}", 100.0 * e.pmax, e.label);
        }
    }
    {
        let mut v: Vec<&Errors> = all.iter().filter(|e| e.angle >= 0.25).collect();
        v.sort_by(|a, b| b.closed_form.total_cmp(&a.closed_form));
        for e in v.iter().take(4) {
            eprintln!(
                "worst flange closed form {:.2} % (angle {:.2}): {}",
                100.0 * e.closed_form,
                e.angle,
                e.label
            );
        }
    }
    for e in &failed {
        eprintln!("failed: {e}");
    }
    assert!(failed.is_empty(), "{} states failed", failed.len());
    assert!(all.len() >= 1000);
    let [tf, tn, tp, ta, tt, _, _, _] = by_region[0];
    // on target at the median on the tread, N and pmax also at P95
    assert!(tf.0 <= 0.01 && tn.0 <= 0.005 && tp.0 <= 0.03 && ta.0 <= 0.03);
    assert!(tp.1 <= 0.03, "tread pmax {tp:?}");
    // states above the targets (force 1 % of μF_z, N 0.5 % of F_z, pmax and area 3 %)
    for (name, lo, hi) in REGIONS {
        let sub: Vec<&Errors> = all
            .iter()
            .filter(|e| e.angle >= lo && e.angle < hi)
            .collect();
        let above = |f: fn(&Errors) -> f64, lim: f64| sub.iter().filter(|e| f(e) > lim).count();
        eprintln!(
            "{name}: {} states; above target: force {}, N {}, pmax {}, area {}",
            sub.len(),
            above(|e| e.force, 0.01),
            above(|e| e.normal, 0.005),
            above(|e| e.pmax, 0.03),
            above(|e| e.area, 0.03)
        );
    }
    // N on the tread: P95 on target, the maximum (roll about the equilibrium roll, through F_y in
    // the vertical balance) guarded
    assert!(tn.1 <= 0.005 && tn.2 <= 0.01, "tread N {tn:?}");
    // guards at the measured values (rounded up): the tread's P95 and maxima (roll about the
    // equilibrium roll), the table's part of the force. With the frame's own roll mapping
    // (format 5) P95 1.25 %, max 5.9 %; with one mapping for shape and frame they were 2.5 % and
    // 8.4 %.
    assert!(tf.1 <= 0.015 && tf.2 <= 0.065, "tread force {tf:?}");
    assert!(
        tt.1 <= 0.015 && tt.2 <= 0.06,
        "tread force, table part {tt:?}"
    );
    // pmax and area: the shape's roll mapping calibrated on the tread by the solver (table.rs,
    // "Roll"): area P95 3.2 %, max 10.1 %, pmax max 12.3 % (geometric mapping: 4.1, 11.6, 14.6 %)
    assert!(tp.2 <= 0.13, "tread pmax {tp:?}");
    assert!(ta.1 <= 0.035 && ta.2 <= 0.11, "tread area {ta:?}");
    // the flange root and flange: the table's part of the force (the closed form's own is the
    // strip model's, fastrip.rs) and pmax, area
    // (the table's part at the flange root, P95 4.6 %, was 3.2 % while the closed form lagged the
    // rigid slip's turn in flange contact: that bias was common to the step and to the closed
    // form on the solver's strips and cancelled in their difference)
    let [_, _, rp, ra, rt, rc, _, _] = by_region[1];
    assert!(rt.1 <= 0.05 && rt.2 <= 0.13, "flange root {rt:?}");
    // (area max 21.7 %: 1353 mm left wheel, dy 8.04 mm, roll 1.24 mrad above equilibrium, yaw
    // −7.8 mrad, where the roll takes the contact from the tread (0.12 rad) to the flange root
    // (0.30 rad): the roll mapping's area is 14.5 % high at yaw 0 there, and the yaw
    // coefficients of the mapped node, fitted where its patch is, add 8 points; 16.1 % before
    // the table had them)
    assert!(rp.2 <= 0.05 && ra.2 <= 0.22, "flange root {rp:?} {ra:?}");
    let [_, _, fp, fa, ft, fc, fs, fsn] = by_region[2];
    // (pmax max 14.9 %: 1353 mm left wheel, dy 9.23 mm, roll 1.39 mrad above equilibrium, yaw
    // −3.5 mrad, 146 kN: 12.6 % from the roll mapping at yaw 0, the mapped node's yaw
    // coefficient adds 2.3 points; the flange's pmax P95 went from 7.5 to 2.2 % with them)
    assert!(
        ft.2 <= 0.35 && fp.2 <= 0.15 && fa.2 <= 0.28,
        "flange {ft:?} {fp:?} {fa:?}"
    );
    // the closed form's own part in flange contact (of μF_z; N is up to 4 F_z there): median
    // 1.05 %, max 3.15 % with 16 slip-zone intervals (8: 5.3 / 16.9 %; 33 % / 77 % before its
    // direction integrator followed the rigid slip's turn along the strips); at the flange root
    // 0.62 / 4.65 % (8: 1.2 / 6.5 %)
    assert!(fc.0 <= 0.015 && fc.2 <= 0.04, "flange closed form {fc:?}");
    assert!(
        rc.0 <= 0.01 && rc.2 <= 0.055,
        "flange root closed form {rc:?}"
    );
    // the time loop's settled result (the coupling at its fixed point instead of the cold
    // step's two rounds): flange median 1.15 %, max 35.7 % of μF_z (1360 mm left wheel, dy 6.49
    // mm, yaw −9.7 mrad, roll 3.2 mrad below equilibrium: the loaded contact angle of the roll
    // mapping 22 mrad below the converged solver's, through the vertical balance)
    assert!(
        fs.0 <= 0.015 && fs.2 <= 0.37 && fsn.2 <= 0.37,
        "flange settled {fs:?} {fsn:?}"
    );
    {
        let mut v: Vec<&Errors> = all.iter().filter(|e| e.angle >= 0.8).collect();
        v.sort_by(|a, b| b.settled_force.total_cmp(&a.settled_force));
        for e in v.iter().take(3) {
            eprintln!(
                "worst flange settled {:.2} % (N {:.2} % of F_z): {}",
                100.0 * e.settled_force,
                100.0 * e.settled_normal,
                e.label
            );
        }
    }
    // the whole flange force: median 1.46 % of μF_z (8 intervals: 6.0 %)
    let ff = by_region[2][0];
    assert!(ff.0 <= 0.02, "flange force {ff:?}");
    // overall medians on target
    assert!(overall[0].0 <= 0.01 && overall[1].0 <= 0.005, "{overall:?}");
    assert!(overall[2].0 <= 0.03 && overall[3].0 <= 0.03, "{overall:?}");
}

#[test]
fn damaged_truncated_or_foreign_tables_are_typed_errors() {
    let bytes = build();
    assert!(ContactTable::<f64>::from_bytes(&bytes).is_ok());
    assert_eq!(
        ContactTable::<f32>::from_bytes(&bytes).unwrap_err(),
        Error::BadTable("precision differs from the caller's")
    );
    assert_eq!(
        ContactTable::<f64>::from_bytes(&bytes[..bytes.len() - 1]).unwrap_err(),
        Error::BadTable("length")
    );
    assert_eq!(
        ContactTable::<f64>::from_bytes(&bytes[..100]).unwrap_err(),
        Error::BadTable("shorter than the header")
    );
    let mut bad = bytes.clone();
    bad[4000] ^= 0x10;
    assert_eq!(
        ContactTable::<f64>::from_bytes(&bad).unwrap_err(),
        Error::BadTable("payload checksum")
    );
    let mut bad = bytes.clone();
    bad[0] = b'X';
    assert_eq!(
        ContactTable::<f64>::from_bytes(&bad).unwrap_err(),
        Error::BadTable("magic")
    );
    // format versions 1 (evenly spaced shifts, no node array), 2 (all slots stored, no roll
    // mapping), 3 (no yaw coefficients) and 4 (one roll mapping for the patch's shape and its
    // frame): rebuild
    assert_eq!(VERSION, 5);
    for (v, why) in [
        (1u32, "format version 1: rebuild the table"),
        (2, "format version 2: rebuild the table"),
        (3, "format version 3: rebuild the table"),
        (4, "format version 4: rebuild the table"),
        (6, "format version"),
    ] {
        let mut bad = bytes.clone();
        bad[8..12].copy_from_slice(&v.to_le_bytes());
        assert_eq!(
            ContactTable::<f64>::from_bytes(&bad).unwrap_err(),
            Error::BadTable(why)
        );
    }
    // shift nodes not strictly increasing, not finite, or not ending at dy_min/dy_max (with a
    // matching checksum, so that the node check is what fails)
    let d0 = f64::from_le_bytes(bytes[HEADER_BYTES..HEADER_BYTES + 8].try_into().unwrap());
    for (node, v) in [(1, d0 - 1.0), (5, f64::NAN), (0, d0 - 0.5), (1, d0)] {
        let mut bad = bytes.clone();
        let o = HEADER_BYTES + 8 * node;
        bad[o..o + 8].copy_from_slice(&v.to_le_bytes());
        let sum = fnv1a(FNV_OFFSET, &bad[HEADER_BYTES..]);
        bad[120..128].copy_from_slice(&sum.to_le_bytes());
        assert_eq!(
            ContactTable::<f64>::from_bytes(&bad).unwrap_err(),
            Error::BadTable("shift nodes"),
            "node {node} = {v}"
        );
    }
    // the f32 copy of the f64 table: the same grid, valid, close to the f64 step
    let mut b32 = vec![0u8; bytes.len()];
    let n32 = narrow_to_f32(&bytes, &mut b32).unwrap();
    let t32 = ContactTable::<f32>::from_bytes(&b32[..n32]).unwrap();
    let t64 = ContactTable::<f64>::from_bytes(&bytes).unwrap();
    assert_eq!(t32.header.n_dy, t64.header.n_dy);
    for i in 0..t64.header.n_dy {
        assert_eq!(t32.dy_node(i), t64.dy_node(i) as f32);
    }
    assert_eq!(
        narrow_to_f32(&bytes[..100], &mut b32).unwrap_err(),
        Error::BadTable("shorter than the header")
    );
    assert!(narrow_to_f32(&bytes, &mut b32[..n32 - 1]).is_err());
    // the refined grid: not evenly spaced, and the step runs on every node (both ends included)
    let t = ContactTable::<f64>::from_bytes(&bytes).unwrap();
    let n = t.header.n_dy;
    let gaps: Vec<f64> = (1..n).map(|i| t.dy_node(i) - t.dy_node(i - 1)).collect();
    assert!(
        gaps.iter().any(|&g| g < 0.2) && gaps.iter().any(|&g| g > 0.2),
        "{gaps:?}"
    );
    for i in 0..n {
        let dy = t.dy_node(i);
        let p = WheelsetPose {
            dy,
            yaw: 0.0,
            roll: 0.0,
        };
        assert!(
            step::<f64, K, ST>(&t, &input(dy, 83_300.0, p)).is_ok(),
            "node {i} {dy}"
        );
    }
    // bad inputs
    let t = ContactTable::<f64>::from_bytes(&bytes).unwrap();
    let pose = WheelsetPose {
        dy: 0.0,
        yaw: 0.0,
        roll: 0.0,
    };
    for (fz, dy) in [
        (f64::NAN, 0.0),
        (-83_300.0, 0.0),
        (83_300.0, f64::NAN),
        (83_300.0, 30.0),
        (1e7, 0.0),
    ] {
        let p = WheelsetPose { dy, ..pose };
        assert!(
            step::<f64, K, ST>(&t, &input(dy, fz, p)).is_err(),
            "fz {fz} dy {dy}"
        );
    }
    // capacity below the table's; a roll beyond 0.1 rad; a rolled pose whose equivalent shift
    // leaves the table (the shift itself inside)
    assert!(step::<f64, 0, ST>(&t, &input(0.0, 83_300.0, pose)).is_err());
    let rolled = |dy: f64, roll: f64| WheelsetPose { dy, yaw: 0.0, roll };
    assert_eq!(
        step::<f64, K, ST>(&t, &input(0.0, 83_300.0, rolled(0.0, 0.15))).unwrap_err(),
        Error::OutOfRange("roll beyond 0.1 rad")
    );
    assert_eq!(
        step::<f64, K, ST>(&t, &input(8.0, 83_300.0, rolled(8.0, 0.02))).unwrap_err(),
        Error::OutOfRange("lateral shift outside the contact table")
    );
    assert!(step::<f64, K, ST>(&t, &input(8.0, 83_300.0, rolled(8.0, 0.0))).is_ok());
    // deterministic
    let a = step::<f64, K, ST>(
        &t,
        &input(-3.3, 83_300.0, WheelsetPose { dy: -3.3, ..pose }),
    )
    .unwrap();
    let b = step::<f64, K, ST>(
        &t,
        &input(-3.3, 83_300.0, WheelsetPose { dy: -3.3, ..pose }),
    )
    .unwrap();
    assert_eq!(a, b);
}

/// The change of the total force between two step results, relative to μF_z at the walk
/// parameter given (the first state's).
type Distance<'a> = dyn Fn(f64, &StepResult<f64, K>, &StepResult<f64, K>) -> f64 + 'a;

/// A jump found by [`walk`] whose table-side inputs to the strip forces (load, frame,
/// creepages, pmax, area of every slot) are continuous at zero creepage: most likely a
/// discontinuity of the closed-form strip forces (`fastrip::strip_forces`), though the check
/// cannot see a table jump crossed only by the coupling round's load ([`walk`]).
#[derive(Debug)]
struct StripJump {
    #[allow(dead_code)] // printed (Debug)
    pose: WheelsetPose<f64>,
    #[allow(dead_code)] // printed (Debug)
    size: f64,
    /// Where along the walk (its parameter u).
    #[allow(dead_code)] // printed (Debug)
    at: f64,
}

/// Walks `pose_at(u)` at the load `fz_at(u)` for u = 0 … `n` in unit steps: no step of the total
/// force may move it by more than 0.5 % of μF_z (F_z at the step's start) unless it is a steep
/// stretch, not a jump: such a step is cut in 10 and every part checked the same way, down to
/// 10⁻⁴ of a step (a jump stays a jump however fine the cut; a steep continuous stretch falls
/// below 0.5 %). At a jump the table's
/// part is checked alone: the step at μ = 10⁻⁹ (creep forces nil, so the vertical balance and
/// everything the table gives depend on the pose only) must be continuous there (load, frame,
/// creepages, pmax, area within 10⁻⁴); then the jump is returned as the strip forces' (the
/// callers fail on it too), else the test fails here. The check at μ = 10⁻⁹ sees the table at
/// the load of zero creepage: a table jump crossed only by the coupling round's load (the load
/// shifted by the creep forces in the vertical balance) passes it and is returned all the same.
/// Returns the largest uncut step, relative to μF_z, and those jumps.
fn walk(
    t: &ContactTable<'_, f64>,
    n: usize,
    fz_at: &dyn Fn(f64) -> f64,
    pose_at: &dyn Fn(f64) -> WheelsetPose<f64>,
) -> (f64, Vec<StripJump>) {
    let run = |u: f64, mu: f64| {
        let p = pose_at(u);
        let inp = StepInput {
            mu,
            ..input(p.dy, fz_at(u), p)
        };
        step::<f64, K, ST>(t, &inp).unwrap_or_else(|e| panic!("{p:?}: {e}"))
    };
    // relative to μF_z at the step's start
    let d = |u: f64, a: &StepResult<f64, K>, b: &StepResult<f64, K>| {
        let (ax, ay, _) = totals(a);
        let (bx, by, _) = totals(b);
        (bx - ax).hypot(by - ay) / (MU * fz_at(u))
    };
    let table_continuous = |u0: f64, u1: f64| {
        let (a, b) = (run(u0, 1e-9), run(u1, 1e-9));
        a.slots.iter().zip(&b.slots).all(|(x, y)| {
            let near = |p: f64, q: f64, scale: f64| (p - q).abs() <= 1e-4 * scale.max(p.abs());
            near(x.load, y.load, fz_at(u0))
                && near(x.angle, y.angle, 1.0)
                && near(x.y_ref_track, y.y_ref_track, 1.0)
                && near(x.z_ref_track, y.z_ref_track, 1.0)
                && near(x.x_ref, y.x_ref, 1.0)
                && near(x.creepage.xi, y.creepage.xi, 1e-3)
                && near(x.creepage.eta, y.creepage.eta, 1e-3)
                && near(x.creepage.phi, y.creepage.phi, 1e-5)
                && near(x.pmax, y.pmax, 1.0)
                && near(x.area, y.area, 1.0)
        })
    };
    #[allow(clippy::too_many_arguments)]
    fn check(
        run: &dyn Fn(f64, f64) -> StepResult<f64, K>,
        d: &Distance<'_>,
        cont: &dyn Fn(f64, f64) -> bool,
        pose_at: &dyn Fn(f64) -> WheelsetPose<f64>,
        (u0, u1): (f64, f64),
        (f0, f1): (&StepResult<f64, K>, &StepResult<f64, K>),
        depth: u32,
        jumps: &mut Vec<StripJump>,
    ) {
        let size = d(u0, f0, f1);
        if size <= 0.005 {
            return;
        }
        if depth == 0 {
            assert!(
                cont(u0, u1),
                "jump of {:.3} % of muFz at {:?}, the table's part too",
                100.0 * size,
                pose_at(u0)
            );
            jumps.push(StripJump {
                pose: pose_at(u0),
                size,
                at: u0,
            });
            return;
        }
        let mut last = (u0, *f0);
        for m in 1..=10 {
            let u = u0 + (u1 - u0) * m as f64 / 10.0;
            let f = if m == 10 { *f1 } else { run(u, MU) };
            check(
                run,
                d,
                cont,
                pose_at,
                (last.0, u),
                (&last.1, &f),
                depth - 1,
                jumps,
            );
            last = (u, f);
        }
    }
    let mut jumps = Vec::new();
    let mut last = run(0.0, MU);
    let (mut largest, mut largest_at) = (0.0f64, 0.0);
    for q in 1..=n {
        let u = q as f64;
        let now = run(u, MU);
        if d(u - 1.0, &last, &now) > largest {
            largest = d(u - 1.0, &last, &now);
            largest_at = u;
        }
        check(
            &run,
            &d,
            &table_continuous,
            pose_at,
            (u - 1.0, u),
            (&last, &now),
            4,
            &mut jumps,
        );
        last = now;
    }
    eprintln!(
        "largest step {:.3} % of muFz before {:?}",
        100.0 * largest,
        pose_at(largest_at)
    );
    (largest, jumps)
}

/// Continuity along the shift: the 1353 and 1360 mm right-wheel tables from flange to flange
/// (the states' range) in 0.01 mm steps at 83.3 kN, yaw 0, the equilibrium roll (solved at the
/// steps, linear between them: the solver's roll is only converged to 1e-9 and would add its
/// noise); a step above 0.5 % of μF_z (the flange contact, where N changes threefold within
/// 0.5 mm) must be a steep stretch, not a jump ([`walk`]), of the table's part or of the strip
/// forces.
#[test]
fn realtime_step_is_continuous_along_the_shift() {
    let (w, r) = tables().unwrap();
    for c in [0, 2] {
        let case = CASES[c];
        let t = ContactTable::<f64>::from_bytes(&case_tables()[c].0).unwrap();
        let (lo, hi) = StateRanges::issue14(&case).dy;
        let n = ((hi - lo) / 0.01).round() as usize;
        let setup = case.setup::<f64>();
        let eq: Vec<f64> = (0..=n)
            .map(|q| {
                equilibrium_roll::<f64, NODES, NODES>(
                    &r,
                    &w,
                    &setup,
                    lo + 0.01 * q as f64,
                    0.0,
                    GRID,
                )
                .unwrap()
                .roll
            })
            .collect();
        let pose_at = |u: f64| {
            let q = (u.floor() as usize).min(n - 1);
            let f = u - q as f64;
            WheelsetPose {
                dy: lo + 0.01 * u,
                yaw: 0.0,
                roll: eq[q] + (eq[q + 1] - eq[q]) * f,
            }
        };
        let (largest, jumps) = walk(&t, n, &|_| 83_300.0, &pose_at);
        eprintln!(
            "{}: largest step along the shift {:.3} % of muFz; strip-force jumps {jumps:?}",
            case.label(),
            100.0 * largest
        );
        assert!(jumps.is_empty(), "{}: {jumps:?}", case.label());
    }
}

/// Continuity in yaw (−10 … 10 mrad in 0.02 mrad steps) and in roll (equilibrium ± 5 mrad in
/// 0.01 mrad steps, through the roll mapping) on the 1353 mm right-wheel table at 83.3 kN, on
/// the tread, at the flange root and in flange contact: no jump at all, of the table's part
/// ([`walk`]) nor of the forces. (The one jump these sweeps found, 1.24 % of μF_z in flange
/// contact at dy −9.8 mm, yaw 2.03 mrad, passed the table check at μ = 10⁻⁹ and looked like the
/// strip forces': it was the frame's interpolation in the load, a quadratic through the three
/// load nodes nearest F that switched at the midpoint between nodes, crossed by the second
/// round's load but not by the load at zero creepage; the step now blends the two quadratics,
/// `step.rs` `frame_weights`.)
#[test]
fn realtime_step_is_continuous_in_yaw_and_roll() {
    let (w, r) = tables().unwrap();
    let t = ContactTable::<f64>::from_bytes(&case_tables()[0].0).unwrap();
    let setup = STANDARD.setup::<f64>();
    let mut all = Vec::new();
    for dy in [0.0, -3.3, -6.0, -8.5, -9.8, 6.0] {
        let eq = equilibrium_roll::<f64, NODES, NODES>(&r, &w, &setup, dy, 0.0, GRID)
            .unwrap()
            .roll;
        let (yaw, jy) = walk(&t, 1000, &|_| 83_300.0, &|u| WheelsetPose {
            dy,
            yaw: -0.01 + 2e-5 * u,
            roll: eq,
        });
        let (roll, jr) = walk(&t, 1000, &|_| 83_300.0, &|u| WheelsetPose {
            dy,
            yaw: 0.0,
            roll: eq - 0.005 + 1e-5 * u,
        });
        eprintln!(
            "dy {dy}: largest step in yaw {:.3} %, in roll {:.3} % of muFz; strip-force jumps \
             in yaw {jy:?}, in roll {jr:?}",
            100.0 * yaw,
            100.0 * roll
        );
        all.extend(jy);
        all.extend(jr);
    }
    assert!(all.is_empty(), "{all:?}");
}

/// Continuity in the load: F_z from 20 to 150 kN in 100 N steps on the 1353 mm right-wheel
/// table at the six shifts of the yaw and roll walks, equilibrium roll, yaw 2 mrad (creep forces
/// under the yaw's lateral creepage, so that the coupling round's load differs from the load of
/// zero creepage): no jump above 0.5 % of μF_z ([`walk`]; at the flange root, dy −8.5 mm, the
/// closed-form strip forces have steps of 0.1–0.3 % of μF_z at 47, 102, 125 and 137 kN, below
/// it). The load is where the step interpolates between its five load nodes and where the
/// frame's interpolation once switched its nodes at the midpoints (`step.rs` `frame_weights`).
#[test]
fn realtime_step_is_continuous_in_the_load() {
    let (w, r) = tables().unwrap();
    let t = ContactTable::<f64>::from_bytes(&case_tables()[0].0).unwrap();
    let setup = STANDARD.setup::<f64>();
    for dy in [0.0, -3.3, -6.0, -8.5, -9.8, 6.0] {
        let roll = equilibrium_roll::<f64, NODES, NODES>(&r, &w, &setup, dy, 0.0, GRID)
            .unwrap()
            .roll;
        let pose = WheelsetPose {
            dy,
            yaw: 0.002,
            roll,
        };
        let (largest, jumps) = walk(&t, 1300, &|u| 20_000.0 + 100.0 * u, &|_| pose);
        eprintln!(
            "dy {dy}: largest step in the load {:.3} % of muFz; jumps {jumps:?}",
            100.0 * largest
        );
        assert!(jumps.is_empty(), "dy {dy}: {jumps:?}");
    }
}

/// The frame's roll mapping (table format 5) on a wide conformal tread patch where one mapping
/// for shape and frame missed: 1360 mm, left wheel, dy 4.107 mm, 50.4 kN, yaw 0, roll −4 and −3
/// mrad from the equilibrium roll. The step's rolling radius and contact angle against the
/// converged solver's: with the shape's mapping alone 0.070 mm / 5.2 mrad off at −4 mrad (F_x 8 %
/// of μF_z at μ 0.13 in the sweep's state nearby); now 0.006 mm / 0.9 mrad and 0.009 mm / 0.7
/// mrad. At −5 mrad, the end of the fitted range, it is still 0.065 mm / 3.7 mrad (the rolled
/// contact's equivalent shift per roll goes from 616 to 682 mm/rad between −4 and −5 mrad, and the
/// pose maps to a node 3.3 mm away whose coefficients are not the probed node's).
#[test]
fn rolled_wide_tread_patch_keeps_its_frame() {
    let (w, r) = tables().unwrap();
    let case = CASES[3];
    assert_eq!((case.back_to_back, case.side), (1360.0, Side::Left));
    let t = ContactTable::<f64>::from_bytes(&case_tables()[3].0).unwrap();
    let setup = case.setup::<f64>();
    let mat = Material::<f64>::steel();
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let (dy, fz) = (4.107, 50_424.0);
    let eq = equilibrium_roll::<f64, NODES, NODES>(&r, &w, &setup, dy, 0.0, GRID)
        .unwrap()
        .roll;
    for d_roll in [-0.004, -0.003] {
        let pose = WheelsetPose {
            dy,
            yaw: 0.0,
            roll: eq + d_roll,
        };
        let rt: StepResult<f64, K> = step::<f64, K, ST>(&t, &input(dy, fz, pose)).unwrap();
        let geom =
            WheelRail::<f64, NODES, NODES>::place(&r, &w, &setup, &pose, case.side, GRID).unwrap();
        let cfg = WheelConfig::recommended(MU, SWEEP_SPEED, R0);
        let res = solve_wheel(&geom, fz, &mat, &cfg, &mut ws, &mut ()).unwrap();
        assert_eq!(res.patches.len(), 1);
        let p = &res.patches[0];
        let s = rt.slots.iter().find(|s| s.load > 0.0).unwrap();
        let (dr, da) = (
            s.rolling_radius - p.frame.rolling_radius,
            s.angle - p.frame.angle,
        );
        eprintln!(
            "roll {:+.1} mrad: rolling radius {:+.4} mm, contact angle {:+.3} mrad off",
            d_roll * 1e3,
            dr,
            da * 1e3
        );
        assert!(dr.abs() <= 0.015 && da.abs() <= 1.2e-3, "{dr} mm, {da} rad");
    }
}

#[test]
fn closed_form_strip_forces_match_fastrip_on_a_fine_hertz_grid() {
    use wrc_kernel::fastrip::{fastrip, strip_forces, FastripSettings};
    use wrc_kernel::patch::{Creepage, GridExtent, SemiEllipticStrips, StripPatch};
    let mat = Material::<f64>::steel();
    let (patch, _) = StripPatch::<f64, 64, 400>::hertz(
        6.0,
        4.0,
        80_000.0,
        &mat,
        GridExtent { fx: 1.0, fy: 1.0 },
    )
    .unwrap();
    for (xi, eta, phi) in [
        (1e-4, 0.0, 0.0),
        (0.0, 1e-4, 0.0),
        (0.0, 0.0, 2e-4),
        (-4e-4, 2e-4, 1e-4),
        (1e-3, 0.0, 0.0),
        (0.0, 0.0, 1e-3),
        (0.0, 1e-2, 0.0),
        (0.0, 1e-2, 1e-4),
        (2e-3, -3e-3, 2e-4),
        (-4.9e-4, -9.6e-3, 1.2e-4),
        (-4.9e-4, -6e-3, 1.2e-4),
    ] {
        let cr = Creepage { xi, eta, phi };
        let set = FastripSettings::new(MU);
        let r = fastrip(&patch, &SemiEllipticStrips, &cr, &set, &mut ()).unwrap();
        let (mut fx, mut fy, mut mz) = (0.0, 0.0, 0.0);
        for s in &patch.strips {
            let (a, b, c) = strip_forces(s, &cr, MU, mat.g, mat.nu).unwrap();
            fx += a;
            fy += b;
            mz += c;
        }
        let n = MU * 80_000.0;
        let k = wrc_kernel::kalker::coefficients(1.5, mat.nu).unwrap();
        let c3 = (24.0f64).powf(1.5);
        eprintln!(
            "linear: fx {:.1} fy(eta) {:.1} fy(phi) {:.1}",
            -mat.g * 24.0 * k.c11 * xi,
            -mat.g * 24.0 * k.c22 * eta - mat.g * c3 * k.c23 * phi,
            0.0
        );
        eprintln!(
            "{xi:e} {eta:e} {phi:e}: fastrip ({:.1},{:.1},{:.0}) closed ({fx:.1},{fy:.1},{mz:.0})",
            r.total.fx, r.total.fy, r.total.mz
        );
        // Within 0.2 % of mu N of the cell FaStrip (measured ≤ 0.02 % with 16 slip-zone
        // intervals, ≤ 0.14 % with 8) up to phi = 2e-4 and at large creepage. At pure spin
        // phi = 1e-3 (far beyond the linear range) F_y is 1.2 % of mu N above: the cell FaStrip
        // converges to -16 725 N (400 and 1600 cells agree within 13 N), the closed form gives
        // -16 957 N, a model difference (FASTSIM re-adhering inside its slip zone under spin,
        // which the closed form's direction field does not follow; 0.76 % with 8 intervals, whose
        // discretisation error partly offset it), asserted at 1.5 %.
        let tol = if phi < 1e-3 { 0.002 } else { 0.015 };
        eprintln!(
            "{xi:e} {eta:e} {phi:e}: fastrip ({:.1},{:.1},{:.0}) closed ({fx:.1},{fy:.1},{mz:.0})",
            r.total.fx, r.total.fy, r.total.mz
        );
        assert!((fx - r.total.fx).abs() <= tol * n, "fx");
        assert!((fy - r.total.fy).abs() <= tol * n, "fy");
        // the resultant never exceeds mu times the strips' load (Σ (π/2) a_j p̂_j δy, 0.012 % above
        // N on this grid)
        let carried: f64 = patch
            .strips
            .iter()
            .map(|s| std::f64::consts::FRAC_PI_2 * s.a * s.p_hat * s.dy)
            .sum();
        assert!(fx.hypot(fy) <= MU * carried * (1.0 + 1e-12));
    }
}

mod garbage {
    //! Property tests: the real-time step and the closed-form strip forces on garbage inputs (NaN,
    //! ±∞, zero, negative, subnormal, huge, and physical values) never panic and never return a
    //! non-finite number: an `Err`, or finite forces whose resultant stays within μ N.
    use super::*;
    use proptest::prelude::*;
    use std::sync::OnceLock;
    use wrc_kernel::fastrip::strip_forces;
    use wrc_kernel::patch::{Creepage, Strip};

    fn any() -> impl Strategy<Value = f64> {
        prop_oneof![
            proptest::num::f64::ANY,
            -10.0..10.0f64,
            -1e-2..1e-2f64,
            1e3..2e5f64,
            Just(0.0),
            Just(f64::NAN),
            Just(f64::INFINITY),
            Just(-f64::INFINITY),
            Just(1e300),
            Just(1e-300),
        ]
    }

    fn table() -> &'static [u8] {
        static T: OnceLock<Vec<u8>> = OnceLock::new();
        T.get_or_init(build)
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 512, .. ProptestConfig::default() })]

        #[test]
        fn step_is_an_error_or_finite(
            dy in any(), yaw in any(), roll in any(), fz in any(), mu in any(),
            v in any(), lat in any(), yr in any(),
        ) {
            let t = ContactTable::<f64>::from_bytes(table()).unwrap();
            let inp = StepInput {
                pose: WheelsetPose { dy, yaw: yaw * 1e-3, roll: roll * 1e-3 },
                fz,
                kinematics: Kinematics {
                    lateral_velocity: lat,
                    yaw_rate: yr,
                    ..Kinematics::nominal(v, R0)
                },
                mu,
            };
            if let Ok(r) = step::<f64, K, ST>(&t, &inp) {
                prop_assert!(r.vertical_approach.is_finite() && r.vertical_load.is_finite());
                for s in &r.slots {
                    for x in [s.load, s.fx, s.fy, s.mz, s.pmax, s.area, s.angle, s.x_ref] {
                        prop_assert!(x.is_finite(), "{s:?}");
                    }
                    prop_assert!(s.load >= 0.0);
                    prop_assert!(s.fx.hypot(s.fy) <= mu * s.load * (1.0 + 1e-9) + 1e-9, "{s:?}");
                }
            }
        }

        #[test]
        fn strip_forces_are_finite_and_bounded(
            a in any(), p_hat in any(), y in any(), xc in any(), g in any(),
            xi in any(), eta in any(), phi in any(), mu in any(),
        ) {
            let mat = Material::<f64>::steel();
            let Ok(kc) = wrc_kernel::kalker::coefficients(1.0 / g.abs().max(1e-3), mat.nu) else {
                return Ok(());
            };
            let s = Strip {
                y, dy: 0.5, a, xc, p_hat,
                c11: kc.c11, c22: kc.c22, c23: kc.c23, c33: kc.c33,
                sqrt_b_over_a: g.abs().max(1e-3).sqrt(),
                ..Strip::default()
            };
            let cr = Creepage { xi, eta, phi };
            let Ok((fx, fy, mz)) = strip_forces(&s, &cr, mu, mat.g, mat.nu) else {
                return Ok(());
            };
            let load = std::f64::consts::FRAC_PI_2 * a * p_hat * s.dy;
            let sane = a.is_finite() && p_hat.is_finite() && mu.is_finite() && mu > 0.0
                && xi.is_finite() && eta.is_finite() && phi.is_finite() && y.is_finite()
                && xc.is_finite() && load.is_finite();
            // Ok is always finite
            prop_assert!(fx.is_finite() && fy.is_finite() && mz.is_finite(), "{fx} {fy} {mz}");
            if sane && a > 0.0 && p_hat > 0.0 {
                prop_assert!(fx.hypot(fy) <= mu * load * (1.0 + 1e-9) + 1e-12, "{fx} {fy} vs {load}");
            }
        }
    }
}
