//! `wrc` — the command line of the wrc wheel–rail contact kernel (contract: docs/cli.md).

mod args;
mod doc;
mod elliptic;
mod exact;
mod plot;
mod sink;
mod sweep;
mod timing;
mod wheelrail;
mod wr_reference;

use args::{Cli, Command, Precision, SolveArgs};
use clap::Parser;
use doc::Document;
use serde_json::json;

/// Capacity buckets the command line is compiled for (strips and cells used ≤ capacity).
const MAX_GRID: usize = 128;

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
        "wheel": a.wr.wheel, "rail": a.wr.rail,
        "dy_mm": a.wr.dy, "yaw_mrad": a.wr.yaw, "roll_mrad": a.wr.roll, "fz_n": a.wr.fz,
        "side": a.wr.side, "gauge_mm": a.wr.gauge, "gauge_depth_mm": a.wr.gauge_depth,
        "back_to_back_mm": a.wr.back_to_back.unwrap_or(1360.0), "cant_rad": a.wr.cant, "r0_mm": a.wr.r0,
        "xi": c.xi, "eta": c.eta, "phi_per_mm": c.phi,
        "mu": c.mu, "e_mpa": c.e_mpa, "nu": c.nu, "speed_m_per_s": c.speed,
        "normal": c.normal.unwrap_or(if elliptic {
            args::Normal::Hertz
        } else if c.tangential == args::Tangential::Exact {
            args::Normal::Norm
        } else {
            args::Normal::Stripes
        }),
        "flex": c.flex.unwrap_or(if elliptic { args::Flex::Hertz } else { args::Flex::Ac }),
        "tangential": c.tangential, "strips": c.strips, "cells": c.cells, "precision": c.precision,
    })
}

fn solve(a: &SolveArgs) -> Result<(), String> {
    let c = &a.common;
    if c.strips > MAX_GRID || c.cells > MAX_GRID {
        return Err(format!("--strips and --cells must be at most {MAX_GRID}"));
    }
    let n = c.strips.max(c.cells);
    let keep = a.plot.is_some();
    if a.ellipse.is_some() || a.curvatures.is_some() {
        let s = match c.precision {
            Precision::F64 => dispatch!(elliptic::solve, f64, n, a, keep),
            Precision::F32 => dispatch!(elliptic::solve, f32, n, a, keep),
        }?;
        if let Some(dir) = &a.plot {
            plot::write_all(dir, &s.cells, s.cell_mm.0, s.cell_mm.1, &s.wear_strips)?;
        }
        emit(
            a,
            &Document::new(inputs_json(a), vec![s.patch], s.status, s.time_us),
        )
    } else {
        if ![16, 32, 64].contains(&c.cells) {
            return Err("--cells must be 16, 32 or 64 for wheel/rail cases".into());
        }
        let s = match (c.precision, c.cells) {
            (Precision::F64, 16) => wheelrail::solve::<f64, 16>(a, keep),
            (Precision::F64, 32) => wheelrail::solve::<f64, 32>(a, keep),
            (Precision::F64, _) => wheelrail::solve::<f64, 64>(a, keep),
            (Precision::F32, 16) => wheelrail::solve::<f32, 16>(a, keep),
            (Precision::F32, 32) => wheelrail::solve::<f32, 32>(a, keep),
            (Precision::F32, _) => wheelrail::solve::<f32, 64>(a, keep),
        }?;
        if let Some(dir) = &a.plot {
            plot::write_all(dir, &s.cells, s.cell_mm.0, s.cell_mm.1, &s.wear_strips)?;
        }
        emit(
            a,
            &Document::new(inputs_json(a), s.patches, s.status, s.time_us),
        )
    }
}

fn emit(a: &SolveArgs, doc: &Document) -> Result<(), String> {
    if a.json {
        println!(
            "{}",
            serde_json::to_string_pretty(doc).map_err(|e| e.to_string())?
        );
    } else {
        print_table(doc);
    }
    Ok(())
}

fn print_table(d: &Document) {
    println!(
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
    );
    println!(
        "{:>5} {:>9} {:>9} {:>8} {:>10} {:>10} {:>10} {:>12} {:>9} {:>9} {:>6} {:>9}",
        "", "mm", "rad", "mm", "N", "N", "N", "N mm", "MPa", "mm2", "-", "um"
    );
    for (k, p) in d.patches.iter().enumerate() {
        println!(
            "{:>5} {:>9.3} {:>9.5} {:>8.5} {:>10.1} {:>10.2} {:>10.2} {:>12.1} {:>9.1} {:>9.2} {:>6.3} {:>9.3e}",
            k, p.y_ref_mm, p.contact_angle_rad, p.approach_mm, p.fn_n, p.fx_n, p.fy_n, p.mz_nmm,
            p.pmax_mpa, p.area_mm2, p.stick_area_fraction, p.wear_depth_max_um
        );
    }
    let t = &d.total;
    println!(
        "total: Fn {:.1} N, Fx {:.2} N, Fy {:.2} N, Mz {:.1} N mm; converged {}, kernel time {:.1} us",
        t.fn_n, t.fx_n, t.fy_n, t.mz_nmm, d.status.converged, d.time_us
    );
}

fn main() {
    let cli = Cli::parse();
    let r = match &cli.command {
        Command::Solve(a) => solve(a),
        Command::Sweep(a) => sweep::run(a),
    };
    if let Err(e) = r {
        eprintln!("wrc: error: {e}");
        std::process::exit(1);
    }
}
