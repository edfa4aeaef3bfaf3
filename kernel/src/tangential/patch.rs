//! The strip × cell contact patch shared by FASTSIM and FaStrip (methods.md §0.3, §3, §4.3).
//!
//! A [`StripPatch<T, S, C>`] holds `S` strips (grid rows or runs, each with its own lateral position
//! y_j, width δy_j, half-length a_j, centre x_c,j, flexibilities and FaStrip reference factors) on a
//! common rolling-direction grid of `C` cells of length δx: x_i = x0 + (i + ½)δx, i = 0..C−1
//! (increasing x; the leading edge is at the largest x). Steady rolling uses the rolling step δq = δx.
//!
//! Cell (i, j) is in **contact** when |x_i − x_c,j| < a_j (strict). A strip with a_j = 0 is empty.
//! For a Hertz patch with exact a_j = a√(1 − y_j²/b²), x_c = 0 this is exactly the centre-inside rule
//! (x/a)² + (y/b)² < 1 of §0.3.
//!
//! The normal pressure comes through the [`PressureField`] trait ([`SemiEllipticStrips`] for Hertz and
//! STRIPES, [`HertzPressure`] for the Hertz ellipse at cell centres, [`CellPressure`] for a per-cell
//! array such as NORM's). Per-cell results leave through a [`CellSink`] (a no-op `()` sink for
//! force-only calls), so the kernel never stores a grid.
//!
//! Minimum grid: [`MIN_STRIPS`] strips × [`MIN_CELLS`] cells (capacity), and at least
//! [`MIN_CONTACT_CELLS`] cells in contact; smaller grids give `Error::GridTooSmall`.

use crate::error::{check_finite, check_positive, Error};
use crate::kalker::{self, KalkerCoefficients};
use crate::math::{self, c};
use crate::{Material, Real};

/// Minimum number of strips S (capacity) of a patch.
pub const MIN_STRIPS: usize = 4;
/// Minimum number of cells C (capacity) along the rolling direction.
pub const MIN_CELLS: usize = 4;
/// Minimum number of cells in contact for a patch to be solved.
pub const MIN_CONTACT_CELLS: usize = 4;

/// FASTSIM flexibilities (mm³/N): u_x = L1 p_x, u_y = L2 p_y, spin term with L3 (methods.md §3.1).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Flexibilities<T> {
    /// L1 (longitudinal), mm³/N.
    pub l1: T,
    /// L2 (lateral), mm³/N.
    pub l2: T,
    /// L3 (spin), mm³/N.
    pub l3: T,
}

impl<T: Real> Flexibilities<T> {
    /// Kalker's flexibilities for an ellipse a (along x), b (mm), combined shear modulus `g` (MPa):
    /// L1 = 8a/(3G C11), L2 = 8a/(3G C22), L3 = πa√(a/b)/(4G C23).
    pub fn kalker(a: T, b: T, g: T, k: &KalkerCoefficients<T>) -> Self {
        let eight_a_3g = c::<T>(8.0) * a / (c::<T>(3.0) * g);
        Self {
            l1: eight_a_3g / k.c11,
            l2: eight_a_3g / k.c22,
            l3: T::PI * a * math::sqrt(a / b) / (c::<T>(4.0) * g * k.c23),
        }
    }

    /// CONTACT's single flexibility L_t = (|ξ|L1 + |η|L2 + c|φ|L3)/√max(1e-10, ξ² + η² + c²φ²),
    /// c = √(a_ref b_ref) (mm); 1e-3 if L_t < 1e-10 (methods.md §3.1).
    pub fn single(&self, cr: &Creepage<T>, sqrt_ab: T) -> T {
        let num = math::abs(cr.xi) * self.l1
            + math::abs(cr.eta) * self.l2
            + sqrt_ab * math::abs(cr.phi) * self.l3;
        let den2 = cr.xi * cr.xi + cr.eta * cr.eta + sqrt_ab * sqrt_ab * cr.phi * cr.phi;
        let lt = num / math::sqrt(math::max(c(1e-10), den2));
        if lt < c(1e-10) {
            c(1e-3)
        } else {
            lt
        }
    }

