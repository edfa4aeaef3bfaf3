//! Solver B: Polonsky–Keer bound-constrained conjugate gradients with FFT products
//! (methods.md §9.1; Polonsky & Keer, Wear 231 (1999) 206–219).

use super::{Control, Grid, Options, Raw};
use crate::fftconv::ToeplitzConv;

/// Runs the PK iteration. Inputs are validated by the caller.
pub(crate) fn solve(
    conv: &mut ToeplitzConv,
    grid: &Grid,
    h: &[f64],
    control: Control,
    opts: &Options,
) -> Raw {
    let n = grid.len();
    let da = grid.element_area();
    let mut p = vec![0.0; n];
    let mut u = vec![0.0; n];
    let mut r = vec![0.0; n];
    let mut t = vec![0.0; n];
    let mut q = vec![0.0; n];
    let (load, delta) = match control {
        Control::Load(f) => (Some(f), 0.0),
        Control::Penetration(d) => (None, d),
    };
    match load {
        Some(f) => p.iter_mut().for_each(|v| *v = f / (n as f64 * da)),
        None => {
            // Start from the rigid interpenetration scaled by the self-influence coefficient
            // (an over-estimate of the pressure; any p ≥ 0 will do).
            let a00 = conv.kernel(0, 0);
            for (pk, hk) in p.iter_mut().zip(h) {
                *pk = (delta - hk).max(0.0) / a00;
            }
            if p.iter().all(|&v| v == 0.0) {
                // h ≥ δ everywhere: no contact.
                return Raw {
                    p,
                    u,
                    approach: delta,
                    iterations: 0,
                    converged: true,
                };
            }
        }
    }
    let mut p_old = vec![0.0; n];
    let mut changed: Vec<(usize, f64)> = Vec::new();
    // u = A p is kept up to date by linearity (u ← s(u − τ A t + Σ A Δ)) with the few elements whose
    // update was clipped or re-entered added column by column; a full FFT product replaces it when
    // more than `direct_max` elements changed that way, and every `REFRESH` iterations.
    let (lx, ly) = conv.padded_dims();
    let direct_max = 2 * ((lx * ly) as f64).log2().ceil() as usize;
    const REFRESH: usize = 16;
    let mut since_refresh = 0usize;
    conv.apply(&p, &mut u);
    let mut g_old = 1.0;
    let mut conjugate = false;
    let mut converged = false;
    let mut iterations = 0;
    for it in 1..=opts.max_iter {
        iterations = it;
        for k in 0..n {
            r[k] = u[k] + h[k] - delta;
        }
        let mut n_s = 0usize;
        if load.is_some() {
            // r̄ = mean over S of (u + h) estimates the approach; subtracting it projects the
            // residual onto the force constraint.
            let (mut s, mut c) = (0.0, 0usize);
            for k in 0..n {
                if p[k] > 0.0 {
                    s += r[k];
                    c += 1;
                }
            }
            let rbar = s / c as f64;
            r.iter_mut().for_each(|v| *v -= rbar);
        }
        let mut g = 0.0;
        for k in 0..n {
            if p[k] > 0.0 {
                g += r[k] * r[k];
                n_s += 1;
            }
        }
        let beta = if conjugate { g / g_old } else { 0.0 };
        for k in 0..n {
            t[k] = if p[k] > 0.0 { r[k] + beta * t[k] } else { 0.0 };
        }
        g_old = g;
        conv.apply(&t, &mut q);
        // Load control: the step direction's displacement with its mean over S removed.
        let qbar = if load.is_some() {
            let mut s = 0.0;
            for k in 0..n {
                if p[k] > 0.0 {
                    s += q[k];
                }
            }
            s / n_s as f64
        } else {
            0.0
        };
        let (mut rt, mut qt) = (0.0, 0.0);
        for k in 0..n {
            if p[k] > 0.0 {
                rt += r[k] * t[k];
                qt += (q[k] - qbar) * t[k];
            }
        }
        if qt.is_nan() || qt <= 0.0 || g == 0.0 {
            // Exact solution on this set (zero residual): nothing left to do.
            converged = g == 0.0;
            break;
        }
        let tau = rt / qt;
        let mut overlap = false;
        for k in 0..n {
            let old = p[k];
            p_old[k] = old;
            if old > 0.0 {
                p[k] = (old - tau * t[k]).max(0.0);
            }
        }
        for k in 0..n {
            if p[k] == 0.0 && r[k] < 0.0 {
                // Interpenetrating exterior element (or one just released with r < 0): re-enter it
                // with a steepest-descent step.
                p[k] = -tau * r[k];
                overlap = true;
            }
        }
        conjugate = !overlap;
        changed.clear();
        for k in 0..n {
            let plain = p_old[k] - tau * t[k];
            if p[k] != plain {
                changed.push((k, p[k] - plain));
            }
        }
        let total: f64 = p.iter().sum();
        let (scale, reference) = match load {
            Some(f) => (f / (da * total), f / da),
            None => (1.0, total),
        };
        if reference <= 0.0 {
            // Penetration control: every element released, no contact.
            p.iter_mut().for_each(|v| *v = 0.0);
            converged = true;
            break;
        }
        if scale != 1.0 {
            p.iter_mut().for_each(|v| *v *= scale);
        }
        since_refresh += 1;
        if changed.len() <= direct_max && since_refresh < REFRESH {
            for k in 0..n {
                u[k] -= tau * q[k];
            }
            for &(k, d) in &changed {
                conv.add_column(k, d, &mut u);
            }
            if scale != 1.0 {
                u.iter_mut().for_each(|v| *v *= scale);
            }
        } else {
            conv.apply(&p, &mut u);
            since_refresh = 0;
        }
        // Relative update in the force norm and in the max norm; the error of an iterate is up to
        // ~3× its last update (measured against the direct solver), hence the factor 1/10.
        let (mut l1, mut linf, mut pmax) = (0.0f64, 0.0f64, 0.0f64);
        for k in 0..n {
            let d = (p[k] - p_old[k]).abs();
            l1 += d;
            linf = linf.max(d);
            pmax = pmax.max(p[k]);
        }
        if (l1 / reference).max(linf / pmax) < 0.1 * opts.tol {
            converged = true;
            break;
        }
    }
    conv.apply(&p, &mut u);
    let approach = match load {
        Some(_) => {
            let (mut s, mut c) = (0.0, 0usize);
            for k in 0..n {
                if p[k] > 0.0 {
                    s += u[k] + h[k];
                    c += 1;
                }
            }
            s / c as f64
        }
        None => delta,
    };
    Raw {
        p,
        u,
        approach,
        iterations,
        converged,
    }
}
