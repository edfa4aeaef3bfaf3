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
use wrc_kernel::fastrip::{fastrip, FastripSettings, LambdaVariant};
use wrc_kernel::fastsim::{fastsim, FastsimSettings};
use wrc_kernel::patch::{
    CellOut, CellSink, Creepage, Ellipse, GridExtent, HertzPressure, StripPatch, Tangential,
    TractionBound,
};
use wrc_kernel::{hertz, kalker, math, Error, Material, Real};

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
    /// A per-precision quantity (e.g. iterations of a solve whose tolerance depends on the float
    /// type): exact against the host in the same precision, not compared between `f32` and `f64`.
    PerPrecision,
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
    /// A per-precision count (iterations).
    pub fn per_precision(&mut self, n: u32) {
        self.push(T::from_usize(n as usize), Kind::PerPrecision);
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

case_table!(
    material,
    maths,
    hertz,
    kalker,
    fastsim_parabolic,
    fastsim_elliptic,
    fastsim_contact_m3_44,
    fastrip_default,
    fastrip_original_m6,
    fastrip_modified_m5,
    rejects,
);

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

/// CONTACT's `fastsim` example (methods.md §10.1, §10.4): a = 8, b = 4 mm, N = 82 kN, G = 82 000 MPa,
/// ν = 0.28, μ = 0.3, ξ = 0, η = −6.25e-4, φ = 6.25e-4 rad/mm, grid ±1.1a × ±1.1b.
pub mod a8b4 {
    /// Semi-axis a along x, mm.
    pub const A: f64 = 8.0;
    /// Semi-axis b along y, mm.
    pub const B: f64 = 4.0;
    /// Normal load, N.
    pub const N: f64 = 82_000.0;
    /// Combined shear modulus, MPa.
    pub const G: f64 = 82_000.0;
    /// Combined Poisson ratio.
    pub const NU: f64 = 0.28;
    /// Friction coefficient.
    pub const MU: f64 = 0.3;
    /// Lateral creepage.
    pub const ETA: f64 = -6.25e-4;
    /// Spin creepage, rad/mm.
    pub const PHI: f64 = 6.25e-4;
    /// Strips × cells of the firmware's FASTSIM/FaStrip runs.
    pub const GRID: usize = 32;
}

fn contact_material<T: Real>() -> Result<Material<T>, Error> {
    Material::from_g_nu(T::from_f64(a8b4::G), T::from_f64(a8b4::NU))
}

fn a8b4_creepage<T: Real>() -> Creepage<T> {
    Creepage {
        xi: T::ZERO,
        eta: T::from_f64(a8b4::ETA),
        phi: T::from_f64(a8b4::PHI),
    }
}

/// Floor of the force comparisons, in units of μN (forces near zero compare absolutely).
const FORCE_FLOOR: f64 = 1e-2;

/// Pushes Fx/(μN), Fy/(μN), Mz/(μN√(ab)), Fn/N, contact and slip cell counts.
fn push_totals<T: Real, const S: usize>(o: &mut Outs<T>, t: &Tangential<T, S>) {
    let mun = T::from_f64(a8b4::MU * a8b4::N);
    let c = T::from_f64(libm_sqrt_ab());
    o.real(t.total.fx / mun, FORCE_FLOOR);
    o.real(t.total.fy / mun, FORCE_FLOOR);
    o.real(t.total.mz / (mun * c), FORCE_FLOOR);
    o.real(t.total.fn_ / T::from_f64(a8b4::N), 0.0);
    o.count(t.total.n_contact);
    o.count(t.total.n_slip);
}

fn libm_sqrt_ab() -> f64 {
    // √(8·4) = √32, exact enough as a constant normaliser.
    5.656_854_249_492_381
}

/// A sink that condenses the per-cell field (traction, slip velocity, bound) into a few numbers.
struct Digest<T> {
    /// Σ |s| over slip cells (slip velocity / V).
    slip_sum: T,
    /// max |p| / g over all contact cells (≤ 1 up to rounding: the bound holds).
    max_util: T,
    /// Σ p_x, Σ p_y over the contact cells of the central strip (MPa).
    mid_px: T,
    mid_py: T,
    /// Slip cells whose traction is not on the bound (should be none).
    slip_off_bound: usize,
}

impl<T: Real> Digest<T> {
    fn new() -> Self {
        Self {
            slip_sum: T::ZERO,
            max_util: T::ZERO,
            mid_px: T::ZERO,
            mid_py: T::ZERO,
            slip_off_bound: 0,
        }
    }
    fn push(&self, o: &mut Outs<T>) {
        o.real(self.slip_sum, 0.0);
        o.real(self.max_util, 0.0);
        o.real(self.mid_px, 10.0);
        o.real(self.mid_py, 10.0);
        o.count(self.slip_off_bound);
    }
}

impl<T: Real> CellSink<T> for Digest<T> {
    fn cell(&mut self, j: usize, _i: usize, c: &CellOut<T>) {
        let p = math::hypot(c.px, c.py);
        if c.bound > T::ZERO {
            self.max_util = math::max(self.max_util, p / c.bound);
        }
        if c.slip {
            self.slip_sum += math::hypot(c.sx, c.sy);
            if math::abs(p - c.bound) > T::from_f64(1e-3) * c.bound {
                self.slip_off_bound += 1;
            }
        }
        if j == a8b4::GRID / 2 {
            self.mid_px += c.px;
            self.mid_py += c.py;
        }
    }
}

type Patch32<T> = StripPatch<T, { a8b4::GRID }, { a8b4::GRID }>;

fn a8b4_patch<T: Real, M: Meter>(m: &mut M) -> Result<(Patch32<T>, Ellipse<T>), Error> {
    let mat = contact_material::<T>()?;
    let (a, b, n) = (
        T::from_f64(a8b4::A),
        T::from_f64(a8b4::B),
        T::from_f64(a8b4::N),
    );
    m.call("StripPatch::hertz 32x32", || {
        Patch32::<T>::hertz(
            black_box(a),
            black_box(b),
            black_box(n),
            &mat,
            GridExtent::contact(),
        )
    })
}

/// Hertz (methods.md §1, §10.1): curvatures from the 8 × 4 mm ellipse, then the solve from load and
/// from approach with those curvatures, and an axis ratio near the robustness limit (A/B = 1e-3).
pub fn hertz<T: Real, M: Meter>(m: &mut M, o: &mut Outs<T>) -> Result<(), Error> {
    let mat = contact_material::<T>()?;
    let (a, b, n) = (
        T::from_f64(a8b4::A),
        T::from_f64(a8b4::B),
        T::from_f64(a8b4::N),
    );
    let inv = m.call("hertz::curvatures_from_semi_axes", || {
        hertz::curvatures_from_semi_axes(black_box(a), black_box(b), black_box(n), &mat)
    })?;
    o.real(inv.curv_a, 0.0);
    o.real(inv.curv_b, 0.0);
    o.real(inv.delta, 0.0);
    o.real(inv.p0, 0.0);
    let (ca, cb) = (inv.curv_a, inv.curv_b);
    let h = m.call("hertz::from_load", || {
        hertz::from_load(black_box(ca), black_box(cb), black_box(n), &mat)
    })?;
    for x in [
        h.a, h.b, h.p0, h.delta, h.coef.m, h.coef.n, h.coef.r, h.coef.k, h.coef.e,
    ] {
        o.real(x, 0.0);
    }
    o.flag(h.coef.converged);
    o.per_precision(h.coef.iterations);
    let d = h.delta;
    let ha = m.call("hertz::from_approach", || {
        hertz::from_approach(black_box(ca), black_box(cb), black_box(d), &mat)
    })?;
    o.real(ha.load, 0.0);
    o.real(ha.a, 0.0);
    // Robustness: curvature ratio giving an axis ratio far below 1e-1.
    let (sa, sb) = (T::from_f64(1e-6), T::from_f64(1e-3));
    let thin = m.call("hertz::from_load A/B=1e-3", || {
        hertz::from_load(black_box(sa), black_box(sb), black_box(n), &mat)
    })?;
    o.real(thin.a, 0.0);
    o.real(thin.b, 0.0);
    o.real(thin.coef.g, 0.0);
    o.flag(thin.coef.converged);
    o.per_precision(thin.coef.iterations);
    Ok(())
}

/// Kalker coefficients (methods.md §2): table interpolation at a/b = 0.5 and 2, the thin-ellipse
/// extrapolations at a/b = 0.05 and 20.
pub fn kalker<T: Real, M: Meter>(m: &mut M, o: &mut Outs<T>) -> Result<(), Error> {
    let nu = T::from_f64(0.28);
    for (label, ab) in [
        ("kalker::coefficients a/b=0.5", 0.5),
        ("kalker::coefficients a/b=2", 2.0),
        ("kalker::coefficients a/b=0.05", 0.05),
        ("kalker::coefficients a/b=20", 20.0),
    ] {
        let r = T::from_f64(ab);
        let k = m.call(label, || kalker::coefficients(black_box(r), black_box(nu)))?;
        for x in [k.c11, k.c22, k.c23, k.c33] {
            o.real(x, 0.0);
        }
    }
    Ok(())
}

fn fastsim_case<T: Real, M: Meter>(
    m: &mut M,
    o: &mut Outs<T>,
    parabolic: bool,
    label: &'static str,
) -> Result<(), Error> {
    let (patch, ell) = a8b4_patch::<T, M>(m)?;
    let pr = HertzPressure(ell);
    let cr = a8b4_creepage::<T>();
    let bound = if parabolic {
        TractionBound::Parabolic(ell)
    } else {
        TractionBound::Elliptic
    };
    let set = FastsimSettings::canonical(T::from_f64(a8b4::MU), bound);
    let t = m.call(label, || {
        fastsim(black_box(&patch), &pr, black_box(&cr), &set, &mut ())
    })?;
    push_totals(o, &t);
    let mut d = Digest::new();
    fastsim(&patch, &pr, &cr, &set, &mut d)?;
    d.push(o);
    Ok(())
}

/// FASTSIM (canonical: three flexibilities, c_off = 0) with Kalker's parabolic bound, 32 × 32.
pub fn fastsim_parabolic<T: Real, M: Meter>(m: &mut M, o: &mut Outs<T>) -> Result<(), Error> {
    fastsim_case(m, o, true, "fastsim parabolic 32x32")
}

/// FASTSIM (canonical) with the elliptic bound μ p_n, 32 × 32.
pub fn fastsim_elliptic<T: Real, M: Meter>(m: &mut M, o: &mut Outs<T>) -> Result<(), Error> {
    fastsim_case(m, o, false, "fastsim elliptic 32x32")
}

/// FASTSIM with CONTACT M=3 settings on CONTACT's own 44 × 44 grid; also flags agreement with
/// CONTACT's printed F_y/(μN) = −0.6118, M_z = −3.900e4 N·mm (methods.md §10.4) within the issue's
/// 0.5 %, and its 1264 contact elements.
pub fn fastsim_contact_m3_44<T: Real, M: Meter>(m: &mut M, o: &mut Outs<T>) -> Result<(), Error> {
    let mat = contact_material::<T>()?;
    let (a, b, n) = (
        T::from_f64(a8b4::A),
        T::from_f64(a8b4::B),
        T::from_f64(a8b4::N),
    );
    let (patch, ell) = StripPatch::<T, 44, 44>::hertz(a, b, n, &mat, GridExtent::contact())?;
    let pr = HertzPressure(ell);
    let cr = a8b4_creepage::<T>();
    let set = FastsimSettings::contact_m3(
        T::from_f64(a8b4::MU),
        TractionBound::Parabolic(ell),
        a,
        b,
        n,
    );
    let t = m.call("fastsim contact-m3 parabolic 44x44", || {
        fastsim(black_box(&patch), &pr, black_box(&cr), &set, &mut ())
    })?;
    push_totals(o, &t);
    let fy = t.total.fy.to_f64() / (a8b4::MU * a8b4::N);
    let mz = t.total.mz.to_f64();
    o.flag(libm_abs(fy / -0.6118 - 1.0) <= 5e-3);
    o.flag(libm_abs(mz / -3.900e4 - 1.0) <= 5e-3);
    o.flag(t.total.n_contact == 1264);
    Ok(())
}

fn libm_abs(x: f64) -> f64 {
    if x < 0.0 {
        -x
    } else {
        x
    }
}

/// FaStrip with the defaults of methods.md §4 (strip-theory λ, `Contact5`, canonical FASTSIM
/// directions, μ p_n), 32 × 32.
pub fn fastrip_default<T: Real, M: Meter>(m: &mut M, o: &mut Outs<T>) -> Result<(), Error> {
    let (patch, ell) = a8b4_patch::<T, M>(m)?;
    let pr = HertzPressure(ell);
    let cr = a8b4_creepage::<T>();
    let set = FastripSettings::new(T::from_f64(a8b4::MU));
    let t = m.call("fastrip default 32x32", || {
        fastrip(black_box(&patch), &pr, black_box(&cr), &set, &mut ())
    })?;
    push_totals(o, &t);
    let mut d = Digest::new();
    fastrip(&patch, &pr, &cr, &set, &mut d)?;
    d.push(o);
    Ok(())
}

/// Original FaStrip (Sichani; CONTACT M=6 set-up, exact Hertz strips), 32 × 32.
pub fn fastrip_original_m6<T: Real, M: Meter>(m: &mut M, o: &mut Outs<T>) -> Result<(), Error> {
    let (patch, ell) = a8b4_patch::<T, M>(m)?;
    let pr = HertzPressure(ell);
    let cr = a8b4_creepage::<T>();
    let set = FastripSettings::contact_m6(T::from_f64(a8b4::MU), ell, LambdaVariant::StripTheory);
    let t = m.call("fastrip original (M6) 32x32", || {
        fastrip(black_box(&patch), &pr, black_box(&cr), &set, &mut ())
    })?;
    push_totals(o, &t);
    Ok(())
}

/// Modified FaStrip (CONTACT M=5 set-up: strips from the contact cells, equivalent ellipse), 32 × 32.
pub fn fastrip_modified_m5<T: Real, M: Meter>(m: &mut M, o: &mut Outs<T>) -> Result<(), Error> {
    let (mut patch, ell) = a8b4_patch::<T, M>(m)?;
    let pr = HertzPressure(ell);
    let cr = a8b4_creepage::<T>();
    let n = T::from_f64(a8b4::N);
    let eq = m.call("StripPatch::modified_fastrip_reference 32x32", || {
        patch.modified_fastrip_reference(&pr, black_box(n))
    })?;
    o.real(eq.a, 0.0);
    o.real(eq.b, 0.0);
    let set = FastripSettings::contact_m5(
        T::from_f64(a8b4::MU),
        T::from_f64(a8b4::A),
        T::from_f64(a8b4::B),
        n,
        eq,
        LambdaVariant::StripTheory,
    );
    let t = m.call("fastrip modified (M5) 32x32", || {
        fastrip(black_box(&patch), &pr, black_box(&cr), &set, &mut ())
    })?;
    push_totals(o, &t);
    Ok(())
}

/// Typed errors on bad input, on the target too (no panic, no fault).
pub fn rejects<T: Real, M: Meter>(_m: &mut M, o: &mut Outs<T>) -> Result<(), Error> {
    let mat = contact_material::<T>()?;
    let one = T::ONE;
    let nan = T::from_f64(f64::NAN);
    let inf = T::from_f64(f64::INFINITY);
    o.flag(hertz::from_load(one, one, nan, &mat) == Err(Error::NonFinite("N")));
    o.flag(hertz::from_load(one, one, -one, &mat) == Err(Error::NonPositive("N")));
    o.flag(hertz::from_load(inf, one, one, &mat) == Err(Error::NonFinite("A")));
    o.flag(kalker::coefficients(-one, T::from_f64(0.28)).is_err());
    o.flag(kalker::coefficients(one, T::from_f64(0.6)) == Err(Error::OutOfRange("nu")));
    let (a, b, n) = (
        T::from_f64(a8b4::A),
        T::from_f64(a8b4::B),
        T::from_f64(a8b4::N),
    );
    o.flag(
        StripPatch::<T, 2, 32>::hertz(a, b, n, &mat, GridExtent::contact()).map(|_| ())
            == Err(Error::GridTooSmall("strips")),
    );
    let (patch, ell) = StripPatch::<T, 8, 8>::hertz(a, b, n, &mat, GridExtent::contact())?;
    let pr = HertzPressure(ell);
    let bad = Creepage {
        xi: nan,
        eta: T::ZERO,
        phi: T::ZERO,
    };
    let set = FastsimSettings::canonical(T::from_f64(a8b4::MU), TractionBound::Elliptic);
    o.flag(fastsim(&patch, &pr, &bad, &set, &mut ()).map(|_| ()) == Err(Error::NonFinite("xi")));
    let zero_mu = FastripSettings::new(T::ZERO);
    o.flag(
        fastrip(&patch, &pr, &a8b4_creepage(), &zero_mu, &mut ()).map(|_| ())
            == Err(Error::NonPositive("mu")),
    );
    Ok(())
}
