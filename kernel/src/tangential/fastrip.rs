//! FaStrip (Sichani, Enblom & Berg 2016; methods.md §4) on a [`StripPatch`], in the general per-strip
//! form of §4.3 — which is the Hertzian form of §4.2 when the patch is a Hertz ellipse with exact
//! strips (P_j = μp̂_j/a_j = μp0/a, reference ellipse (a, b)).
//!
//! Per strip j (creepages made dimensionless with the strip pressure slope P_j = μ p̂_j / a_j):
//! ξ* = −(Gξ/(2P))(4(1−ν)/π²)C11, η* = −(G(1−ν)η/(2P))(4/π²)C22, φ* = −(Gφ/(2P))(3/π)√(b/a)C23,
//! X = ξ* − φ* y_j (published; the default forms X = k_x(ξ − wφ y_j) instead, k_x = ξ*/ξ,
//! w = 4aC33/(bC11), see [`SpinInX`]); slip-zone half-length d = d̃/(1−ν) with
//! d̃ = (η*² + X²)/(√Δ − η*φ*), Δ = η*² + (1 − φ*²)X² (cancellation-free root; `Contact5` rule).
//! Adhesion zone x̄ ∈ (2d − a_j, a_j] (x̄ = x − x_c,j): p = P(κS₁ − κ'S₂, λS₁ − λ'S₂),
//! S₁ = √(a_j² − x̄²), S₂ = √((a_j − d)² − (x̄ − d)²). Slip zone: p = μ p_n · p^F/|p^F| with p^F the
//! FASTSIM traction of the same cell (direction pass, any [`FastsimSettings`]).
//!
//! Numerics: S₁ − S₂ = 2d(a_j − x̄)/(S₁ + S₂) is evaluated in this form and κd, λ'd are formed
//! directly (StripTheory: κd = X/(1−ν), λ'd = η*/(1−ν)), so vanishing creepage has no 0/0 and f32
//! keeps full accuracy in the linear limit.
//!
//! Choices (methods.md \[UNCERTAIN\] items, documented and selectable):
//! * [`LambdaVariant::StripTheory`] (default, §4.4 derivation) or [`LambdaVariant::ContactCompat`]
//!   (CONTACT M=5/M=6: d instead of (1−ν)d in the spin term, then normalised to κ² + λ² = 1).
//! * [`SpinInX::Linear`] (default), [`SpinInX::RigidSlip`] or [`SpinInX::Lateral`] (published,
//!   used by the CONTACT modes and `spec_clip`): the weight of the spin in X_j (evidence below).
//! * [`LargeSpin::Contact5`] (default: same root while Δ ≥ 0 and √Δ − η*φ* > 0, else full slip) or
//!   [`LargeSpin::FullSlip`] (CONTACT M=7: full slip whenever |φ*| ≥ 1).
//! * Slip velocity ([`FastripSettings::slip_velocity`], 0 in adhesion): by default
//!   ([`SlipVelocity::StripTheory`]) from the strip solution itself — the half-plane strain of the
//!   strip's two semi-ellipses, Carter's slip s = (X_j, η)·√((a − x̄)(2d − a − x̄))/d in the
//!   partial-slip zone (the rigid slip plus the strain of the saturated semi-ellipse in full slip),
//!   pointing against the traction. The upwind form of §4.2, s = w + (u(x_i) − u(x_{i+1}))/δx with
//!   u = (L1 p_x, L2 p_y) ([`SlipVelocity::Upwind`], what CONTACT's FaStrip does), differentiates the
//!   μp_n-bounded traction, whose slope is singular at the trailing edge: on Hertz patches its
//!   frictional power ∫p|s|dA is +85 to +357 % off the grid-converged TANG value, the strip
//!   solution's +1 to +3 % without spin and +12 % with spin (host-tests `fastrip_slip`). On the
//!   wheel/rail study (FaStrip-AC on STRIPES vs TANG on NORM) the per-patch wear errors fell from
//!   111/50 % (mean peak/integral) to 20/7.5 %. The tractions and forces do not depend on this.
//! * Direction pass ([`FastripSettings::direction`]): the slip zone carries μ p_n in the direction
//!   of the FASTSIM traction of the same cell. Default: [`SlipRule::CoulombRigidSlip`] (Coulomb's
//!   law on the rigid slip in FASTSIM's slipping cells) and [`BoundCheck::Strip`]; the spec's first
//!   choice (`Clip`, no bound check) is [`FastripSettings::spec_clip`], the CONTACT modes are
//!   [`FastripSettings::contact_m5`] / [`FastripSettings::contact_m6`] (unchanged, CONTACT rows
//!   reproduced).
//!
//! Evidence for the defaults — the statistical Hertzian matrix (methods.md §10.10, 3220 cases,
//! `study-hertz`), |ΔF|/(μF_n) against TANG (Richardson 10/20 elements per semi-axis), kernel
//! 32 × 32, median / P95 / max, and |ΔM_z|/(μF_n c) median / P95:
//!
//! | FaStrip direction pass | ΔF median | P95 | max | ΔM_z median | P95 |
//! |---|---|---|---|---|---|
//! | `Clip`, no bound check (`spec_clip`) | 2.10 % | 11.0 % | 77.8 % | 1.37 % | 9.58 % |
//! | `Coulomb` (on w̃) | 0.84 % | 6.99 % | 77.7 % | 1.28 % | 7.91 % |
//! | `CoulombRigidSlip` | 0.43 % | 4.97 % | 76.4 % | 0.50 % | 5.41 % |
//! | `CoulombRigidSlip` + `LargeSpin::FullSlip` | 0.43 % | 4.46 % | 13.8 % | 0.51 % | 5.02 % |
//! | `CoulombRigidSlip` + `BoundCheck::Local` or `Strip`, `SpinInX::Lateral` | 0.43 % | 4.46 % | 13.8 % | 0.51 % | 4.76 % |
//! | the same with `SpinInX::Linear` (**default**) | 0.43 % | 3.61 % | 11.14 % | 0.37 % | 3.05 % |
//!
//! `Clip` saturates along (ξ/L1, η/L2) instead of the creepage direction (up to 12.9 % of μF_n at
//! full slip, a/b = 0.2); Coulomb's law on FASTSIM's own w̃ fixes that without spin, and the true
//! rigid slip fixes it with spin (FASTSIM's spin weights L1/L3, L2/L3 belong to the adhesion
//! regime). The 77 % maximum is `Contact5`'s root at |φ*| > 1 on a/b = 5 (η*φ* < 0): its adhesion
//! traction exceeds μ p_n near the leading edge; the bound check discards such strips (and
//! keeps `Contact5` where it is valid: the §10.5 case with φ* = −1.0019). The check compares with
//! the strip's own semi-ellipse μ p̂_j √(1 − x̄²/a_j²) (`Strip`), not with the sampled cell pressure
//! (`Local`): identical on Hertz and STRIPES patches, but on NORM pressure `Local` discarded
//! admissible strips at the edge elements (FaStrip-AC on NORM pressure, 1353 dy −2/0/6 mm against
//! TANG: eq. 31 1.26 % with `Local`, 0.98 % with `Strip`). Against the grid-converged
//! exact solution of the §10.5 case (TANG Richardson 20/40: F_y/(μN) = −0.6266) the default gives
//! −0.6291 on 220², the spec's `Clip` pass −0.6097.
//! * Spin in the longitudinal creepage ([`FastripSettings::spin_in_x`], 2026-12-02): the published
//!   X_j = ξ* − φ* y_j ([`SpinInX::Lateral`]) weights the spin by its *lateral* linear-theory
//!   coefficient, w = 3π√(b/a)C23/(4(1−ν)C11) ≈ 1.2 times the weight of ξ. In the linear limit the
//!   strips' spin moment is then −w G C11 φ a b³/4 (closed form, host-tests
//!   `elliptic_validation::fastrip_linear_spin_moment`), +42 % of Kalker's C33 at a/b = 0.1, +2 % at
//!   1, −19 % at 10; and once strips slip the x-traction changes sign at y = ξ/(wφ) instead of at the
//!   zero of the rigid slip — the largest remaining error with `Lateral` (ΔF P95 4.46 %: spin with
//!   longitudinal creepage on wide patches, a/b ≤ 0.5). The default [`SpinInX::Linear`] takes
//!   w = 4aC33/(bC11), which reproduces Kalker's C33 in the linear limit (so C11, C22, C23 and C33
//!   all hold there; F_x, F_y of the linear limit do not depend on w). [`SpinInX::RigidSlip`]
//!   (w = 1, Kalker's strip theory) is kept for comparison. Evidence (`study-hertz`, 3220 Hertzian
//!   cases, the table above; and `study-wheelrail --quick`, FaStrip-AC on the 40 sweep patches at
//!   83.3 kN against TANG, eq. 31 / floored / mean |ΔF| / max |ΔF| / mean |ΔM_z|, %):
//!
//! | `spin_in_x` | matrix ΔF median / P95 / max | matrix ΔM_z median / P95 | §10.5 case M_z (exact −4.731e4) | wheel/rail on NORM pressure | on STRIPES pressure |
//! |---|---|---|---|---|---|
//! | `Lateral` (published) | 0.43 / 4.46 / 13.75 | 0.51 / 4.76 | −4.654e4 (−1.6 %) | 2.28 / 2.03 / 0.78 / 3.00 / 1.55 | 3.04 / 2.28 / 0.80 / 5.49 / 1.76 |
//! | `RigidSlip` | 0.43 / 3.52 / 11.75 | 0.43 / 3.04 | −4.530e4 (−4.3 %) | 1.85 / 1.67 / 0.73 / 2.39 / 1.30 | 2.76 / 2.04 / 0.76 / 5.49 / 1.67 |
//! | `Linear` (**default**) | 0.43 / 3.61 / 11.14 | 0.37 / 3.05 | −4.677e4 (−1.1 %) | 1.88 / 1.68 / 0.75 / 2.74 / 1.44 | 3.07 / 2.33 / 0.82 / 5.49 / 1.69 |
//!
//!   `RigidSlip` is as good on the matrix but misses M_z on the §10.5 case (a/b = 2, where its
//!   linear-limit M_z is −19 % of Kalker's). What is left with `Linear` (P95 3.6 %, target 3 %) is
//!   a/b = 5 with ρφ/μ = 0.5 at low creepage (up to 11.1 %) and a/b = 0.2 with large spin near
//!   saturation (up to 10.2 %).
//! * CONTACT M=6 details are options: [`FastripSettings::leading_slip_retry`] and
//!   [`FastripSettings::edge_margin`]; the M=6 load heuristic of the parabolic bound is
//!   [`m6_parabolic_bound`].

