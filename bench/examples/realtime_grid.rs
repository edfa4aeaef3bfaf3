//! FaStrip defaults on coarser grids (strips × cells) against the TANG reference of the Hertzian
//! matrix, for choosing a real-time configuration: |ΔF|/(μF_n) median / P95 / max and |ΔM_z|/(μF_n c)
//! median / P95 per grid, as `study-hertz` measures the kernel default 32 × 32.
//!
//! Needs `out/hertz_matrix.csv` (the reference columns of a full `study-hertz` run, 23 min):
//! `cargo run --release -p wrc-bench --example realtime_grid`.
//!
//! Measured 2026-12-02 (3220 cases): 32 × 32 0.43 / 4.46 / 13.75 %, M_z 0.51 / 4.77 %;
//! 16 strips × 32 cells 0.38 / 4.47 / 13.64 %, 0.50 / 4.81 %; 32 × 16 0.53 / 6.40 / 15.73 %;
//! 16 × 16 0.53 / 6.34 / 14.84 %; 12 × 12 1.09 / 8.19 / 18.05 %: the strip count can be halved
//! at no loss on Hertz patches, the cell count cannot.
use wrc_kernel::fastrip::{fastrip, FastripSettings};
use wrc_kernel::patch::{Creepage, GridExtent, HertzPressure, StripPatch};
use wrc_kernel::Material;

const MU: f64 = 0.3;
const FN: f64 = 82_000.0;

fn run<const S: usize, const C: usize>(rows: &[[f64; 8]]) -> (f64, f64, f64, f64, f64) {
    let mat = Material::from_g_nu(82_000.0, 0.28).expect("mat");
    let mut df = vec![];
    let mut dm = vec![];
    for r in rows {
        let [a, b, xi, eta, phi, fx, fy, mz] = *r;
        let (patch, ell) =
            StripPatch::<f64, S, C>::hertz(a, b, FN, &mat, GridExtent::contact()).expect("patch");
        let t = fastrip(
            &patch,
            &HertzPressure(ell),
            &Creepage { xi, eta, phi },
            &FastripSettings::new(MU),
            &mut (),
        )
        .expect("fastrip")
        .total;
        let c = (a * b).sqrt();
        df.push((t.fx / (MU * FN) - fx).hypot(t.fy / (MU * FN) - fy));
        dm.push((t.mz / (MU * FN * c) - mz).abs());
    }
    df.sort_by(f64::total_cmp);
    dm.sort_by(f64::total_cmp);
    let n = df.len();
    (
        df[n / 2],
        df[n * 95 / 100],
        df[n - 1],
        dm[n / 2],
        dm[n * 95 / 100],
    )
}

fn main() {
    let txt = std::fs::read_to_string("out/hertz_matrix.csv").expect("csv");
    let mut lines = txt.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| head.iter().position(|h| *h == n).unwrap();
    let ix = ["a", "b", "xi", "eta", "phi", "ref_fx", "ref_fy", "ref_mz"].map(col);
    let rows: Vec<[f64; 8]> = lines
        .map(|l| {
            let v: Vec<&str> = l.split(',').collect();
            ix.map(|k| v[k].parse::<f64>().unwrap())
        })
        .collect();
    let p = |name: &str, r: (f64, f64, f64, f64, f64)| {
        println!(
            "{name}: dF median {:.2} % P95 {:.2} % max {:.2} %; dMz median {:.2} % P95 {:.2} %",
            100.0 * r.0,
            100.0 * r.1,
            100.0 * r.2,
            100.0 * r.3,
            100.0 * r.4
        )
    };
    println!("{} cases", rows.len());
    p("32x32", run::<32, 32>(&rows));
    p("24x24", run::<24, 24>(&rows));
    p("16x32 (strips x cells)", run::<16, 32>(&rows));
    p("32x16", run::<32, 16>(&rows));
    p("16x16", run::<16, 16>(&rows));
    p("12x12", run::<12, 12>(&rows));
}
