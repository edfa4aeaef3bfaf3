//! Non-elliptic adaptations of FASTSIM and FaStrip (methods.md §5): per-strip flexibilities L1..L3
//! and FaStrip reference factors (C11, C22, C23, √(b_ref/a_ref)) for one contact region, plus the
//! default traction bound of each approach (§3.2).
//!
//! Input: a [`StripPatch`] whose strips already carry the normal solution (y_j, δy_j, a_j, x_c,j, p̂_j —
//! from STRIPES via [`region_patch`], or from a NORM pressure via
//! [`StripPatch::strips_from_pressure`]) and, for Ayasse–Chollet, the local ellipse data of each
//! strip ([`LocalEllipse`]: Hertz ratio n/m of (A, B_f) and Ã). [`apply`] then fills the flexibilities
//! and the FaStrip factors:
//!
//! * [`Adaptation::Hertz`] — one ellipse: a₀ = max a_j, b₀ = half the region width; Kalker L1..L3 and
//!   C_ij at a₀/b₀ on every strip (exact on a Hertz patch).
//! * [`Adaptation::KikPiotrowski`] — equivalent ellipse a_e = √(βA_c/π), b_e = √(A_c/(πβ)) with
//!   β = [`KpBeta`] (default L/W: area and ellipticity kept), C_ij at a_e/b_e and the constant
//!   flexibilities L_x = 2π Σa_j²δy/(G C11 A_c), L_y (C22), L_φ = 2π^{3/2} Σa_j³δy/(3 G C23 A_c^{3/2})
//!   (seed A eq. 19 with its missing 3 restored). FaStrip reference (a_e, b_e).
//! * [`Adaptation::Linder`] — common semi-width b_e = (y_R − y_L)/2, y_c = y − (y_L + y_R)/2 (clipped to
//!   0.999 b_e), a_e(y) = a_j b_e/√(b_e² − y_c²); Kalker L's and C_ij at (a_e(y), b_e); FaStrip
//!   reference (a_e(y), b_e).
//! * [`Adaptation::AyasseChollet`] — local ellipse (a_j, b_j = a_j n_j/m_j), C_ij at m_j/n_j; flexibility
//!   length per [`AcFlexLength`] (`StripA` seed A eq. 27: L = Kalker(a_j, b_j); `A0`: scaled to the
//!   region's longest strip a₀; `VirtualA`: scaled to a_loc,j = √(H/Ã_j), H = max_j h_j); FaStrip
//!   reference (a_j, b_j).
//!
//! Default bounds ([`Adaptation::default_bound`]): KP and Linder `StripParabolic(3π/8)`, AC and Hertz
//! `Elliptic` (μ p_n). FaStrip always uses μp_n in its slip zone and an `Elliptic` direction pass.

use crate::error::{check_positive, Error};
use crate::fastrip::{fastrip, FastripSettings};
use crate::fastsim::{fastsim, FastsimSettings};
use crate::kalker;
use crate::math::{self, c};
use crate::patch::{
    CellSink, Creepage, Flexibilities, PressureField, Strip, StripPatch, Tangential, TractionBound,
};
use crate::stripes::StripSet;
use crate::{Material, Real};

/// Kik–Piotrowski β(L/W) (methods.md §5.1, \[UNCERTAIN\]: the seed's empirical function is unknown).
#[derive(Clone, Copy, Debug)]
pub enum KpBeta<T> {
    /// β = L/W (CONTACT's `equiv_ellipse`; default).
    LOverW,
    /// A user function of L/W.
    Function(fn(T) -> T),
}

/// Ayasse–Chollet flexibility length (methods.md §5.3).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum AcFlexLength {
    /// a_j (seed A eq. 27; default).
    StripA,
    /// a₀ = the region's longest strip half-length.
    A0,
    /// a_loc,j = √(H/Ã_j), H = max_j h_j (Hertz-consistent).
    VirtualA,
}

/// The flexibility/reference-ellipse approach.
#[derive(Clone, Copy, Debug)]
pub enum Adaptation<T> {
    /// One ellipse for the region.
    Hertz,
    /// Kik–Piotrowski equivalent ellipse.
    KikPiotrowski(KpBeta<T>),
    /// Linder's virtual ellipses of common width.
    Linder,
    /// Ayasse–Chollet local ellipses.
    AyasseChollet(AcFlexLength),
}

