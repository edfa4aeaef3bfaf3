//! The contact table of the real-time examples and tests (`wrc_kernel::table`): built-in
//! S1002/UIC60, back-to-back 1353 mm, right wheel, the converged solver at μ 0.3 and 100 km/h
//! (zero creepage, so the table does not depend on them), on the host with heap scratch.

use wrc_kernel::geometry::{Side, TrackSetup};
use wrc_kernel::table::{build_table, BuildReport, TableSlot, TableSpec, ROW_BUFFERS};
use wrc_kernel::wheel::{DefaultWheelWorkspace, WheelConfig};
use wrc_kernel::{Error, Material, Real};

use crate::profiles::{manchester_tables, SmoothOptions};

/// Refinement tolerance of the examples' shift grid ([`TableSpec::refine_tol`]).
pub const REFINE_TOL: f64 = 0.01;
/// Most shift nodes of the examples' grid ([`TableSpec::max_dy_nodes`]).
pub const MAX_DY_NODES: usize = 71;

/// The examples' grid: equilibrium roll, dy −8 … 4 mm (+left), coarse nodes every 0.25 mm refined
/// to [`REFINE_TOL`] with at most [`MAX_DY_NODES`] shift nodes (71: the f32 3 × 16 table stays
/// within 256 KiB) × F 15 … 260 kN in 5 log-spaced loads, placement grid 0.05 mm.
pub fn standard_spec<T: Real>() -> TableSpec<T> {
    TableSpec {
        dy_min: T::from_f64(-8.0),
        dy_max: T::from_f64(4.0),
        n_dy: 49,
        f_min: T::from_f64(15_000.0),
        f_max: T::from_f64(260_000.0),
        n_load: 5,
        grid_step: T::from_f64(0.05),
        equilibrium_roll: true,
        refine_tol: T::from_f64(REFINE_TOL),
        max_dy_nodes: MAX_DY_NODES,
    }
}

/// The S1002/UIC60 1353 mm right-wheel table on `spec` with `K` slots × `ST` strips: its bytes
/// and the build report.
///
/// Errors: those of the profiles' tables (as `Error::BadProfile`) and of [`build_table`].
pub fn s1002_uic60_table<T: Real, const K: usize, const ST: usize>(
    spec: &TableSpec<T>,
) -> Result<(Vec<u8>, BuildReport), Error> {
    let (w, r) = manchester_tables::<T>(&SmoothOptions::default())
        .map_err(|_| Error::BadProfile("built-in S1002/UIC60 tables"))?;
    let setup = TrackSetup {
        back_to_back: T::from_f64(1353.0),
        ..TrackSetup::standard()
    };
    let mut out = vec![0u8; spec.capacity_bytes(K, ST)];
    let mut rows = vec![TableSlot::<T, ST>::EMPTY; ROW_BUFFERS * K * spec.n_load];
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
        spec,
        &mut rows,
        &mut ws,
        &mut out,
    )?;
    out.truncate(rep.bytes);
    Ok((out, rep))
}
