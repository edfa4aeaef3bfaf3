//! A wheel off its rail is a typed error, not a converged solve (issue 16): S1002/UIC60,
//! back-to-back 1360 and 1353 mm, no yaw or roll.
//!
//! * dy = 45, 50, 100 mm towards the analysed wheel (left and right): the rigid contact lies on
//!   the flange top or beyond the flange tip → `Error::Derailed` from the placement (before: a
//!   "converged" solve with pmax 4430 MPa on the flange tip at dy 50);
//! * a normal shift −8…+8 mm still solves at 83.3 kN;
//! * F_z = 10 MN (centred): the patch reaches past the profiles →
//!   `OutOfRange(LOAD_BEYOND_PROFILES)` (before: `NoContact`, the wrong cause).

use wrc_host_tests::wheelrail::{tables, NODES};
use wrc_kernel::geometry::{Side, TrackSetup, WheelRail, WheelsetPose, LOAD_BEYOND_PROFILES};
use wrc_kernel::wheel::{solve_wheel, DefaultWheelWorkspace, WheelConfig};
use wrc_kernel::{Error, Material};

fn setup(b2b: f64) -> TrackSetup<f64> {
    TrackSetup {
        back_to_back: b2b,
        ..TrackSetup::standard()
    }
}

/// The pose of a shift `dy` towards the analysed wheel (CONTACT's y_ws is towards the right).
fn pose(side: Side, dy: f64) -> WheelsetPose<f64> {
    WheelsetPose::from_contact(if side == Side::Right { dy } else { -dy }, 0.0, 0.0)
}

#[test]
fn large_shifts_are_derailed_normal_shifts_solve() {
    let (w, r) = tables().unwrap();
    let mat = Material::<f64>::steel();
    let cfg = WheelConfig::recommended(0.3, 200.0 / 3.6 * 1e3, 460.0);
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    for b2b in [1360.0, 1353.0] {
        for side in [Side::Right, Side::Left] {
            for dy in [45.0, 50.0, 100.0] {
                let g = WheelRail::<f64, NODES, NODES>::place(
                    &*r,
                    &*w,
                    &setup(b2b),
                    &pose(side, dy),
                    side,
                    0.05,
                );
                assert_eq!(g.err(), Some(Error::Derailed), "{b2b} {side:?} dy {dy}");
            }
            for i in 0..=16 {
                let dy = -8.0 + i as f64;
                let g = WheelRail::<f64, NODES, NODES>::place(
                    &*r,
                    &*w,
                    &setup(b2b),
                    &pose(side, dy),
                    side,
                    0.05,
                )
                .unwrap_or_else(|e| panic!("{b2b} {side:?} dy {dy}: {e}"));
                let res = solve_wheel(&g, 83_300.0, &mat, &cfg, &mut ws, &mut ())
                    .unwrap_or_else(|e| panic!("{b2b} {side:?} dy {dy}: {e}"));
                assert!(res.converged, "{b2b} {side:?} dy {dy}");
            }
        }
    }
}

#[test]
fn a_load_beyond_the_profiles_names_its_cause() {
    let (w, r) = tables().unwrap();
    let mat = Material::<f64>::steel();
    let cfg = WheelConfig::recommended(0.3, 200.0 / 3.6 * 1e3, 460.0);
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let g = WheelRail::<f64, NODES, NODES>::place(
        &*r,
        &*w,
        &setup(1360.0),
        &pose(Side::Right, 0.0),
        Side::Right,
        0.05,
    )
    .unwrap();
    let e = solve_wheel(&g, 1e7, &mat, &cfg, &mut ws, &mut ()).err();
    assert_eq!(e, Some(Error::OutOfRange(LOAD_BEYOND_PROFILES)));
    assert!(
        solve_wheel(&g, 83_300.0, &mat, &cfg, &mut ws, &mut ())
            .unwrap()
            .converged
    );
}
