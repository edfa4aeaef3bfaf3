//! `wrc sweep`: the lateral-shift sweep of An et al. (2019) with all six simplified models
//! (FASTSIM and FaStrip × Kik–Piotrowski, Linder, Ayasse–Chollet) on the kernel's STRIPES pressure.

use crate::args::{Common, Flex, Normal, SolveArgs, SweepArgs, Tangential};
use crate::doc::Document;
use crate::wheelrail;
use serde_json::json;
use std::fmt::Write as _;

/// The six models in the order of the table.
const MODELS: [(Tangential, Flex); 6] = [
    (Tangential::Fastsim, Flex::Kp),
    (Tangential::Fastsim, Flex::Linder),
    (Tangential::Fastsim, Flex::Ac),
    (Tangential::Fastrip, Flex::Kp),
    (Tangential::Fastrip, Flex::Linder),
    (Tangential::Fastrip, Flex::Ac),
];

/// The name of a model in every output (table, CSV, JSON): the values of `--tangential` and
/// `--flex` joined by a hyphen, e.g. `fastrip-ac`.
pub fn model_name(tang: Tangential, flex: Flex) -> String {
    use clap::ValueEnum;
    let v = |p: Option<clap::builder::PossibleValue>| p.map(|p| p.get_name().to_string());
    format!(
        "{}-{}",
        v(tang.to_possible_value()).unwrap_or_default(),
        v(flex.to_possible_value()).unwrap_or_default()
    )
}

/// The models of the sweep: the six of [`MODELS`] on STRIPES or NORM pressure, the two with the
/// Hertz flexibility on `--normal hertz`; `--tangential` and `--flex` keep those that match.
fn models(a: &SweepArgs) -> Result<Vec<(Tangential, Flex)>, String> {
    let has = |f: &str| a.given.iter().any(|g| g == f);
    let c = &a.common;
    if c.tangential == Tangential::Exact {
        return Err(
            "--tangential exact is not one of the sweep's models (fastsim, fastrip): \
                    use `wrc solve --tangential exact` per shift"
                .into(),
        );
    }
    let all: Vec<(Tangential, Flex)> = if c.normal == Some(Normal::Hertz) {
        vec![
            (Tangential::Fastsim, Flex::Hertz),
            (Tangential::Fastrip, Flex::Hertz),
        ]
    } else {
        if c.flex == Some(Flex::Hertz) {
            return Err(
                "--flex hertz needs --normal hertz in a sweep (the STRIPES and NORM \
                        patches are not elliptic): the sweep's flexibilities are kp, linder, ac"
                    .into(),
            );
        }
        MODELS.to_vec()
    };
    Ok(all
        .into_iter()
        .filter(|(t, f)| {
            (!has("tangential") || *t == c.tangential) && c.flex.is_none_or(|x| x == *f)
        })
        .collect())
}

/// The `wrc solve` arguments of one state of the sweep `a`: shift `dy` (mm) and yaw `yaw`
/// (mrad), the sweep's wheel/rail and model options, `table` for the real-time path and the
/// option names `given` on the command line.
pub fn solve_args(
    a: &SweepArgs,
    dy: f64,
    yaw: f64,
    table: Option<std::path::PathBuf>,
    given: Vec<String>,
) -> SolveArgs {
    let mut wr = a.wr.clone();
    wr.dy = dy;
    wr.yaw = yaw;
    SolveArgs {
        ellipse: None,
        curvatures: None,
        fn_n: None,
        approach: None,
        wr,
        // the sweep's default normal model is STRIPES (many states; the strip model, `wrc
        // solve`'s default, takes 0.1–1 s per patch): `--normal strips` asks for it
        common: Common {
            normal: Some(a.common.normal.unwrap_or(Normal::Stripes)),
            ..a.common.clone()
        },
        json: a.json,
        plot: None,
        plot_reference: false,
        table,
        given,
    }
}

/// One converged state of the sweep: `sa` (shift `dy` mm, yaw `yaw` mrad, its model in
/// `sa.common`) through the converged solver; its patches are appended to the sweep's `table`
/// and `csv`, and its `wrc solve` document returned.
pub fn converged_state(
    sa: &SolveArgs,
    dy: f64,
    yaw: f64,
    table: &mut String,
    csv: &mut String,
) -> Result<Document, String> {
    let (tang, flex) = (sa.common.tangential, sa.common.flex.unwrap_or(Flex::Ac));
    let s = wheelrail::solve_as_asked(sa, false)
        .map_err(|e| format!("dy = {dy} mm, {}: {e}", model_name(tang, flex)))?;
    let model = model_name(tang, flex);
    let (tname, fname) = model.split_once('-').unwrap_or_default();
    for (pi, p) in s.patches.iter().enumerate() {
        writeln!(
            table,
            "{:>6.2} {:>14} {:>8.3} {:>8.5} {:>9.2e} {:>9.2e} {:>9.2e} {:>10.1} {:>10.1} {:>11.1} {:>8.1} {:>8.2} {:>6.3}",
            dy, model, p.y_ref_mm,
            p.contact_angle_rad, p.creepage.xi, p.creepage.eta, p.creepage.phi_per_mm,
            p.fn_n, p.fx_n, p.fy_n, p.pmax_mpa, p.area_mm2, p.stick_area_fraction
        )
        .ok();
        writeln!(
            csv,
            "{dy},{},{tname},{fname},{pi},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{model}",
            yaw,
            p.y_ref_mm,
            p.contact_angle_rad,
            p.creepage.xi,
            p.creepage.eta,
            p.creepage.phi_per_mm,
            p.fn_n,
            p.fx_n,
            p.fy_n,
            p.mz_nmm,
            p.pmax_mpa,
            p.area_mm2,
            p.stick_area_fraction,
            p.wear_depth_max_um,
            s.status.converged,
            s.time_us
        )
        .ok();
    }
    let inputs = json!({
        "dy_mm": dy, "yaw_mrad": yaw, "model": model, "tangential": tang, "flex": flex,
        "normal": sa.common.normal.unwrap_or(Normal::Stripes),
        "wheel": crate::wheelrail::profile_name(sa.wr.wheel.as_deref(), true),
        "rail": crate::wheelrail::profile_name(sa.wr.rail.as_deref(), false),
        "fz_n": sa.wr.fz, "back_to_back_mm": sa.wr.back_to_back, "side": sa.wr.side,
        "mu": sa.common.mu, "e_mpa": sa.common.e_mpa, "nu": sa.common.nu,
        "strips": sa.common.strips, "cells": sa.common.cells, "precision": sa.common.precision,
    });
    Ok(Document::new(inputs, s.patches, s.status, s.time_us))
}

