//! `wrc table` (build a contact table for the real-time step) and `wrc solve --table FILE` (run the
//! fixed-cost step on it). Contract: docs/cli.md; the byte format: docs/realtime.md.

use crate::args::{Precision, Side as ArgSide, SolveArgs, SweepArgs, TableArgs, WheelRail};
use crate::timing::median_time_us;
use crate::wheelrail::{profile_name, table as profile_table, NODES};
use serde_json::json;
use std::fmt::Write as _;
use std::path::Path;
use wrc_kernel::geometry::{Kinematics, Side, TrackSetup, WheelsetPose};
use wrc_kernel::profile::ProfileKind;
use wrc_kernel::step::{step, StepInput, StepResult};
use wrc_kernel::table::{
    build_table, profile_checksum, ContactTable, TableHeader, TableSlot, TableSpec, HEADER_BYTES,
    ROW_BUFFERS,
};
use wrc_kernel::wheel::{DefaultWheelWorkspace, WheelConfig};
use wrc_kernel::{Material, Real};

/// Slots per table node built by `wrc table` and the step's slot capacity for `--table`.
pub const SLOTS: usize = 3;
/// Strips per slot built by `wrc table`.
pub const STRIPS: usize = 16;
/// The step's strip capacity for `--table` (tables with up to this many strips run).
const STRIP_CAP: usize = 64;

fn side_of(s: ArgSide) -> Side {
    match s {
        ArgSide::Left => Side::Left,
        ArgSide::Right => Side::Right,
    }
}

/// The track set-up of the wheel/rail options (`--back-to-back` default `b2b`).
fn setup<T: Real>(wr: &WheelRail, b2b: f64) -> TrackSetup<T> {
    let t = T::from_f64;
    TrackSetup {
        gauge: t(wr.gauge),
        gauge_depth: t(wr.gauge_depth),
        back_to_back: t(wr.back_to_back.unwrap_or(b2b)),
        cant: t(wr.cant),
        r0: t(wr.r0),
        ..TrackSetup::standard()
    }
}

/// The kernel's shift range (+left) of a shift range taken towards the analysed wheel.
fn kernel_range(side: Side, from: f64, to: f64) -> (f64, f64) {
    match side {
        Side::Right => (-to, -from),
        Side::Left => (from, to),
    }
}

/// Margin of the default shift range beyond the flange contacts, mm.
const FLANGE_MARGIN: f64 = 2.0;

/// The shift (towards the analysed wheel, mm) of this wheel's flange contact: the largest
/// contact angle of the rigid contact point at yaw 0 and roll 0 (with `--equilibrium-roll`: the
/// two-wheel equilibrium roll), scanned in 0.1 mm steps from 0 to 25 mm (stopping at the first
/// shift the profiles do not describe or 0.2 rad past the largest).
fn flange_shift(a: &TableArgs) -> Result<f64, String> {
    let wheel = profile_table::<f64>(a.wr.wheel.as_deref(), ProfileKind::Wheel)?;
    let rail = profile_table::<f64>(a.wr.rail.as_deref(), ProfileKind::Rail)?;
    let side = side_of(a.wr.side);
    let setup = setup::<f64>(&a.wr, 1360.0);
    let mut geom =
        wrc_kernel::geometry::WheelRail::<f64, NODES, NODES>::unplaced(&rail, &wheel, &setup);
    let (mut best, mut at) = (f64::MIN, None);
    for q in 0..=250 {
        let s = 0.1 * q as f64;
        let mut pose = WheelsetPose::towards_wheel(side, s, 0.0, 0.0);
        if a.equilibrium_roll {
            match wrc_kernel::geometry::equilibrium_roll::<f64, NODES, NODES>(
                &rail, &wheel, &setup, pose.dy, 0.0, 0.05,
            ) {
                Ok(e) => pose.roll = e.roll,
                Err(_) => break,
            }
        }
        if geom
            .place_in(&rail, &wheel, &setup, &pose, side, 0.05)
            .is_err()
        {
            break;
        }
        let angle = geom.rail.at(geom.rail_t_at(geom.y_rigid)).angle;
        if angle > best {
            (best, at) = (angle, Some(s));
        } else if angle < best - 0.2 {
            break;
        }
    }
    at.ok_or_else(|| "no contact at shift 0: give --dy-from and --dy-to".to_string())
}

