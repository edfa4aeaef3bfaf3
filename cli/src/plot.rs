//! SVG plots of a solved patch: pressure, traction with stick/slip, slip velocity, wear per strip,
//! the strip through y = 0 and the strips (beside the exact reference with `--plot-reference`).
//!
//! Text needs a TrueType font: DejaVu Sans from Debian's `fonts-dejavu-core`
//! (/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf) or the file named by `$WRC_FONT`.

use crate::doc::Patch;
use crate::sink::PlotCell;
use plotters::element::DashedPathElement;
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
    let (y0, y1) = value_range(wear_per_strip.iter().map(|w| w.0));
    if wear_per_strip.is_empty() || y1 <= y0 {
        return Ok(());
    }
    line_chart(
        &root,
        &t("Wear depth per strip and passage (KTH/Archard)"),
        18,
        ("y, mm", "wear depth, µm"),
        &[Series {
            label: String::new(),
            points: wear_per_strip.to_vec(),
            colour: BLUE,
            dashed: false,
            dots: false,
        }],
    )?;
    root.present().map_err(err)?;
    Ok(())
}

/// One line of a [`line_chart`].
pub struct Series {
    /// Legend label (empty: not in the legend).
    pub label: String,
    /// Points (x, y), in the order they are joined.
    pub points: Vec<(f64, f64)>,
    /// Colour.
    pub colour: RGBColor,
    /// Dashed (a reference) or solid (the model).
    pub dashed: bool,
    /// Marks every point with a dot (the model's strips and cells).
    pub dots: bool,
}

/// Top of an axis of magnitudes: 8 % above the largest finite value, 1 when none is above 0.
fn top(values: impl Iterator<Item = f64>) -> f64 {
    let m = values.filter(|v| v.is_finite()).fold(0.0, f64::max);
    if m > 0.0 {
        1.08 * m
    } else {
        1.0
    }
}

/// A line chart of `series` on `area`: caption (`caption_px` high), axis descriptions
/// `desc` = (x, y), x over the points' range, y from 0 (the quantities drawn are magnitudes) to a
/// little above the largest value, and a legend in the upper right when any series has a label
/// (above the data: the y range grows with the legend's entries).
fn line_chart(
    area: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>,
    caption: &str,
    caption_px: u32,
    desc: (&str, &str),
    series: &[Series],
) -> Result<(), String> {
    let (x0, x1) = value_range(series.iter().flat_map(|s| s.points.iter().map(|p| p.0)));
    let pad = 0.02 * (x1 - x0);
    // headroom for the legend in the upper right: about a ninth of the height per entry
    let entries = series.iter().filter(|s| !s.label.is_empty()).count();
    let y1 = top(series.iter().flat_map(|s| s.points.iter().map(|p| p.1)))
        * (1.0 + 0.12 * entries as f64);
    let mut ch = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", caption_px))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d((x0 - pad)..(x1 + pad), 0.0..y1)
        .map_err(err)?;
    ch.configure_mesh()
        .x_desc(desc.0)
        .y_desc(desc.1)
        .draw()
        .map_err(err)?;
    for s in series {
        let (col, pts) = (s.colour, s.points.clone());
        let drawn = if s.dashed {
            ch.draw_series(DashedLineSeries::new(pts, 7, 4, col.stroke_width(2)))
                .map_err(err)?
        } else {
            ch.draw_series(LineSeries::new(pts, col.stroke_width(2)))
                .map_err(err)?
        };
        if !s.label.is_empty() {
            let dashed = s.dashed;
            drawn.label(s.label.as_str()).legend(move |(x, y)| {
                if dashed {
                    DashedPathElement::new(vec![(x, y), (x + 22, y)], 7, 4, col.stroke_width(2))
                        .into_dyn()
                } else {
                    PathElement::new(vec![(x, y), (x + 22, y)], col.stroke_width(2)).into_dyn()
                }
            });
        }
        if s.dots {
            ch.draw_series(s.points.iter().map(|&p| Circle::new(p, 2, col.filled())))
                .map_err(err)?;
        }
    }
    if series.iter().any(|s| !s.label.is_empty()) {
        ch.configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 13))
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(err)?;
    }
    Ok(())
}

/// One patch of y0.svg and strips.svg: the model's and, when paired, the reference's.
pub struct Compared<'p> {
    /// Panel heading (patch number and reference point).
    pub heading: String,
    /// The model's patch.
    pub model: &'p Patch,
    /// The reference's patch paired with it (`--plot-reference`).
    pub reference: Option<&'p Patch>,
}

