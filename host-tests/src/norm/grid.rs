//! The potential-contact grid (methods.md §0.3) and helpers that place it over the region where the
//! undeformed gap is small.

use wrc_kernel::Error;

/// Rectangular potential-contact grid: m_x × m_y elements of size δx × δy (mm); element (i, j) has
/// its centre at x_i = x_0 + (i + ½) δx, y_j = y_0 + (j + ½) δy (methods.md §0.3). Arrays over the
/// grid are row-major with flat index `j * mx + i` (row j = strip at y_j, i increasing along x, the
/// rolling direction).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// Number of elements along x (rolling direction).
    pub mx: usize,
    /// Number of elements along y (number of strips).
    pub my: usize,
    /// Element size along x, mm.
    pub dx: f64,
    /// Element size along y, mm.
    pub dy: f64,
    /// x of the grid's lower-left corner (trailing edge of column 0), mm.
    pub x0: f64,
    /// y of the grid's lower-left corner, mm.
    pub y0: f64,
}

/// A rectangular window [x_lo, x_hi] × [y_lo, y_hi] (mm) in which the gap is searched.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Window {
    /// Lower x bound, mm.
    pub x_lo: f64,
    /// Upper x bound, mm.
    pub x_hi: f64,
    /// Lower y bound, mm.
    pub y_lo: f64,
    /// Upper y bound, mm.
    pub y_hi: f64,
}

impl Window {
    /// The window [−hx, hx] × [−hy, hy].
    pub fn centred(hx: f64, hy: f64) -> Self {
        Self {
            x_lo: -hx,
            x_hi: hx,
            y_lo: -hy,
            y_hi: hy,
        }
    }

    fn check(&self) -> Result<(), Error> {
        for (v, n) in [
            (self.x_lo, "window x_lo"),
            (self.x_hi, "window x_hi"),
            (self.y_lo, "window y_lo"),
            (self.y_hi, "window y_hi"),
        ] {
            if !v.is_finite() {
                return Err(Error::NonFinite(n));
            }
        }
        if self.x_hi <= self.x_lo {
            return Err(Error::NonPositive("window width along x"));
        }
        if self.y_hi <= self.y_lo {
            return Err(Error::NonPositive("window width along y"));
        }
        Ok(())
    }
}

impl Grid {
    /// A grid from its size, element size (mm) and lower-left corner (mm).
    pub fn new(mx: usize, my: usize, dx: f64, dy: f64, x0: f64, y0: f64) -> Result<Self, Error> {
        if mx == 0 {
            return Err(Error::GridTooSmall("mx"));
        }
        if my == 0 {
            return Err(Error::GridTooSmall("my"));
        }
        for (v, n) in [(dx, "dx"), (dy, "dy")] {
            if !v.is_finite() {
                return Err(Error::NonFinite(n));
            }
            if v <= 0.0 {
                return Err(Error::NonPositive(n));
            }
        }
        for (v, n) in [(x0, "x0"), (y0, "y0")] {
            if !v.is_finite() {
                return Err(Error::NonFinite(n));
            }
        }
        Ok(Self {
            mx,
            my,
            dx,
            dy,
            x0,
            y0,
        })
    }

    /// m_x × m_y elements of size δx × δy centred on (x_c, y_c).
    pub fn centred(
        mx: usize,
        my: usize,
        dx: f64,
        dy: f64,
        xc: f64,
        yc: f64,
    ) -> Result<Self, Error> {
        Self::new(
            mx,
            my,
            dx,
            dy,
            xc - 0.5 * mx as f64 * dx,
            yc - 0.5 * my as f64 * dy,
        )
    }

    /// m_x × m_y elements exactly covering the window.
    pub fn covering(w: Window, mx: usize, my: usize) -> Result<Self, Error> {
        w.check()?;
        if mx == 0 {
            return Err(Error::GridTooSmall("mx"));
        }
        if my == 0 {
            return Err(Error::GridTooSmall("my"));
        }
        Self::new(
            mx,
            my,
            (w.x_hi - w.x_lo) / mx as f64,
            (w.y_hi - w.y_lo) / my as f64,
            w.x_lo,
            w.y_lo,
        )
    }

    /// Number of elements m_x·m_y.
    pub fn len(&self) -> usize {
        self.mx * self.my
    }

    /// Always false (a grid has at least one element); for clippy's `len_without_is_empty`.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Flat index of element (i, j).
    #[inline]
    pub fn index(&self, i: usize, j: usize) -> usize {
        j * self.mx + i
    }

    /// x of the centre of column i, mm.
    #[inline]
    pub fn x(&self, i: usize) -> f64 {
        self.x0 + (i as f64 + 0.5) * self.dx
    }

    /// y of the centre of row (strip) j, mm.
    #[inline]
    pub fn y(&self, j: usize) -> f64 {
        self.y0 + (j as f64 + 0.5) * self.dy
    }

    /// Element area δx·δy, mm².
    #[inline]
    pub fn element_area(&self) -> f64 {
        self.dx * self.dy
    }

