//! NORM — Kalker's boundary-element solution of the frictionless normal contact of two quasi-identical
//! elastic half-spaces (methods.md §9.1), the host-side reference for the kernel's normal models and
//! the pressure source for FASTSIM/FaStrip in host tests.
//!
//! * Unknowns: a uniform pressure p_I (MPa) on each rectangular element of a [`Grid`]; normal
//!   displacement difference at element centres u = A p with Love's coefficients
//!   ([`crate::influence::Elements::a_zz`]).
//! * Undeformed gap h_I (mm) at the element centres: any function or array (Hertzian A x² + B y²,
//!   synthetic non-Hertzian gaps, the wheel/rail gap f_n(y) + A(y) x² of methods.md §7.3). h is the
//!   gap *without* the approach; the approach δ (mm, positive = bodies pressed together) enters the
//!   deformed gap e_I = h_I − δ + u_I.
//! * Complementarity: e ≥ 0, p ≥ 0, e·p = 0 elementwise.
//! * Control: [`Control::Load`] (total normal force F_n = δxδy Σ p prescribed, δ is an output) or
//!   [`Control::Penetration`] (δ prescribed, F_n an output).
//! * Solvers: [`Method::ConjugateGradient`] (default, "solver B": Polonsky–Keer bound-constrained
//!   CG with FFT products, [`crate::fftconv::ToeplitzConv`]) and [`Method::ActiveSet`] ("solver A":
//!   Kalker's exact active-set iteration with a dense Cholesky factorisation, for small grids, as a
//!   check of the FFT path).
//!
//! Use [`solve`] for a one-off solve, [`Norm`] to solve repeatedly on one grid (the influence
//! spectrum is set up once), and [`solve_auto`] to let the grid follow the contact patch.

mod cg;
mod direct;
mod grid;

pub use grid::{Grid, Window};

use crate::fftconv::ToeplitzConv;
use crate::influence::Elements;
use wrc_kernel::{Error, Material};

/// What is prescribed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Control {
    /// Total normal force F_n (N, > 0) prescribed; the approach δ is solved for.
    Load(f64),
    /// Approach δ (mm) prescribed; the force follows. δ ≤ min h gives no contact (a valid result with
    /// zero pressure).
    Penetration(f64),
}

/// Which solver.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Polonsky–Keer bound-constrained conjugate gradients with FFT products (methods.md §9.1
    /// solver B). Cost per iteration: two FFT convolutions of size (2m_x)(2m_y).
    ConjugateGradient,
    /// Kalker's active-set iteration with a dense Cholesky solve on the contact set (methods.md §9.1
    /// solver A). Cost O(n_c³) per iteration: small grids only (a few hundred contact elements).
    ActiveSet,
}

/// Solver options.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// Solver.
    pub method: Method,
    /// CG: target relative accuracy of the pressures. The iteration stops when the relative
    /// update, max(δxδy Σ|p − p_old| / F_n, max|p − p_old| / p_max), falls below `tol`/10 (methods.md
    /// §9.1 stops at the first measure < ε; an iterate's error was measured at 1–3× its last update,
    /// so the factor 1/10 makes `tol` the accuracy reached, checked against the direct solver).
    /// Under penetration control F_n is the current force.
    pub tol: f64,
    /// Iteration cap (CG iterations, or active-set updates). Hitting it gives `converged = false`.
    pub max_iter: usize,
}

impl Default for Options {
    /// CG, tol = 1e-10, at most 2000 iterations.
    fn default() -> Self {
        Self {
            method: Method::ConjugateGradient,
            tol: 1e-10,
            max_iter: 2000,
        }
    }
}

impl Options {
    /// The direct active-set solver with an iteration cap of 100 updates.
    pub fn active_set() -> Self {
        Self {
            method: Method::ActiveSet,
            tol: 0.0,
            max_iter: 100,
        }
    }
}

/// One run of consecutive contact elements in a strip (grid row).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Run {
    /// First contact column (trailing side).
    pub i_first: usize,
    /// Last contact column (leading side), inclusive.
    pub i_last: usize,
    /// Trailing edge x_trail = x_{i_first} − δx/2, mm.
    pub x_trail: f64,
    /// Leading edge x_lead = x_{i_last} + δx/2, mm.
    pub x_lead: f64,
    /// Run force per unit width δx Σ p over the run, N/mm.
    pub force_per_width: f64,
}

