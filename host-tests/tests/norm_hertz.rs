//! NORM against Hertz (methods.md §9.1, §10.1): convergence for a/b = 0.2 … 5, the §9.1 table case,
//! the force–approach law, the contact set and the per-strip output.
//!
//! How a, b are measured from a discrete solution: by least squares of p_I² = c0 − c1 x_I² − c2 y_I²
//! over the contact elements (`common::fit_ellipse`; a = √(c0/c1), b = √(c0/c2), p0 = √c0). The
//! element-count area is no usable measure of a·b: it over-counts the elements straddling the edge
//! by ~ one element row, +3.5 % at 10 elements per semi-axis and +1.3…1.6 % at 20 on these grids
//! (+1.9 %/+1.5 % on the §9.1 table grids), decreasing only like δx. The element-edge extents err by
//! up to δx/2 (5 % at 10 per semi-axis) for the same reason. The fit uses every contact pressure,
//! which converges pointwise, and the Hertz form p² = p0²(1 − x²/a² − y²/b²) is exact in the
//! continuum; the contact set itself is checked separately against the Hertz ellipse (within one
//! element of the boundary). p0 is also measured directly: the grids here are odd, so one element
//! is centred on the origin and its pressure is compared with p0.
//!
//! Run the finer table (40 and 80 elements per semi-axis) with
//! `cargo test -p wrc-host-tests --release --test norm_hertz -- --ignored --nocapture`.

mod common;

use common::{fit_ellipse, rel, Hertz};
use std::f64::consts::PI;
use wrc_host_tests::norm::{solve, Control, Grid, NormSolution, Options, Window};
use wrc_kernel::Material;

const N: f64 = 82_000.0;

fn material() -> Material<f64> {
    Material::from_g_nu(82_000.0, 0.28).unwrap()
}

/// The five ellipses of methods.md §10.10: (a/b, a).
const ELLIPSES: [(f64, f64); 5] = [(0.2, 4.0), (0.5, 6.0), (1.0, 9.0), (2.0, 12.0), (5.0, 20.0)];

/// Errors (relative) of one Hertz case at n elements per semi-axis.
#[derive(Debug)]
struct Errors {
    p0_centre: f64,
    p0_fit: f64,
    a: f64,
    b: f64,
    delta: f64,
    force_at_delta: f64,
    iterations: (usize, usize),
}

/// Odd grid (an element centred on the origin) with δx = a/n, δy = b/n over ±(1.1a + δx/2) × ….
fn hertz_grid(hz: &Hertz, n: usize) -> Grid {
    let m = 2 * ((1.1 * n as f64).ceil() as usize) + 1;
    Grid::centred(m, m, hz.a / n as f64, hz.b / n as f64, 0.0, 0.0).unwrap()
}

fn check_solution_basics(s: &NormSolution) {
    assert!(
        s.converged,
        "not converged after {} iterations",
        s.iterations
    );
    assert!(
        s.complementarity < 1e-8,
        "complementarity {}",
        s.complementarity
    );
    assert!(!s.touches_boundary);
}

/// Every element whose centre lies inside the ellipse shrunk by one element (ρ < 1 − 1/n, ρ the
/// normalised radius) is in contact and none beyond ρ > 1 + 1/n.
fn check_contact_set(s: &NormSolution, hz: &Hertz, n: usize) {
    let g = &s.grid;
    for j in 0..g.my {
        for i in 0..g.mx {
            let rho = ((g.x(i) / hz.a).powi(2) + (g.y(j) / hz.b).powi(2)).sqrt();
            let c = s.contact[g.index(i, j)];
            if rho < 1.0 - 1.0 / n as f64 {
                assert!(c, "element ({i},{j}) at rho {rho} not in contact");
            }
            if rho > 1.0 + 1.0 / n as f64 {
                assert!(!c, "element ({i},{j}) at rho {rho} in contact");
            }
        }
    }
}

