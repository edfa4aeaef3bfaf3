//! Command-line arguments (contract: docs/cli.md).

use clap::{Args, Parser, Subcommand, ValueEnum};
use serde::Serialize;
use std::path::PathBuf;

/// wrc — wheel–rail rolling contact in bounded time.
#[derive(Parser, Debug)]
#[command(name = "wrc", version, about, long_about = None)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// Subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Solve one contact case (elliptic or wheel/rail).
    #[command(allow_negative_numbers = true)]
    Solve(SolveArgs),
    /// The lateral-shift sweep of An et al. (2019): every shift with all six simplified models.
    #[command(allow_negative_numbers = true)]
    Sweep(SweepArgs),
    /// Build the contact table of one profile pair and side for the real-time step.
    #[command(allow_negative_numbers = true)]
    Table(TableArgs),
}

/// Normal-contact model.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Normal {
    /// STRIPES semi-Hertzian (kernel default for wheel/rail cases).
    Stripes,
    /// The strip model: STRIPES, then its strips' loads and half-lengths from the elastic
    /// half-space (`wrc_kernel::ritz`; wheel/rail cases, 0.1–1 s per patch).
    Strips,
    /// One Hertz ellipse (kernel default for elliptic cases).
    Hertz,
    /// Kalker's boundary-element NORM (host reference).
    Norm,
}

/// Flexibility adaptation.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Flex {
    /// Kalker's flexibilities of one Hertz ellipse.
    Hertz,
    /// Kik–Piotrowski equivalent ellipse.
    Kp,
    /// Linder's virtual ellipses.
    Linder,
    /// Ayasse–Chollet local ellipses (default for wheel/rail cases).
    Ac,
}

/// Tangential model.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Tangential {
    /// Kalker's simplified theory.
    Fastsim,
    /// FaStrip (default).
    Fastrip,
    /// Kalker's exact steady-rolling theory (host reference).
    Exact,
}

/// Floating-point width of the kernel call.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Precision {
    /// 64-bit.
    F64,
    /// 32-bit.
    F32,
}

/// Wheel side.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Side {
    /// Left wheel.
    Left,
    /// Right wheel.
    Right,
}

/// Parses "A,B" into two numbers.
fn pair(s: &str) -> Result<[f64; 2], String> {
    let mut it = s.split(',').map(|t| t.trim().parse::<f64>());
    match (it.next(), it.next(), it.next()) {
        (Some(Ok(a)), Some(Ok(b)), None) => Ok([a, b]),
        _ => Err(format!("expected two numbers A,B, got {s:?}")),
    }
}

/// Options common to every case.
#[derive(Args, Debug, Clone, Serialize)]
pub struct Common {
    /// Longitudinal creepage ξ (computed from the kinematics for wheel/rail cases unless given).
    #[arg(long, allow_hyphen_values = true)]
    pub xi: Option<f64>,
    /// Lateral creepage η.
    #[arg(long, allow_hyphen_values = true)]
    pub eta: Option<f64>,
    /// Spin creepage φ, 1/mm.
    #[arg(long, allow_hyphen_values = true)]
    pub phi: Option<f64>,
    /// Coefficient of friction.
    #[arg(long, default_value_t = 0.3)]
    pub mu: f64,
    /// Young's modulus of both bodies, MPa.
    #[arg(long = "e-mpa", default_value_t = 205_900.0)]
    pub e_mpa: f64,
    /// Poisson ratio of both bodies.
    #[arg(long, default_value_t = 0.28)]
    pub nu: f64,
    /// Rolling speed, m/s (default 200 km/h).
    #[arg(long, default_value_t = 200.0 / 3.6)]
    pub speed: f64,
    /// Normal model (default: hertz for elliptic cases, stripes for wheel/rail cases).
    #[arg(long, value_enum)]
    pub normal: Option<Normal>,
    /// Flexibility adaptation (default: hertz for elliptic cases, ac for wheel/rail cases).
    #[arg(long, value_enum)]
    pub flex: Option<Flex>,
    /// Tangential model.
    #[arg(long, value_enum, default_value = "fastrip")]
    pub tangential: Tangential,
    /// Strips per contact region.
    #[arg(long, default_value_t = 32)]
    pub strips: usize,
    /// Cells per strip.
    #[arg(long, default_value_t = 32)]
    pub cells: usize,
    /// Precision of the kernel call.
    #[arg(long, value_enum, default_value = "f64")]
    pub precision: Precision,
}

