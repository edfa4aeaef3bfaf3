//! The strip model: a variational (Ritz) normal solve over semi-elliptic strips coupled by the
//! elastic half-space, run after STRIPES on the same samples.
//!
//! STRIPES gives every lateral sample a semi-ellipse along x whose depth comes from a local
//! Hertzian rule; it does not see the elastic displacement that the load of one strip causes at
//! the others beyond that rule. On wide, non-elliptic patches (two basins, conformal tails,
//! flange roots) that misplaces the load across y: against NORM up to 14 % in pmax on the
//! S1002/UIC60 sweep, 18 % on the tread → flange-root band, 11 % in area on Manchester.
//! The strip model keeps STRIPES' family of pressures — per strip a semi-ellipse along x about
//! the strip's rigid contact x_c, with its own load q_i and half-length a_i — and chooses the
//! loads and lengths that minimise Kalker's complementary energy
//!
//! E(q, a) = ½ qᵀ K(a) q + qᵀ h(a),  q_i ≥ 0,  Σ q_i = F,
//!
//! where K_ij = I_ij/(π E*) is the mutual compliance of strips i and j
//! ([`crate::compliance::pair`], mm/N) and h_i = f_i + A_i a_i²/4 the semi-ellipse-weighted mean
//! rigid gap of strip i (gap f_i + A_i (x − x_c)² along the strip; f_i relative to the deepest
//! sample). The multiplier of Σq = F is the approach δ (mm, from the deepest sample). Among the
//! pressures of this family the minimiser is the one closest to the elastic solution in the
//! energy norm; it needs no smoothing term and no fallback (a collocation form of the same
//! strips has spurious "needle" solutions on thin strips).
//!
//! The solve, with fixed trip counts:
//! 1. strips: the candidate samples (rigid gap below [`RitzConfig::candidate`]·δ_STRIPES) merged
//!    into strips at least [`RitzConfig::min_width`]·a_max wide (a_max the longest STRIPES
//!    half-length; finer strips on thin flange patches take needles that lower the energy by
//!    0.2 % and are not physical);
//! 2. q at fixed a: the convex quadratic programme by a primal active-set method (a Cholesky
//!    solve of the active block per step, ≤ [`RitzConfig::qp_steps`] steps), started from the
//!    STRIPES loads;
//! 3. a at fixed q: one Gauss–Seidel pass of a damped Newton step in ln a_i per loaded strip
//!    (the energy along a_i from two finite-difference rows of K, the new row evaluated exactly,
//!    the step halved once if the energy rose);
//! 4. 2 and 3 repeated [`RitzConfig::outer`] times, then 2; strips loaded for the first time by
//!    that last q-solve get one pass of 3 and the q-solve is repeated.
//!
//! `converged` is false if a q-solve hit its step cap or the final approach reached the
//! candidate bound (a strip left out could then be in contact).
#![allow(clippy::neg_cmp_op_on_partial_ord)]
// NaN must count as "not positive"
// The solve indexes parallel per-strip arrays and the rows of K together.
#![allow(clippy::needless_range_loop)]

use crate::compliance::{pair, StripShape};
use crate::error::{check_positive, Error};
use crate::math::{self, c};
use crate::stripes::{StripSample, Stripes, StripesSolution};
use crate::{Material, Real};

/// Strip-model options ([`RitzConfig::recommended`]).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct RitzConfig<T> {
    /// Smallest strip width as a fraction of the longest STRIPES half-length (dimensionless).
    pub min_width: T,
    /// Candidate samples: rigid gap below this multiple of the STRIPES approach (dimensionless,
    /// > 1).
    pub candidate: T,
    /// Outer iterations (q-solve + a-pass).
    pub outer: u32,
    /// Active-set steps per q-solve.
    pub qp_steps: u32,
    /// Finite-difference step in ln a for the a-pass (dimensionless).
    pub fd_step: T,
}

impl<T: Real> RitzConfig<T> {
    /// Defaults: strips ≥ 0.02 a_max, candidates below 1.2 δ, 2 outer iterations, ≤ 16
    /// active-set steps, finite-difference step 0.05 in ln a.
    pub fn recommended() -> Self {
        Self {
            min_width: c(0.02),
            candidate: c(1.2),
            outer: 2,
            qp_steps: 64,
            fd_step: c(0.05),
        }
    }
}

impl<T: Real> Default for RitzConfig<T> {
    fn default() -> Self {
        Self::recommended()
    }
}

