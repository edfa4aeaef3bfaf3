//! Input checks before any solve (contract: docs/cli.md, "Accepted ranges"): every value the
//! command line takes is checked against the range stated in its message, options that have no
//! effect in the chosen case are errors, and kernel error names are mapped to the flags.

use crate::args::{Common, Normal, SolveArgs, TableArgs, Tangential};

/// Options of the wheel/rail case (long names); none of them affects an elliptic case.
pub const WHEEL_RAIL_FLAGS: [&str; 12] = [
    "wheel",
    "rail",
    "dy",
    "yaw",
    "roll",
    "fz",
    "side",
    "gauge",
    "gauge-depth",
    "back-to-back",
    "cant",
    "r0",
];

/// The long names of the options given on the command line of subcommand `name`.
pub fn given(cmd: &clap::Command, m: &clap::ArgMatches) -> Vec<String> {
    cmd.get_arguments()
        .filter(|a| {
            m.value_source(a.get_id().as_str()) == Some(clap::parser::ValueSource::CommandLine)
        })
        .filter_map(|a| a.get_long().map(str::to_string))
        .collect()
}

/// `Err` unless `lo <= v <= hi` (and finite), naming the flag, its unit and the range.
fn within(flag: &str, v: f64, lo: f64, hi: f64, unit: &str) -> Result<(), String> {
    if v.is_finite() && v >= lo && v <= hi {
        Ok(())
    } else {
        Err(format!(
            "--{flag} {v} is out of range: accepted {lo} ..= {hi}{unit}"
        ))
    }
}

/// `Err` unless `0 < v <= hi` (and finite).
fn positive(flag: &str, v: f64, hi: f64, unit: &str, what: &str) -> Result<(), String> {
    if v.is_finite() && v > 0.0 && v <= hi {
        Ok(())
    } else if v.is_nan() || v <= 0.0 {
        Err(format!("--{flag} must be positive ({what}), got {v}"))
    } else {
        Err(format!(
            "--{flag} {v} is out of range: accepted 0 < --{flag} <= {hi}{unit}"
        ))
    }
}

/// Checks of the options common to every case.
pub fn check_common(c: &Common) -> Result<(), String> {
    for (flag, v) in [("xi", c.xi), ("eta", c.eta)] {
        if let Some(v) = v {
            within(flag, v, -1.0, 1.0, " (dimensionless creepage)")?;
        }
    }
    if let Some(v) = c.phi {
        within("phi", v, -1.0, 1.0, " 1/mm (spin creepage)")?;
    }
    if !(c.mu.is_finite() && c.mu > 0.0 && c.mu <= 1.0) {
        return Err(format!(
            "--mu {} is out of range: accepted 0 < --mu <= 1",
            c.mu
        ));
    }
    positive("e-mpa", c.e_mpa, 1e7, " MPa", "Young's modulus, MPa")?;
    if !(c.nu.is_finite() && (0.0..0.5).contains(&c.nu)) {
        return Err(format!(
            "--nu {} is out of range: accepted 0 <= --nu < 0.5 (Poisson ratio)",
            c.nu
        ));
    }
    positive("speed", c.speed, 1000.0, " m/s", "rolling speed, m/s")?;
    Ok(())
}

/// Checks a `solve` case: ranges, options without effect, grid sizes of the chosen models.
pub fn check_solve(a: &SolveArgs) -> Result<(), String> {
    let c = &a.common;
    check_common(c)?;
    if a.plot_reference && a.plot.is_none() {
        return Err(
            "--plot-reference draws the exact reference into the plots of --plot: give --plot DIR"
                .into(),
        );
    }
    let elliptic = a.ellipse.is_some() || a.curvatures.is_some();
    let has = |f: &str| a.given.iter().any(|g| g == f);
    if elliptic {
        let mode = if a.ellipse.is_some() {
            "--ellipse"
        } else {
            "--curvatures"
        };
        if let Some(f) = WHEEL_RAIL_FLAGS.iter().find(|f| has(f)) {
            return Err(format!(
                "--{f} has no effect with {mode} (it belongs to the wheel/rail case)"
            ));
        }
        if let Some([ea, eb]) = a.ellipse {
            positive("ellipse", ea, 100.0, " mm", "semi-axes A,B in mm")?;
            positive("ellipse", eb, 100.0, " mm", "semi-axes A,B in mm")?;
        }
        if let Some([ca, cb]) = a.curvatures {
            positive("curvatures", ca, 1.0, " 1/mm", "gap curvatures A,B in 1/mm")?;
            positive("curvatures", cb, 1.0, " 1/mm", "gap curvatures A,B in 1/mm")?;
        }
        if let Some(f) = a.fn_n {
            positive("fn", f, 1e7, " N", "normal force, N")?;
        }
        if let Some(d) = a.approach {
            positive("approach", d, 1.0, " mm", "approach, mm")?;
        }
        let lo = wrc_kernel::patch::MIN_STRIPS.max(wrc_kernel::patch::MIN_CELLS);
        for (flag, v) in [("strips", c.strips), ("cells", c.cells)] {
            if v < lo || v > crate::MAX_GRID {
                return Err(format!(
                    "--{flag} {v} is out of range: accepted {lo}..={} for elliptic cases",
                    crate::MAX_GRID
                ));
            }
        }
    } else {
        for f in ["fn", "approach"] {
            if has(f) {
                return Err(format!(
                    "--{f} has no effect on a wheel/rail case (the load is --fz; give --ellipse or \
                     --curvatures for an elliptic case)"
                ));
            }
        }
        positive(
            "fz",
            a.wr.fz,
            f64::MAX,
            " N",
            "vertical load on this wheel, N",
        )?;
        positive("gauge", a.wr.gauge, 3000.0, " mm", "track gauge, mm")?;
        positive("r0", a.wr.r0, 2000.0, " mm", "nominal rolling radius, mm")?;
        if let Some(b) = a.wr.back_to_back {
            positive(
                "back-to-back",
                b,
                3000.0,
                " mm",
                "back-to-back distance, mm",
            )?;
        }
        within("gauge-depth", a.wr.gauge_depth, 0.0, 50.0, " mm")?;
        within("cant", a.wr.cant, -0.5, 0.5, " rad")?;
        within("roll", a.wr.roll, -100.0, 100.0, " mrad")?;
        within("yaw", a.wr.yaw, -100.0, 100.0, " mrad")?;
        if c.tangential != Tangential::Exact {
            match c.normal.unwrap_or(Normal::Stripes) {
                Normal::Stripes | Normal::Strips => {
                    if !(8..=32).contains(&c.strips) {
                        return Err(format!(
                            "--strips {} is out of range: accepted 8..=32 (per region) for \
                             wheel/rail cases on STRIPES or the strip model",
                            c.strips
                        ));
                    }
                }
                Normal::Hertz => {
                    if !(4..=64).contains(&c.strips) {
                        return Err(format!(
                            "--strips {} is out of range: accepted 4..=64 with --normal hertz",
                            c.strips
                        ));
                    }
                }
                Normal::Norm => {}
            }
        }
        if ![16, 32, 64].contains(&c.cells) {
            return Err(format!(
                "--cells {} is out of range: accepted 16, 32 or 64 for wheel/rail cases",
                c.cells
            ));
        }
    }
    Ok(())
}