/// `wrc table`: builds the table, writes it to `--out` and prints a summary.
pub fn build(a: &TableArgs) -> Result<(), String> {
    let (from, to) = match (a.dy_from, a.dy_to) {
        (Some(f), Some(t)) => (f, t),
        (f, t) => {
            let e = ((flange_shift(a)? + FLANGE_MARGIN) * 10.0).round() / 10.0;
            (f.unwrap_or(-e), t.unwrap_or(e))
        }
    };
    crate::validate::check_table(a, from, to)?;
    let (bytes, summary) = match a.precision {
        Precision::F64 => build_in::<f64>(a, from, to)?,
        Precision::F32 => build_in::<f32>(a, from, to)?,
    };
    std::fs::write(&a.out, &bytes)
        .map_err(|e| format!("{}: cannot write: {e}", a.out.display()))?;
    crate::out(&summary)
}

fn build_in<T: Real>(a: &TableArgs, dy_from: f64, dy_to: f64) -> Result<(Vec<u8>, String), String> {
    let t = T::from_f64;
    let wheel = profile_table::<T>(a.wr.wheel.as_deref(), ProfileKind::Wheel)?;
    let rail = profile_table::<T>(a.wr.rail.as_deref(), ProfileKind::Rail)?;
    let side = side_of(a.wr.side);
    let (d0, d1) = kernel_range(side, dy_from, dy_to);
    let n_dy = ((dy_to - dy_from) / a.dy_step).round() as usize + 1;
    let spec = TableSpec {
        dy_min: t(d0),
        dy_max: t(d1),
        n_dy,
        f_min: t(a.fz_min),
        f_max: t(a.fz_max),
        n_load: a.loads,
        grid_step: t(0.05),
        equilibrium_roll: a.equilibrium_roll,
        refine_tol: t(a.refine_tol),
        max_dy_nodes: a.max_dy_nodes,
    };
    let setup = setup::<T>(&a.wr, 1360.0);
    let mat = Material::<T>::identical(t(a.e_mpa), t(a.nu)).map_err(crate::validate::kernel_msg)?;
    let cfg = WheelConfig::recommended(t(0.3), t(200.0 / 3.6 * 1e3), setup.r0);
    let mut out = vec![0u8; spec.capacity_bytes(SLOTS, STRIPS)];
    let mut rows = vec![TableSlot::<T, STRIPS>::EMPTY; ROW_BUFFERS * SLOTS * spec.n_load];
    let mut ws = Box::new(DefaultWheelWorkspace::<T>::new());
    let t0 = std::time::Instant::now();
    let rep = build_table::<T, NODES, NODES, SLOTS, STRIPS, 4, 128, 256, 4, 32, 32, 128>(
        &rail, &wheel, &setup, side, &mat, &cfg, &spec, &mut rows, &mut ws, &mut out,
    )
    .map_err(|e| format!("table build: {e}"))?;
    out.truncate(rep.bytes);
    let secs = t0.elapsed().as_secs_f64();
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{}: {} bytes ({:?}), {} × {} nodes (shift {} … {} mm towards the {} wheel, F_z {} … {} N), \
         {}, {} slots used (of {}), {} strips per slot; {} nodes not converged; built in {:.1} s",
        a.out.display(),
        rep.bytes,
        a.precision,
        rep.dy_nodes,
        a.loads,
        dy_from,
        dy_to,
        format!("{:?}", a.wr.side).to_lowercase(),
        a.fz_min,
        a.fz_max,
        if a.equilibrium_roll { "equilibrium roll" } else { "roll 0" },
        rep.slots_used,
        SLOTS,
        STRIPS,
        rep.not_converged,
        secs
    );
    let _ = writeln!(
        s,
        "wheel {}, rail {}",
        profile_name(a.wr.wheel.as_deref(), true),
        profile_name(a.wr.rail.as_deref(), false)
    );
    Ok((out, s))
}

/// The precision a table file was written in (bytes per value in its header).
fn file_precision(bytes: &[u8]) -> Option<Precision> {
    match bytes
        .get(12..16)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    {
        Some(8) => Some(Precision::F64),
        Some(4) => Some(Precision::F32),
        _ => None,
    }
}

/// `wrc solve --table FILE`: the fixed-cost real-time step on the table, as a JSON document or
/// a table on stdout.
pub fn solve(a: &SolveArgs) -> Result<(), String> {
    let path = a.table.as_deref().ok_or("--table FILE is required here")?;
    let bytes = read_table(path)?;
    let doc = run_on(a, &bytes).map_err(|e| format!("{}: {e}", path.display()))?;
    if a.json {
        crate::out(&format!(
            "{}\n",
            serde_json::to_string_pretty(&doc).map_err(|e| e.to_string())?
        ))
    } else {
        crate::out(&text(&doc))
    }
}

