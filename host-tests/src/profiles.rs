//! Profile readers (CONTACT/SIMPACK `.prr`/`.prw`, plain two-column files) and preprocessing into
//! the kernel's fixed-size [`ProfileTable`]s.
//!
//! Pipeline ([`build_table`]):
//! 1. read the points and apply the file's own options (units, `shift.y/z`, `rotate`, `mirror.y/z`,
//!    `inversion`; the bounds clip only when min < max), as CONTACT does;
//! 2. orient the points so that `y` is non-decreasing (reverse if the list runs the other way) and
//!    drop points closer than `point.dist.min` (at least 1e-4 mm) to their predecessor;
//! 3. interpolate with a parametric natural cubic spline (parameter = cumulative chord length) and
//!    resample it on a fine uniform arc-length grid (`fine_step`, default 0.01 mm);
//! 4. smooth: penalised least squares with a second-difference penalty (Whittaker–Reinsch, the
//!    discrete form of the cubic smoothing spline), applied to y(s) and z(s) with
//!    λ = (L / (2π h))⁴, h = fine step. Its transfer function is 1/(1 + (ω/ω_c)⁴) with
//!    ω_c = 2π/L: waves of length L (the **filter wavelength**, `SmoothOptions::wavelength`) keep
//!    half their amplitude, 2L keeps 94 %, L/2 keeps 6 %. L = 0 skips smoothing;
//! 5. tangent angle and curvature by central differences on the fine smoothed curve,
//!    re-parametrised by its own arc length;
//! 6. resample at the table's uniform arc-length step (`ds`), derive dz/dy and d²z/dy².
//!
//! Errors carry the file name, the line number (for syntax errors) and the cause.

use std::fmt;
use std::path::{Path, PathBuf};

use wrc_kernel::profile::{ProfileKind, ProfileTable};

/// A profile read from a file: points in the profile's canonical coordinates (mm; y towards the
/// field side; z down), in file order after the file's own options.
#[derive(Clone, Debug)]
pub struct RawProfile {
    /// Rail or wheel (from the `.prr`/`.prw` header `type`, or given for plain files).
    pub kind: ProfileKind,
    /// Points (y, z), mm.
    pub points: Vec<(f64, f64)>,
    /// Minimum point distance requested by the file, mm.
    pub point_dist_min: f64,
    /// Source file (for messages).
    pub source: PathBuf,
}

/// Why a profile file could not be used.
#[derive(Clone, Debug, PartialEq)]
pub enum ProfileError {
    /// The file could not be read.
    Io {
        /// File.
        path: PathBuf,
        /// OS message.
        message: String,
    },
    /// A syntax or value error on a given line (1-based).
    Line {
        /// File.
        path: PathBuf,
        /// Line number, 1-based.
        line: usize,
        /// What is wrong.
        cause: String,
    },
    /// The file as a whole is unusable (no points, missing sections, non-monotone lateral
    /// coordinate, …).
    File {
        /// File.
        path: PathBuf,
        /// What is wrong.
        cause: String,
    },
}

impl fmt::Display for ProfileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ProfileError::Io { path, message } => {
                write!(f, "{}: cannot read: {message}", path.display())
            }
            ProfileError::Line { path, line, cause } => {
                write!(f, "{}:{line}: {cause}", path.display())
            }
            ProfileError::File { path, cause } => write!(f, "{}: {cause}", path.display()),
        }
    }
}

impl std::error::Error for ProfileError {}

