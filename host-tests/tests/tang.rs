//! Validation of the TANG steady-rolling reference (methods.md §9.2) against closed forms
//! (Carter §10.6, Kalker's linear theory §10.3, full slip §10.7) and CONTACT's exact results
//! (`data/contact_reference/`, §10.4).
//!
//! Heavier convergence checks are `#[ignore]`d; run them with
//! `cargo test -p wrc-host-tests --release --test tang -- --ignored --nocapture`.

use std::f64::consts::PI;
use wrc_host_tests::data::data_file;
use wrc_host_tests::tang::*;
use wrc_host_tests::wear_ref::{strip_wear, WearMap};

const G: f64 = 82_000.0;
const NU: f64 = 0.28;

/// Carter's case (§10.6, CONTACT `carter2d`): P' = 35 780 N / 200 mm, a = 1 mm, μ = 0.3,
/// ξ = −2.4e-4 (ξ_c = 6e-4). The 2-D (plane-strain) limit is one grid row of length L = 1e4 mm ≫ a.
/// Returns (F_x/(μP'), number of slip elements, solution, pressure).
fn carter(n_per_a: usize) -> (f64, usize, TangSolution, Vec<f64>) {
    let (a, l) = (1.0, 1e4);
    let half = (1.1 * n_per_a as f64 - 1e-9).ceil() as usize;
    let dx = a / n_per_a as f64;
    let grid = Grid {
        mx: 2 * half,
        my: 1,
        dx,
        dy: l,
        x0: -(half as f64) * dx,
        y0: -0.5 * l,
    };
    let pp = 35_780.0 / 200.0;
    let p0 = 2.0 * pp / (PI * a);
    let mut pn: Vec<f64> = (0..grid.mx)
        .map(|i| {
            let x = grid.x(i) / a;
            if x.abs() < 1.0 {
                p0 * (1.0 - x * x).sqrt()
            } else {
                0.0
            }
        })
        .collect();
    let s: f64 = pn.iter().sum::<f64>() * dx;
    pn.iter_mut().for_each(|p| *p *= pp / s);
    let sol = TangSolver::new(grid, G, NU).solve(
        &pn,
        0.3,
        Creepage {
            xi: -2.4e-4,
            eta: 0.0,
            phi: 0.0,
        },
        &TangOptions::default(),
        None,
    );
    assert!(sol.converged, "sweeps {}", sol.sweeps);
    (sol.fx / l / (0.3 * pp), sol.n_slip, sol, pn)
}

#[test]
fn carter_2d_creep_force_and_slip_zone() {
    let analytic = 1.0 - (1.0 - 0.4f64).powi(2); // 0.64
    let (f25, nslip, sol, _) = carter(25);
    println!("Carter δx = a/25: F/(μP') = {f25:.5} (analytic {analytic}, CONTACT 0.6480)");
    // Opposes ξ < 0; discretisation error at δx = a/25 no larger than CONTACT's (+1.25 %).
    assert!(f25 > 0.0);
    assert!((f25 / analytic - 1.0).abs() <= 0.0125);
    // Slip zone at the trailing edge, length 2(a − a') = 0.8 mm = 20 elements.
    assert!((19..=21).contains(&nslip), "{nslip}");
    for i in 0..sol.grid.mx {
        if sol.state[i] == ElementState::Slip {
            assert!(sol.grid.x(i) < -1.0 + 0.8 + sol.grid.dx);
        }
    }
    assert!(sol.residual < 1e-4, "{}", sol.residual);
    // First-order convergence: Richardson of a/100 and a/200 hits the closed form.
    let (f100, ..) = carter(100);
    let (f200, _, sol200, _) = carter(200);
    let rich = richardson(f100, f200);
    println!("Carter a/100 {f100:.5}, a/200 {f200:.5}, Richardson {rich:.5}");
    assert!((rich / analytic - 1.0).abs() < 1e-3);
    // Traction in the adhesion zone against Carter's closed form (§10.6), relative to μp0.
    let (a, ap) = (1.0, 0.6);
    let p0 = 2.0 * (35_780.0 / 200.0) / (PI * a);
    let mut worst: f64 = 0.0;
    for i in 0..sol200.grid.mx {
        let x = sol200.grid.x(i);
        if sol200.state[i] == ElementState::Adhesion && x > -1.0 + 0.8 + 0.02 && x < 0.98 {
            let ex = 0.3 * p0 / a
                * ((a * a - x * x).sqrt() - (ap * ap - (x - (a - ap)).powi(2)).max(0.0).sqrt());
            worst = worst.max((sol200.px[i] - ex).abs() / (0.3 * p0));
        }
    }
    println!("Carter a/200: max adhesion traction error {worst:.4} μp0");
    assert!(worst < 0.01);
}

