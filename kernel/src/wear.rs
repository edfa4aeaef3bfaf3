//! KTH wear (Jendel 2002) with Archard's law, per cell and per strip (methods.md §8).
//!
//! Per element and wheel passage: **Δz = k(p, v_s) · p · |s| · δx / H** (mm), with p the normal
//! pressure (MPa), s the dimensionless slip (slip velocity / rolling speed V), δx the cell length
//! along the rolling direction (mm) and H the hardness (MPa). The sliding distance of a cell is
//! V|s|·δx/V = |s|δx. Adhesion cells (s = 0) do not wear. The strip's wear depth per passage is the
//! sum over its cells (seed A eq. 28).
//!
//! The wear coefficient k comes from the KTH map, a step function of pressure and sliding velocity
//! v_s = V|s| (converted to m/s). Regions are implemented by condition, not by label, because the
//! labels differ between seed A and `data/wear_map.md` (methods.md §8):
//!
//! | region | condition | default k (range mid-point) |
//! |---|---|---|
//! | [`WearRegion::MildLowSlip`] | p ≤ 0.8H, v_s < 0.2 m/s | 5.5e-4 |
//! | [`WearRegion::Severe`] | p ≤ 0.8H, 0.2 ≤ v_s ≤ 0.7 m/s | 35e-4 |
//! | [`WearRegion::MildHighSlip`] | p ≤ 0.8H, v_s > 0.7 m/s | 5.5e-4 |
//! | [`WearRegion::Seizure`] | p > 0.8H | 350e-4 |
//!
//! The values are **\[UNCERTAIN\]** (recollection, not checked against Jendel; `wear_map.md`); the map is
//! therefore a plain table input ([`WearMap`]) and absolute wear only scales with it.

use crate::error::{check_finite, check_positive, Error};
use crate::{math, Real};

/// The four regions of the KTH wear map, by condition (see the module table).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum WearRegion {
    /// No sliding (adhesion, s = 0): no wear.
    Adhesion,
    /// p ≤ p_lim and v_s < v_low: mild wear.
    MildLowSlip,
    /// p ≤ p_lim and v_low ≤ v_s ≤ v_high: severe wear.
    Severe,
    /// p ≤ p_lim and v_s > v_high: mild wear (oxide regime).
    MildHighSlip,
    /// p > p_lim: seizure.
    Seizure,
}

impl WearRegion {
    /// Index 0..5 in the order of the enum (for histograms).
    pub const fn index(self) -> usize {
        match self {
            WearRegion::Adhesion => 0,
            WearRegion::MildLowSlip => 1,
            WearRegion::Severe => 2,
            WearRegion::MildHighSlip => 3,
            WearRegion::Seizure => 4,
        }
    }
}

/// The KTH wear-coefficient map and the hardness: a table input.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct WearMap<T> {
    /// Hardness H of the softer body, MPa (seed A: 2625 MPa).
    pub hardness: T,
    /// Pressure limit as a fraction of H above which seizure wear applies (0.8).
    pub p_limit_fraction: T,
    /// Lower sliding-velocity boundary, m/s (0.2).
    pub v_low: T,
    /// Upper sliding-velocity boundary, m/s (0.7).
    pub v_high: T,
    /// k for p ≤ p_lim, v_s < v_low.
    pub k_mild_low: T,
    /// k for p ≤ p_lim, v_low ≤ v_s ≤ v_high.
    pub k_severe: T,
    /// k for p ≤ p_lim, v_s > v_high.
    pub k_mild_high: T,
    /// k for p > p_lim.
    pub k_seizure: T,
}

impl<T: Real> Default for WearMap<T> {
    fn default() -> Self {
        Self::kth()
    }
}

impl<T: Real> WearMap<T> {
    /// The KTH map with the range mid-points and H = 2625 MPa (seed A).
    pub fn kth() -> Self {
        Self {
            hardness: math::c(2625.0),
            p_limit_fraction: math::c(0.8),
            v_low: math::c(0.2),
            v_high: math::c(0.7),
            k_mild_low: math::c(5.5e-4),
            k_severe: math::c(35e-4),
            k_mild_high: math::c(5.5e-4),
            k_seizure: math::c(350e-4),
        }
    }

    /// Checks that every entry is finite and positive and the velocity bounds are ordered.
    pub fn validate(&self) -> Result<(), Error> {
        check_positive(self.hardness, "wear hardness")?;
        check_positive(self.p_limit_fraction, "wear p_limit_fraction")?;
        check_positive(self.v_low, "wear v_low")?;
        check_positive(self.v_high, "wear v_high")?;
        for (k, n) in [
            (self.k_mild_low, "wear k_mild_low"),
            (self.k_severe, "wear k_severe"),
            (self.k_mild_high, "wear k_mild_high"),
            (self.k_seizure, "wear k_seizure"),
        ] {
            check_finite(k, n)?;
            if k < T::ZERO {
                return Err(Error::NonPositive(n));
            }
        }
        if self.v_high < self.v_low {
            return Err(Error::OutOfRange("wear v_high < v_low"));
        }
        Ok(())
    }