/// Result of [`RitzStrips::solve`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct RitzSolution<T> {
    /// Approach δ from the deepest sample, mm.
    pub delta: T,
    /// Total normal force, N.
    pub load: T,
    /// Largest strip peak pressure, MPa.
    pub pmax: T,
    /// Contact area Σ 2 a_i w_i over the loaded strips, mm².
    pub area: T,
    /// Number of strips (candidates).
    pub strips: usize,
    /// Active-set steps, summed.
    pub qp_steps: u32,
    /// Every q-solve converged and the approach stayed below the candidate bound.
    pub converged: bool,
}

/// Largest Newton step in ln a per pass.
const MAX_STEP: f64 = 0.5;
/// Attempts at widening the strips when the candidates exceed the capacity.
const WIDEN: usize = 6;

/// The strip model's caller-owned workspace, `N` strips (memory 2N² + O(N) values: 262 KB in
/// f64 at N = 128).
#[derive(Clone, Debug)]
pub struct RitzStrips<T, const N: usize> {
    shape: [StripShape<T>; N],
    f: [T; N],
    ca: [T; N],
    q: [T; N],
    qn: [T; N],
    u: [T; N],
    v: [T; N],
    row: [[T; N]; 3],
    act: [bool; N],
    idx: [usize; N],
    k: [[T; N]; N],
    l: [[T; N]; N],
    n: usize,
}

impl<T: Real, const N: usize> RitzStrips<T, N> {
    /// Empty workspace (const: can live in a `static`).
    pub const fn new() -> Self {
        Self {
            shape: [StripShape {
                y: T::ZERO,
                w: T::ZERO,
                xc: T::ZERO,
                a: T::ZERO,
            }; N],
            f: [T::ZERO; N],
            ca: [T::ZERO; N],
            q: [T::ZERO; N],
            qn: [T::ZERO; N],
            u: [T::ZERO; N],
            v: [T::ZERO; N],
            row: [[T::ZERO; N]; 3],
            act: [false; N],
            idx: [0; N],
            k: [[T::ZERO; N]; N],
            l: [[T::ZERO; N]; N],
            n: 0,
        }
    }

    /// Number of strips of the last solve.
    pub fn len(&self) -> usize {
        self.n
    }

    /// `true` before the first successful solve.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// Strip `i` of the last solve: its shape (y, w, x_c, a in mm), load q_i (N) and peak
    /// pressure p̂_i = 2 q_i/(π a_i w_i) (MPa); `None` beyond the strip count.
    pub fn strip(&self, i: usize) -> Option<(StripShape<T>, T, T)> {
        if i >= self.n {
            return None;
        }
        let s = self.shape[i];
        let p = if self.q[i] > T::ZERO {
            T::TWO * self.q[i] / (c::<T>(core::f64::consts::PI) * s.a * s.w)
        } else {
            T::ZERO
        };
        Some((s, self.q[i], p))
    }

