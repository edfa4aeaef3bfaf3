//! TANG — Kalker's exact theory of steady rolling on the half-space (methods.md §9.2), the host
//! reference against which FASTSIM and FaStrip are judged.
//!
//! Discretisation (methods.md §0.3): a rectangular grid of m_x × m_y elements of size δx × δy with
//! piecewise-constant tractions p = (p_x, p_y) acting on body 1 (the wheel, §0.2). Tangential
//! displacement differences u = A p use the rectangular-element coefficients of
//! [`crate::influence::Elements`] (A_xx, A_yy, A_xy; identical bodies, no normal–tangential
//! coupling). The steady-state slip with the upwind difference along the rolling direction
//! (δq = δx) is
//!
//! s_I = w_I + (u_I − u'_I)/δq = w_I + Σ_J B(x_I − x_J, y_I − y_J) p_J,
//! B(x, y) = (A(x, y) − A(x + δq, y))/δq,
//!
//! with the rigid slip w = (ξ − φy, η + φx) (dimensionless; the slip velocity is V·s).
//!
//! Friction: Coulomb with the bound g_I = μ p_n,I from any supplied pressure (Hertz at element
//! centres, [`hertz_pressure`], or a NORM solution). Exterior (p_n ≤ 0): p = 0. Adhesion: s = 0,
//! |p| ≤ g. Slip: |p| = g, p = −g s/|s|.
//!
//! Solver: non-linear block Gauss–Seidel of CONTACT's SteadyGS type. Each grid row is swept from
//! the trailing edge (smallest x) to the leading edge. As in SteadyGS the unknown of an adhesion
//! element is its traction *increment* over the upstream neighbour, dp_I = p_I − p_{I+1}, and the
//! unknown of a slip element is its traction: changing element I by Δ therefore shifts the
//! tractions of the whole adhesion run downstream of I (I−1, …, K+1, up to the first element K
//! that slips or is exterior) by Δ, which by the telescoping of the rolling difference changes the
//! slip by s += (A(· − I) − A(· − K)) Δ/δq (two Toeplitz columns of A, exact). The local 2 × 2
//! coefficient of element I is C_I = (A(0) − A(x_I − x_K))/δq (diagonal: A_xy vanishes on a row).
//! This change of variables is what makes the iteration converge: plain Gauss–Seidel on p with
//! B = (A − A_shift)/δq, whose strongest coupling is B_{I,upstream} = −B_II, diverges (verified:
//! Carter 2-D flips between ±μp_n), and so does SteadyGS swept from leading to trailing edge.
//!
//! Element problem (the others frozen): s_I(p) = v + C_I p with v = s_I − C_I p^old. Adhesion
//! trial p^H = −C_I⁻¹ v, accepted if |p^H| ≤ g. Otherwise the element slips and its traction lies
//! on the circle |p| = g: writing s = −σ t, p = g t (|t| = 1, σ = |s| ≥ 0) gives
//! t = −(σ I + g C_I)⁻¹ v, and σ is the unique positive root of f(σ) = |(σI + gC_I)⁻¹ v|² − 1
//! (f is convex and decreasing; f(0) = |p^H|²/g² − 1 > 0). Newton from the lower bound
//! σ₀ = max(0, |v| − g λ_max(C_I)) increases monotonically to the root (a few steps); this is the
//! per-element Newton on the slip circle of §9.2, parametrised by the slip magnitude instead of
//! the angle (same solution, guaranteed convergence).
//!
//! Convergence: Δ_k = max_I |p_I^(k) − p_I^(k−1)| after sweep k, relative to
//! min(max_I |p_I|, μ p_n,max) (the traction scale; μ may be huge for the no-slip linear theory);
//! with the observed contraction r = Δ_k/Δ_{k−1} the remaining error is estimated as
//! Δ_k r/(1−r). The solve stops when Δ_k · max(1, r/(1−r)) < `tol` (default 1e-6) and reports
//! `converged = false` after `max_sweeps` sweeps. The final slip is recomputed from scratch as
//! s = w + B p with an FFT product ([`Conv2`], circulant embedding of the Toeplitz B), which also
//! checks the incremental updates; `residual` reports the complementarity violation of that slip.
//!
//! Discretisation error: first order in δx (upwind rolling difference, element-centre sampling of
//! the contact and slip boundaries). The tests measure it (Carter, Kalker's linear theory,
//! CONTACT's 44 × 44 results) and [`richardson`] extrapolates two grids with halved δx.
//!
//! Units (methods.md §0.1): mm, N, MPa; creepages dimensionless, spin φ in rad/mm.