fn hertz_case(ab: f64, a: f64, n: usize) -> Errors {
    let mat = material();
    let hz = Hertz::from_axes(a, a / ab, N, mat.e_star);
    let grid = hertz_grid(&hz, n);
    let gap = grid.sample(|x, y| hz.gap(x, y));
    let s = solve(&grid, &gap, &mat, Control::Load(N), &Options::default()).unwrap();
    check_solution_basics(&s);
    check_contact_set(&s, &hz, n);
    assert!(rel(s.force, N) < 1e-12, "force balance {}", s.force);
    let c = grid.mx / 2;
    let (fp0, fa, fb) = fit_ellipse(&s);
    // Force–approach law: penetration control at the Hertz approach gives the Hertz force.
    let sp = solve(
        &grid,
        &gap,
        &mat,
        Control::Penetration(hz.delta),
        &Options::default(),
    )
    .unwrap();
    check_solution_basics(&sp);
    Errors {
        p0_centre: rel(s.p(c, c), hz.p0),
        p0_fit: rel(fp0, hz.p0),
        a: rel(fa, hz.a),
        b: rel(fb, hz.b),
        delta: rel(s.approach, hz.delta),
        force_at_delta: rel(sp.force, N),
        iterations: (s.iterations, sp.iterations),
    }
}

fn assert_within(e: &Errors, tol: f64, what: &str) {
    for (v, name) in [
        (e.p0_centre, "p0 (centre element)"),
        (e.p0_fit, "p0 (fit)"),
        (e.a, "a"),
        (e.b, "b"),
        (e.delta, "approach"),
        (e.force_at_delta, "force at Hertz approach"),
    ] {
        assert!(
            v < tol,
            "{what}: {name} error {:.4} % ≥ {:.2} %",
            100.0 * v,
            100.0 * tol
        );
    }
}

/// Issue 4: p0, a, b and the force–approach law within 1 % at 10 elements per semi-axis.
#[test]
fn hertz_convergence_10_per_semi_axis() {
    for (ab, a) in ELLIPSES {
        let e = hertz_case(ab, a, 10);
        assert_within(&e, 0.01, &format!("a/b = {ab}, n = 10"));
    }
}

/// Issue 4: within 0.3 % at 20 elements per semi-axis, and the errors decrease from 10 to 20.
#[test]
fn hertz_convergence_20_per_semi_axis() {
    for (ab, a) in ELLIPSES {
        let e10 = hertz_case(ab, a, 10);
        let e20 = hertz_case(ab, a, 20);
        assert_within(&e20, 0.003, &format!("a/b = {ab}, n = 20"));
        for (x10, x20, name) in [
            (e10.p0_centre, e20.p0_centre, "p0"),
            (e10.a, e20.a, "a"),
            (e10.b, e20.b, "b"),
            (e10.delta, e20.delta, "approach"),
        ] {
            assert!(
                x20 < x10,
                "a/b = {ab}: {name} error grows from n = 10 to 20"
            );
        }
    }
}

/// The convergence table for the closing note (n = 10, 20, 40, 80; slow at 80).
#[test]
#[ignore]
fn hertz_convergence_table() {
    println!("| a/b | n | p0 centre % | p0 fit % | a % | b % | δ % | F(δ_H) % | iterations (load, pen.) |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for (ab, a) in ELLIPSES {
        for n in [10, 20, 40, 80] {
            let e = hertz_case(ab, a, n);
            println!(
                "| {ab} | {n} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {}, {} |",
                100.0 * e.p0_centre,
                100.0 * e.p0_fit,
                100.0 * e.a,
                100.0 * e.b,
                100.0 * e.delta,
                100.0 * e.force_at_delta,
                e.iterations.0,
                e.iterations.1
            );
        }
    }
}