use crate::error::{check_finite, check_positive, Error};
use crate::fastsim::{FastsimSettings, FlexMode, March, SlipRule};
use crate::lanes::{and, not, select2, Lanes, Pair};
use crate::math::{self, c};
use crate::patch::{
    CellOut, CellSink, Creepage, Ellipse, Flexibilities, PressureField, StripPatch, Tangential,
    Totals, TractionBound,
};
use crate::Real;

/// How λ is formed (methods.md §4.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum LambdaVariant {
    /// κ = κ' = X/d̃, λ' = η*/d̃, λ = λ' + φ* (strip-theory derivation; default).
    StripTheory,
    /// CONTACT M=5/M=6: κ = X/N, λ = (η* + φ* d)/N, N = √(X² + (η* + φ*d)²), λ' = λ − φ*.
    ContactCompat,
}

/// Strips whose strip-theory discriminant fails at large spin (methods.md §4.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum LargeSpin {
    /// CONTACT M=5: keep the root while Δ ≥ 0 and √Δ − η*φ* > 0, otherwise full slip (default).
    Contact5,
    /// CONTACT M=7: whole strip in slip whenever |φ*| ≥ 1.
    FullSlip,
}

/// How the spin enters the longitudinal creepage X_j of strip j (methods.md §4.2): X_j = k_x(ξ −
/// w φ y_j), k_x = ξ*/ξ = −(G/(2P))(4/π²)(1−ν)C11, with the weight w of this option.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum SpinInX {
    /// Published FaStrip (Sichani et al. 2016, methods.md §4.2): X_j = ξ* − φ* y_j, i.e. the spin
    /// weighted by its *lateral* linear-theory coefficient C23 (φ* = −(Gφ/(2P))(3/π)√(b/a)C23):
    /// w = 3π√(b/a)C23/(4(1−ν)C11) ≈ 1.2.
    Lateral,
    /// w = 1: each strip driven by its rigid longitudinal slip ξ − φ y_j, as in Kalker's strip
    /// theory.
    RigidSlip,
    /// w = 4aC33/(bC11) at the reference ellipse: the weight for which the strips' linear-limit
    /// spin moment, −w G C11 φ a b³/4, equals Kalker's −G c⁴ C33 φ (default). F_x, F_y of the
    /// linear limit do not depend on w (the spin part of X_j is odd in y). φ* (lateral, C23) is
    /// the same in Δ and λ for all three. See the module docs for the evidence.
    Linear,
}

/// Optional check of the strip-theory adhesion traction against the bound (CONTACT M=5).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum BoundCheck<T> {
    /// No check (default, as CONTACT M=6).
    Off,
    /// Discard strip theory for a strip (keep FASTSIM) if |p| > μ p_n in its adhesion zone.
    Local,
    /// Discard strip theory for a strip if |p| exceeds the strip's own semi-elliptic bound
    /// μ p̂_j √(1 − x̄²/a_j²) = P_j S₁ in its adhesion zone: the admissibility of the strip-theory
    /// solution under the pressure it assumes (on a Hertz patch identical to `Local`; on a sampled
    /// NORM pressure it ignores the element-wise deviations of p_n from the semi-ellipse, which
    /// otherwise discard strips whose solution is admissible).
    Strip,
    /// CONTACT M=5's weaker test: discard if |p| > the given limit μ p0 (MPa).
    Peak(T),
}

/// FaStrip options.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FastripSettings<T> {
    /// The FASTSIM pass that gives the slip-zone directions; its μ is the friction coefficient of the
    /// whole solve (default bound `Elliptic`).
    pub direction: FastsimSettings<T>,
    /// λ form.
    pub lambda: LambdaVariant,
    /// Large-spin rule.
    pub large_spin: LargeSpin,
    /// Bound check.
    pub bound_check: BoundCheck<T>,
    /// Weight of the spin in the strips' longitudinal creepage X_j.
    pub spin_in_x: SpinInX,
    /// CONTACT M=6: if the leading contact cell of a strip slips in the direction pass, repeat the
    /// pass with the single flexibility L_t (argument √(a b), mm). `None` (default): off.
    pub leading_slip_retry: Option<T>,
    /// Cells with |x − x_c,j| ≥ a_j − margin are exterior (mm; CONTACT M=6 uses 1e-3, default 0).
    pub edge_margin: T,
    /// How the slip zone's slip velocity is formed (wear and the cells' `sx`, `sy`).
    pub slip_velocity: SlipVelocity,
}

/// The slip velocity of FaStrip's slip zone (the tractions and forces do not depend on it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum SlipVelocity {
    /// From the strip solution: the half-plane strain of the strip's tractions (Carter's slip in
    /// the partial-slip zone, √-onset at the slip boundary). Default.
    StripTheory,
    /// The upwind form of methods.md §4.2, s = w + (u(x_i) − u(x_{i+1}))/δx with u = L p (what
    /// CONTACT's FaStrip does; 2–7× too fast in the trailing-edge slip band of mostly adhering
    /// patches, where L·∂p/∂x of the μp_n-bounded traction is singular).
    Upwind,
}

impl<T: Real> FastripSettings<T> {
    /// The kernel's defaults: StripTheory λ, `Contact5`, `BoundCheck::Strip`, direction pass
    /// canonical FASTSIM with the `Elliptic` bound (μ p_n) and Coulomb's law on the rigid slip in
    /// its slipping cells ([`SlipRule::CoulombRigidSlip`]). See the module docs for the evidence.
    pub fn new(mu: T) -> Self {
        Self {
            direction: FastsimSettings::with_slip(
                mu,
                TractionBound::Elliptic,
                SlipRule::CoulombRigidSlip,
            ),
            lambda: LambdaVariant::StripTheory,
            large_spin: LargeSpin::Contact5,
            bound_check: BoundCheck::Strip,
            spin_in_x: SpinInX::Linear,
            leading_slip_retry: None,
            edge_margin: T::ZERO,
            slip_velocity: SlipVelocity::StripTheory,
        }
    }

    /// The defaults of methods.md §4 as first implemented (the prototype's FaStrip without its bound
    /// check): StripTheory λ, `Contact5`, no bound check, direction pass canonical FASTSIM
    /// ([`SlipRule::Clip`]) with the `Elliptic` bound. Kept for comparison with the spec's
    /// prototype rows (methods.md §10.5).
    pub fn spec_clip(mu: T) -> Self {
        Self {
            direction: FastsimSettings::canonical(mu, TractionBound::Elliptic),
            bound_check: BoundCheck::Off,
            spin_in_x: SpinInX::Lateral,
            slip_velocity: SlipVelocity::Upwind,
            ..Self::new(mu)
        }
    }
}

impl<T: Real> FastripSettings<T> {
    /// CONTACT M=6 ("original FaStrip") on a Hertz patch with exact strips: direction pass canonical
    /// FASTSIM with the parabolic bound and the load heuristic ([`m6_parabolic_bound`]), leading-slip
    /// retry with L_t, edge margin 1e-3 mm, no bound check (methods.md §4.5 item 4).
    pub fn contact_m6(mu: T, ellipse: Ellipse<T>, lambda: LambdaVariant) -> Self {
        let mut s = Self::spec_clip(mu);
        s.direction.bound = m6_parabolic_bound(ellipse);
        s.leading_slip_retry = Some(math::sqrt(ellipse.a * ellipse.b));
        s.edge_margin = c(1e-3);
        s.lambda = lambda;
        s
    }

    /// CONTACT M=5 ("modified FaStrip"), to be used on a patch prepared with
    /// [`StripPatch::modified_fastrip_reference`]: direction pass FASTSIM with the `Elliptic` bound,
    /// blending for the input ellipse (a, b, N) and c_off = 1/6; CONTACT's peak bound check
    /// |p| > μ p0,e with the equivalent ellipse `equiv`.
    pub fn contact_m5(
        mu: T,
        a: T,
        b: T,
        load: T,
        equiv: Ellipse<T>,
        lambda: LambdaVariant,
    ) -> Self {
        let mut s = Self::spec_clip(mu);
        s.direction.flex = FlexMode::Blended { a, b, load };
        s.direction.c_off = c(1.0 / 6.0);
        s.bound_check = BoundCheck::Peak(mu * equiv.p0);
        s.lambda = lambda;
        s
    }
}

