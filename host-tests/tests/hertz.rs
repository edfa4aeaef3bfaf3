//! Hertz theory (methods.md §1.3, §10.1) against `data/hertz_coefficients*.csv`, closed-form
//! identities and CONTACT's printed values.

use wrc_host_tests::data::data_file;
use wrc_host_tests::table::Table;
use wrc_kernel::hertz::{self, HertzSolution};
use wrc_kernel::{Error, Material};

fn rel(x: f64, y: f64) -> f64 {
    ((x - y) / y).abs()
}

/// m, n, r vs θ: the CSV was computed from the same formulas to ≥ 5 printed digits; the issue asks for
/// ≤ 0.3 %, we assert 1e-4 (the printing precision) and report the maximum.
#[test]
fn coefficients_vs_theta_csv() {
    let t = Table::read(&data_file("hertz_coefficients.csv"));
    let mut worst: f64 = 0.0;
    for i in 0..t.rows.len() {
        let th = t.f64(i, "theta_deg").unwrap().to_radians();
        let c = hertz::coefficients_theta::<f64>(th).unwrap();
        assert!(c.converged);
        for (got, col) in [
            (c.m, "m"),
            (c.n, "n"),
            (c.r, "r"),
            (c.k, "K_e"),
            (c.e, "E_e"),
        ] {
            let want = t.f64(i, col).unwrap();
            let e = rel(got, want);
            worst = worst.max(e);
            assert!(
                e < 1e-4,
                "theta={} {col}: {got} vs {want}",
                t.str(i, "theta_deg")
            );
        }
        // θ > 90°: m and n swap, r symmetric.
        let c2 = hertz::coefficients_theta::<f64>(std::f64::consts::PI - th).unwrap();
        assert!(rel(c2.m, c.n) < 1e-12 && rel(c2.n, c.m) < 1e-12 && rel(c2.r, c.r) < 1e-12);
        // Classic 3-digit table: within 0.3 % except θ = 0.5° (documented −0.7 %).
        if let (Some(cm), Some(cn)) = (t.f64(i, "classic_m"), t.f64(i, "classic_n")) {
            let lim = if t.str(i, "theta_deg") == "0.5" {
                8e-3
            } else {
                3e-3
            };
            assert!(
                rel(c.m, cm) < lim && rel(c.n, cn) < lim,
                "classic at {}",
                t.str(i, "theta_deg")
            );
        }
    }
    println!("max relative error of m,n,r,K,E vs hertz_coefficients.csv: {worst:.2e}");
}

#[test]
fn coefficients_vs_axis_ratio_csv() {
    let t = Table::read(&data_file("hertz_coefficients_vs_axis_ratio.csv"));
    for i in 0..t.rows.len() {
        let g = t.f64(i, "b_over_a").unwrap();
        let rho = 1.0 / t.f64(i, "B_over_A").unwrap();
        // Forward: g → ρ.
        assert!(
            rel(hertz::shape_ratio(g).unwrap(), rho) < 2e-5,
            "rho at g={g}"
        );
        let c = hertz::coefficients::<f64>(1.0, 1.0 / rho).unwrap();
        assert!(rel(c.g, g) < 2e-5, "g={g}: {}", c.g);
        for (got, col) in [(c.m, "m"), (c.n, "n"), (c.r, "r")] {
            assert!(rel(got, t.f64(i, col).unwrap()) < 1e-4, "g={g} {col}");
        }
    }
}

