//! Validation of FASTSIM and FaStrip on Hertz patches (methods.md §10.3, §10.4 creep curve, §10.6,
//! §10.7), each case in f64 and f32 (forces within 1e-4 relative of each other).

use wrc_host_tests::cases::{contact_material, VecSink};
use wrc_host_tests::data::data_file;
use wrc_host_tests::table::Table;
use wrc_kernel::fastrip::{fastrip, FastripSettings, LambdaVariant};
use wrc_kernel::fastsim::{fastsim, FastsimSettings};
use wrc_kernel::patch::{
    Creepage, Ellipse, GridExtent, HertzPressure, StripPatch, Totals, TractionBound,
};
use wrc_kernel::{hertz, kalker, Real};

use std::f64::consts::PI;

fn cr<T: Real>(xi: f64, eta: f64, phi: f64) -> Creepage<T> {
    Creepage {
        xi: T::from_f64(xi),
        eta: T::from_f64(eta),
        phi: T::from_f64(phi),
    }
}

fn tf<T: Real>(t: &Totals<T>) -> [f64; 3] {
    [t.fx.to_f64(), t.fy.to_f64(), t.mz.to_f64()]
}

/// f32 forces against f64: |ΔF| ≤ 1e-4 |F| per component, with |F| the larger force component for
/// F_x, F_y (a vanishing component is compared on the scale of the other) and max(|M_z|, |F|·1 mm)
/// for M_z (a moment that vanishes by symmetry is compared on the scale of the forces times 1 mm).
fn assert_f32(label: &str, a: [f64; 3], b: [f64; 3]) {
    let s = b[0].abs().max(b[1].abs());
    let ez = (a[2] - b[2]).abs() / b[2].abs().max(s);
    let e = ((a[0] - b[0]).abs() / s)
        .max((a[1] - b[1]).abs() / s)
        .max(ez);
    assert!(e < 1e-4, "{label}: f32 {a:?} vs f64 {b:?} (rel {e:.1e})");
}

// ---------------------------------------------------------------------------------------------------
// §10.3 Kalker's linear theory at vanishing creepage, a/b = 0.1 … 10.
// ---------------------------------------------------------------------------------------------------

/// The three linear-theory responses [F_x(ξ), F_y(η), F_y(φ)] of FASTSIM (canonical, parabolic) and
/// FaStrip (defaults) on an S × C grid tight over the ellipse (±a × ±b), relative to Kalker's values.
fn linear_errors<T: Real, const S: usize, const C: usize>(
    ab: f64,
) -> ([f64; 3], [f64; 3], [[f64; 3]; 6]) {
    let mat = contact_material::<T>();
    let (a, b) = (5.0 * ab.sqrt(), 5.0 / ab.sqrt());
    let (patch, ell) = StripPatch::<T, S, C>::hertz(
        T::from_f64(a),
        T::from_f64(b),
        T::from_f64(50_000.0),
        &mat,
        GridExtent::tight(),
    )
    .unwrap();
    let k = kalker::coefficients(a / b, 0.28).unwrap();
    let (g, c) = (82_000.0, (a * b).sqrt());
    let eps = 1e-7;
    let cases = [
        (cr::<T>(eps, 0.0, 0.0), -g * c * c * k.c11 * eps, 0),
        (cr::<T>(0.0, eps, 0.0), -g * c * c * k.c22 * eps, 1),
        (
            cr::<T>(0.0, 0.0, eps / c),
            -g * c * c * c * k.c23 * eps / c,
            1,
        ),
    ];
    let mut e_fs = [0.0; 3];
    let mut e_fr = [0.0; 3];
    let mut forces = [[0.0; 3]; 6];
    let pr = HertzPressure(ell);
    let sfs = FastsimSettings::canonical(T::from_f64(0.3), TractionBound::Parabolic(ell));
    let sfr = FastripSettings::new(T::from_f64(0.3));
    for (n, (c, want, comp)) in cases.iter().enumerate() {
        let t1 = fastsim(&patch, &pr, c, &sfs, &mut ()).unwrap().total;
        let t2 = fastrip(&patch, &pr, c, &sfr, &mut ()).unwrap().total;
        forces[2 * n] = tf(&t1);
        forces[2 * n + 1] = tf(&t2);
        e_fs[n] = tf(&t1)[*comp] / want - 1.0;
        e_fr[n] = tf(&t2)[*comp] / want - 1.0;
    }
    (e_fs, e_fr, forces)
}

