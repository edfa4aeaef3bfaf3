//! The Rust API's forces at the states an FMU simulation saw, for `fmu/tests/fmpy_check.py`.
//!
//! `cargo run --release -p wrc-fmu --example reference -- TABLE.bin IN.csv OUT.csv`
//!
//! IN.csv has a header and the columns `time,dy_used,yaw,fz` (the shift towards the analysed
//! wheel the FMU used, mm; yaw rad; F_z N); OUT.csv gets `time,dy,fx,fy,mz,fn` from
//! `wrc_kernel::step::step` at the pose `WheelsetPose::towards_wheel(side, dy, yaw, 0)`,
//! nominal rolling at the FMU's default speed and r0 and its default μ, with shortest
//! round-trip formatting (exact f64). It also prints the mean kernel time per step.

use std::fmt::Write as _;
use wrc_fmu::model::{DEFAULT_MU, DEFAULT_R0, DEFAULT_SPEED, SLOTS, STRIP_CAP};
use wrc_kernel::geometry::{Kinematics, WheelsetPose};
use wrc_kernel::step::{step, StepInput};
use wrc_kernel::table::ContactTable;

fn run() -> Result<(), String> {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let [table, input, output] = a.as_slice() else {
        return Err("usage: reference TABLE.bin IN.csv OUT.csv".into());
    };
    let bytes = std::fs::read(table).map_err(|e| format!("{table}: {e}"))?;
    let t = ContactTable::<f64>::from_bytes(&bytes).map_err(|e| format!("{table}: {e}"))?;
    let text = std::fs::read_to_string(input).map_err(|e| format!("{input}: {e}"))?;
    let mut states = Vec::new();
    for (n, line) in text.lines().enumerate().skip(1) {
        let v: Result<Vec<f64>, _> = line.split(',').map(|x| x.trim().parse::<f64>()).collect();
        match v.map_err(|e| format!("{input}:{}: {e}", n + 1))?.as_slice() {
            [time, dy, yaw, fz] => states.push([*time, *dy, *yaw, *fz]),
            _ => return Err(format!("{input}:{}: expected 4 columns", n + 1)),
        }
    }
    let mut out = String::from("time,dy,fx,fy,mz,fn\n");
    let t0 = std::time::Instant::now();
    let mut rows = Vec::with_capacity(states.len());
    for [time, dy, yaw, fz] in &states {
        let input = StepInput {
            pose: WheelsetPose::towards_wheel(t.header.side, *dy, *yaw, 0.0),
            fz: *fz,
            kinematics: Kinematics::nominal(DEFAULT_SPEED, DEFAULT_R0),
            mu: DEFAULT_MU,
        };
        let r = step::<f64, SLOTS, STRIP_CAP>(&t, &input)
            .map_err(|e| format!("t = {time}: dy {dy}: {e}"))?;
        let (mut fx, mut fy, mut mz, mut fnn) = (0.0, 0.0, 0.0, 0.0);
        for s in &r.slots {
            fx += s.fx;
            fy += s.fy;
            mz += s.mz;
            fnn += s.load;
        }
        rows.push([*time, *dy, fx, fy, mz, fnn]);
    }
    let us = t0.elapsed().as_secs_f64() * 1e6 / states.len().max(1) as f64;
    for r in rows {
        let _ = writeln!(
            out,
            "{:?},{:?},{:?},{:?},{:?},{:?}",
            r[0], r[1], r[2], r[3], r[4], r[5]
        );
    }
    std::fs::write(output, out).map_err(|e| format!("{output}: {e}"))?;
    println!(
        "reference: {} states, kernel step {us:.2} µs per call (host, this process)",
        states.len()
    );
    Ok(())
}

fn main() {
    if let Err(e) = run() {
        eprintln!("reference: {e}");
        std::process::exit(1);
    }
}