/// The M=6 load heuristic for the direction pass's parabolic bound (methods.md §4.5 item 4): the
/// ellipse with p0 computed from N(1 + (1 − a/b)⁴) when a/b < 1.
pub fn m6_parabolic_bound<T: Real>(e: Ellipse<T>) -> TractionBound<T> {
    let r = e.a / e.b;
    let mut p0 = e.p0;
    if r < T::ONE {
        let q = T::ONE - r;
        p0 *= T::ONE + q * q * q * q;
    }
    TractionBound::Parabolic(Ellipse { p0, ..e })
}

/// Strip-theory solution of one strip.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct StripSolution<T> {
    /// Pressure slope P_j = μ p̂_j/a_j, MPa/mm.
    pub slope: T,
    /// Slip-zone half-length d_j, mm (≥ a_j for full slip).
    pub d: T,
    /// `true` if the whole strip slips.
    pub full_slip: bool,
    /// κ d (mm).
    pub kd: T,
    /// λ' d (mm).
    pub ld: T,
    /// φ* (dimensionless).
    pub phi_star: T,
}

/// Strip-theory quantities of strip (y, a_j, p̂_j, C_ij) for creepages `cr`, the spin in X_j as
/// `spin_in_x` says.
#[allow(clippy::too_many_arguments)]
pub fn strip_solution<T: Real>(
    s: &crate::patch::Strip<T>,
    cr: &Creepage<T>,
    mu: T,
    g: T,
    nu: T,
    lambda: LambdaVariant,
    large_spin: LargeSpin,
    spin_in_x: SpinInX,
) -> StripSolution<T> {
    let p = mu * s.p_hat / s.a;
    let four_pi2 = c::<T>(4.0) / (T::PI * T::PI);
    let xs = -(g * cr.xi / (T::TWO * p)) * four_pi2 * (T::ONE - nu) * s.c11;
    let es = -(g * (T::ONE - nu) * cr.eta / (T::TWO * p)) * four_pi2 * s.c22;
    let ps = -(g * cr.phi / (T::TWO * p)) * (c::<T>(3.0) / T::PI) * s.sqrt_b_over_a * s.c23;
    let x = match spin_in_x {
        SpinInX::Lateral => xs - ps * s.y,
        SpinInX::RigidSlip => {
            -(g * (cr.xi - cr.phi * s.y) / (T::TWO * p)) * four_pi2 * (T::ONE - nu) * s.c11
        }
        SpinInX::Linear => {
            // w = 4 (a/b) C33/C11 with b/a = sqrt_b_over_a²
            let w = c::<T>(4.0) * s.c33 / (s.c11 * s.sqrt_b_over_a * s.sqrt_b_over_a);
            -(g * (cr.xi - w * cr.phi * s.y) / (T::TWO * p)) * four_pi2 * (T::ONE - nu) * s.c11
        }
    };
    let full = StripSolution {
        slope: p,
        d: s.a,
        full_slip: true,
        kd: T::ZERO,
        ld: T::ZERO,
        phi_star: ps,
    };
    let q = es * es + x * x;
    if q == T::ZERO {
        return StripSolution {
            slope: p,
            d: T::ZERO,
            full_slip: false,
            kd: T::ZERO,
            ld: T::ZERO,
            phi_star: ps,
        };
    }
    if large_spin == LargeSpin::FullSlip && math::abs(ps) >= T::ONE {
        return full;
    }
    let delta = es * es + (T::ONE - ps * ps) * x * x;
    // NaN-safe forms (a NaN from overflowing inputs selects full slip).
    let delta_ok = delta >= T::ZERO;
    if !delta_ok {
        return full;
    }
    let den = math::sqrt(delta) - es * ps;
    let den_ok = den > T::ZERO;
    if !den_ok {
        return full;
    }
    let dt = q / den;
    let one_m_nu = T::ONE - nu;
    let d = dt / one_m_nu;
    let partial = d < s.a;
    if !partial || !math::is_finite(d) {
        return full;
    }
    let (kd, ld) = match lambda {
        LambdaVariant::StripTheory => (x / one_m_nu, es / one_m_nu),
        LambdaVariant::ContactCompat => {
            let ly = es + ps * d;
            let nm = math::hypot(x, ly);
            if nm > T::ZERO {
                (x / nm * d, (ly / nm - ps) * d)
            } else {
                (x / one_m_nu, es / one_m_nu)
            }
        }
    };
    StripSolution {
        slope: p,
        d,
        full_slip: false,
        kd,
        ld,
        phi_star: ps,
    }
}

/// Adhesion-zone traction of strip solution `ss` at x̄ (mm) on a strip of half-length `a`
/// (`None` in the slip zone).
#[inline]
fn adhesion_traction<T: Real>(ss: &StripSolution<T>, a: T, xb: T) -> Option<(T, T)> {
    if ss.full_slip || xb <= T::TWO * ss.d - a {
        return None;
    }
    let s1 = math::sqrt(math::max(T::ZERO, a * a - xb * xb));
    let r = a - ss.d;
    let u = xb - ss.d;
    let s2 = math::sqrt(math::max(T::ZERO, r * r - u * u));
    let sum = s1 + s2;
    // (S₁ − S₂)/d = 2(a − x̄)/(S₁ + S₂).
    let diff_over_d = if sum > T::ZERO {
        T::TWO * (a - xb) / sum
    } else {
        T::ZERO
    };
    Some((
        ss.slope * ss.kd * diff_over_d,
        ss.slope * (ss.ld * diff_over_d + ss.phi_star * s1),
    ))
}

/// Slip velocity (dimensionless, s = v_slip/V) of FaStrip's slip zone from its strip solution
/// ([`SlipVelocity::StripTheory`]): the strip's half-plane strain of the tractions, as in Carter's
/// theory. The compliances are those the strip solution uses, 1/K_x with K_x = (G/2)(4/π²)C11 and
/// K_y = (G/2)(4/π²)C22 (so that P κd = −K_x X_j and P λ'd = −K_y η in adhesion).
///
/// * Partial slip (d < a): the two semi-ellipses S₁ and S₂ cancel the rigid slip in the adhesion
///   zone; in the slip zone x̄ < 2d − a only the smaller one is outside its support, and its strain
///   leaves s = −(P κd/K_x, P λ'd/K_y)·√((a − x̄)(2d − a − x̄))/d — zero at the slip boundary
///   (square-root onset), 2(X_j, η)√(a/d) at the trailing edge.
/// * Full slip: the traction μp_n u (u its direction) is a semi-ellipse of slope P along u, so
///   s = w + (P u_x x̄/K_x, P u_y x̄/K_y) with w the rigid slip.
///
/// The slip is returned opposite to the traction (Coulomb's law), with the magnitude above.
#[inline]
fn strip_slip<T: Real>(
    ss: &StripSolution<T>,
    s: &crate::patch::Strip<T>,
    g: T,
    w: (T, T),
    p: (T, T),
    xb: T,
) -> (T, T) {
    let four_pi2 = c::<T>(4.0) / (T::PI * T::PI);
    let kx = T::HALF * g * four_pi2 * s.c11;
    let ky = T::HALF * g * four_pi2 * s.c22;
    let pm = math::hypot_fast(p.0, p.1);
    if !(kx > T::ZERO && ky > T::ZERO) || pm <= T::ZERO {
        return (T::ZERO, T::ZERO);
    }
    let (ux, uy) = (p.0 / pm, p.1 / pm);
    let mag = if ss.full_slip || ss.d >= s.a {
        let sx = w.0 + ss.slope * ux * xb / kx;
        let sy = w.1 + ss.slope * uy * xb / ky;
        math::hypot_fast(sx, sy)
    } else if ss.d > T::ZERO {
        let q = math::max(T::ZERO, (s.a - xb) * (T::TWO * ss.d - s.a - xb));
        let root = math::sqrt(q) / ss.d;
        math::hypot_fast(ss.slope * ss.kd / kx, ss.slope * ss.ld / ky) * root
    } else {
        T::ZERO
    };
    (-mag * ux, -mag * uy)
}

