//! Kalker's creepage coefficients C11, C22, C23, C33 (methods.md §2).
//!
//! The table [`KALKER_TABLE`] is `data/kalker_coefficients.csv` transcribed (a host test reads
//! the CSV and asserts equality). Within the table (g = min(a/b, b/a) ≥ 0.1) [`coefficients`]
//! applies CONTACT's `linrol` rule exactly: linear interpolation in g within the table of its case,
//! quadratic Lagrange interpolation of 1/C in ν through ν = 0, ¼, ½. Below the table it departs
//! from CONTACT on purpose: Kalker's asymptotes plus the table's offset at the edge, fading
//! linearly to 0 at g = 0, instead of CONTACT's bare asymptotes from g = 0.101, which jump (see
//! [`coefficients`]).
//!
//! C33 (single source, **\[UNCERTAIN\]** to the last digit) uses the same rules; its asymptotes are
//! π²/(16(1−ν)g) for a/b → 0 and the b/a = 0.1 row held for b/a → 0 (methods.md §2 item 4).

use crate::error::{check_finite, check_positive, Error};
use crate::math::{self, c};
use crate::Real;

/// Which ratio a table row is indexed by.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum RatioKind {
    /// Row at g = a/b ≤ 1.
    AOverB,
    /// Row at g = b/a < 1.
    BOverA,
}

/// One row of Kalker's table.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KalkerRow {
    /// Ratio the row is indexed by.
    pub kind: RatioKind,
    /// g = a/b or b/a (0.1 … 1.0).
    pub g: f64,
    /// C11(ν=0, ¼, ½), C22(ν=0, ¼, ½), C23(ν=0, ¼, ½), C33(ν=0, ¼, ½).
    pub c: [f64; 12],
}

