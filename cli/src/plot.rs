//! SVG plots of a solved patch: pressure, traction with stick/slip, slip velocity, wear per strip.
//!
//! Text needs a TrueType font: DejaVu Sans from Debian's `fonts-dejavu-core`
//! (/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf) or the file named by `$WRC_FONT`.

use crate::sink::PlotCell;
use plotters::prelude::*;
use plotters::style::colors::colormaps::ViridisRGB;
use std::path::Path;
use std::sync::Once;

static FONT: Once = Once::new();

/// Registers the font once; errors if none is found.
fn register_font() -> Result<(), String> {
    let path = std::env::var("WRC_FONT")
        .unwrap_or_else(|_| "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf".into());
    let bytes = std::fs::read(&path).map_err(|e| {
        format!("--plot needs a TrueType font at {path} (install fonts-dejavu-core or set WRC_FONT): {e}")
    })?;
    let mut res = Ok(());
    FONT.call_once(|| {
        let leaked: &'static [u8] = Box::leak(bytes.into_boxed_slice());
        if plotters::style::register_font("sans-serif", FontStyle::Normal, leaked).is_err() {
            res = Err("could not load the font".to_string());
        }
    });
    res
}

fn err<E: std::fmt::Debug>(e: E) -> String {
    format!("plot: {e:?}")
}

/// Colour range of `values`: their minimum and maximum, widened a little when all are equal so
/// that the colour bar still shows the value (never a fixed 0–1 range).
fn value_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::MAX, f64::MIN);
    for v in values.filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if lo > hi {
        return (0.0, 1.0);
    }
    if hi > lo {
        (lo, hi)
    } else {
        let eps = (lo.abs() * 0.01).max(1e-12);
        (lo - eps, hi + eps)
    }
}

/// Extents of the cells (rectangles δx × δy around the centres).
fn extents(cells: &[PlotCell], dx: f64, dy: f64) -> (f64, f64, f64, f64) {
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for c in cells {
        x0 = x0.min(c.x - dx);
        x1 = x1.max(c.x + dx);
        y0 = y0.min(c.y - dy);
        y1 = y1.max(c.y + dy);
    }
    (x0, x1, y0, y1)
}

/// Ranges widened so that 1 mm in x takes as many pixels as 1 mm in y on a plotting area of
/// `w` × `h` pixels.
fn equal_aspect(x: (f64, f64), y: (f64, f64), w: u32, h: u32) -> ((f64, f64), (f64, f64)) {
    let (w, h) = (f64::from(w.max(1)), f64::from(h.max(1)));
    let s = ((x.1 - x.0) / w).max((y.1 - y.0) / h);
    let (cx, cy) = (0.5 * (x.0 + x.1), 0.5 * (y.0 + y.1));
    (
        (cx - 0.5 * s * w, cx + 0.5 * s * w),
        (cy - 0.5 * s * h, cy + 0.5 * s * h),
    )
}

type Chart<'a> = ChartContext<
    'a,
    SVGBackend<'a>,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// A chart of the patch on `area` with equal scales in x and y, axes drawn.
fn patch_chart<'a>(
    area: &DrawingArea<SVGBackend<'a>, plotters::coord::Shift>,
    cells: &[PlotCell],
    dx: f64,
    dy: f64,
) -> Result<Chart<'a>, String> {
    let (x0, x1, y0, y1) = extents(cells, dx, dy);
    let build = |x: (f64, f64), y: (f64, f64)| {
        ChartBuilder::on(area)
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(50)
            .build_cartesian_2d(x.0..x.1, y.0..y.1)
            .map_err(err)
    };
    let (w, h) = build((x0, x1), (y0, y1))?.plotting_area().dim_in_pixel();
    let (xr, yr) = equal_aspect((x0, x1), (y0, y1), w, h);
    let mut ch = build(xr, yr)?;
    ch.configure_mesh()
        .x_desc("x (rolling direction), mm")
        .y_desc("y, mm")
        .disable_mesh()
        .draw()
        .map_err(err)?;
    Ok(ch)
}

fn cell_rect(c: &PlotCell, dx: f64, dy: f64, col: ShapeStyle) -> Rectangle<(f64, f64)> {
    Rectangle::new(
        [
            (c.x - dx / 2.0, c.y - dy / 2.0),
            (c.x + dx / 2.0, c.y + dy / 2.0),
        ],
        col,
    )
}

