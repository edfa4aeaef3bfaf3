//! Kalker creepage coefficients (methods.md §2, §10.2).

use wrc_host_tests::data::data_file;
use wrc_host_tests::table::Table;
use wrc_kernel::kalker::{self, RatioKind, KALKER_TABLE};

/// The const table equals `kalker_coefficients.csv` value for value.
#[test]
fn const_table_equals_csv() {
    let t = Table::read(&data_file("kalker_coefficients.csv"));
    assert_eq!(t.rows.len(), KALKER_TABLE.len());
    let cols = [
        "C11_nu0",
        "C11_nu0.25",
        "C11_nu0.5",
        "C22_nu0",
        "C22_nu0.25",
        "C22_nu0.5",
        "C23_nu0",
        "C23_nu0.25",
        "C23_nu0.5",
        "C33_nu0",
        "C33_nu0.25",
        "C33_nu0.5",
    ];
    for (i, row) in KALKER_TABLE.iter().enumerate() {
        let kind = match t.str(i, "ratio_kind") {
            "a/b" => RatioKind::AOverB,
            "b/a" => RatioKind::BOverA,
            k => panic!("unknown ratio kind {k}"),
        };
        assert_eq!(row.kind, kind, "row {i}");
        assert_eq!(row.g, t.f64(i, "g").unwrap(), "row {i}");
        for (j, col) in cols.iter().enumerate() {
            assert_eq!(row.c[j], t.f64(i, col).unwrap(), "row {i} {col}");
        }
    }
}

/// At every table node and every tabulated ν the rule returns the table value (f = 0 or 1, Lagrange
/// through the node) — to 1e-12 relative.
#[test]
fn nodes_reproduced() {
    for row in KALKER_TABLE.iter() {
        let ab = match row.kind {
            RatioKind::AOverB => row.g,
            RatioKind::BOverA => 1.0 / row.g,
        };
        for (p, nu) in [0.0, 0.25, 0.5].into_iter().enumerate() {
            let k = kalker::coefficients(ab, nu).unwrap();
            for (q, v) in [k.c11, k.c22, k.c23, k.c33].into_iter().enumerate() {
                let want = row.c[3 * q + p];
                assert!(
                    ((v - want) / want).abs() < 1e-12,
                    "a/b={ab} nu={nu} q={q}: {v} vs {want}"
                );
            }
        }
    }
}

/// §2 reference values (ν = 0.28 and 0.30), printed to 5 digits → 6e-5 absolute.
#[test]
fn reference_values() {
    for &(ab, nu, c11, c22, c23) in &[
        (0.5, 0.28, 3.7335, 3.0256, 0.9435),
        (1.0, 0.28, 4.2262, 3.7049, 1.4881),
        (2.0, 0.28, 5.2037, 4.9715, 2.6566),
        (1.0, 0.30, 4.3000, 3.7285, 1.5003),
    ] {
        let k = kalker::coefficients::<f64>(ab, nu).unwrap();
        assert!(
            (k.c11 - c11).abs() < 6e-5 && (k.c22 - c22).abs() < 6e-5 && (k.c23 - c23).abs() < 6e-5,
            "{ab}: {k:?}"
        );
        let k32 = kalker::coefficients::<f32>(ab as f32, nu as f32).unwrap();
        assert!((k32.c11 as f64 - c11).abs() < 1e-4 && (k32.c23 as f64 - c23).abs() < 1e-4);
    }
}

/// Kalker's asymptotes (§2 item 4) in closed form, g = a/b (`ab`) or b/a, ν: C11, C22, C23, C33
/// (C33 of a ≫ b: none, NaN).
fn asymptote(ab: bool, g: f64, nu: f64) -> [f64; 4] {
    use std::f64::consts::PI;
    if ab {
        let c23 = PI * g.sqrt() / (3.0 * (1.0 - nu)) * (1.0 + nu * ((16.0 / g).ln() - 5.0));
        [
            PI * PI / (4.0 * (1.0 - nu)),
            PI * PI / 4.0,
            c23,
            PI * PI / (16.0 * (1.0 - nu) * g),
        ]
    } else {
        let lam = (16.0 / (g * g)).ln();
        let k3 = 3.0 - 4f64.ln();
        let c11 = 2.0 * PI / ((lam - 2.0 * nu) * g) * (1.0 + k3 / (lam - 2.0 * nu));
        let d2 = (1.0 - nu) * lam + 2.0 * nu;
        let c22 = 2.0 * PI / g * (1.0 + (1.0 - nu) * k3 / d2) / d2;
        let c23 = 2.0 * PI / (3.0 * g.powf(1.5) * ((1.0 - nu) * lam - 2.0 + 4.0 * nu));
        [c11, c22, c23, f64::NAN]
    }
}

fn arr(k: &kalker::KalkerCoefficients<f64>) -> [f64; 4] {
    [k.c11, k.c22, k.c23, k.c33]
}