/// Kalker's table, in the order of `kalker_coefficients.csv`: a/b = 0.1 … 1.0, then b/a = 0.9 … 0.1.
#[allow(clippy::approx_constant)] // 3.14 is a table value (C22 at a/b = 0.5, 0.6), not π
pub const KALKER_TABLE: [KalkerRow; 19] = [
    KalkerRow {
        kind: RatioKind::AOverB,
        g: 0.1,
        c: [
            2.51, 3.31, 4.85, 2.51, 2.52, 2.53, 0.334, 0.473, 0.731, 6.42, 8.28, 11.7,
        ],
    },
    KalkerRow {
        kind: RatioKind::AOverB,
        g: 0.2,
        c: [
            2.59, 3.37, 4.81, 2.59, 2.63, 2.66, 0.483, 0.603, 0.809, 3.46, 4.27, 5.66,
        ],
    },
    KalkerRow {
        kind: RatioKind::AOverB,
        g: 0.3,
        c: [
            2.68, 3.44, 4.8, 2.68, 2.75, 2.81, 0.607, 0.715, 0.889, 2.49, 2.96, 3.72,
        ],
    },
    KalkerRow {
        kind: RatioKind::AOverB,
        g: 0.4,
        c: [
            2.78, 3.53, 4.82, 2.78, 2.88, 2.98, 0.72, 0.823, 0.977, 2.02, 2.32, 2.77,
        ],
    },
    KalkerRow {
        kind: RatioKind::AOverB,
        g: 0.5,
        c: [
            2.88, 3.62, 4.83, 2.88, 3.01, 3.14, 0.827, 0.929, 1.07, 1.74, 1.93, 2.22,
        ],
    },
    KalkerRow {
        kind: RatioKind::AOverB,
        g: 0.6,
        c: [
            2.98, 3.72, 4.91, 2.98, 3.14, 3.31, 0.93, 1.03, 1.18, 1.56, 1.68, 1.86,
        ],
    },
    KalkerRow {
        kind: RatioKind::AOverB,
        g: 0.7,
        c: [
            3.09, 3.81, 4.97, 3.09, 3.28, 3.48, 1.03, 1.14, 1.29, 1.43, 1.5, 1.6,
        ],
    },
    KalkerRow {
        kind: RatioKind::AOverB,
        g: 0.8,
        c: [
            3.19, 3.91, 5.05, 3.19, 3.41, 3.65, 1.13, 1.25, 1.4, 1.34, 1.37, 1.42,
        ],
    },
    KalkerRow {
        kind: RatioKind::AOverB,
        g: 0.9,
        c: [
            3.29, 4.01, 5.12, 3.29, 3.54, 3.82, 1.23, 1.36, 1.51, 1.27, 1.27, 1.27,
        ],
    },
    KalkerRow {
        kind: RatioKind::AOverB,
        g: 1.0,
        c: [
            3.4, 4.12, 5.2, 3.4, 3.67, 3.98, 1.33, 1.47, 1.63, 1.21, 1.19, 1.16,
        ],
    },
    KalkerRow {
        kind: RatioKind::BOverA,
        g: 0.9,
        c: [
            3.51, 4.22, 5.3, 3.51, 3.81, 4.16, 1.44, 1.59, 1.77, 1.16, 1.11, 1.06,
        ],
    },
    KalkerRow {
        kind: RatioKind::BOverA,
        g: 0.8,
        c: [
            3.65, 4.36, 5.42, 3.65, 3.99, 4.39, 1.58, 1.75, 1.94, 1.1, 1.04, 0.954,
        ],
    },
    KalkerRow {
        kind: RatioKind::BOverA,
        g: 0.7,
        c: [
            3.82, 4.54, 5.58, 3.82, 4.21, 4.67, 1.76, 1.95, 2.18, 1.05, 0.965, 0.852,
        ],
    },
    KalkerRow {
        kind: RatioKind::BOverA,
        g: 0.6,
        c: [
            4.06, 4.78, 5.8, 4.06, 4.5, 5.04, 2.01, 2.23, 2.5, 1.01, 0.892, 0.751,
        ],
    },
    KalkerRow {
        kind: RatioKind::BOverA,
        g: 0.5,
        c: [
            4.37, 5.1, 6.11, 4.37, 4.9, 5.56, 2.35, 2.62, 2.96, 0.958, 0.819, 0.65,
        ],
    },
    KalkerRow {
        kind: RatioKind::BOverA,
        g: 0.4,
        c: [
            4.84, 5.57, 6.57, 4.84, 5.48, 6.31, 2.88, 3.24, 3.7, 0.912, 0.747, 0.549,
        ],
    },
    KalkerRow {
        kind: RatioKind::BOverA,
        g: 0.3,
        c: [
            5.57, 6.34, 7.34, 5.57, 6.4, 7.51, 3.79, 4.32, 5.01, 0.868, 0.674, 0.446,
        ],
    },
    KalkerRow {
        kind: RatioKind::BOverA,
        g: 0.2,
        c: [
            6.96, 7.78, 8.82, 6.96, 8.14, 9.79, 5.72, 6.63, 7.89, 0.828, 0.601, 0.341,
        ],
    },
    KalkerRow {
        kind: RatioKind::BOverA,
        g: 0.1,
        c: [
            10.7, 11.7, 12.9, 10.7, 12.8, 16.0, 12.2, 14.6, 18.0, 0.795, 0.526, 0.228,
        ],
    },
];

/// Creepage coefficients at one a/b and ν.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct KalkerCoefficients<T> {
    /// C11 (longitudinal).
    pub c11: T,
    /// C22 (lateral).
    pub c22: T,
    /// C23 = −C32 (lateral force from spin, spin moment from lateral creepage).
    pub c23: T,
    /// C33 (spin moment from spin) — **\[UNCERTAIN\]** single-source table.
    pub c33: T,
}

impl<T: Real> KalkerCoefficients<T> {
    /// All four finite and positive (the asymptotes overflow for a/b or b/a below ~1e-300):
    /// `OutOfRange("a/b")` otherwise.
    fn checked(self) -> Result<Self, Error> {
        for v in [self.c11, self.c22, self.c23, self.c33] {
            if !math::is_finite(v) || v <= T::ZERO {
                return Err(Error::OutOfRange("a/b"));
            }
        }
        Ok(self)
    }
}

/// [`KALKER_TABLE`]'s coefficients rounded to `f32` once, at compile time (the `f32` kernel reads
/// these instead of converting at run time: [`Real::from_rounded`]).
const KALKER_TABLE_F32: [[f32; 12]; 19] = {
    let mut out = [[0.0f32; 12]; 19];
    let mut i = 0;
    while i < 19 {
        let mut j = 0;
        while j < 12 {
            out[i][j] = KALKER_TABLE[i].c[j] as f32;
            j += 1;
        }
        i += 1;
    }
    out
};

