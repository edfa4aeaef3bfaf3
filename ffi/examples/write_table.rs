//! Writes the S1002/UIC60 contact table of the C tests (1353 mm back-to-back, right wheel,
//! equilibrium roll, dy −8…4 mm every 0.25 mm × 15–260 kN in 5 log-spaced loads, 3 slots × 32
//! strips) to a file, for C programs (`wrc_table_check_*`, `wrc_step_*`; format: docs/ffi.md).
//!
//! Run: `cargo run --release -p wrc-ffi --example write_table -- OUT.wrct [f32]` (f64 unless `f32`).

use wrc_host_tests::profiles::{manchester_tables, SmoothOptions};
use wrc_kernel::geometry::{Side, TrackSetup};
use wrc_kernel::table::{build_table, table_bytes, TableSlot, TableSpec};
use wrc_kernel::wheel::{DefaultWheelWorkspace, WheelConfig};
use wrc_kernel::{Material, Real};

const K: usize = 3;
const ST: usize = 32;

fn table<T: Real>() -> Result<Vec<u8>, String> {
    let (w, r) = manchester_tables::<T>(&SmoothOptions::default()).map_err(|e| e.to_string())?;
    let spec = TableSpec {
        dy_min: T::from_f64(-8.0),
        dy_max: T::from_f64(4.0),
        n_dy: 49,
        f_min: T::from_f64(15_000.0),
        f_max: T::from_f64(260_000.0),
        n_load: 5,
        grid_step: T::from_f64(0.05),
        equilibrium_roll: true,
    };
    let setup = TrackSetup {
        back_to_back: T::from_f64(1353.0),
        ..TrackSetup::standard()
    };
    let mut out = vec![0u8; table_bytes::<T>(spec.n_dy, spec.n_load, K, ST)];
    let mut rows = vec![TableSlot::<T, ST>::EMPTY; 2 * K * spec.n_load];
    let mut ws = Box::new(DefaultWheelWorkspace::<T>::new());
    let speed = T::from_f64(100.0 / 3.6 * 1000.0);
    let cfg = WheelConfig::recommended(T::from_f64(0.3), speed, T::from_f64(460.0));
    let rep = build_table::<T, 2048, 2048, K, ST, 4, 128, 256, 4, 32, 32, 128>(
        &r,
        &w,
        &setup,
        Side::Right,
        &Material::steel(),
        &cfg,
        &spec,
        &mut rows,
        &mut ws,
        &mut out,
    )
    .map_err(|e| e.to_string())?;
    eprintln!(
        "{} nodes ({} not converged), {} slots used, {} bytes",
        rep.nodes, rep.not_converged, rep.slots_used, rep.bytes
    );
    Ok(out)
}

fn main() -> Result<(), String> {
    let mut args = std::env::args().skip(1);
    let path = args
        .next()
        .ok_or("usage: write_table OUT.wrct [f32]".to_string())?;
    let bytes = match args.next().as_deref() {
        Some("f32") => table::<f32>()?,
        None | Some("f64") => table::<f64>()?,
        Some(p) => return Err(format!("unknown precision {p}: f64 or f32")),
    };
    std::fs::write(&path, bytes).map_err(|e| format!("{path}: {e}"))
}