/// Reads a profile file: `.prr` / `.prw` (SIMPACK format as used by CONTACT), otherwise a plain
/// two-column file. For plain files `kind` must be given (and is checked against the header for
/// `.prr`/`.prw` if given).
pub fn read_profile(path: &Path, kind: Option<ProfileKind>) -> Result<RawProfile, ProfileError> {
    let text = std::fs::read_to_string(path).map_err(|e| ProfileError::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    parse_profile(&text, path, kind)
}

/// Parses a profile from its text; `path` names it in errors and its extension selects the format
/// as in [`read_profile`].
pub fn parse_profile(
    text: &str,
    path: &Path,
    kind: Option<ProfileKind>,
) -> Result<RawProfile, ProfileError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    if ext == "prr" || ext == "prw" {
        let raw = parse_simpack(text, path)?;
        if let Some(k) = kind {
            if k != raw.kind {
                return Err(ProfileError::File {
                    path: path.to_path_buf(),
                    cause: format!("header type is {:?} but {:?} was expected", raw.kind, k),
                });
            }
        }
        Ok(raw)
    } else {
        let kind = kind.ok_or_else(|| ProfileError::File {
            path: path.to_path_buf(),
            cause: "plain two-column file: profile kind (rail/wheel) must be given".into(),
        })?;
        parse_two_column(text, path, kind)
    }
}

fn line_err(path: &Path, line: usize, cause: impl Into<String>) -> ProfileError {
    ProfileError::Line {
        path: path.to_path_buf(),
        line,
        cause: cause.into(),
    }
}

fn file_err(path: &Path, cause: impl Into<String>) -> ProfileError {
    ProfileError::File {
        path: path.to_path_buf(),
        cause: cause.into(),
    }
}

fn parse_number(tok: &str, path: &Path, line: usize, what: &str) -> Result<f64, ProfileError> {
    let v: f64 = tok
        .parse()
        .map_err(|_| line_err(path, line, format!("{what}: '{tok}' is not a number")))?;
    if !v.is_finite() {
        return Err(line_err(
            path,
            line,
            format!("{what}: '{tok}' is not finite"),
        ));
    }
    Ok(v)
}

/// Splits a data line into numeric fields (whitespace, comma or semicolon separated).
fn fields(line: &str) -> Vec<&str> {
    line.split(|c: char| c.is_whitespace() || c == ',' || c == ';')
        .filter(|t| !t.is_empty())
        .collect()
}

/// Plain two-column file: `y z` per line (whitespace/comma/semicolon separated; an optional
/// third column, a weight, is ignored); lines starting with `#`, `!`, `%` or `//` are comments;
/// one non-numeric header line is allowed before the first point. Coordinates in mm, already in
/// the canonical orientation (y towards the field side, z down).
pub fn parse_two_column(
    text: &str,
    path: &Path,
    kind: ProfileKind,
) -> Result<RawProfile, ProfileError> {
    let mut points = Vec::new();
    let mut header_seen = false;
    for (i, line) in text.lines().enumerate() {
        let ln = i + 1;
        let t = line.trim();
        if t.is_empty()
            || t.starts_with('#')
            || t.starts_with('!')
            || t.starts_with('%')
            || t.starts_with("//")
        {
            continue;
        }
        let f = fields(t);
        let numeric = f.first().map(|s| s.parse::<f64>().is_ok()).unwrap_or(false);
        if !numeric {
            if points.is_empty() && !header_seen {
                header_seen = true;
                continue;
            }
            return Err(line_err(
                path,
                ln,
                format!("expected two numbers 'y z', found '{t}'"),
            ));
        }
        if f.len() < 2 {
            return Err(line_err(path, ln, "expected two numbers 'y z', found one"));
        }
        if f.len() > 3 {
            return Err(line_err(
                path,
                ln,
                format!("expected 2 or 3 columns, found {}", f.len()),
            ));
        }
        let y = parse_number(f[0], path, ln, "y")?;
        let z = parse_number(f[1], path, ln, "z")?;
        points.push((y, z));
    }
    if points.len() < 4 {
        return Err(file_err(
            path,
            format!("{} points found, at least 4 needed", points.len()),
        ));
    }
    Ok(RawProfile {
        kind,
        points,
        point_dist_min: 0.0,
        source: path.to_path_buf(),
    })
}