/// Kalker creepage coefficients at ν = 0.28 from methods.md §2 (linrol interpolation rule).
fn linear_coefficients(a: f64, b: f64, n: usize) -> [f64; 3] {
    let grid = Grid::hertz(a, b, n, 1.1);
    let pn = hertz_pressure(&grid, a, b, 1.0, true);
    let solver = TangSolver::new(grid, G, NU);
    let c = (a * b).sqrt();
    let opts = TangOptions::default();
    // No slip anywhere: the traction bound is irrelevant (μ → ∞), i.e. vanishing creepage.
    let mu = 1e12;
    let rx = solver.solve(
        &pn,
        mu,
        Creepage {
            xi: 1e-4,
            ..Default::default()
        },
        &opts,
        None,
    );
    let ry = solver.solve(
        &pn,
        mu,
        Creepage {
            eta: 1e-4,
            ..Default::default()
        },
        &opts,
        None,
    );
    let rp = solver.solve(
        &pn,
        mu,
        Creepage {
            phi: 1e-5,
            ..Default::default()
        },
        &opts,
        None,
    );
    for r in [&rx, &ry, &rp] {
        assert!(r.converged && r.n_slip == 0);
    }
    [
        -rx.fx / (G * c * c * 1e-4),
        -ry.fy / (G * c * c * 1e-4),
        -rp.fy / (G * c.powi(3) * 1e-5),
    ]
}

#[test]
fn kalker_linear_theory_circle() {
    // a/b = 1, ν = 0.28: C11 4.2262, C22 3.7049, C23 1.4881 (methods.md §2).
    let kalker = [4.2262, 3.7049, 1.4881];
    let c10 = linear_coefficients(5.0, 5.0, 10);
    let c20 = linear_coefficients(5.0, 5.0, 20);
    for k in 0..3 {
        let r = richardson(c10[k], c20[k]);
        println!(
            "C{}: n=10 {:.4}, n=20 {:.4}, Richardson {:.4}, Kalker {:.4} ({:+.2} %)",
            ["11", "22", "23"][k],
            c10[k],
            c20[k],
            r,
            kalker[k],
            100.0 * (r / kalker[k] - 1.0)
        );
        assert!((r / kalker[k] - 1.0).abs() < 0.01);
    }
}

#[test]
fn full_slip_saturates_at_mu_fn() {
    let (a, b, fnn, mu) = (8.0, 4.0, 82_000.0, 0.3);
    let grid = Grid::hertz(a, b, 10, 1.1);
    let pn = hertz_pressure(&grid, a, b, fnn, true);
    let solver = TangSolver::new(grid, G, NU);
    for (xi, eta) in [(0.03, 0.0), (0.0, -0.03), (0.02, 0.02)] {
        let r = solver.solve(
            &pn,
            mu,
            Creepage { xi, eta, phi: 0.0 },
            &TangOptions::default(),
            None,
        );
        assert!(r.converged);
        assert_eq!(r.n_slip, r.n_contact);
        let f = r.fx.hypot(r.fy);
        // Exactly Σg only if all slip directions were parallel; the elastic part of the slip
        // (B p, ≈ 1e-5 here against |w| = 0.03) turns them by ≲ 1e-3 rad.
        assert!((f / (mu * fnn) - 1.0).abs() < 1e-4, "{}", f / (mu * fnn));
        // Force opposes the creepage.
        let cn = xi.hypot(eta);
        assert!(((r.fx * xi + r.fy * eta) / (f * cn) + 1.0).abs() < 1e-3);
    }
}

/// Parse a CONTACT reference CSV (comment lines start with '#').
fn read_csv(rel: &str) -> Vec<std::collections::HashMap<String, String>> {
    let text = std::fs::read_to_string(data_file(rel)).expect("reference file");
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let head: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    lines
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            head.iter()
                .cloned()
                .zip(l.split(',').map(String::from))
                .collect()
        })
        .collect()
}