/// Wheel/rail case options.
#[derive(Args, Debug, Clone, Serialize)]
pub struct WheelRail {
    /// Wheel profile (.prw or two-column file "y z"; default: built-in S1002). Two-column files in
    /// CONTACT's canonical orientation: mm, y positive towards the field side, z positive downwards
    /// (the increase of the rolling radius), so the flange tip is the largest z, at negative y.
    #[arg(long)]
    pub wheel: Option<PathBuf>,
    /// Rail profile (.prr or two-column file "y z"; default: built-in UIC60). Two-column files in
    /// CONTACT's canonical orientation: mm, y positive towards the field side (gauge face at
    /// negative y), z positive downwards, so the rail top is the smallest z.
    #[arg(long)]
    pub rail: Option<PathBuf>,
    /// Lateral wheelset shift, mm, positive towards the analysed wheel (its flange approaches the
    /// gauge face; An et al. 2019).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub dy: f64,
    /// Yaw angle, mrad, in the same sense as --dy (CONTACT's yaw for the right wheel, mirrored for
    /// the left).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub yaw: f64,
    /// Roll angle about the forward track axis, mrad (positive raises the left wheel).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub roll: f64,
    /// Vertical load on this wheel, N.
    #[arg(long, default_value_t = 83_300.0)]
    pub fz: f64,
    /// Which wheel.
    #[arg(long, value_enum, default_value = "right")]
    pub side: Side,
    /// Track gauge, mm.
    #[arg(long, default_value_t = 1435.0)]
    pub gauge: f64,
    /// Depth below the rail top at which the gauge is measured, mm.
    #[arg(long = "gauge-depth", default_value_t = 14.0)]
    pub gauge_depth: f64,
    /// Back-to-back distance of the wheels, mm (default 1360 for `solve`, 1353 for `sweep`).
    #[arg(long = "back-to-back")]
    pub back_to_back: Option<f64>,
    /// Extra rail inclination, rad (the profile's own inclination is used as given).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub cant: f64,
    /// Nominal rolling radius, mm.
    #[arg(long, default_value_t = 460.0)]
    pub r0: f64,
}

/// `wrc solve`.
#[derive(Args, Debug, Clone)]
pub struct SolveArgs {
    /// Elliptic case: semi-axes A_MM,B_MM along x and y.
    #[arg(long, value_parser = pair, conflicts_with_all = ["curvatures", "wheel"])]
    pub ellipse: Option<[f64; 2]>,
    /// Elliptic case: gap curvatures A_PER_MM,B_PER_MM along x and y.
    #[arg(long, value_parser = pair, conflicts_with = "wheel")]
    pub curvatures: Option<[f64; 2]>,
    /// Normal force, N (elliptic case).
    #[arg(long = "fn")]
    pub fn_n: Option<f64>,
    /// Approach, mm (elliptic case, instead of --fn).
    #[arg(long, conflicts_with = "fn_n")]
    pub approach: Option<f64>,
    /// Wheel/rail case data.
    #[command(flatten)]
    pub wr: WheelRail,
    /// Model and material options.
    #[command(flatten)]
    pub common: Common,
    /// Print one JSON document instead of the table.
    #[arg(long)]
    pub json: bool,
    /// Write SVG plots (pressure, traction with stick/slip, slip velocity, wear, the strip through
    /// y = 0, the strips) into this directory.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Also run the exact reference of the case (`--tangential exact --normal norm`; seconds on a
    /// wheel/rail case) and draw it beside the model in y0.svg and strips.svg (needs --plot).
    #[arg(long = "plot-reference")]
    pub plot_reference: bool,
    /// Run the fixed-cost real-time step on this contact table (built by `wrc table`) instead of
    /// the converged solver; the options the table fixes must agree with it or be omitted.
    #[arg(long, conflicts_with_all = ["ellipse", "curvatures"])]
    pub table: Option<PathBuf>,
    /// The long names of the options given on the command line (filled in by `main`).
    #[arg(skip)]
    pub given: Vec<String>,
}

impl SolveArgs {
    /// Whether this is an elliptic case (`--ellipse` or `--curvatures`).
    pub fn elliptic(&self) -> bool {
        self.ellipse.is_some() || self.curvatures.is_some()
    }

    /// The normal model used: `--normal`, else hertz for elliptic cases, norm for a wheel/rail
    /// case with `--tangential exact`, stripes on the real-time path (`--table`: the tables hold
    /// STRIPES strips), the strip model for the other wheel/rail cases.
    pub fn normal(&self) -> Normal {
        self.common.normal.unwrap_or(if self.elliptic() {
            Normal::Hertz
        } else if self.common.tangential == Tangential::Exact {
            Normal::Norm
        } else if self.table.is_some() {
            Normal::Stripes
        } else {
            Normal::Strips
        })
    }
}

