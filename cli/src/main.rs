//! `wrc` — the command line of the wrc wheel–rail contact kernel (contract: docs/cli.md).

mod args;
mod doc;
mod elliptic;
mod exact;
mod orientation;
mod plot;
mod realtime;
mod reference;
mod sink;
mod sweep;
mod timing;
mod validate;
mod wheelrail;
mod wr_reference;

use args::{Cli, Command, Precision, SolveArgs};
use clap::{CommandFactory, FromArgMatches};
use doc::Document;
use serde_json::json;
use std::fmt::Write as _;
use std::io::Write as _;

/// Capacity buckets the command line is compiled for (strips and cells used ≤ capacity).
pub(crate) const MAX_GRID: usize = 128;

/// Calls `$f::<T, N, N>` with the smallest square capacity N ∈ {16, 32, 64, 128} that holds the grid.
macro_rules! dispatch {
    ($($f:ident)::+, $t:ty, $n:expr, $($arg:expr),*) => {
        match $n {
            0..=16 => $($f)::+::<$t, 16, 16>($($arg),*),
            17..=32 => $($f)::+::<$t, 32, 32>($($arg),*),
            33..=64 => $($f)::+::<$t, 64, 64>($($arg),*),
            _ => $($f)::+::<$t, 128, 128>($($arg),*),
        }
    };
}

fn inputs_json(a: &SolveArgs) -> serde_json::Value {
    let c = &a.common;
    let elliptic = a.ellipse.is_some() || a.curvatures.is_some();
    json!({
        "case": if elliptic { "elliptic" } else { "wheel_rail" },
        "ellipse_mm": a.ellipse,
        "curvatures_per_mm": a.curvatures,
        "fn_n": a.fn_n,
        "approach_mm": a.approach,
        "wheel": (!elliptic).then(|| wheelrail::profile_name(a.wr.wheel.as_deref(), true)),
        "rail": (!elliptic).then(|| wheelrail::profile_name(a.wr.rail.as_deref(), false)),
        "dy_mm": a.wr.dy, "yaw_mrad": a.wr.yaw, "roll_mrad": a.wr.roll, "fz_n": a.wr.fz,
        "side": a.wr.side, "gauge_mm": a.wr.gauge, "gauge_depth_mm": a.wr.gauge_depth,
        "back_to_back_mm": a.wr.back_to_back.unwrap_or(1360.0), "cant_rad": a.wr.cant, "r0_mm": a.wr.r0,
        "xi": c.xi, "eta": c.eta, "phi_per_mm": c.phi,
        "mu": c.mu, "e_mpa": c.e_mpa, "nu": c.nu, "speed_m_per_s": c.speed,
        "normal": a.normal(),
        "flex": c.flex.unwrap_or(if elliptic { args::Flex::Hertz } else { args::Flex::Ac }),
        "model": sweep::model_name(c.tangential, c.flex.unwrap_or(if elliptic { args::Flex::Hertz } else { args::Flex::Ac })),
        "tangential": c.tangential, "strips": c.strips, "cells": c.cells, "precision": c.precision,
    })
}

/// The case in plot titles: the geometry (dy, yaw or the ellipse), the load and the models.
fn case_title(a: &SolveArgs) -> String {
    let c = &a.common;
    let v = inputs_json(a);
    let name = |k: &str| v[k].as_str().unwrap_or("").to_string();
    let models = format!(
        "{}, {}-{}",
        name("normal"),
        name("tangential"),
        name("flex")
    );
    if let Some([ea, eb]) = a.ellipse {
        let load = match (a.fn_n, a.approach) {
            (Some(f), _) => format!("F_n {f} N"),
            (_, Some(d)) => format!("approach {d} mm"),
            _ => String::new(),
        };
        format!("ellipse {ea}×{eb} mm, {load}, {models}")
    } else if let Some([ca, cb]) = a.curvatures {
        let load = match (a.fn_n, a.approach) {
            (Some(f), _) => format!("F_n {f} N"),
            (_, Some(d)) => format!("approach {d} mm"),
            _ => String::new(),
        };
        format!("curvatures {ca},{cb} 1/mm, {load}, {models}")
    } else {
        let _ = c;
        format!(
            "dy {} mm, yaw {} mrad, F_z {} N, {}, {models}",
            a.wr.dy,
            a.wr.yaw,
            a.wr.fz,
            format!("{:?}", a.wr.side).to_lowercase()
        )
    }
}