/// Per-strip data (one grid row j), as FASTSIM/FaStrip consume it (methods.md §0.3).
#[derive(Clone, Debug, PartialEq)]
pub struct Strip {
    /// Row index j.
    pub j: usize,
    /// Strip centre y_j, mm.
    pub y: f64,
    /// Strip force per unit width f_j = δx Σ_i p_ij, N/mm (strip force = f_j δy).
    pub force_per_width: f64,
    /// Maximum element pressure in the strip, MPa.
    pub p_max: f64,
    /// Contact runs from trailing to leading edge (empty: strip not in contact).
    pub runs: Vec<Run>,
}

/// Result of a NORM solve: plain data.
#[derive(Clone, Debug, PartialEq)]
pub struct NormSolution {
    /// The grid.
    pub grid: Grid,
    /// Element pressures p_I ≥ 0, MPa (row-major, `j * mx + i`).
    pub pressure: Vec<f64>,
    /// Deformed gap e_I = h_I − δ + u_I, mm (≈ 0 in contact, ≥ 0 outside).
    pub deformed_gap: Vec<f64>,
    /// Contact set: p_I > 0.
    pub contact: Vec<bool>,
    /// Total normal force F_n = δxδy Σ p, N.
    pub force: f64,
    /// Approach δ, mm (prescribed, or under load control the mean of h + u over the contact set).
    pub approach: f64,
    /// Maximum element pressure, MPa.
    pub p_max: f64,
    /// Centre (x, y) of the element carrying `p_max`, mm.
    pub p_max_at: (f64, f64),
    /// Number of contact elements.
    pub n_contact: usize,
    /// Contact area n_contact·δxδy, mm².
    pub area: f64,
    /// Patch extent along x over element edges (x_min, x_max), mm; `None` without contact.
    pub extent_x: Option<(f64, f64)>,
    /// Patch extent along y over element edges (y_min, y_max), mm; `None` without contact.
    pub extent_y: Option<(f64, f64)>,
    /// One entry per grid row.
    pub strips: Vec<Strip>,
    /// Iterations used (CG iterations or active-set updates).
    pub iterations: usize,
    /// Whether the stopping criterion was met within the cap.
    pub converged: bool,
    /// Complementarity residual max_I [max(−e_I, 0) + |e_I|·(p_I > 0)] / (δ − min h)
    /// (dimensionless; 0 for an exact discrete solution; 0 without contact).
    pub complementarity: f64,
    /// A contact element lies on the grid's outer ring: the grid may be too small.
    pub touches_boundary: bool,
}

impl NormSolution {
    /// Pressure of element (i, j), MPa.
    pub fn p(&self, i: usize, j: usize) -> f64 {
        self.pressure[self.grid.index(i, j)]
    }
}

/// The NORM operator on one grid: influence coefficients and their FFT set up once.
#[derive(Debug)]
pub struct Norm {
    grid: Grid,
    material: Material<f64>,
    conv: ToeplitzConv,
}

impl Norm {
    /// Sets up Love's coefficients A_zz (methods.md §9.1) on the grid for the combined material.
    pub fn new(grid: Grid, material: Material<f64>) -> Result<Self, Error> {
        let grid = Grid::new(grid.mx, grid.my, grid.dx, grid.dy, grid.x0, grid.y0)?;
        if !(material.g.is_finite() && material.nu.is_finite()) {
            return Err(Error::NonFinite("material"));
        }
        if material.g <= 0.0 {
            return Err(Error::NonPositive("G"));
        }
        if !(0.0..0.5).contains(&material.nu) {
            return Err(Error::OutOfRange("nu"));
        }
        let el = Elements {
            g: material.g,
            nu: material.nu,
            dx: grid.dx,
            dy: grid.dy,
        };
        let conv = ToeplitzConv::new(grid.mx, grid.my, |di, dj| {
            el.a_zz(di as f64 * grid.dx, dj as f64 * grid.dy)
        });
        Ok(Self {
            grid,
            material,
            conv,
        })
    }

    /// The grid.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// The material.
    pub fn material(&self) -> &Material<f64> {
        &self.material
    }

    /// u = A p (FFT), mm, for element pressures p (MPa).
    pub fn displacement(&mut self, p: &[f64]) -> Vec<f64> {
        let mut u = vec![0.0; self.grid.len()];
        self.conv.apply(p, &mut u);
        u
    }

