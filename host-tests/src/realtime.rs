//! The contact tables of the real-time examples and tests (`wrc_kernel::table`) and the accuracy
//! sweep of the real-time step against the converged per-wheel solver it was built from.
//!
//! Tables: built-in S1002/UIC60, either wheel, back-to-back 1353 or 1360 mm, the converged solver
//! at μ 0.3 and 100 km/h (zero creepage, so the table does not depend on them), on the host with
//! heap scratch. The shift range covers both flanges with margin ([`Case::dy_range`]).

use wrc_kernel::geometry::{
    equilibrium_roll, Kinematics, Side, TrackSetup, WheelRail, WheelsetPose,
};
use wrc_kernel::step::{step, step_from, StepInput, StepResult};
use wrc_kernel::table::{
    build_table, BuildReport, ContactTable, TableSlot, TableSpec, ROW_BUFFERS,
};
use wrc_kernel::wheel::{resolve_patch_strips, solve_wheel, DefaultWheelWorkspace, WheelConfig};
use wrc_kernel::{Error, Material, Real};

use crate::profiles::{manchester_tables, SmoothOptions};

/// Refinement tolerance of the examples' shift grid ([`TableSpec::refine_tol`]).
pub const REFINE_TOL: f64 = 0.01;
/// Coarse shift step of the examples' grid, mm (refined by bisection where needed).
pub const DY_STEP: f64 = 0.5;
/// Most shift nodes of the examples' grid ([`TableSpec::max_dy_nodes`]): the f32 table of one
/// slot × 16 strips × 5 loads stays within 256 KiB.
pub const MAX_DY_NODES: usize = 176;
/// Nominal rolling radius of the cases, mm.
pub const R0: f64 = 460.0;
/// Forward speed of the cases, mm/s (100 km/h).
pub const SPEED: f64 = 100.0 / 3.6 * 1000.0;

/// One configuration of the sweep: a wheel of a wheelset on the built-in S1002/UIC60 pair.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Case {
    /// Back-to-back distance, mm.
    pub back_to_back: f64,
    /// Analysed wheel.
    pub side: Side,
}

/// The four configurations of the accuracy sweep: 1353 and 1360 mm, right and left wheel.
pub const CASES: [Case; 4] = [
    Case {
        back_to_back: 1353.0,
        side: Side::Right,
    },
    Case {
        back_to_back: 1353.0,
        side: Side::Left,
    },
    Case {
        back_to_back: 1360.0,
        side: Side::Right,
    },
    Case {
        back_to_back: 1360.0,
        side: Side::Left,
    },
];

impl Case {
    /// Track set-up: the Manchester/CONTACT standard with this back-to-back distance.
    pub fn setup<T: Real>(&self) -> TrackSetup<T> {
        TrackSetup {
            back_to_back: T::from_f64(self.back_to_back),
            ..TrackSetup::standard()
        }
    }

    /// Shift of the flange contact (largest contact angle, ≈ 1.2 rad, of the free wheelset at
    /// its equilibrium roll), |dy| mm: 9.8 with 1353 mm, 6.3 with 1360 mm (S1002/UIC60, gauge
    /// 1435 mm).
    pub fn flange_dy(&self) -> f64 {
        9.8 - (self.back_to_back - 1353.0) / 2.0
    }

    /// The table's shift range (kernel dy, mm, +left): both flanges with 1.5 mm margin (the
    /// states go 0.5 mm beyond the flange contact; a roll of −5 mrad there maps up to ~1 mm
    /// deeper, [`wrc_kernel::step`]).
    pub fn dy_range(&self) -> (f64, f64) {
        let edge = self.flange_dy() + 2.0;
        (-edge, edge)
    }

    /// Short label, e.g. `1353 R`.
    pub fn label(&self) -> String {
        format!(
            "{} {}",
            self.back_to_back,
            match self.side {
                Side::Right => "R",
                Side::Left => "L",
            }
        )
    }