/// Writes `s` to stdout; a closed pipe (`wrc sweep | head`) ends the program quietly with
/// status 0, as the reader asked for no more.
pub(crate) fn out(s: &str) -> Result<(), String> {
    let mut o = std::io::stdout().lock();
    match o.write_all(s.as_bytes()).and_then(|_| o.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => std::process::exit(0),
        Err(e) => Err(format!("stdout: {e}")),
    }
}

/// Highest maximum pressure reported without a warning, MPa (several times the yield stress of
/// rail steel: the elastic half-space results are meaningless beyond it).
const PMAX_PLAUSIBLE_MPA: f64 = 5000.0;

/// Warnings for results that are legal but implausible; printed on stderr and kept in the JSON.
fn plausibility(doc: &mut Document) {
    let pmax = doc.patches.iter().map(|p| p.pmax_mpa).fold(0.0, f64::max);
    if pmax > PMAX_PLAUSIBLE_MPA {
        doc.status.warnings.push(format!(
            "pmax {pmax:.4e} MPa exceeds {PMAX_PLAUSIBLE_MPA} MPa, far beyond the elastic limit of \
             steel: check the load (--fn/--fz) and the geometry"
        ));
    }
    for w in &doc.status.warnings {
        eprintln!("wrc: warning: {w}");
    }
}

/// The model in the legends of y0.svg and strips.svg: tangential model and flexibility (as in
/// `inputs.model`; the tangential model alone for the exact one) on the normal model.
fn model_label(a: &SolveArgs) -> String {
    let v = inputs_json(a);
    let model = if a.common.tangential == args::Tangential::Exact {
        "exact"
    } else {
        v["model"].as_str().unwrap_or("model")
    };
    format!("{model} on {}", v["normal"].as_str().unwrap_or(""))
}

/// y0.svg and strips.svg of the solved `patches` into `dir`; with `--plot-reference` the exact
/// reference is run ([`reference::run`]), its patches paired with the model's
/// ([`reference::pair`]) and drawn beside them; its warnings and those of the pairing go to
/// `status` (prefixed `--plot-reference`).
fn plot_profiles(
    a: &SolveArgs,
    dir: &std::path::Path,
    patches: &[doc::Patch],
    status: &mut doc::Status,
) -> Result<(), String> {
    let reference = if a.plot_reference {
        let (r, st) = reference::run(a, patches)?;
        status.warnings.extend(
            st.warnings
                .iter()
                .map(|w| format!("--plot-reference: the reference: {w}")),
        );
        Some(r)
    } else {
        None
    };
    let pairs = match &reference {
        Some(r) => {
            let (p, w) = reference::pair(patches, r);
            status.warnings.extend(w);
            p
        }
        None => vec![None; patches.len()],
    };
    let compared: Vec<plot::Compared> = patches
        .iter()
        .zip(&pairs)
        .enumerate()
        .map(|(k, (p, j))| plot::Compared {
            heading: if a.elliptic() {
                format!("patch {k}")
            } else {
                format!("patch {k} (y_ref {:.2} mm)", p.y_ref_mm)
            },
            model: p,
            reference: j.and_then(|j| reference.as_ref().and_then(|r| r.get(j))),
        })
        .collect();
    plot::write_profiles(
        dir,
        &case_title(a),
        a.common.mu,
        &compared,
        &model_label(a),
        reference::LABEL,
    )
}

