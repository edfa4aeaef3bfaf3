//! Profile readers and preprocessing: error cases with line numbers, table contents and
//! smoothing on the Manchester profiles.

use std::path::{Path, PathBuf};
use wrc_host_tests::data::data_file;
use wrc_host_tests::profiles::{self, ProfileError, SmoothOptions};
use wrc_kernel::profile::ProfileKind;

fn tmp(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("wrc-profiles-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn simpack(points: &str, kind: u8) -> String {
    format!(
        "! test\n  header.begin\n    version = 1\n    type = {kind}\n  header.end\n  spline.begin\n    \
         approx.smooth = 0\n    mirror.y = 0\n    units.len.f = 1000\n    point.begin\n{points}    point.end\n  spline.end\n"
    )
}

fn line_of(e: &ProfileError) -> Option<usize> {
    match e {
        ProfileError::Line { line, .. } => Some(*line),
        _ => None,
    }
}

#[test]
fn reader_errors_name_line_and_cause() {
    // a non-number on the 3rd point line (file line 13)
    let p = tmp(
        "bad_number.prr",
        &simpack("0 0\n1 0.1\n2 x0.4\n3 0.9\n4 1.6\n", 0),
    );
    let e = profiles::read_profile(&p, None).unwrap_err();
    assert_eq!(line_of(&e), Some(13), "{e}");
    assert!(e.to_string().contains("not a number"), "{e}");
    // one column
    let p = tmp("one_col.prr", &simpack("0 0\n1\n2 0.4\n3 0.9\n", 0));
    let e = profiles::read_profile(&p, None).unwrap_err();
    assert_eq!(line_of(&e), Some(12), "{e}");
    // unknown profile type
    let p = tmp("bad_type.prr", &simpack("0 0\n1 0.1\n2 0.4\n3 0.9\n", 7));
    let e = profiles::read_profile(&p, None).unwrap_err();
    assert_eq!(line_of(&e), Some(4), "{e}");
    // rail file where a wheel is expected
    let p = tmp("rail.prr", &simpack("0 0\n1 0.1\n2 0.4\n3 0.9\n", 0));
    let e = profiles::read_profile(&p, Some(ProfileKind::Wheel)).unwrap_err();
    assert!(
        matches!(e, ProfileError::File { .. }) && e.to_string().contains("expected"),
        "{e}"
    );
    // missing point.end
    let text = simpack("0 0\n1 0.1\n2 0.4\n3 0.9\n", 0).replace("    point.end\n", "");
    let p = tmp("no_end.prr", &text);
    let e = profiles::read_profile(&p, None).unwrap_err();
    assert!(
        e.to_string().contains("point.end") || e.to_string().contains("section"),
        "{e}"
    );
    // non-finite value
    let p = tmp("inf.prr", &simpack("0 0\n1 inf\n2 0.4\n3 0.9\n", 0));
    let e = profiles::read_profile(&p, None).unwrap_err();
    assert_eq!(line_of(&e), Some(12), "{e}");
    // plain file: kind required, header line allowed, comments skipped, garbage reported
    let p = tmp("plain.txt", "# y z\ny z\n0 0\n1 0.1\n2 0.4\n3 0.9\n4 1.6\n");
    assert!(matches!(
        profiles::read_profile(&p, None),
        Err(ProfileError::File { .. })
    ));
    let raw = profiles::read_profile(&p, Some(ProfileKind::Rail)).unwrap();
    assert_eq!(raw.points.len(), 5);
    let p = tmp("plain_bad.txt", "0 0\n1 0.1\n2; 0.4; 1; 5\n3 0.9\n");
    let e = profiles::read_profile(&p, Some(ProfileKind::Rail)).unwrap_err();
    assert_eq!(line_of(&e), Some(3), "{e}");
    let p = tmp("plain_short.txt", "0 0\n1 0.1\n");
    assert!(profiles::read_profile(&p, Some(ProfileKind::Rail)).is_err());
    // missing file
    let e = profiles::read_profile(Path::new("/nonexistent/x.prr"), None).unwrap_err();
    assert!(matches!(e, ProfileError::Io { .. }));
    // a curve that turns back in y is rejected by the preprocessing with its position
    let p = tmp("zigzag.txt", "0 0\n1 0.1\n2 0.4\n1.5 0.9\n3 1.6\n4 2.5\n");
    let raw = profiles::read_profile(&p, Some(ProfileKind::Rail)).unwrap();
    let e = profiles::preprocess(&raw, &SmoothOptions::default()).unwrap_err();
    assert!(e.to_string().contains("not monotone"), "{e}");
}

/// The shipped files: facts of PROFILES.md (point counts, extents, options applied), table
/// capacity, and the geometry of the tables (tape circle, flange height, rail top).
#[test]
fn manchester_files_and_tables() {
    let w = profiles::read_profile(&data_file("profiles/MBench_S1002_v3.prw"), None).unwrap();
    assert_eq!(w.kind, ProfileKind::Wheel);
    assert_eq!(w.points.len(), 399);
    // mirror.y = 1 and inversion = 1 applied: flange at negative y, field side last
    assert!((w.points[0].0 - 60.0).abs() < 1e-9 && (w.points[398].0 + 69.612628).abs() < 1e-6);
    let r = profiles::read_profile(&data_file("profiles/MBench_UIC60_v3.prr"), None).unwrap();
    assert_eq!(r.kind, ProfileKind::Rail);
    assert_eq!(r.points.len(), 495);
    let (wt, rt) = profiles::manchester_tables::<f64>(&SmoothOptions::default()).unwrap();
    wt.validate().unwrap();
    rt.validate().unwrap();
    // wheel: z(0) = 0 at the tape circle, flange tip 28 mm at y ≈ −54.9
    let mut zmax = f64::MIN;
    let mut y_tip = 0.0;
    let mut z0 = f64::NAN;
    for i in 0..wt.len {
        if wt.z[i] > zmax {
            zmax = wt.z[i];
            y_tip = wt.y[i];
        }
        if i > 0 && wt.y[i - 1] <= 0.0 && wt.y[i] > 0.0 {
            z0 = wt.z[i];
        }
    }
    assert!((zmax - 28.0).abs() < 0.02, "flange height {zmax}");
    assert!((y_tip + 54.89).abs() < 0.3, "flange tip at {y_tip}");
    assert!(z0.abs() < 0.01, "tape circle z {z0}");
    // rail: top z ≈ 0 near y = −0.18
    let (mut zmin, mut y_top) = (f64::MAX, 0.0);
    for i in 0..rt.len {
        if rt.z[i] < zmin {
            zmin = rt.z[i];
            y_top = rt.y[i];
        }
    }
    assert!(
        zmin.abs() < 0.01 && (y_top + 0.18).abs() < 1.0,
        "rail top {zmin} at {y_top}"
    );
}

/// Smoothing: a sampled circle keeps its curvature (R = 13 mm, the gauge-corner radius) within
/// 1 % at L = 0.5 mm; a 0.2 mm ripple of 10 µm keeps 1/(1 + (0.5/0.2)⁴) = 2.5 % (0.25 µm) and a
/// 5 mm wave 99.99 % — the stated transfer function 1/(1 + (L/λ)⁴).
#[test]
fn smoothing_spline_filter_wavelength() {
    // circle arc, points every 0.3 mm
    let rad = 13.0;
    let pts: Vec<String> = (0..200)
        .map(|i| {
            let a = -1.0 + 2.0 * i as f64 / 199.0;
            format!("{} {}", rad * a.sin(), rad - rad * a.cos())
        })
        .collect();
    let p = tmp("circle.txt", &(pts.join("\n") + "\n"));
    let raw = profiles::read_profile(&p, Some(ProfileKind::Rail)).unwrap();
    let fine = profiles::preprocess(&raw, &SmoothOptions::default()).unwrap();
    let n = fine.curvature.len();
    for i in n / 10..9 * n / 10 {
        assert!(
            (fine.curvature[i] * rad - 1.0).abs() < 0.01,
            "curvature {}",
            fine.curvature[i]
        );
    }
    // straight line with a ripple: 10 µm at 0.2 mm wavelength + 10 µm at 5 mm wavelength
    let pts: Vec<String> = (0..2001)
        .map(|i| {
            let y = 0.02 * i as f64;
            let z = 0.01 * (2.0 * std::f64::consts::PI * y / 0.2).sin()
                + 0.01 * (2.0 * std::f64::consts::PI * y / 5.0).sin();
            format!("{y} {z}")
        })
        .collect();
    let p = tmp("ripple.txt", &(pts.join("\n") + "\n"));
    let raw = profiles::read_profile(&p, Some(ProfileKind::Rail)).unwrap();
    let fine = profiles::preprocess(&raw, &SmoothOptions::default()).unwrap();
    let mut worst: f64 = 0.0;
    for i in 0..fine.y.len() {
        let y = fine.y[i];
        if !(5.0..35.0).contains(&y) {
            continue;
        }
        let long = 0.01 * (2.0 * std::f64::consts::PI * y / 5.0).sin();
        // 5 mm wave passes with gain 1/(1 + (0.5/5)^4) = 0.9999
        worst = worst.max((fine.z[i] - long).abs());
    }
    assert!(worst < 3e-4 && worst > 2e-4, "residual {worst} mm");
}