    /// CONTACT's blending (Vollebregt & Voltr 2023; methods.md §3.1) for the ellipse a, b (mm), load N
    /// (N), friction μ, shear modulus G (MPa) and C11, C22 at a/b: the three flexibilities move
    /// towards the combined L_c with weight w = clamp(f/3, 0, 1), f = √((ξ²+η²)/(ξ_c²+η_c²)).
    #[allow(clippy::too_many_arguments)]
    pub fn blended(
        &self,
        cr: &Creepage<T>,
        a: T,
        b: T,
        load: T,
        mu: T,
        g: T,
        c11: T,
        c22: T,
    ) -> Self {
        let f3 = c::<T>(8.0) * a / c::<T>(3.0);
        let f4 = T::PI * a * a / c::<T>(4.0);
        let ps = cr.phi * f4 / f3;
        let num = cr.xi * cr.xi + cr.eta * cr.eta + ps * ps;
        let den = cr.xi * cr.xi / self.l1 + cr.eta * cr.eta / self.l2 + ps * ps / self.l3;
        let lc = if den > T::ZERO { num / den } else { self.l1 };
        let xic = mu * load / (a * b * g * c11);
        let etac = mu * load / (a * b * g * c22);
        let f = math::max(
            c(1e-10),
            math::sqrt((cr.xi * cr.xi + cr.eta * cr.eta) / (xic * xic + etac * etac)),
        );
        let w = math::clamp(f / c::<T>(3.0), T::ZERO, T::ONE);
        let blend = |l: T| (T::ONE - w) * l + w * lc;
        Self {
            l1: blend(self.l1),
            l2: blend(self.l2),
            l3: blend(self.l3),
        }
    }
}

/// Creepages (methods.md §0.2): ξ, η dimensionless, φ spin in rad/mm. Any finite values.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Creepage<T> {
    /// Longitudinal creepage ξ.
    pub xi: T,
    /// Lateral creepage η.
    pub eta: T,
    /// Spin creepage φ, rad/mm.
    pub phi: T,
}

impl<T: Real> Creepage<T> {
    /// Checks that all three creepages are finite.
    pub fn check(&self) -> Result<(), Error> {
        check_finite(self.xi, "xi")?;
        check_finite(self.eta, "eta")?;
        check_finite(self.phi, "phi")?;
        Ok(())
    }
}

/// One strip of a patch.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Strip<T> {
    /// Lateral position y_j from the spin reference point (contact-frame origin), mm.
    pub y: T,
    /// Strip width δy_j, mm.
    pub dy: T,
    /// Half-length a_j along x, mm (0: empty strip).
    pub a: T,
    /// Strip centre x_c,j, mm.
    pub xc: T,
    /// Semi-ellipse pressure amplitude p̂_j (MPa): the FaStrip pressure slope is P_j = μ p̂_j / a_j and
    /// `StripParabolic(c)` bounds use it. Hertz: p0 √(1 − y_j²/b²); NORM/STRIPES: 2f_j/(π a_j) with
    /// f_j = δx Σ_i p_n,ij; CONTACT-M5/KP global normalisation: p0,e a_j / a_e.
    pub p_hat: T,
    /// FASTSIM flexibilities of this strip.
    pub flex: Flexibilities<T>,
    /// C11 at the strip's reference ellipse (FaStrip).
    pub c11: T,
    /// C22 at the reference ellipse (FaStrip).
    pub c22: T,
    /// C23 at the reference ellipse (FaStrip).
    pub c23: T,
    /// C33 at the reference ellipse (FaStrip's spin weight in X_j, [`crate::fastrip::SpinInX::Linear`]).
    pub c33: T,
    /// √(b_ref/a_ref) of the reference ellipse (FaStrip spin term).
    pub sqrt_b_over_a: T,
}