/// Colour of the model's |p_t| and of its per-strip curves.
const MODEL_COLOUR: RGBColor = RGBColor(0x1f, 0x77, 0xb4);
/// Colour of the model's traction bound μ·p_n.
const BOUND_COLOUR: RGBColor = RGBColor(0xff, 0x7f, 0x0e);
/// Colour of the model's slip velocity.
const SLIP_VELOCITY_COLOUR: RGBColor = RGBColor(0xd6, 0x27, 0x28);
/// Colour of the reference's traction bound (its |p_t| and other curves are black).
const REFERENCE_BOUND_COLOUR: RGBColor = RGBColor(0x70, 0x70, 0x70);

/// A root of `cols` columns × 2 rows of panels under `title`, 520 px per column (860 at least).
fn panels<'a>(
    file: &'a Path,
    title: &str,
    cols: usize,
) -> Result<Vec<DrawingArea<SVGBackend<'a>, plotters::coord::Shift>>, String> {
    let w = (520 * cols as u32).max(860);
    let root = SVGBackend::new(file, (w, 780)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let root = root.titled(title, ("sans-serif", 18)).map_err(err)?;
    Ok(root.split_evenly((2, cols.max(1))))
}

/// Writes y0.svg and strips.svg into `dir` for `patches` (one column of panels each):
///
/// * y0.svg: along the strip through y = 0 (the JSON's `y0`), |p_t| and the traction bound μ·p_n
///   (MPa, `mu` the friction coefficient) against x (mm) above, the slip velocity (mm/s) below;
/// * strips.svg: per strip against its centre y (mm), the KTH wear depth per passage (µm) above
///   and the tangential force per unit strip width |F_t|/δy (N/mm; per unit width, as the
///   reference's grid rows are narrower than the kernel's strips) below.
///
/// The model's curves are coloured and solid (legend `model`), the paired reference's black or
/// grey and dashed (legend `reference`), each at its own cells and strip centres. Every title
/// ends with `case`.
pub fn write_profiles(
    dir: &Path,
    case: &str,
    mu: f64,
    patches: &[Compared<'_>],
    model: &str,
    reference: &str,
) -> Result<(), String> {
    register_font()?;
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let solid = |label: String, points: Vec<(f64, f64)>, colour: RGBColor| Series {
        label,
        points,
        colour,
        dashed: false,
        dots: true,
    };
    let dashed = |label: String, points: Vec<(f64, f64)>, colour: RGBColor| Series {
        label,
        points,
        colour,
        dashed: true,
        dots: false,
    };
    let traction = |p: &Patch| -> Vec<(f64, f64)> {
        p.y0.iter()
            .map(|c| (c.x_mm, c.px_mpa.hypot(c.py_mpa)))
            .collect()
    };
    let bound =
        |p: &Patch| -> Vec<(f64, f64)> { p.y0.iter().map(|c| (c.x_mm, mu * c.pn_mpa)).collect() };
    let slip = |p: &Patch| -> Vec<(f64, f64)> {
        p.y0.iter()
            .map(|c| (c.x_mm, c.slip_velocity_mm_s))
            .collect()
    };
    let wear = |p: &Patch| -> Vec<(f64, f64)> {
        p.strips.iter().map(|s| (s.y_mm, s.wear_depth_um)).collect()
    };
    let force = |p: &Patch| -> Vec<(f64, f64)> {
        p.strips
            .iter()
            .filter(|s| s.width_mm > 0.0)
            .map(|s| (s.y_mm, s.fx_n.hypot(s.fy_n) / s.width_mm))
            .collect()
    };
    let file = dir.join("y0.svg");
    let areas = panels(
        &file,
        &format!("Strip through y = 0 — {case}"),
        patches.len(),
    )?;
    let n = patches.len();
    for (k, c) in patches.iter().enumerate() {
        // the bounds first, so that the tractions stay visible where they reach them (slip)
        let mut upper = vec![
            solid(format!("μ·p_n, {model}"), bound(c.model), BOUND_COLOUR),
            solid(format!("|p_t|, {model}"), traction(c.model), MODEL_COLOUR),
        ];
        let mut lower = vec![solid(
            format!("slip velocity, {model}"),
            slip(c.model),
            SLIP_VELOCITY_COLOUR,
        )];
        if let Some(r) = c.reference {
            upper.insert(
                1,
                dashed(
                    format!("μ·p_n, {reference}"),
                    bound(r),
                    REFERENCE_BOUND_COLOUR,
                ),
            );
            upper.push(dashed(format!("|p_t|, {reference}"), traction(r), BLACK));
            lower.push(dashed(
                format!("slip velocity, {reference}"),
                slip(r),
                BLACK,
            ));
        }
        line_chart(
            &areas[k],
            &format!("{}: traction and its bound", c.heading),
            15,
            ("x (rolling direction), mm", "MPa"),
            &upper,
        )?;
        line_chart(
            &areas[n + k],
            &format!("{}: slip velocity", c.heading),
            15,
            ("x (rolling direction), mm", "slip velocity, mm/s"),
            &lower,
        )?;
    }
    if let Some(a) = areas.first() {
        a.present().map_err(err)?;
    }
    drop(areas);
    let file = dir.join("strips.svg");
    let areas = panels(&file, &format!("Per strip — {case}"), patches.len())?;
    for (k, c) in patches.iter().enumerate() {
        let mut w = vec![solid(
            format!("wear depth, {model}"),
            wear(c.model),
            MODEL_COLOUR,
        )];
        let mut f = vec![solid(
            format!("|F_t|/δy, {model}"),
            force(c.model),
            MODEL_COLOUR,
        )];
        if let Some(r) = c.reference {
            w.push(dashed(format!("wear depth, {reference}"), wear(r), BLACK));
            f.push(dashed(format!("|F_t|/δy, {reference}"), force(r), BLACK));
        }
        line_chart(
            &areas[k],
            &format!("{}: KTH wear depth per passage", c.heading),
            15,
            ("strip centre y, mm", "wear depth, µm"),
            &w,
        )?;
        line_chart(
            &areas[n + k],
            &format!("{}: tangential force per unit strip width", c.heading),
            15,
            ("strip centre y, mm", "|F_t|/δy, N/mm"),
            &f,
        )?;
    }
    if let Some(a) = areas.first() {
        a.present().map_err(err)?;
    }
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
        // a quantity no series computes (the real-time step's adhesion fraction) is not drawn
        if !series
            .iter()
            .any(|s| s.1.iter().any(|p| q(&p.1).is_finite()))
        {
            continue;
        }
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
    use super::{equal_aspect, value_range, write_profiles, Compared};
    use crate::doc::{Patch, StripOut, Y0Cell};

    /// A patch at `y_ref` with a few strips and y0 cells scaled by `k`.
    fn patch(y_ref: f64, k: f64) -> Patch {
        Patch {
            y_ref_mm: y_ref,
            strips: (0..5)
                .map(|j| StripOut {
                    y_mm: j as f64 - 2.0,
                    width_mm: 1.0,
                    fx_n: k * 10.0,
                    fy_n: k * j as f64,
                    wear_depth_um: k * 1e-3,
                    ..StripOut::default()
                })
                .collect(),
            y0: (0..7)
                .map(|i| Y0Cell {
                    x_mm: i as f64 - 3.0,
                    pn_mpa: 900.0 - 90.0 * (i as f64 - 3.0).powi(2),
                    px_mpa: k * 20.0 * i as f64,
                    slip_velocity_mm_s: if i < 2 { 100.0 * k } else { 0.0 },
                    ..Y0Cell::default()
                })
                .collect(),
            ..Patch::default()
        }
    }

    #[test]
    fn profiles_draw_one_column_per_patch_and_the_reference_where_paired() {
        let d = std::env::temp_dir().join(format!("wrc-plot-unit-{}", std::process::id()));
        let (m0, m1, r0) = (patch(-5.0, 1.0), patch(30.0, 2.0), patch(-5.0, 1.1));
        let compared = [
            Compared {
                heading: "patch 0".into(),
                model: &m0,
                reference: Some(&r0),
            },
            Compared {
                heading: "patch 1".into(),
                model: &m1,
                reference: None,
            },
        ];
        write_profiles(&d, "case", 0.3, &compared, "the model", "the reference").unwrap();
        for f in ["y0.svg", "strips.svg"] {
            let s = std::fs::read_to_string(d.join(f)).unwrap();
            assert!(s.starts_with("<svg") || s.starts_with("<?xml"), "{f}");
            assert!(s.contains("patch 0") && s.contains("patch 1"), "{f}");
            assert!(
                s.contains("the model") && s.contains("the reference"),
                "{f}"
            );
            // the reference in the first column only: once per panel of that column
            let n = s.matches("the reference").count();
            let expected = if f == "y0.svg" { 3 } else { 2 };
            assert_eq!(n, expected, "{f}");
        }
        let _ = std::fs::remove_dir_all(&d);
    }

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
