//! FASTSIM and FaStrip against CONTACT's `fastsim` example (methods.md §10.4–§10.5,
//! `contact_reference/fastsim_hertz_a8_b4.csv`) and the spec re-implementation rows.
//!
//! Tolerances: the issue asks FASTSIM F_y within 0.5 %, FaStrip within 1 %. CONTACT prints 4 digits;
//! we reproduce the printed values to their precision, so the tests assert |ΔF_y/(μN)| ≤ 2e-4 and
//! |ΔM_z|/|M_z| ≤ 5e-4 (≈ 1 unit of the 4th digit), which implies the tolerances.

use wrc_host_tests::cases::{a8b4, contact_material, VecSink};
use wrc_host_tests::data::data_file;
use wrc_host_tests::table::Table;
use wrc_kernel::fastrip::{fastrip, FastripSettings, LambdaVariant};
use wrc_kernel::fastsim::{fastsim, FastsimSettings};
use wrc_kernel::patch::{Creepage, Ellipse, HertzPressure, StripPatch, Tangential, TractionBound};

const N: f64 = 82_000.0;
const MU: f64 = 0.3;

fn creep(sign: f64) -> Creepage<f64> {
    Creepage {
        xi: 0.0,
        eta: -6.25e-4 * sign,
        phi: 6.25e-4 * sign,
    }
}

#[derive(Clone, Copy, Debug)]
enum Method {
    /// FASTSIM, CONTACT M=3 settings (blending, c_off 1/6).
    FastsimM3 { parabolic: bool },
    /// FASTSIM canonical (no blending, c_off 0).
    FastsimCanonical { parabolic: bool },
    /// FASTSIM, no blending, c_off 1/6.
    FastsimNoBlendOffset { parabolic: bool },
    /// FaStrip CONTACT M=5 set-up; `blend` = direction pass with blending and c_off 1/6.
    FastripM5 { lambda: LambdaVariant, blend: bool },
    /// FaStrip CONTACT M=6 set-up (exact Hertz strips).
    FastripM6 { lambda: LambdaVariant },
    /// FaStrip as first specified (Hertz strips, StripTheory, Contact5, canonical `Clip` FASTSIM
    /// directions, μp_n, no bound check): `FastripSettings::spec_clip`, the spec's prototype rows.
    FastripSpecClip,
    /// FaStrip kernel defaults (`FastripSettings::new`).
    FastripDefault,
}

fn solve_on<const G: usize>(m: Method, sign: f64) -> Tangential<f64, G> {
    let (patch, ell): (StripPatch<f64, G, G>, Ellipse<f64>) = a8b4();
    let pr = HertzPressure(ell);
    let cr = creep(sign);
    let bound = |par: bool| {
        if par {
            TractionBound::Parabolic(ell)
        } else {
            TractionBound::Elliptic
        }
    };
    match m {
        Method::FastsimM3 { parabolic } => {
            let s = FastsimSettings::contact_m3(MU, bound(parabolic), 8.0, 4.0, N);
            fastsim(&patch, &pr, &cr, &s, &mut ()).unwrap()
        }
        Method::FastsimCanonical { parabolic } => {
            let s = FastsimSettings::canonical(MU, bound(parabolic));
            fastsim(&patch, &pr, &cr, &s, &mut ()).unwrap()
        }
        Method::FastsimNoBlendOffset { parabolic } => {
            let mut s = FastsimSettings::canonical(MU, bound(parabolic));
            s.c_off = 1.0 / 6.0;
            fastsim(&patch, &pr, &cr, &s, &mut ()).unwrap()
        }
        Method::FastripM5 { lambda, blend } => {
            let mut p5 = patch;
            let eq = p5.modified_fastrip_reference(&pr, N).unwrap();
            let mut s = FastripSettings::contact_m5(MU, 8.0, 4.0, N, eq, lambda);
            if !blend {
                s.direction = FastsimSettings::canonical(MU, TractionBound::Elliptic);
            }
            fastrip(&p5, &pr, &cr, &s, &mut ()).unwrap()
        }
        Method::FastripM6 { lambda } => {
            let s = FastripSettings::contact_m6(MU, ell, lambda);
            fastrip(&patch, &pr, &cr, &s, &mut ()).unwrap()
        }
        Method::FastripSpecClip => {
            let s = FastripSettings::spec_clip(MU);
            fastrip(&patch, &pr, &cr, &s, &mut ()).unwrap()
        }
        Method::FastripDefault => {
            let s = FastripSettings::new(MU);
            fastrip(&patch, &pr, &cr, &s, &mut ()).unwrap()
        }
    }
}

