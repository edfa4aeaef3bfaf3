//! The real-time step (`wrc_kernel::step`) on an S1002/UIC60 contact table (1353 mm, right wheel,
//! equilibrium roll, dy −11.8…11.8 mm every 0.5 mm refined to 1 % × 15–260 kN in 5 log-spaced
//! loads, 1 slot (of 3) × 16 strips), f64 and f32: table build time and size, and host time per
//! step over 1000 states (dy −7.9…3.9 mm, F_z 20–150 kN, yaw ±10 mrad, μ 0.1–0.5, nominal rolling
//! at 100 km/h plus a lateral velocity and yaw rate): median / P99 / max over the states of each
//! state's fastest of 20 timed calls (the host is shared; the step does the same work every call).
//!
//! Run: `cargo run --release -p wrc-bench --example realtime_step [f64|f32]` (both by default;
//! `WRC_REPEAT=n` times each state n times instead of 20). For instruction counts, per step and
//! per stage: `WRC_REPEAT=1 valgrind --tool=callgrind --callgrind-out-file=rt.cg
//! --toggle-collect='*warm_step*' target/release/examples/realtime_step f64` (1000 time-loop
//! steps; `*one_step*` for the cold step), then `callgrind_annotate --inclusive=no rt.cg`: the
//! step's stages are inlined, and callgrind attributes each instruction to the source file it
//! came from (`fastrip.rs` FaStrip's strip forces, `kalker.rs` the coefficients, `creep.rs` the
//! creepages, `step.rs`/`table.rs` lookup, interpolation and balance, libm).

use std::hint::black_box;
use std::time::Instant;
use wrc_host_tests::profiles::{manchester_tables, SmoothOptions};
use wrc_kernel::geometry::{Kinematics, Side, TrackSetup, WheelsetPose};
use wrc_kernel::step::{step, step_from, StepInput, StepResult};
use wrc_kernel::table::{build_table, ContactTable, TableSlot, TableSpec, ROW_BUFFERS};
use wrc_kernel::wheel::{DefaultWheelWorkspace, WheelConfig};
use wrc_kernel::{Material, Real};

const K: usize = 3;
const ST: usize = 16;
/// Timings per state (the fastest is kept); `WRC_REPEAT` overrides it.
const REPEAT: usize = 20;

fn repeat() -> usize {
    std::env::var("WRC_REPEAT")
        .ok()
        .and_then(|v| v.parse().ok())
        .filter(|&n| n > 0)
        .unwrap_or(REPEAT)
}

/// The cold step ([`step`], two coupling rounds).
#[inline(never)]
fn one_step<T: Real>(t: &ContactTable<'_, T>, i: &StepInput<T>) -> StepResult<T, K> {
    step::<T, K, ST>(t, i).expect("state inside the table")
}

/// The time loop's step ([`step_from`], one round from the previous result).
#[inline(never)]
fn warm_step<T: Real>(
    t: &ContactTable<'_, T>,
    i: &StepInput<T>,
    prev: &StepResult<T, K>,
) -> StepResult<T, K> {
    step_from::<T, K, ST>(t, i, prev).expect("state inside the table")
}

fn run<T: Real>(name: &str) {
    let (w, r) = manchester_tables::<T>(&SmoothOptions::default()).expect("built-in profiles");
    let spec: TableSpec<T> = wrc_host_tests::realtime::standard_spec();
    let setup = TrackSetup {
        back_to_back: T::from_f64(1353.0),
        ..TrackSetup::standard()
    };
    let mut out = vec![0u8; spec.capacity_bytes(K, ST)];
    let mut rows = vec![TableSlot::<T, ST>::EMPTY; ROW_BUFFERS * K * spec.n_load];
    let mut ws = Box::new(DefaultWheelWorkspace::<T>::new());
    let speed = T::from_f64(100.0 / 3.6 * 1000.0);
    let cfg = WheelConfig::recommended(T::from_f64(0.3), speed, T::from_f64(460.0));
    let t0 = Instant::now();
    let rep = build_table::<T, 2048, 2048, K, ST, 4, 128, 256, 4, 32, 32, 128>(
        &r,
        &w,
        &setup,
        Side::Right,
        &Material::steel(),
        &cfg,
        &spec,
        &mut rows,
        &mut ws,
        &mut out,
    )
    .expect("table build");
    out.truncate(rep.bytes);
    let build = t0.elapsed();
    let table = ContactTable::<T>::from_bytes(&out).expect("valid table");
    let (mut times, mut warm) = (vec![], vec![]);
    for q in 0..1000 {
        let f = |a: f64, b: f64| (q as f64 * a + b).fract();
        let dy = -7.9 + 11.8 * f(0.618_033_988_75, 0.1);
        let inp = StepInput {
            pose: WheelsetPose {
                dy: T::from_f64(dy),
                yaw: T::from_f64(0.01 * (2.0 * f(0.754_877_666, 0.2) - 1.0)),
                roll: T::ZERO,
            },
            fz: T::from_f64(20_000.0 + 130_000.0 * f(0.569_840_29, 0.3)),
            kinematics: Kinematics {
                lateral_velocity: T::from_f64(100.0 * (2.0 * f(0.453_397_65, 0.4) - 1.0)),
                yaw_rate: T::from_f64(0.02 * (2.0 * f(0.380_364_3, 0.5) - 1.0)),
                ..Kinematics::nominal(speed, T::from_f64(460.0))
            },
            mu: T::from_f64(0.1 + 0.4 * f(0.324_717_957, 0.6)),
        };
        // each state timed REPEAT times, the fastest kept: the step's own cost, not the shared
        // host's scheduling (the step does the same work every time)
        let (mut tc, mut tw) = (f64::INFINITY, f64::INFINITY);
        for _ in 0..repeat() {
            let s = Instant::now();
            let prev = black_box(one_step(&table, black_box(&inp)));
            tc = tc.min(s.elapsed().as_secs_f64() * 1e6);
            let s = Instant::now();
            black_box(warm_step(&table, black_box(&inp), black_box(&prev)));
            tw = tw.min(s.elapsed().as_secs_f64() * 1e6);
        }
        times.push(tc);
        warm.push(tw);
    }
    times.sort_by(f64::total_cmp);
    warm.sort_by(f64::total_cmp);
    println!(
        "{name}: table {} shift nodes, {} nodes solved ({} not converged, {} slots used) {} bytes, build {:.1} s; over {} states: cold step (2 rounds) median {:.2} µs, P99 {:.2} µs, max {:.2} µs; time-loop step (1 round) median {:.2} µs, P99 {:.2} µs, max {:.2} µs",
        rep.dy_nodes,
        rep.nodes,
        rep.not_converged,
        rep.slots_used,
        rep.bytes,
        build.as_secs_f64(),
        times.len(),
        times[times.len() / 2],
        times[times.len() * 99 / 100],
        times[times.len() - 1],
        warm[warm.len() / 2],
        warm[warm.len() * 99 / 100],
        warm[warm.len() - 1]
    );
}

fn main() {
    let which = std::env::args().nth(1).unwrap_or_default();
    if which != "f32" {
        run::<f64>("f64");
    }
    if which != "f64" {
        run::<f32>("f32");
    }
}