impl<T: Real> Strip<T> {
    /// Reference factors and flexibilities of the ellipse (a_ref, b_ref) (mm) set on this strip.
    pub fn with_reference(mut self, a_ref: T, b_ref: T, mat: &Material<T>) -> Result<Self, Error> {
        check_positive(a_ref, "a_ref")?;
        check_positive(b_ref, "b_ref")?;
        let k = kalker::coefficients(a_ref / b_ref, mat.nu)?;
        self.flex = Flexibilities::kalker(a_ref, b_ref, mat.g, &k);
        self.c11 = k.c11;
        self.c22 = k.c22;
        self.c23 = k.c23;
        self.c33 = k.c33;
        self.sqrt_b_over_a = math::sqrt(b_ref / a_ref);
        Ok(self)
    }
}

/// Grid extents of a Hertz patch, as multiples of the semi-axes: cells over ±`fx`·a, strips over
/// ±`fy`·b (both ≥ 1; CONTACT's examples use 1.1).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct GridExtent<T> {
    /// Cells span x ∈ [−fx·a, fx·a].
    pub fx: T,
    /// Strips span y ∈ [−fy·b, fy·b].
    pub fy: T,
}

impl<T: Real> GridExtent<T> {
    /// Cells and strips exactly over the ellipse (±a × ±b).
    pub fn tight() -> Self {
        Self {
            fx: T::ONE,
            fy: T::ONE,
        }
    }
    /// CONTACT's ±1.1a × ±1.1b potential-contact grid (methods.md §10.4).
    pub fn contact() -> Self {
        Self {
            fx: c(1.1),
            fy: c(1.1),
        }
    }
}

/// A Hertz ellipse (a, b, p0) as data for the `Parabolic` bound and the pressure field.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Ellipse<T> {
    /// Semi-axis along x, mm.
    pub a: T,
    /// Semi-axis along y, mm.
    pub b: T,
    /// Peak pressure p0 = 3N/(2πab), MPa.
    pub p0: T,
}

/// The strip × cell patch (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StripPatch<T, const S: usize, const C: usize> {
    /// The strips.
    pub strips: [Strip<T>; S],
    /// x of the left edge of cell 0, mm.
    pub x0: T,
    /// Cell length δx along x, mm.
    pub dx: T,
    /// Combined material (G, ν).
    pub mat: Material<T>,
}

impl<T: Real, const S: usize, const C: usize> StripPatch<T, S, C> {
    /// A patch from explicit strips on the cell grid x_i = x0 + (i+½)δx. Validates the grid and the
    /// strips (finite; δy_j > 0; a_j ≥ 0; where a_j > 0: p̂_j > 0, flexibilities and C_ij > 0).
    pub fn new(strips: [Strip<T>; S], x0: T, dx: T, mat: Material<T>) -> Result<Self, Error> {
        let p = Self {
            strips,
            x0,
            dx,
            mat,
        };
        p.validate()?;
        Ok(p)
    }

    /// Rescales every strip's p̂_j by one factor so that the semi-elliptic strip pressure sampled
    /// at the cell centres ([`SemiEllipticStrips`]) carries `load` (N): Σ_j Σ_i p_n δx δy_j = load
    /// to rounding. Returns the factor.
    ///
    /// Why: FASTSIM and FaStrip bound each cell by μ p_n of the *sampled* pressure, so a strip's
    /// and the patch's resultant never exceed μ times the sampled load; the midpoint samples of
    /// a semi-ellipse on a finite grid carry more than the strips' own load (Hertz 32 × 32:
    /// +0.19 %), and without this a solve that reports the patch's load N showed |F| = 1.0019 μN
    /// in full slip (issue 16). [`crate::adapt::region_patch`] applies the same rule to each
    /// STRIPES region.
    ///
    /// Errors: `NonPositive("load")` for a non-positive or non-finite load, `GridTooSmall("cells")`
    /// if no cell centre lies inside a strip, `NonFinite` if the factor is not finite.
    pub fn scale_to_load(&mut self, load: T) -> Result<T, Error> {
        check_positive(load, "load")?;
        let mut sum = T::ZERO;
        for j in 0..S {
            let s = self.strips[j];
            for i in 0..C {
                sum += SemiEllipticStrips.pn(j, i, self.x(i), &s) * self.dx * s.dy;
            }
        }
        if sum <= T::ZERO {
            return Err(Error::GridTooSmall("cells"));
        }
        let f = load / sum;
        if !math::is_finite(f) {
            return Err(Error::NonFinite("pressure scale"));
        }
        for s in self.strips.iter_mut() {
            if s.a > T::ZERO {
                s.p_hat *= f;
            }
        }
        Ok(f)
    }