/// Checks the `wrc table` options; `(dy_from, dy_to)` is the shift range (given or found).
pub fn check_table(a: &TableArgs, dy_from: f64, dy_to: f64) -> Result<(), String> {
    let has = |f: &str| a.given.iter().any(|g| g == f);
    for f in ["dy", "yaw", "roll", "fz"] {
        if has(f) {
            return Err(format!(
                "--{f} has no effect on `wrc table` (the table spans shift and load: use \
                 --dy-from/--dy-to/--dy-step and --fz-min/--fz-max/--loads)"
            ));
        }
    }
    within("dy-from", dy_from, -40.0, 40.0, " mm")?;
    within("dy-to", dy_to, -40.0, 40.0, " mm")?;
    if dy_to <= dy_from {
        return Err(format!("--dy-to {dy_to} must exceed --dy-from {dy_from}"));
    }
    positive(
        "dy-step",
        a.dy_step,
        dy_to - dy_from,
        " mm",
        "shift step, mm",
    )?;
    within("refine-tol", a.refine_tol, 0.0, 1.0, "")?;
    if !(2..=4096).contains(&a.max_dy_nodes) {
        return Err(format!(
            "--max-dy-nodes {}: accepted 2..=4096",
            a.max_dy_nodes
        ));
    }
    let n = ((dy_to - dy_from) / a.dy_step).round() + 1.0;
    if !(2.0..=4096.0).contains(&n) {
        return Err(format!(
            "--dy-step {} gives {n} shift nodes: accepted 2..=4096",
            a.dy_step
        ));
    }
    positive("fz-min", a.fz_min, 1e7, " N", "lowest vertical load, N")?;
    positive("fz-max", a.fz_max, 1e7, " N", "highest vertical load, N")?;
    if a.fz_max <= a.fz_min {
        return Err(format!(
            "--fz-max {} must exceed --fz-min {}",
            a.fz_max, a.fz_min
        ));
    }
    if !(2..=256).contains(&a.loads) {
        return Err(format!(
            "--loads {} is out of range: accepted 2..=256",
            a.loads
        ));
    }
    positive("e-mpa", a.e_mpa, 1e7, " MPa", "Young's modulus, MPa")?;
    if !(a.nu.is_finite() && (0.0..0.5).contains(&a.nu)) {
        return Err(format!(
            "--nu {} is out of range: accepted 0 <= --nu < 0.5 (Poisson ratio)",
            a.nu
        ));
    }
    positive("gauge", a.wr.gauge, 3000.0, " mm", "track gauge, mm")?;
    positive("r0", a.wr.r0, 2000.0, " mm", "nominal rolling radius, mm")?;
    if let Some(b) = a.wr.back_to_back {
        positive(
            "back-to-back",
            b,
            3000.0,
            " mm",
            "back-to-back distance, mm",
        )?;
    }
    within("gauge-depth", a.wr.gauge_depth, 0.0, 50.0, " mm")?;
    within("cant", a.wr.cant, -0.5, 0.5, " rad")?;
    Ok(())
}

/// A kernel error with the kernel's parameter names replaced by the command line's flags.
pub fn kernel_msg(e: impl std::fmt::Display) -> String {
    let s = e.to_string();
    for (kernel, flag) in [
        (": nu1", ": --nu"),
        (": nu2", ": --nu"),
        (": e1", ": --e-mpa"),
        (": e2", ": --e-mpa"),
    ] {
        if let Some(head) = s.strip_suffix(&kernel[2..]) {
            if head.ends_with(": ") {
                return format!("{head}{}", &flag[2..]);
            }
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::kernel_msg;

    #[test]
    fn kernel_names_become_flags() {
        assert_eq!(
            kernel_msg("input out of range: nu1"),
            "input out of range: --nu"
        );
        assert_eq!(kernel_msg("non-positive: e2"), "non-positive: --e-mpa");
        assert_eq!(kernel_msg("input out of range: g"), "input out of range: g");
    }
}
