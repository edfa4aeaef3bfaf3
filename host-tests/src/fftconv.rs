//! Products with Toeplitz-block-Toeplitz matrices by FFT (methods.md §9.1), shared by the NORM and
//! TANG reference solvers.
//!
//! On a rectangular grid of m_x × m_y elements (row-major, index `j * m_x + i`, i along x), an
//! influence matrix whose entries depend only on the index offset, A_IJ = K(i_I − i_J, j_I − j_J),
//! is applied as a discrete convolution u = K ∗ p. The kernel is stored for offsets
//! (−m_x+1..m_x−1) × (−m_y+1..m_y−1) in a circulant of size L_x × L_y, L ≥ 2m − 1 the smallest
//! 2^a 3^b 5^c (zero padding; unused positions are 0), so that the circular convolution of the
//! zero-padded p equals the Toeplitz product on the grid exactly (up to rounding). (Plain 2m
//! padding can hit slow large-prime FFT lengths, e.g. 2·89.)
//!
//! Implementation: real-to-complex FFT along x (only the m_y non-zero rows), complex FFT along y
//! on the m_x + 1 retained frequency columns, pointwise product with the kernel spectrum, inverse
//! along y, complex-to-real along x for the m_y rows that are kept. Kernels need not be symmetric.

use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

/// Smallest L ≥ 2m − 1 of the form 2^a 3^b 5^c.
fn padded_len(m: usize) -> usize {
    let mut l = (2 * m).saturating_sub(1).max(1);
    loop {
        let mut r = l;
        for f in [2, 3, 5] {
            while r.is_multiple_of(f) {
                r /= f;
            }
        }
        if r == 1 {
            return l;
        }
        l += 1;
    }
}

/// A Toeplitz-block-Toeplitz operator on an m_x × m_y grid, applied by FFT.
pub struct ToeplitzConv {
    mx: usize,
    my: usize,
    /// Padded lengths L_x, L_y.
    nx: usize,
    ny: usize,
    /// Kernel values K(di, dj) for di ∈ (−m_x, m_x), dj ∈ (−m_y, m_y), index
    /// (dj + m_y − 1)(2m_x − 1) + (di + m_x − 1). Kept for dense access (direct solvers).
    table: Vec<f64>,
    /// Kernel spectrum scaled by 1/(L_x L_y), column-major: k·L_y + l, k = 0..=L_x/2.
    spectrum: Vec<Complex<f64>>,
    r2c: Arc<dyn RealToComplex<f64>>,
    c2r: Arc<dyn ComplexToReal<f64>>,
    fwd: Arc<dyn Fft<f64>>,
    inv: Arc<dyn Fft<f64>>,
    row: Vec<f64>,
    row_spec: Vec<Complex<f64>>,
    work: Vec<Complex<f64>>,
    scratch_r: Vec<Complex<f64>>,
    scratch_c: Vec<Complex<f64>>,
}

impl std::fmt::Debug for ToeplitzConv {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ToeplitzConv")
            .field("mx", &self.mx)
            .field("my", &self.my)
            .field("nx", &self.nx)
            .field("ny", &self.ny)
            .finish_non_exhaustive()
    }
}