    /// Checks everything [`StripPatch::new`] promises (solvers call it too).
    pub fn validate(&self) -> Result<(), Error> {
        if S < MIN_STRIPS {
            return Err(Error::GridTooSmall("strips"));
        }
        if C < MIN_CELLS {
            return Err(Error::GridTooSmall("cells"));
        }
        check_finite(self.x0, "x0")?;
        check_positive(self.dx, "dx")?;
        check_positive(self.mat.g, "G")?;
        check_finite(self.mat.nu, "nu")?;
        if self.mat.nu < T::ZERO || self.mat.nu >= T::HALF {
            return Err(Error::OutOfRange("nu"));
        }
        for s in self.strips.iter() {
            check_finite(s.y, "strip y")?;
            check_positive(s.dy, "strip dy")?;
            check_finite(s.a, "strip a")?;
            check_finite(s.xc, "strip xc")?;
            if s.a < T::ZERO {
                return Err(Error::NonPositive("strip a"));
            }
            if s.a > T::ZERO {
                check_positive(s.p_hat, "strip p_hat")?;
                check_positive(s.flex.l1, "L1")?;
                check_positive(s.flex.l2, "L2")?;
                check_positive(s.flex.l3, "L3")?;
                check_positive(s.c11, "C11")?;
                check_positive(s.c22, "C22")?;
                check_positive(s.c23, "C23")?;
                check_positive(s.c33, "C33")?;
                check_positive(s.sqrt_b_over_a, "sqrt(b/a)")?;
            }
        }
        if self.contact_cells() < MIN_CONTACT_CELLS {
            return Err(Error::GridTooSmall("contact cells"));
        }
        Ok(())
    }

    /// Centre x_i of cell i, mm.
    #[inline]
    pub fn x(&self, i: usize) -> T {
        self.x0 + (T::from_usize(i) + T::HALF) * self.dx
    }

    /// Whether cell i of strip j is in contact (|x_i − x_c,j| < a_j).
    #[inline]
    pub fn in_contact(&self, j: usize, i: usize) -> bool {
        match self.strips.get(j) {
            Some(s) => math::abs(self.x(i) - s.xc) < s.a,
            None => false,
        }
    }

    /// Number of cells in contact.
    pub fn contact_cells(&self) -> usize {
        let mut n = 0;
        for j in 0..S {
            for i in 0..C {
                if self.in_contact(j, i) {
                    n += 1;
                }
            }
        }
        n
    }

    /// A Hertz ellipse a × b (mm) under load N (N) discretised into S strips uniform over ±fy·b and C
    /// cells over ±fx·a, strips with exact a_j = a√(1 − y_j²/b²), x_c = 0, p̂_j = p0√(1 − y_j²/b²),
    /// Kalker flexibilities and C_ij at a/b, ν. Returns the patch and the ellipse (a, b, p0).
    /// The strips are exact (as CONTACT M=6), so the pressure sampled at the cell centres carries
    /// slightly more than N (32 × 32: +0.19 %); [`StripPatch::scale_to_load`] makes it carry N.
    pub fn hertz(
        a: T,
        b: T,
        load: T,
        mat: &Material<T>,
        ext: GridExtent<T>,
    ) -> Result<(Self, Ellipse<T>), Error> {
        check_positive(a, "a")?;
        check_positive(b, "b")?;
        check_positive(load, "N")?;
        check_finite(ext.fx, "fx")?;
        check_finite(ext.fy, "fy")?;
        if ext.fx < T::ONE || ext.fy < T::ONE || ext.fx > c(10.0) || ext.fy > c(10.0) {
            return Err(Error::OutOfRange("grid extent"));
        }
        let p0 = c::<T>(3.0) * load / (T::TWO * T::PI * a * b);
        let template = Strip::default().with_reference(a, b, mat)?;
        let dy = T::TWO * ext.fy * b / T::from_usize(S);
        let mut strips = [template; S];
        let half_s = T::from_usize(S) * T::HALF;
        for (j, s) in strips.iter_mut().enumerate() {
            // y_j = −fy·b + (j + ½)δy, written so that y_{S−1−j} = −y_j exactly in floating point
            // (mirror-symmetric strips: antisymmetric responses cancel exactly, also in f32).
            let y = (T::from_usize(j) + T::HALF - half_s) * dy;
            let q = T::ONE - (y / b) * (y / b);
            let root = if q > T::ZERO { math::sqrt(q) } else { T::ZERO };
            s.y = y;
            s.dy = dy;
            s.a = a * root;
            s.xc = T::ZERO;
            s.p_hat = p0 * root;
        }
        let dx = T::TWO * ext.fx * a / T::from_usize(C);
        let patch = Self::new(strips, -ext.fx * a, dx, *mat)?;
        Ok((patch, Ellipse { a, b, p0 }))
    }