/// CONTACT `fastsim.inp` case 1 (exact, 44 × 44 over ±1.1a × ±1.1b): a = 8, b = 4, F_n = 82 kN,
/// μ = 0.3, η = −6.25e-4, φ = 6.25e-4. Forces on the rail in the file (module-3 convention equal
/// to ours for this basic-contact case, §0.2).
#[test]
fn contact_fastsim_exact_44() {
    let rows = read_csv("contact_reference/fastsim_hertz_a8_b4.csv");
    let ex = rows
        .iter()
        .find(|r| r["method"] == "CONTACT_exact")
        .unwrap();
    let fy_ref: f64 = ex["fy_rel"].parse().unwrap();
    let mz_ref: f64 = ex["MZ"].parse().unwrap();
    let (a, b, fnn, mu) = (8.0, 4.0, 82_000.0, 0.3);
    let grid = Grid::hertz(a, b, 20, 1.1);
    assert_eq!((grid.mx, grid.my), (44, 44));
    let pn = hertz_pressure(&grid, a, b, fnn, true);
    let r = TangSolver::new(grid, G, NU).solve(
        &pn,
        mu,
        Creepage {
            xi: 0.0,
            eta: -6.25e-4,
            phi: 6.25e-4,
        },
        &TangOptions::default(),
        None,
    );
    let fy = r.fy / (mu * fnn);
    let c = (a * b).sqrt();
    println!(
        "44x44: Fy/(μN) {fy:.4} (CONTACT {fy_ref}), Mz {:.4e} (CONTACT {mz_ref:.4e}), contact {} (1276), slip {} (920), sweeps {}",
        r.mz, r.n_contact, r.n_slip, r.sweeps
    );
    assert!(r.converged);
    assert!((fy - fy_ref).abs() < 0.02);
    assert!(r.fx.abs() / (mu * fnn) < 0.02);
    assert!((r.mz - mz_ref).abs() / (mu * fnn * c) < 0.02);
    // The pressures differ (Hertz at element centres, 1264 elements, vs CONTACT's NORM, 1276):
    // the slip area agrees within 5 %.
    assert!((r.n_slip as f64 / 920.0 - 1.0).abs() < 0.05);
    // Per-strip wear is finite, non-negative and only where elements slip.
    let w = strip_wear(&WearMap::default(), &r, &pn, 30_000.0);
    assert_eq!(w.len(), 44);
    assert!(w.iter().all(|&z| z >= 0.0 && z.is_finite()));
    assert!(w.iter().any(|&z| z > 0.0));
    // The kernel's wear law (kernel/src/wear.rs) applied to the same TANG cells gives the same
    // strip depths as this reference (same law, independent code).
    let kmap = wrc_kernel::wear::WearMap::<f64>::kth();
    let mut kw = wrc_kernel::wear::StripWear::<f64, 44>::new();
    for j in 0..44 {
        for i in 0..44 {
            let k = r.grid.idx(i, j);
            if r.state[k] == ElementState::Slip {
                kw.add_cell(&kmap, j, pn[k], r.sx[k].hypot(r.sy[k]), 30_000.0, r.grid.dx);
            }
        }
    }
    for (j, (kd, rd)) in kw.depth.iter().zip(&w).enumerate() {
        assert!((kd - rd).abs() <= 1e-12 * rd.abs().max(1e-30), "{j}");
    }
}

