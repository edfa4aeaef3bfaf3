//! A cell sink that accumulates what the JSON and the plots need: wear per strip, stick area, and
//! optionally the full field for plots.

use wrc_kernel::patch::{CellOut, CellSink};
use wrc_kernel::wear::{StripWear, WearMap};
use wrc_kernel::Real;

/// One stored cell for plots (f64 regardless of the kernel precision).
#[derive(Clone, Copy, Debug, Default)]
pub struct PlotCell {
    /// x, mm.
    pub x: f64,
    /// y, mm.
    pub y: f64,
    /// Pressure, MPa.
    pub pn: f64,
    /// Traction p_x, MPa.
    pub px: f64,
    /// Traction p_y, MPa.
    pub py: f64,
    /// In slip.
    pub slip: bool,
    /// Slip velocity magnitude, m/s.
    pub vs: f64,
    /// Wear depth of this cell, µm.
    pub wear_um: f64,
}

/// Accumulates wear, stick area and (optionally) a copy of every contact cell.
pub struct StatsSink<T: Real, const S: usize> {
    /// Wear map.
    pub map: WearMap<T>,
    /// Rolling speed, mm/s.
    pub speed: T,
    /// Cell length, mm.
    pub dx: T,
    /// Wear per strip.
    pub wear: StripWear<T, S>,
    /// Contact area in adhesion, mm².
    pub stick_area: f64,
    /// Contact area, mm².
    pub area: f64,
    /// Cells kept for plots (only when `keep` is set).
    pub cells: Vec<PlotCell>,
    /// Whether to keep cells.
    pub keep: bool,
}

impl<T: Real, const S: usize> StatsSink<T, S> {
    /// A new sink.
    pub fn new(map: WearMap<T>, speed: T, dx: T, keep: bool) -> Self {
        Self {
            map,
            speed,
            dx,
            wear: StripWear::new(),
            stick_area: 0.0,
            area: 0.0,
            cells: Vec::new(),
            keep,
        }
    }
}

impl<T: Real, const S: usize> CellSink<T> for StatsSink<T, S> {
    fn cell(&mut self, j: usize, _i: usize, o: &CellOut<T>) {
        let slip = wrc_kernel::math::hypot(o.sx, o.sy);
        self.wear
            .add_cell(&self.map, j, o.pn, slip, self.speed, self.dx);
        let a = o.area.to_f64();
        self.area += a;
        if !o.slip {
            self.stick_area += a;
        }
        if self.keep {
            let (dz, _) = self.map.cell_depth(o.pn, slip, self.speed, self.dx);
            self.cells.push(PlotCell {
                x: o.x.to_f64(),
                y: o.y.to_f64(),
                pn: o.pn.to_f64(),
                px: o.px.to_f64(),
                py: o.py.to_f64(),
                slip: o.slip,
                vs: slip.to_f64() * self.speed.to_f64() * 1e-3,
                wear_um: dz.to_f64() * 1e3,
            });
        }
    }
}
