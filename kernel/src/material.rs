//! Combined elastic constants of two quasi-identical bodies (methods.md §1.1).

use crate::error::{check_positive, Error};
use crate::Real;

/// Combined material of the wheel (body 1) and rail (body 2).
///
/// `g` is the combined shear modulus G (MPa), `nu` the combined Poisson ratio ν and `e_star` the
/// contact modulus E* = G/(1−ν) (MPa). The kernel assumes quasi-identity (K = 0), which holds for
/// steel on steel.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Material<T> {
    /// Combined shear modulus G, MPa.
    pub g: T,
    /// Combined Poisson ratio ν.
    pub nu: T,
    /// Contact modulus E* = G/(1−ν), MPa.
    pub e_star: T,
}

impl<T: Real> Material<T> {
    /// Both bodies of the same material: Young's modulus `e` (MPa) and Poisson ratio `nu`.
    pub fn identical(e: T, nu: T) -> Result<Self, Error> {
        Self::two_bodies(e, nu, e, nu)
    }

    /// Two bodies (methods.md §1.1): G = 2/(1/G1 + 1/G2), ν = (G/2)(ν1/G1 + ν2/G2), E* = G/(1−ν).
    pub fn two_bodies(e1: T, nu1: T, e2: T, nu2: T) -> Result<Self, Error> {
        check_positive(e1, "E1")?;
        check_positive(e2, "E2")?;
        for (nu, name) in [(nu1, "nu1"), (nu2, "nu2")] {
            crate::error::check_finite(nu, name)?;
            if nu < T::ZERO || nu >= T::HALF {
                return Err(Error::OutOfRange(name));
            }
        }
        let g1 = e1 / (T::TWO * (T::ONE + nu1));
        let g2 = e2 / (T::TWO * (T::ONE + nu2));
        let g = T::TWO / (T::ONE / g1 + T::ONE / g2);
        let nu = g / T::TWO * (nu1 / g1 + nu2 / g2);
        Ok(Self {
            g,
            nu,
            e_star: g / (T::ONE - nu),
        })
    }

    /// From combined G (MPa) and ν directly (as CONTACT's input does).
    pub fn from_g_nu(g: T, nu: T) -> Result<Self, Error> {
        check_positive(g, "G")?;
        crate::error::check_finite(nu, "nu")?;
        if nu < T::ZERO || nu >= T::HALF {
            return Err(Error::OutOfRange("nu"));
        }
        Ok(Self {
            g,
            nu,
            e_star: g / (T::ONE - nu),
        })
    }

    /// Steel as in An et al. (2019): E = 205.9 GPa, ν = 0.28 → G = 80 429.7 MPa, E* = 111 707.9 MPa.
    pub fn steel() -> Self {
        let e = T::from_f64(205_900.0);
        let nu = T::from_f64(0.28);
        let g = e / (T::TWO * (T::ONE + nu));
        Self {
            g,
            nu,
            e_star: g / (T::ONE - nu),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steel_matches_spec() {
        let m = Material::<f64>::steel();
        assert!((m.g - 80_429.687_5).abs() < 1e-6);
        assert!((m.e_star - 111_707.9).abs() < 0.1);
        let m2 = Material::<f64>::identical(205_900.0, 0.28).unwrap();
        assert!((m2.g - m.g).abs() < 1e-9 && (m2.nu - 0.28).abs() < 1e-15);
    }

    #[test]
    fn rejects_bad_inputs() {
        assert_eq!(
            Material::<f64>::identical(f64::NAN, 0.28),
            Err(Error::NonFinite("E1"))
        );
        assert_eq!(
            Material::<f64>::identical(-1.0, 0.28),
            Err(Error::NonPositive("E1"))
        );
        assert_eq!(
            Material::<f64>::identical(1.0, 0.5),
            Err(Error::OutOfRange("nu1"))
        );
    }
}