struct Got {
    fy_rel: f64,
    mz: f64,
    n_contact: usize,
    n_slip: usize,
}

fn solve(m: Method, fine: bool, sign: f64) -> Got {
    let t = if fine {
        solve_on::<220>(m, sign).total
    } else {
        solve_on::<44>(m, sign).total
    };
    Got {
        fy_rel: t.fy / (MU * N),
        mz: t.mz,
        n_contact: t.n_contact,
        n_slip: t.n_slip,
    }
}

fn check(label: &str, g: &Got, fy_rel: f64, mz: f64) {
    let dfy = (g.fy_rel - fy_rel).abs();
    let dmz = ((g.mz - mz) / mz).abs();
    println!(
        "{label}: Fy/(muN) {:.5} (ref {fy_rel}, |d| {dfy:.1e}, {:.3} %), Mz {:.5e} (ref {mz:.4e}, {:.3} %), contact {}, slip {}",
        g.fy_rel,
        100.0 * dfy / fy_rel.abs(),
        g.mz,
        100.0 * dmz,
        g.n_contact,
        g.n_slip
    );
    assert!(dfy <= 2e-4, "{label}: Fy/(muN) {} vs {fy_rel}", g.fy_rel);
    assert!(dmz <= 5e-4, "{label}: Mz {} vs {mz}", g.mz);
}

/// Every row of `fastsim_hertz_a8_b4.csv` except CONTACT's exact solution (case 1, TANG's job).
#[test]
fn contact_reference_csv() {
    let t = Table::read(&data_file("contact_reference/fastsim_hertz_a8_b4.csv"));
    let mut n_rows = 0;
    for r in 0..t.rows.len() {
        let method = t.str(r, "method").to_string();
        let fine = method.contains("fine");
        let sign = if t.f64(r, "cphi").unwrap() < 0.0 {
            -1.0
        } else {
            1.0
        };
        let m = match method.as_str() {
            "CONTACT_exact" => continue,
            s if s.starts_with("FASTSIM_parabolic") => Method::FastsimM3 { parabolic: true },
            s if s.starts_with("FASTSIM_elliptic") => Method::FastsimM3 { parabolic: false },
            s if s.starts_with("FaStrip_elliptic") => Method::FastripM5 {
                lambda: LambdaVariant::ContactCompat,
                blend: true,
            },
            s => panic!("unknown method {s}"),
        };
        // Case 8: rolling direction and spin reversed in CONTACT's fixed frame. Our frame always rolls
        // in +x (§0.2): rotate by π about z (η → −η, φ unchanged, F_y → −F_y, M_z unchanged), i.e.
        // solve with (η, φ) = (+6.25e-4, −6.25e-4) and map F_y back.
        let reversed = method.ends_with("reversed");
        assert_eq!(t.f64(r, "ceta").unwrap(), -6.25e-4);
        let mut g = solve(m, fine, sign);
        if reversed {
            g.fy_rel = -g.fy_rel;
        }
        let fy_rel = t.f64(r, "fy_rel").unwrap();
        let mz = t.f64(r, "MZ").unwrap();
        check(&method, &g, fy_rel, mz);
        // FY column in N: printed to 4 digits.
        let fy = t.f64(r, "FY").unwrap();
        assert!(((g.fy_rel * MU * N - fy) / fy).abs() < 5e-4, "{method}: FY");
        // Issue tolerances (implied by the above, asserted for the record).
        let tol = if method.starts_with("FaStrip") {
            0.01
        } else {
            0.005
        };
        assert!(((g.fy_rel - fy_rel) / fy_rel).abs() < tol);
        n_rows += 1;
    }
    assert_eq!(n_rows, 7);
}

