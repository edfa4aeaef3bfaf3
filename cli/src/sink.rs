//! A cell sink that accumulates what the JSON and the plots need: wear per strip, stick area, and
//! optionally the full field for plots.

use crate::doc::Y0Cell;
use wrc_kernel::patch::{CellOut, CellSink, Totals};
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
    /// Per-strip record (only when `detail` is set, see [`StatsSink::detailed`]).
    pub rows: Vec<StripRow<T>>,
    /// Whether to fill `rows`.
    pub detail: bool,
}

/// What a [`StatsSink`] with detail records of one strip: its cells' totals (the kernel's
/// [`Totals::add`]), its position and its cells for the `y0` output.
#[derive(Clone, Debug, Default)]
pub struct StripRow<T> {
    /// Whether any contact cell of this strip was reported.
    pub seen: bool,
    /// Strip position y of its cells, mm.
    pub y: f64,
    /// Cell index i of the strip's first reported cell.
    pub i_first: usize,
    /// Totals over the strip's cells.
    pub totals: Totals<T>,
    /// The strip's cells: x, p_n, p_x, p_y and slip velocity (mm/s).
    pub cells: Vec<Y0Cell>,
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
            rows: Vec::new(),
            detail: false,
        }
    }

    /// The same sink, also recording every strip's totals and cells (`rows`).
    pub fn detailed(mut self) -> Self {
        self.detail = true;
        self
    }
}

impl<T: Real, const S: usize> CellSink<T> for StatsSink<T, S> {
    fn cell(&mut self, j: usize, i: usize, o: &CellOut<T>) {
        let slip = wrc_kernel::math::hypot(o.sx, o.sy);
        self.wear
            .add_cell(&self.map, j, o.pn, slip, self.speed, self.dx);
        let a = o.area.to_f64();
        self.area += a;
        if !o.slip {
            self.stick_area += a;
        }
        if self.detail {
            if self.rows.len() <= j {
                self.rows.resize_with(j + 1, StripRow::default);
            }
            let r = &mut self.rows[j];
            if !r.seen {
                r.seen = true;
                r.y = o.y.to_f64();
                r.i_first = i;
            }
            r.totals.add(o);
            r.cells.push(Y0Cell {
                x_mm: o.x.to_f64(),
                pn_mpa: o.pn.to_f64(),
                px_mpa: o.px.to_f64(),
                py_mpa: o.py.to_f64(),
                slip_velocity_mm_s: if o.slip {
                    slip.to_f64() * self.speed.to_f64()
                } else {
                    0.0
                },
            });
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

/// `strips` and `y0` of a kernel strip patch solved with a detailed sink (strips `0..n` with
/// contact, a_j > 0): the strip's centre and half-length from the patch, its normal load and
/// forces from the kernel's per-strip totals `res.strips` (normal load δxδyΣp_n of its cells),
/// its wear from the sink's per-strip KTH wear (the wear the patch's `wear_depth_max_um` is the
/// maximum of); `y0` the cells of the strip through y = 0 ([`crate::doc::y0_strip`]).
pub fn kernel_strips<T: Real, const S: usize, const C: usize>(
    patch: &wrc_kernel::patch::StripPatch<T, S, C>,
    n: usize,
    res: &wrc_kernel::patch::Tangential<T, S>,
    sink: &StatsSink<T, S>,
) -> (Vec<crate::doc::StripOut>, Vec<Y0Cell>) {
    let used: Vec<usize> = (0..n.min(S))
        .filter(|&j| patch.strips[j].a > T::ZERO)
        .collect();
    let strips = used
        .iter()
        .map(|&j| {
            let (s, t) = (&patch.strips[j], &res.strips[j]);
            crate::doc::StripOut {
                y_mm: s.y.to_f64(),
                half_length_mm: s.a.to_f64(),
                width_mm: s.dy.to_f64(),
                fn_n: t.fn_.to_f64(),
                fx_n: t.fx.to_f64(),
                fy_n: t.fy.to_f64(),
                wear_depth_um: sink.wear.depth[j].to_f64() * 1e3,
            }
        })
        .collect();
    let k = crate::doc::y0_strip(
        used.iter()
            .map(|&j| (patch.strips[j].y.to_f64(), patch.strips[j].dy.to_f64())),
    );
    let mut y0 = k
        .and_then(|k| sink.rows.get(used[k]))
        .map(|r| r.cells.clone())
        .unwrap_or_default();
    crate::doc::sort_by_x(&mut y0);
    (strips, y0)
}