/// Closed-form identities (§1.3 items 5–6, hertz.md), relative 1e-9, for axis ratios 1e-3 … 1.
#[test]
fn closed_form_identities() {
    let mat = Material::<f64>::from_g_nu(82_000.0, 0.28).unwrap();
    let mut worst: f64 = 0.0;
    for &g in &[1e-3, 3e-3, 0.01, 0.05, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 1.0] {
        let rho = hertz::shape_ratio(g).unwrap();
        for &(ca, cb) in &[(rho * 1e-3, 1e-3), (1e-3, rho * 1e-3)] {
            let s = hertz::from_load(ca, cb, 82_000.0, &mat).unwrap();
            let (m, n, r) = (s.coef.m, s.coef.n, s.coef.r);
            let sum = ca + cb;
            let mut chk = |x: f64, y: f64| {
                let e = rel(x, y);
                worst = worst.max(e);
                assert!(e < 1e-9, "g={g} A={ca} B={cb}: {x} vs {y}");
            };
            // Axis ratio reproduced.
            chk(s.a.min(s.b) / s.a.max(s.b), g);
            // p0/a = 2E*(A+B)/(π m² n).
            chk(
                s.p0 / s.a,
                2.0 * mat.e_star * sum / (std::f64::consts::PI * m * m * n),
            );
            // a²A/δ = m²A/(r(A+B)), b²B/δ = n²B/(r(A+B)).
            chk(s.a * s.a * ca / s.delta, m * m * ca / (r * sum));
            chk(s.b * s.b * cb / s.delta, n * n * cb / (r * sum));
            // δ = 3 N K / (2π E* a_major)  (hertz.md).
            chk(
                s.delta,
                3.0 * s.load * s.coef.k / (2.0 * std::f64::consts::PI * mat.e_star * s.a.max(s.b)),
            );
            // N = C_H δ^{3/2}, C_H = (4E*/3)(A+B)^{-1/2} r^{-3/2}.
            chk(
                s.load,
                4.0 * mat.e_star / 3.0 / sum.sqrt() / r.powf(1.5) * s.delta.powf(1.5),
            );
            // Load ↔ approach round trip.
            let s2 = hertz::from_approach(ca, cb, s.delta, &mat).unwrap();
            chk(s2.load, s.load);
            chk(s2.a, s.a);
            // Inverse: semi-axes + N → curvatures.
            let inv = hertz::curvatures_from_semi_axes(s.a, s.b, s.load, &mat).unwrap();
            chk(inv.curv_a, ca);
            chk(inv.curv_b, cb);
            chk(inv.delta, s.delta);
            // Legendre's relation E K' + E' K − K K' = π/2 (K', E' at the complementary modulus).
            if g < 1.0 {
                let ep = (1.0 - g * g).sqrt();
                let i1 = hertz::elliptic_integrals(g).unwrap();
                let i2 = hertz::elliptic_integrals(ep).unwrap();
                chk(
                    i1.e * i2.k + i2.e * i1.k - i1.k * i2.k,
                    std::f64::consts::FRAC_PI_2,
                );
            }
        }
    }
    // Circle: m = n = r = 1, a³ = 3NR/(4E*), δ = a²/R.
    let s = hertz::from_load(1e-3, 1e-3, 82_000.0, &mat).unwrap();
    let rr = 1.0 / 2e-3;
    assert!(rel(s.a.powi(3), 3.0 * 82_000.0 * rr / (4.0 * mat.e_star)) < 1e-12);
    assert!(rel(s.delta, s.a * s.a / rr) < 1e-12);
    println!("max relative error of the closed-form identities: {worst:.2e}");
}

fn contact_mat() -> Material<f64> {
    Material::from_g_nu(82_000.0, 0.28).unwrap()
}

/// §10.1 case 1: a = 8, b = 4, N = 82 kN (CONTACT's fastsim example, IPOTCN = −3).
#[test]
fn contact_example_a8_b4() {
    let s: HertzSolution<f64> =
        hertz::curvatures_from_semi_axes(8.0, 4.0, 82_000.0, &contact_mat()).unwrap();
    // §10.1 prints 5–6 digits and several of them are 1–4e-5 off the exact values (CSV: m = 1.45558
    // at b/a = 0.5; K, E, p0 are checked against A&S / the closed form to 1e-12 below), hence 2–7e-5.
    let checks = [
        (s.curv_a, 0.8464e-3, 1e-4),
        (s.curv_b, 0.2406e-2, 2e-4),
        (2.0 / (s.curv_a + s.curv_b), 614.9, 1e-4),
        // The spec's δ and K are 1.5e-5 resp. 1.2e-5 below the exact values: K(m = 0.75) =
        // 2.156515647… (Abramowitz & Stegun table 17.1), δ = 3NK/(2πE*a) follows K. CONTACT prints 0.09267.
        (s.delta, 0.092668, 2e-5),
        // p0 = 3N/(2πab) = 246000/(64π) = 1223.504 exactly; the spec prints 1223.46 (3.6e-5 low).
        (s.p0, 1223.46, 5e-5),
        (s.p0, 246_000.0 / (64.0 * std::f64::consts::PI), 1e-14),
        (s.coef.g, 0.5, 1e-14),
        (s.coef.k, 2.15649, 2e-5),
        (s.coef.k, 2.156_515_647_499_6, 1e-12),
        (s.coef.e, 1.211_056_027_568_5, 1e-12),
        (s.coef.e, 1.21107, 2e-5), // exact 1.2110560 (A&S); the spec rounds up
        (s.coef.m, 1.45555, 3e-5),
        (s.coef.n, 0.72780, 3e-5),
        (s.coef.r, 0.94319, 3e-5),
    ];
    for (i, (got, want, tol)) in checks.iter().enumerate() {
        println!(
            "check {i}: {got:.6e} vs {want:.6e}, rel {:.2e}",
            rel(*got, *want)
        );
        assert!(rel(*got, *want) < *tol, "check {i}: {got} vs {want}");
    }
    // Forward from the printed curvatures reproduces the semi-axes.
    let f = hertz::from_load(s.curv_a, s.curv_b, 82_000.0, &contact_mat()).unwrap();
    assert!(rel(f.a, 8.0) < 1e-11 && rel(f.b, 4.0) < 1e-11);
}