/// FaStrip on `patch` with normal pressure `pressure` (slip zone bound μ p_n, also used by the
/// direction pass's `Elliptic` bound), creepages `cr`; every contact cell goes to `sink`.
///
/// Errors: as [`crate::fastsim::fastsim`], plus a non-finite or negative `edge_margin` or
/// `leading_slip_retry` argument.
pub fn fastrip<T: Real, const S: usize, const C: usize, P: PressureField<T>, K: CellSink<T>>(
    patch: &StripPatch<T, S, C>,
    pressure: &P,
    cr: &Creepage<T>,
    set: &FastripSettings<T>,
    sink: &mut K,
) -> Result<Tangential<T, S>, Error> {
    patch.validate()?;
    cr.check()?;
    let dset = &set.direction;
    dset.check()?;
    dset.bound.check_on(dset.mu, patch)?;
    check_finite(set.edge_margin, "edge_margin")?;
    if set.edge_margin < T::ZERO {
        return Err(Error::NonPositive("edge_margin"));
    }
    if let Some(r) = set.leading_slip_retry {
        check_positive(r, "retry sqrt_ab")?;
    }
    if let BoundCheck::Peak(l) = set.bound_check {
        check_positive(l, "bound check limit")?;
    }
    let mu = dset.mu;
    let (g, nu) = (patch.mat.g, patch.mat.nu);
    let dx = patch.dx;
    let margin = set.edge_margin;
    let rigid = dset.slip == SlipRule::CoulombRigidSlip;
    let mut res = Tangential::<T, S>::default();
    for j in 0..S {
        let s = patch.strips[j];
        if s.a <= margin {
            continue;
        }
        let half = s.a - margin;
        let ss = strip_solution(&s, cr, mu, g, nu, set.lambda, set.large_spin, set.spin_in_x);
        // Adhesion-zone tractions, computed once (by the bound check, if any) and reused.
        let mut adh = [[T::ZERO; 2]; C];
        let mut cached = false;
        // Optional bound check over the adhesion zone (independent of the direction pass).
        let mut discard = false;
        if set.bound_check != BoundCheck::Off && !ss.full_slip {
            cached = true;
            for (i, slot) in adh.iter_mut().enumerate() {
                let x = patch.x(i);
                let xb = x - s.xc;
                let inside = math::abs(xb) < half;
                if !inside {
                    continue;
                }
                if let Some((px, py)) = adhesion_traction(&ss, s.a, xb) {
                    *slot = [px, py];
                    // Clearly admissible (|p|² below the squared limit by a margin of 32ε that
                    // covers the roundings of both sides): the decision of the exact test
                    // below without its square roots.
                    let m2 = px * px + py * py;
                    let lim2 = match set.bound_check {
                        BoundCheck::Local => {
                            let l = mu * pressure.pn(j, i, x, &s);
                            l * l
                        }
                        BoundCheck::Strip => {
                            let u = xb / s.a;
                            let mp = mu * s.p_hat;
                            mp * mp * math::max(T::ZERO, T::ONE - u * u)
                        }
                        BoundCheck::Peak(l) => l * l,
                        BoundCheck::Off => T::MAX,
                    };
                    let margin2 = T::ONE + c::<T>(32.0) * T::EPSILON;
                    if lim2 >= T::MIN_POSITIVE / T::EPSILON && m2 * margin2 < lim2 {
                        continue;
                    }
                    let mag = math::hypot_fast(px, py);
                    let lim = match set.bound_check {
                        BoundCheck::Local => mu * pressure.pn(j, i, x, &s),
                        BoundCheck::Strip => {
                            let u = xb / s.a;
                            mu * s.p_hat * math::sqrt(math::max(T::ZERO, T::ONE - u * u))
                        }
                        BoundCheck::Peak(l) => l,
                        BoundCheck::Off => T::MAX,
                    };
                    if mag > lim {
                        discard = true;
                        break;
                    }
                }
            }
        }
        // One pass, leading → trailing edge: the direction pass (FASTSIM) cell by cell, and
        // FaStrip's traction of the same cell (or FASTSIM's own if the strip was discarded).
        let (fl0, _) = dset.strip_flex(&s.flex, cr, g, s.c11, s.c22);
        let mut fl = fl0;
        let new_march = |fl: &Flexibilities<T>| {
            March::new(&s, dx, cr, mu, &dset.bound, dset.c_off, dset.slip, fl)
        };
        let mut march = new_march(&fl);
        let mut first = true;
        let area = dx * s.dy;
        let wx = cr.xi - cr.phi * s.y;
        // Slip velocity on the same rigid slip as the direction pass's slipping cells.
        let mut wtx = if rigid {
            wx
        } else {
            cr.xi - (fl.l1 / fl.l3) * cr.phi * s.y
        };
        let mut up = [T::ZERO; 2]; // u of the upstream neighbour
        let mut tot = Totals::default();
        for ii in 0..C {
            let i = C - 1 - ii;
            let x = patch.x(i);
            let xb = x - s.xc;
            let inside = math::abs(xb) < half;
            if !inside {
                march.reset();
                up = [T::ZERO; 2];
                continue;
            }
            let pn = pressure.pn(j, i, x, &s);
            let mut dir = march.cell(x, pn);
            if first {
                first = false;
                // CONTACT M=6: the leading contact cell slips → the pass with L_t.
                if let (Some(sqrt_ab), true) = (set.leading_slip_retry, dir.slip) {
                    let lt = s.flex.single(cr, sqrt_ab);
                    fl = Flexibilities {
                        l1: lt,
                        l2: lt,
                        l3: lt,
                    };
                    march = new_march(&fl);
                    dir = march.cell(x, pn);
                    if !rigid {
                        wtx = cr.xi - (fl.l1 / fl.l3) * cr.phi * s.y;
                    }
                }
            }
            if discard {
                tot.add(&dir);
                sink.cell(j, i, &dir);
                continue;
            }
            let wy = cr.eta + cr.phi * x;
            let wty = if rigid {
                wy
            } else {
                cr.eta + (fl.l2 / fl.l3) * cr.phi * (x + dset.c_off * dx)
            };
            let at = if cached {
                let zone = xb > T::TWO * ss.d - s.a;
                match adh.get(i) {
                    Some(&[px, py]) if zone => Some((px, py)),
                    _ => None,
                }
            } else {
                adhesion_traction(&ss, s.a, xb)
            };
            let (px, py, slip, bound) = match at {
                Some((px, py)) => (px, py, false, mu * pn),
                None => {
                    let gb = mu * pn;
                    let (fx, fy) = (dir.px, dir.py);
                    let m = math::hypot_fast(fx, fy);
                    let (dxn, dyn_) = if m >= c(1e-10) {
                        (fx / m, fy / m)
                    } else {
                        let mw = math::hypot_fast(wx, wy);
                        if mw > T::ZERO {
                            (-wx / mw, -wy / mw)
                        } else {
                            (T::ZERO, T::ZERO)
                        }
                    };
                    (gb * dxn, gb * dyn_, true, gb)
                }
            };
            let u = [fl.l1 * px, fl.l2 * py];
            let (sx, sy) = if !slip {
                (T::ZERO, T::ZERO)
            } else if set.slip_velocity == SlipVelocity::Upwind {
                (wtx + (u[0] - up[0]) / dx, wty + (u[1] - up[1]) / dx)
            } else {
                strip_slip(&ss, &s, g, (wx, wy), (px, py), xb)
            };
            up = u;
            let o = CellOut {
                x,
                y: s.y,
                area,
                pn,
                bound,
                px,
                py,
                slip,
                sx,
                sy,
                wx,
                wy,
            };
            tot.add(&o);
            sink.cell(j, i, &o);
        }
        res.strips[j] = tot;
        res.total.merge(&tot);
    }
    res.checked()
}

/// Intervals of the slip-zone quadrature of [`strip_forces`] (uniform in θ, x̄ = −a cos θ; the
/// quarter interval comes from [`SLIP_HALVINGS`] angle halvings).
///
/// 16, not 8: where the rigid slip turns fast along a long strip — flange contact, spin φ with
/// φa comparable to |ξ| (S1002/UIC60 deep flange: a_j up to 24 mm, φ ≈ 2e-3 1/mm, ξ ≈ −3e-2) —
/// the direction's error is second order in the interval. On such a strip (host-tests
/// `realtime_cells`, the single-strip check) the closed form was 6.5 % of μN off the
/// grid-converged cell FaStrip with 8 intervals, 1.0 % with 16, 0.2 % with 32; at ξ = −5e-3 with
/// the same spin 21.9, 4.6, 0.6 %. On the issue-14 sweep the closed form's own part of the
/// flange force error went from 5.3 / 16.3 / 16.9 to 1.1 / 2.7 / 3.2 % of μF_z (median / P95 /
/// max) for +49 % instructions per real-time step (BENCHMARKS.md).
pub const SLIP_STEPS: usize = 16;
/// Angle halvings of θ_top that give the quarter interval θ_top/(4 [`SLIP_STEPS`]).
pub const SLIP_HALVINGS: usize = 6;
const _: () = assert!(1 << SLIP_HALVINGS == 4 * SLIP_STEPS);
/// Samples of the FASTSIM slip-onset search of [`strip_forces`] (then [`ONSET_BISECTIONS`]).
pub const ONSET_SAMPLES: usize = 8;
/// Bisection steps of the FASTSIM slip-onset search.
pub const ONSET_BISECTIONS: usize = 8;
/// Steps of the direction field upstream of FaStrip's slip zone (FASTSIM slipping there; 1:
/// the span's midpoint and the step's angle come from three angle halvings, doubled).
pub const UPSTREAM_STEPS: usize = 1;

/// Strips per group of the real-time step's FaStrip ([`strip_forces_lanes`], [`crate::step`]):
/// 16 on 64-bit hosts (x86_64, aarch64), whose out-of-order cores run the strips' independent
/// chains side by side and whose SIMD registers hold several lanes; 1 on the microcontrollers (in
/// order: lanes would only add register pressure). A lane's result does not depend on the group
/// (bit-identical). Measured on the real-time step's time loop (BENCHMARKS.md, x86-64 with SSE2,
/// f64 / f32 median): 21–23 / 20–21 µs one strip at a time; 15.7 / 14.5 µs by 2; 10.1 / 9.7 µs
/// by 4; 9.4 / 8.1 µs by 8; 8.2 / 6.1 µs by 16.
pub const LANES: usize = if cfg!(any(target_arch = "x86_64", target_arch = "aarch64")) {
    16
} else {
    1
};

type V<T, const N: usize> = Lanes<T, N>;