    /// Equivalent ellipse of the contact cells as CONTACT's modified FaStrip (M=5) computes it
    /// (methods.md §4.5 item 5): a_e = √(A_c/π)√(L/W), b_e = √(A_c/π)√(W/L), with A_c the contact
    /// area (δx Σ_j δy_j × cells) and L, W the bounding box of the contact cells (cell extents).
    pub fn equivalent_ellipse(&self) -> Result<(T, T), Error> {
        let mut area = T::ZERO;
        let mut xmin = T::MAX;
        let mut xmax = -T::MAX;
        let mut ymin = T::MAX;
        let mut ymax = -T::MAX;
        for (j, s) in self.strips.iter().enumerate() {
            for i in 0..C {
                if self.in_contact(j, i) {
                    let x = self.x(i);
                    area += self.dx * s.dy;
                    xmin = math::min(xmin, x - self.dx * T::HALF);
                    xmax = math::max(xmax, x + self.dx * T::HALF);
                    ymin = math::min(ymin, s.y - s.dy * T::HALF);
                    ymax = math::max(ymax, s.y + s.dy * T::HALF);
                }
            }
        }
        if area <= T::ZERO {
            return Err(Error::NoContact);
        }
        let l = xmax - xmin;
        let w = ymax - ymin;
        let r = math::sqrt(area / T::PI);
        Ok((r * math::sqrt(l / w), r * math::sqrt(w / l)))
    }

    /// Re-derives the strips from the contact cells of `pressure` (p_n > 0) as CONTACT M=5 does and
    /// §0.3 prescribes for non-Hertz patches: per strip x_trail = min x_i − δx/2, x_lead = max x_i + δx/2
    /// over its contact cells, a_j = (x_lead − x_trail)/2, x_c,j = (x_lead + x_trail)/2. A strip whose
    /// contact cells are not one contiguous run gives `Error::TooManyRegions` (split it into two strips
    /// with [`StripPatch::new`] instead). p̂_j = 2f_j/(π a_j) with f_j = δx Σ_i p_n,ij (§3.2, §4.3).
    /// Flexibilities and FaStrip factors are kept.
    pub fn strips_from_pressure<P: PressureField<T>>(&mut self, pressure: &P) -> Result<(), Error> {
        for j in 0..S {
            let s = self.strips[j];
            let mut first: Option<usize> = None;
            let mut last = 0usize;
            let mut runs = 0usize;
            let mut prev = false;
            let mut f = T::ZERO;
            for i in 0..C {
                let pn = pressure.pn(j, i, self.x(i), &s);
                let on = pn > T::ZERO;
                if on {
                    f += pn * self.dx;
                    if first.is_none() {
                        first = Some(i);
                    }
                    last = i;
                    if !prev {
                        runs += 1;
                    }
                }
                prev = on;
            }
            if runs > 1 {
                return Err(Error::TooManyRegions);
            }
            let st = &mut self.strips[j];
            match first {
                Some(i0) => {
                    let xt = self.x0 + T::from_usize(i0) * self.dx;
                    let xl = self.x0 + T::from_usize(last + 1) * self.dx;
                    st.a = (xl - xt) * T::HALF;
                    st.xc = (xl + xt) * T::HALF;
                    st.p_hat = T::TWO * f / (T::PI * st.a);
                }
                None => {
                    st.a = T::ZERO;
                    st.xc = T::ZERO;
                    st.p_hat = T::ZERO;
                }
            }
        }
        self.validate()
    }
}

