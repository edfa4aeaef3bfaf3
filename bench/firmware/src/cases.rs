//! The on-target test cases, shared verbatim by the firmware (Cortex-M, under QEMU) and by the host
//! generator `wrc-bench`'s `firmware-expected` binary, which includes this file with `#[path]`.
//!
//! Each case runs kernel calls generic over the float type `T` and pushes its results into an
//! [`Outs`]. The host runs every case in `f32` and `f64` and writes the results bit-exactly into
//! `expected.rs`; the firmware runs the same cases on the target and compares. Every kernel call
//! whose cost is of interest goes through [`Meter::call`]: a no-op on the host, an instruction,
//! stack and timing meter on the target.
//!
//! Inputs are passed through [`black_box`] inside the metered closure so the compiler cannot fold
//! the kernel call at build time.

use core::hint::black_box;
use wrc_kernel::{math, Error, Material, Real};

/// Capacity of one case's result vector.
pub const MAX_VALUES: usize = 32;

/// How a result compares between `f32` and `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// A real value; relative error against `max(|reference|, floor)`.
    Real {
        /// Denominator floor for values that may legitimately be close to zero.
        floor: f64,
    },
    /// A count (elements in stick/slip, iterations): exact within one precision; between `f32` and
    /// `f64` it may differ by [`COUNT_SLACK`] (elements on the stick/slip boundary).
    Count,
    /// A flag (0 or 1, e.g. "converged", "expected error returned"): exact everywhere.
    Flag,
}

/// Allowed difference of a [`Kind::Count`] between the `f32` and the `f64` run.
pub const COUNT_SLACK: f64 = 2.0;

/// Results of one case, in push order.
pub struct Outs<T> {
    /// Values.
    pub v: [T; MAX_VALUES],
    /// How each value compares.
    pub kind: [Kind; MAX_VALUES],
    /// Number of values pushed.
    pub n: usize,
    /// Set if a case pushed more than [`MAX_VALUES`] values (the excess is dropped; a failure).
    pub overflow: bool,
}

impl<T: Real> Default for Outs<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Real> Outs<T> {
    /// Empty result vector.
    pub fn new() -> Self {
        Self {
            v: [T::ZERO; MAX_VALUES],
            kind: [Kind::Flag; MAX_VALUES],
            n: 0,
            overflow: false,
        }
    }
    fn push(&mut self, x: T, k: Kind) {
        if self.n < MAX_VALUES {
            self.v[self.n] = x;
            self.kind[self.n] = k;
            self.n += 1;
        } else {
            self.overflow = true;
        }
    }
    /// A real value compared relative to `max(|reference|, floor)`.
    pub fn real(&mut self, x: T, floor: f64) {
        self.push(x, Kind::Real { floor });
    }
    /// A count.
    pub fn count(&mut self, n: usize) {
        self.push(T::from_usize(n), Kind::Count);
    }
    /// A flag.
    pub fn flag(&mut self, b: bool) {
        self.push(if b { T::ONE } else { T::ZERO }, Kind::Flag);
    }
}

/// Runs one kernel call; the target implementation meters it.
pub trait Meter {
    /// Runs `f` (one kernel call) and returns its result. `label` names the call in the report.
    fn call<R, F: FnOnce() -> R>(&mut self, label: &'static str, f: F) -> R;
}

/// The host's meter: just calls.
pub struct NoMeter;

impl Meter for NoMeter {
    #[inline(always)]
    fn call<R, F: FnOnce() -> R>(&mut self, _label: &'static str, f: F) -> R {
        f()
    }
}

/// A case: runs kernel calls through the meter and pushes results.
pub type CaseFn<T, M> = fn(&mut M, &mut Outs<T>) -> Result<(), Error>;

macro_rules! case_table {
    ($($name:ident),* $(,)?) => {
        /// Case names, in table order (also written into `expected.rs` to detect a stale file).
        pub const NAMES: &[&str] = &[$(stringify!($name)),*];
        /// Number of cases.
        pub const N_CASES: usize = NAMES.len();
        /// The case functions for float type `T` and meter `M`, in the order of [`NAMES`].
        pub fn table<T: Real, M: Meter>() -> [CaseFn<T, M>; N_CASES] {
            [$($name::<T, M>),*]
        }
    };
}

case_table!(material, maths);

/// Combined material constants (methods.md §1.1): two different bodies, steel, and from G, ν.
pub fn material<T: Real, M: Meter>(m: &mut M, o: &mut Outs<T>) -> Result<(), Error> {
    let (e1, nu1, e2, nu2) = (
        T::from_f64(205_900.0),
        T::from_f64(0.28),
        T::from_f64(210_000.0),
        T::from_f64(0.30),
    );
    let two = m.call("Material::two_bodies", || {
        Material::two_bodies(black_box(e1), black_box(nu1), black_box(e2), black_box(nu2))
    })?;
    o.real(two.g, 0.0);
    o.real(two.nu, 0.0);
    o.real(two.e_star, 0.0);
    let steel = Material::<T>::steel();
    o.real(steel.g, 0.0);
    o.real(steel.e_star, 0.0);
    let gn = Material::from_g_nu(T::from_f64(82_000.0), T::from_f64(0.28))?;
    o.real(gn.e_star, 0.0);
    // Typed errors on bad input, on the target too.
    o.flag(Material::<T>::identical(T::from_f64(f64::NAN), nu1) == Err(Error::NonFinite("E1")));
    o.flag(Material::<T>::identical(-e1, nu1) == Err(Error::NonPositive("E1")));
    o.flag(Material::<T>::identical(e1, T::HALF) == Err(Error::OutOfRange("nu1")));
    Ok(())
}

/// The maths backend (`wrc_kernel::math`) on arguments typical of the kernel: libm is expected to
/// give identical bits on host and target.
pub fn maths<T: Real, M: Meter>(m: &mut M, o: &mut Outs<T>) -> Result<(), Error> {
    let x = T::from_f64(0.731_5);
    let y = T::from_f64(-2.25);
    o.real(m.call("math::sqrt", || math::sqrt(black_box(x))), 0.0);
    o.real(m.call("math::cbrt", || math::cbrt(black_box(y))), 0.0);
    o.real(m.call("math::exp", || math::exp(black_box(y))), 0.0);
    o.real(m.call("math::ln", || math::ln(black_box(x))), 0.0);
    o.real(
        m.call("math::powf", || math::powf(black_box(x), black_box(y))),
        0.0,
    );
    o.real(m.call("math::sin", || math::sin(black_box(y))), 0.0);
    o.real(m.call("math::cos", || math::cos(black_box(y))), 0.0);
    o.real(
        m.call("math::atan2", || math::atan2(black_box(y), black_box(x))),
        0.0,
    );
    o.real(m.call("math::asinh", || math::asinh(black_box(y))), 0.0);
    o.real(
        m.call("math::hypot", || math::hypot(black_box(x), black_box(y))),
        0.0,
    );
    o.real(math::acos(x), 0.0);
    o.real(math::asin(x), 0.0);
    o.real(math::atan(y), 0.0);
    o.real(math::tan(x), 0.0);
    o.real(math::floor(y), 0.0);
    Ok(())
}