    /// The grid's window.
    pub fn window(&self) -> Window {
        Window {
            x_lo: self.x0,
            x_hi: self.x0 + self.mx as f64 * self.dx,
            y_lo: self.y0,
            y_hi: self.y0 + self.my as f64 * self.dy,
        }
    }

    /// A function h(x, y) sampled at the element centres (row-major).
    pub fn sample(&self, h: impl Fn(f64, f64) -> f64) -> Vec<f64> {
        let mut v = Vec::with_capacity(self.len());
        for j in 0..self.my {
            let y = self.y(j);
            for i in 0..self.mx {
                v.push(h(self.x(i), y));
            }
        }
        v
    }

    /// A grid over the region where the undeformed gap is below `level` (mm),
    /// R = {h(x, y) < level} inside the search window.
    ///
    /// R's bounding box (found by sampling h on a 401 × 401 lattice over the window, and widened by
    /// one lattice step on every side) has semi-extents (X, Y); the elements have δx = X/n,
    /// δy = Y/n (`square`: both min(X, Y)/n) with n = `per_semi_axis`, and the grid covers the box
    /// widened by `margin`·X and `margin`·Y on each side. For a penetration-controlled solve pass
    /// the approach δ as `level`: the contact patch lies inside R (a contact element has
    /// h = δ − u < δ). Note that R is larger than the patch (for Hertz, by √2 on a circle), so the
    /// patch gets fewer than n elements per semi-axis; [`super::solve_auto`] adapts the grid to
    /// the patch instead.
    ///
    /// Errors: invalid window or level, `per_semi_axis` < 1, R empty ([`Error::NoContact`]), or R
    /// touching the window's edge (the window is too small: [`Error::OutOfRange`]).
    pub fn over_gap_level(
        h: impl Fn(f64, f64) -> f64,
        window: Window,
        level: f64,
        per_semi_axis: usize,
        margin: f64,
        square: bool,
    ) -> Result<Self, Error> {
        window.check()?;
        if !level.is_finite() {
            return Err(Error::NonFinite("level"));
        }
        if !(margin.is_finite() && margin >= 0.0) {
            return Err(Error::OutOfRange("margin"));
        }
        if per_semi_axis == 0 {
            return Err(Error::GridTooSmall("per_semi_axis"));
        }
        const N: usize = 401;
        let sx = (window.x_hi - window.x_lo) / (N - 1) as f64;
        let sy = (window.y_hi - window.y_lo) / (N - 1) as f64;
        let (mut ilo, mut ihi, mut jlo, mut jhi) = (N, 0usize, N, 0usize);
        for j in 0..N {
            let y = window.y_lo + j as f64 * sy;
            for i in 0..N {
                let x = window.x_lo + i as f64 * sx;
                let v = h(x, y);
                if !v.is_finite() {
                    return Err(Error::NonFinite("gap"));
                }
                if v < level {
                    ilo = ilo.min(i);
                    ihi = ihi.max(i);
                    jlo = jlo.min(j);
                    jhi = jhi.max(j);
                }
            }
        }
        if ilo > ihi {
            return Err(Error::NoContact);
        }
        if ilo == 0 || jlo == 0 || ihi == N - 1 || jhi == N - 1 {
            return Err(Error::OutOfRange("window (gap region reaches its edge)"));
        }
        let b = Window {
            x_lo: window.x_lo + (ilo - 1) as f64 * sx,
            x_hi: window.x_lo + (ihi + 1) as f64 * sx,
            y_lo: window.y_lo + (jlo - 1) as f64 * sy,
            y_hi: window.y_lo + (jhi + 1) as f64 * sy,
        };
        Self::over_box(b, per_semi_axis, margin, square)
    }

    /// A grid over the box `b` (e.g. a contact patch's extents) with `per_semi_axis` elements per
    /// semi-extent of the box (`square`: δx = δy = the smaller size), widened by `margin` times
    /// the semi-extents plus one element on each side. The grid is centred on the box.
    pub fn over_box(
        b: Window,
        per_semi_axis: usize,
        margin: f64,
        square: bool,
    ) -> Result<Self, Error> {
        b.check()?;
        if per_semi_axis == 0 {
            return Err(Error::GridTooSmall("per_semi_axis"));
        }
        if !(margin.is_finite() && margin >= 0.0) {
            return Err(Error::OutOfRange("margin"));
        }
        let (sx, sy) = (0.5 * (b.x_hi - b.x_lo), 0.5 * (b.y_hi - b.y_lo));
        let (mut dx, mut dy) = (sx / per_semi_axis as f64, sy / per_semi_axis as f64);
        if square {
            dx = dx.min(dy);
            dy = dx;
        }
        let mx = 2 * ((sx * (1.0 + margin) / dx).ceil() as usize + 1);
        let my = 2 * ((sy * (1.0 + margin) / dy).ceil() as usize + 1);
        Self::centred(
            mx,
            my,
            dx,
            dy,
            0.5 * (b.x_lo + b.x_hi),
            0.5 * (b.y_lo + b.y_hi),
        )
    }
}