impl ToeplitzConv {
    /// Builds the operator for an `mx` × `my` grid from the kernel `k(di, dj)` (value at index
    /// offset (di, dj) = (i_obs − i_src, j_obs − j_src)). Panics if `mx` or `my` is 0.
    pub fn new(mx: usize, my: usize, k: impl Fn(isize, isize) -> f64) -> Self {
        assert!(mx > 0 && my > 0, "ToeplitzConv needs a non-empty grid");
        let (nx, ny) = (padded_len(mx), padded_len(my));
        let (tx, ty) = (2 * mx - 1, 2 * my - 1);
        let mut table = vec![0.0; tx * ty];
        for dj in -(my as isize - 1)..=(my as isize - 1) {
            for di in -(mx as isize - 1)..=(mx as isize - 1) {
                let idx = (dj + my as isize - 1) as usize * tx + (di + mx as isize - 1) as usize;
                table[idx] = k(di, dj);
            }
        }
        let mut rp = RealFftPlanner::<f64>::new();
        let r2c = rp.plan_fft_forward(nx);
        let c2r = rp.plan_fft_inverse(nx);
        let mut cp = FftPlanner::<f64>::new();
        let fwd = cp.plan_fft_forward(ny);
        let inv = cp.plan_fft_inverse(ny);
        let kx = nx / 2 + 1;
        let scratch_r = vec![Complex::default(); r2c.get_scratch_len().max(c2r.get_scratch_len())];
        let scratch_c = vec![
            Complex::default();
            fwd.get_inplace_scratch_len()
                .max(inv.get_inplace_scratch_len())
        ];
        let mut me = Self {
            mx,
            my,
            nx,
            ny,
            table,
            spectrum: vec![Complex::default(); kx * ny],
            r2c,
            c2r,
            fwd,
            inv,
            row: vec![0.0; nx],
            row_spec: vec![Complex::default(); kx],
            work: vec![Complex::default(); kx * ny],
            scratch_r,
            scratch_c,
        };
        // Circulant kernel: row l of the padded array holds offset dj = l (l < my) or l − L_y
        // (l > L_y − my); same along x. Positions in between stay 0.
        let mut spec = vec![Complex::default(); kx * ny];
        for l in 0..ny {
            let dj = if l < my {
                Some(l as isize)
            } else if l > ny - my {
                Some(l as isize - ny as isize)
            } else {
                None
            };
            for c in 0..nx {
                let di = if c < mx {
                    Some(c as isize)
                } else if c > nx - mx {
                    Some(c as isize - nx as isize)
                } else {
                    None
                };
                me.row[c] = match (di, dj) {
                    (Some(di), Some(dj)) => me.kernel(di, dj),
                    _ => 0.0,
                };
            }
            me.r2c
                .process_with_scratch(&mut me.row, &mut me.row_spec, &mut me.scratch_r)
                .expect("buffer sizes are set from the plan");
            for (k, z) in me.row_spec.iter().enumerate() {
                spec[k * ny + l] = *z;
            }
        }
        me.fwd.process_with_scratch(&mut spec, &mut me.scratch_c);
        let scale = 1.0 / (nx * ny) as f64;
        for z in spec.iter_mut() {
            *z *= scale;
        }
        me.spectrum = spec;
        me
    }

    /// Grid size (m_x, m_y).
    pub fn dims(&self) -> (usize, usize) {
        (self.mx, self.my)
    }

    /// Padded FFT lengths (L_x, L_y).
    pub fn padded_dims(&self) -> (usize, usize) {
        (self.nx, self.ny)
    }

    /// Kernel value at index offset (di, dj); 0 outside |di| < m_x, |dj| < m_y.
    #[inline]
    pub fn kernel(&self, di: isize, dj: isize) -> f64 {
        let (mx, my) = (self.mx as isize, self.my as isize);
        if di.abs() >= mx || dj.abs() >= my {
            return 0.0;
        }
        self.table[((dj + my - 1) * (2 * mx - 1) + (di + mx - 1)) as usize]
    }

    /// Matrix entry A_IJ for flat element indices I (observation) and J (source).
    #[inline]
    pub fn entry(&self, obs: usize, src: usize) -> f64 {
        let (io, jo) = ((obs % self.mx) as isize, (obs / self.mx) as isize);
        let (is, js) = ((src % self.mx) as isize, (src / self.mx) as isize);
        self.kernel(io - is, jo - js)
    }