    /// Solves the strip model on `samples` at total load `load` (N), after STRIPES (`stripes`
    /// holds its solution `sol` of the same samples and load): see the module docs.
    ///
    /// Errors: `NonPositive`/`NonFinite` load, `NoContact` if STRIPES has no loaded sample,
    /// `GridTooSmall("ritz strips")` if the candidates exceed `N` strips even when widened
    /// 64-fold, `NonFinite("ritz")` if the solve produced a non-finite value.
    pub fn solve<const NS: usize, const NB: usize, const NR: usize>(
        &mut self,
        samples: &[StripSample<T>],
        stripes: &Stripes<T, NS, NB, NR>,
        sol: &StripesSolution<T, NR>,
        load: T,
        mat: &Material<T>,
        cfg: &RitzConfig<T>,
    ) -> Result<RitzSolution<T>, Error> {
        check_positive(load, "load")?;
        let ns = samples.len().min(stripes.len());
        if ns == 0 {
            return Err(Error::NoContact);
        }
        let zmin = samples[..ns]
            .iter()
            .fold(samples[0].z, |m, s| math::min(m, s.z));
        let mut a_max = T::ZERO;
        for i in 0..ns {
            a_max = math::max(a_max, stripes.half_length(i));
        }
        let delta_s = sol.delta;
        if a_max <= T::ZERO || !(delta_s > T::ZERO) {
            return Err(Error::NoContact);
        }
        let bound = cfg.candidate * delta_s;
        // 1. strips
        let mut wmin = cfg.min_width * a_max;
        let mut built = false;
        for _ in 0..WIDEN {
            if self.build(samples, stripes, zmin, bound, wmin) {
                built = true;
                break;
            }
            wmin *= T::TWO;
        }
        if !built {
            return Err(Error::GridTooSmall("ritz strips"));
        }
        let n = self.n;
        let pe = c::<T>(core::f64::consts::PI) * mat.e_star;
        // initial a for strips STRIPES leaves unloaded: the rigid-indentation length at the
        // STRIPES approach (at least 5 % of it)
        for i in 0..n {
            if !(self.shape[i].a > T::ZERO) {
                let h = math::max(delta_s - self.f[i], c::<T>(0.05) * delta_s);
                self.shape[i].a = c::<T>(0.7) * math::sqrt(h / self.ca[i]);
            }
        }
        for i in 0..n {
            for j in i..n {
                let kij = pair(&self.shape[i], &self.shape[j]) / pe;
                self.k[i][j] = kij;
                self.k[j][i] = kij;
            }
        }
        // feasible start: the STRIPES loads scaled to F
        let q0: T = self.q[..n].iter().fold(T::ZERO, |s, &x| s + x);
        if !(q0 > T::ZERO) {
            return Err(Error::NoContact);
        }
        for i in 0..n {
            self.q[i] = self.q[i] * load / q0;
        }
        let mut out = RitzSolution {
            strips: n,
            converged: true,
            ..RitzSolution::default()
        };
        for _ in 0..cfg.outer {
            let (steps, ok, _) = self.qp(load, cfg.qp_steps);
            out.qp_steps += steps;
            out.converged &= ok;
            self.a_pass(pe, cfg.fd_step, None);
        }
        // last q-solve; strips loaded for the first time get their a-pass and a repeat
        let mut fresh = [false; N];
        for i in 0..n {
            fresh[i] = !(self.q[i] > T::ZERO);
        }
        let (steps, ok, d) = self.qp(load, cfg.qp_steps);
        out.qp_steps += steps;
        out.converged &= ok;
        let mut delta = d;
        let mut any = false;
        for i in 0..n {
            fresh[i] &= self.q[i] > T::ZERO;
            any |= fresh[i];
        }
        if any {
            self.a_pass(pe, cfg.fd_step, Some(&fresh));
            let (steps, ok, d) = self.qp(load, cfg.qp_steps);
            out.qp_steps += steps;
            out.converged &= ok;
            delta = d;
        }
        out.delta = delta;
        out.converged &= delta < bound;
        for i in 0..n {
            if let Some((s, q, p)) = self.strip(i) {
                if q > T::ZERO {
                    out.load += q;
                    out.pmax = math::max(out.pmax, p);
                    out.area += T::TWO * s.a * s.w;
                }
            }
        }
        if !(T::is_finite(out.delta) && T::is_finite(out.pmax) && T::is_finite(out.area)) {
            return Err(Error::NonFinite("ritz"));
        }
        Ok(out)
    }

    /// Merges the candidate samples into strips ≥ `wmin` wide; `false` if they exceed `N`.
    /// Fills shape (a = the width-weighted STRIPES half-length), f, ca and q (STRIPES loads).
    fn build<const NS: usize, const NB: usize, const NR: usize>(
        &mut self,
        samples: &[StripSample<T>],
        st: &Stripes<T, NS, NB, NR>,
        zmin: T,
        bound: T,
        wmin: T,
    ) -> bool {
        let ns = samples.len().min(st.len());
        let half_pi = c::<T>(core::f64::consts::FRAC_PI_2);
        let mut n = 0usize;
        let mut open = false; // a strip is being accumulated
        let mut run_first = 0usize; // first strip of the current candidate run
        let (mut lo, mut hi) = (T::ZERO, T::ZERO);
        let (mut sw, mut sf, mut sa, mut sx, mut sl, mut sq) =
            (T::ZERO, T::ZERO, T::ZERO, T::ZERO, T::ZERO, T::ZERO);
        for i in 0..=ns {
            let cand = i < ns && samples[i].z - zmin < bound;
            if cand {
                let s = &samples[i];
                if !open {
                    if n == N {
                        return false;
                    }
                    lo = s.y - T::HALF * s.dy;
                    sw = T::ZERO;
                    sf = T::ZERO;
                    sa = T::ZERO;
                    sx = T::ZERO;
                    sl = T::ZERO;
                    sq = T::ZERO;
                    open = true;
                }
                hi = s.y + T::HALF * s.dy;
                let al = st.half_length(i);
                sw += s.dy;
                sf += s.dy * (s.z - zmin);
                sa += s.dy * s.curv_a;
                sx += s.dy * s.xc;
                sl += s.dy * al;
                sq += half_pi * st.peak_pressure(i) * al * s.dy;
            }
            let run_ends = !cand && open;
            if open && (sw >= wmin || run_ends) {
                // a narrow last strip of a run joins the previous strip of the same run
                let merge = run_ends && sw < T::HALF * wmin && n > run_first;
                if merge {
                    let p = n - 1;
                    let wp = self.shape[p].w;
                    let wt = wp + sw;
                    self.f[p] = (self.f[p] * wp + sf) / wt;
                    self.ca[p] = (self.ca[p] * wp + sa) / wt;
                    self.shape[p].xc = (self.shape[p].xc * wp + sx) / wt;
                    self.shape[p].a = (self.shape[p].a * wp + sl) / wt;
                    let lo_p = self.shape[p].y - T::HALF * wp;
                    self.shape[p].w = hi - lo_p;
                    self.shape[p].y = T::HALF * (lo_p + hi);
                    self.q[p] += sq;
                } else {
                    self.shape[n] = StripShape {
                        y: T::HALF * (lo + hi),
                        w: hi - lo,
                        xc: sx / sw,
                        a: sl / sw,
                    };
                    self.f[n] = sf / sw;
                    self.ca[n] = sa / sw;
                    self.q[n] = sq;
                    n += 1;
                }
                open = false;
            }
            if !cand {
                run_first = n;
            }
        }
        self.n = n;
        n > 0
    }

