//! The default wheel pipeline (geometry → STRIPES → AC → FaStrip → wear) in its prescribed
//! normal-load mode (`wheel::solve_wheel_normal`: the main patch carries the normal load)
//! on the S1002/UIC60 sweep of issue 6: right and left wheel, back-to-back 1353 and 1360 mm,
//! lateral shift −3…6 mm towards the analysed wheel, yaw 1.2 × shift mrad, equilibrium roll,
//! loads 40, 83.3 and 120 kN, μ 0.3, E 205.9 GPa, ν 0.28, V = 100 km/h, nominal kinematics.
//!
//! Default run: 83.3 kN (40 cases); all three loads with `-- --ignored` (120 cases).
//! Asserts: every case solves with the load carried and the frame fixed point converged; f32
//! against f64 over the whole sweep (pipeline alone and end to end): F_x, F_y within 1e-3 of
//! μF_n. The table goes to
//! `out/pipeline_sweep.txt` and stdout.

use std::fmt::Write as _;
use wrc_host_tests::profiles::{self, SmoothOptions};
use wrc_kernel::geometry::*;
use wrc_kernel::patch::Creepage;
use wrc_kernel::pipeline::{solve_patch, DefaultWorkspace, PipelineConfig};
use wrc_kernel::profile::ProfileTable;
use wrc_kernel::stripes::StripSample;
use wrc_kernel::wheel::{solve_wheel_normal, WheelConfig, WheelWorkspace};
use wrc_kernel::{Material, Real};

/// 4 geometry patches of 256 samples, the default pipeline workspace.
type Ws<T> = WheelWorkspace<T, 4, 256, 256, 4, 32, 32, 128>;

/// The main patch's result and the solver's counts.
struct Main<T> {
    patch: wrc_kernel::pipeline::PatchResult<T, 4>,
    creepage: Creepage<T>,
    frame: PatchFrame<T>,
    frame_passes: u32,
    frame_converged: bool,
}

struct Res {
    fx: f64,
    fy: f64,
    mz: f64,
    pmax: f64,
    area: f64,
    regions: usize,
    patches: usize,
    passes: u32,
    conv: bool,
    wear: f64,
    pipe32: f64,
}

#[allow(clippy::too_many_arguments)]
fn run<T: Real>(
    w: &ProfileTable<T, 2048>,
    r: &ProfileTable<T, 2048>,
    setup: &TrackSetup<T>,
    pose: &WheelsetPose<f64>,
    side: Side,
    load: f64,
    ws: &mut Ws<T>,
) -> Res {
    let pose = WheelsetPose {
        dy: T::from_f64(pose.dy),
        yaw: T::from_f64(pose.yaw),
        roll: T::from_f64(pose.roll),
    };
    let geom =
        WheelRail::<T, 2048, 2048>::place(r, w, setup, &pose, side, T::from_f64(0.05)).unwrap();
    let mat = Material::<T>::steel();
    let v = T::from_f64(100.0 / 3.6 * 1000.0);
    let mut cfg = WheelConfig::recommended(T::from_f64(0.3), v, T::from_f64(460.0));
    cfg.patches.samples = 256;
    let wres = solve_wheel_normal(&geom, T::from_f64(load), &mat, &cfg, ws, &mut ()).unwrap();
    assert!(
        wres.converged,
        "{} bytes, {:?} {:?} it {} load {}",
        core::mem::size_of::<T>(),
        side,
        pose,
        wres.iterations,
        wres.vertical_load.to_f64()
    );
    assert_eq!(wres.patches.len(), 1);
    let res = &wres.patches[0];
    assert!((res.load.to_f64() / load - 1.0).abs() <= 2.0 * cfg.tol.to_f64());
    let patches_found = ws.patches.len;
    let res = Main {
        patch: res.result.clone(),
        creepage: res.creepage,
        frame_passes: wres.iterations,
        frame_converged: wres.converged,
        frame: res.frame,
    };
    // The same samples and creepages through the f32 patch pipeline (kernel precision without the
    // f32 geometry).
    let k = ws.patches.main_index().unwrap();
    assert!(
        (ws.patches.items[k].frame.y_ref_rail - res.frame.y_ref_rail)
            .to_f64()
            .abs()
            < 1e-9
    );
    let sm = &ws.patches.items[k].samples;
    let mut st = vec![StripSample::<f32>::default(); sm.n];
    for (i, x) in st.iter_mut().enumerate() {
        *x = StripSample {
            y: sm.s(i).to_f64() as f32,
            dy: sm.width[i].to_f64() as f32,
            z: sm.f_n[i].to_f64() as f32,
            curv_a: sm.a_long[i].to_f64() as f32,
            curv_b: sm.b_lat[i].to_f64() as f32,
            xc: sm.x_c[i].to_f64() as f32,
        };
    }
    let cr = Creepage {
        xi: res.creepage.xi.to_f64() as f32,
        eta: res.creepage.eta.to_f64() as f32,
        phi: res.creepage.phi.to_f64() as f32,
    };
    let mut pw = Box::new(DefaultWorkspace::<f32>::new());
    let cfg32 = PipelineConfig::<f32>::recommended(0.3, (100.0 / 3.6 * 1000.0) as f32);
    let p32 = solve_patch(
        &st,
        load as f32,
        &cr,
        &Material::<f32>::steel(),
        &cfg32,
        &mut pw,
        &mut (),
    )
    .unwrap();
    let pipe32 = ((p32.totals.fx as f64 - res.patch.totals.fx.to_f64()).abs())
        .max((p32.totals.fy as f64 - res.patch.totals.fy.to_f64()).abs())
        / (0.3 * load);
    let mut wear = 0.0f64;
    for k in 0..res.patch.regions.len() {
        wear = wear.max(res.patch.regions[k].wear_max.to_f64());
    }
    Res {
        fx: res.patch.totals.fx.to_f64(),
        fy: res.patch.totals.fy.to_f64(),
        mz: res.patch.totals.mz.to_f64(),
        pmax: res.patch.pmax.to_f64(),
        area: res.patch.area.to_f64(),
        regions: res.patch.regions.len(),
        patches: patches_found,
        passes: res.frame_passes,
        conv: res.frame_converged,
        pipe32,
        wear,
    }
}