/// The bytes of a table file (at least a header long).
fn read_table(path: &Path) -> Result<Vec<u8>, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: cannot read: {e}", path.display()))?;
    if bytes.len() < HEADER_BYTES {
        return Err(format!(
            "{}: not a contact table (too short)",
            path.display()
        ));
    }
    Ok(bytes)
}

/// The real-time step of `a`'s state on the table `bytes`, in the table's precision: the JSON
/// document of `wrc solve --table`.
fn run_on(a: &SolveArgs, bytes: &[u8]) -> Result<serde_json::Value, String> {
    match file_precision(bytes) {
        Some(Precision::F64) => solve_in::<f64>(a, bytes),
        Some(Precision::F32) => solve_in::<f32>(a, bytes),
        None => Err("not a contact table (precision field)".into()),
    }
}

/// `wrc sweep --table FILE`: the real-time step at every shift of the sweep (yaw `yaw_of(dy)`
/// mrad), printed as the sweep's table (model `realtime`), or as a JSON array of `wrc solve
/// --table` documents, CSV and plots as the converged sweep writes them (no adhesion fraction
/// or wear: the step computes none).
pub fn sweep(
    a: &SweepArgs,
    path: &Path,
    shifts: &[f64],
    yaw_of: &dyn Fn(f64) -> f64,
) -> Result<(), String> {
    let bytes = read_table(path)?;
    // the sweep's own options are not the solve's
    let own = [
        "dy", "dy-from", "dy-to", "dy-step", "csv", "plot", "json", "table", "compare",
    ];
    let given: Vec<String> = a
        .given
        .iter()
        .filter(|g| !own.contains(&g.as_str()))
        .cloned()
        .collect();
    let mut docs = vec![];
    for &dy in shifts {
        let sa =
            crate::sweep::solve_args(a, dy, yaw_of(dy), Some(path.to_path_buf()), given.clone());
        if docs.is_empty() {
            crate::validate::check_solve(&sa)?;
        }
        let d =
            run_on(&sa, &bytes).map_err(|e| format!("{}: dy = {dy} mm: {e}", path.display()))?;
        docs.push((dy, d));
    }
    // --compare: the converged solver's FaStrip-AC at the same states, on the table's set-up
    let (mut cmp_table, mut cmp_csv) = (String::new(), String::new());
    let mut compared: Vec<(f64, crate::doc::Document)> = vec![];
    if a.compare {
        for (dy, d) in &docs {
            let mut sa = crate::sweep::solve_args(a, *dy, yaw_of(*dy), None, vec![]);
            sa.wr.back_to_back = d["inputs"]["back_to_back_mm"].as_f64();
            sa.wr.gauge = d["inputs"]["gauge_mm"].as_f64().unwrap_or(sa.wr.gauge);
            sa.common.tangential = crate::args::Tangential::Fastrip;
            sa.common.flex = Some(crate::args::Flex::Ac);
            let doc =
                crate::sweep::converged_state(&sa, *dy, yaw_of(*dy), &mut cmp_table, &mut cmp_csv)?;
            compared.push((*dy, doc));
        }
    }
    let f = |p: &serde_json::Value, k: &str| p[k].as_f64().unwrap_or(f64::NAN);
    let cr = |p: &serde_json::Value, k: &str| p["creepage"][k].as_f64().unwrap_or(f64::NAN);
    if let Some(file) = &a.csv {
        let mut csv = String::from(crate::sweep::CSV_HEADER);
        for (dy, d) in &docs {
            for (pi, p) in d["patches"].as_array().into_iter().flatten().enumerate() {
                let _ = writeln!(
                    csv,
                    "{dy},{},fastrip,ac,{pi},{},{},{},{},{},{},{},{},{},{},{},,,true,{},realtime",
                    yaw_of(*dy),
                    f(p, "y_ref_mm"),
                    f(p, "contact_angle_rad"),
                    cr(p, "xi"),
                    cr(p, "eta"),
                    cr(p, "phi_per_mm"),
                    f(p, "fn_n"),
                    f(p, "fx_n"),
                    f(p, "fy_n"),
                    f(p, "mz_nmm"),
                    f(p, "pmax_mpa"),
                    f(p, "area_mm2"),
                    f(d, "time_us"),
                );
            }
        }
        csv.push_str(&cmp_csv);
        std::fs::write(file, csv).map_err(|e| format!("{}: {e}", file.display()))?;
    }
    if let Some(dir) = &a.plot {
        let series: Vec<(f64, crate::doc::Document)> = docs
            .iter()
            .map(|(dy, d)| {
                let patches = d["patches"]
                    .as_array()
                    .into_iter()
                    .flatten()
                    .map(|p| crate::doc::Patch {
                        y_ref_mm: f(p, "y_ref_mm"),
                        contact_angle_rad: f(p, "contact_angle_rad"),
                        creepage: crate::doc::Creepage {
                            xi: cr(p, "xi"),
                            eta: cr(p, "eta"),
                            phi_per_mm: cr(p, "phi_per_mm"),
                        },
                        fn_n: f(p, "fn_n"),
                        fx_n: f(p, "fx_n"),
                        fy_n: f(p, "fy_n"),
                        mz_nmm: f(p, "mz_nmm"),
                        pmax_mpa: f(p, "pmax_mpa"),
                        area_mm2: f(p, "area_mm2"),
                        stick_area_fraction: f64::NAN,
                        wear_depth_max_um: f64::NAN,
                        ..Default::default()
                    })
                    .collect();
                let status = crate::doc::Status {
                    path: "realtime",
                    converged: true,
                    iterations: wrc_kernel::step::COLD_ROUNDS,
                    warnings: vec![],
                };
                let doc = crate::doc::Document::new(
                    d["inputs"].clone(),
                    patches,
                    status,
                    f(d, "time_us"),
                );
                (*dy, doc)
            })
            .collect();
        let yaw = if a.given.iter().any(|g| g == "yaw") {
            format!("yaw {} mrad", a.wr.yaw)
        } else {
            "yaw 1.2·dy mrad".to_string()
        };
        let case = format!(
            "real-time step on {}, F_z {} N, {yaw}",
            path.file_name().unwrap_or_default().to_string_lossy(),
            a.wr.fz
        );
        let mut all = vec![("realtime".to_string(), series)];
        if a.compare {
            all.push(("fastrip-ac (converged)".to_string(), compared.clone()));
        }
        crate::plot::sweep_plots(dir, &case, &all)?;
    }
    if a.json {
        let mut all: Vec<serde_json::Value> = docs.iter().map(|d| d.1.clone()).collect();
        for (_, d) in &compared {
            all.push(serde_json::to_value(d).map_err(|e| e.to_string())?);
        }
        return crate::out(&format!(
            "{}\n",
            serde_json::to_string_pretty(&all).map_err(|e| e.to_string())?
        ));
    }
    let mut s = crate::sweep::table_header();
    let mut times = vec![];
    for (dy, d) in &docs {
        times.push(f(d, "time_us"));
        for p in d["patches"].as_array().into_iter().flatten() {
            let _ = writeln!(
                s,
                "{:>6.2} {:>14} {:>8.3} {:>8.5} {:>9.2e} {:>9.2e} {:>9.2e} {:>10.1} {:>10.1} {:>11.1} {:>8.1} {:>8.2} {:>6}",
                dy, "realtime", f(p, "y_ref_mm"), f(p, "contact_angle_rad"),
                cr(p, "xi"), cr(p, "eta"), cr(p, "phi_per_mm"),
                f(p, "fn_n"), f(p, "fx_n"), f(p, "fy_n"), f(p, "pmax_mpa"), f(p, "area_mm2"), "-"
            );
        }
    }
    s.push_str(&cmp_table);
    times.sort_by(f64::total_cmp);
    if a.compare {
        // the largest difference of the total force, of μF_z
        let mut worst = (0.0f64, f64::NAN);
        for ((dy, d), (_, c)) in docs.iter().zip(&compared) {
            let t = &d["total"];
            let df = (f(t, "fx_n") - c.total.fx_n).hypot(f(t, "fy_n") - c.total.fy_n)
                / (a.common.mu * a.wr.fz);
            if df > worst.0 {
                worst = (df, *dy);
            }
        }
        let _ = writeln!(
            s,
            "real-time step against the converged FaStrip-AC: largest |ΔF| {:.2} % of μF_z (dy = {} mm)",
            100.0 * worst.0,
            worst.1
        );
    }
    let _ = writeln!(
        s,
        "realtime path: the fixed-cost step on {} (FaStrip-AC per strip on the table's STRIPES \
         strips); step time median {:.2} µs, max {:.2} µs over {} shifts",
        path.display(),
        times[times.len() / 2],
        times[times.len() - 1],
        times.len()
    );
    crate::out(&s)
}

