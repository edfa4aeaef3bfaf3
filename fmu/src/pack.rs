//! The packaged contact table and the `.fmu` archive (used by the `wrc-fmu-pack` binary).
//!
//! The table is the one `wrc table --back-to-back 1353 --equilibrium-roll --out table.bin`
//! writes: built-in S1002 wheel / UIC60 rail, right wheel, f64, shift −11.8 … 11.8 mm (the
//! default: both flange contacts, found from the profiles, and 2 mm), coarse nodes every 0.5 mm
//! refined to 1 % (at most 176 shift nodes), F_z 15 … 260 kN in 5 log-spaced loads, up to 3
//! slots (1 used) × 16 strips, steel
//! (E 205 900 MPa, ν 0.28), gauge 1435 mm, gauge depth 14 mm, no cant, r0 460 mm — the same
//! kernel call with the same arguments as `cli/src/realtime.rs`.

use std::io::Write as _;
use std::path::Path;
use wrc_host_tests::profiles::{
    build_table_from_text, SmoothOptions, S1002_NAME, S1002_PRW, UIC60_NAME, UIC60_PRR,
};
use wrc_kernel::geometry::{Side, TrackSetup};
use wrc_kernel::profile::{ProfileKind, ProfileTable};
use wrc_kernel::table::{build_table, BuildReport, TableSlot, TableSpec, ROW_BUFFERS};
use wrc_kernel::wheel::{DefaultWheelWorkspace, WheelConfig};
use wrc_kernel::Material;

/// Profile capacity (nodes), as the command line's.
pub const NODES: usize = 2048;
/// Strips per slot of the packaged table (as `wrc table`).
pub const STRIPS: usize = 16;
/// Back-to-back distance of the packaged table, mm.
pub const BACK_TO_BACK: f64 = 1353.0;

fn profile(kind: ProfileKind) -> Result<Box<ProfileTable<f64, NODES>>, String> {
    let (text, name) = match kind {
        ProfileKind::Wheel => (S1002_PRW, S1002_NAME),
        ProfileKind::Rail => (UIC60_PRR, UIC60_NAME),
    };
    build_table_from_text::<f64, NODES>(
        text,
        Path::new(name),
        Some(kind),
        &SmoothOptions::default(),
    )
    .map_err(|e| e.to_string())
}

/// Builds the packaged table (module docs): its bytes and the build report.
pub fn default_table() -> Result<(Vec<u8>, BuildReport), String> {
    let wheel = profile(ProfileKind::Wheel)?;
    let rail = profile(ProfileKind::Rail)?;
    // `wrc table` defaults for this pair: the flange contacts at 9.8 mm and 2 mm more.
    let (dy_from, dy_to, dy_step): (f64, f64, f64) = (-11.8, 11.8, 0.5);
    let spec = TableSpec {
        dy_min: -dy_to,
        dy_max: -dy_from,
        n_dy: ((dy_to - dy_from) / dy_step).round() as usize + 1,
        f_min: 15_000.0,
        f_max: 260_000.0,
        n_load: 5,
        grid_step: 0.05,
        equilibrium_roll: true,
        // `wrc table`'s defaults (--refine-tol, --max-dy-nodes)
        refine_tol: 0.01,
        max_dy_nodes: 176,
    };
    let setup = TrackSetup {
        gauge: 1435.0,
        gauge_depth: 14.0,
        back_to_back: BACK_TO_BACK,
        cant: 0.0,
        r0: 460.0,
        ..TrackSetup::standard()
    };
    let mat = Material::<f64>::identical(205_900.0, 0.28).map_err(|e| e.to_string())?;
    let cfg = WheelConfig::recommended(0.3, 200.0 / 3.6 * 1e3, setup.r0);
    let k = crate::model::SLOTS;
    let mut out = vec![0u8; spec.capacity_bytes(k, STRIPS)];
    let mut rows = vec![TableSlot::<f64, STRIPS>::EMPTY; ROW_BUFFERS * k * spec.n_load];
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let rep = build_table::<f64, NODES, NODES, 3, STRIPS, 4, 128, 256, 4, 32, 32, 128>(
        &rail,
        &wheel,
        &setup,
        Side::Right,
        &mat,
        &cfg,
        &spec,
        &mut rows,
        &mut ws,
        &mut out,
    )
    .map_err(|e| format!("table build: {e}"))?;
    out.truncate(rep.bytes);
    Ok((out, rep))
}

/// Writes the `.fmu` archive to `out`: `modelDescription.xml`, `binaries/linux64/wrc.so`
/// (the bytes `library`) and `resources/table.bin` (`table`), entries stored uncompressed.
pub fn write_fmu(out: &Path, library: &[u8], table: &[u8]) -> Result<(), String> {
    let file = std::fs::File::create(out).map_err(|e| format!("{}: {e}", out.display()))?;
    let mut z = zip::ZipWriter::new(file);
    let opts = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Stored)
        .unix_permissions(0o644);
    let md = crate::xml::model_description();
    let so = format!("binaries/linux64/{}.so", crate::xml::MODEL_IDENTIFIER);
    for (name, bytes, mode) in [
        ("modelDescription.xml", md.as_bytes(), 0o644),
        (so.as_str(), library, 0o755),
        ("resources/table.bin", table, 0o644),
    ] {
        z.start_file(name, opts.unix_permissions(mode))
            .map_err(|e| format!("{name}: {e}"))?;
        z.write_all(bytes).map_err(|e| format!("{name}: {e}"))?;
    }
    z.finish().map_err(|e| format!("{}: {e}", out.display()))?;
    Ok(())
}