impl<T: Real, const S: usize, const C: usize> StripPatch<T, S, C> {
    /// CONTACT's "modified FaStrip" (M=5) set-up (methods.md §4.5 item 5) on this patch: strips from
    /// the contact cells of `pressure` ([`StripPatch::strips_from_pressure`]), the equivalent ellipse
    /// (a_e, b_e) of the contact cells ([`StripPatch::equivalent_ellipse`]), FaStrip factors C_ij and
    /// √(b_e/a_e) at a_e/b_e, and the global normalisation P = μ p0,e/a_e with p0,e = 3N/(2π a_e b_e)
    /// (p̂_j = p0,e a_j/a_e). The strips' FASTSIM flexibilities are kept (CONTACT computes them from
    /// the input ellipse). Returns the equivalent ellipse with p0,e.
    pub fn modified_fastrip_reference<P: PressureField<T>>(
        &mut self,
        pressure: &P,
        load: T,
    ) -> Result<Ellipse<T>, Error> {
        check_positive(load, "N")?;
        self.strips_from_pressure(pressure)?;
        let (ae, be) = self.equivalent_ellipse()?;
        let p0e = c::<T>(3.0) * load / (T::TWO * T::PI * ae * be);
        let k = kalker::coefficients(ae / be, self.mat.nu)?;
        let sq = math::sqrt(be / ae);
        for s in self.strips.iter_mut() {
            s.c11 = k.c11;
            s.c22 = k.c22;
            s.c23 = k.c23;
            s.c33 = k.c33;
            s.sqrt_b_over_a = sq;
            s.p_hat = p0e * s.a / ae;
        }
        self.validate()?;
        Ok(Ellipse {
            a: ae,
            b: be,
            p0: p0e,
        })
    }
}

/// Normal pressure p_n (MPa) at cell i of strip j (cell centre x, mm). Must return 0 outside contact.
pub trait PressureField<T> {
    /// p_n ≥ 0 at (strip j, cell i).
    fn pn(&self, j: usize, i: usize, x: T, strip: &Strip<T>) -> T;
}

/// Semi-elliptic strip pressure p̂_j √(1 − ((x − x_c,j)/a_j)²) (Hertz with exact strips; STRIPES).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SemiEllipticStrips;

impl<T: Real> PressureField<T> for SemiEllipticStrips {
    #[inline]
    fn pn(&self, _j: usize, _i: usize, x: T, s: &Strip<T>) -> T {
        if s.a <= T::ZERO {
            return T::ZERO;
        }
        let u = (x - s.xc) / s.a;
        let q = T::ONE - u * u;
        if q > T::ZERO {
            s.p_hat * math::sqrt(q)
        } else {
            T::ZERO
        }
    }
}

/// The Hertz pressure p0√(1 − x²/a² − y²/b²) of an ellipse centred at the origin, sampled at cell
/// centres (CONTACT's "actual pressure" on a Hertz case, whatever the strip half-lengths).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HertzPressure<T>(pub Ellipse<T>);

impl<T: Real> PressureField<T> for HertzPressure<T> {
    #[inline]
    fn pn(&self, _j: usize, _i: usize, x: T, s: &Strip<T>) -> T {
        let e = &self.0;
        let q = T::ONE - (x / e.a) * (x / e.a) - (s.y / e.b) * (s.y / e.b);
        if q > T::ZERO {
            e.p0 * math::sqrt(q)
        } else {
            T::ZERO
        }
    }
}

/// A per-cell pressure array `p[j][i]` (MPa), e.g. NORM's solution fed in by a host test.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CellPressure<'a, T, const S: usize, const C: usize>(pub &'a [[T; C]; S]);