/// Table index in [`KALKER_TABLE`] of row k (1-based, g = 0.1 k) of case 1 (a/b) or case 2 (b/a).
fn row_index(case_ab: bool, k: usize) -> usize {
    if case_ab {
        k - 1
    } else {
        19 - k
    }
}

/// 1/C quadratic Lagrange interpolation in ν through ν = 0, ¼, ½ (§2 item 3).
fn poisson<T: Real>(c0: T, c25: T, c50: T, nu: T) -> T {
    let q = c::<T>(0.25);
    let inv = c::<T>(8.0) * (nu - q) * (nu - T::HALF) / c0
        - c::<T>(16.0) * nu * (nu - T::HALF) / c25
        + c::<T>(8.0) * nu * (nu - q) / c50;
    T::ONE / inv
}

/// Lowest g = min(a/b, b/a) of the table; below it the asymptotes with the edge correction.
pub const TABLE_EDGE: f64 = 0.1;

/// C11, C22, C23, C33 at semi-axis ratio `a_over_b` = a/b (a along x) and Poisson ratio `nu`.
///
/// With g = min(a/b, b/a): for g ≥ [`TABLE_EDGE`] CONTACT's `linrol` rule (linear in g within
/// the table of the case, quadratic in 1/C over ν), except that the row is found by ⌊10g⌋
/// rather than ⌊10g − 0.005⌋ (continuous; the same at every row); below it Kalker's asymptotes plus the
/// table's offset at the edge fading linearly to 0 at g = 0:
///
/// C(g) = C_asy(g) + (g/0.1)·(C_tab(0.1) − C_asy(0.1)),
///
/// continuous at the edge and exact as g → 0. CONTACT switches at g = 0.101 to the bare
/// asymptotes, a jump of up to 6 % (C23, a/b side) and 4 % (C11, b/a side): a strip whose local
/// ellipse crosses the edge would change its flexibility, and with it its creep force, at once
/// (methods.md §2 item 4).
///
/// Errors: non-finite or non-positive a/b; `OutOfRange("nu")` unless 0 ≤ ν ≤ ½.
pub fn coefficients<T: Real>(a_over_b: T, nu: T) -> Result<KalkerCoefficients<T>, Error> {
    check_positive(a_over_b, "a/b")?;
    check_finite(nu, "nu")?;
    if nu < T::ZERO || nu > T::HALF {
        return Err(Error::OutOfRange("nu"));
    }
    let case_ab = a_over_b <= T::ONE;
    let g = if case_ab { a_over_b } else { T::ONE / a_over_b };
    if !math::is_finite(g) || g <= T::ZERO {
        return Err(Error::OutOfRange("a/b"));
    }
    let out = if g >= c(TABLE_EDGE) {
        let x = c::<T>(10.0) * g;
        // k = floor(x) clamped to 1 … 9, by comparisons (no float → integer conversion: a
        // software call for f32 → f64 → usize on a Cortex-M4F). CONTACT takes floor(x − 0.005),
        // which extrapolates the row below by up to 0.005 of a row step past each row and then
        // jumps (C33 by 0.3 % at a/b = 0.2005); floor(x) agrees with it at the rows and is
        // continuous between them.
        let mut k = 1;
        for j in 2..=9 {
            if x >= T::from_usize(j) {
                k = j;
            }
        }
        let f = x - T::from_usize(k);
        table(case_ab, k, f, nu)
    } else {
        let asy = asymptotes(case_ab, g, math::sqrt(g), math::ln(g), nu);
        // the asymptotes and the table at the edge (√0.1 and ln 0.1 = −ln 10 as constants)
        let edge = asymptotes(
            case_ab,
            c(TABLE_EDGE),
            c(0.316_227_766_016_837_94),
            -c::<T>(core::f64::consts::LN_10),
            nu,
        );
        let tab = table(case_ab, 1, T::ZERO, nu);
        let w = g / c::<T>(TABLE_EDGE);
        core::array::from_fn(|q| asy[q] + w * (tab[q] - edge[q]))
    };
    KalkerCoefficients {
        c11: out[0],
        c22: out[1],
        c23: out[2],
        c33: out[3],
    }
    .checked()
}