/// Grid 400 × 400 over ±a × ±b: FASTSIM's error is first order in the cell size (measured +1.28 %,
/// +0.65 %, +0.31 % on 100², 200², 400² for F_x, independent of a/b); FaStrip's adhesion traction has an
/// integrable √ singularity at the trailing edge at vanishing creepage, so it converges erratically
/// (−1.5 %, +0.3…1.0 %, −0.08…+0.30 %). 400² is the coarsest uniform grid where both are inside 1 %
/// for all a/b with margin.
#[test]
fn kalker_linear_limit() {
    for ab in [0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0] {
        let (fs, fr, f64s) = linear_errors::<f64, 400, 400>(ab);
        println!(
            "a/b {ab:5}: FASTSIM Fx {:+.3} % Fy(eta) {:+.3} % Fy(phi) {:+.3} %; FaStrip {:+.3} % {:+.3} % {:+.3} %",
            100.0 * fs[0], 100.0 * fs[1], 100.0 * fs[2], 100.0 * fr[0], 100.0 * fr[1], 100.0 * fr[2]
        );
        for e in fs.iter().chain(fr.iter()) {
            assert!(e.abs() < 0.01, "a/b {ab}: {fs:?} {fr:?}");
        }
        let (_, _, f32s) = linear_errors::<f32, 400, 400>(ab);
        for (a, b) in f32s.iter().zip(f64s.iter()) {
            assert_f32(&format!("linear a/b {ab}"), *a, *b);
        }
    }
}

// ---------------------------------------------------------------------------------------------------
// §10.7 Full slip.
// ---------------------------------------------------------------------------------------------------

fn full_slip<T: Real, const G: usize>(ab: f64) -> Vec<(String, [f64; 3])> {
    let mat = contact_material::<T>();
    let (a, b) = (5.0 * ab.sqrt(), 5.0 / ab.sqrt());
    let (patch, ell) = StripPatch::<T, G, G>::hertz(
        T::from_f64(a),
        T::from_f64(b),
        T::from_f64(50_000.0),
        &mat,
        GridExtent::contact(),
    )
    .unwrap();
    let pr = HertzPressure(ell);
    let mu = T::from_f64(0.3);
    let mut out = vec![];
    for k in 0..24 {
        let th = k as f64 * PI / 12.0;
        let c = cr::<T>(0.1 * th.cos(), 0.1 * th.sin(), 0.0);
        for (name, bound) in [
            ("parabolic", TractionBound::Parabolic(ell)),
            ("elliptic", TractionBound::Elliptic),
            (
                "strip 3pi/8",
                TractionBound::StripParabolic(T::from_f64(3.0 * PI / 8.0)),
            ),
            (
                "strip 4/3",
                TractionBound::StripParabolic(T::from_f64(4.0 / 3.0)),
            ),
        ] {
            let t = fastsim(
                &patch,
                &pr,
                &c,
                &FastsimSettings::canonical(mu, bound),
                &mut (),
            )
            .unwrap();
            assert_eq!(t.total.n_slip, t.total.n_contact, "{name}: all cells slip");
            out.push((format!("FASTSIM {name} th {k}"), tf(&t.total)));
        }
        let t = fastrip(&patch, &pr, &c, &FastripSettings::new(mu), &mut ()).unwrap();
        assert_eq!(t.total.n_slip, t.total.n_contact, "FaStrip: all cells slip");
        out.push((format!("FaStrip th {k}"), tf(&t.total)));
    }
    out
}