/// The continuum FASTSIM direction pass on N strips side by side (Coulomb's law on the rigid
/// slip, the default [`SlipRule::CoulombRigidSlip`]), in θ with x̄ = −a cos θ (θ = π the leading
/// edge); one lane per strip.
#[derive(Clone, Copy)]
struct DirectionField<T, const N: usize> {
    a: V<T, N>,
    /// μ p̂.
    mp: V<T, N>,
    xc: V<T, N>,
    l1: V<T, N>,
    l2: V<T, N>,
    /// ξ/L1 − φ y/L3.
    ax: V<T, N>,
    /// η/L2 + φ x_c/L3.
    b0: V<T, N>,
    /// φ/L3.
    ph: V<T, N>,
    /// Rigid slip x: ξ − φ y.
    wx: V<T, N>,
    eta: V<T, N>,
    phi: V<T, N>,
    /// L1 − L2.
    dl: V<T, N>,
    /// a / (μ p̂).
    a_mp: V<T, N>,
}

impl<T: Real> DirectionField<T, 1> {
    /// The field of one strip of half-length `a`, pressure peak `p_hat`, at lateral `y`, centre
    /// `xc`, flexibilities `l1`–`l3` (all positive).
    #[allow(clippy::too_many_arguments)]
    fn one(a: T, p_hat: T, y: T, xc: T, l: (T, T, T), cr: &Creepage<T>, mu: T) -> Self {
        let (l1, l2, l3) = l;
        let s = V::<T, 1>::splat;
        DirectionField {
            a: s(a),
            mp: s(mu * p_hat),
            xc: s(xc),
            l1: s(l1),
            l2: s(l2),
            ax: s(cr.xi / l1 - cr.phi * y / l3),
            b0: s(cr.eta / l2 + cr.phi * xc / l3),
            ph: s(cr.phi / l3),
            wx: s(cr.xi - cr.phi * y),
            eta: s(cr.eta),
            phi: s(cr.phi),
            dl: s(l1 - l2),
            a_mp: s(a / (mu * p_hat)),
        }
    }
}

impl<T: Real, const N: usize> DirectionField<T, N> {
    /// The N strips' fields side by side.
    fn gather(f: &[DirectionField<T, 1>; N]) -> Self {
        let g = |q: fn(&DirectionField<T, 1>) -> V<T, 1>| {
            let mut r = [T::ZERO; N];
            for (r, f) in r.iter_mut().zip(f) {
                *r = q(f).0[0];
            }
            Lanes(r)
        };
        DirectionField {
            a: g(|f| f.a),
            mp: g(|f| f.mp),
            xc: g(|f| f.xc),
            l1: g(|f| f.l1),
            l2: g(|f| f.l2),
            ax: g(|f| f.ax),
            b0: g(|f| f.b0),
            ph: g(|f| f.ph),
            wx: g(|f| f.wx),
            eta: g(|f| f.eta),
            phi: g(|f| f.phi),
            dl: g(|f| f.dl),
            a_mp: g(|f| f.a_mp),
        }
    }
    /// FASTSIM's adhesion traction is −a(1 + cos θ)·V(θ), V = (A_x, B₀ + (φ/L3) a(1 − cos θ)/2)
    /// (the march from the leading edge, exact for a semi-elliptic strip).
    #[inline]
    fn v(&self, cos: V<T, N>) -> Pair<T, N> {
        (
            self.ax,
            self.b0 + self.ph * self.a * (V::splat(T::ONE) - cos) * V::splat(T::HALF),
        )
    }
    /// The adhesion traction's direction at θ (a unit vector; (0, 0) without creepage).
    #[inline]
    fn adhesion_dir(&self, cos: V<T, N>) -> Pair<T, N> {
        let (vx, vy) = self.v(cos);
        let m = vx.zip(vy, math::hypot_fast);
        let zero = V::splat(T::ZERO);
        let inv = V::splat(-T::ONE) / m;
        select2(
            m.test(zero, |m, z| m > z),
            (vx * inv, vy * inv),
            (zero, zero),
        )
    }
    /// F(τ) = a²(1 − τ)|V|² − (μp̂)²τ, τ = sin²(θ/2): FASTSIM adheres where F < 0.
    #[inline]
    fn onset_fn(&self, tau: V<T, N>) -> V<T, N> {
        let (vx, vy) = self.v(V::splat(T::ONE) - V::splat(T::TWO) * tau);
        self.a * self.a * (V::splat(T::ONE) - tau) * (vx * vx + vy * vy) - self.mp * self.mp * tau
    }
    /// τ_F of FASTSIM's slip onset, the first root of F from the leading edge (τ = 1) down:
    /// [`ONSET_SAMPLES`] samples bracket it, [`ONSET_BISECTIONS`] bisections refine it (fixed
    /// counts). F(1) < 0 and F(0) ≥ 0 always. Returned: the bracket's adhering end (F < 0), so
    /// that the adhesion traction is within μp_n wherever it is used and |F| ≤ μN holds by
    /// construction; the bracket's middle put adhesion past a root that lay within the last
    /// bracket (a 147 m strip under spin 2.4e21/mm, proptest: |F| 10³¹ × μN).
    fn onset(&self) -> V<T, N> {
        let n = V::splat(T::from_usize(ONSET_SAMPLES));
        let zero = V::splat(T::ZERO);
        let (mut lo, mut hi) = (zero, V::splat(T::ONE));
        let mut found = [false; N];
        for k in (0..ONSET_SAMPLES).rev() {
            let tk = V::splat(T::from_usize(k)) / n;
            if found.iter().all(|&f| f) {
                // every lane's bracket is found (the rest would be discarded)
                continue;
            }
            let take = and(not(found), self.onset_fn(tk).test(zero, |f, z| f >= z));
            lo = V::select(take, tk, lo);
            hi = V::select(take, V::splat(T::from_usize(k + 1)) / n, hi);
            for (f, &t) in found.iter_mut().zip(&take) {
                *f = *f || t;
            }
        }
        for _ in 0..ONSET_BISECTIONS {
            let mid = (lo + hi) * V::splat(T::HALF);
            let up = self.onset_fn(mid).test(zero, |f, z| f >= z);
            lo = V::select(up, mid, lo);
            hi = V::select(up, hi, mid);
        }
        hi
    }
    /// dα/dθ of the slip-zone traction direction u at θ (cos θ, sin θ > 0): Coulomb's law on
    /// s = w − L dp/dx with |p| = μ p_n, p = μ p_n u:
    /// dα/dθ = cos θ (L1 − L2) u_x u_y / (sin θ D) − a (w × u) / (μ p̂ D), D = L1 u_y² + L2 u_x².
    #[inline]
    fn rate(&self, cos: V<T, N>, sin: V<T, N>, u: Pair<T, N>) -> V<T, N> {
        let (ux, uy) = u;
        let d = self.l1 * uy * uy + self.l2 * ux * ux;
        let wy = self.eta + self.phi * (self.xc - self.a * cos);
        let cross = self.wx * uy - wy * ux;
        (cos * self.dl * ux * uy - self.a_mp * cross * sin) / (sin * d)
    }
    /// [`Self::rate`] and the derivative with respect to α of its relaxation term
    /// −a (w × u)/(μ p̂ D) alone, −a (w · u)/(μ p̂ D) (the stiff part, for the linearly implicit
    /// step; the anisotropy term stays explicit).
    ///
    /// Third: the derivative with respect to θ, at fixed u, of the relaxation term,
    /// a φ a sin θ u_x/(μ p̂ D) (the rigid slip turns along the strip: ∂w_y/∂θ = φ a sin θ).
    #[inline]
    fn rate_and_slope(
        &self,
        cos: V<T, N>,
        sin: V<T, N>,
        u: Pair<T, N>,
    ) -> (V<T, N>, V<T, N>, V<T, N>) {
        let (ux, uy) = u;
        let d = self.l1 * uy * uy + self.l2 * ux * ux;
        let wy = self.eta + self.phi * (self.xc - self.a * cos);
        let cross = self.wx * uy - wy * ux;
        let dot = self.wx * ux + wy * uy;
        // one division: 1/(sin θ D)
        let inv = V::splat(T::ONE) / (sin * d);
        let r = (cos * self.dl * ux * uy - self.a_mp * cross * sin) * inv;
        let s2 = sin * sin * inv;
        (
            r,
            -self.a_mp * dot * sin * inv,
            self.a_mp * self.phi * self.a * ux * s2,
        )
    }
}

/// u turned by the angle β, |β| clamped to π/2, by the Cayley form: t = tan(β/2) by its series
/// to β⁹ (relative error below 2e-10 at |β| = 0.4, 4e-3 at the clamp), then
/// (cos β, sin β) = (1 − t², 2t)/(1 + t²), exactly of unit length: one division and no
/// trigonometric call.
#[inline]
fn turn<T: Real, const N: usize>(u: Pair<T, N>, beta: V<T, N>) -> Pair<T, N> {
    let q = V::<T, N>::c;
    let half_pi = V::splat(T::PI * T::HALF);
    let x = beta.clamp(-half_pi, half_pi) * V::splat(T::HALF);
    let x2 = x * x;
    let t = x
        * (V::splat(T::ONE)
            + x2 * (q(1.0 / 3.0)
                + x2 * (q(2.0 / 15.0) + x2 * (q(17.0 / 315.0) + x2 * q(62.0 / 2835.0)))));
    let t2 = t * t;
    let inv = V::splat(T::ONE) / (V::splat(T::ONE) + t2);
    let (co, si) = ((V::splat(T::ONE) - t2) * inv, V::splat(T::TWO) * t * inv);
    (u.0 * co - u.1 * si, u.0 * si + u.1 * co)
}

/// (cos, sin) of θ − h from those of θ and h.
#[inline]
fn step_down<T: Real, const N: usize>(cs: Pair<T, N>, h: Pair<T, N>) -> Pair<T, N> {
    (cs.0 * h.0 + cs.1 * h.1, cs.1 * h.0 - cs.0 * h.1)
}