/// Element counts on 44² (§10.4, §10.5): CONTACT M=3 parabolic 1264 contact / 526 slip; canonical
/// 522 slip; M=5 FaStrip 626 adhesion / 638 slip.
#[test]
fn element_counts_44() {
    let g = solve(Method::FastsimM3 { parabolic: true }, false, 1.0);
    assert_eq!((g.n_contact, g.n_slip), (1264, 526));
    let g = solve(Method::FastsimCanonical { parabolic: true }, false, 1.0);
    assert_eq!((g.n_contact, g.n_slip), (1264, 522));
    for lambda in [LambdaVariant::ContactCompat, LambdaVariant::StripTheory] {
        let g = solve(
            Method::FastripM5 {
                lambda,
                blend: true,
            },
            false,
            1.0,
        );
        assert_eq!((g.n_contact - g.n_slip, g.n_slip), (626, 638));
    }
}

/// §10.4 flexibilities: Kalker 4.9996e-5, 5.2331e-5, 4.0790e-5; CONTACT blended 4.9374e-5, 5.1522e-5,
/// 4.0903e-5 (mm³/N), printed to 5 digits.
#[test]
fn flexibilities() {
    let (patch, _) = a8b4::<f64, 44, 44>();
    let f = patch.strips[22].flex;
    for (x, y) in [(f.l1, 4.9996e-5), (f.l2, 5.2331e-5), (f.l3, 4.0790e-5)] {
        assert!(((x - y) / y).abs() < 2e-5, "{x} vs {y}");
    }
    let k = wrc_kernel::kalker::coefficients(2.0, 0.28).unwrap();
    let b = f.blended(&creep(1.0), 8.0, 4.0, N, MU, 82_000.0, k.c11, k.c22);
    for (x, y) in [(b.l1, 4.9374e-5), (b.l2, 5.1522e-5), (b.l3, 4.0903e-5)] {
        assert!(((x - y) / y).abs() < 2e-5, "{x} vs {y}");
    }
}

/// CONTACT's printed pmax of the FASTSIM rows: the largest bound/μ at a cell centre, 1629 (parabolic
/// 44²), 1631 (parabolic 220²), 1223 (elliptic = Hertz p at the centre cells).
#[test]
fn printed_pmax() {
    let (patch, ell) = a8b4::<f64, 44, 44>();
    for (bound, want) in [
        (TractionBound::Parabolic(ell), 1629.0),
        (TractionBound::Elliptic, 1223.0),
    ] {
        let mut sink = VecSink::default();
        fastsim(
            &patch,
            &HertzPressure(ell),
            &creep(1.0),
            &FastsimSettings::canonical(MU, bound),
            &mut sink,
        )
        .unwrap();
        let pmax = sink.0.iter().map(|c| c.2.bound / MU).fold(0.0, f64::max);
        assert!((pmax - want).abs() < 0.5, "{pmax} vs {want}");
    }
    let (patch, ell) = a8b4::<f64, 220, 220>();
    let mut sink = VecSink::default();
    fastsim(
        &patch,
        &HertzPressure(ell),
        &creep(1.0),
        &FastsimSettings::canonical(MU, TractionBound::Parabolic(ell)),
        &mut sink,
    )
    .unwrap();
    let pmax = sink.0.iter().map(|c| c.2.bound / MU).fold(0.0, f64::max);
    assert!((pmax - 1631.0).abs() < 0.5, "{pmax}");
}

