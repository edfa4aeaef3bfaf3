//! Cost of the real-time step through the C interface (`wrc_step_f64` / `wrc_step_f32`, the same
//! entry points the static library exports) against the kernel's `step` called directly, on the
//! S1002/UIC60 table of bench `realtime_step` (1353 mm, right wheel, equilibrium roll, dy
//! −11.8…11.8 mm every 0.5 mm refined to 1 % × 15–260 kN in 5 loads, 1 slot × 32 strips) over its
//! 1000 states (dy −7.9…3.9 mm, F_z 20–150 kN, yaw ±10 mrad, μ 0.1–0.5, 100 km/h plus lateral velocity and yaw rate):
//! host time per call, median / P99 / max; and the one-off `wrc_table_check_*` (payload hash).
//!
//! Run: `cargo run --release -p wrc-ffi --example ffi_step`.

use std::hint::black_box;
use std::time::Instant;
use wrc_ffi::*;
use wrc_host_tests::realtime::{s1002_uic60_table, standard_spec};
use wrc_kernel::geometry::{Kinematics, WheelsetPose};
use wrc_kernel::step::{step, StepInput};
use wrc_kernel::table::ContactTable;
use wrc_kernel::Real;

const K: usize = 3;
const ST: usize = 32;

fn table<T: Real>() -> Vec<u8> {
    s1002_uic60_table::<T, K, ST>(&standard_spec())
        .expect("table build")
        .0
}

/// State `q` of the bench's 1000 (f64).
fn state(q: usize) -> StepInput<f64> {
    let f = |a: f64, b: f64| (q as f64 * a + b).fract();
    let speed = 100.0 / 3.6 * 1000.0;
    StepInput {
        pose: WheelsetPose {
            dy: -7.9 + 11.8 * f(0.618_033_988_75, 0.1),
            yaw: 0.01 * (2.0 * f(0.754_877_666, 0.2) - 1.0),
            roll: 0.0,
        },
        fz: 20_000.0 + 130_000.0 * f(0.569_840_29, 0.3),
        kinematics: Kinematics {
            lateral_velocity: 100.0 * (2.0 * f(0.453_397_65, 0.4) - 1.0),
            yaw_rate: 0.02 * (2.0 * f(0.380_364_3, 0.5) - 1.0),
            ..Kinematics::nominal(speed, 460.0)
        },
        mu: 0.1 + 0.4 * f(0.324_717_957, 0.6),
    }
}

fn c64(s: &StepInput<f64>) -> wrc_step_input_f64 {
    let k = &s.kinematics;
    wrc_step_input_f64 {
        dy: s.pose.dy,
        yaw: s.pose.yaw,
        roll: s.pose.roll,
        fz: s.fz,
        speed: k.speed,
        pitch_rate: k.pitch_rate,
        lateral_velocity: k.lateral_velocity,
        yaw_rate: k.yaw_rate,
        roll_rate: k.roll_rate,
        mu: s.mu,
        normalisation: 0,
    }
}

fn c32(s: &StepInput<f64>) -> wrc_step_input_f32 {
    let c = c64(s);
    wrc_step_input_f32 {
        dy: c.dy as f32,
        yaw: c.yaw as f32,
        roll: c.roll as f32,
        fz: c.fz as f32,
        speed: c.speed as f32,
        pitch_rate: c.pitch_rate as f32,
        lateral_velocity: c.lateral_velocity as f32,
        yaw_rate: c.yaw_rate as f32,
        roll_rate: c.roll_rate as f32,
        mu: c.mu as f32,
        normalisation: 0,
    }
}

fn stats(name: &str, mut t: Vec<f64>) {
    t.sort_by(f64::total_cmp);
    println!(
        "{name}: {} calls, median {:.2} µs, P99 {:.2} µs, max {:.2} µs",
        t.len(),
        t[t.len() / 2],
        t[t.len() * 99 / 100],
        t[t.len() - 1]
    );
}

fn main() {
    let t64 = table::<f64>();
    let t32 = table::<f32>();
    let s = Instant::now();
    // SAFETY: a valid slice; out_info may be NULL.
    let st = unsafe { wrc_table_check_f64(t64.as_ptr(), t64.len(), std::ptr::null_mut()) };
    println!(
        "wrc_table_check_f64 ({} bytes): {:?} in {:.0} µs",
        t64.len(),
        st,
        s.elapsed().as_secs_f64() * 1e6
    );
    let kt = ContactTable::<f64>::from_bytes(&t64).expect("valid table");
    for rep in 0..2 {
        let (mut a, mut b, mut c) = (vec![], vec![], vec![]);
        for q in 0..1000 {
            let inp = state(q);
            let ci = c64(&inp);
            let mut o = wrc_step_output_f64::default();
            let s = Instant::now();
            // SAFETY: a valid slice and references.
            let st = unsafe { wrc_step_f64(black_box(t64.as_ptr()), t64.len(), &ci, &mut o) };
            a.push(s.elapsed().as_secs_f64() * 1e6);
            assert_eq!(st, wrc_status::WRC_OK);
            black_box(o);
            let s = Instant::now();
            black_box(step::<f64, K, ST>(&kt, black_box(&inp)).expect("state inside"));
            b.push(s.elapsed().as_secs_f64() * 1e6);
            let ci = c32(&inp);
            let mut o = wrc_step_output_f32::default();
            let s = Instant::now();
            // SAFETY: a valid slice and references.
            let st = unsafe { wrc_step_f32(black_box(t32.as_ptr()), t32.len(), &ci, &mut o) };
            c.push(s.elapsed().as_secs_f64() * 1e6);
            assert_eq!(st, wrc_status::WRC_OK);
            black_box(o);
        }
        if rep == 1 {
            stats("wrc_step_f64 (C interface)", a);
            stats("kernel step::<f64, 3, 32> ", b);
            stats("wrc_step_f32 (C interface)", c);
        }
    }
}