/// One step of the traction direction from θ (cos/sin `a`) through the midpoint (`mid`) down
/// by h: a two-stage Rosenbrock-W method in the marching variable s = −θ for
/// dα/ds = g(s, α) = −rate,
/// W k₁ = g + γ h A_s, W k₂ = g(s + h/2, α + (h/2) k₁) − γ h A k₁, α ← α + h k₂,
/// W = 1 − γ h A, with A = w J (J the Jacobian of the relaxation term) and A_s = w ∂g/∂s (of the
/// relaxation term: the rigid slip turns along the strip).
///
/// * Order: second for any A and A_s (the W-method conditions b₁ + b₂ = 1, b₂ α = ½,
///   b₂ γ₂₁ = −γ; with b₁ = 0 and no s-term in the second stage the s-derivative enters no
///   order condition). At w = 0 it is the explicit midpoint rule.
/// * Stiffness: at w = 1 it is L-stable with γ = 1 + 1/√2 (R(∞) = 1 + (½ − 2γ)/γ² = 0), as
///   ROS2, and, with the s-derivative term of weight γ, it follows a moving equilibrium
///   exactly to first order in its speed (for α' = λ(α − α_eq(s)), λh → −∞:
///   α₁ − α_eq(s + h) = O(h² α_eq'')). Without that term it lagged the rigid slip's direction as
///   it turns along the strip, which put the lateral force of flange-contact patches (large ξ
///   with spin: ξ ≈ −5e-3 … −4e-2, φ ≈ 5e-4 … 2e-3 1/mm, S1002/UIC60 1353 mm, dy −8.5 …
///   −11.5 mm) 4.6–13 % of μN off the cell FaStrip.
/// * w rises smoothly with the stiffness z = γ h J from 0 at z = 1 to 1 at z = 2 (continuous in
///   the state; one rate and slope, one rate and two rotations per step whatever z is). The
///   relaxation towards the rigid slip's direction is stiff where a|w|/(μ p̂ L) ≫ 1/h (large
///   creepage on a lightly loaded strip): an explicit step oscillates there (the slip zone's
///   resultant fell to 0.77 μN at S1002/UIC60, dy −4.15 mm, ψ = 9.6 mrad, 28 kN). Where it is
///   mild the explicit midpoint rule is the more accurate at these step sizes: ROS2 (or Heun's
///   rule, the W-form of ROS2 at A = 0) there put the resultant's direction in flange contact
///   (nearly full slip with spin, z ≈ 1) about 1° off the cell FaStrip's, 2.3 % of μF_z (Heun's:
///   1.6 %).
///
/// Returns (the stage direction, the step's result). With `w_scale` = 0 the weight is 0 and the
/// stage is the explicit Euler step of h/2 from `a`.
#[inline(always)]
fn ros2<T: Real, const N: usize>(
    f: &DirectionField<T, N>,
    u: Pair<T, N>,
    h: V<T, N>,
    a: Pair<T, N>,
    mid: Pair<T, N>,
    w_scale: V<T, N>,
) -> (Pair<T, N>, Pair<T, N>) {
    let one = V::splat(T::ONE);
    let gamma = V::c(1.0 + core::f64::consts::FRAC_1_SQRT_2);
    let (r, dr, dt) = f.rate_and_slope(a.0, a.1, u);
    // z = γ h dr = −γ h J (g = −r, J = −dr, ∂g/∂s = ∂r/∂θ = dt); an unstable direction
    // (z < 0) is explicit
    let z = gamma * h * dr;
    let wgt = (z - one).clamp(V::splat(T::ZERO), one);
    let wgt = w_scale * wgt * wgt * (V::c(3.0) - V::splat(T::TWO) * wgt);
    let wz = wgt * z; // −γ h A
    let inv_den = one / (one + wz).max(one);
    let k1 = (wgt * gamma * h * dt - r) * inv_den;
    let stage = turn(u, h * V::splat(T::HALF) * k1);
    let k2 = (-f.rate(mid.0, mid.1, stage) + wz * k1) * inv_den;
    (stage, turn(u, h * k2))
}

/// `x`, computed whichever branch uses it: the real-time strip forces evaluate every branch
/// and select, so that their cost does not depend on the state ([`strip_forces`]); this keeps
/// the compiler from moving a branch's work into the branch (`core::hint::black_box`, timing
/// only: values are unchanged).
#[inline(always)]
fn computed<X>(x: X) -> X {
    core::hint::black_box(x)
}

/// (cos, sin) of θ/2 from those of θ ∈ [0, π] (no trigonometric call, full precision at both
/// ends).
#[inline]
fn halve<T: Real, const N: usize>(cs: Pair<T, N>) -> Pair<T, N> {
    let one = |i: usize| {
        let (co, si) = (cs.0 .0[i], cs.1 .0[i]);
        let c2 = math::sqrt(math::max(T::ZERO, (T::ONE + co) * T::HALF));
        let s2 = if c2 > c::<T>(0.7) {
            si / (T::TWO * c2)
        } else {
            math::sqrt(math::max(T::ZERO, (T::ONE - co) * T::HALF))
        };
        (c2, s2)
    };
    let (mut c2, mut s2) = cs;
    for i in 0..N {
        (c2.0[i], s2.0[i]) = one(i);
    }
    (c2, s2)
}

/// asin s for 0 ≤ s ≤ 0.4 (series to s⁹: relative error below 1e-5 at 0.4, 1e-11 at 0.1).
#[inline]
fn asin_small<T: Real, const N: usize>(s: V<T, N>) -> V<T, N> {
    let q = V::<T, N>::c;
    let s2 = s * s;
    s * (V::splat(T::ONE)
        + s2 * (q(1.0 / 6.0)
            + s2 * (q(3.0 / 40.0) + s2 * (q(5.0 / 112.0) + s2 * q(35.0 / 1152.0)))))
}

/// (cos, sin) of the angle b − a ∈ [0, π] from those of a and b.
#[inline]
fn difference<T: Real, const N: usize>(b: Pair<T, N>, a: Pair<T, N>) -> Pair<T, N> {
    (b.0 * a.0 + b.1 * a.1, b.1 * a.0 - b.0 * a.1)
}

/// ∫ μ p_n u dx̄ and ∫ x̄ μ p_n u_y dx̄ per unit width (N/mm, N) over θ ∈ [0, θ_top] (cos/sin
/// `top`), u the FASTSIM direction: the adhesion traction's direction above FASTSIM's onset θ_F
/// (cos/sin `onset`), Coulomb's law on the rigid slip below it ([`DirectionField::rate`],
/// RK2). If θ_F > θ_top the direction is first carried from θ_F down to θ_top. Angles enter
/// only through their cosines and sines (halvings and a short series): no trigonometric call.
/// Each lane is one strip; the lanes' control flow is the same (per-lane choices are selects).
fn slip_zone<T: Real, const N: usize>(
    f: &DirectionField<T, N>,
    top: Pair<T, N>,
    onset: Pair<T, N>,
) -> [(T, T, T); N] {
    // Every step below runs whatever the state (constant cost): a strip without slip zone
    // (θ_top = 0) runs on a stand-in zone θ_top = π/2 whose result is discarded; the upstream
    // march runs on a zero span where FASTSIM does not slip above θ_top; each interval computes
    // the carried direction, the adhesion direction and the march started at FASTSIM's onset,
    // and selects.
    let (zero, one) = (V::splat(T::ZERO), V::splat(T::ONE));
    // NaN must count as "no slip zone"
    let empty = not(top.0.test(one, |t, o| t < o));
    let top = select2(empty, (zero, one), top);
    // θ ≥ θ_F ⇔ cos θ ≤ cos θ_F (θ ∈ [0, π])
    let upstream = onset.0.test(top.0, |o, t| o < t);
    // the direction at θ_top, if FASTSIM already slips there: Δ = θ_F − θ_top in
    // UPSTREAM_STEPS = 1 step through its midpoint
    let span = select2(upstream, difference(onset, top), (one, zero));
    let e8 = halve(halve(halve(span)));
    let two = V::splat(T::TWO);
    let e4 = (e8.0 * e8.0 - e8.1 * e8.1, two * e8.0 * e8.1);
    let e = (e4.0 * e4.0 - e4.1 * e4.1, two * e4.0 * e4.1);
    let h = V::c(8.0) * asin_small(e8.1);
    // FASTSIM's adhesion direction at its slip onset: where both marches below start
    let v_onset = f.adhesion_dir(onset.0);
    // one step from the onset through the span's midpoint; at an onset on the leading edge
    // (sin θ_F = 0) the rate is singular there: the first stage is taken at the midpoint
    let mid = step_down(onset, e);
    let at = select2(onset.1.test(zero, |s, z| s > z), onset, mid);
    // the carried direction u, where `has` (else not yet started: FASTSIM adheres above)
    let mut u = computed(ros2(f, v_onset, h, at, mid, one).1);
    let mut has = upstream;
    // SLIP_STEPS intervals of h = θ_top/SLIP_STEPS: (cos, sin) of h/4 by SLIP_HALVINGS
    // halvings, h/2 doubled
    let mut hq = top;
    for _ in 0..SLIP_HALVINGS {
        hq = halve(hq);
    }
    let hh = (hq.0 * hq.0 - hq.1 * hq.1, two * hq.0 * hq.1);
    let h = V::c(4.0) * asin_small(hq.1);
    let (mut fx, mut fy, mut xpy) = (zero, zero, zero);
    let mut hi = top; // upper node of the interval
    let (clamp_lo, clamp_hi) = (zero, V::c(0.4));
    for k in 0..SLIP_STEPS {
        let m = step_down(hi, hh);
        // the carried direction's step: from θ_top over h/2 to the first midpoint, then from
        // the previous midpoint over h
        let (from, mid, hk) = if k == 0 {
            (top, step_down(top, hq), h * V::splat(T::HALF))
        } else {
            (step_down(hi, (hh.0, -hh.1)), hi, h)
        };
        let lo = step_down(m, hh);
        // above FASTSIM's onset: the adhesion traction's direction
        let adh = computed(f.adhesion_dir(m.0));
        // below it, one step to this midpoint: the carried direction from θ_top (h/2) or from
        // the previous midpoint (h); or, where FASTSIM's onset lies within h above this
        // midpoint, from the onset's adhesion direction over θ_F − θ_m ≤ h with the rates at
        // the midpoint (at an onset on the leading edge, sin θ_F → 0, the rate's anisotropy
        // term is singular); above the onset the same step on a zero span, discarded
        // (the onset's start is the stage of a step of 2(θ_F − θ_m), explicit: one Euler step)
        let dir = if has.iter().all(|&h| h) {
            // every lane carries its direction (after the onset): no lane to select
            let (_, full) = computed(ros2(f, u, hk, from, mid, one));
            u = full;
            full
        } else {
            let h_onset = two * asin_small(difference(onset, m).1.clamp(clamp_lo, clamp_hi));
            let start = select2(has, u, v_onset);
            let (st_hk, st_from, st_mid) = (
                V::select(has, hk, h_onset),
                select2(has, from, m),
                select2(has, mid, m),
            );
            let w_scale = V::select(has, one, zero);
            let (stage, full) = computed(ros2(f, start, st_hk, st_from, st_mid, w_scale));
            let stepped = select2(has, full, stage);
            let take_adh = and(not(has), m.0.test(onset.0, |m, o| m <= o));
            u = select2(take_adh, u, stepped);
            has = not(take_adh);
            select2(take_adh, adh, stepped)
        };
        // exact weights of the interval: ∫ sin²θ dθ, ∫ −a cos θ sin²θ dθ
        let half = V::splat(T::HALF);
        let w0 = h * half - (hi.1 * hi.0 - lo.1 * lo.0) * half;
        let wx = -f.a * (hi.1 * hi.1 * hi.1 - lo.1 * lo.1 * lo.1) / V::c(3.0);
        fx += w0 * dir.0;
        fy += w0 * dir.1;
        xpy += wx * dir.1;
        hi = lo;
    }
    // p_n dx̄ = p̂ a sin²θ dθ
    let k = f.mp * f.a;
    let (fx, fy, xpy) = (k * fx, k * fy, k * xpy);
    let mut out = [(T::ZERO, T::ZERO, T::ZERO); N];
    for (i, o) in out.iter_mut().enumerate() {
        if !empty[i] {
            *o = (fx.0[i], fy.0[i], xpy.0[i]);
        }
    }
    out
}

