//! Solver A: Kalker's active-set iteration with a dense Cholesky solve on the contact set
//! (methods.md §9.1). For small grids; a check of the FFT/CG path.

use super::{Control, Grid, Options, Raw};
use crate::fftconv::ToeplitzConv;

/// In-place Cholesky factorisation A = L Lᵀ of the dense symmetric n × n matrix `a` (row-major,
/// lower triangle used and overwritten by L). Returns false if A is not positive definite.
pub(crate) fn cholesky(a: &mut [f64], n: usize) -> bool {
    for j in 0..n {
        let mut d = a[j * n + j];
        for k in 0..j {
            d -= a[j * n + k] * a[j * n + k];
        }
        if d.is_nan() || d <= 0.0 {
            return false;
        }
        let d = d.sqrt();
        a[j * n + j] = d;
        for i in j + 1..n {
            let (ri, rj) = (i * n, j * n);
            let mut s = a[ri + j];
            for k in 0..j {
                s -= a[ri + k] * a[rj + k];
            }
            a[ri + j] = s / d;
        }
    }
    true
}

/// Solves L Lᵀ x = b in place (b becomes x).
pub(crate) fn cholesky_solve(l: &[f64], n: usize, b: &mut [f64]) {
    for i in 0..n {
        let mut s = b[i];
        for k in 0..i {
            s -= l[i * n + k] * b[k];
        }
        b[i] = s / l[i * n + i];
    }
    for i in (0..n).rev() {
        let mut s = b[i];
        for k in i + 1..n {
            s -= l[k * n + i] * b[k];
        }
        b[i] = s / l[i * n + i];
    }
}

/// Runs the active-set iteration. Inputs are validated by the caller.
///
/// Start: C = {h < δ} (penetration control) or all elements (load control). Each update solves
/// A_CC p_C = δ − h_C (load control: with the unknown δ and δxδy Σ p = F_n, by two solves with the
/// same factor: p = δ A⁻¹1 − A⁻¹h, δ = (F_n/δxδy + 1ᵀA⁻¹h)/(1ᵀA⁻¹1)), then drops contact elements
/// with p < 0 and adds exterior elements with e < 0, until the set no longer changes.
pub(crate) fn solve(
    conv: &mut ToeplitzConv,
    grid: &Grid,
    h: &[f64],
    control: Control,
    opts: &Options,
) -> Raw {
    let n = grid.len();
    let da = grid.element_area();
    let mut set: Vec<bool> = match control {
        Control::Load(_) => vec![true; n],
        Control::Penetration(d) => h.iter().map(|&v| v < d).collect(),
    };
    let mut p = vec![0.0; n];
    let mut u = vec![0.0; n];
    let mut approach = match control {
        Control::Penetration(d) => d,
        Control::Load(_) => 0.0,
    };
    let mut iterations = 0;
    let mut converged = false;
    for it in 1..=opts.max_iter {
        iterations = it;
        let idx: Vec<usize> = (0..n).filter(|&k| set[k]).collect();
        let nc = idx.len();
        p.iter_mut().for_each(|v| *v = 0.0);
        if nc == 0 {
            if let Control::Load(_) = control {
                // Cannot happen (the force equation needs one element); guard anyway.
                break;
            }
        } else {
            let mut a = vec![0.0; nc * nc];
            for (r, &kr) in idx.iter().enumerate() {
                for (c, &kc) in idx.iter().enumerate().take(r + 1) {
                    a[r * nc + c] = conv.entry(kr, kc);
                }
            }
            if !cholesky(&mut a, nc) {
                break;
            }
            match control {
                Control::Penetration(d) => {
                    let mut b: Vec<f64> = idx.iter().map(|&k| d - h[k]).collect();
                    cholesky_solve(&a, nc, &mut b);
                    for (&k, &v) in idx.iter().zip(&b) {
                        p[k] = v;
                    }
                }
                Control::Load(f) => {
                    let mut y1 = vec![1.0; nc];
                    let mut y2: Vec<f64> = idx.iter().map(|&k| h[k]).collect();
                    cholesky_solve(&a, nc, &mut y1);
                    cholesky_solve(&a, nc, &mut y2);
                    let s1: f64 = y1.iter().sum();
                    let s2: f64 = y2.iter().sum();
                    approach = (f / da + s2) / s1;
                    for (c, &k) in idx.iter().enumerate() {
                        p[k] = approach * y1[c] - y2[c];
                    }
                }
            }
        }
        conv.apply_dense(&p, &mut u);
        let mut changed = false;
        for k in 0..n {
            let member = if set[k] {
                p[k] >= 0.0
            } else {
                h[k] - approach + u[k] < 0.0
            };
            if member != set[k] {
                set[k] = member;
                changed = true;
            }
        }
        if !changed {
            converged = true;
            break;
        }
    }
    // Report the solution of the last solve restricted to p ≥ 0 (unchanged when converged).
    if !converged {
        p.iter_mut().for_each(|v| *v = v.max(0.0));
        conv.apply_dense(&p, &mut u);
    }
    Raw {
        p,
        u,
        approach,
        iterations,
        converged,
    }
}
