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
//!    half-length). Default 0.005: on the narrow Manchester flange patches (≈ 0.7 mm
//!    wide, a ≈ 8 mm) 0.02 left 7 strips across the patch and FaStrip-AC's wear profile a
//!    staircase (wear-weighted peak error over the study 36 % against TANG); 0.005 gives 28
//!    and no "needles" (a prototype with a 24-cell quadrature of the compliance had strips
//!    alternating in a below 0.02; with [`crate::compliance::pair`] the pmax stays within
//!    1.3 % of NORM's at 0.005);
//! 2. q at fixed a: the convex quadratic programme by a primal active-set method (a Cholesky
//!    solve of the active block per step, ≤ [`RitzConfig::qp_steps`] steps), started from the
//!    STRIPES loads;
//! 3. a at fixed q: one Gauss–Seidel pass of a damped Newton step in ln a_i per loaded strip
//!    (the energy along a_i from two finite-difference rows of K, the new row evaluated exactly,
//!    the step halved once if the energy rose; the pass direction alternates), then one Newton
//!    step on the common scale of all loaded a_i (the long-wavelength mode that single-strip
//!    steps resolve slowly: on a two-basin gap it takes pmax from 2.2 % to 0.8 % off the
//!    converged value after 2 iterations);
//! 4. 2 and 3 repeated [`RitzConfig::outer`] times (default 4: pmax within 0.2 %, strip loads
//!    within 1 % of the 16-iteration solution), then 2; strips loaded for the first time by
//!    that last q-solve get one pass of 3 and the q-solve is repeated.
//!
//! `converged` is false if a q-solve hit its step cap, or if a sample left out of the
//! candidates (its rigid gap above the bound) has a gap below the final approach and the
//! displacement of the solved loads does not keep it apart (it would be in contact).
#![allow(clippy::neg_cmp_op_on_partial_ord)]
// NaN must count as "not positive"
// The solve indexes parallel per-strip arrays and the rows of K together.
#![allow(clippy::needless_range_loop)]