    /// The examples' grid for this case: equilibrium roll, [`Case::dy_range`], coarse nodes every
    /// [`DY_STEP`] refined to [`REFINE_TOL`] with at most [`MAX_DY_NODES`] shift nodes × F
    /// 15 … 260 kN in 5 log-spaced loads, placement grid 0.05 mm.
    pub fn spec<T: Real>(&self) -> TableSpec<T> {
        let (lo, hi) = self.dy_range();
        TableSpec {
            dy_min: T::from_f64(lo),
            dy_max: T::from_f64(hi),
            n_dy: ((hi - lo) / DY_STEP).round() as usize + 1,
            f_min: T::from_f64(15_000.0),
            f_max: T::from_f64(260_000.0),
            n_load: 5,
            grid_step: T::from_f64(0.05),
            equilibrium_roll: true,
            refine_tol: T::from_f64(REFINE_TOL),
            max_dy_nodes: MAX_DY_NODES,
        }
    }

    /// This case's table on `spec` with `K` slots × `ST` strips: its bytes and the build report.
    ///
    /// Errors: those of the profiles' tables (as `Error::BadProfile`) and of [`build_table`].
    pub fn table<T: Real, const K: usize, const ST: usize>(
        &self,
        spec: &TableSpec<T>,
    ) -> Result<(Vec<u8>, BuildReport), Error> {
        self.table_of::<T, K, ST>(spec, &Material::steel())
    }

    /// [`Case::table`] for the material `mat` (e.g. CONTACT's in the Manchester runs).
    ///
    /// Errors: as [`Case::table`].
    pub fn table_of<T: Real, const K: usize, const ST: usize>(
        &self,
        spec: &TableSpec<T>,
        mat: &Material<T>,
    ) -> Result<(Vec<u8>, BuildReport), Error> {
        let (w, r) = manchester_tables::<T>(&SmoothOptions::default())
            .map_err(|_| Error::BadProfile("built-in S1002/UIC60 tables"))?;
        let mut out = vec![0u8; spec.capacity_bytes(K, ST)];
        let mut rows = vec![TableSlot::<T, ST>::EMPTY; ROW_BUFFERS * K * spec.n_load];
        let mut ws = Box::new(DefaultWheelWorkspace::<T>::new());
        let cfg = WheelConfig::recommended(T::from_f64(0.3), T::from_f64(SPEED), T::from_f64(R0));
        let rep = build_table::<T, 2048, 2048, K, ST, 4, 128, 256, 4, 32, 32, 128>(
            &r,
            &w,
            &self.setup(),
            self.side,
            mat,
            &cfg,
            spec,
            &mut rows,
            &mut ws,
            &mut out,
        )?;
        out.truncate(rep.bytes);
        Ok((out, rep))
    }
}

/// The examples' standard case: 1353 mm, right wheel.
pub const STANDARD: Case = CASES[0];

/// The examples' grid ([`Case::spec`] of [`STANDARD`]: dy −10.8 … 10.8 mm).
pub fn standard_spec<T: Real>() -> TableSpec<T> {
    STANDARD.spec()
}

/// The S1002/UIC60 1353 mm right-wheel table on `spec` with `K` slots × `ST` strips: its bytes
/// and the build report.
///
/// Errors: those of the profiles' tables (as `Error::BadProfile`) and of [`build_table`].
pub fn s1002_uic60_table<T: Real, const K: usize, const ST: usize>(
    spec: &TableSpec<T>,
) -> Result<(Vec<u8>, BuildReport), Error> {
    STANDARD.table::<T, K, ST>(spec)
}

/// One state of the sweep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct State {
    /// Pose (kernel convention), roll = equilibrium roll + `roll_offset`.
    pub pose: WheelsetPose<f64>,
    /// Roll relative to the free wheelset's equilibrium roll at this shift and yaw 0, rad.
    pub roll_offset: f64,
    /// Vertical wheel load F_z, N.
    pub fz: f64,
    /// Coefficient of friction.
    pub mu: f64,
    /// Kinematics (nominal rolling at [`SPEED`], R0 [`R0`], plus lateral velocity and yaw rate).
    pub kinematics: Kinematics<f64>,
}