impl<T: Real> Adaptation<T> {
    /// The recommended traction bound of the approach for FASTSIM (§3.2).
    pub fn default_bound(&self) -> TractionBound<T> {
        match self {
            Adaptation::KikPiotrowski(_) | Adaptation::Linder => {
                TractionBound::StripParabolic(c(3.0 * core::f64::consts::PI / 8.0))
            }
            Adaptation::Hertz | Adaptation::AyasseChollet(_) => TractionBound::Elliptic,
        }
    }
    /// The recommended default: Ayasse–Chollet with `StripA`.
    pub fn recommended() -> Self {
        Adaptation::AyasseChollet(AcFlexLength::StripA)
    }
}

/// Local ellipse data of one strip for Ayasse–Chollet: n/m of the Hertz coefficients of (A, B_f)
/// (= b/a of the local ellipse) and Ã = (n/m)² B_f (1/mm), for `VirtualA`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LocalEllipse<T> {
    /// n_j/m_j.
    pub n_over_m: T,
    /// Ã_j, 1/mm.
    pub a_tilde: T,
}

/// The tangential method.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Method {
    /// FASTSIM (§3).
    Fastsim,
    /// FaStrip (§4).
    Fastrip,
}

/// Fills flexibilities and FaStrip reference factors of the first `n` strips of `patch` (the rest
/// must be empty, a = 0). `y_lo`, `y_hi`: the region's lateral limits (mm); `local`: one entry per
/// strip (used by Ayasse–Chollet only; may be empty otherwise).
pub fn apply<T: Real, const S: usize, const C: usize>(
    patch: &mut StripPatch<T, S, C>,
    n: usize,
    y_lo: T,
    y_hi: T,
    local: &[LocalEllipse<T>],
    adapt: &Adaptation<T>,
) -> Result<(), Error> {
    let n = n.min(S);
    let mat = patch.mat;
    let width = y_hi - y_lo;
    check_positive(width, "region width")?;
    let mut a0 = T::ZERO;
    let mut area = T::ZERO;
    let mut i2 = T::ZERO;
    let mut i3 = T::ZERO;
    let mut xlo = T::MAX;
    let mut xhi = -T::MAX;
    for s in patch.strips.iter().take(n) {
        if s.a > T::ZERO {
            a0 = math::max(a0, s.a);
            area += T::TWO * s.a * s.dy;
            i2 += s.a * s.a * s.dy;
            i3 += s.a * s.a * s.a * s.dy;
            xlo = math::min(xlo, s.xc - s.a);
            xhi = math::max(xhi, s.xc + s.a);
        }
    }
    if a0 <= T::ZERO {
        return Err(Error::NoContact);
    }
    match adapt {
        Adaptation::Hertz => {
            let b0 = T::HALF * width;
            for s in patch.strips.iter_mut().take(n) {
                *s = s.with_reference(a0, b0, &mat)?;
            }
        }
        Adaptation::KikPiotrowski(beta) => {
            let lw = (xhi - xlo) / width;
            let beta = match beta {
                KpBeta::LOverW => lw,
                KpBeta::Function(f) => f(lw),
            };
            check_positive(beta, "KP beta")?;
            let ae = math::sqrt(beta * area / T::PI);
            let be = math::sqrt(area / (T::PI * beta));
            let k = kalker::coefficients(ae / be, mat.nu)?;
            let g = mat.g;
            let two_pi = T::TWO * T::PI;
            let flex = Flexibilities {
                l1: two_pi * i2 / (g * k.c11 * area),
                l2: two_pi * i2 / (g * k.c22 * area),
                l3: T::TWO * T::PI * math::sqrt(T::PI) * i3
                    / (c::<T>(3.0) * g * k.c23 * area * math::sqrt(area)),
            };
            let sq = math::sqrt(be / ae);
            for s in patch.strips.iter_mut().take(n) {
                s.flex = flex;
                s.c11 = k.c11;
                s.c22 = k.c22;
                s.c23 = k.c23;
                s.c33 = k.c33;
                s.sqrt_b_over_a = sq;
            }
        }
        Adaptation::Linder => {
            let be = T::HALF * width;
            let ym = T::HALF * (y_lo + y_hi);
            let lim = c::<T>(0.999) * be;
            for s in patch.strips.iter_mut().take(n) {
                if s.a <= T::ZERO {
                    continue;
                }
                let yc = math::clamp(s.y - ym, -lim, lim);
                let ae = s.a * be / math::sqrt(be * be - yc * yc);
                *s = s.with_reference(ae, be, &mat)?;
            }
        }
        Adaptation::AyasseChollet(len) => {
            if local.len() < n {
                return Err(Error::OutOfRange("local ellipse data"));
            }
            let mut hmax = T::ZERO;
            for (s, l) in patch.strips.iter().zip(local.iter()).take(n) {
                hmax = math::max(hmax, s.a * s.a * l.a_tilde);
            }
            for (s, l) in patch.strips.iter_mut().zip(local.iter()).take(n) {
                if s.a <= T::ZERO {
                    continue;
                }
                check_positive(l.n_over_m, "n/m")?;
                let b = s.a * l.n_over_m;
                let base = s.with_reference(s.a, b, &mat)?;
                let scale = match len {
                    AcFlexLength::StripA => T::ONE,
                    AcFlexLength::A0 => a0 / s.a,
                    AcFlexLength::VirtualA => {
                        check_positive(l.a_tilde, "A tilde")?;
                        math::sqrt(hmax / l.a_tilde) / s.a
                    }
                };
                *s = base;
                s.flex.l1 *= scale;
                s.flex.l2 *= scale;
                s.flex.l3 *= scale;
            }
        }
    }
    Ok(())
}

