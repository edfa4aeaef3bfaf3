//! Property tests: random and garbage inputs (NaN, ±∞, zero, negative, subnormal, huge) never panic;
//! every call returns a typed error or finite results.

use proptest::prelude::*;
use wrc_kernel::fastrip::{
    fastrip, BoundCheck, FastripSettings, LambdaVariant, LargeSpin, SpinInX,
};
use wrc_kernel::fastsim::{fastsim, FastsimSettings, FlexMode};
use wrc_kernel::patch::{
    CellPressure, Creepage, Ellipse, Flexibilities, GridExtent, HertzPressure, SemiEllipticStrips,
    Strip, StripPatch, Tangential, TractionBound,
};
use wrc_kernel::{hertz, kalker, Material};

/// Any f64 bit pattern class (incl. NaN, ±∞, subnormal) half of the time, a physical magnitude the
/// other half (so that the deeper code paths are reached too).
fn garbage() -> impl Strategy<Value = f64> {
    prop_oneof![
        proptest::num::f64::ANY,
        -1e3..1e3f64,
        1e-6..1e6f64,
        Just(0.0),
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(1e300),
        Just(1e-300),
    ]
}

fn positive() -> impl Strategy<Value = f64> {
    prop_oneof![1e-3..1e3f64, 1e-8..1e8f64, garbage()]
}

fn creep() -> impl Strategy<Value = f64> {
    prop_oneof![-1e-2..1e-2f64, -1e-5..1e-5f64, Just(0.0), garbage()]
}

