//! FASTSIM, Kalker's simplified theory (methods.md §3), on a [`StripPatch`].
//!
//! Steady rolling, δq = δx: every strip is marched from the leading edge (largest x) to the trailing
//! edge; the adhesion trial p^H = p⁺ − δx (w̃_x/L1, w̃_y/L2) is clipped to the traction bound g where
//! |p^H| > g (slip, direction kept). w̃ = (ξ − (L1/L3)φy, η + (L2/L3)φx̃), x̃ = x + c_off δx, is the
//! flexibility-weighted rigid slip; the slip reported is s = w̃ + (L1(p_x − p⁺_x), L2(p_y − p⁺_y))/δx
//! (CONTACT's definition, §3.3), the true rigid slip w = (ξ − φy, η + φx) is reported too.
//! Tractions act on the wheel (§0.2): at small creepage F_x = −G ab C11 ξ.
//!
//! Cost: one pass over S × C cells, no iteration.

use crate::error::Error;
use crate::math;
use crate::patch::{
    CellOut, CellSink, Creepage, Flexibilities, PressureField, StripPatch, Tangential, Totals,
    TractionBound,
};
use crate::Real;

/// How the flexibilities of each strip are used (methods.md §3.1).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum FlexMode<T> {
    /// The strip's three flexibilities L1, L2, L3 (canonical).
    Three,
    /// CONTACT's single flexibility L_t from the strip's L1..L3; `sqrt_ab` = √(a_ref b_ref) (mm).
    Single {
        /// √(a b) of the reference ellipse, mm.
        sqrt_ab: T,
    },
    /// CONTACT's blending (needed only to reproduce CONTACT M=3/M=5 numbers) for the ellipse a, b (mm)
    /// and total normal load N (N); C11, C22 from each strip, G from the patch material.
    Blended {
        /// Semi-axis a along x, mm.
        a: T,
        /// Semi-axis b along y, mm.
        b: T,
        /// Normal load N, N.
        load: T,
    },
}

/// FASTSIM options.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FastsimSettings<T> {
    /// Coefficient of friction μ (> 0).
    pub mu: T,
    /// Traction bound (§3.2).
    pub bound: TractionBound<T>,
    /// Spin-term offset c_off in units of δx: 0 canonical (default), 1/6 CONTACT compatibility.
    pub c_off: T,
    /// Flexibility mode.
    pub flex: FlexMode<T>,
}

impl<T: Real> FastsimSettings<T> {
    /// Canonical FASTSIM: three flexibilities, c_off = 0.
    pub fn canonical(mu: T, bound: TractionBound<T>) -> Self {
        Self {
            mu,
            bound,
            c_off: T::ZERO,
            flex: FlexMode::Three,
        }
    }

    /// CONTACT M=3 compatibility: blending for the ellipse (a, b, N) and c_off = 1/6.
    pub fn contact_m3(mu: T, bound: TractionBound<T>, a: T, b: T, load: T) -> Self {
        Self {
            mu,
            bound,
            c_off: math::c(1.0 / 6.0),
            flex: FlexMode::Blended { a, b, load },
        }
    }

    pub(crate) fn check(&self) -> Result<(), Error> {
        crate::error::check_positive(self.mu, "mu")?;
        crate::error::check_finite(self.c_off, "c_off")?;
        self.bound.check()?;
        match self.flex {
            FlexMode::Three => {}
            FlexMode::Single { sqrt_ab } => {
                crate::error::check_positive(sqrt_ab, "sqrt_ab")?;
            }
            FlexMode::Blended { a, b, load } => {
                crate::error::check_positive(a, "blend a")?;
                crate::error::check_positive(b, "blend b")?;
                crate::error::check_positive(load, "blend N")?;
            }
        }
        Ok(())
    }

    /// The flexibilities used on a strip with base flexibilities `f` and C11, C22 (blending).
    pub(crate) fn strip_flex(
        &self,
        f: &Flexibilities<T>,
        cr: &Creepage<T>,
        g: T,
        c11: T,
        c22: T,
    ) -> (Flexibilities<T>, bool) {
        match self.flex {
            FlexMode::Three => (*f, false),
            FlexMode::Single { sqrt_ab } => {
                let lt = f.single(cr, sqrt_ab);
                (
                    Flexibilities {
                        l1: lt,
                        l2: lt,
                        l3: lt,
                    },
                    true,
                )
            }
            FlexMode::Blended { a, b, load } => {
                (f.blended(cr, a, b, load, self.mu, g, c11, c22), false)
            }
        }
    }
}