/// SIMPACK `.prr`/`.prw` (version 1) as described in `data/profiles/PROFILES.md`.
pub fn parse_simpack(text: &str, path: &Path) -> Result<RawProfile, ProfileError> {
    #[derive(PartialEq)]
    enum Sec {
        None,
        Header,
        Spline,
        Points,
    }
    let mut sec = Sec::None;
    let mut version: Option<i64> = None;
    let mut kind: Option<ProfileKind> = None;
    let mut seen_header = false;
    let mut seen_points_end = false;
    let mut opt = std::collections::HashMap::<String, (f64, usize)>::new();
    let mut pts: Vec<(f64, f64)> = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let ln = i + 1;
        // strip comments
        let t = match line.find('!') {
            Some(p) => &line[..p],
            None => line,
        }
        .trim();
        if t.is_empty() {
            continue;
        }
        let lower = t.to_ascii_lowercase();
        match lower.as_str() {
            "header.begin" => {
                if sec != Sec::None {
                    return Err(line_err(path, ln, "header.begin inside another section"));
                }
                sec = Sec::Header;
                seen_header = true;
                continue;
            }
            "header.end" => {
                if sec != Sec::Header {
                    return Err(line_err(path, ln, "header.end without header.begin"));
                }
                sec = Sec::None;
                continue;
            }
            "spline.begin" => {
                if sec != Sec::None {
                    return Err(line_err(path, ln, "spline.begin inside another section"));
                }
                sec = Sec::Spline;
                continue;
            }
            "spline.end" => {
                if sec != Sec::Spline {
                    return Err(line_err(path, ln, "spline.end outside the spline section"));
                }
                sec = Sec::None;
                continue;
            }
            "point.begin" => {
                if sec != Sec::Spline {
                    return Err(line_err(path, ln, "point.begin outside the spline section"));
                }
                sec = Sec::Points;
                continue;
            }
            "point.end" => {
                if sec != Sec::Points {
                    return Err(line_err(path, ln, "point.end without point.begin"));
                }
                sec = Sec::Spline;
                seen_points_end = true;
                continue;
            }
            _ => {}
        }
        match sec {
            Sec::Points => {
                let f = fields(t);
                if f.len() < 2 || f.len() > 3 {
                    return Err(line_err(
                        path,
                        ln,
                        format!("expected 'y z [weight]', found {} fields", f.len()),
                    ));
                }
                let y = parse_number(f[0], path, ln, "y")?;
                let z = parse_number(f[1], path, ln, "z")?;
                if f.len() == 3 {
                    parse_number(f[2], path, ln, "weight")?;
                }
                pts.push((y, z));
            }
            Sec::Header | Sec::Spline => {
                let Some((k, v)) = t.split_once('=') else {
                    return Err(line_err(
                        path,
                        ln,
                        format!("expected 'key = value', found '{t}'"),
                    ));
                };
                let key = k.trim().to_ascii_lowercase();
                let val = v.trim();
                if sec == Sec::Header {
                    let n = parse_number(val, path, ln, &key)?;
                    match key.as_str() {
                        "version" => version = Some(n as i64),
                        "type" => {
                            kind = Some(match n as i64 {
                                0 => ProfileKind::Rail,
                                1 => ProfileKind::Wheel,
                                other => {
                                    return Err(line_err(
                                        path,
                                        ln,
                                        format!("type = {other}: expected 0 (rail) or 1 (wheel)"),
                                    ))
                                }
                            })
                        }
                        _ => {}
                    }
                } else if val.starts_with('\'') || val.starts_with('"') {
                    // string option (file, comment, units.len): informational
                } else {
                    let n = parse_number(val, path, ln, &key)?;
                    opt.insert(key, (n, ln));
                }
            }
            Sec::None => {
                return Err(line_err(
                    path,
                    ln,
                    format!("unexpected text outside sections: '{t}'"),
                ))
            }
        }
    }
    if !seen_header {
        return Err(file_err(path, "no header.begin … header.end section"));
    }
    if sec != Sec::None {
        return Err(file_err(path, "file ends inside a section (missing .end)"));
    }
    if !seen_points_end {
        return Err(file_err(path, "no point.begin … point.end list"));
    }
    match version {
        Some(1) => {}
        Some(v) => {
            return Err(file_err(
                path,
                format!("version = {v}: only version 1 is known"),
            ))
        }
        None => return Err(file_err(path, "header has no version")),
    }
    let kind = kind.ok_or_else(|| file_err(path, "header has no type (0 rail, 1 wheel)"))?;
    let get = |k: &str, d: f64| opt.get(k).map(|v| v.0).unwrap_or(d);
    if let Some((s, ln)) = opt.get("approx.smooth") {
        if *s != 0.0 {
            return Err(line_err(
                path,
                *ln,
                "approx.smooth != 0 is not supported (use the preprocessing filter wavelength)",
            ));
        }
    }
    let len_f = get("units.len.f", 1000.0);
    if !len_f.is_finite() || len_f <= 0.0 {
        return Err(file_err(path, "units.len.f must be positive"));
    }
    let ang_f = get("units.ang.f", 1.0);
    if !ang_f.is_finite() || ang_f <= 0.0 {
        return Err(file_err(path, "units.ang.f must be positive"));
    }
    let to_mm = 1000.0 / len_f;
    let rot = get("rotate", 0.0) / ang_f;
    let (sy, sz) = (get("shift.y", 0.0), get("shift.z", 0.0));
    let (ymin, ymax) = (get("bound.y.min", 1.0), get("bound.y.max", 0.0));
    let (zmin, zmax) = (get("bound.z.min", 1.0), get("bound.z.max", 0.0));
    let mirror_y = get("mirror.y", 0.0) != 0.0;
    let mirror_z = get("mirror.z", 0.0) != 0.0;
    let inversion = get("inversion", 0.0) != 0.0;
    let pdmin = get("point.dist.min", 0.0);
    // SIMPACK order of the processing steps as numbered in the file: 1 point distance, 2 shift,
    // 3 rotate, 4 bounds, 5 mirror, 6 inversion, 7 units.
    let (cr, sr) = (rot.cos(), rot.sin());
    let mut out = Vec::with_capacity(pts.len());
    for (y, z) in pts {
        let (y, z) = (y + sy, z + sz);
        let (y, z) = (cr * y - sr * z, sr * y + cr * z);
        if ymin < ymax && (y < ymin || y > ymax) {
            continue;
        }
        if zmin < zmax && (z < zmin || z > zmax) {
            continue;
        }
        let y = if mirror_y { -y } else { y };
        let z = if mirror_z { -z } else { z };
        out.push((y * to_mm, z * to_mm));
    }
    if inversion {
        out.reverse();
    }
    if out.len() < 4 {
        return Err(file_err(
            path,
            format!("{} points after clipping, at least 4 needed", out.len()),
        ));
    }
    Ok(RawProfile {
        kind,
        points: out,
        point_dist_min: pdmin * to_mm,
        source: path.to_path_buf(),
    })
}

