//! NORM on the kernel's wheel/rail gap against CONTACT's exact solutions of the Manchester
//! cases (`mbench_a22_exact.csv`, 42 cases, 10 kN; methods.md §7.3, §9.1, §10.9).
//!
//! Gap: the kernel geometry placed at CONTACT's printed normal approach (`patches_at_normal_approach`,
//! contact-plane projection, 256 samples) gives per lateral sample s the normal separation f_n(s),
//! the longitudinal curvature A(s) and, with yaw, the strip's rigid-contact offset x_c(s); NORM takes
//! h(x, s) = f_n(s) + A(s)(x − x_c(s))² (linear interpolation in s) on CONTACT's grid size
//! δx = δs = 0.2 mm and is load-controlled to CONTACT's F_n. Compared: approach, max element
//! pressure and contact area (CONTACT: ncon·0.04 mm²).
//!
//! Asserted: all three within 2 % (issue 4) on the left wheel and on the right wheel up to
//! y_ws = 4.5 mm (33 tread cases; worst 1.7 %). On the right wheel from y_ws = 5 mm (flange-root /
//! flange contact, contact angles 0.29–1.06 rad) approach and pmax stay within 2 % except at the
//! jump y_ws = 5 mm (§10.9 marks it), but the area is 4–9 % below CONTACT's for y_ws ≥ 6.5 mm.
//! Cause (test `flange_area_is_limited_by_the_grid_phase`): those flange patches are only
//! 0.7–0.8 mm wide laterally and ≈ 14 mm long, i.e. 4–5 element rows at 0.2 mm, one row being
//! ≈ 30 % of the area; the element-count area then depends on where the rows fall relative to
//! the patch edges. Shifting NORM's grid by a fraction of an element in s moves its area by up to
//! ±8 % (y_ws = 7: −7.6 % … +5.8 %) and pmax by ≈ 5 %; CONTACT's value lies inside NORM's range
//! over the grid phases in every flange case, and NORM's pmax converges to within 2.6 % of
//! CONTACT's under refinement (0.05 mm). So the gap is the resolution of a 0.2 mm element-count
//! area on a 4-row patch (CONTACT's own number carries the same uncertainty), not a geometry
//! error; the flange areas are therefore printed, not asserted at 2 %.
//!
//! `cargo test -p wrc-host-tests --release --test norm_mbench -- --nocapture` prints the table.

use wrc_host_tests::norm::{solve, Control, Grid, Options};
use wrc_host_tests::profiles::{self, SmoothOptions};
use wrc_host_tests::wheelrail::{mbench_rows, MbenchRow as Row};
use wrc_kernel::geometry::*;
use wrc_kernel::Material;

fn rows() -> Vec<Row> {
    mbench_rows().expect("mbench_a22_exact.csv")
}

/// Lateral samples of the main patch: (s, f_n, A, x_c).
fn samples(
    w: &wrc_kernel::profile::ProfileTable<f64, 2048>,
    r: &wrc_kernel::profile::ProfileTable<f64, 2048>,
    row: &Row,
) -> Vec<(f64, f64, f64, f64)> {
    let pose = WheelsetPose::from_contact(row.y_ws, row.yaw, row.roll);
    let geom =
        WheelRail::<f64, 2048, 2048>::place(r, w, &TrackSetup::standard(), &pose, row.side, 0.05)
            .unwrap();
    let mut ps = Box::new(Patches::<f64, 4, 256>::new());
    let opts = PatchOptions {
        samples: 256,
        ..PatchOptions::default()
    };
    patches_at_normal_approach(&geom, row.approach, &opts, &mut ps).unwrap();
    let k = ps.main_index().unwrap();
    let s = &ps.as_slice()[k].samples;
    (0..s.n)
        .map(|i| (s.s(i), s.f_n[i], s.a_long[i], s.x_c[i]))
        .collect()
}

/// Linear interpolation of the samples at s (clamped at the ends).
fn interp(sm: &[(f64, f64, f64, f64)], s: f64) -> (f64, f64, f64) {
    let n = sm.len();
    if s <= sm[0].0 {
        return (sm[0].1, sm[0].2, sm[0].3);
    }
    if s >= sm[n - 1].0 {
        return (sm[n - 1].1, sm[n - 1].2, sm[n - 1].3);
    }
    let i = sm.partition_point(|p| p.0 <= s) - 1;
    let (a, b) = (sm[i], sm[i + 1]);
    let t = (s - a.0) / (b.0 - a.0);
    (
        a.1 + t * (b.1 - a.1),
        a.2 + t * (b.2 - a.2),
        a.3 + t * (b.3 - a.3),
    )
}

