//! Shared set-ups of the elliptic-core validation (CONTACT's examples, methods.md §10).

use wrc_kernel::patch::{CellOut, CellSink, Ellipse, GridExtent, StripPatch};
use wrc_kernel::stripes::StripSample;
use wrc_kernel::{Material, Real};

/// CONTACT's material in its examples: G = 82 000 MPa, ν = 0.28.
pub fn contact_material<T: Real>() -> Material<T> {
    Material::from_g_nu(T::from_f64(82_000.0), T::from_f64(0.28)).expect("valid material")
}

/// CONTACT's `fastsim` example (§10.4): a = 8, b = 4 mm, N = 82 kN on the ±1.1a × ±1.1b grid.
pub fn a8b4<T: Real, const S: usize, const C: usize>() -> (StripPatch<T, S, C>, Ellipse<T>) {
    StripPatch::hertz(
        T::from_f64(8.0),
        T::from_f64(4.0),
        T::from_f64(82_000.0),
        &contact_material(),
        GridExtent::contact(),
    )
    .expect("valid patch")
}

/// A heap-backed full-field sink: (strip, cell, result) of every contact cell.
#[derive(Default, Debug)]
pub struct VecSink<T>(pub Vec<(usize, usize, CellOut<T>)>);

impl<T: Copy> CellSink<T> for VecSink<T> {
    fn cell(&mut self, j: usize, i: usize, out: &CellOut<T>) {
        self.0.push((j, i, *out));
    }
}

/// A Hertzian gap for STRIPES and the strip model: z = B y² + 0.3 mm on samples of width `dy`
/// over ±`half` (mm), constant curvatures A = `ca`, B = `cb` (1/mm), no yaw.
pub fn hertz_gap(ca: f64, cb: f64, half: f64, dy: f64) -> Vec<StripSample<f64>> {
    let n = (2.0 * half / dy).round() as usize;
    (0..n)
        .map(|i| {
            let y = -half + (i as f64 + 0.5) * dy;
            StripSample {
                y,
                dy,
                z: cb * y * y + 0.3,
                curv_a: ca,
                curv_b: cb,
                xc: 0.0,
            }
        })
        .collect()
}