/// Ranges of the sweep's states.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StateRanges {
    /// Shift, mm (kernel dy).
    pub dy: (f64, f64),
    /// Yaw amplitude, rad (uniform in ±).
    pub yaw: f64,
    /// Roll amplitude about the equilibrium roll, rad (uniform in ±).
    pub roll: f64,
    /// Vertical load, N.
    pub fz: (f64, f64),
    /// Friction coefficient.
    pub mu: (f64, f64),
    /// Lateral velocity amplitude, mm/s (uniform in ±).
    pub lateral_velocity: f64,
    /// Yaw rate amplitude, rad/s (uniform in ±).
    pub yaw_rate: f64,
}

impl StateRanges {
    /// Issue 14's ranges for `case`: the shift from flange to flange, 0.5 mm beyond each flange
    /// contact, yaw ±10 mrad, roll ±5 mrad about the equilibrium roll, F_z 20–150 kN, μ 0.1–0.5,
    /// lateral velocity ±100 mm/s, yaw rate ±0.02 rad/s (the benches' ranges).
    pub fn issue14(case: &Case) -> Self {
        let edge = case.flange_dy() + 0.5;
        StateRanges {
            dy: (-edge, edge),
            yaw: 0.01,
            roll: 0.005,
            fz: (20_000.0, 150_000.0),
            mu: (0.1, 0.5),
            lateral_velocity: 100.0,
            yaw_rate: 0.02,
        }
    }
}

/// `n` deterministic quasi-random states of `case` (golden-ratio sequences from `offset`).
///
/// Errors: those of [`equilibrium_roll`].
pub fn states(case: &Case, r: &StateRanges, n: usize, offset: usize) -> Result<Vec<State>, Error> {
    let (w, rail) = manchester_tables::<f64>(&SmoothOptions::default())
        .map_err(|_| Error::BadProfile("built-in S1002/UIC60 tables"))?;
    let setup = case.setup::<f64>();
    let mut out = Vec::with_capacity(n);
    for k in 0..n {
        let q = (k + offset) as f64;
        let f = |a: f64, b: f64| (q * a + b).fract();
        let sym = |a: f64, b: f64| 2.0 * f(a, b) - 1.0;
        let dy = r.dy.0 + (r.dy.1 - r.dy.0) * f(0.618_033_988_75, 0.1);
        let eq = equilibrium_roll::<f64, 2048, 2048>(&rail, &w, &setup, dy, 0.0, 0.05)?.roll;
        let roll_offset = r.roll * sym(0.453_397_651_5, 0.7);
        out.push(State {
            pose: WheelsetPose {
                dy,
                yaw: r.yaw * sym(0.569_840_290_998, 0.5),
                roll: eq + roll_offset,
            },
            roll_offset,
            fz: r.fz.0 + (r.fz.1 - r.fz.0) * f(0.754_877_666_2, 0.3),
            mu: r.mu.0 + (r.mu.1 - r.mu.0) * f(0.324_717_957_2, 0.6),
            kinematics: Kinematics {
                lateral_velocity: r.lateral_velocity * sym(0.380_364_3, 0.2),
                yaw_rate: r.yaw_rate * sym(0.267_949_192_4, 0.9),
                ..Kinematics::nominal(SPEED, R0)
            },
        });
    }
    Ok(out)
}

/// The step's errors against the converged solver at one state.
#[derive(Clone, Debug, PartialEq)]
pub struct Errors {
    /// |ΔF|/(μF_z), F = (ΣF_x, ΣF_y) over the patches.
    pub force: f64,
    /// |ΔN|/F_z, N = ΣN_k.
    pub normal: f64,
    /// |Δpmax|/pmax, pmax the largest over the patches.
    pub pmax: f64,
    /// |Δarea|/area, area the sum over the patches.
    pub area: f64,
    /// |ΔF|/(μF_z) of the closed-form strip forces on the converged solver's own strips and
    /// creepages against its cell FaStrip: the part of `force` that is not the table's.
    pub closed_form: f64,
    /// |ΔF|/(μF_z) of the step against the closed form on the converged solver's strips: the
    /// table's part (interpolation, roll mapping, yaw) and the vertical balance's.
    pub table_force: f64,
    /// |ΔF|/(μF_z) of the step's settled result: [`step_from`] repeated [`SETTLE`] times from the
    /// cold step at the same state, the time loop's result at a state it stays in (the coupling at
    /// its fixed point instead of the cold step's two rounds).
    pub settled_force: f64,
    /// |ΔN|/F_z of the settled result.
    pub settled_normal: f64,
    /// Contact angle of the converged solver's most loaded patch, rad (tread ≲ 0.2, flange ≳ 1).
    pub angle: f64,
    /// The state and both results, for the report.
    pub label: String,
}

