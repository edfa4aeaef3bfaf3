//! The strip model (`wrc_kernel::ritz`) against NORM at the same load on real-profile geometry.
//!
//! Same cases and measures as `stripes_norm_sweep` (per wheel: pmax the largest over the wheel's
//! patches, area the sum): the kernel's default wheel solve fixes every patch (frame, load,
//! STRIPES samples); NORM solves the patch's gap at that load; STRIPES is re-run on the kernel's
//! samples and the strip model after it.

use std::fmt::Write as _;
use wrc_host_tests::wheelrail::*;
use wrc_kernel::ritz::{RitzConfig, RitzStrips};
use wrc_kernel::stripes::{Stripes, StripesConfig};
use wrc_kernel::Material;

struct Row {
    label: String,
    /// per wheel: (strip model, STRIPES, NORM)
    pmax: (f64, f64, f64),
    area: (f64, f64, f64),
    converged: bool,
    strips: usize,
    qp: u32,
    secs: f64,
}

fn rows_of(
    label: String,
    sol: &CaseSolution,
    mat: &Material<f64>,
    cfg: &StripesConfig<f64>,
) -> Row {
    let mut r = Row {
        label,
        pmax: (0.0, 0.0, 0.0),
        area: (0.0, 0.0, 0.0),
        converged: true,
        strips: 0,
        qp: 0,
        secs: 0.0,
    };
    let mut st = Box::new(Stripes::<f64, 256, 8, 4>::new());
    let mut rz = Box::new(RitzStrips::<f64, 160>::new());
    for p in &sol.patches {
        let s = st
            .solve(&p.stripes_samples, p.load, mat, cfg)
            .unwrap_or_else(|e| panic!("{}: {e}", r.label));
        let t0 = std::time::Instant::now();
        let z = rz
            .solve(&p.stripes_samples, &st, &s, p.load, mat, &ritz_config())
            .unwrap_or_else(|e| panic!("{}: {e}", r.label));
        r.secs += t0.elapsed().as_secs_f64();
        if std::env::var("RITZ_DIAG").is_ok_and(|d| r.label.contains(&d)) {
            println!(
                "{} patch load {:.0}: ritz pmax {:.0} area {:.2} | STRIPES {:.0} {:.2} | NORM {:.0} {:.2} | strips {}",
                r.label, p.load, z.pmax, z.area, p.kernel.pmax, p.kernel.area, p.norm.p_max, p.norm.area, z.strips
            );
            for i in 0..rz.len() {
                let (sh, q, pk) = rz.strip(i).unwrap();
                // NORM line load at this y
                let nl = p
                    .norm
                    .strips
                    .iter()
                    .min_by(|a, b| (a.y - sh.y).abs().partial_cmp(&(b.y - sh.y).abs()).unwrap())
                    .map(|s| (s.force_per_width, s.p_max))
                    .unwrap_or((0.0, 0.0));
                println!(
                    "  y {:8.3} w {:.3} a {:.3} q/w {:8.1} p {:6.0} | NORM q/w {:8.1} p {:.0}",
                    sh.y,
                    sh.w,
                    sh.a,
                    q / sh.w,
                    pk,
                    nl.0,
                    nl.1
                );
            }
        }
        assert!((z.load / p.load - 1.0).abs() < 1e-9, "{}", r.label);
        r.converged &= z.converged;
        r.strips = r.strips.max(z.strips);
        r.qp += z.qp_steps;
        r.pmax.0 = r.pmax.0.max(z.pmax);
        r.pmax.1 = r.pmax.1.max(p.kernel.pmax);
        r.pmax.2 = r.pmax.2.max(p.norm.p_max);
        r.area.0 += z.area;
        r.area.1 += p.kernel.area;
        r.area.2 += p.norm.area;
    }
    r
}

fn ritz_config() -> RitzConfig<f64> {
    let mut c = RitzConfig::recommended();
    let env = |k: &str| std::env::var(k).ok().and_then(|v| v.parse::<f64>().ok());
    if let Some(v) = env("RITZ_MINW") {
        c.min_width = v;
    }
    if let Some(v) = env("RITZ_OUTER") {
        c.outer = v as u32;
    }
    if let Some(v) = env("RITZ_FD") {
        c.fd_step = v;
    }
    c
}

fn stats(e: &[f64]) -> (f64, f64, usize) {
    let a: Vec<f64> = e.iter().map(|x| x.abs()).collect();
    (
        a.iter().sum::<f64>() / a.len().max(1) as f64,
        a.iter().cloned().fold(0.0, f64::max),
        a.iter().filter(|x| **x > 0.10).count(),
    )
}