use crate::influence::Elements;
use rustfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};
use std::f64::consts::PI;
use std::sync::Arc;

/// Rectangular potential-contact grid (methods.md §0.3): element (i, j) has centre
/// x_i = x0 + (i + ½)δx, y_j = y0 + (j + ½)δy; storage index j·m_x + i.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// Number of elements along x (rolling direction).
    pub mx: usize,
    /// Number of elements along y.
    pub my: usize,
    /// Element size along x, mm (also the rolling step δq).
    pub dx: f64,
    /// Element size along y, mm.
    pub dy: f64,
    /// x of the grid's lower edge, mm.
    pub x0: f64,
    /// y of the grid's lower edge, mm.
    pub y0: f64,
}

impl Grid {
    /// A grid centred on the origin for a Hertz ellipse with semi-axes `a` (x) and `b` (y), mm:
    /// `n` elements per semi-axis (δx = a/n, δy = b/n) over ±`margin`·a × ±`margin`·b, rounded
    /// up to whole elements (n = 20, margin = 1.1 gives CONTACT's 44 × 44 grid of §10.4).
    pub fn hertz(a: f64, b: f64, n: usize, margin: f64) -> Self {
        let half = (margin * n as f64 - 1e-9).ceil() as usize;
        let (dx, dy) = (a / n as f64, b / n as f64);
        Self {
            mx: 2 * half,
            my: 2 * half,
            dx,
            dy,
            x0: -(half as f64) * dx,
            y0: -(half as f64) * dy,
        }
    }

    /// Number of elements.
    pub fn len(&self) -> usize {
        self.mx * self.my
    }

    /// True for an empty grid.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Centre x of column i, mm.
    pub fn x(&self, i: usize) -> f64 {
        self.x0 + (i as f64 + 0.5) * self.dx
    }

    /// Centre y of row j, mm.
    pub fn y(&self, j: usize) -> f64 {
        self.y0 + (j as f64 + 0.5) * self.dy
    }

    /// Storage index of element (i, j).
    pub fn idx(&self, i: usize, j: usize) -> usize {
        j * self.mx + i
    }

    /// Element area δxδy, mm².
    pub fn area(&self) -> f64 {
        self.dx * self.dy
    }
}

/// NORM's solution as a TANG grid (the same elements) and pressure (MPa, grid order; negative
/// round-off clipped to 0): the reference tangential problem on the exact normal pressure.
pub fn from_norm(sol: &crate::norm::NormSolution) -> (Grid, Vec<f64>) {
    let g = &sol.grid;
    let grid = Grid {
        mx: g.mx,
        my: g.my,
        dx: g.dx,
        dy: g.dy,
        x0: g.x0,
        y0: g.y0,
    };
    let mut pn = vec![0.0; grid.len()];
    for j in 0..g.my {
        for i in 0..g.mx {
            pn[grid.idx(i, j)] = sol.p(i, j).max(0.0);
        }
    }
    (grid, pn)
}

/// Hertz pressure p0 √(1 − x²/a² − y²/b²) at the element centres strictly inside the ellipse
/// (0 elsewhere), p0 = 3F_n/(2πab), MPa. If `rescale`, the sampled pressure is scaled so that
/// δxδy Σ p_n = F_n exactly (as a NORM solution would; methods.md §0.5).
pub fn hertz_pressure(grid: &Grid, a: f64, b: f64, fn_: f64, rescale: bool) -> Vec<f64> {
    let p0 = 3.0 * fn_ / (2.0 * PI * a * b);
    let mut p = vec![0.0; grid.len()];
    for j in 0..grid.my {
        for i in 0..grid.mx {
            let r2 = (grid.x(i) / a).powi(2) + (grid.y(j) / b).powi(2);
            if r2 < 1.0 {
                p[grid.idx(i, j)] = p0 * (1.0 - r2).sqrt();
            }
        }
    }
    if rescale {
        let sum: f64 = p.iter().sum::<f64>() * grid.area();
        if sum > 0.0 {
            p.iter_mut().for_each(|v| *v *= fn_ / sum);
        }
    }
    p
}

/// Creepages (methods.md §0.2): longitudinal ξ, lateral η (dimensionless), spin φ (rad/mm).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Creepage {
    /// Longitudinal creepage ξ.
    pub xi: f64,
    /// Lateral creepage η.
    pub eta: f64,
    /// Spin creepage φ, rad/mm.
    pub phi: f64,
}