/// Preprocessing options.
#[derive(Clone, Copy, Debug)]
pub struct SmoothOptions {
    /// Filter wavelength L of the smoothing spline, mm (amplitude halved at L; 0 = none).
    pub wavelength: f64,
    /// Fine working grid step in arc length, mm.
    pub fine_step: f64,
    /// Table arc-length step ds, mm; `None`: the smallest step for which the table fits `N`.
    pub ds: Option<f64>,
}

impl Default for SmoothOptions {
    /// L = 0.5 mm (removes measurement noise and the kinks of linearly spaced data shorter than
    /// ≈ 0.3 mm, keeps the 12–13 mm gauge-corner and flange-root radii), fine step 0.01 mm,
    /// ds = 0.1 mm.
    fn default() -> Self {
        SmoothOptions {
            wavelength: 0.5,
            fine_step: 0.01,
            ds: Some(0.1),
        }
    }
}

/// Natural cubic spline second derivatives for knots `t` (strictly increasing) and values `v`.
fn natural_spline(t: &[f64], v: &[f64]) -> Vec<f64> {
    let n = t.len();
    let mut m = vec![0.0; n];
    if n < 3 {
        return m;
    }
    let mut c = vec![0.0; n];
    let mut d = vec![0.0; n];
    for i in 1..n - 1 {
        let h0 = t[i] - t[i - 1];
        let h1 = t[i + 1] - t[i];
        let a = h0 / 6.0;
        let b = (h0 + h1) / 3.0;
        let cc = h1 / 6.0;
        let r = (v[i + 1] - v[i]) / h1 - (v[i] - v[i - 1]) / h0;
        let denom = b - a * c[i - 1];
        c[i] = cc / denom;
        d[i] = (r - a * d[i - 1]) / denom;
    }
    for i in (1..n - 1).rev() {
        m[i] = d[i] - c[i] * m[i + 1];
    }
    m
}

