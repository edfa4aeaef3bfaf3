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
    CellOut, CellSink, Creepage, Flexibilities, PressureField, Strip, StripPatch, Tangential,
    Totals, TractionBound,
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

/// How a slipping cell's traction is found (methods.md §3.3).
///
/// Evidence (statistical Hertzian matrix of methods.md §10.10 against the exact steady-rolling
/// solution TANG, `host-tests/src/bin/study-hertz.rs`, 3220 cases, kernel 32 × 32): see the
/// numbers in the README section "Accuracy study"; `Clip` saturates along (ξ/L1, η/L2) instead of
/// the creepage direction, which costs up to 12.9 % of μF_n at full slip when L1 ≠ L2 (a/b = 0.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum SlipRule {
    /// Seed A eqs. (7)–(8) and CONTACT: the adhesion trial p^H keeps its direction and is clipped
    /// to the bound, p = g p^H/|p^H|. Needed to reproduce CONTACT's FASTSIM numbers. The slip is then
    /// antiparallel to p only when L1 = L2.
    Clip,
    /// Coulomb's law in the cell: p = −g s/|s| with the cell's own slip
    /// s = w̃ + (L1(p_x − p⁺_x), L2(p_y − p⁺_y))/δx, i.e. p = g t with
    /// t = −((σ + gL1/δx)⁻¹ v_x, (σ + gL2/δx)⁻¹ v_y), v = w̃ − (L1 p⁺_x, L2 p⁺_y)/δx and σ = |s| the
    /// root of |t| = 1 (Newton, monotone from a lower bound, at most [`COULOMB_MAX_ITER`] steps).
    /// At large creepage the traction follows −w̃, the (flexibility-weighted) rigid slip.
    Coulomb,
    /// As [`SlipRule::Coulomb`] but with the true rigid slip w = (ξ − φy, η + φx) in place of w̃
    /// in the slipping cells: s = w + (L1(p_x − p⁺_x), L2(p_y − p⁺_y))/δx, p = −g s/|s|. The spin
    /// weighting L1/L3, L2/L3 of w̃ is Kalker's device for the linear (adhesion) regime; in slip the
    /// physical slip is w − ∂u/∂x, so at large creepage the traction follows −w as in the exact
    /// theory (methods.md §10.7). Adhesion cells are unchanged (w̃, s = 0), so the linear limit is
    /// Kalker's. FaStrip's default direction pass (evidence in [`crate::fastrip`]).
    CoulombRigidSlip,
}

/// Iteration cap of the per-cell Newton solve of [`SlipRule::Coulomb`] (it converges
/// quadratically from a bracketing start; 1–3 steps are typical).
pub const COULOMB_MAX_ITER: usize = 30;

/// The traction of a slipping cell under [`SlipRule::Coulomb`]: bound `g` (MPa), diagonal cell
/// compliances `c1` = L1/δx, `c2` = L2/δx (mm/MPa per mm) and the slip with the cell's own traction
/// removed, `v` (dimensionless). Requires |C⁻¹v| > g (the adhesion trial failed). Returns p.
///
/// σ = |s| is the root of f(σ) = Σ v_i²/(σ + g c_i)² − 1 (decreasing, convex). Newton starts from
/// σ₀ = |v| − (v_x² g c1 + v_y² g c2)/|v|², a lower bound of the root by Jensen's inequality
/// (exact when c1 = c2), and so climbs monotonically; it stops once a step is below
/// ½√ε (σ + g min c_i), after which the remaining error is below 0.4 ε (σ + g min c_i)
/// (|f''/2f'| ≤ 1.5/(σ + g min c_i)), so |p| = g to within about 2ε without normalising;
/// otherwise (iteration cap, NaN) p is normalised onto |p| = g.
#[inline]
pub(crate) fn coulomb_cell<T: Real>(g: T, c1: T, c2: T, vx: T, vy: T) -> (T, T) {
    if g <= T::ZERO {
        return (T::ZERO, T::ZERO);
    }
    let (gc1, gc2) = (g * c1, g * c2);
    let (vx2, vy2) = (vx * vx, vy * vy);
    let v2 = vx2 + vy2;
    // Jensen's lower bound of the root (the cruder |v| − max g c_i if it is not finite).
    let mut mean = math::max(gc1, gc2);
    let jensen = (vx2 * gc1 + vy2 * gc2) / v2;
    if math::is_finite(jensen) {
        mean = math::min(mean, jensen);
    }
    let mut sig = math::max(T::ZERO, math::hypot_fast(vx, vy) - mean);
    let tol = T::HALF * math::sqrt(T::EPSILON);
    let gmin = math::min(gc1, gc2);
    let mut converged = false;
    for _ in 0..COULOMB_MAX_ITER {
        let (r1, r2) = (T::ONE / (sig + gc1), T::ONE / (sig + gc2));
        let (tx, ty) = (vx * r1, vy * r2);
        let (tx2, ty2) = (tx * tx, ty * ty);
        let f = tx2 + ty2 - T::ONE;
        // −f'(σ)/2 = v_x²/d1³ + v_y²/d2³ > 0.
        let fp2 = tx2 * r1 + ty2 * r2;
        // NaN-safe: stop unless f > 0 and f' < 0 are both true.
        let descending = fp2 > T::ZERO && f > T::ZERO;
        if !descending {
            break;
        }
        let step = f / (T::TWO * fp2);
        sig += step;
        if step <= tol * (sig + gmin) {
            converged = true;
            break;
        }
    }
    let (tx, ty) = (-vx / (sig + gc1), -vy / (sig + gc2));
    if converged {
        // |t| = 1 to within 2ε: no normalisation needed.
        return (g * tx, g * ty);
    }
    let m = math::hypot_fast(tx, ty);
    if m > T::ZERO && math::is_finite(m) {
        (g * tx / m, g * ty / m)
    } else {
        let mv = math::hypot(vx, vy);
        (-g * vx / mv, -g * vy / mv)
    }
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
    /// Traction of a slipping cell.
    pub slip: SlipRule,
}