/// Richardson extrapolation of a first-order quantity from a coarse (δx) and a fine (δx/2) grid:
/// 2·fine − coarse.
pub fn richardson(coarse: f64, fine: f64) -> f64 {
    2.0 * fine - coarse
}

/// Solver settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TangOptions {
    /// Stopping tolerance on the estimated traction error relative to the traction scale
    /// min(max|p|, μ p_n,max) (module docs).
    pub tol: f64,
    /// Iteration cap (Gauss–Seidel sweeps); reaching it gives `converged = false`.
    pub max_sweeps: usize,
}

impl Default for TangOptions {
    fn default() -> Self {
        Self {
            tol: 1e-6,
            max_sweeps: 2000,
        }
    }
}

/// State of one element of the solution.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ElementState {
    /// Outside the contact (p_n ≤ 0): p = 0.
    Exterior,
    /// Adhesion: s = 0, |p| ≤ μ p_n.
    Adhesion,
    /// Slip: |p| = μ p_n, p opposite to s.
    Slip,
}

/// Solution of one steady-rolling case.
#[derive(Clone, Debug)]
pub struct TangSolution {
    /// The grid the solution lives on.
    pub grid: Grid,
    /// Traction on the wheel along x per element, MPa.
    pub px: Vec<f64>,
    /// Traction on the wheel along y per element, MPa.
    pub py: Vec<f64>,
    /// Relative slip s_x (dimensionless; slip velocity = V s), 0 in adhesion and exterior.
    pub sx: Vec<f64>,
    /// Relative slip s_y (dimensionless), 0 in adhesion and exterior.
    pub sy: Vec<f64>,
    /// Element states.
    pub state: Vec<ElementState>,
    /// F_x = δxδy Σ p_x, N.
    pub fx: f64,
    /// F_y = δxδy Σ p_y, N.
    pub fy: f64,
    /// F_n = δxδy Σ p_n of the supplied pressure, N.
    pub fn_: f64,
    /// M_z = δxδy Σ (x p_y − y p_x) about the grid origin, N·mm.
    pub mz: f64,
    /// Gauss–Seidel sweeps used.
    pub sweeps: usize,
    /// Whether the stopping test of the module docs was met within `max_sweeps`.
    pub converged: bool,
    /// Final estimated traction error relative to the traction scale (module docs).
    pub error_estimate: f64,
    /// Largest complementarity violation of the final state, relative: adhesion |s| / max|w|,
    /// slip |p|/g − 1 and the angle between p and −s (rad).
    pub residual: f64,
    /// Number of contact elements.
    pub n_contact: usize,
    /// Number of slipping elements.
    pub n_slip: usize,
}

impl TangSolution {
    /// Slip velocity magnitude V|s| per element, mm/s, for rolling speed `v` (mm/s).
    pub fn slip_velocity(&self, v: f64) -> Vec<f64> {
        self.sx
            .iter()
            .zip(&self.sy)
            .map(|(a, b)| v * a.hypot(*b))
            .collect()
    }
}

/// Two-dimensional FFT convolution with the 2 × 2 Toeplitz kernel B (circulant embedding on a
/// 2m_x × 2m_y torus): s = B p for all elements in O(N log N).
pub struct Conv2 {
    nx: usize,
    ny: usize,
    fwd_x: Arc<dyn Fft<f64>>,
    fwd_y: Arc<dyn Fft<f64>>,
    inv_x: Arc<dyn Fft<f64>>,
    inv_y: Arc<dyn Fft<f64>>,
    kxx: Vec<Complex64>,
    kxy: Vec<Complex64>,
    kyy: Vec<Complex64>,
}

impl Conv2 {
    fn new(grid: &Grid, tab: &BTable) -> Self {
        let (nx, ny) = (2 * grid.mx, 2 * grid.my);
        let mut planner = FftPlanner::new();
        let mut c = Self {
            nx,
            ny,
            fwd_x: planner.plan_fft_forward(nx),
            fwd_y: planner.plan_fft_forward(ny),
            inv_x: planner.plan_fft_inverse(nx),
            inv_y: planner.plan_fft_inverse(ny),
            kxx: vec![Complex64::default(); nx * ny],
            kxy: vec![Complex64::default(); nx * ny],
            kyy: vec![Complex64::default(); nx * ny],
        };
        let (mx, my) = (grid.mx as isize, grid.my as isize);
        for dj in -(my - 1)..my {
            for di in -(mx - 1)..mx {
                let t = tab.index(di, dj);
                let k = (dj.rem_euclid(ny as isize) as usize) * nx
                    + di.rem_euclid(nx as isize) as usize;
                c.kxx[k] = Complex64::new(tab.xx[t], 0.0);
                c.kxy[k] = Complex64::new(tab.xy[t], 0.0);
                c.kyy[k] = Complex64::new(tab.yy[t], 0.0);
            }
        }
        let mut kxx = std::mem::take(&mut c.kxx);
        let mut kxy = std::mem::take(&mut c.kxy);
        let mut kyy = std::mem::take(&mut c.kyy);
        for k in [&mut kxx, &mut kxy, &mut kyy] {
            c.fft2(k, true);
        }
        c.kxx = kxx;
        c.kxy = kxy;
        c.kyy = kyy;
        c
    }