fn report(name: &str, rows: &[Row], txt: &mut String) -> [(f64, f64, usize); 4] {
    let e = |f: &dyn Fn(&Row) -> f64| rows.iter().map(f).collect::<Vec<_>>();
    let s = [
        stats(&e(&|r| r.pmax.0 / r.pmax.2 - 1.0)),
        stats(&e(&|r| r.area.0 / r.area.2 - 1.0)),
        stats(&e(&|r| r.pmax.1 / r.pmax.2 - 1.0)),
        stats(&e(&|r| r.area.1 / r.area.2 - 1.0)),
    ];
    writeln!(
        txt,
        "| {name} | {} | {:.2} / {:.2} ({}) | {:.2} / {:.2} ({}) | {:.2} / {:.2} ({}) | {:.2} / {:.2} ({}) | {:.0} / {:.0} |",
        rows.len(),
        100.0 * s[0].0, 100.0 * s[0].1, s[0].2,
        100.0 * s[1].0, 100.0 * s[1].1, s[1].2,
        100.0 * s[2].0, 100.0 * s[2].1, s[2].2,
        100.0 * s[3].0, 100.0 * s[3].1, s[3].2,
        1e3 * rows.iter().map(|r| r.secs).sum::<f64>() / rows.len() as f64,
        1e3 * rows.iter().map(|r| r.secs).fold(0.0, f64::max),
    )
    .unwrap();
    s
}

/// The strip model against NORM on the issue-17 sets, per wheel. Asserted (issue 17 targets):
/// mean |Δpmax| and mean |Δarea| ≤ 3 % on every set, every case within 10 %, every solve
/// converged. The transition shifts are checked against NORM at 0.1 mm elements: their small
/// secondary regions (≈ 3.4 mm wide) are resolved by 17 rows at 0.2 mm, whose edge rows alone
/// move NORM's area by 2–3 % (1360 mm dy 5.16 mm 40 kN: strip model −7.6 % against 0.2 mm,
/// −5.4 % against 0.1 mm). Table on stdout; `RITZ_SETS=sweep,band,trans,mb` selects sets,
/// `RITZ_DIAG=<label part>` prints the strips of matching cases beside NORM's rows,
/// `RITZ_MINW`, `RITZ_OUTER`, `RITZ_FD` override the configuration.
#[test]
fn strip_model_against_norm() {
    let (w, r) = tables().unwrap();
    let o = NormGridOptions::default();
    let fine = NormGridOptions {
        max_element: 0.1,
        ..o
    };
    let cfg = StripesConfig::recommended();
    let only = std::env::var("RITZ_SETS").unwrap_or_else(|_| "sweep,band,trans,mb".into());
    let mut sets: Vec<(&str, Vec<Row>)> = vec![];
    let sweep_rows = |cases: Vec<SweepCase>, o: &NormGridOptions| -> Vec<Row> {
        cases
            .iter()
            .map(|c| {
                let sol = solve_sweep_case(&w, &r, c, o).unwrap();
                rows_of(c.label.clone(), &sol, &Material::steel(), &cfg)
            })
            .collect()
    };
    if only.contains("sweep") {
        sets.push(("sweep", sweep_rows(sweep_cases(&SWEEP_LOADS).unwrap(), &o)));
    }
    if only.contains("band") {
        sets.push(("band", sweep_rows(band_cases(&w, &r), &o)));
    }
    if only.contains("trans") {
        let c = transition_cases(&SWEEP_LOADS, 6).unwrap();
        sets.push(("transition shifts (NORM 0.1 mm)", sweep_rows(c, &fine)));
    }
    if only.contains("mb") {
        let rows = mbench_rows()
            .unwrap()
            .iter()
            .map(|row| {
                let sol = solve_mbench_row(&w, &r, row, &o).unwrap();
                rows_of(row.label(), &sol, &mbench_material(), &cfg)
            })
            .collect();
        sets.push(("Manchester A-2.2", rows));
    }
    let mut txt = String::from(
        "| set | cases | strip model pmax mean / max % (> 10 %) | strip model area | STRIPES pmax | STRIPES area | strip model ms mean / max |\n|---|---|---|---|---|---|---|\n",
    );
    let mut worst = String::new();
    let mut fails = vec![];
    for (name, rows) in &sets {
        let s = report(name, rows, &mut txt);
        for (what, st) in [("pmax", s[0]), ("area", s[1])] {
            if st.0 > 0.03 || st.2 > 0 {
                fails.push(format!(
                    "{name}: {what} mean {:.2} % (≤ 3 %), {} cases beyond 10 %",
                    100.0 * st.0,
                    st.2
                ));
            }
        }
        for r in rows.iter().filter(|r| !r.converged) {
            fails.push(format!("{}: not converged", r.label));
        }
        let mut v: Vec<&Row> = rows.iter().collect();
        let err = |r: &Row| {
            (r.pmax.0 / r.pmax.2 - 1.0)
                .abs()
                .max((r.area.0 / r.area.2 - 1.0).abs())
        };
        v.sort_by(|a, b| err(b).partial_cmp(&err(a)).unwrap());
        for r in v.iter().take(4) {
            writeln!(
                worst,
                "{name}: {} pmax {:+.2} % (STRIPES {:+.2}) area {:+.2} % (STRIPES {:+.2}) strips {} qp steps {}",
                r.label,
                100.0 * (r.pmax.0 / r.pmax.2 - 1.0),
                100.0 * (r.pmax.1 / r.pmax.2 - 1.0),
                100.0 * (r.area.0 / r.area.2 - 1.0),
                100.0 * (r.area.1 / r.area.2 - 1.0),
                r.strips,
                r.qp,
            )
            .unwrap();
        }
    }
    println!("{txt}\n{worst}");
    assert!(fails.is_empty(), "{fails:#?}");
}
