//! Mutual compliance of two semi-elliptic strips on the elastic half-space: the strip model's
//! influence coefficients ([`crate::ritz`]).
//!
//! A strip `(y, w, x_c, a)` carries a pressure that is uniform across its width w (from y − w/2
//! to y + w/2) and semi-elliptic along x about x_c with half-length a, normalised to unit load:
//! φ(x, y) = 2/(π a w) · √(1 − ((x − x_c)/a)²). The surface displacement of both bodies under a
//! pressure p is u = 1/(π E*) ∫∫ p/r dA (Boussinesq). [`pair`] returns
//!
//! I_ij = π E* ∫∫ φ_i u(φ_j) dA  (1/mm),
//!
//! the φ_i-weighted mean displacement that a unit load on strip j causes on strip i, times πE*.
//! It is symmetric (I_ij = I_ji), and I/(π E*) is the strip model's compliance in mm/N.
//!
//! How it is evaluated (accuracy against a converged brute-force integration in the unit test,
//! ≤ 1e-4 relative on thin, wide, adjacent, distant, offset and unequal strips):
//! * across the two widths in closed form: ∫∫ dy dy'/√(X² + (y − y')²) = Σ± G(t_k), G(t) =
//!   t asinh(t/|X|) − √(X² + t²), over the four corner offsets t_k = d ± (w_i ± w_j)/2
//!   (d = y_i − y_j). Its logarithmic singularity −c ln|X| at X = 0 (c = Σ±|t_k|, twice the
//!   overlap of the two widths) is split off and integrated against the source's semi-ellipse
//!   in closed form (the displacement of a two-dimensional Hertz pressure,
//!   (2/π)∫√(1 − t²) ln|u − t| dt = u² − ½ − ln 2 for |u| ≤ 1);
//! * along the source in θ (x = x_c + a sin θ: the semi-ellipse's square-root ends become a
//!   smooth weight cos²θ), 4-point Gauss–Legendre on panels graded geometrically (ratio 3)
//!   towards the target point, the smallest a quarter of the lateral length scale
//!   ℓ = max(|d|, (w_i + w_j)/2) on which the width kernel varies (ratio 2 with 6 points was
//!   no more accurate; a smallest panel of ℓ/2 or 6 target nodes doubled the worst error);
//! * along the target (the shorter strip of the two: I is symmetric) by Gauss–Chebyshev of the
//!   second kind (weight √(1 − t²)), 8 nodes;
//! * pairs apart laterally (no overlap of the widths) by tensor Gauss–Chebyshev nodes on the
//!   closed-form width kernel: 4 × 4 beyond ℓ = 1.5 a (a the longer half-length) or centres
//!   beyond 2(a_i + a_j), 6 × 6 beyond 0.75 a, 8 × 8 beyond 0.5 a (each checked at its bound
//!   against the brute force: ≤ 4e-5; 0.4 a with 8 × 8 gave 2.3e-4).
//!
//! Every loop has a fixed bound: at most `2 (2 + log₃(2π a/ℓ))` panels of 4 nodes per target
//! node (≤ 24 per side), ℓ ≥ the strips' widths. Host cost (f64): 0.3–10 µs per pair; the
//! strip model's solve of a wheel/rail patch evaluates 10⁵–2·10⁵ pairs.

use crate::math::{self, c};
use crate::Real;

/// One semi-elliptic strip: lateral centre `y` and width `w`, longitudinal centre `xc` and
/// half-length `a` (mm; `w`, `a` > 0).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct StripShape<T> {
    /// Lateral centre, mm.
    pub y: T,
    /// Width, mm (> 0).
    pub w: T,
    /// Longitudinal centre, mm.
    pub xc: T,
    /// Half-length, mm (> 0).
    pub a: T,
}

/// Gauss–Legendre, 6 nodes on [−1, 1]: (node, weight), positive half.
const GL6: [(f64, f64); 3] = [
    (0.238_619_186_083_197, 0.467_913_934_572_691),
    (0.661_209_386_466_264_5, 0.360_761_573_048_138_6),
    (0.932_469_514_203_152, 0.171_324_492_379_170_4),
];

