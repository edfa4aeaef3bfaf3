//! Per-wheel solve along time series, cold (`wheel::solve_wheel`) against warm-started
//! (`wheel::solve_wheel_warm`, one `WheelState` carried from step to step), S1002/UIC60, 1360 mm,
//! right wheel, μ 0.3, V = 100 km/h, placement grid 0.05 mm, f64:
//!
//! * `ramp`: lateral shift dy = −3 … 6 mm (CONTACT's y_ws sense, towards the flange) in steps
//!   cycling 0.01, 0.02, 0.03, 0.04, 0.05 mm (300 steps), yaw 1.2 × dy mrad, F_z = 83.3 kN;
//! * `hunting`: 1 s at 1 kHz (1000 steps), dy = 4 sin(2π t / 1 s) mm, yaw as a kinematic (Klingel)
//!   oscillation of the same wavelength, ψ = (2π · 4 mm / L) cos(2π t / 1 s) with L = V · 1 s
//!   (0.90 mrad amplitude), F_z = 83.3 kN · (1 + 0.1 sin(2π t / 0.3 s)) (±10 %).
//!
//! The roll of every step is the two-wheel equilibrium roll (`geometry::equilibrium_roll`),
//! interpolated linearly on a 0.25 mm grid of dy (yaw 1.2 × dy mrad; the roll's yaw dependence
//! is below 1e-6 rad here) so the series pose stays smooth and cheap to generate.
//!
//! Run:
//! * `cargo run --release -p wrc-bench --example wheel_series [ramp|hunting|both]`: per series
//!   the loop counts per call (geometry passes, STRIPES solves of the load split, coupling
//!   rounds; median / max), host time per call (median / max), and the warm − cold differences
//!   per step (median / max over the steps; per patch, patches matched by reference point):
//!   |ΔF|/(μ F_z) with F = (F_x, F_y) of the patch, |ΔN|/F_z, |Δpmax|/pmax, |Δarea|/area,
//!   |Δδ_v|/δ_v.
//! * `wheel_series <ramp|hunting|both> [steps] [preset]`: the same with another configuration,
//!   `preset` = `default`, `realtime` (`WheelConfig::realtime`) or `s<strips>x<samples>[t<tol>]`
//!   (e.g. `s16x64`, `s32x128t1e-4`);
//! * `wheel_series compare <ramp|hunting> <preset>`: the preset run warm (one `WheelState`, as a
//!   real-time loop runs it) against the default run cold, per step and patch: |ΔF|/(μF_z),
//!   |ΔN|/F_z, |Δpmax|/pmax, |Δarea|/area (median / max) and the preset's geometry passes;
//! * instruction counts per call: `valgrind --tool=callgrind --callgrind-out-file=/tmp/cg/out
//!   --dump-before='*cold_call*' --dump-before='*warm_call*' --dump-before='*mark*'
//!   target/release/examples/wheel_series ramp` then
//!   `target/release/examples/wheel_series cg /tmp/cg/out` (median / max of the instructions
//!   inside each `cold_call` and each `warm_call`, from the dump files: every step runs
//!   placement, `cold_call`, `warm_call`, `mark`, so the dump before `warm_call` holds the cold
//!   solve and the dump before `mark` the warm one, each with a timer read).

use std::time::Instant;
use wrc_kernel::geometry::{equilibrium_roll, Side, TrackSetup, WheelRail, WheelsetPose};
use wrc_kernel::profile::ProfileTable;
use wrc_kernel::wheel::{
    solve_wheel, solve_wheel_warm, DefaultWheelWorkspace, WheelConfig, WheelResult, WheelState,
};
use wrc_kernel::Material;

const FZ: f64 = 83_300.0;
const GRID: f64 = 0.05;
const MU: f64 = 0.3;

type Res = WheelResult<f64, 4, 4>;

/// One time step: lateral shift (CONTACT's y_ws sense, mm), yaw (rad, CONTACT's sense), load (N).
#[derive(Clone, Copy)]
struct Step {
    y: f64,
    yaw: f64,
    fz: f64,
}

fn ramp() -> Vec<Step> {
    let mut v = vec![];
    let mut y = -3.0;
    let mut i = 0usize;
    while y <= 6.0 + 1e-9 {
        v.push(Step {
            y,
            yaw: 1.2e-3 * y,
            fz: FZ,
        });
        y += 0.01 * (1 + i % 5) as f64;
        i += 1;
    }
    v
}

fn hunting() -> Vec<Step> {
    let tau = std::f64::consts::TAU;
    let v_mm_s = 100.0 / 3.6 * 1000.0;
    let amp = 4.0;
    let yaw_amp = tau * amp / v_mm_s; // wavelength L = V · 1 s
    (0..1000)
        .map(|i| {
            let t = i as f64 * 1e-3;
            Step {
                y: amp * (tau * t).sin(),
                yaw: yaw_amp * (tau * t).cos(),
                fz: FZ * (1.0 + 0.1 * (tau * t / 0.3).sin()),
            }
        })
        .collect()
}