fn spline_eval(t: &[f64], v: &[f64], m: &[f64], x: f64, k: &mut usize) -> f64 {
    let n = t.len();
    while *k + 2 < n && x > t[*k + 1] {
        *k += 1;
    }
    let i = *k;
    let h = t[i + 1] - t[i];
    let a = (t[i + 1] - x) / h;
    let b = (x - t[i]) / h;
    a * v[i] + b * v[i + 1] + ((a * a * a - a) * m[i] + (b * b * b - b) * m[i + 1]) * h * h / 6.0
}

/// Whittaker–Reinsch smoother: solves (I + λ DᵀD) x = d with D the second-difference operator
/// (symmetric pentadiagonal, banded LDLᵀ).
fn whittaker(d: &[f64], lambda: f64) -> Vec<f64> {
    let n = d.len();
    if lambda <= 0.0 || n < 5 {
        return d.to_vec();
    }
    // matrix bands: a0 (diag), a1 (first off), a2 (second off)
    let mut a0 = vec![0.0; n];
    let mut a1 = vec![0.0; n];
    let mut a2 = vec![0.0; n];
    // DᵀD for D rows (1,-2,1) at i..i+2, i = 0..n-3
    for i in 0..n - 2 {
        let idx = [i, i + 1, i + 2];
        let w = [1.0, -2.0, 1.0];
        for p in 0..3 {
            for q in p..3 {
                let v = lambda * w[p] * w[q];
                match q - p {
                    0 => a0[idx[p]] += v,
                    1 => a1[idx[p]] += v,
                    _ => a2[idx[p]] += v,
                }
            }
        }
    }
    for x in a0.iter_mut() {
        *x += 1.0;
    }
    // LDLᵀ with bandwidth 2: L has l1[i] (i,i-1) and l2[i] (i,i-2)
    let mut dd = vec![0.0; n];
    let mut l1 = vec![0.0; n];
    let mut l2 = vec![0.0; n];
    for i in 0..n {
        if i >= 2 {
            l2[i] = a2[i - 2] / dd[i - 2];
        }
        if i >= 1 {
            let mut v = a1[i - 1];
            if i >= 2 {
                v -= l2[i] * dd[i - 2] * l1[i - 1];
            }
            l1[i] = v / dd[i - 1];
        }
        let mut v = a0[i];
        if i >= 1 {
            v -= l1[i] * l1[i] * dd[i - 1];
        }
        if i >= 2 {
            v -= l2[i] * l2[i] * dd[i - 2];
        }
        dd[i] = v;
    }
    let mut y = d.to_vec();
    for i in 0..n {
        if i >= 1 {
            y[i] -= l1[i] * y[i - 1];
        }
        if i >= 2 {
            y[i] -= l2[i] * y[i - 2];
        }
    }
    for i in 0..n {
        y[i] /= dd[i];
    }
    for i in (0..n).rev() {
        if i + 1 < n {
            y[i] -= l1[i + 1] * y[i + 1];
        }
        if i + 2 < n {
            y[i] -= l2[i + 2] * y[i + 2];
        }
    }
    y
}

/// A preprocessed curve on a fine uniform arc-length grid (host-side, any length).
#[derive(Clone, Debug)]
pub struct FineCurve {
    /// Arc-length step, mm.
    pub h: f64,
    /// Lateral coordinates, mm.
    pub y: Vec<f64>,
    /// Vertical coordinates (down), mm.
    pub z: Vec<f64>,
    /// Tangent angle, rad.
    pub angle: Vec<f64>,
    /// Curvature dβ/ds, 1/mm.
    pub curvature: Vec<f64>,
}