/// Gauss–Legendre, 4 nodes on [−1, 1]: (node, weight), positive half.
const GL4: [(f64, f64); 2] = [
    (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
];

/// Largest number of graded panels on one side of the target point.
const MAX_LEVELS: usize = 24;

/// The corner offsets of the width integral with their weights: four, or three when the widths
/// are equal (the two middle corners coincide, weight −2).
#[derive(Clone, Copy)]
struct Corners<T> {
    t: [(T, T); 4],
    n: usize,
}

#[inline]
fn corners<T: Real>(d: T, wi: T, wj: T) -> Corners<T> {
    let s = T::HALF * (wi + wj);
    let dl = T::HALF * (wi - wj);
    if dl == T::ZERO {
        Corners {
            t: [
                (d + s, T::ONE),
                (d, -T::TWO),
                (d - s, T::ONE),
                (T::ZERO, T::ZERO),
            ],
            n: 3,
        }
    } else {
        Corners {
            t: [
                (d + s, T::ONE),
                (d + dl, -T::ONE),
                (d - dl, -T::ONE),
                (d - s, T::ONE),
            ],
            n: 4,
        }
    }
}

/// Twice the overlap of the two widths: c = Σ± |t_k| (the coefficient of −ln|X|).
#[inline]
fn overlap<T: Real>(t: &Corners<T>) -> T {
    t.t[..t.n]
        .iter()
        .fold(T::ZERO, |acc, &(tk, sg)| acc + sg * math::abs(tk))
}

/// The regular part R(X) = W(X) + c ln|X| of the width kernel
/// W(X) = ∫∫ dy dy'/√(X² + (y − y')²) = Σ± [|t| ln(|t| + ρ) − ρ] − c ln|X|, ρ = √(t² + X²).
#[inline]
fn width_regular<T: Real>(t: &Corners<T>, x: T) -> T {
    let x2 = x * x;
    let mut r = T::ZERO;
    for &(tk, sg) in &t.t[..t.n] {
        let at = math::abs(tk);
        let rho = math::sqrt(at * at + x2);
        let lg = if at > T::ZERO {
            at * math::ln(at + rho)
        } else {
            T::ZERO
        };
        r += sg * (lg - rho);
    }
    r
}

/// The full width kernel W(X) (X ≠ 0 or c = 0).
#[inline]
fn width_kernel<T: Real>(t: &Corners<T>, cov: T, x: T) -> T {
    let r = width_regular(t, x);
    if cov > T::ZERO {
        r - cov * math::ln(math::abs(x))
    } else {
        r
    }
}

/// (2/π) ∫_{−1}^{1} √(1 − t²) ln|u − t| dt.
#[inline]
fn log_potential<T: Real>(u: T) -> T {
    let au = math::abs(u);
    let base = u * u - T::HALF - c::<T>(core::f64::consts::LN_2);
    if au <= T::ONE {
        base
    } else {
        let r = math::sqrt(u * u - T::ONE);
        base - au * r + math::ln(au + r)
    }
}

/// Gauss–Chebyshev (second kind) nodes cos(kπ/(n+1)) on [−1, 1] and weights 2 sin²(kπ/(n+1))/(n+1),
/// normalised so that they sum to 1 against the semi-ellipse density (2/π)√(1 − t²); n = 4, 6, 8.
const GC4: [(f64, f64); 4] = [
    (0.8090169943749475, 0.1381966011250105),
    (0.30901699437494745, 0.36180339887498947),
    (-0.30901699437494734, 0.3618033988749895),
    (-0.8090169943749473, 0.1381966011250106),
];
const GC6: [(f64, f64); 6] = [
    (0.9009688679024191, 0.053787171163038064),
    (0.6234898018587336, 0.1746458477080449),
    (0.22252093395631445, 0.27156698112891703),
    (-0.22252093395631434, 0.27156698112891703),
    (-0.6234898018587335, 0.17464584770804498),
    (-0.900968867902419, 0.0537871711630381),
];
const GC8: [(f64, f64); 8] = [
    (0.9396926207859084, 0.025995061875669103),
    (0.766044443118978, 0.09181686914811883),
    (0.5000000000000001, 0.16666666666666663),
    (0.17364817766693041, 0.21552140230954536),
    (-0.1736481776669303, 0.21552140230954536),
    (-0.4999999999999998, 0.16666666666666669),
    (-0.7660444431189779, 0.09181686914811889),
    (-0.9396926207859083, 0.025995061875669127),
];

/// Node k of the n-node Gauss–Chebyshev rule (n = 4, 6 or 8; else 8).
#[inline]
fn gc2<T: Real>(k: usize, n: usize) -> (T, T) {
    let (x, w) = match n {
        4 => GC4[k],
        6 => GC6[k],
        _ => GC8[k],
    };
    (c(x), c(w))
}

/// ∫ φ_j(x') R(x − x') dx' along the source `src` (semi-ellipse density), graded towards x.
fn source_regular<T: Real>(t: &Corners<T>, src: &StripShape<T>, x: T, ell: T) -> T {
    let half_pi = c::<T>(core::f64::consts::FRAC_PI_2);
    let u = (x - src.xc) / src.a;
    let th0 = math::asin(math::clamp(u, -T::ONE, T::ONE));
    // distance of x beyond the source's end (0 inside)
    let outside = math::max(math::abs(x - src.xc) - src.a, T::ZERO);
    // smallest panel in θ: a quarter of ℓ in x (θ-scale: x − x_c = a sin θ)
    let h0 = math::min(c::<T>(0.25) * ell / src.a, half_pi);
    let graded = outside < c::<T>(4.0) * ell;
    let w2pi = c::<T>(2.0 / core::f64::consts::PI);
    let mut sum = T::ZERO;
    let panel = |lo: T, hi: T, sum: &mut T| {
        let mid = T::HALF * (lo + hi);
        let hw = T::HALF * (hi - lo);
        for &(g, wg) in GL4.iter() {
            for sg in [-T::ONE, T::ONE] {
                let th = mid + sg * c::<T>(g) * hw;
                let cs = math::cos(th);
                let xs = src.xc + src.a * math::sin(th);
                *sum += c::<T>(wg) * hw * w2pi * cs * cs * width_regular(t, x - xs);
            }
        }
    };
    if !graded {
        panel(-half_pi, T::ZERO, &mut sum);
        panel(T::ZERO, half_pi, &mut sum);
        return sum;
    }
    // panels of widths h0, 3 h0, 9 h0, … upwards from θ0, the mirror downwards
    for dir in [T::ONE, -T::ONE] {
        let end = dir * half_pi;
        let mut lo = th0;
        let mut h = h0;
        for _ in 0..MAX_LEVELS {
            if (end - lo) * dir <= T::ZERO {
                break;
            }
            let mut hi = lo + dir * h;
            if (hi - end) * dir >= T::ZERO || (end - hi) * dir < h {
                hi = end;
            }
            let (a, b) = if dir > T::ZERO { (lo, hi) } else { (hi, lo) };
            panel(a, b, &mut sum);
            lo = hi;
            h *= c::<T>(3.0);
        }
        if (end - lo) * dir > T::ZERO {
            let (a, b) = if dir > T::ZERO { (lo, end) } else { (end, lo) };
            panel(a, b, &mut sum);
        }
    }
    sum
}

/// Mutual compliance I_ij · (see module docs), 1/mm: multiply by 1/(π E*) for mm/N. Symmetric.
pub fn pair<T: Real>(si: &StripShape<T>, sj: &StripShape<T>) -> T {
    // the target is the shorter strip
    // the target is the shorter strip; ties broken by position so that pair(i, j) and
    // pair(j, i) run the same evaluation (bit-identical symmetry)
    let key = |s: &StripShape<T>| (s.a, s.y, s.xc, s.w);
    let first = !matches!(
        key(si).partial_cmp(&key(sj)),
        Some(core::cmp::Ordering::Greater)
    );
    let (tg, src) = if first { (si, sj) } else { (sj, si) };
    let d = tg.y - src.y;
    let t = corners(d, tg.w, src.w);
    let cov = overlap(&t);
    let ell = math::max(math::abs(d), T::HALF * (tg.w + src.w));
    let dxc = tg.xc - src.xc;
    let dist = math::sqrt(d * d + dxc * dxc);
    let ww = tg.w * src.w;
    // far pairs: tensor Gauss–Chebyshev on the closed-form width kernel (c = 0 there)
    let far = |n: usize| {
        let mut s = T::ZERO;
        for k in 0..n {
            let (xk, wk) = gc2::<T>(k, n);
            let x = tg.xc + tg.a * xk;
            for m in 0..n {
                let (xm, wm) = gc2::<T>(m, n);
                let xs = src.xc + src.a * xm;
                s += wk * wm * width_kernel(&t, cov, x - xs);
            }
        }
        s / ww
    };
    if cov <= T::ZERO && dist > T::TWO * (tg.a + src.a) {
        return far(4);
    }
    if cov <= T::ZERO && ell > c::<T>(1.5) * src.a {
        return far(4);
    }
    if cov <= T::ZERO && ell > c::<T>(0.75) * src.a {
        return far(6);
    }
    if cov <= T::ZERO && ell > T::HALF * src.a {
        return far(8);
    }
    let v = |x: T| {
        let mut v = source_regular(&t, src, x, ell);
        if cov > T::ZERO {
            v -= cov * (math::ln(src.a) + log_potential((x - src.xc) / src.a));
        }
        v
    };
    // The source's displacement has a square-root kink at the source's ends: where one lies
    // inside the target, the target is split there (θ-panels, Gauss–Legendre), else 8
    // Gauss–Chebyshev nodes.
    let half_pi = c::<T>(core::f64::consts::FRAC_PI_2);
    let mut cuts = [T::ZERO; 2];
    let mut nc = 0;
    for e in [src.xc - src.a, src.xc + src.a] {
        let u = (e - tg.xc) / tg.a;
        if math::abs(u) < c::<T>(0.98) {
            cuts[nc] = math::asin(u);
            nc += 1;
        }
    }
    let mut s = T::ZERO;
    if nc == 0 {
        const NT: usize = 8;
        for k in 0..NT {
            let (xk, wk) = gc2::<T>(k, NT);
            s += wk * v(tg.xc + tg.a * xk);
        }
        return s / ww;
    }
    let w2pi = c::<T>(2.0 / core::f64::consts::PI);
    let mut lo = -half_pi;
    for q in 0..=nc {
        let hi = cuts.get(q).copied().filter(|_| q < nc).unwrap_or(half_pi);
        // two panels per piece, the inner one graded towards the cut
        let mid = T::HALF * (lo + hi);
        for (pa, pb) in [(lo, mid), (mid, hi)] {
            let m = T::HALF * (pa + pb);
            let hw = T::HALF * (pb - pa);
            for &(g, wg) in GL6.iter() {
                for sg in [-T::ONE, T::ONE] {
                    let th = m + sg * c::<T>(g) * hw;
                    let cs = math::cos(th);
                    s += c::<T>(wg) * hw * w2pi * cs * cs * v(tg.xc + tg.a * math::sin(th));
                }
            }
        }
        lo = hi;
    }
    s / ww
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    /// Brute force: midpoint rule on fine cells of both strips with the closed-form width kernel
    /// integrated over each target/source cell pair's widths, and the log singularity of
    /// coincident x-cells handled by sub-splitting. Converged by refinement (n, 2n).
    fn brute(si: &StripShape<f64>, sj: &StripShape<f64>, n: usize) -> f64 {
        // θ-midpoints: x = xc + a sin θ, weight (2/π) cos²θ dθ
        let pts = |s: &StripShape<f64>, n: usize| -> std::vec::Vec<(f64, f64)> {
            let h = core::f64::consts::PI / n as f64;
            (0..n)
                .map(|k| {
                    let th = -core::f64::consts::FRAC_PI_2 + (k as f64 + 0.5) * h;
                    let cs = math::cos(th);
                    (
                        s.xc + s.a * math::sin(th),
                        2.0 / core::f64::consts::PI * cs * cs * h,
                    )
                })
                .collect()
        };
        let pi_ = pts(si, n);
        let pj = pts(sj, n + 1);
        let t = corners(si.y - sj.y, si.w, sj.w);
        let cov = overlap(&t);
        let mut s = 0.0;
        for &(x, w) in &pi_ {
            for &(xs, ws) in &pj {
                let dx = x - xs;
                // avoid X = 0 exactly; offset by a tiny fraction (integrable log)
                let dx = if dx.abs() < 1e-12 { 1e-9 } else { dx };
                s += w * ws * width_kernel(&t, cov, dx);
            }
        }
        s / (si.w * sj.w)
    }

    fn check(si: StripShape<f64>, sj: StripShape<f64>, tol: f64) {
        let fast = pair(&si, &sj);
        let sym = pair(&sj, &si);
        assert_eq!(fast, sym, "symmetry");
        let b1 = brute(&si, &sj, 1000);
        let b2 = brute(&si, &sj, 2000);
        // the coincident-node log error is O(ln n / n): first-order Richardson
        let b = 2.0 * b2 - b1;
        let b4 = brute(&si, &sj, 4000);
        let conv = ((2.0 * b4 - b2) - b).abs() / b.abs();
        let b2 = 2.0 * b4 - b2;
        let rel = (fast - b2).abs() / b2.abs();
        std::println!(
            "{si:?} {sj:?}: fast {fast:.6e} brute {b2:.6e} (conv {conv:.1e}) rel {rel:.2e}"
        );
        assert!(rel < tol + 2.0 * conv, "rel {rel:.3e} conv {conv:.3e}");
    }

    #[test]
    fn pair_compliance_against_brute_force() {
        let s = |y: f64, w: f64, xc: f64, a: f64| StripShape { y, w, xc, a };
        // self, thin and wide
        check(s(0.0, 0.06, 0.0, 3.0), s(0.0, 0.06, 0.0, 3.0), 1e-3);
        check(s(0.0, 1.0, 0.0, 3.0), s(0.0, 1.0, 0.0, 3.0), 1e-3);
        // far apart, distant laterally
        check(s(0.0, 0.2, 0.0, 3.0), s(10.0, 0.3, 0.5, 4.0), 1e-3);
        // moderately separated
        check(s(0.0, 0.2, 0.0, 3.0), s(2.0, 0.3, 0.5, 4.0), 1e-3);
        // adjacent, equal widths
        check(s(0.0, 0.2, 0.0, 3.0), s(0.2, 0.2, 0.0, 3.1), 1e-3);
        // neighbours one strip apart, different lengths and centres
        check(s(0.0, 0.2, 0.0, 1.5), s(0.4, 0.2, 0.3, 3.0), 1e-3);
        // the tensor Gauss–Chebyshev tiers at their bounds: 8 × 8, 6 × 6, 4 × 4
        check(s(0.0, 0.2, 0.0, 3.0), s(1.51, 0.2, 0.4, 3.0), 1e-4);
        check(s(0.0, 0.2, 0.0, 3.0), s(2.26, 0.2, -0.4, 3.0), 1e-4);
        check(s(0.0, 0.2, 0.0, 3.0), s(4.51, 0.2, 0.4, 3.0), 1e-4);
        check(s(0.0, 0.1, 0.0, 0.4), s(1.51, 0.1, 0.4, 3.0), 1e-4);
        check(s(0.0, 0.2, 0.0, 3.0), s(1.8, 0.2, 0.4, 3.2), 1e-4);
        check(s(0.0, 0.2, 0.0, 1.0), s(2.5, 0.2, 0.0, 4.0), 1e-4);
        check(s(0.0, 0.2, 0.0, 3.0), s(3.5, 0.2, 0.4, 3.2), 1e-4);
        check(s(0.0, 0.2, 0.0, 0.5), s(4.5, 0.2, 0.4, 4.0), 1e-4);
        // the target beyond the source's end (yawed strips)
        check(s(0.0, 0.2, 0.0, 1.0), s(0.2, 0.2, 3.5, 2.0), 1e-3);
        check(s(0.0, 0.1, 2.2, 1.0), s(0.1, 0.1, 0.0, 2.0), 1e-3);
    }
}
