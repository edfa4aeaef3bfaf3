//! Manchester geometry against CONTACT (methods.md §10.9).

use wrc_host_tests::data::shared_file;
use wrc_host_tests::profiles::{self, SmoothOptions};
use wrc_kernel::geometry::*;

#[derive(Debug, Clone)]
struct Row {
    side: Side,
    y_ws: f64,
    yaw: f64,
    roll: f64,
    ycp_r: f64,
    zcp_r: f64,
    delta: f64,
    cksi: f64,
    ceta: f64,
    cphi: f64,
    approach: f64,
    zcp_w: f64,
    ycp_w: f64,
}

fn rows() -> Vec<Row> {
    let text = std::fs::read_to_string(shared_file("contact_reference/mbench_a22_exact.csv")).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| head.iter().position(|h| *h == n).unwrap();
    lines
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            let g = |n: &str| f[col(n)].parse::<f64>().unwrap();
            Row {
                side: if f[col("side")] == "left" { Side::Left } else { Side::Right },
                y_ws: g("y_ws"),
                yaw: g("yaw_ws"),
                roll: g("roll_ws"),
                ycp_r: g("ycp_r"),
                zcp_r: g("zcp_r"),
                delta: g("deltcp_tr"),
                cksi: g("cksi"),
                ceta: g("ceta"),
                cphi: g("cphi"),
                approach: g("approach"),
                zcp_w: g("zcp_w"),
                ycp_w: g("ycp_w"),
            }
        })
        .collect()
}


struct Case {
    row: Row,
    frame: PatchFrame<f64>,
    np: usize,
}

fn solve_cases(opts: &PatchOptions<f64>) -> Vec<Case> {
    let (w, r) = profiles::manchester_tables::<f64>(&SmoothOptions::default()).unwrap();
    let setup = TrackSetup::<f64>::standard();
    rows().into_iter().map(|row| {
        let pose = WheelsetPose::from_contact(row.y_ws, row.yaw, row.roll);
        let geom = WheelRail::<f64, 2048, 2048>::place(&r, &w, &setup, &pose, row.side, 0.05).unwrap();
        let mut ps = Box::new(Patches::<f64, 4, 64>::new());
        let (_it, conv) = patches_at_normal_approach(&geom, row.approach, opts, &mut ps).unwrap();
        assert!(conv);
        let k = ps.main_index().unwrap();
        Case { row, frame: ps.items[k].frame, np: ps.len }
    }).collect()
}

fn creep_at(case: &Case, omega: f64) -> Creepages<f64> {
    let (w, r) = profiles::manchester_tables::<f64>(&SmoothOptions::default()).unwrap();
    let setup = TrackSetup::<f64>::standard();
    let pose = WheelsetPose::from_contact(case.row.y_ws, case.row.yaw, case.row.roll);
    let geom = WheelRail::<f64, 2048, 2048>::place(&r, &w, &setup, &pose, case.row.side, 0.05).unwrap();
    let kin = Kinematics { speed: 2000.0, pitch_rate: omega, lateral_velocity: 0.0, yaw_rate: 0.0, roll_rate: 0.0, normalisation: Normalisation::Mean };
    creepages(&geom, &case.frame, &kin).unwrap()
}

#[test]
fn mbench_creep_print() {
    let cases = solve_cases(&PatchOptions::default());
    let n = cases.len() / 2;
    for i in 0..n {
        for (me, other) in [(i, i + n), (i + n, i)] {
            let (c, o) = (&cases[me], &cases[other]);
            // Ω from the other wheel's ξ (CONTACT ξ_K = −ξ_C)
            let target = -o.row.cksi;
            let (mut a, mut b) = (2000.0 / 460.0, 2000.0 / 460.0 * 1.001);
            let (mut fa, mut fb) = (creep_at(o, a).xi - target, creep_at(o, b).xi - target);
            for _ in 0..4 { let x = b - fb * (b - a) / (fb - fa); a = b; fa = fb; b = x; fb = creep_at(o, b).xi - target; }
            let cr = creep_at(c, b);
            let nom = creep_at(c, 2000.0/460.0);
            let (xi, eta, phi) = (-c.row.cksi, c.row.ceta, c.row.cphi);
            println!("{:?} {:4.1} Ω·R0/V={:.6}  xi {:+.4e} ({:+6.2}%)  eta {:+.4e} ({:+6.2}%)  phi {:+.4e} ({:+6.2}%)  | nominalΩ: xi {:+6.2}% phi {:+6.2}%",
                c.row.side, c.row.y_ws, b * 460.0 / 2000.0, cr.xi, (cr.xi/xi-1.0)*100.0, cr.eta, (cr.eta/eta-1.0)*100.0, cr.phi, (cr.phi/phi-1.0)*100.0, (nom.xi/xi-1.0)*100.0, (nom.phi/phi-1.0)*100.0);
        }
    }
}

#[test]
fn mbench_print() {
    let (w, r) = profiles::manchester_tables::<f64>(&SmoothOptions::default()).unwrap();
    let setup = TrackSetup::<f64>::standard();
    for row in rows() {
        let pose = WheelsetPose::from_contact(row.y_ws, row.yaw, row.roll);
        let geom = WheelRail::<f64, 2048, 2048>::place(&r, &w, &setup, &pose, row.side, 0.05).unwrap();
        let mut ps = Box::new(Patches::<f64, 4, 64>::new());
        let (it, conv) = patches_at_normal_approach(&geom, row.approach, &PatchOptions::default(), &mut ps).unwrap();
        let k = ps.main_index().unwrap();
        let f = ps.items[k].frame;
        let (y_ref_c, d_c) = match row.side { Side::Left => (-row.ycp_r, row.delta), Side::Right => (row.ycp_r, -row.delta) };
        for p in ps.as_slice() { println!("   patch y={:.4} ang={:.4} w={:.3e} ovl={:?} comps={} appr={:.5} yw={:.4} zw={:.4} (c {:.4} {:.4})", p.frame.y_ref_rail, p.frame.angle, p.frame.weight, p.frame.overlap_y, p.frame.components, p.frame.approach, p.frame.y_ref_wheel, p.frame.z_ref_wheel, row.ycp_w, row.zcp_w); }
        println!("{:?} {:5.1} np={} it={} {} dy_ref={:8.4} dang={:8.3}mrad  y={:8.3} ang={:7.4} R={:9.4} Rc={:9.4} z={:.4}/{:.4}",
            row.side, row.y_ws, ps.len, it, conv, f.y_ref_rail - y_ref_c, (f.angle - d_c)*1e3, f.y_ref_rail, f.angle, f.rolling_radius, 460.0+row.zcp_w, f.z_ref_rail, row.zcp_r);
    }
}