/// Forces of one FaStrip strip without a cell grid (the real-time step, [`crate::step`]):
/// (F_x, F_y, M_z) on the wheel, N and N·mm (M_z about the frame origin), of strip `s` (width
/// `s.dy`, semi-elliptic pressure p̂_j √(1 − x̄²/a_j²)) under creepages `cr`, friction `mu`, the
/// kernel's default FaStrip choices ([`FastripSettings::new`]: `StripTheory`, `Contact5`,
/// `BoundCheck::Strip`, [`SpinInX::Linear`], direction pass [`SlipRule::CoulombRigidSlip`]).
/// The strip's FASTSIM flexibilities are `s.flex`, or, if unset, Kalker's at its own reference
/// ellipse (a_j, a_j·(√(b/a))²), as the Ayasse–Chollet strips.
///
/// The same strip solution as [`fastrip`] ([`strip_solution`]) and the same direction pass, in
/// the continuum limit instead of on cells (x̄ = −a cos θ, θ = π at the leading edge):
/// * adhesion zone x̄ ∈ (2d − a, a]: closed forms with t = d/a,
///   ∫S₁ = a²(π/2 − asin√t − (2t − 1)√(t(1 − t))), ∫S₂ = π(a − d)²/2,
///   ∫x̄S₁ = (8/3)a³(t(1 − t))^{3/2}, ∫x̄S₂ = dπ(a − d)²/2, the differences divided by d formed
///   without cancellation;
/// * slip zone x̄ ∈ [−a, 2d − a] (θ ∈ [0, θ₁], θ₁ = 2 asin √t): μ p_n in the direction of the
///   direction pass, FASTSIM with Coulomb's law on the rigid slip. On a semi-elliptic strip its
///   march is exact in closed form up to FASTSIM's slip onset: p^F = −(a − x̄)·(ξ/L1 − φy/L3,
///   η/L2 + (φ/L3)(x_c + (a + x̄)/2)); the onset τ_F = sin²(θ_F/2) is the first root from the
///   leading edge of a²(1 − τ)|V|² = (μp̂)²τ (a cubic: [`ONSET_SAMPLES`] samples bracket it,
///   then [`ONSET_BISECTIONS`] bisections). Below the onset the direction α of p = μ p_n (cos α, sin α) follows
///   Coulomb's law on s = w − L dp/dx, w = (ξ − φy, η + φx):
///   dα/dθ = cos θ (L1 − L2) u_x u_y / (sin θ D) − a (w × u)/(μ p̂ D), D = L1 u_y² + L2 u_x²,
///   integrated on [`SLIP_STEPS`] uniform intervals in θ whose weights ∫sin²θ dθ and
///   ∫−a cos θ sin²θ dθ are exact, by a two-stage Rosenbrock-W step that is the explicit
///   midpoint rule where the relaxation towards the rigid slip is mild and L-stable (as ROS2)
///   where it is stiff, continuously in between (rotations in the Cayley form: no
///   trigonometric call); where FASTSIM already slips above the slip zone, the direction is
///   carried down to it in [`UPSTREAM_STEPS`] step (0.67 → 0.79 % of μN at pure spin against
///   two steps before the s-derivative term, 0.76 % with it, the sweep's errors unchanged, 4.5 % fewer instructions);
/// * a strip whose adhesion traction exceeds its semi-ellipse bound (`BoundCheck::Strip`, exact
///   here: |(κd q, λ'd q + φ*)| ≤ 1 for q = (S₁ − S₂)/(d S₁), convex in q, checked at the
///   leading edge q = (1 − √(1 − t))/d) carries FASTSIM's tractions, as in [`fastrip`]: p^F in
///   closed form over [x̄_F, a] and μ p_n along the direction field below.
///
/// Every count is fixed (no data-dependent iteration), and the cost does not depend on the
/// state: both adhesion forms are evaluated and one selected, the slip zone runs all its steps
/// even when it is empty (on a stand-in zone, discarded), and every interval computes the
/// carried, the adhesion and the onset's direction and selects (the real-time step's constant
/// cost, [`crate::step`]). Against [`fastrip`] on a 6 × 4 mm Hertz
/// patch with 400 cells per strip (host-tests `realtime_step`): within 0.02 % of μN up to
/// φ = 2e-4 1/mm and at large creepage (η = 1e-2), 1.2 % at pure spin φ = 1e-3 1/mm (the cell
/// FaStrip is grid-converged there: FASTSIM re-adheres inside its slip zone under spin, which
/// this direction field does not follow; with 8 intervals 0.76 %, their discretisation error
/// partly offsetting it; following the re-adhesion, a free march in closed form until |p|
/// reaches μ p_n again, brought 8 intervals to 0.35 % at 4 % more instructions per step, with no
/// change on the S1002/UIC60 sweep). In flange contact (φ ≈ 2.5e-4 1/mm, ξ ≈ −2.4e-3, nearly full
/// slip, stiffness z = γhJ ≈ 1) the resultant's direction was about 1° off the cell FaStrip's
/// (up to 2.3 % of μN of the patch) with full ROS2 from z = 1 and 1.6 % with Heun's rule below
/// z = 1; with the explicit midpoint rule below z = 1 it is within the table's own error there
/// (S1002/UIC60 sweep: force maximum 1.4 % of μF_z). Deeper in flange contact (ξ down to −4.4e-2,
/// φ up to 1.9e-3 1/mm) the closed form is within 0.16–1.2 % of μN of the cell FaStrip on the
/// converged solver's strips (host-tests `realtime_cells`), with the Rosenbrock step's
/// s-derivative term (module-private `ros2`); without it 4.6–13 %; on longer strips, where the
/// rigid slip turns by most of a half-turn, see [`SLIP_STEPS`]. Before this direction pass the slip zone
/// took the strip theory's slip direction blended into the rigid slip's, 7.9 % of μN off at
/// φ = 1e-3 and 4.3 % of μF_z in flange contact.
///
/// The resultant never exceeds μ times the strip load: the slip zone carries exactly μ p_n, the
/// adhesion zone at most μ p_n (bound check). An empty strip (a_j, p̂_j or δy not positive) has
/// no forces.
///
/// Errors: `NonFinite` for non-finite creepages or forces that overflow (inputs far beyond any
/// strip), `NonPositive` for μ or G not positive.
#[allow(clippy::neg_cmp_op_on_partial_ord)] // NaN must count as "not positive"
pub fn strip_forces<T: Real>(
    s: &crate::patch::Strip<T>,
    cr: &Creepage<T>,
    mu: T,
    g: T,
    nu: T,
) -> Result<(T, T, T), Error> {
    Ok(strip_forces_lanes::<T, 1>(&[*s], cr, mu, g, nu)?[0])
}