/// The spec's other FASTSIM rows (§10.4): canonical, and no blending with c_off = 1/6.
#[test]
fn spec_fastsim_rows() {
    let rows: [(Method, bool, f64, Option<f64>); 6] = [
        (
            Method::FastsimCanonical { parabolic: true },
            false,
            -0.5978,
            Some(-3.969e4),
        ),
        (
            Method::FastsimCanonical { parabolic: false },
            false,
            -0.5927,
            Some(-4.886e4),
        ),
        (
            Method::FastsimNoBlendOffset { parabolic: true },
            false,
            -0.6172,
            None,
        ),
        (
            Method::FastsimNoBlendOffset { parabolic: true },
            true,
            -0.6414,
            None,
        ),
        (
            Method::FastsimNoBlendOffset { parabolic: false },
            false,
            -0.6035,
            None,
        ),
        (
            Method::FastsimNoBlendOffset { parabolic: false },
            true,
            -0.5976,
            None,
        ),
    ];
    for (m, fine, fy, mz) in rows {
        let g = solve(m, fine, 1.0);
        check(&format!("{m:?} fine={fine}"), &g, fy, mz.unwrap_or(g.mz));
    }
}

/// §10.5 FaStrip table: M=5 rows (CONTACT-verified) and the M=6 ‡ and prototype rows (spec
/// re-implementation regressions), 44² and 220².
#[test]
fn spec_fastrip_rows() {
    use LambdaVariant::{ContactCompat as CC, StripTheory as ST};
    let rows: [(Method, [f64; 4]); 7] = [
        (
            Method::FastripM5 {
                lambda: CC,
                blend: true,
            },
            [-0.6435, -4.816e4, -0.6442, -4.757e4],
        ),
        (
            Method::FastripM5 {
                lambda: CC,
                blend: false,
            },
            [-0.6385, -4.860e4, -0.6438, -4.762e4],
        ),
        (
            Method::FastripM5 {
                lambda: ST,
                blend: true,
            },
            [-0.6102, -4.903e4, -0.6104, -4.841e4],
        ),
        (
            Method::FastripM5 {
                lambda: ST,
                blend: false,
            },
            [-0.6052, -4.946e4, -0.6099, -4.846e4],
        ),
        (
            Method::FastripM6 { lambda: CC },
            [-0.6148, -4.972e4, -0.6278, -4.851e4],
        ),
        (
            Method::FastripM6 { lambda: ST },
            [-0.5808, -5.057e4, -0.5939, -4.936e4],
        ),
        (
            Method::FastripSpecClip,
            [-0.6026, -4.92e4, -0.6097, -4.845e4],
        ),
    ];
    for (m, r) in rows {
        check(&format!("{m:?} 44"), &solve(m, false, 1.0), r[0], r[1]);
        check(&format!("{m:?} 220"), &solve(m, true, 1.0), r[2], r[3]);
    }
}

/// The kernel's default FaStrip against the grid-converged exact solution of the same case: TANG
/// (host-tests/src/tang.rs) Richardson-extrapolated from 20 and 40 elements per semi-axis gives
/// F_y/(μN) = −0.62661, M_z = −4.731e4 N·mm (10/20: −0.62665, −4.673e4; CONTACT's 44² value
/// −0.6074 is a coarse-grid value: TANG gives −0.5956 at 44², −0.6111 at 88²). On the fine 220²
/// grid the default is within 0.5 % of μN and 3 % in M_z (measured −0.6291, −4.654e4), the
/// spec's `Clip` direction pass 2.7 % off (−0.6097).
#[test]
fn default_fastrip_against_converged_exact() {
    let g = solve(Method::FastripDefault, true, 1.0);
    println!("default 220: Fy/(muN) {:.5}, Mz {:.4e}", g.fy_rel, g.mz);
    assert!((g.fy_rel - -0.62661).abs() < 5e-3, "{}", g.fy_rel);
    assert!(((g.mz - -4.731e4) / 4.731e4).abs() < 0.03, "{}", g.mz);
    let s = solve(Method::FastripSpecClip, true, 1.0);
    assert!((s.fy_rel - -0.62661).abs() > 2.5 * (g.fy_rel - -0.62661).abs());
}