/// Checks that the options the table fixes agree with it.
fn agrees<T: Real>(a: &SolveArgs, h: &TableHeader) -> Result<(), String> {
    let has = |f: &str| a.given.iter().any(|g| g == f);
    if side_of(a.wr.side) != h.side {
        return Err(format!(
            "the table is for the {:?} wheel; give --side accordingly",
            h.side
        )
        .to_lowercase());
    }
    let setup = setup::<T>(&a.wr, h.back_to_back);
    for (flag, given, table) in [
        ("back-to-back", setup.back_to_back.to_f64(), h.back_to_back),
        ("gauge", setup.gauge.to_f64(), h.gauge),
    ] {
        if has(flag) && (given - table).abs() > 1e-9 * table.abs() {
            return Err(format!(
                "--{flag} {given} differs from the table's {table} mm"
            ));
        }
    }
    let prec = if h.value_bytes == 8 {
        Precision::F64
    } else {
        Precision::F32
    };
    if has("precision") && a.common.precision != prec {
        return Err(format!("--precision differs from the table's ({prec:?})"));
    }
    for f in [
        "cant",
        "gauge-depth",
        "e-mpa",
        "nu",
        "normal",
        "flex",
        "strips",
        "cells",
        "plot",
    ] {
        if has(f) {
            return Err(format!(
                "--{f} is fixed by the table (or not used by the real-time step): omit it with --table"
            ));
        }
    }
    if a.common.xi.is_some() || a.common.eta.is_some() || a.common.phi.is_some() {
        return Err("the real-time step computes the creepages from the kinematics: omit --xi, --eta, --phi with --table".into());
    }
    if a.common.tangential != crate::args::Tangential::Fastrip {
        return Err(
            "the real-time step is FaStrip (closed form per strip): omit --tangential with --table"
                .into(),
        );
    }
    for (kind, path, sum) in [
        (ProfileKind::Wheel, a.wr.wheel.as_deref(), h.wheel_checksum),
        (ProfileKind::Rail, a.wr.rail.as_deref(), h.rail_checksum),
    ] {
        if path.is_some() {
            let p = profile_table::<T>(path, kind)?;
            if profile_checksum(&p) != sum {
                return Err(format!(
                    "{}: not the profile the table was built from (checksum differs)",
                    path.map(|p| p.display().to_string()).unwrap_or_default()
                ));
            }
        }
    }
    Ok(())
}