/// |F| → μN within 0.5 % in 24 directions of (ξ, η) at |creepage| = 0.1, a/b = 0.1, 1, 10, on the
/// 44² and 100² CONTACT-style grids (measured worst: parabolic 3e-5, elliptic 7.6e-4, strip 3π/8
/// 2.6e-4, FaStrip 7.6e-4); `StripParabolic(4/3)` saturates at 32/(9π) μN (§3.2) within 0.5 %.
#[test]
fn full_slip_every_direction() {
    let mun = 0.3 * 50_000.0;
    let mut worst: f64 = 0.0;
    for ab in [0.1, 1.0, 10.0] {
        let r64 = [full_slip::<f64, 44>(ab), full_slip::<f64, 100>(ab)];
        let r32 = [full_slip::<f32, 44>(ab), full_slip::<f32, 100>(ab)];
        for (v64, v32) in r64.iter().zip(r32.iter()) {
            for ((name, f), (_, g)) in v64.iter().zip(v32.iter()) {
                let want = if name.contains("4/3") {
                    32.0 / (9.0 * PI)
                } else {
                    1.0
                };
                let e = f[0].hypot(f[1]) / mun / want - 1.0;
                if !name.contains("4/3") {
                    worst = worst.max(e.abs());
                }
                assert!(
                    e.abs() < 5e-3,
                    "a/b {ab} {name}: |F|/muN = {}",
                    f[0].hypot(f[1]) / mun
                );
                assert_f32(&format!("full slip a/b {ab} {name}"), *g, *f);
            }
        }
    }
    println!("full slip: worst ||F|/(mu N) - 1| = {worst:.2e}");
}

/// §10.7 grid sums δxδyΣg/(μN) on CONTACT's ±1.1a × ±1.1b grid for a = 8, b = 4: 44²: 1.0000
/// (parabolic), 1.0008 (elliptic); 22²: 1.0004, 1.0023 (printed to 4 decimals).
#[test]
fn bound_grid_sums() {
    fn sums<const G: usize>() -> [f64; 2] {
        let (patch, ell): (StripPatch<f64, G, G>, Ellipse<f64>) = wrc_host_tests::cases::a8b4();
        let mut out = [0.0; 2];
        for (k, bound) in [TractionBound::Parabolic(ell), TractionBound::Elliptic]
            .into_iter()
            .enumerate()
        {
            let mut sink = VecSink::default();
            fastsim(
                &patch,
                &HertzPressure(ell),
                &cr(0.0, 0.03, 0.0),
                &FastsimSettings::canonical(0.3, bound),
                &mut sink,
            )
            .unwrap();
            out[k] = sink.0.iter().map(|c| c.2.area * c.2.bound).sum::<f64>() / (0.3 * 82_000.0);
        }
        out
    }
    for (got, want) in [
        (sums::<44>(), [1.0000, 1.0008]),
        (sums::<22>(), [1.0004, 1.0023]),
    ] {
        for (g, w) in got.iter().zip(want.iter()) {
            assert!((g - w).abs() < 6e-5, "{got:?} vs {want:?}");
        }
    }
}

// ---------------------------------------------------------------------------------------------------
// §10.6 Carter's 2-D creep curve in the long-strip limit.
// ---------------------------------------------------------------------------------------------------

