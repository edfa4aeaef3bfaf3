//! **Reference implementation of the KTH/Archard wear law (methods.md §8)** — the host version the
//! kernel's wear module will be checked against. Plain functions, f64, no shortcuts.
//!
//! Per element and wheel passage: Δz = k(p, v_s) · p · |s| · δx / H (mm), with p the normal
//! pressure (MPa), s the dimensionless relative slip of the tangential solution (slip velocity
//! v_s = V|s|), δx the element length along the rolling direction (mm) and H the hardness (MPa).
//! Adhesion elements (s = 0) do not wear. Per strip (grid row j): Δz(y_j) = Σ_i Δz(x_i, y_j).
//!
//! Wear map k(p, v_s), v_s in m/s (the kernel's V is in mm/s: divide by 1000). Regions are chosen
//! by condition, never by label (methods.md §8 notes a label conflict with `wear_map.md`):
//! seizure p > 0.8H; otherwise mild below 0.2 m/s, severe for 0.2 ≤ v_s ≤ 0.7 m/s, mild above
//! 0.7 m/s. Defaults are the range mid-points (5.5e-4, 35e-4, 5.5e-4, 350e-4), H = 2625 MPa (seed A).
//! The values are [UNCERTAIN] (`data/wear_map.md`); the map is an input.

use crate::tang::{ElementState, TangSolution};

/// The KTH wear map (a table input).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WearMap {
    /// Hardness H, MPa.
    pub hardness: f64,
    /// Pressure threshold of the seizure region as a fraction of H (0.8).
    pub p_seizure_frac: f64,
    /// Lower sliding-velocity boundary, m/s (0.2).
    pub v_low: f64,
    /// Upper sliding-velocity boundary, m/s (0.7).
    pub v_high: f64,
    /// k for p ≤ 0.8H, v_s < v_low (mild).
    pub k_mild_low: f64,
    /// k for p ≤ 0.8H, v_low ≤ v_s ≤ v_high (severe).
    pub k_severe: f64,
    /// k for p ≤ 0.8H, v_s > v_high (mild).
    pub k_mild_high: f64,
    /// k for p > 0.8H (seizure).
    pub k_seizure: f64,
}

impl Default for WearMap {
    fn default() -> Self {
        Self {
            hardness: 2625.0,
            p_seizure_frac: 0.8,
            v_low: 0.2,
            v_high: 0.7,
            k_mild_low: 5.5e-4,
            k_severe: 35e-4,
            k_mild_high: 5.5e-4,
            k_seizure: 350e-4,
        }
    }
}

impl WearMap {
    /// Wear coefficient k for pressure `p` (MPa) and slip velocity `v_s_m_per_s` (m/s).
    pub fn k(&self, p: f64, v_s_m_per_s: f64) -> f64 {
        if p > self.p_seizure_frac * self.hardness {
            self.k_seizure
        } else if v_s_m_per_s < self.v_low {
            self.k_mild_low
        } else if v_s_m_per_s <= self.v_high {
            self.k_severe
        } else {
            self.k_mild_high
        }
    }

    /// Wear depth of one element per passage, mm: k(p, V|s|) · p · |s| · δx / H; 0 for p ≤ 0 or
    /// s = 0. `s_abs` dimensionless, `v` rolling speed in mm/s, `dx` in mm.
    pub fn element_depth(&self, p: f64, s_abs: f64, v: f64, dx: f64) -> f64 {
        if p <= 0.0 || s_abs <= 0.0 {
            return 0.0;
        }
        let vs = v * s_abs / 1000.0;
        self.k(p, vs) * p * s_abs * dx / self.hardness
    }
}

/// Wear depth per element (grid order, mm) of a tangential solution with normal pressure `pn`
/// (MPa) at rolling speed `v` (mm/s). Only slipping elements wear.
pub fn element_wear(map: &WearMap, sol: &TangSolution, pn: &[f64], v: f64) -> Vec<f64> {
    (0..sol.px.len())
        .map(|k| match sol.state[k] {
            ElementState::Slip => {
                map.element_depth(pn[k], sol.sx[k].hypot(sol.sy[k]), v, sol.grid.dx)
            }
            _ => 0.0,
        })
        .collect()
}

/// Wear depth per strip (grid row j, mm): Δz(y_j) = Σ_i Δz(x_i, y_j) (methods.md §8, eq. 28).
pub fn strip_wear(map: &WearMap, sol: &TangSolution, pn: &[f64], v: f64) -> Vec<f64> {
    let e = element_wear(map, sol, pn, v);
    let mx = sol.grid.mx;
    e.chunks_exact(mx).map(|row| row.iter().sum()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regions_by_condition() {
        let m = WearMap::default();
        let h = m.hardness;
        assert_eq!(m.k(0.9 * h, 0.0), 350e-4);
        assert_eq!(m.k(0.5 * h, 0.1), 5.5e-4);
        assert_eq!(m.k(0.5 * h, 0.2), 35e-4);
        assert_eq!(m.k(0.5 * h, 0.7), 35e-4);
        assert_eq!(m.k(0.5 * h, 0.71), 5.5e-4);
    }

    /// Archard units: k p |s| δx / H with p = 1000 MPa, |s| = 0.01, V = 30 m/s (v_s = 0.3 m/s,
    /// severe), δx = 0.1 mm: 35e-4 · 1000 · 0.01 · 0.1 / 2625 mm.
    #[test]
    fn element_depth_closed_form() {
        let m = WearMap::default();
        let dz = m.element_depth(1000.0, 0.01, 30_000.0, 0.1);
        assert!((dz - 35e-4 * 1000.0 * 0.01 * 0.1 / 2625.0).abs() < 1e-18);
        assert_eq!(m.element_depth(1000.0, 0.0, 30_000.0, 0.1), 0.0);
        assert_eq!(m.element_depth(0.0, 0.1, 30_000.0, 0.1), 0.0);
    }
}