    /// u = A p by FFT. `p` and `u` have length m_x·m_y (row-major, `j * m_x + i`).
    pub fn apply(&mut self, p: &[f64], u: &mut [f64]) {
        let (mx, my) = (self.mx, self.my);
        let ny = self.ny;
        assert_eq!(p.len(), mx * my, "p has the grid's length");
        assert_eq!(u.len(), mx * my, "u has the grid's length");
        let kx = self.nx / 2 + 1;
        // Rows my..L_y of the padded input are zero: their spectra are zero.
        for l in 0..ny {
            if l < my {
                self.row[..mx].copy_from_slice(&p[l * mx..(l + 1) * mx]);
                self.row[mx..].iter_mut().for_each(|v| *v = 0.0);
                self.r2c
                    .process_with_scratch(&mut self.row, &mut self.row_spec, &mut self.scratch_r)
                    .expect("buffer sizes are set from the plan");
                for (k, z) in self.row_spec.iter().enumerate() {
                    self.work[k * ny + l] = *z;
                }
            } else {
                for k in 0..kx {
                    self.work[k * ny + l] = Complex::default();
                }
            }
        }
        self.fwd
            .process_with_scratch(&mut self.work, &mut self.scratch_c);
        for (w, s) in self.work.iter_mut().zip(self.spectrum.iter()) {
            *w *= *s;
        }
        self.inv
            .process_with_scratch(&mut self.work, &mut self.scratch_c);
        for l in 0..my {
            for k in 0..kx {
                self.row_spec[k] = self.work[k * ny + l];
            }
            // The product of real-data spectra has a real DC (and, for even L_x, Nyquist) bin up to
            // rounding.
            self.row_spec[0].im = 0.0;
            if self.nx.is_multiple_of(2) {
                self.row_spec[kx - 1].im = 0.0;
            }
            self.c2r
                .process_with_scratch(&mut self.row_spec, &mut self.row, &mut self.scratch_r)
                .expect("buffer sizes are set from the plan");
            u[l * mx..(l + 1) * mx].copy_from_slice(&self.row[..mx]);
        }
    }

    /// u += coef · A[:, src] (the displacements due to `coef` on element `src`), by direct
    /// summation in O(m_x m_y); cheaper than an FFT product for a few changed elements.
    pub fn add_column(&self, src: usize, coef: f64, u: &mut [f64]) {
        let (mx, my) = (self.mx, self.my);
        assert_eq!(u.len(), mx * my, "u has the grid's length");
        assert!(src < mx * my, "source element inside the grid");
        let (is, js) = (src % mx, src / mx);
        let tx = 2 * mx - 1;
        for jo in 0..my {
            // Offsets dj = jo − js, di = io − is for io = 0..mx: a contiguous slice of the table.
            let row = (jo + my - 1 - js) * tx + (mx - 1 - is);
            let k = &self.table[row..row + mx];
            for (ui, ki) in u[jo * mx..(jo + 1) * mx].iter_mut().zip(k) {
                *ui += coef * ki;
            }
        }
    }

    /// u = A p by direct summation, O((m_x m_y)²); for checks on small grids.
    pub fn apply_dense(&self, p: &[f64], u: &mut [f64]) {
        let n = self.mx * self.my;
        assert_eq!(p.len(), n, "p has the grid's length");
        assert_eq!(u.len(), n, "u has the grid's length");
        for (obs, ui) in u.iter_mut().enumerate() {
            *ui = (0..n)
                .filter(|&s| p[s] != 0.0)
                .map(|s| self.entry(obs, s) * p[s])
                .sum();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The FFT product equals direct summation for a non-symmetric kernel on odd and even grids.
    #[test]
    fn fft_matches_direct_sum() {
        for &(mx, my) in &[(1usize, 1usize), (2, 1), (5, 3), (8, 8), (7, 12), (14, 23)] {
            let k = |di: isize, dj: isize| {
                1.0 / (1.0 + (di as f64 - 0.3).powi(2) + 2.0 * (dj as f64 + 0.2).powi(2))
            };
            let mut c = ToeplitzConv::new(mx, my, k);
            let mut u3 = vec![0.0; mx * my];
            let p: Vec<f64> = (0..mx * my)
                .map(|n| ((n * 37 % 11) as f64 - 4.0) * 0.7)
                .collect();
            let mut u1 = vec![0.0; mx * my];
            let mut u2 = vec![0.0; mx * my];
            c.apply(&p, &mut u1);
            c.apply_dense(&p, &mut u2);
            for (src, &v) in p.iter().enumerate() {
                c.add_column(src, v, &mut u3);
            }
            let scale = u2.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for ((a, b), c) in u1.iter().zip(&u2).zip(&u3) {
                assert!((a - b).abs() <= 1e-13 * scale, "{mx}x{my}: {a} vs {b}");
                assert!((c - b).abs() <= 1e-13 * scale, "{mx}x{my}: {c} vs {b}");
            }
        }
    }
}