/// An ellipse a = 1 mm, b = 1000 mm (a/b = 1e-3: C11 = π²/(4(1−ν)), Kalker's asymptote) with the
/// centre-strip pressure of CONTACT's `carter2d` (P' = 35 780 N/200 mm, p0 = 2P'/(πa) = 113.9 MPa,
/// ξ_c = 2(1−ν)μp0/G = 6.0e-4). Each strip is a Carter problem with its own p̂_j:
/// F_x,j = −sign(ξ) μ f_j [1 − (1 − |ξ|/ξ_c,j)²], f_j = (π/2) a_j p̂_j δy.
fn carter<T: Real>() -> Vec<[f64; 3]> {
    let mat = contact_material::<T>();
    let p0 = 2.0 * (35_780.0 / 200.0) / PI;
    let n = 2.0 * PI * 1000.0 * p0 / 3.0;
    let (patch, ell) = StripPatch::<T, 200, 200>::hertz(
        T::ONE,
        T::from_f64(1000.0),
        T::from_f64(n),
        &mat,
        GridExtent::tight(),
    )
    .unwrap();
    let mu = 0.3;
    let mut out = vec![];
    for xi in [-2.4e-4, -1e-5, 1e-4, 3e-4, 5.9e-4, 1e-3] {
        let r = fastrip(
            &patch,
            &HertzPressure(ell),
            &cr::<T>(xi, 0.0, 0.0),
            &FastripSettings::new(T::from_f64(mu)),
            &mut (),
        )
        .unwrap();
        let mut analytic = 0.0;
        let mut centre = [0.0; 2];
        for (j, s) in patch.strips.iter().enumerate() {
            let (aj, ph, dy) = (s.a.to_f64(), s.p_hat.to_f64(), s.dy.to_f64());
            let fj = PI / 2.0 * aj * ph * dy;
            let xic = 2.0 * (1.0 - 0.28) * mu * ph / 82_000.0;
            let q = (1.0 - xi.abs() / xic).max(0.0);
            let v = -xi.signum() * mu * fj * (1.0 - q * q);
            analytic += v;
            if j == 100 {
                centre = [r.strips[j].fx.to_f64() / (mu * fj), v / (mu * fj)];
            }
        }
        out.push([r.total.fx.to_f64(), analytic, 0.0]);
        out.push([centre[0], centre[1], 0.0]);
        out.push(tf(&r.total));
    }
    out
}

/// FaStrip reproduces Carter strip by strip: total within 1e-3 of the analytic sum (measured ≤ 2e-4),
/// and CONTACT's `carter2d` point ξ = −2.4e-4 → F_x/(μP') = 0.6400 on the centre strip (measured
/// 0.64002; CONTACT's exact full theory gives 0.6480, a different model).
#[test]
fn carter_long_strip() {
    let r64 = carter::<f64>();
    let r32 = carter::<f32>();
    for (k, (v, w)) in r64.chunks(3).zip(r32.chunks(3)).enumerate() {
        let (tot, cen) = (v[0], v[1]);
        println!(
            "case {k}: total/analytic − 1 = {:+.2e}, centre strip {:.5} vs {:.5}",
            tot[0] / tot[1] - 1.0,
            cen[0],
            cen[1]
        );
        assert!((tot[0] / tot[1] - 1.0).abs() < 1e-3);
        assert!((cen[0] - cen[1]).abs() < 2e-3 * cen[1].abs().max(0.05));
        assert_f32("carter", w[2], v[2]);
    }
    let c = r64[1];
    assert!(
        (c[0] - 0.6400).abs() < 5e-4 && (c[1] - 0.6400).abs() < 1e-4,
        "{c:?}"
    );
}

// ---------------------------------------------------------------------------------------------------
// §10.4 creep curve (CONTACT `tractcurv`, pure ξ) and §10.3 convergence rows.
// ---------------------------------------------------------------------------------------------------

const TC_N: f64 = 106_700.0;
const TC_MU: f64 = 0.33;

/// F_x/(μN) of [FASTSIM parabolic, FASTSIM elliptic, FaStrip M=5 (StripTheory), FaStrip M=6 form
/// (exact strips, defaults)] for the tractcurv case (A = 0.8e-3, a/b = 0.5, N = 106.7 kN) on CONTACT's
/// grid: C cells along x, S strips along y over ±1.1a × ±1.1b.
fn tractcurv<T: Real, const S: usize, const C: usize>(xi: f64) -> [f64; 4] {
    let mat = contact_material::<T>();
    let ca = T::from_f64(0.8e-3);
    let cb = ca * hertz::shape_ratio(T::HALF).unwrap();
    let h = hertz::from_load(ca, cb, T::from_f64(TC_N), &mat).unwrap();
    let (patch, ell) =
        StripPatch::<T, S, C>::hertz(h.a, h.b, h.load, &mat, GridExtent::contact()).unwrap();
    let mu = T::from_f64(TC_MU);
    let c = cr::<T>(xi, 0.0, 0.0);
    let pr = HertzPressure(ell);
    let mun = TC_MU * TC_N;
    let par = fastsim(
        &patch,
        &pr,
        &c,
        &FastsimSettings::canonical(mu, TractionBound::Parabolic(ell)),
        &mut (),
    )
    .unwrap();
    let el = fastsim(
        &patch,
        &pr,
        &c,
        &FastsimSettings::canonical(mu, TractionBound::Elliptic),
        &mut (),
    )
    .unwrap();
    let mut p5 = patch;
    let eq = p5.modified_fastrip_reference(&pr, h.load).unwrap();
    let s5 = FastripSettings::contact_m5(mu, h.a, h.b, h.load, eq, LambdaVariant::StripTheory);
    let m5 = fastrip(&p5, &pr, &c, &s5, &mut ()).unwrap();
    let m6 = fastrip(&patch, &pr, &c, &FastripSettings::new(mu), &mut ()).unwrap();
    [par, el, m5, m6].map(|t| t.total.fx.to_f64() / mun)
}