/// §10.1 case 2: A = 0.8e-3, a/b = 0.5, N = 106.7 kN (CONTACT tractcurv, IPOTCN = −2).
#[test]
fn contact_tractcurv_case() {
    let ca = 0.8e-3;
    // a/b = 0.5 with a along x: the long axis is along y, so B/A = ρ(0.5).
    let cb = ca * hertz::shape_ratio(0.5).unwrap();
    let s = hertz::from_load(ca, cb, 106_700.0, &contact_mat()).unwrap();
    // The spec's a, b were computed from the rounded B = 0.2814e-3 (their ratio is 0.49998, not 0.5),
    // hence 5e-5 on a and b; CONTACT prints 6.304, 12.61.
    for (got, want, tol) in [
        (cb, 0.2814e-3, 2e-4),
        (s.a, 6.3035, 5e-5),
        (s.b, 12.6076, 5e-5),
        (s.delta, 0.076516, 2e-5), // same K offset as case 1
        (s.p0, 641.0, 1e-4),
    ] {
        println!("{got:.6e} vs {want:.6e}, rel {:.2e}", rel(got, want));
        assert!(rel(got, want) < tol, "{got} vs {want}");
    }
}

/// Axis ratios 1e-3 … 1 in f32 and f64: converged, f32 within 1e-4 of f64.
#[test]
fn f32_matches_f64_down_to_1e3() {
    let m64 = contact_mat();
    let m32 = Material::<f32>::from_g_nu(82_000.0, 0.28).unwrap();
    for &g in &[1e-3, 0.01, 0.1, 0.5, 1.0] {
        let rho = hertz::shape_ratio(g).unwrap();
        let s64 = hertz::from_load(1e-3, 1e-3 / rho, 50_000.0, &m64).unwrap();
        let s32 = hertz::from_load(1e-3f32, (1e-3 / rho) as f32, 50_000.0, &m32).unwrap();
        assert!(s32.coef.converged && s64.coef.converged);
        for (x, y) in [
            (s32.a, s64.a),
            (s32.b, s64.b),
            (s32.p0, s64.p0),
            (s32.delta, s64.delta),
        ] {
            assert!(rel(x as f64, y) < 1e-4, "g={g}: {x} vs {y}");
        }
        assert!(
            s64.coef.iterations <= 12,
            "g={g}: {} iterations",
            s64.coef.iterations
        );
    }
}

#[test]
fn typed_errors() {
    let m = contact_mat();
    assert_eq!(
        hertz::from_load(1e-3, 1e-3, -1.0, &m).map(|s| s.a),
        Err(Error::NonPositive("N"))
    );
    assert_eq!(
        hertz::from_load(1e-3, f64::INFINITY, 1.0, &m).map(|s| s.a),
        Err(Error::NonFinite("B"))
    );
    assert_eq!(
        hertz::from_approach(0.0, 1e-3, 0.1, &m).map(|s| s.a),
        Err(Error::NonPositive("A"))
    );
    assert_eq!(
        hertz::curvatures_from_semi_axes(f64::NAN, 1.0, 1.0, &m).map(|s| s.a),
        Err(Error::NonFinite("a"))
    );
    assert_eq!(
        hertz::coefficients_theta(4.0f64).map(|c| c.m),
        Err(Error::OutOfRange("theta"))
    );
    assert_eq!(
        hertz::elliptic_integrals(1.5f64).map(|c| c.k),
        Err(Error::OutOfRange("g"))
    );
}