/// A heat map of `value(cell)` over the patch cells, each drawn as a rectangle δx × δy, with a
/// colour bar over the data's own range.
#[allow(clippy::too_many_arguments)]
fn heat(
    file: &Path,
    title: &str,
    unit: &str,
    cells: &[PlotCell],
    dx: f64,
    dy: f64,
    value: impl Fn(&PlotCell) -> f64,
) -> Result<(), String> {
    if cells.is_empty() {
        return Ok(());
    }
    let root = SVGBackend::new(file, (860, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let root = root.titled(title, ("sans-serif", 18)).map_err(err)?;
    let (vmin, vmax) = value_range(cells.iter().map(&value));
    let (main, bar) = root.split_horizontally(720);
    let mut ch = patch_chart(&main, cells, dx, dy)?;
    ch.draw_series(cells.iter().map(|c| {
        let col = ViridisRGB::get_color_normalized(value(c), vmin, vmax);
        cell_rect(c, dx, dy, col.filled())
    }))
    .map_err(err)?;
    // Colour bar.
    let mut cb = ChartBuilder::on(&bar)
        .margin_top(30)
        .margin_bottom(52)
        .margin_left(10)
        .margin_right(10)
        .right_y_label_area_size(80)
        .caption(unit, ("sans-serif", 14))
        .build_cartesian_2d(0.0..1.0, vmin..vmax)
        .map_err(err)?
        .set_secondary_coord(0.0..1.0, vmin..vmax);
    cb.configure_secondary_axes()
        .y_labels(6)
        .label_style(("sans-serif", 13))
        .draw()
        .map_err(err)?;
    let n = 100;
    let span = vmax - vmin;
    cb.draw_series((0..n).map(|k| {
        let a = vmin + span * k as f64 / n as f64;
        let b = vmin + span * (k + 1) as f64 / n as f64;
        Rectangle::new(
            [(0.0, a), (1.0, b)],
            ViridisRGB::get_color_normalized(a, vmin, vmax).filled(),
        )
    }))
    .map_err(err)?;
    root.present().map_err(err)?;
    Ok(())
}

/// Adhesion colour of the stick/slip map.
pub const STICK_COLOUR: RGBColor = RGBColor(0x1f, 0x77, 0xb4);
/// Slip colour of the stick/slip map.
pub const SLIP_COLOUR: RGBColor = RGBColor(0xd6, 0x27, 0x28);

/// The stick/slip map: two discrete colours and a legend.
fn stick_slip(
    file: &Path,
    title: &str,
    cells: &[PlotCell],
    dx: f64,
    dy: f64,
) -> Result<(), String> {
    if cells.is_empty() {
        return Ok(());
    }
    let root = SVGBackend::new(file, (860, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let root = root.titled(title, ("sans-serif", 18)).map_err(err)?;
    let mut ch = patch_chart(&root, cells, dx, dy)?;
    for (slip, col, label) in [
        (false, STICK_COLOUR, "adhesion (stick)"),
        (true, SLIP_COLOUR, "slip"),
    ] {
        ch.draw_series(
            cells
                .iter()
                .filter(|c| c.slip == slip)
                .map(|c| cell_rect(c, dx, dy, col.filled())),
        )
        .map_err(err)?
        .label(label)
        .legend(move |(x, y)| Rectangle::new([(x, y - 6), (x + 14, y + 6)], col.filled()));
    }
    ch.configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 14))
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(err)?;
    root.present().map_err(err)?;
    Ok(())
}

/// Writes pressure.svg, traction.svg, stick_slip.svg, slip_velocity.svg, wear_cells.svg and
/// wear.svg into `dir`; every title ends with `case` (the case: dy, load, model).
/// `dx`, `dy` are the cell sizes (mm); `wear_per_strip` holds (y mm, depth µm) per strip.
pub fn write_all(
    dir: &Path,
    case: &str,
    cells: &[PlotCell],
    dx: f64,
    dy: f64,
    wear_per_strip: &[(f64, f64)],
) -> Result<(), String> {
    register_font()?;
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let t = |what: &str| format!("{what} — {case}");
    heat(
        &dir.join("pressure.svg"),
        &t("Normal pressure"),
        "MPa",
        cells,
        dx,
        dy,
        |c| c.pn,
    )?;
    heat(
        &dir.join("traction.svg"),
        &t("Tangential traction |p_t| on the wheel"),
        "MPa",
        cells,
        dx,
        dy,
        |c| c.px.hypot(c.py),
    )?;
    stick_slip(
        &dir.join("stick_slip.svg"),
        &t("Adhesion and slip"),
        cells,
        dx,
        dy,
    )?;
    heat(
        &dir.join("slip_velocity.svg"),
        &t("Slip velocity"),
        "m/s",
        cells,
        dx,
        dy,
        |c| c.vs,
    )?;
    heat(
        &dir.join("wear_cells.svg"),
        &t("Wear depth per cell and passage"),
        "µm",
        cells,
        dx,
        dy,
        |c| c.wear_um,
    )?;
    // Wear per strip.
    let file = dir.join("wear.svg");
    let root = SVGBackend::new(&file, (860, 440)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let (mut y0, mut y1, mut w1) = (f64::MAX, f64::MIN, 0.0f64);
    for &(y, w) in wear_per_strip {
        y0 = y0.min(y);
        y1 = y1.max(y);
        w1 = w1.max(w);
    }
    if wear_per_strip.is_empty() || y1 <= y0 {
        return Ok(());
    }
    let mut ch = ChartBuilder::on(&root)
        .caption(
            t("Wear depth per strip and passage (KTH/Archard)"),
            ("sans-serif", 18),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(y0..y1, 0.0..(w1 * 1.1).max(1e-12))
        .map_err(err)?;
    ch.configure_mesh()
        .x_desc("y, mm")
        .y_desc("wear depth, µm")
        .draw()
        .map_err(err)?;
    ch.draw_series(LineSeries::new(
        wear_per_strip.iter().copied(),
        BLUE.stroke_width(2),
    ))
    .map_err(err)?;
    root.present().map_err(err)?;
    Ok(())
}

/// The sweep's plots: F_y, F_x, F_n (totals over the patches), p_max and the adhesion fraction
/// against the shift, one line per model, into `dir` (sweep_fy.svg, sweep_fx.svg, sweep_fn.svg,
/// sweep_pmax.svg, sweep_stick.svg).
pub fn sweep_plots(
    dir: &Path,
    case: &str,
    series: &[(String, Vec<(f64, crate::doc::Document)>)],
) -> Result<(), String> {
    use crate::doc::Document;
    register_font()?;
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let stick = |d: &Document| {
        let a: f64 = d.patches.iter().map(|p| p.area_mm2).sum();
        let s: f64 = d
            .patches
            .iter()
            .map(|p| p.area_mm2 * p.stick_area_fraction)
            .sum();
        if a > 0.0 {
            s / a
        } else {
            0.0
        }
    };
    type Quantity<'q> = (
        &'q str,
        &'q str,
        &'q str,
        Box<dyn Fn(&Document) -> f64 + 'q>,
    );
    let quantities: [Quantity; 5] = [
        (
            "sweep_fy.svg",
            "Lateral creep force F_y",
            "F_y, N",
            Box::new(|d| d.total.fy_n),
        ),
        (
            "sweep_fx.svg",
            "Longitudinal creep force F_x",
            "F_x, N",
            Box::new(|d| d.total.fx_n),
        ),
        (
            "sweep_fn.svg",
            "Normal force F_n",
            "F_n, N",
            Box::new(|d| d.total.fn_n),
        ),
        (
            "sweep_pmax.svg",
            "Maximum pressure",
            "p_max, MPa",
            Box::new(|d| d.patches.iter().map(|p| p.pmax_mpa).fold(0.0, f64::max)),
        ),
        (
            "sweep_stick.svg",
            "Adhesion area fraction",
            "-",
            Box::new(stick),
        ),
    ];
    let palette = [
        RGBColor(0x1f, 0x77, 0xb4),
        RGBColor(0xff, 0x7f, 0x0e),
        RGBColor(0x2c, 0xa0, 0x2c),
        RGBColor(0xd6, 0x27, 0x28),
        RGBColor(0x94, 0x67, 0xbd),
        RGBColor(0x8c, 0x56, 0x4b),
    ];
    for (name, what, ylab, q) in quantities.iter() {
        let file = dir.join(name);
        let root = SVGBackend::new(&file, (860, 520)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let xs = value_range(series.iter().flat_map(|s| s.1.iter().map(|p| p.0)));
        let ys = value_range(series.iter().flat_map(|s| s.1.iter().map(|p| q(&p.1))));
        let pad = 0.05 * (ys.1 - ys.0);
        let mut ch = ChartBuilder::on(&root)
            .caption(format!("{what} — {case}"), ("sans-serif", 18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(80)
            .build_cartesian_2d(xs.0..xs.1, (ys.0 - pad)..(ys.1 + pad))
            .map_err(err)?;
        ch.configure_mesh()
            .x_desc("lateral shift dy, mm")
            .y_desc(*ylab)
            .draw()
            .map_err(err)?;
        for (k, (model, pts)) in series.iter().enumerate() {
            let col = palette[k % palette.len()];
            ch.draw_series(LineSeries::new(
                pts.iter().map(|(dy, d)| (*dy, q(d))),
                col.stroke_width(2),
            ))
            .map_err(err)?
            .label(model.as_str())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], col.stroke_width(2)));
            ch.draw_series(
                pts.iter()
                    .map(|(dy, d)| Circle::new((*dy, q(d)), 3, col.filled())),
            )
            .map_err(err)?;
        }
        ch.configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 13))
            .draw()
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::{equal_aspect, value_range};

    #[test]
    fn equal_aspect_gives_one_scale_for_x_and_y() {
        let ((x0, x1), (y0, y1)) = equal_aspect((-8.0, 8.0), (-2.0, 2.0), 600, 400);
        assert!(((x1 - x0) / 600.0 - (y1 - y0) / 400.0).abs() < 1e-12);
        assert!(x0 <= -8.0 && x1 >= 8.0 && y0 <= -2.0 && y1 >= 2.0);
    }

    #[test]
    fn colour_range_follows_the_data() {
        assert_eq!(
            value_range([0.001, 0.027, 0.01].into_iter()),
            (0.001, 0.027)
        );
        let (lo, hi) = value_range([0.027; 3].into_iter());
        assert!(lo < 0.027 && hi > 0.027 && hi - lo < 0.001);
    }
}