    fn fft2(&self, data: &mut [Complex64], forward: bool) {
        let (fx, fy) = if forward {
            (&self.fwd_x, &self.fwd_y)
        } else {
            (&self.inv_x, &self.inv_y)
        };
        for row in data.chunks_exact_mut(self.nx) {
            fx.process(row);
        }
        let mut col = vec![Complex64::default(); self.ny];
        for i in 0..self.nx {
            for (j, c) in col.iter_mut().enumerate() {
                *c = data[j * self.nx + i];
            }
            fy.process(&mut col);
            for (j, c) in col.iter().enumerate() {
                data[j * self.nx + i] = *c;
            }
        }
    }

    /// s = B p on the grid (`px`, `py`, `sx`, `sy` in grid storage order).
    fn apply(&self, grid: &Grid, px: &[f64], py: &[f64], sx: &mut [f64], sy: &mut [f64]) {
        let (nx, ny) = (self.nx, self.ny);
        let mut z = vec![Complex64::default(); nx * ny];
        for j in 0..grid.my {
            for i in 0..grid.mx {
                let g = grid.idx(i, j);
                z[j * nx + i] = Complex64::new(px[g], py[g]);
            }
        }
        self.fft2(&mut z, true);
        // Unpack the spectra of the two real fields, multiply by the kernel, repack.
        let mut out = vec![Complex64::default(); nx * ny];
        for kj in 0..ny {
            for ki in 0..nx {
                let k = kj * nx + ki;
                let km = ((ny - kj) % ny) * nx + (nx - ki) % nx;
                let (zk, zm) = (z[k], z[km].conj());
                let pxk = (zk + zm) * 0.5;
                let pyk = (zk - zm) * Complex64::new(0.0, -0.5);
                let sxk = self.kxx[k] * pxk + self.kxy[k] * pyk;
                let syk = self.kxy[k] * pxk + self.kyy[k] * pyk;
                out[k] = sxk + Complex64::new(0.0, 1.0) * syk;
            }
        }
        self.fft2(&mut out, false);
        let scale = 1.0 / (nx * ny) as f64;
        for j in 0..grid.my {
            for i in 0..grid.mx {
                let g = grid.idx(i, j);
                sx[g] = out[j * nx + i].re * scale;
                sy[g] = out[j * nx + i].im * scale;
            }
        }
    }
}

/// Table of the steady-rolling coefficients B for all index offsets (di, dj) ∈
/// (−m_x+1..m_x−1) × (−m_y+1..m_y−1), stored row-major in dj (B_yx = B_xy).
struct BTable {
    mx: usize,
    my: usize,
    xx: Vec<f64>,
    xy: Vec<f64>,
    yy: Vec<f64>,
}

impl BTable {
    fn new(grid: &Grid, el: &Elements) -> Self {
        let (wx, wy) = (2 * grid.mx - 1, 2 * grid.my - 1);
        let mut t = Self {
            mx: grid.mx,
            my: grid.my,
            xx: vec![0.0; wx * wy],
            xy: vec![0.0; wx * wy],
            yy: vec![0.0; wx * wy],
        };
        let dq = grid.dx;
        for dj in -(grid.my as isize - 1)..grid.my as isize {
            let y = dj as f64 * grid.dy;
            for di in -(grid.mx as isize - 1)..grid.mx as isize {
                let x = di as f64 * grid.dx;
                let k = t.index(di, dj);
                t.xx[k] = (el.a_xx(x, y) - el.a_xx(x + dq, y)) / dq;
                t.xy[k] = (el.a_xy(x, y) - el.a_xy(x + dq, y)) / dq;
                t.yy[k] = (el.a_yy(x, y) - el.a_yy(x + dq, y)) / dq;
            }
        }
        t
    }