/// Marches strip j (leading → trailing edge) with flexibilities `fl`, calling `emit(i, &cell)` for
/// every contact cell. Cells with |x − x_c| ≥ a_j − `margin` are exterior.
#[allow(clippy::too_many_arguments)]
pub(crate) fn march_strip<T: Real, const S: usize, const C: usize, P: PressureField<T>>(
    patch: &StripPatch<T, S, C>,
    j: usize,
    pressure: &P,
    cr: &Creepage<T>,
    mu: T,
    bound: &TractionBound<T>,
    c_off: T,
    fl: &Flexibilities<T>,
    margin: T,
    mut emit: impl FnMut(usize, &CellOut<T>),
) {
    let Some(s) = patch.strips.get(j) else {
        return;
    };
    let dx = patch.dx;
    let area = dx * s.dy;
    let (l1, l2, l3) = (fl.l1, fl.l2, fl.l3);
    let wtx = cr.xi - (l1 / l3) * cr.phi * s.y;
    let mut ppx = T::ZERO;
    let mut ppy = T::ZERO;
    for ii in 0..C {
        let i = C - 1 - ii;
        let x = patch.x(i);
        let inside = math::abs(x - s.xc) < s.a - margin;
        if !inside {
            ppx = T::ZERO;
            ppy = T::ZERO;
            continue;
        }
        let pn = pressure.pn(j, i, x, s);
        let g = bound.eval(mu, x, s, pn);
        let xt = x + c_off * dx;
        let wty = cr.eta + (l2 / l3) * cr.phi * xt;
        let phx = ppx - dx * wtx / l1;
        let phy = ppy - dx * wty / l2;
        let mag = math::hypot(phx, phy);
        let (px, py, slip, sx, sy) = if mag <= g {
            (phx, phy, false, T::ZERO, T::ZERO)
        } else {
            let f = g / mag;
            let (px, py) = (phx * f, phy * f);
            (
                px,
                py,
                true,
                wtx + l1 * (px - ppx) / dx,
                wty + l2 * (py - ppy) / dx,
            )
        };
        let out = CellOut {
            x,
            y: s.y,
            area,
            pn,
            bound: g,
            px,
            py,
            slip,
            sx,
            sy,
            wx: cr.xi - cr.phi * s.y,
            wy: cr.eta + cr.phi * x,
        };
        emit(i, &out);
        ppx = px;
        ppy = py;
    }
}

/// FASTSIM on `patch` with normal pressure `pressure`, creepages `cr`; every contact cell goes to
/// `sink` (use `&mut ()` for forces only). Returns totals and per-strip totals (forces on the wheel).
///
/// Errors: invalid patch (see [`StripPatch::validate`]), non-finite creepages, μ ≤ 0 or non-finite,
/// invalid bound or flexibility-mode parameters.
pub fn fastsim<T: Real, const S: usize, const C: usize, P: PressureField<T>, K: CellSink<T>>(
    patch: &StripPatch<T, S, C>,
    pressure: &P,
    cr: &Creepage<T>,
    set: &FastsimSettings<T>,
    sink: &mut K,
) -> Result<Tangential<T, S>, Error> {
    patch.validate()?;
    cr.check()?;
    set.check()?;
    let mut res = Tangential::<T, S>::default();
    for j in 0..S {
        let s = patch.strips[j];
        if s.a <= T::ZERO {
            continue;
        }
        let (fl, _) = set.strip_flex(&s.flex, cr, patch.mat.g, s.c11, s.c22);
        let mut tot = Totals::default();
        march_strip(
            patch,
            j,
            pressure,
            cr,
            set.mu,
            &set.bound,
            set.c_off,
            &fl,
            T::ZERO,
            |i, o| {
                tot.add(o);
                sink.cell(j, i, o);
            },
        );
        res.strips[j] = tot;
        res.total.merge(&tot);
    }
    res.checked()
}
