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

/// A heat map of `value(cell)` over the patch cells, each drawn as a rectangle δx × δy.
fn heat(
    file: &Path,
    title: &str,
    unit: &str,
    cells: &[PlotCell],
    dx: f64,
    dy: f64,
    value: impl Fn(&PlotCell) -> f64,
) -> Result<(), String> {
    let root = SVGBackend::new(file, (780, 520)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    let (mut vmin, mut vmax) = (f64::MAX, f64::MIN);
    for c in cells {
        x0 = x0.min(c.x - dx);
        x1 = x1.max(c.x + dx);
        y0 = y0.min(c.y - dy);
        y1 = y1.max(c.y + dy);
        let v = value(c);
        vmin = vmin.min(v);
        vmax = vmax.max(v);
    }
    if cells.is_empty() {
        return Ok(());
    }
    let span = if vmax > vmin { vmax - vmin } else { 1.0 };
    let (main, bar) = root.split_horizontally(640);
    let mut ch = ChartBuilder::on(&main)
        .caption(title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(50)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(err)?;
    ch.configure_mesh()
        .x_desc("x (rolling direction), mm")
        .y_desc("y, mm")
        .disable_mesh()
        .draw()
        .map_err(err)?;
    ch.draw_series(cells.iter().map(|c| {
        let col = ViridisRGB::get_color_normalized(value(c), vmin, vmin + span);
        Rectangle::new(
            [
                (c.x - dx / 2.0, c.y - dy / 2.0),
                (c.x + dx / 2.0, c.y + dy / 2.0),
            ],
            col.filled(),
        )
    }))
    .map_err(err)?;
    // Colour bar.
    let mut cb = ChartBuilder::on(&bar)
        .margin_top(40)
        .margin_bottom(52)
        .margin_left(10)
        .margin_right(10)
        .right_y_label_area_size(70)
        .caption(unit, ("sans-serif", 14))
        .build_cartesian_2d(0.0..1.0, vmin..vmin + span)
        .map_err(err)?
        .set_secondary_coord(0.0..1.0, vmin..vmin + span);
    cb.configure_secondary_axes()
        .y_labels(6)
        .label_style(("sans-serif", 13))
        .draw()
        .map_err(err)?;
    let n = 100;
    cb.draw_series((0..n).map(|k| {
        let a = vmin + span * k as f64 / n as f64;
        let b = vmin + span * (k + 1) as f64 / n as f64;
        Rectangle::new(
            [(0.0, a), (1.0, b)],
            ViridisRGB::get_color_normalized(a, vmin, vmin + span).filled(),
        )
    }))
    .map_err(err)?;
    root.present().map_err(err)?;
    Ok(())
}

/// Writes pressure.svg, traction.svg, stick_slip.svg, slip_velocity.svg, wear_cells.svg and
/// wear.svg into `dir`.
/// `dx`, `dy` are the cell sizes (mm); `wear_per_strip` holds (y mm, depth µm) per strip.
pub fn write_all(
    dir: &Path,
    cells: &[PlotCell],
    dx: f64,
    dy: f64,
    wear_per_strip: &[(f64, f64)],
) -> Result<(), String> {
    register_font()?;
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    heat(
        &dir.join("pressure.svg"),
        "Normal pressure",
        "MPa",
        cells,
        dx,
        dy,
        |c| c.pn,
    )?;
    heat(
        &dir.join("traction.svg"),
        "Tangential traction |p_t| on the wheel",
        "MPa",
        cells,
        dx,
        dy,
        |c| c.px.hypot(c.py),
    )?;
    heat(
        &dir.join("stick_slip.svg"),
        "Adhesion (0) and slip (1)",
        "-",
        cells,
        dx,
        dy,
        |c| if c.slip { 1.0 } else { 0.0 },
    )?;
    heat(
        &dir.join("slip_velocity.svg"),
        "Slip velocity",
        "m/s",
        cells,
        dx,
        dy,
        |c| c.vs,
    )?;
    heat(
        &dir.join("wear_cells.svg"),
        "Wear depth per cell and passage",
        "um",
        cells,
        dx,
        dy,
        |c| c.wear_um,
    )?;
    // Wear per strip.
    let file = dir.join("wear.svg");
    let root = SVGBackend::new(&file, (760, 420)).into_drawing_area();
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
            "Wear depth per strip and passage (KTH/Archard)",
            ("sans-serif", 20),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(y0..y1, 0.0..(w1 * 1.1).max(1e-12))
        .map_err(err)?;
    ch.configure_mesh()
        .x_desc("y, mm")
        .y_desc("wear depth, um")
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