impl<T: Real> FastsimSettings<T> {
    /// Canonical FASTSIM (Kalker 1982, seed A): three flexibilities, c_off = 0, [`SlipRule::Clip`].
    pub fn canonical(mu: T, bound: TractionBound<T>) -> Self {
        Self {
            mu,
            bound,
            c_off: T::ZERO,
            flex: FlexMode::Three,
            slip: SlipRule::Clip,
        }
    }

    /// [`FastsimSettings::canonical`] with a different slip rule.
    pub fn with_slip(mu: T, bound: TractionBound<T>, slip: SlipRule) -> Self {
        Self {
            slip,
            ..Self::canonical(mu, bound)
        }
    }

    /// CONTACT M=3 compatibility: blending for the ellipse (a, b, N) and c_off = 1/6.
    pub fn contact_m3(mu: T, bound: TractionBound<T>, a: T, b: T, load: T) -> Self {
        Self {
            mu,
            bound,
            c_off: math::c(1.0 / 6.0),
            flex: FlexMode::Blended { a, b, load },
            slip: SlipRule::Clip,
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

/// The FASTSIM march along one strip (leading → trailing edge), one cell per [`March::cell`]
/// call, with the strip's constants hoisted out of the cell loop. FaStrip runs its direction
/// pass through it, fused with its own output pass.
pub(crate) struct March<T> {
    mu: T,
    bound: TractionBound<T>,
    rule: SlipRule,
    strip: Strip<T>,
    dx: T,
    area: T,
    l1: T,
    l2: T,
    /// w̃_x = ξ − (L1/L3)φ y.
    wtx: T,
    /// δx w̃_x / L1.
    kx: T,
    /// (L2/L3)φ.
    k2: T,
    /// c_off δx.
    coff_dx: T,
    /// True rigid slip w_x = ξ − φ y.
    wx: T,
    eta: T,
    phi: T,
    /// Cell compliances L1/δx, L2/δx.
    c1: T,
    c2: T,
    ppx: T,
    ppy: T,
}

impl<T: Real> March<T> {
    /// The march of strip `s` with flexibilities `fl` on cells of length `dx`.
    #[allow(clippy::too_many_arguments)]
    #[inline]
    pub(crate) fn new(
        s: &Strip<T>,
        dx: T,
        cr: &Creepage<T>,
        mu: T,
        bound: &TractionBound<T>,
        c_off: T,
        rule: SlipRule,
        fl: &Flexibilities<T>,
    ) -> Self {
        let (l1, l2, l3) = (fl.l1, fl.l2, fl.l3);
        let wtx = cr.xi - (l1 / l3) * cr.phi * s.y;
        Self {
            mu,
            bound: *bound,
            rule,
            strip: *s,
            dx,
            area: dx * s.dy,
            l1,
            l2,
            wtx,
            kx: dx * wtx / l1,
            k2: (l2 / l3) * cr.phi,
            coff_dx: c_off * dx,
            wx: cr.xi - cr.phi * s.y,
            eta: cr.eta,
            phi: cr.phi,
            c1: l1 / dx,
            c2: l2 / dx,
            ppx: T::ZERO,
            ppy: T::ZERO,
        }
    }

    /// An exterior cell: the march restarts with zero traction upstream.
    #[inline]
    pub(crate) fn reset(&mut self) {
        self.ppx = T::ZERO;
        self.ppy = T::ZERO;
    }

    /// The next contact cell (centre `x`, pressure `pn`).
    #[inline(always)]
    pub(crate) fn cell(&mut self, x: T, pn: T) -> CellOut<T> {
        let s = &self.strip;
        let (ppx, ppy) = (self.ppx, self.ppy);
        let g = self.bound.eval(self.mu, x, s, pn);
        let xt = x + self.coff_dx;
        let wty = self.eta + self.k2 * xt;
        let phx = ppx - self.kx;
        let phy = ppy - self.dx * wty / self.l2;
        let wy = self.eta + self.phi * x;
        // |p^H| ≤ g without the square root where |p^H|² is clearly below g² (the margin
        // 8ε covers the roundings: the decision is that of `hypot_fast(p^H) <= g`).
        let m2 = phx * phx + phy * phy;
        let gg = g * g;
        let clearly_in =
            gg >= T::MIN_POSITIVE && m2 < gg * (T::ONE - math::c::<T>(8.0) * T::EPSILON);
        let (px, py, slip, sx, sy) = if clearly_in {
            (phx, phy, false, T::ZERO, T::ZERO)
        } else {
            let mag = math::hypot_fast(phx, phy);
            if mag <= g {
                (phx, phy, false, T::ZERO, T::ZERO)
            } else {
                let (c1, c2) = (self.c1, self.c2);
                let (px, py) = match self.rule {
                    SlipRule::Clip => {
                        let f = g / mag;
                        (phx * f, phy * f)
                    }
                    SlipRule::Coulomb => {
                        coulomb_cell(g, c1, c2, self.wtx - c1 * ppx, wty - c2 * ppy)
                    }
                    SlipRule::CoulombRigidSlip => {
                        coulomb_cell(g, c1, c2, self.wx - c1 * ppx, wy - c2 * ppy)
                    }
                };
                (
                    px,
                    py,
                    true,
                    self.wtx + self.l1 * (px - ppx) / self.dx,
                    wty + self.l2 * (py - ppy) / self.dx,
                )
            }
        };
        self.ppx = px;
        self.ppy = py;
        CellOut {
            x,
            y: s.y,
            area: self.area,
            pn,
            bound: g,
            px,
            py,
            slip,
            sx,
            sy,
            wx: self.wx,
            wy,
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
    rule: SlipRule,
    fl: &Flexibilities<T>,
    margin: T,
    mut emit: impl FnMut(usize, &CellOut<T>),
) {
    let Some(s) = patch.strips.get(j) else {
        return;
    };
    let mut m = March::new(s, patch.dx, cr, mu, bound, c_off, rule, fl);
    let half = s.a - margin;
    for ii in 0..C {
        let i = C - 1 - ii;
        let x = patch.x(i);
        let inside = math::abs(x - s.xc) < half;
        if !inside {
            m.reset();
            continue;
        }
        let pn = pressure.pn(j, i, x, s);
        let out = m.cell(x, pn);
        emit(i, &out);
    }
}

/// FASTSIM on `patch` with normal pressure `pressure`, creepages `cr`; every contact cell goes to
/// `sink` (use `&mut ()` for forces only). Returns totals and per-strip totals (forces on the wheel).
///
/// Errors: invalid patch (see [`StripPatch::validate`]), non-finite creepages, μ ≤ 0 or non-finite,
/// invalid bound or flexibility-mode parameters, a bound that overflows on the patch
/// ([`TractionBound::check_on`]).
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
    set.bound.check_on(set.mu, patch)?;
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
            set.slip,
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The Coulomb cell solution lies on the circle |p| = g and opposes its own slip
    /// s = v + C p (C = diag(c1, c2)), also for strongly anisotropic C.
    #[test]
    fn coulomb_cell_on_circle_opposing_slip() {
        for &(c1, c2, vx, vy, g) in &[
            (2.0, 0.5, 0.7, -1.9, 0.4),
            (0.1, 3.0, -5.0, 0.2, 1.0),
            (1.0, 1.0, 0.0, 2.0, 0.5),
            (1e-3, 10.0, 1.0, 1.0, 1e-2),
        ] {
            let (px, py): (f64, f64) = coulomb_cell(g, c1, c2, vx, vy);
            assert!((px.hypot(py) - g).abs() < 1e-12 * g);
            let (sx, sy) = (vx + c1 * px, vy + c2 * py);
            let sn = sx.hypot(sy);
            assert!((px + g * sx / sn).abs() < 1e-9 * g, "{px} {sx}");
            assert!((py + g * sy / sn).abs() < 1e-9 * g, "{py} {sy}");
        }
        // Same in f32 to its precision.
        let (px, py) = coulomb_cell(0.4f32, 2.0, 0.5, 0.7, -1.9);
        let (sx, sy) = (0.7 + 2.0 * px, -1.9 + 0.5 * py);
        let sn = sx.hypot(sy);
        assert!((px + 0.4 * sx / sn).abs() < 1e-5 && (py + 0.4 * sy / sn).abs() < 1e-5);
    }
}