/// Time-loop steps ([`step_from`]) after the cold step for [`Errors::settled_force`]: 6 coupling
/// rounds in all (8 move the flange forces by at most 1 % of μF_z more, the tread's not at all).
pub const SETTLE: usize = 4;

/// Runs the step (capacities `K`, `ST`) on `table` at every state and the converged solver
/// (`solve_wheel`, the table's configuration with the state's kinematics and μ) at the same
/// pose; a state where the step fails gives `Err` in its place (with the state's label).
pub fn compare<const K: usize, const ST: usize>(
    table: &[u8],
    case: &Case,
    states: &[State],
) -> Vec<Result<Errors, String>> {
    let (w, rail) = manchester_tables::<f64>(&SmoothOptions::default()).expect("profiles");
    let t = ContactTable::<f64>::from_bytes(table).expect("valid table");
    let setup = case.setup::<f64>();
    let mat = Material::<f64>::steel();
    let mut ws = Box::new(DefaultWheelWorkspace::<f64>::new());
    let mut out = Vec::with_capacity(states.len());
    for s in states {
        let label = format!(
            "{} dy {:+.3} yaw {:+.2} mrad roll {:+.2}{:+.2} mrad Fz {:.0} mu {:.2} vy {:+.0} r {:+.4}",
            case.label(),
            s.pose.dy,
            s.pose.yaw * 1e3,
            (s.pose.roll - s.roll_offset) * 1e3,
            s.roll_offset * 1e3,
            s.fz,
            s.mu,
            s.kinematics.lateral_velocity,
            s.kinematics.yaw_rate
        );
        let input = StepInput {
            pose: s.pose,
            fz: s.fz,
            kinematics: s.kinematics,
            mu: s.mu,
        };
        let rt: StepResult<f64, K> = match step::<f64, K, ST>(&t, &input) {
            Ok(r) => r,
            Err(e) => {
                out.push(Err(format!("{label}: step {e}")));
                continue;
            }
        };
        let mut settled = rt;
        let mut settle_err = None;
        for _ in 0..SETTLE {
            match step_from::<f64, K, ST>(&t, &input, &settled) {
                Ok(r) => settled = r,
                Err(e) => settle_err = Some(e),
            }
        }
        if let Some(e) = settle_err {
            out.push(Err(format!("{label}: step_from {e}")));
            continue;
        }
        let mut cfg = WheelConfig::recommended(s.mu, SPEED, R0);
        cfg.kinematics = s.kinematics;
        let geom = match WheelRail::<f64, 2048, 2048>::place(
            &rail, &w, &setup, &s.pose, case.side, 0.05,
        ) {
            Ok(g) => g,
            Err(e) => {
                out.push(Err(format!("{label}: placement {e}")));
                continue;
            }
        };
        let refr = match solve_wheel(&geom, s.fz, &mat, &cfg, &mut ws, &mut ()) {
            Ok(r) => r,
            Err(e) => {
                out.push(Err(format!("{label}: converged solver {e}")));
                continue;
            }
        };
        let (mut fx, mut fy, mut n, mut pm, mut ar) = (0.0, 0.0, 0.0, 0.0f64, 0.0);
        let (mut cx, mut cy) = (0.0, 0.0);
        let (mut angle, mut most) = (0.0, 0.0);
        for (q, p) in refr.patches.iter().enumerate() {
            fx += p.result.totals.fx;
            fy += p.result.totals.fy;
            n += p.load;
            pm = pm.max(p.result.pmax);
            ar += p.result.area;
            if p.load > most {
                most = p.load;
                angle = p.frame.angle;
            }
            // the closed form on the solver's own strips and creepages
            let mut c = cfg;
            c.creepage = Some(p.creepage);
            if resolve_patch_strips(&mut ws, q, p.load, &mat, &c).is_ok() {
                let (a, b) = closed_form_on(&ws.pipeline.set, &p.creepage, s.mu, &mat);
                cx += a;
                cy += b;
            }
        }
        let (mut gx, mut gy, mut gn, mut gp, mut ga) = (0.0, 0.0, 0.0, 0.0f64, 0.0);
        for sl in &rt.slots {
            gx += sl.fx;
            gy += sl.fy;
            gn += sl.load;
            gp = gp.max(sl.pmax);
            ga += sl.area;
        }
        let (mut hx, mut hy, mut hn) = (0.0, 0.0, 0.0);
        for sl in &settled.slots {
            hx += sl.fx;
            hy += sl.fy;
            hn += sl.load;
        }
        let muf = s.mu * s.fz;
        out.push(Ok(Errors {
            force: (gx - fx).hypot(gy - fy) / muf,
            normal: (gn - n).abs() / s.fz,
            pmax: (gp - pm).abs() / pm,
            area: (ga - ar).abs() / ar,
            closed_form: (cx - fx).hypot(cy - fy) / muf,
            table_force: (gx - cx).hypot(gy - cy) / muf,
            settled_force: (hx - fx).hypot(hy - fy) / muf,
            settled_normal: (hn - n).abs() / s.fz,
            angle,
            label: format!(
                "{label}: reference converged {} in {} rounds; F ({fx:.0}, {fy:.0}) step ({gx:.0}, {gy:.0}) closed form ({cx:.0}, {cy:.0}); \
                 N {n:.0} step {gn:.0}; pmax {pm:.0} step {gp:.0}; area {ar:.1} step {ga:.1}",
                refr.converged,
                refr.coupling_rounds
            ),
        }));
    }
    out
}