    /// h_i = f_i + A_i a_i²/4.
    #[inline]
    fn h(&self, i: usize) -> T {
        let a = self.shape[i].a;
        self.f[i] + self.ca[i] * a * a * c::<T>(0.25)
    }

    /// Convex q-solve at fixed a (primal active set from the feasible q, active set `act`).
    /// Returns (steps, converged, δ).
    fn qp(&mut self, load: T, cap: u32) -> (u32, bool, T) {
        let n = self.n;
        for i in 0..n {
            self.act[i] = self.q[i] > T::ZERO;
        }
        if !self.act[..n].iter().any(|&x| x) {
            let mut best = 0;
            for i in 1..n {
                if self.h(i) < self.h(best) {
                    best = i;
                }
            }
            self.act[best] = true;
            self.q[best] = load;
        }
        let mut delta = T::ZERO;
        let mut steps = 0u32;
        let mut converged = false;
        for _ in 0..cap {
            steps += 1;
            // active block
            let mut m = 0;
            for i in 0..n {
                if self.act[i] {
                    self.idx[m] = i;
                    m += 1;
                }
            }
            if !self.cholesky(m) {
                break;
            }
            // K u = 1, K v = h
            for r in 0..m {
                self.u[r] = T::ONE;
                self.v[r] = self.h(self.idx[r]);
            }
            self.chol_solve(m);
            let su = self.u[..m].iter().fold(T::ZERO, |s, &x| s + x);
            let sv = self.v[..m].iter().fold(T::ZERO, |s, &x| s + x);
            if !(su > T::ZERO) {
                break;
            }
            delta = (load + sv) / su;
            let mut alpha = T::ONE;
            let mut blocked = false;
            for r in 0..m {
                let i = self.idx[r];
                let qn = delta * self.u[r] - self.v[r];
                self.qn[i] = qn;
                if qn <= T::ZERO {
                    blocked = true;
                    let qi = self.q[i];
                    let t = if qi - qn > T::ZERO {
                        qi / (qi - qn)
                    } else {
                        T::ZERO
                    };
                    alpha = math::min(alpha, t);
                }
            }
            if blocked {
                for r in 0..m {
                    let i = self.idx[r];
                    let q = self.q[i] + alpha * (self.qn[i] - self.q[i]);
                    if q <= T::ZERO || self.qn[i] <= T::ZERO && q <= c::<T>(1e-12) * load {
                        self.q[i] = T::ZERO;
                        self.act[i] = false;
                    } else {
                        self.q[i] = q;
                    }
                }
                continue;
            }
            for r in 0..m {
                let i = self.idx[r];
                self.q[i] = self.qn[i];
            }
            // multipliers of the inactive strips
            let mut worst = T::ZERO;
            let mut add = usize::MAX;
            let tol = c::<T>(1e-9) * math::abs(delta);
            for i in 0..n {
                if self.act[i] {
                    continue;
                }
                let mut g = self.h(i) - delta;
                for r in 0..m {
                    let j = self.idx[r];
                    g += self.k[i][j] * self.q[j];
                }
                if g < -tol && g < worst {
                    worst = g;
                    add = i;
                }
            }
            if add == usize::MAX {
                converged = true;
                break;
            }
            self.act[add] = true;
        }
        (steps, converged, delta)
    }