fn finite_totals<const S: usize>(r: &Tangential<f64, S>) {
    let t = &r.total;
    assert!(
        t.fx.is_finite() && t.fy.is_finite() && t.mz.is_finite() && t.fn_.is_finite(),
        "{t:?}"
    );
    assert!(t.n_slip <= t.n_contact);
    for s in r.strips.iter() {
        assert!(s.fx.is_finite() && s.fy.is_finite() && s.mz.is_finite());
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, .. ProptestConfig::default() })]

    #[test]
    fn hertz_never_panics(a in positive(), b in positive(), n in positive(), nu in garbage(), g in positive()) {
        if let Ok(m) = Material::from_g_nu(g, nu) {
            let all = [hertz::from_load(a, b, n, &m), hertz::from_approach(a, b, n * 1e-5, &m),
                       hertz::curvatures_from_semi_axes(a, b, n, &m)];
            for s in all.iter().flatten() {
                for v in [s.a, s.b, s.p0, s.delta, s.load, s.curv_a, s.curv_b, s.coef.m, s.coef.n, s.coef.r] {
                    prop_assert!(v.is_finite() && v > 0.0, "{s:?}");
                }
            }
        }
        if let Ok(c) = hertz::coefficients_theta(a) {
            prop_assert!(c.m.is_finite() && c.n.is_finite() && c.r.is_finite());
        }
        if let Ok(s) = hertz::solve_axis_ratio(b) {
            prop_assert!(s.g.is_finite() && s.g > 0.0 && s.g <= 1.0);
        }
        if let Ok(e) = hertz::elliptic_integrals(a) {
            prop_assert!(e.k.is_finite() && e.e.is_finite());
        }
        // f32 as well.
        if let Ok(m) = Material::<f32>::from_g_nu(g as f32, nu as f32) {
            if let Ok(s) = hertz::from_load(a as f32, b as f32, n as f32, &m) {
                prop_assert!(s.a.is_finite() && s.p0.is_finite() && s.delta.is_finite());
            }
        }
    }

    #[test]
    fn kalker_never_panics(ab in positive(), nu in garbage()) {
        if let Ok(k) = kalker::coefficients(ab, nu) {
            for v in [k.c11, k.c22, k.c23, k.c33] {
                prop_assert!(v.is_finite() && v > 0.0, "{ab} {nu} {k:?}");
            }
        }
        if let Ok(k) = kalker::coefficients(ab as f32, nu as f32) {
            prop_assert!(k.c11.is_finite() && k.c23.is_finite());
        }
    }

    #[test]
    fn hertz_patch_solvers_never_panic(
        a in positive(), b in positive(), n in positive(),
        fx in prop_oneof![1.0..3.0f64, garbage()], fy in prop_oneof![1.0..3.0f64, garbage()],
        xi in creep(), eta in creep(), phi in creep(), mu in prop_oneof![0.05..1.0f64, garbage()],
        c_off in prop_oneof![Just(0.0), Just(1.0 / 6.0), garbage()],
        flexmode in 0usize..3, boundk in 0usize..4, variant in 0usize..8, spin in 0usize..3,
    ) {
        let mat = Material::from_g_nu(82_000.0, 0.28).unwrap();
        let Ok((patch, ell)) = StripPatch::<f64, 12, 10>::hertz(a, b, n, &mat, GridExtent { fx, fy }) else {
            return Ok(());
        };
        let cr = Creepage { xi, eta, phi };
        let bound = match boundk {
            0 => TractionBound::Parabolic(ell),
            1 => TractionBound::Elliptic,
            2 => TractionBound::StripParabolic(3.0 * std::f64::consts::PI / 8.0),
            _ => TractionBound::StripParabolic(mu),
        };
        let flex = match flexmode {
            0 => FlexMode::Three,
            1 => FlexMode::Single { sqrt_ab: (a * b).sqrt() },
            _ => FlexMode::Blended { a, b, load: n },
        };
        let set = FastsimSettings { mu, bound, c_off, flex, slip: wrc_kernel::fastsim::SlipRule::Clip };
        let both = [
            fastsim(&patch, &HertzPressure(ell), &cr, &set, &mut ()),
            fastsim(&patch, &SemiEllipticStrips, &cr, &set, &mut ()),
        ];
        for r in both.iter().flatten() {
            finite_totals(r);
        }
        let mut fs = FastripSettings::new(mu);
        fs.direction = set;
        fs.lambda = if variant & 1 == 0 { LambdaVariant::StripTheory } else { LambdaVariant::ContactCompat };
        fs.large_spin = if variant & 2 == 0 { LargeSpin::Contact5 } else { LargeSpin::FullSlip };
        fs.bound_check = match variant / 4 { 0 => BoundCheck::Off, _ => BoundCheck::Local };
        fs.spin_in_x = [SpinInX::Linear, SpinInX::RigidSlip, SpinInX::Lateral][spin];
        if let Ok(r) = fastrip(&patch, &HertzPressure(ell), &cr, &fs, &mut ()) { finite_totals(&r); }
        let m6 = FastripSettings::contact_m6(mu, Ellipse { p0: ell.p0 * 2.0, ..ell }, fs.lambda);
        if let Ok(r) = fastrip(&patch, &HertzPressure(ell), &cr, &m6, &mut ()) { finite_totals(&r); }
        let mut p5 = patch;
        if let Ok(eq) = p5.modified_fastrip_reference(&HertzPressure(ell), n) {
            let s5 = FastripSettings::contact_m5(mu, a, b, n, eq, fs.lambda);
            if let Ok(r) = fastrip(&p5, &HertzPressure(ell), &cr, &s5, &mut ()) { finite_totals(&r); }
        }
    }

    /// Hand-built strips and per-cell pressure arrays full of garbage.
    #[test]
    fn general_patch_never_panics(
        vals in proptest::collection::vec(garbage(), 8 * 13),
        press in proptest::collection::vec(garbage(), 8 * 8),
        x0 in garbage(), dx in positive(), xi in creep(), eta in creep(), phi in creep(),
        mu in prop_oneof![0.05..1.0f64, garbage()],
    ) {
        let mat = Material::from_g_nu(82_000.0, 0.28).unwrap();
        let mut strips = [Strip::<f64>::default(); 8];
        for (s, v) in strips.iter_mut().zip(vals.chunks(13)) {
            *s = Strip {
                y: v[0], dy: v[1], a: v[2], xc: v[3], p_hat: v[4],
                flex: Flexibilities { l1: v[5], l2: v[6], l3: v[7] },
                c11: v[8], c22: v[9], c23: v[10], c33: v[12], sqrt_b_over_a: v[11],
            };
        }
        let mut pn = [[0.0f64; 8]; 8];
        for (r, v) in pn.iter_mut().zip(press.chunks(8)) {
            r.copy_from_slice(v);
        }
        let cr = Creepage { xi, eta, phi };
        if let Ok(mut patch) = StripPatch::<f64, 8, 8>::new(strips, x0, dx, mat) {
            let set = FastsimSettings::canonical(mu, TractionBound::Elliptic);
            if let Ok(r) = fastsim(&patch, &CellPressure(&pn), &cr, &set, &mut ()) { finite_totals(&r); }
            if let Ok(r) = fastrip(&patch, &CellPressure(&pn), &cr, &FastripSettings::new(mu), &mut ()) { finite_totals(&r); }
            if patch.strips_from_pressure(&CellPressure(&pn)).is_ok() {
                if let Ok(r) = fastrip(&patch, &CellPressure(&pn), &cr, &FastripSettings::new(mu), &mut ()) { finite_totals(&r); }
            }
        }
    }
}