/// Strip `j` of a STRIPES strip set as the real-time step builds it (Kalker's C_ij at the local
/// ellipse ratio n_j/m_j, floored at 1e-3): `None` for a strip without contact.
pub fn step_strip<const S: usize, const NR: usize>(
    set: &wrc_kernel::stripes::StripSet<f64, S, NR>,
    j: usize,
    nu: f64,
) -> Option<Result<wrc_kernel::patch::Strip<f64>, wrc_kernel::Error>> {
    if !(set.a[j] > 0.0 && set.pmax[j] > 0.0) {
        return None;
    }
    let g = set.n_over_m[j].max(1e-3);
    Some(
        wrc_kernel::kalker::coefficients(1.0 / g, nu).map(|kc| wrc_kernel::patch::Strip {
            y: set.y[j],
            dy: set.dy[j],
            a: set.a[j],
            xc: set.xc[j],
            p_hat: set.pmax[j],
            c11: kc.c11,
            c22: kc.c22,
            c23: kc.c23,
            c33: kc.c33,
            sqrt_b_over_a: g.sqrt(),
            ..wrc_kernel::patch::Strip::default()
        }),
    )
}

/// ΣF_x, ΣF_y of the closed-form strip forces (`fastrip::strip_forces`) on a STRIPES strip set
/// at creepage `cr` and friction `mu`, the strips as the step builds them ([`step_strip`]).
fn closed_form_on<const S: usize, const NR: usize>(
    set: &wrc_kernel::stripes::StripSet<f64, S, NR>,
    cr: &wrc_kernel::patch::Creepage<f64>,
    mu: f64,
    mat: &Material<f64>,
) -> (f64, f64) {
    let (mut fx, mut fy) = (0.0, 0.0);
    for j in 0..set.n_strips.min(S) {
        let Some(Ok(st)) = step_strip(set, j, mat.nu) else {
            continue;
        };
        if let Ok((a, b, _)) = wrc_kernel::fastrip::strip_forces(&st, cr, mu, mat.g, mat.nu) {
            fx += a;
            fy += b;
        }
    }
    (fx, fy)
}

/// Median, P95 and maximum of `v` (sorted in place); zeros for an empty `v`.
pub fn stats(v: &mut [f64]) -> (f64, f64, f64) {
    if v.is_empty() {
        return (0.0, 0.0, 0.0);
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    (v[n / 2], v[(n * 95 / 100).min(n - 1)], v[n - 1])
}