/// Below the table (g < 0.1): the asymptotes plus the table's offset at the edge fading linearly
/// to 0 at g = 0, C(g) = C_asy(g) + (g/0.1)(C_tab(0.1) − C_asy(0.1)), in closed form; exact
/// asymptotes as g → 0; and the documented ratio asymptote/table at the table edge.
#[test]
fn asymptotes() {
    for nu in [0.0, 0.25, 0.28, 0.5] {
        let edge_ab = arr(&kalker::coefficients(0.1, nu).unwrap());
        let edge_ba = arr(&kalker::coefficients(10.0, nu).unwrap());
        for g in [0.09, 0.05, 0.01] {
            for (ab, edge) in [(true, edge_ab), (false, edge_ba)] {
                let k = arr(&kalker::coefficients(if ab { g } else { 1.0 / g }, nu).unwrap());
                let (asy, asy_edge) = (asymptote(ab, g, nu), asymptote(ab, 0.1, nu));
                for q in 0..4 {
                    let want = if q == 3 && !ab {
                        edge[3] // C33 of a ≫ b: the b/a = 0.1 row held
                    } else {
                        asy[q] + g / 0.1 * (edge[q] - asy_edge[q])
                    };
                    assert!(
                        ((k[q] - want) / want).abs() < 1e-12,
                        "nu {nu} g {g} ab {ab} C[{q}] {} want {want}",
                        k[q]
                    );
                }
            }
        }
        // g → 0: the asymptotes themselves (relative offset ≤ 10 g times the edge's, ≤ 6 %)
        for ab in [true, false] {
            let g = 1e-4;
            let k = arr(&kalker::coefficients(if ab { g } else { 1.0 / g }, nu).unwrap());
            let asy = asymptote(ab, g, nu);
            for q in 0..if ab { 4 } else { 3 } {
                assert!(
                    ((k[q] - asy[q]) / asy[q]).abs() < 2e-3,
                    "nu {nu} ab {ab} C[{q}]"
                );
            }
        }
    }
    // Ratios asymptote/table at the table edge g = 0.1 (§2): a/b side C11 0.98–1.02, C22
    // 0.975–0.983, C23 0.94–0.99; b/a side C11 0.957–0.97, C22 0.97–0.98, C23 ≈ 1.00 — the jump
    // CONTACT's switch at g = 0.101 has and the edge correction removes.
    for nu in [0.0, 0.25, 0.5] {
        let (asy, tab) = (
            asymptote(true, 0.1, nu),
            arr(&kalker::coefficients(0.1, nu).unwrap()),
        );
        let (r11, r22, r23) = (asy[0] / tab[0], asy[1] / tab[1], asy[2] / tab[2]);
        assert!((0.975..=1.025).contains(&r11), "nu={nu} r11={r11}");
        assert!((0.97..=0.99).contains(&r22), "nu={nu} r22={r22}");
        assert!((0.93..=1.0).contains(&r23), "nu={nu} r23={r23}");
        let (asy, tab) = (
            asymptote(false, 0.1, nu),
            arr(&kalker::coefficients(10.0, nu).unwrap()),
        );
        let (r11, r22, r23) = (asy[0] / tab[0], asy[1] / tab[1], asy[2] / tab[2]);
        assert!((0.95..=0.975).contains(&r11), "nu={nu} b/a r11={r11}");
        assert!((0.965..=0.985).contains(&r22), "nu={nu} b/a r22={r22}");
        assert!((0.985..=1.02).contains(&r23), "nu={nu} b/a r23={r23}");
    }
}

/// Continuity across the table edge and along g: no jump anywhere in a/b ∈ [0.02, 50] (the
/// largest relative step over a 1e-6 relative change of a/b stays below 1e-4).
#[test]
fn continuous_across_the_table_edge() {
    for nu in [0.0, 0.28, 0.5] {
        for edge in [0.1, 10.0] {
            for s in [1.0 - 1e-9, 1.0 + 1e-9] {
                let (a, b) = (
                    arr(&kalker::coefficients(edge, nu).unwrap()),
                    arr(&kalker::coefficients(edge * s, nu).unwrap()),
                );
                for q in 0..4 {
                    assert!(
                        ((a[q] - b[q]) / a[q]).abs() < 1e-7,
                        "nu {nu} edge {edge} C[{q}]"
                    );
                }
            }
        }
        let mut prev = arr(&kalker::coefficients(0.02, nu).unwrap());
        let n = 200_000;
        for i in 1..=n {
            let ab = 0.02 * (2500f64).powf(i as f64 / n as f64);
            let k = arr(&kalker::coefficients(ab, nu).unwrap());
            for q in 0..4 {
                assert!(
                    ((k[q] - prev[q]) / prev[q]).abs() < 1e-3,
                    "nu {nu} a/b {ab} C[{q}] {} → {}",
                    prev[q],
                    k[q]
                );
            }
            prev = k;
        }
    }
}

#[test]
fn typed_errors() {
    use wrc_kernel::Error;
    assert_eq!(
        kalker::coefficients(f64::NAN, 0.28).map(|k| k.c11),
        Err(Error::NonFinite("a/b"))
    );
    assert_eq!(
        kalker::coefficients(0.0, 0.28).map(|k| k.c11),
        Err(Error::NonPositive("a/b"))
    );
    assert_eq!(
        kalker::coefficients(1.0, 0.6).map(|k| k.c11),
        Err(Error::OutOfRange("nu"))
    );
    assert!(kalker::coefficients(1e-30f64, 0.28)
        .unwrap()
        .c33
        .is_finite());
    assert!(kalker::coefficients(1e30f64, 0.28).unwrap().c23.is_finite());
    // C33 ~ 1/g and C23 ~ g^(-3/2) overflow: a typed error, not ∞.
    assert_eq!(
        kalker::coefficients(1e-310f64, 0.28).map(|k| k.c33),
        Err(Error::OutOfRange("a/b"))
    );
    assert_eq!(
        kalker::coefficients(1e300f64, 0.28).map(|k| k.c23),
        Err(Error::OutOfRange("a/b"))
    );
}