/// CSV rows 61–90 (CONTACT FASTSIM parabolic on 48 × 44; for pure ξ CONTACT's blending and c_off do
/// not act, so canonical FASTSIM applies) and the spec's elliptic and FaStrip (M=5) columns: printed
/// to 4 digits, asserted within 2e-4 of F_x/(μN).
#[test]
fn tractcurv_creep_curve() {
    let t = Table::read(&data_file("contact_reference/tractcurv_eurosprinter.csv"));
    let mut rows = 0;
    for r in 0..t.rows.len() {
        if t.str(r, "curve") != "fastsim_parabolic" {
            continue;
        }
        let xi = t.f64(r, "cksi").unwrap();
        let want = t.f64(r, "fx_rel").unwrap();
        let got = tractcurv::<f64, 44, 48>(xi);
        let tol = if xi < 1e-4 { 1e-6 } else { 2e-4 };
        println!(
            "xi {xi:e}: FASTSIM parabolic {:.5} vs CONTACT {want}",
            got[0]
        );
        assert!(
            (got[0] - want).abs() <= tol,
            "xi {xi}: {} vs {want}",
            got[0]
        );
        let g32 = tractcurv::<f32, 44, 48>(xi);
        for (a, b) in g32.iter().zip(got.iter()) {
            assert!((a - b).abs() <= 1e-4 * b.abs(), "f32 xi {xi}: {a} vs {b}");
        }
        rows += 1;
    }
    assert_eq!(rows, 30);
    // §10.4 table: elliptic FASTSIM and FaStrip (M5 form) columns.
    let spec = [
        (4e-4, -0.2763, -0.2558),
        (8e-4, -0.5075, -0.4721),
        (1.2e-3, -0.6762, -0.6503),
        (1.6e-3, -0.7893, -0.7859),
        (2.0e-3, -0.8623, -0.8851),
        (2.4e-3, -0.9089, -0.9510),
        (2.8e-3, -0.9389, -0.9876),
        (3.2e-3, -0.9584, -1.0005),
    ];
    for (xi, el, m5) in spec {
        let got = tractcurv::<f64, 44, 48>(xi);
        println!(
            "xi {xi:e}: FASTSIM elliptic {:.5} vs {el}; FaStrip M5 {:.5} vs {m5}",
            got[1], got[2]
        );
        assert!(
            (got[1] - el).abs() <= 2e-4 && (got[2] - m5).abs() <= 2e-4,
            "xi {xi}: {got:?}"
        );
    }
}

