//! Writes the S1002/UIC60 contact table of the C tests (1353 mm back-to-back, right wheel,
//! equilibrium roll, dy −11.8…11.8 mm every 0.5 mm refined to 1 % × 15–260 kN in 5 log-spaced
//! loads, 1 slot × 32 strips) to a file, for C programs (`wrc_table_check_*`, `wrc_step_*`; format: docs/ffi.md).
//!
//! Run: `cargo run --release -p wrc-ffi --example write_table -- OUT.wrct [f32]` (f64 unless `f32`).

use wrc_host_tests::realtime::{s1002_uic60_table, standard_spec};
use wrc_kernel::Real;

const K: usize = 3;
const ST: usize = 32;

fn table<T: Real>() -> Result<Vec<u8>, String> {
    let (out, rep) = s1002_uic60_table::<T, K, ST>(&standard_spec()).map_err(|e| e.to_string())?;
    eprintln!(
        "{} shift nodes, {} nodes solved ({} not converged), {} slots used, {} bytes",
        rep.dy_nodes, rep.nodes, rep.not_converged, rep.slots_used, rep.bytes
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