    #[inline]
    fn index(&self, di: isize, dj: isize) -> usize {
        ((dj + self.my as isize - 1) as usize) * (2 * self.mx - 1)
            + (di + self.mx as isize - 1) as usize
    }
}

/// Table of the displacement coefficients A for index offsets (di, dj) ∈ (−m_x..m_x) ×
/// (−m_y+1..m_y−1) (one column more on each side than the grid needs, for a traction run that
/// ends beyond the trailing edge of the grid).
struct ATable {
    mx: usize,
    my: usize,
    xx: Vec<f64>,
    xy: Vec<f64>,
    yy: Vec<f64>,
}

impl ATable {
    fn new(grid: &Grid, el: &Elements) -> Self {
        let (wx, wy) = (2 * grid.mx + 1, 2 * grid.my - 1);
        let mut t = Self {
            mx: grid.mx,
            my: grid.my,
            xx: vec![0.0; wx * wy],
            xy: vec![0.0; wx * wy],
            yy: vec![0.0; wx * wy],
        };
        for dj in -(grid.my as isize - 1)..grid.my as isize {
            let y = dj as f64 * grid.dy;
            for di in -(grid.mx as isize)..=grid.mx as isize {
                let x = di as f64 * grid.dx;
                let k = t.index(di, dj);
                t.xx[k] = el.a_xx(x, y);
                t.xy[k] = el.a_xy(x, y);
                t.yy[k] = el.a_yy(x, y);
            }
        }
        t
    }

    #[inline]
    fn index(&self, di: isize, dj: isize) -> usize {
        ((dj + self.my as isize - 1) as usize) * (2 * self.mx + 1)
            + (di + self.mx as isize) as usize
    }

    #[inline]
    fn at(&self, di: isize, dj: isize) -> [f64; 3] {
        let k = self.index(di, dj);
        [self.xx[k], self.xy[k], self.yy[k]]
    }
}

/// The TANG reference solver for one grid and material (coefficient tables are built once and
/// reused for every pressure, friction coefficient and creepage on that grid).
pub struct TangSolver {
    grid: Grid,
    tab: BTable,
    atab: ATable,
    conv: Conv2,
}

/// Per-element local problem: B_II (symmetric 2×2), v = slip with the element's own traction
/// removed, g the bound. Returns (p, slipping, σ = |s|).
fn local_solve(b: [f64; 3], v: [f64; 2], g: f64) -> ([f64; 2], bool) {
    let [bxx, bxy, byy] = b;
    let det = bxx * byy - bxy * bxy;
    // Adhesion trial p^H = −B⁻¹ v.
    let ph = [
        -(byy * v[0] - bxy * v[1]) / det,
        -(bxx * v[1] - bxy * v[0]) / det,
    ];
    if ph[0].hypot(ph[1]) <= g {
        return (ph, false);
    }
    if g <= 0.0 {
        return ([0.0, 0.0], true);
    }
    // Slip: σ root of f(σ) = |(σI + gB)⁻¹ v|² − 1.
    let tr = bxx + byy;
    let lmax = 0.5 * tr + (0.25 * (bxx - byy).powi(2) + bxy * bxy).sqrt();
    let vn = v[0].hypot(v[1]);
    let mut sig = (vn - g * lmax).max(0.0);
    let mut t = [0.0; 2];
    for _ in 0..50 {
        let (m11, m12, m22) = (sig + g * bxx, g * bxy, sig + g * byy);
        let d = m11 * m22 - m12 * m12;
        // t = −M⁻¹ v,  dt/dσ = −M⁻¹ t... (d/dσ M⁻¹ = −M⁻²)
        let mv = [(m22 * v[0] - m12 * v[1]) / d, (m11 * v[1] - m12 * v[0]) / d];
        let m2v = [
            (m22 * mv[0] - m12 * mv[1]) / d,
            (m11 * mv[1] - m12 * mv[0]) / d,
        ];
        let f = mv[0] * mv[0] + mv[1] * mv[1] - 1.0;
        let fp = -2.0 * (mv[0] * m2v[0] + mv[1] * m2v[1]);
        t = [-mv[0], -mv[1]];
        if fp >= 0.0 {
            break;
        }
        let step = -f / fp;
        sig += step;
        if step.abs() <= 1e-14 * sig.max(1e-300) + 1e-300 {
            let (m11, m12, m22) = (sig + g * bxx, g * bxy, sig + g * byy);
            let d = m11 * m22 - m12 * m12;
            t = [
                -(m22 * v[0] - m12 * v[1]) / d,
                -(m11 * v[1] - m12 * v[0]) / d,
            ];
            break;
        }
    }
    let tn = t[0].hypot(t[1]);
    ([g * t[0] / tn, g * t[1] / tn], true)
}