impl<T: Real, const S: usize, const C: usize> PressureField<T> for CellPressure<'_, T, S, C> {
    #[inline]
    fn pn(&self, j: usize, i: usize, _x: T, _s: &Strip<T>) -> T {
        match self.0.get(j).and_then(|r| r.get(i)) {
            Some(&p) if p > T::ZERO => p,
            _ => T::ZERO,
        }
    }
}

/// Traction bound g (methods.md §3.2).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum TractionBound<T> {
    /// Kalker's parabola μ(4/3)p0(1 − x²/a² − y²/b²)₊ of the given ellipse (centred at the origin).
    Parabolic(Ellipse<T>),
    /// μ p_n from the pressure field.
    Elliptic,
    /// c μ p̂_j (1 − ((x − x_c,j)/a_j)²)₊ per strip (c = 3π/8 saturates at μN; 4/3 is seed A's).
    StripParabolic(T),
}

impl<T: Real> TractionBound<T> {
    /// The bound g (MPa) at cell centre x of strip `s` with pressure `pn`, friction `mu`.
    #[inline]
    pub fn eval(&self, mu: T, x: T, s: &Strip<T>, pn: T) -> T {
        match *self {
            TractionBound::Parabolic(e) => {
                let q = T::ONE - (x / e.a) * (x / e.a) - (s.y / e.b) * (s.y / e.b);
                if q > T::ZERO {
                    mu * c::<T>(4.0 / 3.0) * e.p0 * q
                } else {
                    T::ZERO
                }
            }
            TractionBound::Elliptic => mu * pn,
            TractionBound::StripParabolic(cf) => {
                if s.a <= T::ZERO {
                    return T::ZERO;
                }
                let u = (x - s.xc) / s.a;
                let q = T::ONE - u * u;
                if q > T::ZERO {
                    cf * mu * s.p_hat * q
                } else {
                    T::ZERO
                }
            }
        }
    }

    /// Checks the bound's parameters (finite, positive).
    pub fn check(&self) -> Result<(), Error> {
        match *self {
            TractionBound::Parabolic(e) => {
                check_positive(e.a, "bound a")?;
                check_positive(e.b, "bound b")?;
                check_positive(e.p0, "bound p0")?;
            }
            TractionBound::Elliptic => {}
            TractionBound::StripParabolic(cf) => {
                check_positive(cf, "bound c")?;
            }
        }
        Ok(())
    }

    /// Checks that the bound's peak on `patch` with friction `mu` is a finite number of MPa:
    /// c μ max_j p̂_j (`StripParabolic`), (4/3) μ p0 (`Parabolic`), μ max_j p̂_j (`Elliptic`, the
    /// strips' peak pressure). A finite but huge coefficient (e.g. `StripParabolic(f64::MAX)`)
    /// would otherwise overflow to an infinite bound in the cells and in their reported `bound`.
    ///
    /// Errors: `OutOfRange("traction bound overflows")`.
    pub fn check_on<const S: usize, const C: usize>(
        &self,
        mu: T,
        patch: &StripPatch<T, S, C>,
    ) -> Result<(), Error> {
        let mut p_max = T::ZERO;
        for s in patch.strips.iter() {
            if s.a > T::ZERO {
                p_max = math::max(p_max, s.p_hat);
            }
        }
        let peak = match *self {
            TractionBound::Parabolic(e) => mu * c::<T>(4.0 / 3.0) * e.p0,
            TractionBound::Elliptic => mu * p_max,
            TractionBound::StripParabolic(cf) => cf * mu * p_max,
        };
        if math::is_finite(peak) {
            Ok(())
        } else {
            Err(Error::OutOfRange("traction bound overflows"))
        }
    }
}

/// Results of one contact cell, handed to a [`CellSink`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct CellOut<T> {
    /// Cell centre x, mm.
    pub x: T,
    /// Strip position y, mm.
    pub y: T,
    /// Cell area δx δy_j, mm².
    pub area: T,
    /// Normal pressure p_n, MPa.
    pub pn: T,
    /// Traction bound g used, MPa (μ p_n in FaStrip's slip zone).
    pub bound: T,
    /// Tangential traction on the wheel p_x, MPa.
    pub px: T,
    /// p_y, MPa.
    pub py: T,
    /// `true` in slip, `false` in adhesion.
    pub slip: bool,
    /// Relative slip s_x (dimensionless; slip velocity / V); 0 in adhesion.
    pub sx: T,
    /// s_y.
    pub sy: T,
    /// True rigid slip w_x = ξ − φy.
    pub wx: T,
    /// w_y = η + φx.
    pub wy: T,
}

