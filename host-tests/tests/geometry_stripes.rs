//! Geometry → STRIPES interface on the Manchester cases: the per-patch samples of the
//! kernel geometry (at CONTACT's approach) feed the kernel's STRIPES normal solver under CONTACT's
//! normal force. Checks the interface end to end (units, ordering, signs): the solver converges,
//! carries the load, and its peak pressure lies within the project's per-case STRIPES-class bound
//! (≤ 20 % against the exact solution, methods.md §10.11) of CONTACT's, with both
//! correspondences (contact-plane projection and isosceles pairs).

use wrc_host_tests::data::data_file;
use wrc_host_tests::profiles::{self, SmoothOptions};
use wrc_kernel::geometry::*;
use wrc_kernel::pipeline::samples_from_arrays;
use wrc_kernel::stripes::{StripSample, Stripes, StripesConfig};
use wrc_kernel::Material;

#[test]
fn manchester_patches_feed_stripes() {
    let (w, r) = profiles::manchester_tables::<f64>(&SmoothOptions::default()).unwrap();
    let text =
        std::fs::read_to_string(data_file("contact_reference/mbench_a22_exact.csv")).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| head.iter().position(|h| *h == n).unwrap();
    let mat = Material::identical(2.0 * 82000.0 * 1.28, 0.28).unwrap();
    let mut solver = Box::new(Stripes::<f64, 512, 8, 4>::new());
    let mut worst: f64 = 0.0;
    for l in lines {
        let f: Vec<&str> = l.split(',').collect();
        let g = |n: &str| f[col(n)].parse::<f64>().unwrap();
        let side = if f[col("side")] == "left" {
            Side::Left
        } else {
            Side::Right
        };
        let pose = WheelsetPose::from_contact(g("y_ws"), g("yaw_ws"), g("roll_ws"));
        let geom =
            WheelRail::<f64, 2048, 2048>::place(&r, &w, &TrackSetup::standard(), &pose, side, 0.05)
                .unwrap();
        let mut res = [(0.0, 0.0, 0.0); 2];
        for (c, corr) in [Correspondence::Projection, Correspondence::Isosceles]
            .into_iter()
            .enumerate()
        {
            let mut ps = Box::new(Patches::<f64, 4, 512>::new());
            let opts = PatchOptions {
                samples: 400,
                correspondence: corr,
                ..PatchOptions::default()
            };
            patches_at_normal_approach(&geom, g("approach"), &opts, &mut ps).unwrap();
            let k = ps.main_index().unwrap();
            let p = &ps.items[k].samples;
            let mut st = [StripSample::<f64>::default(); 512];
            let n = samples_from_arrays(
                |i| p.s(i),
                &p.width,
                &p.f_n,
                &p.a_long,
                &p.b_lat,
                p.n,
                &mut st,
            )
            .unwrap();
            let sol = solver
                .solve(&st[..n], g("FN"), &mat, &StripesConfig::recommended())
                .unwrap();
            assert!(sol.converged);
            assert!((sol.load / g("FN") - 1.0).abs() < 1e-6);
            let e = sol.pmax / g("pmax") - 1.0;
            worst = worst.max(e.abs());
            res[c] = (sol.pmax, e, sol.area);
        }
        println!(
            "{side:?} y_ws {:4.1}: pmax proj {:7.1} iso {:7.1} CONTACT {:7.1} ({:+5.1} % / {:+5.1} %), area proj {:6.2} iso {:6.2} CONTACT {:6.2}",
            g("y_ws"),
            res[0].0,
            res[1].0,
            g("pmax"),
            100.0 * res[0].1,
            100.0 * res[1].1,
            res[0].2,
            res[1].2,
            0.04 * g("ncon")
        );
    }
    println!("worst |Δpmax| {:.1} %", 100.0 * worst);
    assert!(worst <= 0.2);
}
