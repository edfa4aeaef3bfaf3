//! Typed errors: small, `Copy`, and saying which stage failed and why.

/// Why a kernel call could not produce a result.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum Error {
    /// An input was NaN or infinite; the payload names the input.
    NonFinite(&'static str),
    /// An input that must be strictly positive was zero or negative; the payload names it.
    NonPositive(&'static str),
    /// An input lies outside its documented range; the payload names it.
    OutOfRange(&'static str),
    /// The grid (strips × cells) is too small to resolve the patch; the payload names the dimension.
    GridTooSmall(&'static str),
    /// Wheel and rail do not touch at this position (the gap is positive everywhere).
    NoContact,
    /// More contact regions than the fixed capacity holds.
    TooManyRegions,
    /// A profile table is malformed (too few points, non-monotone lateral coordinate, …).
    BadProfile(&'static str),
    /// A contact table's bytes are wrong, truncated or damaged ([`crate::table`]); the payload
    /// names the check that failed.
    BadTable(&'static str),
    /// The wheel is off the rail: at this lateral shift the wheel's rigid contact point lies on
    /// the top of its flange (within [`crate::geometry::FLANGE_TIP_BAND`] of the flange tip's
    /// height, past the steepest point of the flank) or beyond the tip on the flange-back side,
    /// i.e. the wheel has been lifted by the whole flange height (the shift is beyond the
    /// flange contact the profiles describe).
    Derailed,
}

impl core::fmt::Display for Error {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Error::NonFinite(w) => write!(f, "non-finite input: {w}"),
            Error::NonPositive(w) => write!(f, "input must be positive: {w}"),
            Error::OutOfRange(w) => write!(f, "input out of range: {w}"),
            Error::GridTooSmall(w) => write!(f, "grid too small: {w}"),
            Error::NoContact => write!(f, "no contact: wheel and rail do not touch"),
            Error::TooManyRegions => write!(f, "more contact regions than the capacity"),
            Error::BadProfile(w) => write!(f, "bad profile: {w}"),
            Error::BadTable(w) => write!(f, "bad contact table: {w}"),
            Error::Derailed => write!(
                f,
                "wheel off the rail: the contact lies on the flange tip or beyond it (lateral shift too large)"
            ),
        }
    }
}

/// Returns `Err(NonFinite)` unless `x` is finite, `Err(NonPositive)` unless `x > 0`.
pub fn check_positive<T: crate::Real>(x: T, name: &'static str) -> Result<T, Error> {
    if !T::is_finite(x) {
        Err(Error::NonFinite(name))
    } else if x <= T::ZERO {
        Err(Error::NonPositive(name))
    } else {
        Ok(x)
    }
}

/// Returns `Err(NonFinite)` unless `x` is finite.
pub fn check_finite<T: crate::Real>(x: T, name: &'static str) -> Result<T, Error> {
    if T::is_finite(x) {
        Ok(x)
    } else {
        Err(Error::NonFinite(name))
    }
}