/// Typed errors for the documented bad inputs.
#[test]
fn typed_errors() {
    use wrc_kernel::Error;
    let mat = Material::from_g_nu(82_000.0, 0.28).unwrap();
    let ext = GridExtent::contact();
    assert_eq!(
        StripPatch::<f64, 3, 8>::hertz(8.0, 4.0, 1e4, &mat, ext).err(),
        Some(Error::GridTooSmall("strips"))
    );
    assert_eq!(
        StripPatch::<f64, 8, 3>::hertz(8.0, 4.0, 1e4, &mat, ext).err(),
        Some(Error::GridTooSmall("cells"))
    );
    assert_eq!(
        StripPatch::<f64, 8, 8>::hertz(-8.0, 4.0, 1e4, &mat, ext).err(),
        Some(Error::NonPositive("a"))
    );
    assert_eq!(
        StripPatch::<f64, 8, 8>::hertz(8.0, f64::NAN, 1e4, &mat, ext).err(),
        Some(Error::NonFinite("b"))
    );
    assert_eq!(
        StripPatch::<f64, 8, 8>::hertz(8.0, 4.0, 0.0, &mat, ext).err(),
        Some(Error::NonPositive("N"))
    );
    assert_eq!(
        StripPatch::<f64, 8, 8>::hertz(8.0, 4.0, 1e4, &mat, GridExtent { fx: 0.5, fy: 1.0 }).err(),
        Some(Error::OutOfRange("grid extent"))
    );
    let (p, e) = StripPatch::<f64, 8, 8>::hertz(8.0, 4.0, 1e4, &mat, ext).unwrap();
    let s = FastsimSettings::canonical(0.3, TractionBound::Parabolic(e));
    let bad = Creepage {
        xi: f64::NAN,
        eta: 0.0,
        phi: 0.0,
    };
    assert_eq!(
        fastsim(&p, &HertzPressure(e), &bad, &s, &mut ()).err(),
        Some(Error::NonFinite("xi"))
    );
    let ok = Creepage {
        xi: 1e-3,
        eta: 0.0,
        phi: 0.0,
    };
    let s0 = FastsimSettings::canonical(0.0, TractionBound::Elliptic);
    assert_eq!(
        fastsim(&p, &HertzPressure(e), &ok, &s0, &mut ()).err(),
        Some(Error::NonPositive("mu"))
    );
    assert_eq!(
        fastrip(
            &p,
            &HertzPressure(e),
            &Creepage {
                phi: f64::INFINITY,
                ..ok
            },
            &FastripSettings::new(0.3),
            &mut ()
        )
        .err(),
        Some(Error::NonFinite("phi"))
    );
    // Too few contact cells: an ellipse far smaller than its grid cannot be made (extent ≤ 10), but a
    // hand-built patch with one short strip can.
    let mut strips = p.strips;
    for s in strips.iter_mut() {
        s.a = 0.0;
    }
    strips[0].a = 0.5 * p.dx;
    assert_eq!(
        StripPatch::<f64, 8, 8>::new(strips, p.x0, p.dx, mat).err(),
        Some(Error::GridTooSmall("contact cells"))
    );
}
