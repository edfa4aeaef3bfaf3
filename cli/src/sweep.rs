//! `wrc sweep`: the lateral-shift sweep of An et al. (2019) with all six simplified models
//! (FASTSIM and FaStrip × Kik–Piotrowski, Linder, Ayasse–Chollet) on the kernel's STRIPES pressure.

use crate::args::{Flex, Precision, SolveArgs, SweepArgs, Tangential};
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

/// Runs the sweep and prints/writes its outputs.
pub fn run(a: &SweepArgs) -> Result<(), String> {
    if a.dy_step.is_nan() || a.dy_step <= 0.0 || a.dy_to < a.dy_from {
        return Err("need --dy-step > 0 and --dy-to >= --dy-from".into());
    }
    let n = ((a.dy_to - a.dy_from) / a.dy_step + 1e-9).floor() as usize + 1;
    if n > 10_000 {
        return Err("more than 10000 shifts".into());
    }
    let mut table = String::new();
    let mut csv = String::from("dy_mm,yaw_mrad,tangential,flex,patch,y_ref_mm,contact_angle_rad,xi,eta,phi_per_mm,fn_n,fx_n,fy_n,mz_nmm,pmax_mpa,area_mm2,stick_area_fraction,wear_depth_max_um,converged,time_us\n");
    writeln!(
        table,
        "{:>6} {:>9} {:>8} {:>8} {:>9} {:>9} {:>9} {:>10} {:>10} {:>11} {:>8} {:>8} {:>6}",
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
    .ok();
    let mut docs = vec![];
    for k in 0..n {
        let dy = a.dy_from + k as f64 * a.dy_step;
        for (tang, flex) in MODELS {
            let mut wr = a.wr.clone();
            wr.dy = dy;
            wr.yaw = 1.2 * dy;
            wr.back_to_back = Some(wr.back_to_back.unwrap_or(1353.0));
            let mut common = a.common.clone();
            common.tangential = tang;
            common.flex = Some(flex);
            let sa = SolveArgs {
                ellipse: None,
                curvatures: None,
                fn_n: None,
                approach: None,
                wr,
                common,
                json: a.json,
                plot: None,
            };
            let s = match (sa.common.precision, sa.common.cells) {
                (Precision::F64, 16) => wheelrail::solve::<f64, 16>(&sa, false),
                (Precision::F64, 64) => wheelrail::solve::<f64, 64>(&sa, false),
                (Precision::F64, _) => wheelrail::solve::<f64, 32>(&sa, false),
                (Precision::F32, 16) => wheelrail::solve::<f32, 16>(&sa, false),
                (Precision::F32, 64) => wheelrail::solve::<f32, 64>(&sa, false),
                (Precision::F32, _) => wheelrail::solve::<f32, 32>(&sa, false),
            }
            .map_err(|e| format!("dy = {dy} mm, {tang:?}-{flex:?}: {e}"))?;
            let model = format!("{tang:?}-{flex:?}").to_lowercase();
            for (pi, p) in s.patches.iter().enumerate() {
                writeln!(
                    table,
                    "{:>6.2} {:>9} {:>8.3} {:>8.5} {:>9.2e} {:>9.2e} {:>9.2e} {:>10.1} {:>10.1} {:>11.1} {:>8.1} {:>8.2} {:>6.3}",
                    dy, model.replace("fastsim", "fs").replace("fastrip", "fr"), p.y_ref_mm,
                    p.contact_angle_rad, p.creepage.xi, p.creepage.eta, p.creepage.phi_per_mm,
                    p.fn_n, p.fx_n, p.fy_n, p.pmax_mpa, p.area_mm2, p.stick_area_fraction
                )
                .ok();
                writeln!(
                    csv,
                    "{dy},{},{tang:?},{flex:?},{pi},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
                    1.2 * dy,
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
                "dy_mm": dy, "yaw_mrad": 1.2 * dy, "tangential": tang, "flex": flex,
                "fz_n": sa.wr.fz, "back_to_back_mm": sa.wr.back_to_back, "side": sa.wr.side,
                "mu": sa.common.mu, "e_mpa": sa.common.e_mpa, "nu": sa.common.nu,
                "strips": sa.common.strips, "cells": sa.common.cells, "precision": sa.common.precision,
            });
            docs.push(Document::new(inputs, s.patches, s.status, s.time_us));
        }
    }
    if let Some(f) = &a.csv {
        std::fs::write(f, csv).map_err(|e| format!("{}: {e}", f.display()))?;
    }
    if a.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&docs).map_err(|e| e.to_string())?
        );
    } else {
        print!("{table}");
    }
    Ok(())
}