    /// Cholesky factor of the active block K[idx][idx] (m × m) into `l`; `false` if not
    /// positive definite.
    fn cholesky(&mut self, m: usize) -> bool {
        for r in 0..m {
            for s in 0..=r {
                let mut sum = self.k[self.idx[r]][self.idx[s]];
                for t in 0..s {
                    sum -= self.l[r][t] * self.l[s][t];
                }
                if r == s {
                    if !(sum > T::ZERO) {
                        return false;
                    }
                    self.l[r][r] = math::sqrt(sum);
                } else {
                    self.l[r][s] = sum / self.l[s][s];
                }
            }
        }
        true
    }

    /// Solves L Lᵀ x = b for b = `u` and b = `v` (first m entries), in place.
    fn chol_solve(&mut self, m: usize) {
        for vec in 0..2 {
            let b = if vec == 0 { &mut self.u } else { &mut self.v };
            for r in 0..m {
                let mut s = b[r];
                for t in 0..r {
                    s -= self.l[r][t] * b[t];
                }
                b[r] = s / self.l[r][r];
            }
            for r in (0..m).rev() {
                let mut s = b[r];
                for t in r + 1..m {
                    s -= self.l[t][r] * b[t];
                }
                b[r] = s / self.l[r][r];
            }
        }
    }

    /// Row of K for strip i at half-length `a` (into `row[slot]`); returns the self term.
    fn eval_row(&mut self, i: usize, a: T, pe: T, slot: usize) -> T {
        let mut si = self.shape[i];
        si.a = a;
        for j in 0..self.n {
            self.row[slot][j] = if j == i {
                pair(&si, &si) / pe
            } else {
                pair(&si, &self.shape[j]) / pe
            };
        }
        self.row[slot][i]
    }

    /// Strip i's part of the energy with row `slot` at half-length `a`.
    fn energy_i(&self, i: usize, a: T, slot: usize) -> T {
        let qi = self.q[i];
        let mut e = T::HALF * qi * qi * self.row[slot][i];
        for j in 0..self.n {
            if j != i && self.q[j] > T::ZERO {
                e += qi * self.q[j] * self.row[slot][j];
            }
        }
        e + qi * (self.f[i] + self.ca[i] * a * a * c::<T>(0.25))
    }

    /// One Gauss–Seidel pass of damped Newton steps in ln a over the loaded strips (`only`:
    /// just those flagged).
    fn a_pass(&mut self, pe: T, eps: T, only: Option<&[bool; N]>) {
        let n = self.n;
        for i in 0..n {
            if !(self.q[i] > T::ZERO) || only.is_some_and(|o| !o[i]) {
                continue;
            }
            let a0 = self.shape[i].a;
            for j in 0..n {
                self.row[0][j] = self.k[i][j];
            }
            let e0 = self.energy_i(i, a0, 0);
            let am = a0 * math::exp(-eps);
            let ap = a0 * math::exp(eps);
            self.eval_row(i, am, pe, 1);
            let em = self.energy_i(i, am, 1);
            self.eval_row(i, ap, pe, 2);
            let ep = self.energy_i(i, ap, 2);
            let g = (ep - em) / (T::TWO * eps);
            let hh = (ep - T::TWO * e0 + em) / (eps * eps);
            let max_step = c::<T>(MAX_STEP);
            let mut step = if hh > T::ZERO {
                -g / hh
            } else if g > T::ZERO {
                -max_step
            } else {
                max_step
            };
            step = math::clamp(step, -max_step, max_step);
            if !(T::is_finite(step)) || math::abs(step) < c::<T>(1e-4) {
                continue;
            }
            let mut accepted = false;
            for _ in 0..2 {
                let an = a0 * math::exp(step);
                self.eval_row(i, an, pe, 1);
                let en = self.energy_i(i, an, 1);
                if en < e0 {
                    self.shape[i].a = an;
                    for j in 0..n {
                        self.k[i][j] = self.row[1][j];
                        self.k[j][i] = self.row[1][j];
                    }
                    accepted = true;
                    break;
                }
                step *= T::HALF;
            }
            let _ = accepted;
        }
    }
}

impl<T: Real, const N: usize> Default for RitzStrips<T, N> {
    fn default() -> Self {
        Self::new()
    }
}
