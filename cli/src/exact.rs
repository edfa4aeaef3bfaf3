//! `--tangential exact`: Kalker's exact steady-rolling theory (the host reference TANG,
//! `wrc_host_tests::tang`) on the normal solution of the case.
//!
//! Elliptic cases: the grid is CONTACT's potential-contact grid over ±1.1a × ±1.1b with `--cells`
//! × `--strips` elements; the pressure is Hertz's at the element centres (rescaled so that
//! δxδyΣp_n = F_n, `--normal hertz`) or NORM's on the same grid (`--normal norm`). TANG runs in f64
//! whatever `--precision` says (a host reference; a warning says so for f32). Wear: the KTH map of
//! `wrc_host_tests::wear_ref` on TANG's slip (the same law as the kernel's), per grid row.

use crate::doc::{sort_by_x, y0_strip, Creepage as DocCreepage, Patch, Status, StripOut, Y0Cell};
use crate::sink::PlotCell;
use wrc_host_tests::norm::NormSolution;
use wrc_host_tests::tang::{
    hertz_pressure, Creepage, ElementState, Grid, TangOptions, TangSolution, TangSolver,
};
use wrc_host_tests::wear_ref::{element_wear, strip_wear, WearMap};
use wrc_kernel::Material;

/// What an exact solve reports for the JSON document and the plots.
pub struct ExactPatch {
    /// The JSON patch.
    pub patch: Patch,
    /// Status (converged, Gauss–Seidel sweeps).
    pub status: Status,
    /// Wall time of the TANG solve, µs (one run: the reference is too slow to repeat).
    pub time_us: f64,
    /// Cells for plots (empty unless asked for).
    pub cells: Vec<PlotCell>,
    /// (y, wear depth µm) per grid row with contact.
    pub wear_strips: Vec<(f64, f64)>,
}

/// The TANG grid of an elliptic case: `mx` × `my` elements over ±1.1a × ±1.1b, mm.
pub fn elliptic_grid(a: f64, b: f64, mx: usize, my: usize) -> Grid {
    Grid {
        mx,
        my,
        dx: 2.2 * a / mx as f64,
        dy: 2.2 * b / my as f64,
        x0: -1.1 * a,
        y0: -1.1 * b,
    }
}

/// The Hertz pressure at the element centres of `grid` (rescaled to F_n), MPa.
pub fn hertz_on(grid: &Grid, a: f64, b: f64, fn_: f64) -> Vec<f64> {
    hertz_pressure(grid, a, b, fn_, true)
}

/// Half-length of every row of `grid` from the Hertz ellipse a × b: a √(1 − (y_j/b)²), 0 outside.
pub fn hertz_half_lengths(grid: &Grid, a: f64, b: f64) -> Vec<f64> {
    (0..grid.my)
        .map(|j| {
            let q = 1.0 - (grid.y(j) / b).powi(2);
            if q > 0.0 {
                a * q.sqrt()
            } else {
                0.0
            }
        })
        .collect()
}

/// Half-length of every row of NORM's grid: half the length of its contact runs (Σ over runs of
/// (x_lead − x_trail)/2, NORM's interpolated edges).
pub fn norm_half_lengths(sol: &NormSolution) -> Vec<f64> {
    (0..sol.grid.my)
        .map(|j| {
            sol.strips
                .get(j)
                .map(|st| st.runs.iter().map(|r| 0.5 * (r.x_lead - r.x_trail)).sum())
                .unwrap_or(0.0)
        })
        .collect()
}

/// `strips` and `y0` of a TANG solution on pressure `pn`: one strip per grid row with a contact
/// element, at the row centre, half-length `half_lengths[j]`; normal load and forces δxδy Σ over
/// the row (they sum to TANG's F_n, F_x, F_y), wear the KTH depth of the row
/// (`wrc_host_tests::wear_ref::strip_wear`, speed `speed_mm_s`). `y0`: the row through y = 0
/// ([`crate::doc::y0_strip`] over the rows with contact), its contact elements with the slip
/// velocity V·|s| (mm/s; 0 in adhesion).
pub fn tang_strips(
    sol: &TangSolution,
    pn: &[f64],
    speed_mm_s: f64,
    half_lengths: &[f64],
) -> (Vec<StripOut>, Vec<Y0Cell>) {
    let g = sol.grid;
    let depth = strip_wear(&WearMap::default(), sol, pn, speed_mm_s);
    let area = g.area();
    let rows: Vec<usize> = (0..g.my)
        .filter(|&j| (0..g.mx).any(|i| sol.state[g.idx(i, j)] != ElementState::Exterior))
        .collect();
    let strips = rows
        .iter()
        .map(|&j| {
            let (mut f_n, mut fx, mut fy) = (0.0, 0.0, 0.0);
            for i in 0..g.mx {
                let k = g.idx(i, j);
                f_n += pn[k];
                fx += sol.px[k];
                fy += sol.py[k];
            }
            StripOut {
                y_mm: g.y(j),
                half_length_mm: half_lengths.get(j).copied().unwrap_or(0.0),
                width_mm: g.dy,
                fn_n: f_n * area,
                fx_n: fx * area,
                fy_n: fy * area,
                wear_depth_um: depth[j] * 1e3,
            }
        })
        .collect();
    let mut y0 = vec![];
    if let Some(r) = y0_strip(rows.iter().map(|&j| (g.y(j), g.dy))) {
        let j = rows[r];
        for i in 0..g.mx {
            let k = g.idx(i, j);
            if sol.state[k] == ElementState::Exterior {
                continue;
            }
            y0.push(Y0Cell {
                x_mm: g.x(i),
                pn_mpa: pn[k],
                px_mpa: sol.px[k],
                py_mpa: sol.py[k],
                slip_velocity_mm_s: if sol.state[k] == ElementState::Slip {
                    speed_mm_s * sol.sx[k].hypot(sol.sy[k])
                } else {
                    0.0
                },
            });
        }
    }
    sort_by_x(&mut y0);
    (strips, y0)
}