/// f32 against f64 on the CONTACT example: forces within 1e-4 relative.
#[test]
fn f32_vs_f64() {
    let mat32 = contact_material::<f32>();
    let _ = mat32;
    let (p64, e64) = a8b4::<f64, 44, 44>();
    let (p32, e32) = a8b4::<f32, 44, 44>();
    let c64 = creep(1.0);
    let c32 = Creepage {
        xi: 0.0f32,
        eta: -6.25e-4,
        phi: 6.25e-4,
    };
    let cmp = |a: &Tangential<f32, 44>, b: &Tangential<f64, 44>, label: &str| {
        let scale = b.total.fy.abs().max(b.total.fx.abs());
        for (x, y, s) in [
            (a.total.fx as f64, b.total.fx, scale),
            (a.total.fy as f64, b.total.fy, scale),
            (a.total.mz as f64, b.total.mz, b.total.mz.abs()),
        ] {
            let e = (x - y).abs() / s;
            println!("{label}: f32 {x:.6e} f64 {y:.6e} rel {e:.1e}");
            assert!(e < 1e-4, "{label}: {x} vs {y}");
        }
    };
    for par in [true, false] {
        let s64 = FastsimSettings::contact_m3(
            MU,
            if par {
                TractionBound::Parabolic(e64)
            } else {
                TractionBound::Elliptic
            },
            8.0,
            4.0,
            N,
        );
        let s32 = FastsimSettings::contact_m3(
            0.3f32,
            if par {
                TractionBound::Parabolic(e32)
            } else {
                TractionBound::Elliptic
            },
            8.0,
            4.0,
            82_000.0,
        );
        let a = fastsim(&p32, &HertzPressure(e32), &c32, &s32, &mut ()).unwrap();
        let b = fastsim(&p64, &HertzPressure(e64), &c64, &s64, &mut ()).unwrap();
        cmp(&a, &b, "fastsim");
    }
    for lambda in [LambdaVariant::StripTheory, LambdaVariant::ContactCompat] {
        let mut s64 = FastripSettings::new(MU);
        s64.lambda = lambda;
        let mut s32 = FastripSettings::new(0.3f32);
        s32.lambda = lambda;
        let a = fastrip(&p32, &HertzPressure(e32), &c32, &s32, &mut ()).unwrap();
        let b = fastrip(&p64, &HertzPressure(e64), &c64, &s64, &mut ()).unwrap();
        cmp(&a, &b, "fastrip");
        let s64 = FastripSettings::contact_m6(MU, e64, lambda);
        let s32 = FastripSettings::contact_m6(0.3f32, e32, lambda);
        let a = fastrip(&p32, &HertzPressure(e32), &c32, &s32, &mut ()).unwrap();
        let b = fastrip(&p64, &HertzPressure(e64), &c64, &s64, &mut ()).unwrap();
        cmp(&a, &b, "fastrip m6");
    }
}