/// §10.3: F_x/(μN) at ξ = 1e-5 on 48×44, 96×88, 192×176 — FASTSIM −7.13e-3, −6.99e-3, −6.94e-3;
/// FaStrip (exact strips) −7.07e-3, −6.94e-3, −6.91e-3; FaStrip M5 −6.61e-3, −6.79e-3, −7.17e-3
/// (printed to 3 digits: ±6e-6); linear theory −6.910e-3.
#[test]
fn linear_limit_convergence_tractcurv() {
    let g = [
        tractcurv::<f64, 44, 48>(1e-5),
        tractcurv::<f64, 88, 96>(1e-5),
        tractcurv::<f64, 176, 192>(1e-5),
    ];
    let want = [
        [-7.13e-3, -6.99e-3, -6.94e-3],
        [-6.61e-3, -6.79e-3, -7.17e-3],
        [-7.07e-3, -6.94e-3, -6.91e-3],
    ];
    for (k, col) in [0usize, 2, 3].into_iter().enumerate() {
        for (n, w) in want[k].iter().enumerate() {
            println!("method {col} grid {n}: {:.4e} vs {w:e}", g[n][col]);
            assert!(
                (g[n][col] - w).abs() <= 6e-6,
                "method {col} grid {n}: {} vs {w}",
                g[n][col]
            );
        }
    }
    // Linear theory F_x = −G ab C11 ξ: −6.910e-3 μN.
    let k = kalker::coefficients(0.5, 0.28).unwrap();
    let h = hertz::from_load(
        0.8e-3,
        0.8e-3 * hertz::shape_ratio(0.5).unwrap(),
        TC_N,
        &contact_material(),
    )
    .unwrap();
    let lin = -82_000.0 * h.a * h.b * k.c11 * 1e-5 / (TC_MU * TC_N);
    assert!((lin + 6.910e-3).abs() < 1e-6, "{lin}");
}

/// FaStrip's spin moment in the linear limit (pure spin φ = 1e-7/c, 400 × 400 over ±a × ±b,
/// a/b = 0.1 … 10). The spin part of X_j = k_x(ξ − wφy_j) gives each strip
/// F_x,j = −(2G/π)C11 a_j(ξ − wφy_j)·dy (the adhesion traction P κd(S₁ − S₂)/d integrates to
/// π a_j P X_j/(1−ν) as d → 0), and the lateral spin term P φ* S₁ has no moment about the strip
/// centre, so M_z = −w G C11 φ a b³/4, with w = 3π√(b/a)C23/(4(1−ν)C11) for [`SpinInX::Lateral`]
/// (published), 1 for [`SpinInX::RigidSlip`] and 4aC33/(bC11) for [`SpinInX::Linear`] (default;
/// then M_z = Kalker's −G c⁴ C33 φ). Asserted within 1 % of the closed form (the grid's erratic
/// trailing-edge convergence, see `kalker_linear_limit`; measured ≤ 0.45 %). Against Kalker
/// (printed): Lateral +42 % at a/b = 0.1, +2 % at 1, −19 % at 10; RigidSlip 0 / −11 / −40 %.
#[test]
fn fastrip_linear_spin_moment() {
    use wrc_kernel::fastrip::SpinInX;
    for ab in [0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0] {
        let mat = contact_material::<f64>();
        let (a, b) = (5.0 * f64::sqrt(ab), 5.0 / f64::sqrt(ab));
        let (patch, ell) =
            StripPatch::<f64, 400, 400>::hertz(a, b, 50_000.0, &mat, GridExtent::tight()).unwrap();
        let k = kalker::coefficients(a / b, 0.28).unwrap();
        let (g, nu, c) = (82_000.0, 0.28, (a * b).sqrt());
        let phi = 1e-7 / c;
        let kalker = -g * c.powi(4) * k.c33 * phi;
        let f = 3.0 * std::f64::consts::PI * (b / a).sqrt() * k.c23 / (4.0 * (1.0 - nu) * k.c11);
        let pr = HertzPressure(ell);
        let mut line = format!("a/b {ab:4}:");
        let linear = 4.0 * a * k.c33 / (b * k.c11);
        for (sp, w) in [
            (SpinInX::Lateral, f),
            (SpinInX::RigidSlip, 1.0),
            (SpinInX::Linear, linear),
        ] {
            let mut s = FastripSettings::new(0.3);
            s.spin_in_x = sp;
            let mz = fastrip(&patch, &pr, &cr::<f64>(0.0, 0.0, phi), &s, &mut ())
                .unwrap()
                .total
                .mz;
            let want = -w * g * k.c11 * phi * a * b.powi(3) / 4.0;
            line += &format!(
                " {sp:?} {:+.3} % of the closed form, {:+.1} % of Kalker;",
                100.0 * (mz / want - 1.0),
                100.0 * (mz / kalker - 1.0)
            );
            assert!((mz / want - 1.0).abs() < 0.01, "{line}");
        }
        println!("{line}");
    }
}