fn solve(a: &SolveArgs) -> Result<(), String> {
    let c = &a.common;
    validate::check_solve(a)?;
    if a.table.is_some() {
        return realtime::solve(a);
    }
    let n = c.strips.max(c.cells);
    let keep = a.plot.is_some();
    if a.elliptic() {
        let s = match c.precision {
            Precision::F64 => dispatch!(elliptic::solve, f64, n, a, keep),
            Precision::F32 => dispatch!(elliptic::solve, f32, n, a, keep),
        }?;
        let patches = vec![s.patch];
        let mut status = s.status;
        if let Some(dir) = &a.plot {
            plot::write_all(
                dir,
                &case_title(a),
                &s.cells,
                s.cell_mm.0,
                s.cell_mm.1,
                &s.wear_strips,
            )?;
            plot_profiles(a, dir, &patches, &mut status)?;
        }
        emit(
            a,
            &Document::new(inputs_json(a), patches, status, s.time_us),
        )
    } else {
        let s = wheelrail::solve_as_asked(a, keep)?;
        let mut status = s.status;
        if let Some(dir) = &a.plot {
            plot::write_all(
                dir,
                &case_title(a),
                &s.cells,
                s.cell_mm.0,
                s.cell_mm.1,
                &s.wear_strips,
            )?;
            plot_profiles(a, dir, &s.patches, &mut status)?;
        }
        emit(
            a,
            &Document::new(inputs_json(a), s.patches, status, s.time_us),
        )
    }
}

fn emit(a: &SolveArgs, doc: &Document) -> Result<(), String> {
    let mut doc = doc.clone();
    plausibility(&mut doc);
    if a.json {
        out(&format!(
            "{}\n",
            serde_json::to_string_pretty(&doc).map_err(|e| e.to_string())?
        ))
    } else {
        out(&table(&doc))
    }
}

fn table(d: &Document) -> String {
    let mut s = String::new();
    writeln!(
        s,
        "{:>5} {:>9} {:>9} {:>8} {:>10} {:>10} {:>10} {:>12} {:>9} {:>9} {:>6} {:>9}",
        "patch",
        "y_ref",
        "angle",
        "approach",
        "Fn",
        "Fx",
        "Fy",
        "Mz",
        "pmax",
        "area",
        "stick",
        "wear"
    )
    .ok();
    writeln!(
        s,
        "{:>5} {:>9} {:>9} {:>8} {:>10} {:>10} {:>10} {:>12} {:>9} {:>9} {:>6} {:>9}",
        "", "mm", "rad", "mm", "N", "N", "N", "N mm", "MPa", "mm2", "-", "µm"
    )
    .ok();
    for (k, p) in d.patches.iter().enumerate() {
        writeln!(
            s,
            "{:>5} {:>9.3} {:>9.5} {:>8.5} {:>10.1} {:>10.2} {:>10.2} {:>12.1} {:>9.1} {:>9.2} {:>6.3} {:>9.3e}",
            k, p.y_ref_mm, p.contact_angle_rad, p.approach_mm, p.fn_n, p.fx_n, p.fy_n, p.mz_nmm,
            p.pmax_mpa, p.area_mm2, p.stick_area_fraction, p.wear_depth_max_um
        )
        .ok();
    }
    let t = &d.total;
    writeln!(
        s,
        "total: Fn {:.1} N, Fx {:.2} N, Fy {:.2} N, Mz {:.1} N mm; {} path, converged {}, kernel time {:.1} µs",
        t.fn_n, t.fx_n, t.fy_n, t.mz_nmm, d.status.path, d.status.converged, d.time_us
    )
    .ok();
    s
}

fn main() {
    let cmd = Cli::command();
    let m = cmd.clone().get_matches();
    let mut cli = Cli::from_arg_matches(&m).unwrap_or_else(|e| e.exit());
    if let Some((name, sm)) = m.subcommand() {
        let sub = cmd.find_subcommand(name).expect("parsed subcommand exists");
        let given = validate::given(sub, sm);
        match &mut cli.command {
            Command::Solve(a) => a.given = given,
            Command::Sweep(a) => a.given = given,
            Command::Table(a) => a.given = given,
        }
    }
    let r = match &cli.command {
        Command::Solve(a) => solve(a),
        Command::Sweep(a) => sweep::run(a),
        Command::Table(a) => realtime::build(a),
    };
    if let Err(e) = r {
        eprintln!("wrc: error: {e}");
        std::process::exit(1);
    }
}
