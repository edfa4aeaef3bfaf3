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
    /// One entry per strip of the tangential grid with contact, in order of `y_mm`.
    pub strips: Vec<StripOut>,
    /// The cells of the strip through the reference point (y = 0), in order of x.
    pub y0: Vec<Y0Cell>,
}

/// One strip of a patch's tangential grid (docs/cli.md, "JSON document").
#[derive(Clone, Copy, Debug, Default, Serialize, PartialEq)]
pub struct StripOut {
    /// Strip centre, lateral, in the patch's contact-local frame (mm).
    pub y_mm: f64,
    /// Half-length a_j of the strip's contact along x (mm).
    pub half_length_mm: f64,
    /// Width δy_j of the strip (mm): forces per unit width are `fx_n / width_mm`, comparable
    /// between strip layouts.
    pub width_mm: f64,
    /// Normal load of the strip (N); the strips sum to the patch's `fn_n`.
    pub fn_n: f64,
    /// Longitudinal traction force of the strip on the wheel (N).
    pub fx_n: f64,
    /// Lateral traction force of the strip on the wheel (N).
    pub fy_n: f64,
    /// KTH wear depth of the strip per passage (µm).
    pub wear_depth_um: f64,
}

/// One cell of the strip through the reference point (docs/cli.md, "JSON document").
#[derive(Clone, Copy, Debug, Default, Serialize, PartialEq)]
pub struct Y0Cell {
    /// Cell centre along x, contact-local frame (mm).
    pub x_mm: f64,
    /// Normal pressure p_n (MPa).
    pub pn_mpa: f64,
    /// Traction p_x on the wheel (MPa).
    pub px_mpa: f64,
    /// Traction p_y on the wheel (MPa).
    pub py_mpa: f64,
    /// Magnitude of the slip velocity |s|·V (mm/s), 0 in adhesion.
    pub slip_velocity_mm_s: f64,
}

/// Index of the strip through y = 0 among strips given as (centre, width): the first whose
/// half-open range [y − δy/2, y + δy/2) contains 0, else the one whose centre is nearest to 0.
/// `None` for no strips.
pub fn y0_strip(strips: impl Iterator<Item = (f64, f64)>) -> Option<usize> {
    let mut nearest: Option<(usize, f64)> = None;
    for (j, (y, dy)) in strips.enumerate() {
        if y - 0.5 * dy <= 0.0 && 0.0 < y + 0.5 * dy {
            return Some(j);
        }
        if nearest.is_none_or(|(_, d)| y.abs() < d) {
            nearest = Some((j, y.abs()));
        }
    }
    nearest.map(|n| n.0)
}

/// Sorts y0 cells by x.
pub fn sort_by_x(cells: &mut [Y0Cell]) {
    cells.sort_by(|a, b| a.x_mm.total_cmp(&b.x_mm));
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
    /// Which computation ran: `"converged"` (a wheel/rail case through the iterative per-wheel
    /// solve, with whatever normal and tangential models), `"realtime"` (the fixed-cost step on a
    /// contact table, `--table`) or `"elliptic"` (an elliptic case).
    pub path: &'static str,
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