/// Issue 16: with the pressure scaled to carry the patch's load ([`StripPatch::scale_to_load`]),
/// FaStrip's resultant never exceeds μN — per strip (against μ times the strip's sampled load)
/// and for the patch (against μN) — in full slip and over a sweep of creepages, on a Hertz patch
/// (6 × 4 mm, 32 × 32, tight grid: before the scaling |F| = 1.0019 μN at η = 10) and on a
/// non-elliptic one (two lobes, shifted strip centres, uneven p̂_j). To rounding: 1 + 1e-12.
#[test]
fn fastrip_resultant_never_exceeds_mu_n() {
    use proptest::prelude::*;
    use proptest::test_runner::{Config, TestRunner};
    use wrc_kernel::patch::{GridExtent, SemiEllipticStrips, Strip};
    let mat = contact_material::<f64>();
    let (mut hertz, _) =
        StripPatch::<f64, 32, 32>::hertz(6.0, 4.0, 80_000.0, &mat, GridExtent::tight()).unwrap();
    // the sampled Hertz pressure carries more than N before the scaling
    let f = hertz.scale_to_load(80_000.0).unwrap();
    assert!(f < 0.999, "scale factor {f}");
    // a non-elliptic patch: two lobes of strips, centres moving along y, uneven peaks
    let template = Strip::default().with_reference(5.0, 4.0, &mat).unwrap();
    let mut strips = [template; 32];
    for (j, s) in strips.iter_mut().enumerate() {
        let y = -8.0 + (j as f64 + 0.5) * 0.5;
        let lobe = (1.0 - ((y.abs() - 4.0) / 3.5).powi(2)).max(0.0);
        s.y = y;
        s.dy = 0.5;
        s.a = 5.0 * lobe.sqrt();
        s.xc = 0.3 * y;
        s.p_hat = if lobe > 0.0 {
            900.0 * (0.6 + 0.4 * (0.7 * y).sin().abs())
        } else {
            1.0
        };
    }
    let mut odd = StripPatch::<f64, 32, 32>::new(strips, -8.0, 0.5, mat).unwrap();
    odd.scale_to_load(60_000.0).unwrap();
    let check = |patch: &StripPatch<f64, 32, 32>, load: f64, cr: Creepage<f64>| {
        let t = fastrip(
            patch,
            &SemiEllipticStrips,
            &cr,
            &FastripSettings::new(MU),
            &mut (),
        )
        .unwrap();
        assert!(
            (t.total.fn_ / load - 1.0).abs() <= 1e-12,
            "{} vs {load}",
            t.total.fn_
        );
        for (j, s) in t.strips.iter().enumerate() {
            let f = s.fx.hypot(s.fy);
            assert!(
                f <= MU * s.fn_ * (1.0 + 1e-12),
                "{cr:?} strip {j}: |F| {f} > mu F_n {}",
                MU * s.fn_
            );
        }
        let f = t.total.fx.hypot(t.total.fy);
        f / (MU * load)
    };
    for (patch, load) in [(&hertz, 80_000.0), (&odd, 60_000.0)] {
        for cr in [
            Creepage {
                xi: 0.0,
                eta: 10.0,
                phi: 0.0,
            },
            Creepage {
                xi: -10.0,
                eta: 3.0,
                phi: 0.0,
            },
            Creepage {
                xi: 0.0,
                eta: 10.0,
                phi: 0.05,
            },
        ] {
            let r = check(patch, load, cr);
            assert!(r <= 1.0 + 1e-12, "{cr:?}: |F|/(mu N) = {r}");
            if cr.phi == 0.0 {
                // full slip without spin: all cells parallel, the resultant is μN
                assert!(r > 1.0 - 1e-9, "{cr:?}: |F|/(mu N) = {r}");
            }
        }
        let mut runner = TestRunner::new(Config {
            cases: 256,
            ..Config::default()
        });
        runner
            .run(
                &(-3.0f64..3.0, -3.0f64..3.0, -0.1f64..0.1, -3.0f64..1.0),
                |(sx, sy, phi, lg)| {
                    // |ξ|, |η| up to 1e-6…3e-2: from the linear limit to full slip
                    let s = 1e-3 * 10f64.powf(lg);
                    let cr = Creepage {
                        xi: sx * s,
                        eta: sy * s,
                        phi: phi * s * 10.0,
                    };
                    let r = check(patch, load, cr);
                    prop_assert!(r <= 1.0 + 1e-12, "{:?}: |F|/(mu N) = {}", cr, r);
                    Ok(())
                },
            )
            .unwrap();
    }
}