/// Receives every contact cell (cells outside contact are not reported; their traction is 0).
pub trait CellSink<T> {
    /// Cell i of strip j.
    fn cell(&mut self, j: usize, i: usize, out: &CellOut<T>);
}

/// The no-op sink for force-only calls.
impl<T> CellSink<T> for () {
    #[inline(always)]
    fn cell(&mut self, _j: usize, _i: usize, _out: &CellOut<T>) {}
}

/// A full-field buffer: stores every contact cell's result in `cells[j][i]` (exterior cells keep
/// their default, all zero).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FieldSink<T, const S: usize, const C: usize> {
    /// Per-cell results.
    pub cells: [[CellOut<T>; C]; S],
    /// Whether the cell was reported (in contact).
    pub contact: [[bool; C]; S],
}

impl<T: Real, const S: usize, const C: usize> Default for FieldSink<T, S, C> {
    fn default() -> Self {
        Self {
            cells: [[CellOut::default(); C]; S],
            contact: [[false; C]; S],
        }
    }
}

impl<T: Real, const S: usize, const C: usize> CellSink<T> for FieldSink<T, S, C> {
    fn cell(&mut self, j: usize, i: usize, out: &CellOut<T>) {
        if let Some(r) = self.cells.get_mut(j).and_then(|r| r.get_mut(i)) {
            *r = *out;
        }
        if let Some(r) = self.contact.get_mut(j).and_then(|r| r.get_mut(i)) {
            *r = true;
        }
    }
}

/// Totals of a strip or of the patch (methods.md §0.3): forces on the wheel (N), spin moment about the
/// contact-frame origin (N·mm), normal force δxδyΣp_n (N), cell counts.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Totals<T> {
    /// F_x = δxδy Σ p_x, N.
    pub fx: T,
    /// F_y = δxδy Σ p_y, N.
    pub fy: T,
    /// M_z = δxδy Σ (x p_y − y p_x), N·mm.
    pub mz: T,
    /// F_n = δxδy Σ p_n, N.
    pub fn_: T,
    /// Cells in contact.
    pub n_contact: usize,
    /// Cells in slip.
    pub n_slip: usize,
}

impl<T: Real> Totals<T> {
    /// Adds one cell.
    #[inline]
    pub fn add(&mut self, o: &CellOut<T>) {
        self.fx += o.area * o.px;
        self.fy += o.area * o.py;
        self.mz += o.area * (o.x * o.py - o.y * o.px);
        self.fn_ += o.area * o.pn;
        self.n_contact += 1;
        if o.slip {
            self.n_slip += 1;
        }
    }
    /// Adds another total.
    #[inline]
    pub fn merge(&mut self, o: &Totals<T>) {
        self.fx += o.fx;
        self.fy += o.fy;
        self.mz += o.mz;
        self.fn_ += o.fn_;
        self.n_contact += o.n_contact;
        self.n_slip += o.n_slip;
    }
}

/// Result of a tangential solve: patch totals and per-strip totals.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tangential<T, const S: usize> {
    /// Patch totals.
    pub total: Totals<T>,
    /// Per-strip totals.
    pub strips: [Totals<T>; S],
}

impl<T: Real, const S: usize> Tangential<T, S> {
    /// `Err(NonFinite("tangential result"))` unless all totals are finite (inputs so extreme that
    /// the tractions overflow, e.g. creepages ~1e300).
    pub(crate) fn checked(self) -> Result<Self, Error> {
        let t = &self.total;
        for v in [t.fx, t.fy, t.mz, t.fn_] {
            check_finite(v, "tangential result")?;
        }
        Ok(self)
    }
}

impl<T: Real, const S: usize> Default for Tangential<T, S> {
    fn default() -> Self {
        Self {
            total: Totals::default(),
            strips: [Totals::default(); S],
        }
    }
}