/// Steps 2–5 of the pipeline: orientation, de-duplication, interpolation, smoothing, derivatives.
pub fn preprocess(raw: &RawProfile, opts: &SmoothOptions) -> Result<FineCurve, ProfileError> {
    let path = raw.source.as_path();
    if !opts.fine_step.is_finite()
        || opts.fine_step <= 0.0
        || !opts.wavelength.is_finite()
        || opts.wavelength < 0.0
    {
        return Err(file_err(
            path,
            "smoothing options: fine_step > 0 and wavelength >= 0 required",
        ));
    }
    let mut pts = raw.points.clone();
    let (first, last) = (pts[0], pts[pts.len() - 1]);
    if last.0 < first.0 {
        pts.reverse();
    }
    let dmin = raw.point_dist_min.max(1e-4);
    let mut p: Vec<(f64, f64)> = Vec::with_capacity(pts.len());
    for q in pts {
        if let Some(&b) = p.last() {
            if ((q.0 - b.0).powi(2) + (q.1 - b.1).powi(2)).sqrt() < dmin {
                continue;
            }
        }
        p.push(q);
    }
    if p.len() < 4 {
        return Err(file_err(path, "fewer than 4 distinct points"));
    }
    for w in p.windows(2) {
        if w[1].0 < w[0].0 - 1e-6 {
            return Err(file_err(
                path,
                format!(
                    "lateral coordinate is not monotone (y = {:.4} after {:.4} mm): the profile \
                     must be a curve running from one side to the other",
                    w[1].0, w[0].0
                ),
            ));
        }
    }
    // chord-length parametrisation, natural cubic splines y(t), z(t)
    let mut t = vec![0.0; p.len()];
    for i in 1..p.len() {
        t[i] = t[i - 1] + ((p[i].0 - p[i - 1].0).powi(2) + (p[i].1 - p[i - 1].1).powi(2)).sqrt();
    }
    let ys: Vec<f64> = p.iter().map(|q| q.0).collect();
    let zs: Vec<f64> = p.iter().map(|q| q.1).collect();
    let my = natural_spline(&t, &ys);
    let mz = natural_spline(&t, &zs);
    // arc length of the spline on a sub-grid, then uniform arc-length samples
    let sub = 20.0 * (t[t.len() - 1] / opts.fine_step).ceil().max(10.0);
    let nsub = sub as usize;
    let (mut ky, mut kz) = (0usize, 0usize);
    let mut tt = Vec::with_capacity(nsub + 1);
    let mut sy: Vec<f64> = Vec::with_capacity(nsub + 1);
    let mut sz: Vec<f64> = Vec::with_capacity(nsub + 1);
    let mut arc: Vec<f64> = Vec::with_capacity(nsub + 1);
    let total_t = t[t.len() - 1];
    for k in 0..=nsub {
        let x = total_t * k as f64 / nsub as f64;
        let yy = spline_eval(&t, &ys, &my, x, &mut ky);
        let zz = spline_eval(&t, &zs, &mz, x, &mut kz);
        let a = match (sy.last(), sz.last(), arc.last()) {
            (Some(&py), Some(&pz), Some(&pa)) => {
                pa + ((yy - py) * (yy - py) + (zz - pz) * (zz - pz)).sqrt()
            }
            _ => 0.0,
        };
        tt.push(x);
        sy.push(yy);
        sz.push(zz);
        arc.push(a);
    }
    let total = arc[arc.len() - 1];
    let h = opts.fine_step;
    let nf = (total / h).floor() as usize + 1;
    let resample = |arc: &[f64], vals: &[f64], n: usize, h: f64| -> Vec<f64> {
        let mut out = Vec::with_capacity(n);
        let mut k = 0usize;
        for i in 0..n {
            let s = h * i as f64;
            while k + 2 < arc.len() && arc[k + 1] < s {
                k += 1;
            }
            let d = arc[k + 1] - arc[k];
            let u = if d > 0.0 {
                ((s - arc[k]) / d).clamp(0.0, 1.0)
            } else {
                0.0
            };
            out.push(vals[k] + u * (vals[k + 1] - vals[k]));
        }
        out
    };
    let fy = resample(&arc, &sy, nf, h);
    let fz = resample(&arc, &sz, nf, h);
    let lambda = if opts.wavelength > 0.0 {
        (opts.wavelength / (2.0 * std::f64::consts::PI * h)).powi(4)
    } else {
        0.0
    };
    let gy = whittaker(&fy, lambda);
    let gz = whittaker(&fz, lambda);
    // re-parametrise by the smoothed curve's own arc length
    let mut arc2 = vec![0.0; gy.len()];
    for i in 1..gy.len() {
        arc2[i] = arc2[i - 1] + ((gy[i] - gy[i - 1]).powi(2) + (gz[i] - gz[i - 1]).powi(2)).sqrt();
    }
    let total2 = arc2[arc2.len() - 1];
    let n2 = (total2 / h).floor() as usize + 1;
    let y = resample(&arc2, &gy, n2, h);
    let z = resample(&arc2, &gz, n2, h);
    let n = y.len();
    if n < 5 {
        return Err(file_err(path, "profile shorter than 5 fine steps"));
    }
    let mut angle = vec![0.0; n];
    let mut curvature = vec![0.0; n];
    for i in 0..n {
        let (a, b) = if i == 0 {
            (0, 2)
        } else if i == n - 1 {
            (n - 3, n - 1)
        } else {
            (i - 1, i + 1)
        };
        let c = if i == 0 {
            1
        } else if i == n - 1 {
            n - 2
        } else {
            i
        };
        let dy = (y[b] - y[a]) / (2.0 * h);
        let dz = (z[b] - z[a]) / (2.0 * h);
        let ddy = (y[b] - 2.0 * y[c] + y[a]) / (h * h);
        let ddz = (z[b] - 2.0 * z[c] + z[a]) / (h * h);
        angle[i] = dz.atan2(dy);
        let sp = (dy * dy + dz * dz).powf(1.5);
        curvature[i] = if sp > 0.0 {
            (dy * ddz - dz * ddy) / sp
        } else {
            0.0
        };
    }
    for (i, a) in angle.iter().enumerate() {
        if a.abs() > std::f64::consts::FRAC_PI_2 + 1e-9 {
            return Err(file_err(
                path,
                format!(
                    "after smoothing the curve turns back near y = {:.3} mm (not monotone in y)",
                    y[i]
                ),
            ));
        }
    }
    Ok(FineCurve {
        h,
        y,
        z,
        angle,
        curvature,
    })
}

