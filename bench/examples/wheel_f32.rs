//! The per-wheel default pipeline (placement at 0.05 mm + `wheel::solve_wheel`, 83.3 kN) in f32
//! against f64 over the 40 cases of the issue-6 sweep: per case the largest force difference
//! max(|ΔF_x|, |ΔF_y|)/(μF_z) over the patches, the relative differences of pmax and area of the
//! main patch, the difference of the vertical approach δ_v (mm) and the geometry passes
//! (`contact_patches` calls) of each precision; the worst values and the pass totals at the end.
//! `cargo run --release -p wrc-bench --example wheel_f32`

use wrc_kernel::geometry::{TrackSetup, WheelRail, WheelsetPose};
use wrc_kernel::wheel::{solve_wheel, DefaultWheelWorkspace, WheelConfig, WheelResult};
use wrc_kernel::{Material, Real};

fn solve<T: Real>(
    pair: &wrc_host_tests::profiles::ManchesterPair<T>,
    c: &wrc_bench::Case,
    ws: &mut DefaultWheelWorkspace<T>,
) -> WheelResult<T, 4, 4> {
    let (w, r) = pair;
    let s = &c.setup;
    let setup = TrackSetup {
        gauge: T::from_f64(s.gauge),
        gauge_depth: T::from_f64(s.gauge_depth),
        back_to_back: T::from_f64(s.back_to_back),
        flange_back_pos: T::from_f64(s.flange_back_pos),
        r0: T::from_f64(s.r0),
        cant: T::from_f64(s.cant),
    };
    let pose = WheelsetPose {
        dy: T::from_f64(c.pose.dy),
        yaw: T::from_f64(c.pose.yaw),
        roll: T::from_f64(c.pose.roll),
    };
    let mut g = Box::new(WheelRail::<T, 2048, 2048>::unplaced(r, w, &setup));
    g.place_in(r, w, &setup, &pose, c.side, T::from_f64(0.05))
        .expect("placement");
    let cfg = WheelConfig::recommended(
        T::from_f64(0.3),
        T::from_f64(100.0 / 3.6 * 1000.0),
        T::from_f64(460.0),
    );
    solve_wheel(
        &g,
        T::from_f64(83_300.0),
        &Material::<T>::steel(),
        &cfg,
        ws,
        &mut (),
    )
    .expect("wheel")
}

fn main() {
    let pair = wrc_bench::tables::<f64>();
    let pair32 = wrc_bench::tables::<f32>();
    let cases = wrc_bench::sweep(&pair);
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let mut ws32 = Box::new(DefaultWheelWorkspace::<f32>::new());
    let muf = 0.3 * 83_300.0;
    let (mut wf, mut wp, mut wa, mut wd) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let (mut calls, mut calls32) = (0, 0);
    println!("case side dy | max dF/muFz | d pmax rel | d area rel | d dv mm | passes f64 f32");
    for (i, c) in cases.iter().enumerate() {
        let a = solve(&pair, c, &mut ws);
        let b = solve(&pair32, c, &mut ws32);
        let mut df = 0.0f64;
        let (mut dp, mut da) = (0.0f64, 0.0f64);
        for (pa, pb) in a.patches.iter().zip(b.patches.iter()) {
            let (ta, tb) = (&pa.result.totals, &pb.result.totals);
            df = df
                .max((ta.fx - tb.fx.to_f64()).abs())
                .max((ta.fy - tb.fy.to_f64()).abs());
            dp = dp.max((pa.result.pmax - pb.result.pmax.to_f64()).abs() / pa.result.pmax);
            da = da.max((pa.result.area - pb.result.area.to_f64()).abs() / pa.result.area);
        }
        let dd = (a.vertical_approach - b.vertical_approach.to_f64()).abs();
        let df = if a.patches.len() == b.patches.len() {
            df / muf
        } else {
            f64::INFINITY
        };
        println!(
            "{i:2} {:?} {:+.0} | {df:.2e} | {dp:.2e} | {da:.2e} | {dd:.2e} | {} {}",
            c.side, c.dy, a.geometry_calls, b.geometry_calls
        );
        wf = wf.max(df);
        wp = wp.max(dp);
        wa = wa.max(da);
        wd = wd.max(dd);
        calls += a.geometry_calls;
        calls32 += b.geometry_calls;
    }
    println!(
        "worst: dF/muFz {wf:.2e}, pmax {wp:.2e}, area {wa:.2e}, dv {wd:.2e} mm; geometry passes f64 {calls}, f32 {calls32}"
    );
}