/// [`strip_forces`] of N strips side by side under the same creepages (one lane each; the
/// real-time step runs a slot's strips in groups of [`LANES`]): the same operations in the same order for every lane, so that each
/// result is bit-identical to that of [`strip_forces`] on its strip, whatever N. The lanes'
/// independent chains of operations run side by side on an out-of-order core (host: the
/// real-time step's FaStrip is mostly latency, BENCHMARKS.md).
///
/// Errors: as [`strip_forces`], the first lane's error in lane order.
#[allow(clippy::neg_cmp_op_on_partial_ord)] // NaN must count as "not positive"
pub fn strip_forces_lanes<T: Real, const N: usize>(
    s: &[crate::patch::Strip<T>; N],
    cr: &Creepage<T>,
    mu: T,
    g: T,
    nu: T,
) -> Result<[(T, T, T); N], Error> {
    check_finite(cr.xi, "xi")?;
    check_finite(cr.eta, "eta")?;
    check_finite(cr.phi, "phi")?;
    check_positive(mu, "mu")?;
    check_positive(g, "g")?;
    // Per strip: the strip solution, the bound check and the direction field. A lane without
    // forces (empty strip, or flexibilities not positive) runs on another lane's field and is
    // discarded.
    let mut active = [false; N];
    let mut fastsim_strip = [false; N];
    let mut sol: [Option<StripSolution<T>>; N] = [None; N];
    let mut fields: [Option<DirectionField<T, 1>>; N] = [None; N];
    for (i, s) in s.iter().enumerate() {
        if !(s.a > T::ZERO) || !(s.p_hat > T::ZERO) || !(s.dy > T::ZERO) {
            continue;
        }
        let a = s.a;
        let ss = strip_solution(
            s,
            cr,
            mu,
            g,
            nu,
            LambdaVariant::StripTheory,
            LargeSpin::Contact5,
            SpinInX::Linear,
        );
        // Bound check at the leading edge (the slip-boundary end is the equality κ² + λ² = 1):
        // a strip that fails it carries FASTSIM's tractions (as the cell FaStrip's
        // `BoundCheck::Strip`).
        if !ss.full_slip && ss.d > T::ZERO {
            let t = ss.d / a;
            let q0 = (T::ONE - math::sqrt(math::max(T::ZERO, T::ONE - t))) / ss.d;
            let (bx, by) = (ss.kd * q0, ss.ld * q0 + ss.phi_star);
            let m2 = bx * bx + by * by;
            if !(m2 <= T::ONE + c::<T>(32.0) * T::EPSILON) {
                fastsim_strip[i] = true;
            }
        } else if !ss.full_slip && !(math::abs(ss.phi_star) <= T::ONE) {
            // d = 0 (no creepage but spin-free X): adhesion traction P φ* S₁, bound P S₁.
            fastsim_strip[i] = true;
        }
        // The direction pass: FASTSIM on the strip in the continuum limit, with the strip's
        // flexibilities (if unset: Kalker's at the strip's own reference ellipse, a and
        // b = a (√(b/a))², as the Ayasse–Chollet strips).
        let (l1, l2, l3) = if s.flex.l1 > T::ZERO && s.flex.l2 > T::ZERO && s.flex.l3 > T::ZERO {
            (s.flex.l1, s.flex.l2, s.flex.l3)
        } else {
            let k = c::<T>(8.0) * a / (c::<T>(3.0) * g);
            (
                k / s.c11,
                k / s.c22,
                T::PI * a / (s.sqrt_b_over_a * c::<T>(4.0) * g * s.c23),
            )
        };
        if l1 > T::ZERO && l2 > T::ZERO && l3 > T::ZERO {
            fields[i] = Some(DirectionField::one(
                a,
                s.p_hat,
                s.y,
                s.xc,
                (l1, l2, l3),
                cr,
                mu,
            ));
            sol[i] = Some(ss);
            active[i] = true;
        }
    }
    let Some(stand_in) = fields.iter().flatten().next().copied() else {
        return Ok([(T::ZERO, T::ZERO, T::ZERO); N]);
    };
    let field = DirectionField::<T, N>::gather(&fields.map(|f| f.unwrap_or(stand_in)));
    let tau_f = field.onset();
    let (one, two) = (V::splat(T::ONE), V::splat(T::TWO));
    let onset = (
        one - two * tau_f,
        two * V::splat(T::ZERO).max(tau_f * (one - tau_f)).sqrt(),
    );
    let pi = T::PI;
    // Per strip: both adhesion zones are evaluated and one selected, and one slip zone always
    // runs (constant cost, [`computed`]).
    let mut adhesion = [(T::ZERO, T::ZERO, T::ZERO); N];
    let mut top = (V::splat(T::ZERO), V::splat(T::ZERO));
    for i in 0..N {
        let a = field.a.0[i];
        let tau_f = tau_f.0[i];
        let (ax, b0, ph) = (field.ax.0[i], field.b0.0[i], field.ph.0[i]);
        let ss = sol[i].unwrap_or(StripSolution {
            slope: T::ZERO,
            d: T::ZERO,
            full_slip: true,
            kd: T::ZERO,
            ld: T::ZERO,
            phi_star: T::ZERO,
        });
        // ∫ x̄ p_y dx̄ for the moment: M_z = ∫ (x p_y − y p_x) = x_c F_y + ∫ x̄ p_y − y F_x.
        // FASTSIM's adhesion zone x̄ ∈ [x̄_F, a], p = −(a − x̄)(A_x, B₀ + (φ/L3)(a + x̄)/2) (a
        // strip failing the bound check): with u = a − x̄ ∈ [0, U], U = 2a(1 − τ_F), closed
        // forms.
        let fastsim_adhesion = computed({
            let uu = T::TWO * a * (T::ONE - tau_f);
            let u2 = uu * uu;
            let u3 = u2 * uu;
            let cc = b0 + ph * a;
            let e = ph * T::HALF;
            (
                -ax * u2 * T::HALF,
                -(cc * u2 * T::HALF - e * u3 / c::<T>(3.0)),
                -(a * cc * u2 * T::HALF - (cc + a * e) * u3 / c::<T>(3.0)
                    + e * u2 * u2 * c::<T>(0.25)),
            )
        });
        // the strip solution's adhesion zone x̄ ∈ (2d − a, a], t = d/a (none at t = 1)
        let t = if ss.full_slip {
            T::ONE
        } else {
            math::clamp(ss.d / a, T::ZERO, T::ONE)
        };
        let strip_adhesion = computed({
            let st = math::sqrt(t);
            let as_t = math::asin(st);
            let r = math::sqrt(t * (T::ONE - t));
            let i1 = a * a * (pi * T::HALF - as_t - (T::TWO * t - T::ONE) * r);
            // (I₁ − I₂)/d and (J₁ − J₂)/d.
            let tail = if t > T::ZERO {
                (as_t - (T::ONE - T::TWO * t) * r) / t
            } else {
                T::ZERO
            };
            let d_over = a * (pi * (T::ONE - t * T::HALF) - tail);
            let omt = T::ONE - t;
            let j1 = c::<T>(8.0 / 3.0) * a * a * a * r * r * r;
            let j_over =
                a * a * (c::<T>(8.0 / 3.0) * st * omt * math::sqrt(omt) - pi * omt * omt * T::HALF);
            let p = ss.slope;
            (
                p * ss.kd * d_over,
                p * (ss.ld * d_over + ss.phi_star * i1),
                p * (ss.ld * j_over + ss.phi_star * j1),
            )
        });
        adhesion[i] = if fastsim_strip[i] {
            fastsim_adhesion
        } else if t < T::ONE {
            strip_adhesion
        } else {
            (T::ZERO, T::ZERO, T::ZERO)
        };
        // the slip zone: below FASTSIM's onset for a strip failing the bound check; else
        // θ ∈ [0, θ₁], θ₁ = 2 asin √t: sin θ₁ = 2√(t(1 − t)), cos θ₁ = 1 − 2t (none at t = 0);
        // μ p_n in the direction pass's direction
        let (c_top, s_top) = if fastsim_strip[i] {
            (onset.0 .0[i], onset.1 .0[i])
        } else {
            (
                T::ONE - T::TWO * t,
                T::TWO * math::sqrt(math::max(T::ZERO, t * (T::ONE - t))),
            )
        };
        top.0 .0[i] = c_top;
        top.1 .0[i] = s_top;
    }
    let slip = slip_zone(&field, top, onset);
    let mut out = [(T::ZERO, T::ZERO, T::ZERO); N];
    for i in 0..N {
        if !active[i] {
            continue;
        }
        let s = &s[i];
        let (fx, fy, xpy) = adhesion[i];
        let (sx, sy, sm) = slip[i];
        let (fx, fy, xpy) = (fx + sx, fy + sy, xpy + sm);
        let mz = s.xc * fy + xpy - s.y * fx;
        let o = (fx * s.dy, fy * s.dy, mz * s.dy);
        if !(math::is_finite(o.0) && math::is_finite(o.1) && math::is_finite(o.2)) {
            // only beyond any physical strip (e.g. a = 1e300 mm with p̂ = 1e-300 MPa)
            return Err(Error::NonFinite("strip forces"));
        }
        out[i] = o;
    }
    Ok(out)
}