impl TangSolver {
    /// Build the coefficient tables for `grid` and the combined material (`g_mod` = G in MPa,
    /// `nu` = ν).
    pub fn new(grid: Grid, g_mod: f64, nu: f64) -> Self {
        let el = Elements {
            g: g_mod,
            nu,
            dx: grid.dx,
            dy: grid.dy,
        };
        let tab = BTable::new(&grid, &el);
        let atab = ATable::new(&grid, &el);
        let conv = Conv2::new(&grid, &tab);
        Self {
            grid,
            tab,
            atab,
            conv,
        }
    }

    /// The grid.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// The diagonal block B_II = (B_xx, B_xy, B_yy) at offset zero, mm/MPa per mm.
    pub fn b_self(&self) -> [f64; 3] {
        let k = self.tab.index(0, 0);
        [self.tab.xx[k], self.tab.xy[k], self.tab.yy[k]]
    }

    /// s = w + B p for tractions (`px`, `py`) and creepages `c` at every element (exterior
    /// included), computed by FFT.
    pub fn slip(&self, c: Creepage, px: &[f64], py: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let gr = &self.grid;
        let (mut sx, mut sy) = (vec![0.0; gr.len()], vec![0.0; gr.len()]);
        self.conv.apply(gr, px, py, &mut sx, &mut sy);
        for j in 0..gr.my {
            for i in 0..gr.mx {
                let k = gr.idx(i, j);
                sx[k] += c.xi - c.phi * gr.y(j);
                sy[k] += c.eta + c.phi * gr.x(i);
            }
        }
        (sx, sy)
    }