use crate::compliance::{pair, StripShape};
use crate::error::{check_positive, Error};
use crate::math::{self, c};
use crate::stripes::{
    RegionSummary, StripSample, StripSet, Stripes, StripesSolution, MIN_STRIPS_PER_REGION,
};
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
    /// Defaults: strips ≥ 0.005 a_max, candidates below 1.2 δ, 4 outer iterations, ≤ 64
    /// active-set steps (16 left 5 band and transition cases unconverged), finite-difference
    /// step 0.05 in ln a.
    pub fn recommended() -> Self {
        Self {
            min_width: c(0.005),
            candidate: c(1.2),
            outer: 4,
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
    /// Every q-solve converged and no sample left out of the candidates is in contact.
    pub converged: bool,
}

/// Sub-points per layout strip of the reconstruction ([`RitzStrips::layout`]).
const SUB: usize = 4;
/// Largest Newton step in ln a per pass.
const MAX_STEP: f64 = 2.0;
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
    row: [[T; N]; 2],
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
            row: [[T::ZERO; N]; 2],
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
        for it in 0..cfg.outer {
            let (steps, ok, _) = self.qp(load, cfg.qp_steps);
            out.qp_steps += steps;
            out.converged &= ok;
            self.a_pass(pe, cfg.fd_step, None, it % 2 == 1);
            self.scale_pass(pe, cfg.fd_step);
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
            self.a_pass(pe, cfg.fd_step, Some(&fresh), false);
            let (steps, ok, d) = self.qp(load, cfg.qp_steps);
            out.qp_steps += steps;
            out.converged &= ok;
            delta = d;
        }
        out.delta = delta;
        // Samples left out (rigid gap ≥ the candidate bound) whose gap is below the approach:
        // out of contact only if the displacement the loads cause there keeps them apart.
        if delta > bound {
            out.converged &= self.excluded_apart(samples, zmin, bound, delta, pe);
        }
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

    /// `true` if every sample outside the candidates with a rigid gap below `delta` stays out of
    /// contact under the solved loads: u + f + A a²/4 ≥ δ for a strip of the sample's width
    /// and its rigid-indentation half-length a = √((δ − f)/A).
    fn excluded_apart(
        &self,
        samples: &[StripSample<T>],
        zmin: T,
        bound: T,
        delta: T,
        pe: T,
    ) -> bool {
        for s in samples {
            let f = s.z - zmin;
            if f < bound || f >= delta {
                continue;
            }
            let a = math::sqrt((delta - f) / s.curv_a);
            let probe = StripShape {
                y: s.y,
                w: s.dy,
                xc: s.xc,
                a,
            };
            let mut g = f + s.curv_a * a * a * c::<T>(0.25) - delta;
            for j in 0..self.n {
                if self.q[j] > T::ZERO {
                    g += pair(&probe, &self.shape[j]) / pe * self.q[j];
                }
            }
            if g < T::ZERO {
                return false;
            }
        }
        true
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

    /// Lays the last solve out on the pipeline's strips `out`, as [`Stripes::layout`] does for
    /// STRIPES: the regions are the runs of adjacent loaded strips (while there are more than
    /// `NR`, the two runs with the narrowest gap between them are merged), each with
    /// `per_region` evenly spaced strips (at most `S`/regions). Per layout strip the line load
    /// and the load-weighted half-length are the means over the strip's width of the
    /// piecewise-linear reconstruction through the strip model's strip centres (4 sub-points;
    /// the region's load then scaled to the strip model's, so it is conserved), p̂ =
    /// 2·(line load)/(π a). Why the reconstruction: on a narrow flange patch (14 strips of the
    /// model under 32 layout strips) the piecewise-constant profile put steps into p̂ that moved
    /// the KTH map's pressure threshold by a strip (Manchester right y_ws 6.5 mm: FaStrip-AC
    /// wear peak 31 % off TANG's with steps, 17 % with the reconstruction). x_c and A come from `samples`,
    /// B_f, n/m, Ã and the strip stiffness from STRIPES (`st`, the solve this one started
    /// from) at the strip's centre; h = Ã a². `sol` is this workspace's last result.
    ///
    /// Errors: `NoContact` without a loaded strip, `GridTooSmall` if fewer than 8 strips per
    /// region fit.
    pub fn layout<const NS: usize, const NB: usize, const NR: usize, const S: usize>(
        &self,
        samples: &[StripSample<T>],
        st: &Stripes<T, NS, NB, NR>,
        sol: &RitzSolution<T>,
        per_region: usize,
        out: &mut StripSet<T, S, NR>,
    ) -> Result<(), Error> {
        let n = self.n;
        // runs of adjacent loaded strips, merged across the narrowest gaps beyond NR
        let mut runs = [(0usize, 0usize); 8];
        let cap = NR.min(runs.len() - 1);
        let mut nr = 0usize;
        for k in 0..n {
            if !(self.q[k] > T::ZERO) {
                continue;
            }
            let adjacent = nr > 0 && runs[nr - 1].1 + 1 == k && {
                let (p, s) = (self.shape[k - 1], self.shape[k]);
                math::abs(p.y + T::HALF * p.w - (s.y - T::HALF * s.w)) <= c::<T>(1e-6) * s.w
            };
            if adjacent {
                runs[nr - 1].1 = k;
                continue;
            }
            runs[nr] = (k, k);
            nr += 1;
            if nr > cap {
                // merge the two neighbouring runs with the narrowest gap
                let mut best = 0;
                let mut gap = T::ZERO;
                for r in 0..nr - 1 {
                    let g = self.lower(runs[r + 1].0) - self.upper(runs[r].1);
                    if r == 0 || g < gap {
                        best = r;
                        gap = g;
                    }
                }
                runs[best].1 = runs[best + 1].1;
                for r in best + 1..nr - 1 {
                    runs[r] = runs[r + 1];
                }
                nr -= 1;
            }
        }
        if nr == 0 {
            return Err(Error::NoContact);
        }
        if per_region < MIN_STRIPS_PER_REGION {
            return Err(Error::GridTooSmall("strips per region"));
        }
        let per = per_region.min(S / nr);
        if per < MIN_STRIPS_PER_REGION {
            return Err(Error::GridTooSmall("strip capacity"));
        }
        let two_over_pi = c::<T>(2.0 / core::f64::consts::PI);
        out.total_load = T::ZERO;
        out.total_area = T::ZERO;
        out.total_pmax = T::ZERO;
        let mut j = 0usize;
        let mut si = 0usize; // sample bracket
        let mut li = 0usize; // STRIPES bracket
        for (r, &(k0, k1)) in runs[..nr].iter().enumerate() {
            let (y_lo, y_hi) = (self.lower(k0), self.upper(k1));
            let dy = (y_hi - y_lo) / T::from_usize(per);
            let mut reg = RegionSummary {
                y_lo,
                y_hi,
                first: j,
                count: per,
                ..RegionSummary::default()
            };
            let mut k = k0;
            for q in 0..per {
                let lo = y_lo + T::from_usize(q) * dy;
                let y = lo + T::HALF * dy;
                // line load and load-weighted half-length over [lo, hi] of the piecewise-linear
                // reconstruction through the strip centres (`SUB` midpoints)
                let (mut fl, mut fa) = (T::ZERO, T::ZERO);
                for m in 0..SUB {
                    let ym = lo + (T::from_usize(m) + T::HALF) * dy / T::from_usize(SUB);
                    let (l, a) = self.reconstruct(k0, k1, ym, &mut k);
                    fl += l;
                    fa += l * a;
                }
                fl *= dy / T::from_usize(SUB);
                fa *= dy / T::from_usize(SUB);
                let (xc, ca) = sample_at(samples, y, &mut si);
                let (bf, nm, at, kst) = st.local_at(y, &mut li);
                let a = if fl > T::ZERO { fa / fl } else { T::ZERO };
                out.y[j] = y;
                out.dy[j] = dy;
                out.a[j] = a;
                out.xc[j] = xc;
                out.pmax[j] = if a > T::ZERO {
                    two_over_pi * fl / (dy * a)
                } else {
                    T::ZERO
                };
                out.h[j] = at * a * a;
                out.curv_a[j] = ca;
                out.curv_bf[j] = bf;
                out.n_over_m[j] = nm;
                out.a_tilde[j] = at;
                out.stiffness[j] = kst;
                out.region[j] = r as u8;
                reg.load += fl;
                reg.area += T::TWO * a * dy;
                reg.pmax = math::max(reg.pmax, out.pmax[j]);
                reg.a_max = math::max(reg.a_max, a);
                j += 1;
            }
            // the reconstruction's load → the strips' own (conserved per region)
            let q_run = self.q[k0..=k1].iter().fold(T::ZERO, |acc, &x| acc + x);
            if reg.load > T::ZERO {
                let f = q_run / reg.load;
                reg.pmax = T::ZERO;
                for jj in reg.first..j {
                    out.pmax[jj] *= f;
                    reg.pmax = math::max(reg.pmax, out.pmax[jj]);
                }
                reg.load = q_run;
            }
            out.total_load += reg.load;
            out.total_area += reg.area;
            out.total_pmax = math::max(out.total_pmax, reg.pmax);
            out.regions[r] = reg;
        }
        out.n_strips = j;
        out.n_regions = nr;
        out.delta = sol.delta;
        out.iterations = sol.qp_steps;
        out.converged = sol.converged;
        Ok(())
    }

    /// Line load (N/mm) and half-length (mm) at `y` of the piecewise-linear reconstruction
    /// through the centres of strips k0..=k1 (constant beyond the end centres; the half-length
    /// of an unloaded strip is its loaded neighbour's). `k` is the bracket search start.
    fn reconstruct(&self, k0: usize, k1: usize, y: T, k: &mut usize) -> (T, T) {
        let line = |i: usize| {
            if self.q[i] > T::ZERO {
                self.q[i] / self.shape[i].w
            } else {
                T::ZERO
            }
        };
        if *k < k0 || *k > k1 || self.shape[*k].y > y {
            *k = k0;
        }
        while *k < k1 && self.shape[*k + 1].y <= y {
            *k += 1;
        }
        let i0 = *k;
        if i0 == k1 || y <= self.shape[i0].y {
            return (line(i0), self.shape[i0].a);
        }
        let i1 = i0 + 1;
        let t = (y - self.shape[i0].y) / (self.shape[i1].y - self.shape[i0].y);
        let (l0, l1) = (line(i0), line(i1));
        let (a0, a1) = match (l0 > T::ZERO, l1 > T::ZERO) {
            (true, true) => (self.shape[i0].a, self.shape[i1].a),
            (true, false) => (self.shape[i0].a, self.shape[i0].a),
            (false, true) => (self.shape[i1].a, self.shape[i1].a),
            (false, false) => (T::ZERO, T::ZERO),
        };
        (l0 + t * (l1 - l0), a0 + t * (a1 - a0))
    }

    /// Lower lateral edge of strip k, mm.
    #[inline]
    fn lower(&self, k: usize) -> T {
        self.shape[k].y - T::HALF * self.shape[k].w
    }

    /// Upper lateral edge of strip k, mm.
    #[inline]
    fn upper(&self, k: usize) -> T {
        self.shape[k].y + T::HALF * self.shape[k].w
    }

    /// h_i = f_i + A_i a_i²/4 at the current half-length.
    #[inline]
    fn h(&self, i: usize) -> T {
        self.mean_gap(i, self.shape[i].a)
    }

    /// The semi-ellipse-weighted mean rigid gap f_i + A_i a²/4 of strip i at half-length `a`.
    #[inline]
    fn mean_gap(&self, i: usize, a: T) -> T {
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

    /// Row of K for strip i at half-length `a` (into `row[slot]`): every entry, or (`loaded`)
    /// only those of the loaded strips and the self term, the ones the energy of strip i uses.
    fn eval_row(&mut self, i: usize, a: T, pe: T, slot: usize, loaded: bool) {
        let mut si = self.shape[i];
        si.a = a;
        for j in 0..self.n {
            self.row[slot][j] = if j == i {
                pair(&si, &si) / pe
            } else if !loaded || self.q[j] > T::ZERO {
                pair(&si, &self.shape[j]) / pe
            } else {
                T::ZERO
            };
        }
    }

    /// Energy ½ qᵀK(a')q + qᵀh(a') with every loaded strip's half-length scaled by e^t
    /// (evaluated; `store`: the rows of the loaded strips at the scaled lengths go to `l`).
    fn scaled_energy(&mut self, t: T, pe: T, store: bool) -> T {
        let n = self.n;
        let f = math::exp(t);
        let mut e = T::ZERO;
        for i in 0..n {
            if !(self.q[i] > T::ZERO) {
                continue;
            }
            let mut si = self.shape[i];
            si.a *= f;
            e += self.q[i] * self.mean_gap(i, si.a);
            for j in 0..n {
                let loaded = self.q[j] > T::ZERO;
                if !(store || loaded && j >= i) {
                    continue;
                }
                let mut sj = self.shape[j];
                if loaded {
                    sj.a *= f;
                }
                let kij = pair(&si, &sj) / pe;
                if store {
                    self.l[i][j] = kij;
                }
                if loaded && j > i {
                    e += self.q[i] * self.q[j] * kij;
                } else if j == i {
                    e += T::HALF * self.q[i] * self.q[i] * kij;
                }
            }
        }
        e
    }

    /// Energy at the current half-lengths from the stored K.
    fn energy(&self) -> T {
        let n = self.n;
        let mut e = T::ZERO;
        for i in 0..n {
            if !(self.q[i] > T::ZERO) {
                continue;
            }
            e += self.q[i] * self.h(i) + T::HALF * self.q[i] * self.q[i] * self.k[i][i];
            for j in i + 1..n {
                if self.q[j] > T::ZERO {
                    e += self.q[i] * self.q[j] * self.k[i][j];
                }
            }
        }
        e
    }

    /// Coarse correction of the a-pass: one damped Newton step on the common scale e^t of all
    /// loaded half-lengths (the long-wavelength mode that single-strip steps resolve slowly).
    fn scale_pass(&mut self, pe: T, eps: T) {
        let n = self.n;
        let e0 = self.energy();
        let em = self.scaled_energy(-eps, pe, false);
        let ep = self.scaled_energy(eps, pe, false);
        let g = (ep - em) / (T::TWO * eps);
        let hh = (ep - T::TWO * e0 + em) / (eps * eps);
        if !(hh > T::ZERO) {
            return;
        }
        let mut t = math::clamp(-g / hh, -T::ONE, T::ONE);
        if !T::is_finite(t) || math::abs(t) < c::<T>(1e-5) {
            return;
        }
        for _ in 0..2 {
            let et = self.scaled_energy(t, pe, true);
            if et < e0 {
                let f = math::exp(t);
                for i in 0..n {
                    if self.q[i] > T::ZERO {
                        self.shape[i].a *= f;
                    }
                }
                for i in 0..n {
                    if self.q[i] > T::ZERO {
                        for j in 0..n {
                            let kij = self.l[i][j];
                            self.k[i][j] = kij;
                            self.k[j][i] = kij;
                        }
                    }
                }
                return;
            }
            t *= T::HALF;
        }
    }

    /// Strip i's part of the energy with K's row `row` at half-length `a`.
    fn energy_i(&self, i: usize, a: T, row: &[T; N]) -> T {
        let qi = self.q[i];
        let mut e = T::HALF * qi * qi * row[i];
        for j in 0..self.n {
            if j != i && self.q[j] > T::ZERO {
                e += qi * self.q[j] * row[j];
            }
        }
        e + qi * self.mean_gap(i, a)
    }

    /// One Gauss–Seidel pass of damped Newton steps in ln a over the loaded strips (`only`:
    /// just those flagged).
    fn a_pass(&mut self, pe: T, eps: T, only: Option<&[bool; N]>, backward: bool) {
        let n = self.n;
        for ii in 0..n {
            let i = if backward { n - 1 - ii } else { ii };
            if !(self.q[i] > T::ZERO) || only.is_some_and(|o| !o[i]) {
                continue;
            }
            let a0 = self.shape[i].a;
            let e0 = self.energy_i(i, a0, &self.k[i]);
            let am = a0 * math::exp(-eps);
            let ap = a0 * math::exp(eps);
            self.eval_row(i, am, pe, 0, true);
            let em = self.energy_i(i, am, &self.row[0]);
            self.eval_row(i, ap, pe, 1, true);
            let ep = self.energy_i(i, ap, &self.row[1]);
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
            // the step, halved once if the energy rose; the rest of the row once accepted
            for _ in 0..2 {
                let an = a0 * math::exp(step);
                self.eval_row(i, an, pe, 0, true);
                let en = self.energy_i(i, an, &self.row[0]);
                if en < e0 {
                    self.shape[i].a = an;
                    let si = self.shape[i];
                    for j in 0..n {
                        let kij = if j != i && !(self.q[j] > T::ZERO) {
                            pair(&si, &self.shape[j]) / pe
                        } else {
                            self.row[0][j]
                        };
                        self.k[i][j] = kij;
                        self.k[j][i] = kij;
                    }
                    break;
                }
                step *= T::HALF;
            }
        }
    }
}

/// (x_c, A) of `samples` at lateral position `y` (linear, clamped); `i` the bracket start.
fn sample_at<T: Real>(samples: &[StripSample<T>], y: T, i: &mut usize) -> (T, T) {
    let n = samples.len();
    if n < 2 {
        return samples
            .first()
            .map_or((T::ZERO, T::ZERO), |s| (s.xc, s.curv_a));
    }
    if *i + 1 >= n || samples[*i].y > y {
        *i = 0;
    }
    while *i + 2 < n && samples[*i + 1].y < y {
        *i += 1;
    }
    let (s0, s1) = (&samples[*i], &samples[*i + 1]);
    let t = math::clamp((y - s0.y) / (s1.y - s0.y), T::ZERO, T::ONE);
    (
        s0.xc + t * (s1.xc - s0.xc),
        s0.curv_a + t * (s1.curv_a - s0.curv_a),
    )
}

impl<T: Real, const N: usize> Default for RitzStrips<T, N> {
    fn default() -> Self {
        Self::new()
    }
}