    /// Solves the normal problem for the undeformed gap `gap` (mm, at element centres, row-major).
    ///
    /// Errors: wrong length or non-finite gap, non-positive or non-finite load, non-finite approach,
    /// invalid options.
    pub fn solve(
        &mut self,
        gap: &[f64],
        control: Control,
        opts: &Options,
    ) -> Result<NormSolution, Error> {
        if gap.len() != self.grid.len() {
            return Err(Error::OutOfRange("gap length"));
        }
        if gap.iter().any(|v| !v.is_finite()) {
            return Err(Error::NonFinite("gap"));
        }
        match control {
            Control::Load(f) => {
                if !f.is_finite() {
                    return Err(Error::NonFinite("normal force"));
                }
                if f <= 0.0 {
                    return Err(Error::NonPositive("normal force"));
                }
            }
            Control::Penetration(d) => {
                if !d.is_finite() {
                    return Err(Error::NonFinite("approach"));
                }
            }
        }
        if opts.max_iter == 0 {
            return Err(Error::OutOfRange("max_iter"));
        }
        if opts.method == Method::ConjugateGradient && !(opts.tol.is_finite() && opts.tol > 0.0) {
            return Err(Error::OutOfRange("tol"));
        }
        let raw = match opts.method {
            Method::ConjugateGradient => cg::solve(&mut self.conv, &self.grid, gap, control, opts),
            Method::ActiveSet => direct::solve(&mut self.conv, &self.grid, gap, control, opts),
        };
        Ok(finish(&self.grid, gap, raw))
    }
}

/// One-off solve on `grid` (see [`Norm::solve`]).
pub fn solve(
    grid: &Grid,
    gap: &[f64],
    material: &Material<f64>,
    control: Control,
    opts: &Options,
) -> Result<NormSolution, Error> {
    Norm::new(*grid, *material)?.solve(gap, control, opts)
}

/// Settings of [`solve_auto`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AutoGrid {
    /// Target number of elements per semi-extent of the contact patch (along x and y).
    pub per_semi_axis: usize,
    /// Extra grid width beyond the patch, as a fraction of the patch semi-extents (plus one element).
    pub margin: f64,
    /// Square elements (δx = δy = the smaller of the two sizes), as CONTACT uses on wheel/rail.
    pub square: bool,
}

impl Default for AutoGrid {
    /// 20 elements per semi-axis, 15 % margin, rectangular elements.
    fn default() -> Self {
        Self {
            per_semi_axis: 20,
            margin: 0.15,
            square: false,
        }
    }
}

/// Solves with a grid that follows the contact patch.
///
/// 1. A first grid: under penetration control over {h < δ} ([`Grid::over_gap_level`]); under load
///    control 48 × 48 elements over the whole search window.
/// 2. Up to 6 refinements: the next grid is [`Grid::over_box`] of the current patch extents with
///    `auto.per_semi_axis` elements per semi-extent. A solution is accepted when its contact does not
///    touch the grid's outer ring and its patch spans at least `per_semi_axis − 1` elements per
///    semi-extent on the grid it was solved on (so the grid matches the patch it produced).
///
/// The gap function h(x, y) (mm) is the undeformed gap without the approach. Errors: as
/// [`Norm::solve`]; [`Error::NoContact`] under penetration control if h ≥ δ everywhere in the window;
/// [`Error::OutOfRange`] if the patch reaches the window's edge; the last solution is returned with
/// `converged = false` if no grid was accepted.
pub fn solve_auto(
    h: impl Fn(f64, f64) -> f64,
    window: Window,
    material: &Material<f64>,
    control: Control,
    auto: AutoGrid,
    opts: &Options,
) -> Result<NormSolution, Error> {
    if auto.per_semi_axis < 2 {
        return Err(Error::GridTooSmall("per_semi_axis"));
    }
    let mut grid = match control {
        Control::Penetration(d) => Grid::over_gap_level(&h, window, d, 8, 0.1, auto.square)?,
        Control::Load(_) => Grid::covering(window, 48, 48)?,
    };
    let first = grid;
    let mut sol = solve(&grid, &grid.sample(&h), material, control, opts)?;
    let mut margin = auto.margin;
    for _ in 0..6 {
        let (Some((xl, xh)), Some((yl, yh))) = (sol.extent_x, sol.extent_y) else {
            return Err(Error::NoContact);
        };
        if grid == first && sol.touches_boundary && matches!(control, Control::Load(_)) {
            // The first load-controlled grid is the whole search window.
            return Err(Error::OutOfRange("window (contact reaches its edge)"));
        }
        let n = auto.per_semi_axis as f64;
        let resolved = 0.5 * (xh - xl) / grid.dx >= n - 1.0 - 1e-9
            && 0.5 * (yh - yl) / grid.dy >= n - 1.0 - 1e-9;
        if !sol.touches_boundary && resolved && grid != first {
            return Ok(sol);
        }
        if sol.touches_boundary && grid != first {
            margin = 2.0 * margin + 0.1;
        }
        let b = if sol.touches_boundary {
            // Grow the box beyond the current grid where the patch touches it.
            let w = grid.window();
            Window {
                x_lo: if xl <= w.x_lo + 0.5 * grid.dx {
                    xl - 0.5 * (xh - xl)
                } else {
                    xl
                },
                x_hi: if xh >= w.x_hi - 0.5 * grid.dx {
                    xh + 0.5 * (xh - xl)
                } else {
                    xh
                },
                y_lo: if yl <= w.y_lo + 0.5 * grid.dy {
                    yl - 0.5 * (yh - yl)
                } else {
                    yl
                },
                y_hi: if yh >= w.y_hi - 0.5 * grid.dy {
                    yh + 0.5 * (yh - yl)
                } else {
                    yh
                },
            }
        } else {
            Window {
                x_lo: xl,
                x_hi: xh,
                y_lo: yl,
                y_hi: yh,
            }
        };
        grid = Grid::over_box(b, auto.per_semi_axis, margin, auto.square)?;
        sol = solve(&grid, &grid.sample(&h), material, control, opts)?;
    }
    sol.converged = false;
    Ok(sol)
}