/// methods.md §9.1 convergence table, a = 8, b = 4, N = 82 kN, G = 82 000, ν = 0.28, grid over
/// ±1.1a × ±1.1b: max element pressure, δ, element-count area and rms error / p0 at 10 and 20 elements
/// per semi-axis, to the digits printed there.
#[test]
fn spec_table_case() {
    let mat = material();
    let hz = Hertz::from_axes(8.0, 4.0, N, mat.e_star);
    // §10.1: the Hertz numbers themselves. §10.1's δ = 0.092668 and p0 = 1223.46 follow from the
    // curvatures rounded to 4 digits (A + B 5.5e-5 low): exact a = 8, b = 4 give 0.0926694 and
    // 1223.50, hence the 5e-5 relative tolerance.
    assert!(rel(hz.delta, 0.092668) < 5e-5, "Hertz δ {}", hz.delta);
    assert!(rel(hz.p0, 1223.46) < 5e-5, "Hertz p0 {}", hz.p0);
    assert!(rel(hz.ca, 0.8464e-3) < 1e-4 && rel(hz.cb, 0.2406e-2) < 1e-4);
    // (n, max p, exact p at its centre, δ, area, rms error / p0 in %)
    let rows = [
        (10usize, 1220.9, 1220.4, 0.09263, 102.40, 0.78),
        (20, 1222.8, 1222.7, 0.09266, 102.08, 0.48),
    ];
    for (n, pmax, pexact, delta, area, rms) in rows {
        let m = 22 * n / 10;
        let grid = Grid::covering(Window::centred(8.8, 4.4), m, m).unwrap();
        let gap = grid.sample(|x, y| hz.gap(x, y));
        let s = solve(&grid, &gap, &mat, Control::Load(N), &Options::default()).unwrap();
        check_solution_basics(&s);
        let (x, y) = s.p_max_at;
        let se: f64 = (0..m)
            .flat_map(|j| (0..m).map(move |i| (i, j)))
            .map(|(i, j)| (s.p(i, j) - hz.p(grid.x(i), grid.y(j))).powi(2))
            .sum();
        let rms_pct = 100.0 * (se / (m * m) as f64).sqrt() / hz.p0;
        assert!((s.p_max - pmax).abs() <= 0.05, "n {n}: max p {}", s.p_max);
        assert!(
            (hz.p(x, y) - pexact).abs() <= 0.05,
            "n {n}: exact {}",
            hz.p(x, y)
        );
        assert!(
            (s.approach - delta).abs() <= 0.5e-5,
            "n {n}: δ {}",
            s.approach
        );
        assert!((s.area - area).abs() <= 0.005, "n {n}: area {}", s.area);
        assert!((rms_pct - rms).abs() <= 0.005, "n {n}: rms {rms_pct} %");
        // §9.1 expectation: p0 within 1 % and δ within 0.1 % from 10 elements per semi-axis.
        assert!(rel(s.p_max, hz.p0) < 0.01 && rel(s.approach, hz.delta) < 0.001);
    }
}

/// Per-strip output: Σ f_j δy = F_n, run edges bracket the Hertz half-widths a√(1 − y²/b²) within one
/// element, and the strip force per unit width matches the Hertz line load
/// ∫p dx = (π/2) p0 a_j √(1 − y²/b²) within 2 % on the strips with |y| < 0.8 b.
#[test]
fn strip_data_hertz() {
    let mat = material();
    let hz = Hertz::from_axes(8.0, 4.0, N, mat.e_star);
    let n = 20;
    let grid = hertz_grid(&hz, n);
    let s = solve(
        &grid,
        &grid.sample(|x, y| hz.gap(x, y)),
        &mat,
        Control::Load(N),
        &Options::default(),
    )
    .unwrap();
    let total: f64 = s.strips.iter().map(|st| st.force_per_width * grid.dy).sum();
    assert!(rel(total, N) < 1e-12);
    assert_eq!(s.strips.len(), grid.my);
    let mut n_strips = 0;
    for st in &s.strips {
        let runs_force: f64 = st.runs.iter().map(|r| r.force_per_width).sum();
        assert!((runs_force - st.force_per_width).abs() <= 1e-12 * st.force_per_width.max(1.0));
        let y = st.y;
        if (y / hz.b).abs() < 1.0 - 1.0 / n as f64 {
            n_strips += 1;
            assert_eq!(st.runs.len(), 1, "strip at y = {y}: one run");
            let r = st.runs[0];
            let aj = hz.a * (1.0 - (y / hz.b).powi(2)).sqrt();
            assert!(
                (r.x_lead - aj).abs() <= grid.dx,
                "lead {} vs {aj}",
                r.x_lead
            );
            assert!(
                (r.x_trail + aj).abs() <= grid.dx,
                "trail {} vs {}",
                r.x_trail,
                -aj
            );
            // ∫ p dx over the strip = (π/2) p0 a_j √(1 − y²/b²) for the Hertz pressure.
            let line = 0.5 * PI * hz.p0 * aj * (1.0 - (y / hz.b).powi(2)).sqrt();
            if (y / hz.b).abs() < 0.8 {
                assert!(
                    rel(st.force_per_width, line) < 0.02,
                    "y {y}: {} vs {line}",
                    st.force_per_width
                );
            }
        } else if (y / hz.b).abs() > 1.0 + 1.0 / n as f64 {
            assert!(st.runs.is_empty() && st.force_per_width == 0.0);
        }
    }
    assert!(n_strips >= 2 * (n - 1) - 1);
}