/// CONTACT `tractcurv.inp` exact creep curve (Coulomb μ = 0.33, cases with curve =
/// exact_coulomb): A = 0.8e-3 1/mm, a/b = 0.5, F_n = 106.7 kN → a = 6.3035, b = 12.6076 mm
/// (§10.1), 44 × 44 grid. Forces within 2 % of μF_n.
#[test]
fn contact_tractcurv_exact_curve() {
    let rows = read_csv("contact_reference/tractcurv_eurosprinter.csv");
    let (a, b, fnn, mu) = (6.3035, 12.6076, 106_700.0, 0.33);
    let grid = Grid::hertz(a, b, 20, 1.1);
    let pn = hertz_pressure(&grid, a, b, fnn, true);
    let solver = TangSolver::new(grid, G, NU);
    let mut prev: Option<(Vec<f64>, Vec<f64>)> = None;
    let mut worst: f64 = 0.0;
    for r in rows.iter().filter(|r| r["curve"] == "exact_coulomb") {
        let xi: f64 = r["cksi"].parse().unwrap();
        let fx_ref: f64 = r["fx_rel"].parse().unwrap();
        let sol = solver.solve(
            &pn,
            mu,
            Creepage {
                xi,
                eta: 0.0,
                phi: 0.0,
            },
            &TangOptions::default(),
            prev.as_ref().map(|(x, y)| (x.as_slice(), y.as_slice())),
        );
        assert!(sol.converged);
        let fx = sol.fx / (mu * fnn);
        println!(
            "ξ {xi:.2e}: Fx/(μN) {fx:.4} (CONTACT {fx_ref}), sweeps {}",
            sol.sweeps
        );
        worst = worst.max((fx - fx_ref).abs());
        prev = Some((sol.px.clone(), sol.py.clone()));
    }
    println!("worst |ΔFx|/(μN) = {worst:.4}");
    assert!(worst < 0.02);
}

/// Kalker's linear theory for a/b = 0.5 and 2 (ν = 0.28, §2: 3.7335, 3.0256, 0.9435 and
/// 5.2037, 4.9715, 2.6566), Richardson of 20 and 40 elements per semi-axis. About a minute.
#[test]
#[ignore]
fn kalker_linear_theory_ellipses_fine() {
    for (a, b, kalker) in [
        (4.0, 8.0, [3.7335, 3.0256, 0.9435]),
        (8.0, 4.0, [5.2037, 4.9715, 2.6566]),
    ] {
        let c20 = linear_coefficients(a, b, 20);
        let c40 = linear_coefficients(a, b, 40);
        for k in 0..3 {
            let r = richardson(c20[k], c40[k]);
            println!(
                "a/b = {}: C{}: n=20 {:.4}, n=40 {:.4}, Richardson {:.4}, Kalker {:.4} ({:+.2} %)",
                a / b,
                ["11", "22", "23"][k],
                c20[k],
                c40[k],
                r,
                kalker[k],
                100.0 * (r / kalker[k] - 1.0)
            );
            assert!((r / kalker[k] - 1.0).abs() < 0.01);
        }
    }
}

/// The same CONTACT case with NORM's pressure (load control, same 44 × 44 grid) instead of Hertz at
/// element centres: TANG on the normal solution, as CONTACT computes it.
#[test]
fn contact_fastsim_exact_44_on_norm_pressure() {
    let (a, b, fnn, mu) = (8.0, 4.0, 82_000.0, 0.3);
    let mat = wrc_kernel::Material::from_g_nu(G, NU).unwrap();
    let hz = wrc_kernel::hertz::curvatures_from_semi_axes(a, b, fnn, &mat).unwrap();
    let grid = Grid::hertz(a, b, 20, 1.1);
    let ngrid = wrc_host_tests::norm::Grid {
        mx: grid.mx,
        my: grid.my,
        dx: grid.dx,
        dy: grid.dy,
        x0: grid.x0,
        y0: grid.y0,
    };
    let gap: Vec<f64> = (0..grid.len())
        .map(|k| {
            let (x, y) = (grid.x(k % grid.mx), grid.y(k / grid.mx));
            hz.curv_a * x * x + hz.curv_b * y * y
        })
        .collect();
    let ns = wrc_host_tests::norm::solve(
        &ngrid,
        &gap,
        &mat,
        wrc_host_tests::norm::Control::Load(fnn),
        &Default::default(),
    )
    .unwrap();
    let r = TangSolver::new(grid, G, NU).solve(
        &ns.pressure,
        mu,
        Creepage {
            xi: 0.0,
            eta: -6.25e-4,
            phi: 6.25e-4,
        },
        &TangOptions::default(),
        None,
    );
    let fy = r.fy / (mu * fnn);
    println!(
        "44x44 on NORM: Fy/(μN) {fy:.4} (CONTACT -0.6074), Mz {:.4e} (-4.821e4), contact {} (1276), slip {} (920), sweeps {}",
        r.mz, r.n_contact, r.n_slip, r.sweeps
    );
    assert!(r.converged);
    assert!((fy + 0.6074).abs() < 0.02);
    assert!((r.mz + 4.821e4).abs() / (mu * fnn * (a * b).sqrt()) < 0.02);
}