/// Resamples a fine curve into a kernel table with capacity `N` (step `opts.ds`, or the smallest
/// step that fits). Values are converted with `T::from_f64`.
pub fn table_from_fine<T: wrc_kernel::Real, const N: usize>(
    fine: &FineCurve,
    kind: ProfileKind,
    opts: &SmoothOptions,
) -> Result<Box<ProfileTable<T, N>>, ProfileError> {
    let total = fine.h * (fine.y.len() - 1) as f64;
    let ds = match opts.ds {
        Some(ds) => ds,
        None => total / (N as f64 - 1.0),
    };
    if !ds.is_finite() || ds <= 0.0 {
        return Err(ProfileError::File {
            path: PathBuf::new(),
            cause: "table step ds must be positive".into(),
        });
    }
    let n = (total / ds).floor() as usize + 1;
    if n > N {
        return Err(ProfileError::File {
            path: PathBuf::new(),
            cause: format!(
                "profile of {total:.1} mm needs {n} nodes at ds = {ds} mm but the table holds {N}"
            ),
        });
    }
    let mut t = Box::new(ProfileTable::<T, N>::empty(kind));
    let lerp = |v: &[f64], s: f64| -> f64 {
        let x = s / fine.h;
        let i = (x.floor() as usize).min(v.len() - 2);
        let u = x - i as f64;
        v[i] + u * (v[i + 1] - v[i])
    };
    for i in 0..n {
        let s = ds * i as f64;
        let (y, z) = (lerp(&fine.y, s), lerp(&fine.z, s));
        let a = lerp(&fine.angle, s);
        let k = lerp(&fine.curvature, s);
        t.y[i] = T::from_f64(y);
        t.z[i] = T::from_f64(z);
        t.angle[i] = T::from_f64(a);
        t.curvature[i] = T::from_f64(k);
        let c = a.cos();
        t.dz_dy[i] = T::from_f64(if c > 1e-6 { a.tan() } else { 1e6 * a.signum() });
        t.d2z_dy2[i] = T::from_f64(if c > 1e-4 {
            k / (c * c * c)
        } else {
            1e12 * k.signum()
        });
    }
    t.len = n;
    t.ds = T::from_f64(ds);
    t.filter_wavelength = T::from_f64(opts.wavelength);
    t.validate().map_err(|e| ProfileError::File {
        path: PathBuf::new(),
        cause: format!("table failed validation: {e}"),
    })?;
    Ok(t)
}