/// C11, C22, C23, C33 of the table of the case, linear in g between rows k and k + 1 (weight
/// `f` on row k + 1), quadratic in 1/C over ν.
#[inline(always)]
fn table<T: Real>(case_ab: bool, k: usize, f: T, nu: T) -> [T; 4] {
    let (il, ih) = (row_index(case_ab, k), row_index(case_ab, k + 1));
    let (lo, lo32) = (&KALKER_TABLE[il].c, &KALKER_TABLE_F32[il]);
    let (hi, hi32) = (&KALKER_TABLE[ih].c, &KALKER_TABLE_F32[ih]);
    let mut out = [T::ZERO; 4];
    for (q, o) in out.iter_mut().enumerate() {
        let mut v = [T::ZERO; 3];
        for (p, vp) in v.iter_mut().enumerate() {
            let i = 3 * q + p;
            *vp = f * T::from_rounded(hi[i], hi32[i])
                + (T::ONE - f) * T::from_rounded(lo[i], lo32[i]);
        }
        *o = poisson(v[0], v[1], v[2], nu);
    }
    out
}

/// Kalker's asymptotes (methods.md §2 item 4) at g with √g and ln g given: C11, C22, C23, C33
/// for a ≪ b (`case_ab`) or a ≫ b. C33 for a ≫ b holds the b/a = 0.1 row (no asymptote known).
#[inline(always)]
fn asymptotes<T: Real>(case_ab: bool, g: T, sqrt_g: T, ln_g: T, nu: T) -> [T; 4] {
    let pi = T::PI;
    let one_m_nu = T::ONE - nu;
    let ln16 = c::<T>(2.772_588_722_239_781);
    if case_ab {
        // a ≪ b.
        let c11 = pi * pi / (c::<T>(4.0) * one_m_nu);
        let c22 = pi * pi / c::<T>(4.0);
        let c23 =
            pi * sqrt_g / (c::<T>(3.0) * one_m_nu) * (T::ONE + nu * (ln16 - ln_g - c::<T>(5.0)));
        let c33 = pi * pi / (c::<T>(16.0) * one_m_nu * g);
        [c11, c22, c23, c33]
    } else {
        // a ≫ b.
        // Λ = ln(16/g²) = ln 16 − 2 ln g (no underflow of g²).
        let lam = ln16 - T::TWO * ln_g;
        let k3 = c::<T>(1.613_705_638_880_109_4); // 3 − ln 4
        let d1 = lam - T::TWO * nu;
        let c11 = T::TWO * pi / (d1 * g) * (T::ONE + k3 / d1);
        let d2 = one_m_nu * lam + T::TWO * nu;
        let c22 = T::TWO * pi / g * (T::ONE + one_m_nu * k3 / d2) / d2;
        let c23 =
            T::TWO * pi / (c::<T>(3.0) * g * sqrt_g * (one_m_nu * lam - T::TWO + c::<T>(4.0) * nu));
        let r = &KALKER_TABLE[18].c;
        let r32 = &KALKER_TABLE_F32[18];
        let c33 = poisson(
            T::from_rounded(r[9], r32[9]),
            T::from_rounded(r[10], r32[10]),
            T::from_rounded(r[11], r32[11]),
            nu,
        );
        [c11, c22, c23, c33]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(x: f64, y: f64, tol: f64) -> bool {
        (x - y).abs() <= tol
    }

    #[test]
    fn reference_values_spec_section2() {
        for &(ab, nu, c11, c22, c23) in &[
            (0.5, 0.28, 3.7335, 3.0256, 0.9435),
            (1.0, 0.28, 4.2262, 3.7049, 1.4881),
            (2.0, 0.28, 5.2037, 4.9715, 2.6566),
            (1.0, 0.30, 4.3000, 3.7285, 1.5003),
        ] {
            let k = coefficients::<f64>(ab, nu).unwrap();
            assert!(close(k.c11, c11, 6e-5), "{ab} {nu} {k:?}");
            assert!(close(k.c22, c22, 6e-5), "{ab} {nu} {k:?}");
            assert!(close(k.c23, c23, 6e-5), "{ab} {nu} {k:?}");
        }
    }
}