/// Equilibrium roll on a 0.25 mm grid of y_ws from −4.5 to 6.5 mm (yaw 1.2 y_ws mrad).
struct Roll {
    y0: f64,
    h: f64,
    r: Vec<f64>,
}

impl Roll {
    fn new(
        r: &ProfileTable<f64, 2048>,
        w: &ProfileTable<f64, 2048>,
        setup: &TrackSetup<f64>,
    ) -> Self {
        let (y0, h) = (-4.5, 0.25);
        let r = (0..=44)
            .map(|i| {
                let y = y0 + h * i as f64;
                let p = WheelsetPose::from_contact(y, 1.2e-3 * y, 0.0);
                equilibrium_roll::<f64, 2048, 2048>(r, w, setup, p.dy, p.yaw, 0.2)
                    .expect("equilibrium roll")
                    .roll
            })
            .collect();
        Roll { y0, h, r }
    }

    fn at(&self, y: f64) -> f64 {
        let u = ((y - self.y0) / self.h).clamp(0.0, (self.r.len() - 1) as f64);
        let i = (u.floor() as usize).min(self.r.len() - 2);
        let f = u - i as f64;
        self.r[i] * (1.0 - f) + self.r[i + 1] * f
    }
}

#[inline(never)]
fn cold_call(
    g: &WheelRail<'_, f64, 2048, 2048>,
    fz: f64,
    mat: &Material<f64>,
    cfg: &WheelConfig<f64>,
    ws: &mut DefaultWheelWorkspace<f64>,
) -> Res {
    solve_wheel(g, fz, mat, cfg, ws, &mut ()).expect("cold solve")
}

#[inline(never)]
fn warm_call(
    g: &WheelRail<'_, f64, 2048, 2048>,
    fz: f64,
    mat: &Material<f64>,
    cfg: &WheelConfig<f64>,
    ws: &mut DefaultWheelWorkspace<f64>,
    st: &mut WheelState<f64, 4>,
) -> Res {
    solve_wheel_warm(g, fz, mat, cfg, ws, st, &mut ()).expect("warm solve")
}

/// Marks the end of a step for callgrind's `--dump-before`.
#[inline(never)]
fn mark(x: f64) -> f64 {
    std::hint::black_box(x)
}