/// Reads a file and builds a kernel table (full pipeline).
pub fn build_table<T: wrc_kernel::Real, const N: usize>(
    path: &Path,
    kind: Option<ProfileKind>,
    opts: &SmoothOptions,
) -> Result<Box<ProfileTable<T, N>>, ProfileError> {
    let raw = read_profile(path, kind)?;
    table_from_raw(raw, path, opts)
}

/// Builds a kernel table from a profile's text (full pipeline); `path` names it in errors and its
/// extension selects the format as in [`read_profile`].
pub fn build_table_from_text<T: wrc_kernel::Real, const N: usize>(
    text: &str,
    path: &Path,
    kind: Option<ProfileKind>,
    opts: &SmoothOptions,
) -> Result<Box<ProfileTable<T, N>>, ProfileError> {
    let raw = parse_profile(text, path, kind)?;
    table_from_raw(raw, path, opts)
}

fn table_from_raw<T: wrc_kernel::Real, const N: usize>(
    raw: RawProfile,
    path: &Path,
    opts: &SmoothOptions,
) -> Result<Box<ProfileTable<T, N>>, ProfileError> {
    let fine = preprocess(&raw, opts)?;
    table_from_fine(&fine, raw.kind, opts).map_err(|e| match e {
        ProfileError::File { cause, .. } => ProfileError::File {
            path: path.to_path_buf(),
            cause,
        },
        other => other,
    })
}

/// Table type of [`manchester_tables`]: 2048 nodes.
pub type ManchesterTable<T> = ProfileTable<T, 2048>;

/// (wheel, rail) tables of [`manchester_tables`].
pub type ManchesterPair<T> = (Box<ManchesterTable<T>>, Box<ManchesterTable<T>>);

/// The Manchester S1002 wheel profile, built into the binary (`data/profiles/MBench_S1002_v3.prw`).
pub const S1002_PRW: &str = include_str!("../../data/profiles/MBench_S1002_v3.prw");
/// The Manchester UIC60 rail profile, built into the binary (`data/profiles/MBench_UIC60_v3.prr`).
pub const UIC60_PRR: &str = include_str!("../../data/profiles/MBench_UIC60_v3.prr");
/// File name under which [`S1002_PRW`] is reported.
pub const S1002_NAME: &str = "MBench_S1002_v3.prw";
/// File name under which [`UIC60_PRR`] is reported.
pub const UIC60_NAME: &str = "MBench_UIC60_v3.prr";

/// The shipped Manchester profiles (the built-in [`S1002_PRW`] and [`UIC60_PRR`] of
/// `data/profiles/`), default preprocessing, capacity 2048 nodes at ds = 0.1 mm:
/// `(wheel S1002, rail UIC60 pre-canted 1:40)`.
pub fn manchester_tables<T: wrc_kernel::Real>(
    opts: &SmoothOptions,
) -> Result<ManchesterPair<T>, ProfileError> {
    let w = build_table_from_text::<T, 2048>(
        S1002_PRW,
        Path::new(S1002_NAME),
        Some(ProfileKind::Wheel),
        opts,
    )?;
    let r = build_table_from_text::<T, 2048>(
        UIC60_PRR,
        Path::new(UIC60_NAME),
        Some(ProfileKind::Rail),
        opts,
    )?;
    Ok((w, r))
}