    /// Solve the steady-rolling problem for pressure `pn` (MPa, grid order; p_n ≤ 0 = exterior),
    /// friction coefficient `mu` and creepages `c`. `init` = optional initial tractions (e.g. the
    /// previous point of a creep curve).
    pub fn solve(
        &self,
        pn: &[f64],
        mu: f64,
        c: Creepage,
        opts: &TangOptions,
        init: Option<(&[f64], &[f64])>,
    ) -> TangSolution {
        let gr = self.grid;
        let n = gr.len();
        assert_eq!(pn.len(), n, "pressure array must match the grid");
        let contact: Vec<bool> = pn.iter().map(|&p| p > 0.0).collect();
        let (mut px, mut py) = match init {
            Some((x, y)) => (x.to_vec(), y.to_vec()),
            None => (vec![0.0; n], vec![0.0; n]),
        };
        for k in 0..n {
            if !contact[k] {
                px[k] = 0.0;
                py[k] = 0.0;
            }
        }
        // Row ranges [lo, hi) of contact per row, for the slip updates.
        let mut rows: Vec<(usize, usize, usize)> = Vec::new();
        for j in 0..gr.my {
            let r = &contact[j * gr.mx..(j + 1) * gr.mx];
            if let (Some(lo), Some(hi)) = (r.iter().position(|&c| c), r.iter().rposition(|&c| c)) {
                rows.push((j, lo, hi + 1));
            }
        }
        let pmax = pn.iter().cloned().fold(0.0, f64::max);
        let scale = (mu * pmax).max(f64::MIN_POSITIVE);
        let (mut sx, mut sy) = self.slip(c, &px, &py);
        let a0 = self.atab.at(0, 0);
        let dq = gr.dx;
        let mut state: Vec<ElementState> = contact
            .iter()
            .map(|&c| {
                if c {
                    ElementState::Adhesion
                } else {
                    ElementState::Exterior
                }
            })
            .collect();
        let mut prev = f64::INFINITY;
        let mut sweeps = 0;
        let mut converged = false;
        let mut err = f64::INFINITY;
        let n_contact = contact.iter().filter(|&&c| c).count();
        if n_contact == 0 {
            converged = true;
            err = 0.0;
        }
        while !converged && sweeps < opts.max_sweeps {
            sweeps += 1;
            let mut dmax: f64 = 0.0;
            for &(j, lo, hi) in &rows {
                for i in lo..hi {
                    let kk = gr.idx(i, j);
                    if !contact[kk] {
                        continue;
                    }
                    // First element downstream (smaller x) of I that is not in adhesion: the
                    // traction increment of I is carried by the adhesion run I−1..K+1.
                    let mut kd = i as isize - 1;
                    while kd >= 0 && state[gr.idx(kd as usize, j)] == ElementState::Adhesion {
                        kd -= 1;
                    }
                    let di = i as isize - kd;
                    let ak = self.atab.at(di, 0);
                    let cm = [
                        (a0[0] - ak[0]) / dq,
                        (a0[1] - ak[1]) / dq,
                        (a0[2] - ak[2]) / dq,
                    ];
                    let g = mu * pn[kk];
                    let v = [
                        sx[kk] - cm[0] * px[kk] - cm[1] * py[kk],
                        sy[kk] - cm[1] * px[kk] - cm[2] * py[kk],
                    ];
                    let (p, slip) = local_solve(cm, v, g);
                    state[kk] = if slip {
                        ElementState::Slip
                    } else {
                        ElementState::Adhesion
                    };
                    let (dpx, dpy) = (p[0] - px[kk], p[1] - py[kk]);
                    dmax = dmax.max(dpx.hypot(dpy));
                    if dpx == 0.0 && dpy == 0.0 {
                        continue;
                    }
                    for q in (kd + 1) as usize..=i {
                        let k2 = gr.idx(q, j);
                        px[k2] += dpx;
                        py[k2] += dpy;
                    }
                    // s += (A(· − I) − A(· − K)) Δ/δq on every contact row (Toeplitz rows).
                    let (ex, ey) = (dpx / dq, dpy / dq);
                    for &(jr, rlo, rhi) in &rows {
                        let dj = jr as isize - j as isize;
                        let len = rhi - rlo;
                        let ti = self.atab.index(rlo as isize - i as isize, dj);
                        let tk = self.atab.index(rlo as isize - kd, dj);
                        let base = jr * gr.mx + rlo;
                        let (rsx, rsy) = (&mut sx[base..base + len], &mut sy[base..base + len]);
                        let (ixx, ixy, iyy) = (
                            &self.atab.xx[ti..ti + len],
                            &self.atab.xy[ti..ti + len],
                            &self.atab.yy[ti..ti + len],
                        );
                        let (kxx, kxy, kyy) = (
                            &self.atab.xx[tk..tk + len],
                            &self.atab.xy[tk..tk + len],
                            &self.atab.yy[tk..tk + len],
                        );
                        for q in 0..len {
                            let (bxx, bxy, byy) =
                                (ixx[q] - kxx[q], ixy[q] - kxy[q], iyy[q] - kyy[q]);
                            rsx[q] += bxx * ex + bxy * ey;
                            rsy[q] += bxy * ex + byy * ey;
                        }
                    }
                }
            }
            let pabs = px
                .iter()
                .zip(&py)
                .map(|(a, b)| a.hypot(*b))
                .fold(0.0, f64::max);
            let d = dmax / pabs.min(scale).max(f64::MIN_POSITIVE);
            let r = if prev.is_finite() && prev > 0.0 {
                d / prev
            } else {
                1.0
            };
            err = if r < 1.0 {
                d * (r / (1.0 - r)).max(1.0)
            } else {
                f64::INFINITY
            };
            if d == 0.0 {
                err = 0.0;
            }
            prev = d;
            if err < opts.tol {
                converged = true;
            }
        }
        // Final exact slip, outputs and complementarity residual.
        let (fsx, fsy) = self.slip(c, &px, &py);
        let mut wmax: f64 = 0.0;
        for j in 0..gr.my {
            for i in 0..gr.mx {
                if contact[gr.idx(i, j)] {
                    wmax = wmax.max((c.xi - c.phi * gr.y(j)).hypot(c.eta + c.phi * gr.x(i)));
                }
            }
        }
        let mut out_sx = vec![0.0; n];
        let mut out_sy = vec![0.0; n];
        let mut residual: f64 = 0.0;
        let (mut fx, mut fy, mut fnn, mut mz) = (0.0, 0.0, 0.0, 0.0);
        let mut n_slip = 0;
        for j in 0..gr.my {
            for i in 0..gr.mx {
                let k = gr.idx(i, j);
                if !contact[k] {
                    state[k] = ElementState::Exterior;
                    continue;
                }
                let g = mu * pn[k];
                match state[k] {
                    ElementState::Slip => {
                        n_slip += 1;
                        out_sx[k] = fsx[k];
                        out_sy[k] = fsy[k];
                        let pm = px[k].hypot(py[k]);
                        let sm = fsx[k].hypot(fsy[k]);
                        if g > 0.0 {
                            residual = residual.max((pm / g - 1.0).abs());
                        }
                        if sm > 0.0 && pm > 0.0 {
                            let cross = (px[k] * fsy[k] - py[k] * fsx[k]) / (pm * sm);
                            let dot = (px[k] * fsx[k] + py[k] * fsy[k]) / (pm * sm);
                            residual = residual.max(cross.atan2(-dot).abs());
                        }
                    }
                    _ => {
                        if wmax > 0.0 {
                            residual = residual.max(fsx[k].hypot(fsy[k]) / wmax);
                        }
                    }
                }
                fx += px[k];
                fy += py[k];
                fnn += pn[k];
                mz += gr.x(i) * py[k] - gr.y(j) * px[k];
            }
        }
        let da = gr.area();
        TangSolution {
            grid: gr,
            px,
            py,
            sx: out_sx,
            sy: out_sy,
            state,
            fx: fx * da,
            fy: fy * da,
            fn_: fnn * da,
            mz: mz * da,
            sweeps,
            converged,
            error_estimate: err,
            residual,
            n_contact,
            n_slip,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn local_solve_slip_is_on_circle_and_opposes_slip() {
        let b = [2.0, 0.3, 1.5];
        let v = [0.7, -1.9];
        let g = 0.4;
        let (p, slip) = local_solve(b, v, g);
        assert!(slip);
        assert!((p[0].hypot(p[1]) - g).abs() < 1e-12);
        let s = [
            v[0] + b[0] * p[0] + b[1] * p[1],
            v[1] + b[1] * p[0] + b[2] * p[1],
        ];
        // p = −g s/|s|
        let sn = s[0].hypot(s[1]);
        assert!((p[0] + g * s[0] / sn).abs() < 1e-12);
        assert!((p[1] + g * s[1] / sn).abs() < 1e-12);
    }

    #[test]
    fn local_solve_adhesion_zeroes_slip() {
        let b = [2.0, 0.0, 1.5];
        let v = [0.1, -0.2];
        let (p, slip) = local_solve(b, v, 10.0);
        assert!(!slip);
        assert!((v[0] + b[0] * p[0]).abs() < 1e-15 && (v[1] + b[2] * p[1]).abs() < 1e-15);
    }

    /// The FFT slip equals the direct sum s = w + Σ B p.
    #[test]
    fn fft_product_matches_direct_sum() {
        let grid = Grid {
            mx: 7,
            my: 5,
            dx: 0.3,
            dy: 0.2,
            x0: -1.0,
            y0: -0.5,
        };
        let el = Elements {
            g: 82_000.0,
            nu: 0.28,
            dx: grid.dx,
            dy: grid.dy,
        };
        let s = TangSolver::new(grid, el.g, el.nu);
        let px: Vec<f64> = (0..grid.len())
            .map(|k| ((k * 7) % 11) as f64 - 5.0)
            .collect();
        let py: Vec<f64> = (0..grid.len())
            .map(|k| ((k * 5) % 13) as f64 - 6.0)
            .collect();
        let c = Creepage {
            xi: 1e-3,
            eta: -2e-3,
            phi: 1e-4,
        };
        let (sx, sy) = s.slip(c, &px, &py);
        for jo in 0..grid.my {
            for io in 0..grid.mx {
                let (x, y) = (grid.x(io), grid.y(jo));
                let mut ex = c.xi - c.phi * y;
                let mut ey = c.eta + c.phi * x;
                for j in 0..grid.my {
                    for i in 0..grid.mx {
                        let (ox, oy) = (x - grid.x(i), y - grid.y(j));
                        let bxx = (el.a_xx(ox, oy) - el.a_xx(ox + grid.dx, oy)) / grid.dx;
                        let bxy = (el.a_xy(ox, oy) - el.a_xy(ox + grid.dx, oy)) / grid.dx;
                        let byy = (el.a_yy(ox, oy) - el.a_yy(ox + grid.dx, oy)) / grid.dx;
                        let k = grid.idx(i, j);
                        ex += bxx * px[k] + bxy * py[k];
                        ey += bxy * px[k] + byy * py[k];
                    }
                }
                let k = grid.idx(io, jo);
                assert!(
                    (sx[k] - ex).abs() < 1e-12 * (1.0 + ex.abs()),
                    "{} {}",
                    sx[k],
                    ex
                );
                assert!((sy[k] - ey).abs() < 1e-12 * (1.0 + ey.abs()));
            }
        }
    }
}