/// Runs TANG on `pn` (MPa, grid order) for creepages `cr`, friction `mu`, material `mat`, rolling
/// speed `speed_mm_s` (slip velocity, wear) and fills the JSON patch (normal fields from `normal`,
/// row half-lengths `half_lengths` for `strips`).
#[allow(clippy::too_many_arguments)]
pub fn solve(
    grid: Grid,
    pn: &[f64],
    cr: Creepage,
    mu: f64,
    mat: &Material<f64>,
    speed_mm_s: f64,
    normal: NormalFields,
    half_lengths: &[f64],
    keep_cells: bool,
) -> ExactPatch {
    let t0 = std::time::Instant::now();
    let solver = TangSolver::new(grid, mat.g, mat.nu);
    let sol = solver.solve(pn, mu, cr, &TangOptions::default(), None);
    let time_us = t0.elapsed().as_secs_f64() * 1e6;
    let map = WearMap::default();
    let wear = element_wear(&map, &sol, pn, speed_mm_s);
    let (strips, y0) = tang_strips(&sol, pn, speed_mm_s, half_lengths);
    let wear_strips: Vec<(f64, f64)> = strips.iter().map(|s| (s.y_mm, s.wear_depth_um)).collect();
    let mut stick = 0usize;
    let mut cells = vec![];
    for j in 0..grid.my {
        for i in 0..grid.mx {
            let k = grid.idx(i, j);
            if sol.state[k] == ElementState::Exterior {
                continue;
            }
            if sol.state[k] == ElementState::Adhesion {
                stick += 1;
            }
            if keep_cells {
                cells.push(PlotCell {
                    x: grid.x(i),
                    y: grid.y(j),
                    pn: pn[k],
                    px: sol.px[k],
                    py: sol.py[k],
                    slip: sol.state[k] == ElementState::Slip,
                    vs: speed_mm_s * sol.sx[k].hypot(sol.sy[k]) * 1e-3,
                    wear_um: wear[k] * 1e3,
                });
            }
        }
    }
    let wear_max = wear_strips.iter().map(|w| w.1).fold(0.0, f64::max);
    let patch = Patch {
        y_ref_mm: 0.0,
        z_ref_mm: 0.0,
        contact_angle_rad: 0.0,
        creepage: DocCreepage {
            xi: cr.xi,
            eta: cr.eta,
            phi_per_mm: cr.phi,
        },
        approach_mm: normal.approach_mm,
        fn_n: sol.fn_,
        fx_n: sol.fx,
        fy_n: sol.fy,
        mz_nmm: sol.mz,
        pmax_mpa: normal.pmax_mpa,
        area_mm2: normal.area_mm2,
        x_extent_mm: normal.x_extent_mm,
        y_extent_mm: normal.y_extent_mm,
        stick_area_fraction: if sol.n_contact > 0 {
            stick as f64 / sol.n_contact as f64
        } else {
            0.0
        },
        wear_depth_max_um: wear_max,
        strips,
        y0,
    };
    let mut warnings = vec![];
    if !sol.converged {
        warnings.push(format!(
            "TANG did not converge in {} sweeps (estimated error {:.1e})",
            sol.sweeps, sol.error_estimate
        ));
    }
    ExactPatch {
        patch,
        status: Status {
            path: "elliptic",
            converged: sol.converged,
            iterations: sol.sweeps as u32,
            warnings,
        },
        time_us,
        cells,
        wear_strips,
    }
}

/// The normal-contact fields of the JSON patch (from Hertz or NORM).
#[derive(Clone, Copy, Debug)]
pub struct NormalFields {
    /// Approach, mm.
    pub approach_mm: f64,
    /// Peak pressure, MPa.
    pub pmax_mpa: f64,
    /// Contact area, mm².
    pub area_mm2: f64,
    /// x extent, mm.
    pub x_extent_mm: [f64; 2],
    /// y extent, mm.
    pub y_extent_mm: [f64; 2],
}