/// Builds the strip × cell patch of region `region` of a STRIPES [`StripSet`] and applies `adapt`.
///
/// Cells span [min(x_c − a), max(x_c + a)] of the region's strips (C cells); strips beyond the
/// region's count stay empty. p̂_j = p_max,j scaled by one factor per region so that the cell sum
/// δxΣδy_jΣp_n equals the region's STRIPES load (§0.5).
pub fn region_patch<T: Real, const S: usize, const C: usize, const SS: usize, const NR: usize>(
    set: &StripSet<T, SS, NR>,
    region: usize,
    adapt: &Adaptation<T>,
    mat: &Material<T>,
    local: &mut [LocalEllipse<T>; S],
) -> Result<StripPatch<T, S, C>, Error> {
    // The set's fields are public: counts beyond the arrays (n_regions > NR, n_strips > SS,
    // first + count overflowing) are typed errors, never an out-of-bounds index.
    if region >= set.n_regions || region >= NR {
        return Err(Error::OutOfRange("region"));
    }
    if set.n_strips > SS {
        return Err(Error::OutOfRange("strip count exceeds the set's capacity"));
    }
    let reg = set.regions[region];
    if reg.count > S {
        return Err(Error::OutOfRange("strips exceed patch capacity"));
    }
    match reg.first.checked_add(reg.count) {
        Some(end) if end <= set.n_strips => {}
        _ => return Err(Error::OutOfRange("strip index")),
    }
    let mut strips = [Strip::default(); S];
    let mut xlo = T::MAX;
    let mut xhi = -T::MAX;
    let mut dy_last = T::ONE;
    for q in 0..reg.count {
        let j = reg.first + q;
        if j >= set.n_strips {
            return Err(Error::OutOfRange("strip index"));
        }
        let s = &mut strips[q];
        s.y = set.y[j];
        s.dy = set.dy[j];
        s.a = set.a[j];
        s.xc = set.xc[j];
        s.p_hat = set.pmax[j];
        dy_last = s.dy;
        local[q] = LocalEllipse {
            n_over_m: set.n_over_m[j],
            a_tilde: set.a_tilde[j],
        };
        if s.a > T::ZERO {
            xlo = math::min(xlo, s.xc - s.a);
            xhi = math::max(xhi, s.xc + s.a);
        }
    }
    if xhi <= xlo {
        return Err(Error::NoContact);
    }
    for s in strips.iter_mut().skip(reg.count) {
        s.dy = dy_last;
    }
    let dx = (xhi - xlo) / T::from_usize(C);
    let mut patch = StripPatch {
        strips,
        x0: xlo,
        dx,
        mat: *mat,
    };
    // Rescale p̂ so the sampled pressure carries the region's load.
    patch.scale_to_load(reg.load)?;
    apply(&mut patch, reg.count, reg.y_lo, reg.y_hi, &local[..], adapt)?;
    patch.validate()?;
    Ok(patch)
}

/// One of the six (+Hertz) models on a prepared patch: `method` with the bound `bound` for FASTSIM
/// (FaStrip: μp_n slip zone, `Elliptic` direction pass, §4 defaults), friction `mu`.
pub fn solve_tangential<
    T: Real,
    const S: usize,
    const C: usize,
    P: PressureField<T>,
    K: CellSink<T>,
>(
    patch: &StripPatch<T, S, C>,
    pressure: &P,
    cr: &Creepage<T>,
    method: Method,
    bound: TractionBound<T>,
    mu: T,
    sink: &mut K,
) -> Result<Tangential<T, S>, Error> {
    match method {
        Method::Fastsim => fastsim(
            patch,
            pressure,
            cr,
            &FastsimSettings::canonical(mu, bound),
            sink,
        ),
        Method::Fastrip => fastrip(patch, pressure, cr, &FastripSettings::new(mu), sink),
    }
}
