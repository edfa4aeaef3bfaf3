//! Host benchmarks of the wrc kernel live in `benches/`; the QEMU firmware in `bench/firmware/`.
//!
//! [`sweep`] is the S1002/UIC60 sweep of issue 6 (as `host-tests/tests/pipeline_sweep.rs` sets it
//! up), shared by the per-wheel benchmark (`benches/wheel.rs`) and the profiling example
//! (`examples/wheel_profile.rs`).

use wrc_host_tests::profiles::{self, ManchesterPair, SmoothOptions};
use wrc_kernel::geometry::{equilibrium_roll, Side, TrackSetup, WheelsetPose};

/// One case of the sweep: track set-up, wheelset pose (with the two-wheel equilibrium roll) and
/// the analysed wheel.
#[derive(Clone, Copy, Debug)]
pub struct Case {
    /// Track set-up (back-to-back 1353 or 1360 mm, otherwise standard).
    pub setup: TrackSetup<f64>,
    /// Wheelset pose: lateral shift −3…6 mm towards the analysed wheel, yaw 1.2 × shift mrad,
    /// equilibrium roll.
    pub pose: WheelsetPose<f64>,
    /// Analysed wheel.
    pub side: Side,
    /// Lateral shift towards the analysed wheel (CONTACT's y_ws sense), mm.
    pub dy: f64,
}

/// The Manchester profiles (S1002 wheel, UIC60 rail) with the default preprocessing.
pub fn tables<T: wrc_kernel::Real>() -> ManchesterPair<T> {
    profiles::manchester_tables::<T>(&SmoothOptions::default()).expect("shipped profiles")
}

/// The 40 geometry cases of the issue-6 sweep: back-to-back 1353 and 1360 mm, lateral shift
/// −3…6 mm, right and left wheel (the load is chosen by the caller).
pub fn sweep(pair: &ManchesterPair<f64>) -> Vec<Case> {
    let (w, r) = pair;
    let mut v = vec![];
    for b2b in [1353.0, 1360.0] {
        let setup = TrackSetup {
            back_to_back: b2b,
            ..TrackSetup::<f64>::standard()
        };
        for dy in -3..=6 {
            let dy = dy as f64;
            for side in [Side::Right, Side::Left] {
                let y_c = if side == Side::Right { dy } else { -dy };
                let p0 = WheelsetPose::from_contact(y_c, 1.2e-3 * y_c, 0.0);
                let eq = equilibrium_roll::<f64, 2048, 2048>(r, w, &setup, p0.dy, p0.yaw, 0.2)
                    .expect("equilibrium roll");
                v.push(Case {
                    setup,
                    pose: WheelsetPose {
                        roll: eq.roll,
                        ..p0
                    },
                    side,
                    dy,
                });
            }
        }
    }
    v
}