/// Raw solver output: pressures, approach, u, iterations, convergence.
pub(crate) struct Raw {
    pub p: Vec<f64>,
    pub u: Vec<f64>,
    pub approach: f64,
    pub iterations: usize,
    pub converged: bool,
}

/// Derived quantities from the raw solution.
fn finish(grid: &Grid, h: &[f64], raw: Raw) -> NormSolution {
    let Raw {
        p,
        u,
        approach,
        iterations,
        converged,
    } = raw;
    let n = grid.len();
    let da = grid.element_area();
    let contact: Vec<bool> = p.iter().map(|&v| v > 0.0).collect();
    let deformed_gap: Vec<f64> = (0..n).map(|k| h[k] - approach + u[k]).collect();
    let force = da * p.iter().sum::<f64>();
    let n_contact = contact.iter().filter(|&&c| c).count();
    let (mut p_max, mut k_max) = (0.0, 0usize);
    for (k, &v) in p.iter().enumerate() {
        if v > p_max {
            p_max = v;
            k_max = k;
        }
    }
    let hmin = h.iter().fold(f64::INFINITY, |m, &v| m.min(v));
    let depth = approach - hmin;
    let complementarity = if n_contact == 0 || depth <= 0.0 {
        0.0
    } else {
        (0..n)
            .map(|k| {
                let e = deformed_gap[k];
                (-e).max(0.0) + if contact[k] { e.abs() } else { 0.0 }
            })
            .fold(0.0, f64::max)
            / depth
    };
    let (mut ilo, mut ihi, mut jlo, mut jhi) = (usize::MAX, 0, usize::MAX, 0);
    let mut touches_boundary = false;
    let mut strips = Vec::with_capacity(grid.my);
    for j in 0..grid.my {
        let row = &p[j * grid.mx..(j + 1) * grid.mx];
        let mut runs = Vec::new();
        let mut i = 0;
        while i < grid.mx {
            if row[i] > 0.0 {
                let first = i;
                let mut s = 0.0;
                while i < grid.mx && row[i] > 0.0 {
                    s += row[i];
                    i += 1;
                }
                let last = i - 1;
                ilo = ilo.min(first);
                ihi = ihi.max(last);
                jlo = jlo.min(j);
                jhi = jhi.max(j);
                if first == 0 || last == grid.mx - 1 || j == 0 || j == grid.my - 1 {
                    touches_boundary = true;
                }
                runs.push(Run {
                    i_first: first,
                    i_last: last,
                    x_trail: grid.x(first) - 0.5 * grid.dx,
                    x_lead: grid.x(last) + 0.5 * grid.dx,
                    force_per_width: grid.dx * s,
                });
            } else {
                i += 1;
            }
        }
        strips.push(Strip {
            j,
            y: grid.y(j),
            force_per_width: grid.dx * row.iter().sum::<f64>(),
            p_max: row.iter().fold(0.0, |m: f64, &v| m.max(v)),
            runs,
        });
    }
    let (extent_x, extent_y) = if n_contact > 0 {
        (
            Some((grid.x(ilo) - 0.5 * grid.dx, grid.x(ihi) + 0.5 * grid.dx)),
            Some((grid.y(jlo) - 0.5 * grid.dy, grid.y(jhi) + 0.5 * grid.dy)),
        )
    } else {
        (None, None)
    };
    NormSolution {
        grid: *grid,
        p_max_at: (grid.x(k_max % grid.mx), grid.y(k_max / grid.mx)),
        pressure: p,
        deformed_gap,
        contact,
        force,
        approach,
        p_max,
        n_contact,
        area: n_contact as f64 * da,
        extent_x,
        extent_y,
        strips,
        iterations,
        converged,
        complementarity,
        touches_boundary,
    }
}