/// `wrc sweep`.
#[derive(Args, Debug, Clone)]
pub struct SweepArgs {
    /// Wheel/rail data (defaults: the shared S1002/UIC60 profiles, 83.3 kN, back-to-back 1353 mm).
    #[command(flatten)]
    pub wr: WheelRail,
    /// First lateral shift, mm.
    #[arg(long = "dy-from", default_value_t = -3.0, allow_hyphen_values = true)]
    pub dy_from: f64,
    /// Last lateral shift, mm.
    #[arg(long = "dy-to", default_value_t = 6.0, allow_hyphen_values = true)]
    pub dy_to: f64,
    /// Shift step, mm.
    #[arg(long = "dy-step", default_value_t = 1.0)]
    pub dy_step: f64,
    /// Material and grid options.
    #[command(flatten)]
    pub common: Common,
    /// Print one JSON document (an array of solve documents per model).
    #[arg(long)]
    pub json: bool,
    /// Write the table as CSV.
    #[arg(long)]
    pub csv: Option<PathBuf>,
    /// Write SVG plots into this directory.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Run the fixed-cost real-time step on this contact table (built by `wrc table`) at every
    /// shift instead of the six converged models; the options the table fixes must agree with it
    /// or be omitted (as for `wrc solve --table`).
    #[arg(long)]
    pub table: Option<PathBuf>,
    /// With --table: also run the converged solver's FaStrip-AC (the default pipeline) at every
    /// shift on the table's track set-up, beside the real-time step in the table, CSV, JSON and
    /// plots.
    #[arg(long, requires = "table")]
    pub compare: bool,
    /// The long names of the options given on the command line (filled in by `main`).
    #[arg(skip)]
    pub given: Vec<String>,
}

/// `wrc table`.
#[derive(Args, Debug, Clone)]
pub struct TableArgs {
    /// Profiles and track set-up (the shift, yaw, roll and load options are not used: the table
    /// spans them).
    #[command(flatten)]
    pub wr: WheelRail,
    /// Lowest lateral shift, mm, towards the analysed wheel (as `solve --dy`; default: the
    /// other wheel's flange contact, found from the profiles, and 2 mm more).
    #[arg(long = "dy-from", allow_hyphen_values = true)]
    pub dy_from: Option<f64>,
    /// Highest lateral shift, mm (default: this wheel's flange contact and 2 mm more).
    #[arg(long = "dy-to", allow_hyphen_values = true)]
    pub dy_to: Option<f64>,
    /// Shift step between the coarse table nodes, mm (refined by --refine-tol).
    #[arg(long = "dy-step", default_value_t = 0.5)]
    pub dy_step: f64,
    /// Refinement tolerance of the shift grid: an interval is bisected while its midpoint's
    /// pmax, area (relative), load share (absolute) or the creep force its frame gives
    /// (relative to μF, μ = 0.3) differs from the interpolation by more than this (0: the
    /// coarse grid only).
    #[arg(long = "refine-tol", default_value_t = 0.01)]
    pub refine_tol: f64,
    /// Most shift nodes after refinement (the coarse nodes are always kept).
    #[arg(long = "max-dy-nodes", default_value_t = 176)]
    pub max_dy_nodes: usize,
    /// Lowest vertical load of the table, N.
    #[arg(long = "fz-min", default_value_t = 15_000.0)]
    pub fz_min: f64,
    /// Highest vertical load of the table, N.
    #[arg(long = "fz-max", default_value_t = 260_000.0)]
    pub fz_max: f64,
    /// Load nodes, log-spaced between --fz-min and --fz-max.
    #[arg(long, default_value_t = 5)]
    pub loads: usize,
    /// Build every shift at the two-wheel equilibrium roll of the wheelset (as a free wheelset
    /// takes it) instead of roll 0 (as `wrc solve` without `--roll`).
    #[arg(long = "equilibrium-roll")]
    pub equilibrium_roll: bool,
    /// Young's modulus of wheel and rail, MPa.
    #[arg(long = "e-mpa", default_value_t = 205_900.0)]
    pub e_mpa: f64,
    /// Poisson ratio of wheel and rail.
    #[arg(long, default_value_t = 0.28)]
    pub nu: f64,
    /// Precision of the table's values.
    #[arg(long, value_enum, default_value = "f64")]
    pub precision: Precision,
    /// The table file to write.
    #[arg(long)]
    pub out: PathBuf,
    /// The long names of the options given on the command line (filled in by `main`).
    #[arg(skip)]
    pub given: Vec<String>,
}