/// The CSV header of the sweep (one row per shift, model and patch).
pub const CSV_HEADER: &str = "dy_mm,yaw_mrad,tangential,flex,patch,y_ref_mm,contact_angle_rad,xi,eta,phi_per_mm,fn_n,fx_n,fy_n,mz_nmm,pmax_mpa,area_mm2,stick_area_fraction,wear_depth_max_um,converged,time_us,model\n";

/// The header line of the sweep's table on stdout.
pub fn table_header() -> String {
    format!(
        "{:>6} {:>14} {:>8} {:>8} {:>9} {:>9} {:>9} {:>10} {:>10} {:>11} {:>8} {:>8} {:>6}\n",
        "dy",
        "model",
        "y_ref",
        "angle",
        "xi",
        "eta",
        "phi",
        "Fn",
        "Fx",
        "Fy",
        "pmax",
        "area",
        "stick"
    )
}

/// Runs the sweep and prints/writes its outputs (`--table`: the real-time step instead of the
/// six converged models).
pub fn run(a: &SweepArgs) -> Result<(), String> {
    let has = |f: &str| a.given.iter().any(|g| g == f);
    let (dy_from, dy_to, dy_step) = if has("dy") {
        if let Some(f) = ["dy-from", "dy-to", "dy-step"].iter().find(|f| has(f)) {
            return Err(format!(
                "--dy runs the sweep at one shift; give either --dy or --{f}"
            ));
        }
        (a.wr.dy, a.wr.dy, 1.0)
    } else {
        (a.dy_from, a.dy_to, a.dy_step)
    };
    if dy_step.is_nan()
        || dy_step <= 0.0
        || dy_to < dy_from
        || !dy_from.is_finite()
        || !dy_to.is_finite()
    {
        return Err("need --dy-step > 0 and --dy-to >= --dy-from".into());
    }
    let n = ((dy_to - dy_from) / dy_step + 1e-9).floor() as usize + 1;
    if n > 10_000 {
        return Err("more than 10000 shifts".into());
    }
    let shifts: Vec<f64> = (0..n).map(|k| dy_from + k as f64 * dy_step).collect();
    // yaw: 1.2 mrad per mm of shift (An et al. 2019) unless --yaw fixes it
    let yaw_of = |dy: f64| if has("yaw") { a.wr.yaw } else { 1.2 * dy };
    if let Some(t) = &a.table {
        return crate::realtime::sweep(a, t, &shifts, &yaw_of);
    }
    let models = models(a)?;
    if models.is_empty() {
        return Err("no model of the sweep matches --tangential and --flex".into());
    }
    let mut table = String::new();
    let mut csv = String::from(CSV_HEADER);
    table.push_str(&table_header());
    let mut docs = vec![];
    let mut series: Vec<(String, Vec<(f64, Document)>)> = vec![];
    for (k, &dy) in shifts.iter().enumerate() {
        for (mi, &(tang, flex)) in models.iter().enumerate() {
            let mut sa = solve_args(a, dy, yaw_of(dy), None, vec![]);
            sa.wr.back_to_back = Some(sa.wr.back_to_back.unwrap_or(1353.0));
            sa.common.tangential = tang;
            sa.common.flex = Some(flex);
            if k == 0 && mi == 0 {
                crate::validate::check_solve(&sa)?;
            }
            let d = converged_state(&sa, dy, yaw_of(dy), &mut table, &mut csv)?;
            let model = model_name(tang, flex);
            if series.len() <= mi {
                series.push((model.clone(), vec![]));
            }
            series[mi].1.push((dy, d.clone()));
            docs.push(d);
        }
    }
    if let Some(f) = &a.csv {
        std::fs::write(f, csv).map_err(|e| format!("{}: {e}", f.display()))?;
    }
    if let Some(dir) = &a.plot {
        let yaw = if has("yaw") {
            format!("yaw {} mrad", a.wr.yaw)
        } else {
            "yaw 1.2·dy mrad".to_string()
        };
        let case = format!(
            "{}/{}, F_z {} N, {yaw}, {}",
            crate::wheelrail::profile_short(a.wr.wheel.as_deref(), true),
            crate::wheelrail::profile_short(a.wr.rail.as_deref(), false),
            a.wr.fz,
            a.common
                .normal
                .map(|n| format!("{n:?}").to_lowercase())
                .unwrap_or_else(|| "stripes".into()),
        );
        crate::plot::sweep_plots(dir, &case, &series)?;
    }
    if a.json {
        crate::out(&format!(
            "{}\n",
            serde_json::to_string_pretty(&docs).map_err(|e| e.to_string())?
        ))
    } else {
        crate::out(&table)
    }
}