fn solve_in<T: Real>(a: &SolveArgs, bytes: &[u8]) -> Result<serde_json::Value, String> {
    let table = ContactTable::<T>::from_bytes(bytes).map_err(|e| e.to_string())?;
    let h = table.header;
    agrees::<T>(a, &h)?;
    let t = T::from_f64;
    let side = side_of(a.wr.side);
    let speed = a.common.speed * 1e3;
    let input = StepInput {
        pose: WheelsetPose::towards_wheel(
            side,
            t(a.wr.dy),
            t(a.wr.yaw * 1e-3),
            t(a.wr.roll * 1e-3),
        ),
        fz: t(a.wr.fz),
        kinematics: Kinematics::nominal(t(speed), t(a.wr.r0)),
        mu: t(a.common.mu),
    };
    let run = || step::<T, SLOTS, STRIP_CAP>(&table, &input);
    let r: StepResult<T, SLOTS> = match run() {
        Ok(r) => r,
        Err(wrc_kernel::Error::OutOfRange(why)) => {
            return Err(format!(
                "{why}: the table covers a shift of {} … {} mm towards the wheel and F_z {} … {} N",
                towards(side, h.dy_min, h.dy_max).0,
                towards(side, h.dy_min, h.dy_max).1,
                h.f_min,
                h.f_max
            ))
        }
        Err(e) => return Err(e.to_string()),
    };
    if h.slots > SLOTS {
        return Err(format!(
            "the table has {} slots; this tool runs at most {SLOTS}",
            h.slots
        ));
    }
    let time_us = median_time_us(|| {
        let _ = std::hint::black_box(run());
    });
    // a roll other than the table's enters through the roll mapping (docs/realtime.md), fitted
    // for ±5 mrad about the table's roll
    let warnings: Vec<String> = vec![];
    for w in &warnings {
        eprintln!("wrc: warning: {w}");
    }
    let mut patches = vec![];
    let (mut fn_t, mut fx_t, mut fy_t, mut mz_t) = (0.0, 0.0, 0.0, 0.0);
    for (k, s) in r.slots.iter().enumerate().take(h.slots) {
        if s.load.partial_cmp(&T::ZERO) != Some(core::cmp::Ordering::Greater) {
            continue;
        }
        let g = |v: T| v.to_f64();
        fn_t += g(s.load);
        fx_t += g(s.fx);
        fy_t += g(s.fy);
        mz_t += g(s.mz);
        patches.push(json!({
            "slot": k,
            "y_ref_mm": g(s.y_ref_rail),
            "contact_angle_rad": g(s.angle),
            "rolling_radius_mm": g(s.rolling_radius),
            "creepage": {"xi": g(s.creepage.xi), "eta": g(s.creepage.eta), "phi_per_mm": g(s.creepage.phi)},
            "fn_n": g(s.load),
            "fx_n": g(s.fx),
            "fy_n": g(s.fy),
            "mz_nmm": g(s.mz),
            "pmax_mpa": g(s.pmax),
            "area_mm2": g(s.area),
        }));
    }
    let mut inputs = json!({
        "case": "wheel_rail",
        "table": a.table.as_ref().map(|p| p.display().to_string()),
        "dy_mm": a.wr.dy, "yaw_mrad": a.wr.yaw, "roll_mrad": a.wr.roll, "fz_n": a.wr.fz,
        "side": a.wr.side, "mu": a.common.mu, "speed_m_per_s": a.common.speed, "r0_mm": a.wr.r0,
        "back_to_back_mm": h.back_to_back, "gauge_mm": h.gauge,
        "e_star_mpa": h.e_star, "nu": h.nu,
        "normal": "stripes-table", "model": "fastrip-ac-strip", "tangential": "fastrip", "flex": "ac",
        "precision": a.common.precision,
    });
    inputs["precision"] = json!(if h.value_bytes == 8 { "f64" } else { "f32" });
    Ok(json!({
        "inputs": inputs,
        "patches": patches,
        "total": {"fn_n": fn_t, "fx_n": fx_t, "fy_n": fy_t, "mz_nmm": mz_t},
        "status": {
            "path": "realtime", "converged": true, "iterations": wrc_kernel::step::COLD_ROUNDS,
            "warnings": warnings,
            "vertical_approach_mm": r.vertical_approach.to_f64(),
            "vertical_load_n": r.vertical_load.to_f64(),
        },
        "time_us": time_us,
    }))
}

