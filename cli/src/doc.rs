//! The JSON document of `wrc solve --json` (contract: docs/cli.md). Field names and
//! meanings are fixed by the contract; add fields, never rename them.

use serde::Serialize;

/// Creepages of a patch (dimensionless ξ, η; spin φ in 1/mm).
#[derive(Clone, Copy, Debug, Default, Serialize, PartialEq)]
pub struct Creepage {
    /// Longitudinal creepage ξ.
    pub xi: f64,
    /// Lateral creepage η.
    pub eta: f64,
    /// Spin creepage φ, 1/mm.
    pub phi_per_mm: f64,
}

/// One contact patch.
#[derive(Clone, Debug, Default, Serialize, PartialEq)]
pub struct Patch {
    /// Reference point, lateral, in the rail profile file's coordinates (mm); 0 for elliptic cases.
    pub y_ref_mm: f64,
    /// Reference point, vertical, in the rail profile file's coordinates (mm); 0 for elliptic cases.
    pub z_ref_mm: f64,
    /// Contact angle of the region in the track frame (rad).
    pub contact_angle_rad: f64,
    /// Creepages used for this patch.
    pub creepage: Creepage,
    /// Normal approach (mm).
    pub approach_mm: f64,
    /// Normal force (N).
    pub fn_n: f64,
    /// Longitudinal creep force on the wheel (N).
    pub fx_n: f64,
    /// Lateral creep force on the wheel (N).
    pub fy_n: f64,
    /// Spin moment about the patch reference point (N·mm).
    pub mz_nmm: f64,
    /// Maximum pressure (MPa).
    pub pmax_mpa: f64,
    /// Contact area (mm²).
    pub area_mm2: f64,
    /// Extent along x in the contact-local frame (mm).
    pub x_extent_mm: [f64; 2],
    /// Extent along y in the contact-local frame (mm).
    pub y_extent_mm: [f64; 2],
    /// Fraction of the contact area in adhesion.
    pub stick_area_fraction: f64,
    /// Largest wear depth per passage over the strips (µm).
    pub wear_depth_max_um: f64,
}

/// Sums over all patches.
#[derive(Clone, Copy, Debug, Default, Serialize, PartialEq)]
pub struct Total {
    /// Normal force (N).
    pub fn_n: f64,
    /// Longitudinal force (N).
    pub fx_n: f64,
    /// Lateral force (N).
    pub fy_n: f64,
    /// Spin moment (N·mm), each patch about its own reference point.
    pub mz_nmm: f64,
}

/// Solver status.
#[derive(Clone, Debug, Default, Serialize, PartialEq)]
pub struct Status {
    /// Every iterative stage converged.
    pub converged: bool,
    /// Iterations of the outermost iterative stage.
    pub iterations: u32,
    /// Human-readable warnings (flagged results).
    pub warnings: Vec<String>,
}

/// The whole document.
#[derive(Clone, Debug, Serialize)]
pub struct Document {
    /// Every option as used, with defaults filled in.
    pub inputs: serde_json::Value,
    /// Patches.
    pub patches: Vec<Patch>,
    /// Totals.
    pub total: Total,
    /// Status.
    pub status: Status,
    /// Wall time of the kernel call alone, µs (median of a few repeats).
    pub time_us: f64,
}

impl Document {
    /// Builds the totals from the patches.
    pub fn new(
        inputs: serde_json::Value,
        patches: Vec<Patch>,
        status: Status,
        time_us: f64,
    ) -> Self {
        let mut total = Total::default();
        for p in &patches {
            total.fn_n += p.fn_n;
            total.fx_n += p.fx_n;
            total.fy_n += p.fy_n;
            total.mz_nmm += p.mz_nmm;
        }
        Self {
            inputs,
            patches,
            total,
            status,
            time_us,
        }
    }
}