/// Default run: the 40 cases at 83.3 kN.
#[test]
fn default_pipeline_sweep_f32_vs_f64() {
    sweep(&[83_300.0], "pipeline_sweep_83kN.txt");
}

/// The full 120-case sweep: `cargo test -p wrc-host-tests --release --test pipeline_sweep -- --ignored`.
#[test]
#[ignore]
fn full_pipeline_sweep_f32_vs_f64() {
    sweep(&[40_000.0, 83_300.0, 120_000.0], "pipeline_sweep.txt");
}

fn sweep(loads: &[f64], file: &str) {
    let (w, r) = profiles::manchester_tables::<f64>(&SmoothOptions::default()).unwrap();
    let (w32, r32) = profiles::manchester_tables::<f32>(&SmoothOptions::default()).unwrap();
    let mut ws = Box::new(Ws::<f64>::new());
    let mut ws32 = Box::new(Ws::<f32>::new());
    let mut txt = String::new();
    writeln!(txt, "| b2b | side | dy | N kN | patches | regions | passes | pmax MPa | area mm² | Fx/μN | Fy/μN | Mz N·mm | wear max mm | f32 pipeline ΔF/μN | f32 end-to-end ΔF/μN |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|").unwrap();
    let mut worst = 0.0f64;
    let mut worst_pipe = 0.0f64;
    let mut n = 0;
    for b2b in [1353.0, 1360.0] {
        let setup = TrackSetup {
            back_to_back: b2b,
            ..TrackSetup::<f64>::standard()
        };
        let setup32 = TrackSetup {
            back_to_back: b2b as f32,
            ..TrackSetup::<f32>::standard()
        };
        for dy in -3..=6 {
            let dy = dy as f64;
            for side in [Side::Right, Side::Left] {
                // shift towards the analysed wheel (CONTACT's y_ws convention is towards the right)
                let y_c = if side == Side::Right { dy } else { -dy };
                let p0 = WheelsetPose::from_contact(y_c, 1.2e-3 * y_c, 0.0);
                let eq = equilibrium_roll::<f64, 2048, 2048>(&r, &w, &setup, p0.dy, p0.yaw, 0.2)
                    .unwrap();
                let pose = WheelsetPose {
                    roll: eq.roll,
                    ..p0
                };
                for &load in loads {
                    let a = run(&w, &r, &setup, &pose, side, load, &mut ws);
                    let b = run(&w32, &r32, &setup32, &pose, side, load, &mut ws32);
                    let mun = 0.3 * load;
                    let d = (a.fx - b.fx).abs().max((a.fy - b.fy).abs()) / mun;
                    worst = worst.max(d);
                    worst_pipe = worst_pipe.max(a.pipe32);
                    n += 1;
                    writeln!(txt, "| {b2b} | {side:?} | {dy:+.0} | {:.1} | {} | {} | {} | {:.0} | {:.1} | {:+.3} | {:+.3} | {:+.0} | {:.2e} | {:.1e} | {d:.1e} |",
                        load / 1000.0, a.patches, a.regions, format_args!("{}{}", a.passes, if a.conv { "" } else { "*" }), a.pmax, a.area, a.fx / mun, a.fy / mun, a.mz, a.wear, a.pipe32).unwrap();
                }
            }
        }
    }
    writeln!(txt, "\n{n} cases; f32 vs f64 max |ΔF|/(μFn): kernel pipeline on the same samples {worst_pipe:.2e}, end to end with f32 geometry {worst:.2e}").unwrap();
    println!("{txt}");
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap();
    std::fs::create_dir_all(root.join("out")).unwrap();
    std::fs::write(root.join("out").join(file), &txt).unwrap();
    // The STRIPES/AC/FaStrip/wear pipeline in f32 against f64 on the same geometry samples, and
    // end to end with the f32 geometry: the 1e-3 μFn. (End to end once missed it on the
    // flat-topped gap of 1360 mm, left wheel, dy = 0, 120 kN, 5.3e-3, while the geometry summed
    // ≈ 700 mm track coordinates in f32; it works in local coordinates since: 8.7e-4 worst over
    // the 120 cases, 7.3e-4 over the default 40.)
    assert!(worst_pipe <= 1e-3, "{worst_pipe}");
    assert!(worst <= 1e-3, "{worst}");
}