fn median(v: &[f64]) -> f64 {
    let mut v = v.to_vec();
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

fn max(v: &[f64]) -> f64 {
    v.iter().cloned().fold(0.0, f64::max)
}

/// Differences of one step, warm against cold (patches matched by nearest reference point).
#[derive(Default)]
struct Diff {
    force: f64,
    load: f64,
    pmax: f64,
    area: f64,
    dv: f64,
    same_patches: bool,
}

fn diff(c: &Res, w: &Res, fz: f64) -> Diff {
    let mut d = Diff {
        dv: (w.vertical_approach / c.vertical_approach - 1.0).abs(),
        same_patches: c.patches.len() == w.patches.len(),
        ..Diff::default()
    };
    for pc in c.patches.iter() {
        let pw = w.patches.iter().min_by(|a, b| {
            (a.frame.y_ref_rail - pc.frame.y_ref_rail)
                .abs()
                .total_cmp(&(b.frame.y_ref_rail - pc.frame.y_ref_rail).abs())
        });
        let Some(pw) = pw else {
            d.force = f64::INFINITY;
            continue;
        };
        let (tc, tw) = (&pc.result.totals, &pw.result.totals);
        d.force = d
            .force
            .max(((tw.fx - tc.fx).powi(2) + (tw.fy - tc.fy).powi(2)).sqrt() / (MU * fz));
        d.load = d.load.max((pw.load - pc.load).abs() / fz);
        d.pmax = d.pmax.max((pw.result.pmax / pc.result.pmax - 1.0).abs());
        d.area = d.area.max((pw.result.area / pc.result.area - 1.0).abs());
    }
    d
}

/// The solver configuration of a run: `default` (`WheelConfig::recommended`), `realtime`
/// (`WheelConfig::realtime`), or `s<strips>x<samples>` (recommended with that many strips per
/// region and geometry samples per patch, e.g. `s16x64`).
fn config(preset: &str) -> WheelConfig<f64> {
    let v = 100.0 / 3.6 * 1000.0;
    match preset {
        "default" => WheelConfig::recommended(MU, v, 460.0),
        "realtime" => WheelConfig::realtime(MU, v, 460.0),
        p => {
            let (a, b) = p
                .strip_prefix('s')
                .and_then(|r| r.split_once('x'))
                .expect("preset: default, realtime or s<strips>x<samples>[t<tol>]");
            let (b, t) = b.split_once('t').unwrap_or((b, ""));
            let mut c = WheelConfig::recommended(MU, v, 460.0);
            c.pipeline.strips_per_region = a.parse().expect("strips");
            c.patches.samples = b.parse().expect("samples");
            if !t.is_empty() {
                c.tol = t.parse().expect("tol");
            }
            c
        }
    }
}

fn run(name: &str, steps: &[Step], cfg: &WheelConfig<f64>) {
    let pair = wrc_bench::tables::<f64>();
    let (w, r) = (&*pair.0, &*pair.1);
    let setup = TrackSetup {
        back_to_back: 1360.0,
        ..TrackSetup::<f64>::standard()
    };
    let roll = Roll::new(r, w, &setup);
    let mat = Material::<f64>::steel();
    let cfg = *cfg;
    let mut ws_c = Box::new(DefaultWheelWorkspace::<f64>::new());
    let mut ws_w = Box::new(DefaultWheelWorkspace::<f64>::new());
    let mut st = WheelState::<f64, 4>::new();
    let mut counts = [
        [vec![], vec![]],
        [vec![], vec![]],
        [vec![], vec![]],
        [vec![], vec![]],
    ];
    let (mut t_c, mut t_w) = (vec![], vec![]);
    let mut diffs = vec![];
    let mut unconverged = [0, 0];
    let mut check = [0.0, 0.0];
    for s in steps {
        let pose = WheelsetPose::from_contact(s.y, s.yaw, roll.at(s.y));
        let g = WheelRail::<f64, 2048, 2048>::place(r, w, &setup, &pose, Side::Right, GRID)
            .expect("placement");
        let t0 = Instant::now();
        let c = cold_call(&g, s.fz, &mat, &cfg, &mut ws_c);
        t_c.push(t0.elapsed().as_secs_f64());
        let t0 = Instant::now();
        let wr = warm_call(&g, s.fz, &mat, &cfg, &mut ws_w, &mut st);
        t_w.push(mark(t0.elapsed().as_secs_f64()));
        for (i, res) in [&c, &wr].into_iter().enumerate() {
            counts[0][i].push(res.geometry_calls as f64);
            counts[1][i].push(res.stripes_solves as f64);
            counts[2][i].push(res.coupling_rounds as f64);
            counts[3][i].push(res.iterations as f64);
            unconverged[i] += usize::from(!res.converged);
            for p in res.patches.iter() {
                check[i] += p.result.totals.fy.abs() + p.result.pmax;
            }
        }
        diffs.push(diff(&c, &wr, s.fz));
    }
    println!(
        "== {name}: {} steps; Σ(|Fy| + pmax) cold {:.9} warm {:.9}; not converged: cold {} warm {}",
        steps.len(),
        check[0],
        check[1],
        unconverged[0],
        unconverged[1]
    );
    for (label, c) in [
        "geometry passes",
        "STRIPES solves",
        "coupling rounds",
        "load-loop passes",
    ]
    .iter()
    .zip(&counts)
    {
        println!(
            "  {label:16} cold median {:4.1} max {:4.0} | warm median {:4.1} max {:4.0}",
            median(&c[0]),
            max(&c[0]),
            median(&c[1]),
            max(&c[1])
        );
    }
    println!(
        "  host time per call: cold median {:.0} µs max {:.0} µs | warm median {:.0} µs max {:.0} µs",
        1e6 * median(&t_c),
        1e6 * max(&t_c),
        1e6 * median(&t_w),
        1e6 * max(&t_w)
    );
    let col = |f: &dyn Fn(&Diff) -> f64| -> (f64, f64) {
        let v: Vec<f64> = diffs.iter().map(f).collect();
        (median(&v), max(&v))
    };
    for (label, f) in [
        ("|ΔF|/(μFz)", &(|d: &Diff| d.force) as &dyn Fn(&Diff) -> f64),
        ("|ΔN|/Fz", &|d: &Diff| d.load),
        ("|Δpmax|/pmax", &|d: &Diff| d.pmax),
        ("|Δarea|/area", &|d: &Diff| d.area),
        ("|Δδv|/δv", &|d: &Diff| d.dv),
    ] {
        let (m, x) = col(f);
        println!("  warm − cold {label:14} median {m:.2e} max {x:.2e}");
    }
    println!(
        "  steps with a different patch count: {}",
        diffs.iter().filter(|d| !d.same_patches).count()
    );
}

/// Warm solves of `preset` (one `WheelState` along the series, as a real-time loop runs it)
/// against cold solves of the default configuration: per step and patch (matched by reference
/// point) |ΔF|/(μF_z), |ΔN|/F_z, |Δpmax|/pmax, |Δarea|/area; median / max; and the preset's
/// geometry passes per call.
fn compare(name: &str, steps: &[Step], preset: &str) {
    let pair = wrc_bench::tables::<f64>();
    let (w, r) = (&*pair.0, &*pair.1);
    let setup = TrackSetup {
        back_to_back: 1360.0,
        ..TrackSetup::<f64>::standard()
    };
    let roll = Roll::new(r, w, &setup);
    let mat = Material::<f64>::steel();
    let (c0, c1) = (config("default"), config(preset));
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let mut st = WheelState::<f64, 4>::new();
    let mut diffs = vec![];
    let mut passes: Vec<f64> = vec![];
    for s in steps {
        let pose = WheelsetPose::from_contact(s.y, s.yaw, roll.at(s.y));
        let g = WheelRail::<f64, 2048, 2048>::place(r, w, &setup, &pose, Side::Right, GRID)
            .expect("placement");
        let a = cold_call(&g, s.fz, &mat, &c0, &mut ws);
        let b = warm_call(&g, s.fz, &mat, &c1, &mut ws, &mut st);
        passes.push(b.geometry_calls as f64);
        diffs.push(diff(&a, &b, s.fz));
    }
    println!(
        "== {name}: {preset} warm against default cold, {} steps; geometry passes median {} max {}",
        steps.len(),
        median(&passes),
        max(&passes)
    );
    for (label, f) in [
        ("|ΔF|/(μFz)", &(|d: &Diff| d.force) as &dyn Fn(&Diff) -> f64),
        ("|ΔN|/Fz", &|d: &Diff| d.load),
        ("|Δpmax|/pmax", &|d: &Diff| d.pmax),
        ("|Δarea|/area", &|d: &Diff| d.area),
    ] {
        let v: Vec<f64> = diffs.iter().map(f).collect();
        println!("  {label:14} median {:.2e} max {:.2e}", median(&v), max(&v));
    }
    println!(
        "  steps with a different patch count: {}",
        diffs.iter().filter(|d| !d.same_patches).count()
    );
}

/// Reads callgrind dump files `<base>.1`, `<base>.2`, … and prints median / max instructions of
/// the cold solves (dumps before `warm_call`) and the warm ones (dumps before `mark`).
fn parse_callgrind(base: &str) {
    let (mut cold, mut warm) = (vec![], vec![]);
    let mut part = 1;
    // every call gives 2 dumps; 10^6 parts is far beyond any series here
    while part < 1_000_000 {
        let Ok(text) = std::fs::read_to_string(format!("{base}.{part}")) else {
            break;
        };
        part += 1;
        let trigger = text
            .lines()
            .find(|l| l.starts_with("desc: Trigger:"))
            .unwrap_or("")
            .to_string();
        let total: f64 = text
            .lines()
            .find_map(|l| l.strip_prefix("summary:").or(l.strip_prefix("totals:")))
            .and_then(|s| s.split_whitespace().next()?.parse().ok())
            .unwrap_or(0.0);
        if trigger.ends_with("wheel_series::warm_call") {
            cold.push(total);
        } else if trigger.ends_with("wheel_series::mark") {
            warm.push(total);
        }
    }
    for (label, v) in [("cold", &cold), ("warm", &warm)] {
        if v.is_empty() {
            println!("{label}: no dumps");
            continue;
        }
        println!(
            "{label}: {} calls; instructions per call median {:.3} M, max {:.3} M, mean {:.3} M",
            v.len(),
            median(v) / 1e6,
            max(v) / 1e6,
            v.iter().sum::<f64>() / v.len() as f64 / 1e6
        );
    }
}

fn main() {
    // wheel_series [ramp|hunting|both] [steps] [preset]  |  wheel_series cg <base>
    //   |  wheel_series compare <ramp|hunting> <preset>
    let args: Vec<String> = std::env::args().skip(1).collect();
    let what = args.first().map(String::as_str).unwrap_or("both");
    let hunt = |n: usize| hunting()[..n.min(1000)].to_vec();
    match what {
        "cg" => parse_callgrind(args.get(1).expect("callgrind output base name")),
        "compare" => {
            let preset = args.get(2).map(String::as_str).unwrap_or("realtime");
            match args.get(1).map(String::as_str) {
                Some("ramp") => compare("ramp", &ramp(), preset),
                _ => compare("hunting", &hunt(1000), preset),
            }
        }
        _ => {
            // optional step count (a shorter hunting series for callgrind), then a preset
            let n: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1000);
            let preset = args
                .iter()
                .skip(1)
                .find(|a| a.parse::<usize>().is_err())
                .map(String::as_str)
                .unwrap_or("default");
            let cfg = config(preset);
            match what {
                "ramp" => run("ramp", &ramp(), &cfg),
                "hunting" => run("hunting", &hunt(n), &cfg),
                _ => {
                    run("ramp", &ramp(), &cfg);
                    run("hunting", &hunt(n), &cfg);
                }
            }
        }
    }
}