#[test]
fn norm_against_contact_mbench() {
    let (w, r) = profiles::manchester_tables::<f64>(&SmoothOptions::default()).unwrap();
    let mat = Material::from_g_nu(82_000.0, 0.28).unwrap();
    let d = 0.2;
    let mut worst = [0.0f64; 3];
    let mut fails = Vec::new();
    println!("| side | y_ws | δ NORM / CONTACT | pmax NORM / CONTACT | area NORM / CONTACT | it |");
    for row in rows() {
        let sm = samples(&w, &r, &row);
        // Rows over the sampled lateral range; columns over the interpenetration in x, +15 %.
        let (s_lo, s_hi) = (sm[0].0, sm[sm.len() - 1].0);
        let xmax = sm
            .iter()
            .filter(|p| p.1 < row.approach)
            .map(|p| ((row.approach - p.1) / p.2).sqrt() + p.3.abs())
            .fold(0.0, f64::max);
        let mx = 2 * ((1.15 * xmax / d).ceil() as usize + 1);
        let my = ((s_hi - s_lo) / d).ceil() as usize + 2;
        let grid = Grid::centred(mx, my, d, d, 0.0, 0.5 * (s_lo + s_hi)).unwrap();
        let gap = grid.sample(|x, y| {
            let (f, a, xc) = interp(&sm, y);
            f + a * (x - xc) * (x - xc)
        });
        let s = solve(
            &grid,
            &gap,
            &mat,
            Control::Load(row.fn_),
            &Options::default(),
        )
        .unwrap();
        assert!(s.converged && !s.touches_boundary);
        let e = [
            s.approach / row.approach - 1.0,
            s.p_max / row.pmax - 1.0,
            s.area / row.area() - 1.0,
        ];
        println!(
            "| {:?} | {} | {:.5} / {:.5} ({:+.2} %) | {:.1} / {:.1} ({:+.2} %) | {:.2} / {:.2} ({:+.2} %) | {} |",
            row.side, row.y_ws, s.approach, row.approach, 100.0 * e[0], s.p_max, row.pmax,
            100.0 * e[1], s.area, row.area(), 100.0 * e[2], s.iterations
        );
        for (wk, ek) in worst.iter_mut().zip(e) {
            *wk = wk.max(ek.abs());
        }
        let tread = matches!(row.side, Side::Left) || row.y_ws <= 4.5;
        let jump = matches!(row.side, Side::Right) && row.y_ws == 5.0;
        let checked: &[f64] = if tread {
            &e
        } else if jump {
            &[]
        } else {
            &e[..2]
        };
        if checked.iter().any(|v| v.abs() > 0.02) {
            fails.push(format!("{:?} y_ws {}", row.side, row.y_ws));
        }
    }
    println!(
        "worst: approach {:.2} %, pmax {:.2} %, area {:.2} %",
        100.0 * worst[0],
        100.0 * worst[1],
        100.0 * worst[2]
    );
    assert!(fails.is_empty(), "beyond 2 %: {fails:?}");
}

/// The flange cases (right wheel, y_ws ≥ 6.5 mm) at CONTACT's element size 0.2 mm, with the grid
/// shifted laterally by 0, ¼, ½ and ¾ element: CONTACT's element-count area lies inside the range
/// of NORM's areas over the phases (the 4–9 % "gap" of the main test is the grid phase of a patch
/// 4–5 rows wide), and that range is wide (> 8 % of the area) in every case.
#[test]
fn flange_area_is_limited_by_the_grid_phase() {
    use wrc_host_tests::wheelrail::{gap_at, GapSample};
    let (w, r) = profiles::manchester_tables::<f64>(&SmoothOptions::default()).unwrap();
    let mat = Material::from_g_nu(82_000.0, 0.28).unwrap();
    let d = 0.2;
    for row in rows()
        .into_iter()
        .filter(|r| r.side == Side::Right && r.y_ws >= 6.5)
    {
        let sm: Vec<GapSample> = samples(&w, &r, &row)
            .into_iter()
            .map(|(s, f_n, a_long, x_c)| GapSample {
                s,
                f_n,
                a_long,
                b_lat: 0.0,
                x_c,
            })
            .collect();
        let lvl = 1.3 * row.approach;
        let inside: Vec<&GapSample> = sm.iter().filter(|p| p.f_n < lvl).collect();
        let (ylo, yhi) = (inside[0].s - 3.0 * d, inside[inside.len() - 1].s + 3.0 * d);
        let hx = inside
            .iter()
            .map(|p| ((lvl - p.f_n) / p.a_long).sqrt() + p.x_c.abs())
            .fold(0.0, f64::max)
            + 2.0 * d;
        let (mx, my) = (
            (2.0 * hx / d).ceil() as usize,
            ((yhi - ylo) / d).ceil() as usize,
        );
        let mut areas = vec![];
        for phase in [0.0, 0.25, 0.5, 0.75] {
            let grid = Grid::centred(mx, my, d, d, 0.0, 0.5 * (ylo + yhi) + phase * d).unwrap();
            let h = grid.sample(|x, y| gap_at(&sm, x, y));
            let s = solve(&grid, &h, &mat, Control::Load(row.fn_), &Options::default()).unwrap();
            assert!(s.converged && !s.touches_boundary);
            areas.push(s.area);
        }
        let lo = areas.iter().cloned().fold(f64::MAX, f64::min);
        let hi = areas.iter().cloned().fold(0.0, f64::max);
        println!(
            "y_ws {}: CONTACT {:.2}, NORM over the phases {:.2} … {:.2} mm²",
            row.y_ws,
            row.area(),
            lo,
            hi
        );
        assert!(lo <= row.area() && row.area() <= hi, "y_ws {}", row.y_ws);
        assert!(hi / lo - 1.0 > 0.08, "y_ws {}", row.y_ws);
    }
}