/// The shift range towards the analysed wheel of a kernel range (+left).
fn towards(side: Side, lo: f64, hi: f64) -> (f64, f64) {
    match side {
        Side::Right => (-hi, -lo),
        Side::Left => (lo, hi),
    }
}

fn text(d: &serde_json::Value) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{:>5} {:>9} {:>9} {:>10} {:>10} {:>10} {:>12} {:>9} {:>9}",
        "slot", "y_ref", "angle", "Fn", "Fx", "Fy", "Mz", "pmax", "area"
    );
    let _ = writeln!(
        s,
        "{:>5} {:>9} {:>9} {:>10} {:>10} {:>10} {:>12} {:>9} {:>9}",
        "", "mm", "rad", "N", "N", "N", "N mm", "MPa", "mm2"
    );
    let f = |p: &serde_json::Value, k: &str| p[k].as_f64().unwrap_or(f64::NAN);
    for p in d["patches"].as_array().into_iter().flatten() {
        let _ = writeln!(
            s,
            "{:>5} {:>9.3} {:>9.5} {:>10.1} {:>10.2} {:>10.2} {:>12.1} {:>9.1} {:>9.2}",
            p["slot"].as_u64().unwrap_or(0),
            f(p, "y_ref_mm"),
            f(p, "contact_angle_rad"),
            f(p, "fn_n"),
            f(p, "fx_n"),
            f(p, "fy_n"),
            f(p, "mz_nmm"),
            f(p, "pmax_mpa"),
            f(p, "area_mm2")
        );
    }
    let t = &d["total"];
    let _ = writeln!(
        s,
        "total: Fn {:.1} N, Fx {:.2} N, Fy {:.2} N, Mz {:.1} N mm; realtime path (the fixed-cost step), kernel time {:.2} µs",
        f(t, "fn_n"),
        f(t, "fx_n"),
        f(t, "fy_n"),
        f(t, "mz_nmm"),
        d["time_us"].as_f64().unwrap_or(f64::NAN)
    );
    s
}