    /// Region of the map for pressure `p` (MPa) and sliding velocity `vs` (m/s).
    #[inline]
    pub fn region(&self, p: T, vs: T) -> WearRegion {
        // NaN compares false everywhere: a NaN pressure or velocity is treated as no sliding.
        let sliding = vs > T::ZERO && p > T::ZERO;
        if !sliding {
            WearRegion::Adhesion
        } else if p > self.p_limit_fraction * self.hardness {
            WearRegion::Seizure
        } else if vs < self.v_low {
            WearRegion::MildLowSlip
        } else if vs <= self.v_high {
            WearRegion::Severe
        } else {
            WearRegion::MildHighSlip
        }
    }

    /// Wear coefficient k of a region (0 for adhesion).
    #[inline]
    pub fn k_of(&self, region: WearRegion) -> T {
        match region {
            WearRegion::Adhesion => T::ZERO,
            WearRegion::MildLowSlip => self.k_mild_low,
            WearRegion::Severe => self.k_severe,
            WearRegion::MildHighSlip => self.k_mild_high,
            WearRegion::Seizure => self.k_seizure,
        }
    }

    /// Wear depth (mm) of one cell per passage: k(p, V|s|) · p · |s| · δx / H.
    ///
    /// `p` pressure (MPa), `slip` = |s| (dimensionless, slip velocity / V), `speed` = V (mm/s),
    /// `dx` cell length (mm). Returns the depth and the region.
    #[inline]
    pub fn cell_depth(&self, p: T, slip: T, speed: T, dx: T) -> (T, WearRegion) {
        let vs = slip * speed * math::c::<T>(1e-3);
        let region = self.region(p, vs);
        let k = self.k_of(region);
        (k * p * slip * dx / self.hardness, region)
    }
}

/// Wear accumulated per strip over one passage: depth per strip (mm) and a histogram of the map
/// regions hit (cells per region, in [`WearRegion::index`] order).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct StripWear<T, const S: usize> {
    /// Wear depth per strip per passage, mm (Σ over the strip's cells).
    pub depth: [T; S],
    /// Number of cells per map region (index by [`WearRegion::index`]).
    pub region_cells: [u32; 5],
}

impl<T: Real, const S: usize> Default for StripWear<T, S> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Real, const S: usize> StripWear<T, S> {
    /// All zero.
    pub const fn new() -> Self {
        Self {
            depth: [T::ZERO; S],
            region_cells: [0; 5],
        }
    }

    /// Resets to zero.
    pub fn clear(&mut self) {
        *self = Self::new();
    }

    /// Adds one cell of strip `j` (ignored if `j ≥ S`); see [`WearMap::cell_depth`] for the units.
    #[inline]
    pub fn add_cell(&mut self, map: &WearMap<T>, j: usize, p: T, slip: T, speed: T, dx: T) {
        let (dz, region) = map.cell_depth(p, math::abs(slip), speed, dx);
        if let Some(d) = self.depth.get_mut(j) {
            *d += dz;
            self.region_cells[region.index()] += 1;
        }
    }

    /// Largest strip depth among the first `n` strips, mm.
    pub fn max_depth(&self, n: usize) -> T {
        let mut m = T::ZERO;
        for d in self.depth.iter().take(n.min(S)) {
            m = math::max(m, *d);
        }
        m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regions_by_condition() {
        let m = WearMap::<f64>::kth();
        let plim = 0.8 * 2625.0;
        assert_eq!(m.region(1000.0, 0.0), WearRegion::Adhesion);
        assert_eq!(m.region(1000.0, 0.1), WearRegion::MildLowSlip);
        assert_eq!(m.region(1000.0, 0.2), WearRegion::Severe);
        assert_eq!(m.region(1000.0, 0.7), WearRegion::Severe);
        assert_eq!(m.region(1000.0, 0.71), WearRegion::MildHighSlip);
        assert_eq!(m.region(plim, 0.5), WearRegion::Severe);
        assert_eq!(m.region(plim + 1e-9, 0.05), WearRegion::Seizure);
        assert_eq!(m.region(f64::NAN, 0.5), WearRegion::Adhesion);
        assert_eq!(m.region(1000.0, f64::NAN), WearRegion::Adhesion);
    }

    #[test]
    fn archard_depth() {
        let m = WearMap::<f64>::kth();
        // p = 1000 MPa, s = 0.002, V = 200 km/h = 55 555.6 mm/s → v_s = 0.111 m/s (mild, low slip).
        let v = 200.0 / 3.6 * 1000.0;
        let (dz, r) = m.cell_depth(1000.0, 0.002, v, 0.25);
        assert_eq!(r, WearRegion::MildLowSlip);
        assert!((dz - 5.5e-4 * 1000.0 * 0.002 * 0.25 / 2625.0).abs() < 1e-18);
        let mut w = StripWear::<f64, 4>::new();
        w.add_cell(&m, 1, 1000.0, -0.002, v, 0.25);
        w.add_cell(&m, 1, 1000.0, 0.0, v, 0.25);
        w.add_cell(&m, 9, 1000.0, 0.002, v, 0.25);
        assert!((w.depth[1] - dz).abs() < 1e-18);
        assert_eq!(w.region_cells, [1, 1, 0, 0, 0]);
        assert_eq!(w.max_depth(4), w.depth[1]);
    }

    #[test]
    fn validate_rejects_garbage() {
        let mut m = WearMap::<f64>::kth();
        assert!(m.validate().is_ok());
        m.hardness = -1.0;
        assert!(m.validate().is_err());
        let mut m = WearMap::<f32>::kth();
        m.k_severe = f32::NAN;
        assert!(m.validate().is_err());
    }
}
