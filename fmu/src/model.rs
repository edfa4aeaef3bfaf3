//! The FMU's model: its variables (the one table that `modelDescription.xml`, `fmi2GetReal`/
//! `fmi2SetReal` and the value references all come from), the state of one instance and its
//! evaluation through the kernel's real-time step. Safe Rust only; the C boundary is in
//! [`crate::fmi`].

use wrc_kernel::geometry::{Kinematics, Side, WheelsetPose};
use wrc_kernel::step::{step, StepInput, StepResult};
use wrc_kernel::table::ContactTable;
use wrc_kernel::Error;

/// Slot capacity of the step (the packaged table stores the 1 slot S1002/UIC60 uses; tables of up
/// to 3 run); also the number of per-slot output groups `slot1_*` … `slot3_*`.
pub const SLOTS: usize = 3;
/// Strip capacity of the step (the packaged table has 16 strips per slot).
pub const STRIP_CAP: usize = 16;

/// Default forward speed, mm/s (200 km/h).
pub const DEFAULT_SPEED: f64 = 55_555.6;
/// Default vertical wheel load, N.
pub const DEFAULT_FZ: f64 = 83_300.0;
/// Default coefficient of friction.
pub const DEFAULT_MU: f64 = 0.3;
/// Default nominal rolling radius, mm.
pub const DEFAULT_R0: f64 = 460.0;

/// FMI base type of a variable.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BaseType {
    /// `fmi2Real` (f64).
    Real,
    /// `fmi2Integer` (i32).
    Integer,
}

/// FMI causality.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Causality {
    /// Set by the environment before or between steps.
    Input,
    /// A parameter.
    Parameter,
    /// Computed by the FMU.
    Output,
}

/// FMI variability.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Variability {
    /// Changes at any time (real inputs and outputs).
    Continuous,
    /// Changes only at communication points (integer outputs).
    Discrete,
    /// Set before initialisation ends, fixed afterwards.
    Fixed,
    /// May be changed between steps.
    Tunable,
}

/// Inputs, in [`Instance::inputs`] order.
pub const INPUTS: [(&str, &str, f64, &str); 7] = [
    (
        "dy",
        "mm",
        0.0,
        "lateral shift of the wheelset towards the analysed wheel",
    ),
    (
        "yaw",
        "rad",
        0.0,
        "yaw angle, positive with a shift towards the analysed wheel (wrc solve --yaw)",
    ),
    (
        "roll",
        "rad",
        0.0,
        "roll angle in the track frame, positive raises the left wheel",
    ),
    ("fz", "N", DEFAULT_FZ, "vertical wheel load (> 0)"),
    (
        "speed",
        "mm/s",
        DEFAULT_SPEED,
        "forward speed of the wheelset centre (> 0)",
    ),
    (
        "lateral_velocity",
        "mm/s",
        0.0,
        "lateral velocity of the wheelset centre, d(dy)/dt (towards the analysed wheel)",
    ),
    (
        "yaw_rate",
        "rad/s",
        0.0,
        "yaw rate, d(yaw)/dt in the sign of yaw",
    ),
];

/// Parameters, in [`Instance::params`] order: (name, unit, start, variability, description).
pub const PARAMS: [(&str, &str, f64, Variability, &str); 2] = [
    (
        "mu",
        "1",
        DEFAULT_MU,
        Variability::Tunable,
        "coefficient of friction (> 0)",
    ),
    (
        "r0",
        "mm",
        DEFAULT_R0,
        Variability::Fixed,
        "nominal rolling radius: pitch rate = speed / r0",
    ),
];

/// Totals, in [`Outputs::totals`] order.
pub const TOTALS: [(&str, &str, &str); 5] = [
    (
        "fx",
        "N",
        "longitudinal creep force on the wheel, summed over the patches (patch frames)",
    ),
    (
        "fy",
        "N",
        "lateral creep force on the wheel, summed over the patches (patch frames)",
    ),
    (
        "mz",
        "N.mm",
        "spin moment, summed over the patches (each about its reference point)",
    ),
    ("fn", "N", "total normal load, summed over the patches"),
    ("dy_used", "mm", "the input dy the last evaluation used"),
];

/// Per-slot outputs `slot<k>_<name>`, in [`Outputs::slots`] order.
pub const SLOT_OUTPUTS: [(&str, &str, &str); 7] = [
    (
        "fn",
        "N",
        "normal load of the patch (0: no patch in this slot)",
    ),
    ("fx", "N", "longitudinal creep force (patch frame)"),
    ("fy", "N", "lateral creep force (patch frame)"),
    ("mz", "N.mm", "spin moment about the reference point"),
    ("angle", "rad", "contact angle"),
    ("pmax", "MPa", "peak pressure"),
    ("area", "mm2", "contact area"),
];

/// What a variable reads or writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// [`Instance::inputs`]`[i]`.
    Input(usize),
    /// [`Instance::params`]`[i]`.
    Param(usize),
    /// [`Outputs::totals`]`[i]`.
    Total(usize),
    /// [`Outputs::slots`]`[slot][field]`.
    Slot(usize, usize),
    /// [`Outputs::n_patches`].
    NPatches,
    /// [`Outputs::status`].
    Status,
}

/// One model variable. Its value reference is its index in [`variables`].
#[derive(Clone, Debug, PartialEq)]
pub struct Variable {
    /// Name.
    pub name: String,
    /// Base type.
    pub base: BaseType,
    /// Causality.
    pub causality: Causality,
    /// Variability.
    pub variability: Variability,
    /// Unit (real variables).
    pub unit: &'static str,
    /// Start value (inputs and parameters).
    pub start: Option<f64>,
    /// Description.
    pub description: String,
    /// What it reads or writes.
    pub quantity: Quantity,
}

/// The model's variables; the value reference of `variables()[i]` is `i`.
pub fn variables() -> Vec<Variable> {
    let mut v = Vec::new();
    let real =
        |name: String, causality, variability, unit, start, description: String, q| Variable {
            name,
            base: BaseType::Real,
            causality,
            variability,
            unit,
            start,
            description,
            quantity: q,
        };
    for (i, (name, unit, start, d)) in INPUTS.iter().enumerate() {
        v.push(real(
            name.to_string(),
            Causality::Input,
            Variability::Continuous,
            unit,
            Some(*start),
            d.to_string(),
            Quantity::Input(i),
        ));
    }
    for (i, (name, unit, start, var, d)) in PARAMS.iter().enumerate() {
        v.push(real(
            name.to_string(),
            Causality::Parameter,
            *var,
            unit,
            Some(*start),
            d.to_string(),
            Quantity::Param(i),
        ));
    }
    for (i, (name, unit, d)) in TOTALS.iter().enumerate() {
        v.push(real(
            name.to_string(),
            Causality::Output,
            Variability::Continuous,
            unit,
            None,
            d.to_string(),
            Quantity::Total(i),
        ));
    }
    for k in 0..SLOTS {
        for (i, (name, unit, d)) in SLOT_OUTPUTS.iter().enumerate() {
            v.push(real(
                format!("slot{}_{name}", k + 1),
                Causality::Output,
                Variability::Continuous,
                unit,
                None,
                format!("slot {}: {d}", k + 1),
                Quantity::Slot(k, i),
            ));
        }
    }
    for (name, q, d) in [
        (
            "n_patches",
            Quantity::NPatches,
            "number of slots carrying a patch",
        ),
        (
            "status",
            Quantity::Status,
            "0: ok; otherwise the kernel's error code of the last evaluation (docs/fmu.md), the force outputs are then 0",
        ),
    ] {
        v.push(Variable {
            name: name.into(),
            base: BaseType::Integer,
            causality: Causality::Output,
            variability: Variability::Discrete,
            unit: "",
            start: None,
            description: d.into(),
            quantity: q,
        });
    }
    v
}

/// The `status` output of a kernel error (0 is "ok").
pub fn error_code(e: &Error) -> i32 {
    match e {
        Error::NonFinite(_) => 1,
        Error::NonPositive(_) => 2,
        Error::OutOfRange(_) => 3,
        Error::GridTooSmall(_) => 4,
        Error::NoContact => 5,
        Error::TooManyRegions => 6,
        Error::BadProfile(_) => 7,
        Error::BadTable(_) => 8,
        Error::Derailed => 9,
        _ => 99,
    }
}

/// Outputs of one evaluation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Outputs {
    /// fx, fy, mz, fn, dy_used ([`TOTALS`]).
    pub totals: [f64; 5],
    /// Per slot: fn, fx, fy, mz, angle, pmax, area ([`SLOT_OUTPUTS`]).
    pub slots: [[f64; 7]; SLOTS],
    /// Slots carrying a patch.
    pub n_patches: i32,
    /// 0 or [`error_code`].
    pub status: i32,
}

/// The step's input at the FMU's inputs `inputs` ([`INPUTS`] order) and parameters `params`
/// ([`PARAMS`] order) for the wheel on `side`: shift and yaw towards that wheel
/// ([`WheelsetPose::towards_wheel`]), the rates in the same sign, nominal rolling at `speed`
/// with pitch rate speed / r0, no roll rate.
pub fn step_input(side: Side, inputs: &[f64; 7], params: &[f64; 2]) -> StepInput<f64> {
    let [dy, yaw, roll, fz, speed, lateral_velocity, yaw_rate] = *inputs;
    let [mu, r0] = *params;
    // The kernel's lateral axis and yaw point left/up; "towards the wheel" is −y for the right
    // wheel and +y for the left (as `towards_wheel` maps dy and yaw).
    let sign = match side {
        Side::Right => -1.0,
        Side::Left => 1.0,
    };
    let mut kinematics = Kinematics::nominal(speed, r0);
    kinematics.lateral_velocity = sign * lateral_velocity;
    kinematics.yaw_rate = sign * yaw_rate;
    StepInput {
        pose: WheelsetPose::towards_wheel(side, dy, yaw, roll),
        fz,
        kinematics,
        mu,
    }
}

/// Evaluates the step on `table` at `inputs` and `params`; a kernel error gives zero forces and
/// its code in `status`.
pub fn evaluate(table: &ContactTable<'_, f64>, inputs: &[f64; 7], params: &[f64; 2]) -> Outputs {
    let input = step_input(table.header.side, inputs, params);
    let mut out = Outputs::default();
    out.totals[4] = inputs[0];
    match step::<f64, SLOTS, STRIP_CAP>(table, &input) {
        Ok(r) => fill(&mut out, &r),
        Err(e) => out.status = error_code(&e),
    }
    out
}

fn fill(out: &mut Outputs, r: &StepResult<f64, SLOTS>) {
    for (k, s) in r.slots.iter().enumerate() {
        out.totals[0] += s.fx;
        out.totals[1] += s.fy;
        out.totals[2] += s.mz;
        out.totals[3] += s.load;
        out.slots[k] = [s.load, s.fx, s.fy, s.mz, s.angle, s.pmax, s.area];
        if s.load > 0.0 {
            out.n_patches += 1;
        }
    }
}

/// Where an instance is in the FMI 2.0 co-simulation state machine.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Phase {
    /// After `fmi2Instantiate` or `fmi2Reset`.
    Instantiated,
    /// Between `fmi2EnterInitializationMode` and `fmi2ExitInitializationMode`.
    Initialization,
    /// Stepping.
    StepComplete,
    /// After `fmi2Terminate`.
    Terminated,
    /// After an error: only `fmi2FreeInstance`, `fmi2Reset` and getters are allowed.
    Error,
}

/// The state of one FMU instance (apart from its C callbacks).
#[derive(Debug)]
pub struct Instance {
    /// The contact table.
    pub table: ContactTable<'static, f64>,
    /// Inputs, [`INPUTS`] order.
    pub inputs: [f64; 7],
    /// Parameters, [`PARAMS`] order.
    pub params: [f64; 2],
    /// The last evaluation.
    pub outputs: Outputs,
    /// Inputs or parameters changed since the last evaluation.
    pub dirty: bool,
    /// Current communication point, s.
    pub time: f64,
    /// Phase.
    pub phase: Phase,
}

/// Why a variable access was refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refused(pub String);

impl Instance {
    /// A new instance on `table` with the start values.
    pub fn new(table: ContactTable<'static, f64>) -> Self {
        Instance {
            table,
            inputs: INPUTS.map(|i| i.2),
            params: PARAMS.map(|p| p.2),
            outputs: Outputs::default(),
            dirty: true,
            time: 0.0,
            phase: Phase::Instantiated,
        }
    }

    /// Back to the start values (`fmi2Reset`).
    pub fn reset(&mut self) {
        *self = Instance::new(self.table);
    }

    /// Evaluates if an input or parameter changed since the last evaluation.
    pub fn refresh(&mut self) {
        if self.dirty {
            self.evaluate();
        }
    }

    /// Evaluates the step at the current inputs.
    pub fn evaluate(&mut self) {
        self.outputs = evaluate(&self.table, &self.inputs, &self.params);
        self.dirty = false;
    }

    /// The value of real variable `vr` (outputs are brought up to date with the inputs first).
    pub fn get_real(&mut self, vars: &[Variable], vr: u32) -> Result<f64, Refused> {
        let v = lookup(vars, vr, BaseType::Real)?;
        Ok(match v.quantity {
            Quantity::Input(i) => self.inputs[i],
            Quantity::Param(i) => self.params[i],
            Quantity::Total(i) => {
                self.refresh();
                self.outputs.totals[i]
            }
            Quantity::Slot(k, i) => {
                self.refresh();
                self.outputs.slots[k][i]
            }
            Quantity::NPatches | Quantity::Status => unreachable!("integer variables"),
        })
    }

    /// The value of integer variable `vr`.
    pub fn get_integer(&mut self, vars: &[Variable], vr: u32) -> Result<i32, Refused> {
        let v = lookup(vars, vr, BaseType::Integer)?;
        self.refresh();
        Ok(match v.quantity {
            Quantity::NPatches => self.outputs.n_patches,
            _ => self.outputs.status,
        })
    }

    /// Sets real variable `vr`: inputs at any time, tunable parameters at any time, fixed ones
    /// only before initialisation ends; outputs never.
    pub fn set_real(&mut self, vars: &[Variable], vr: u32, x: f64) -> Result<(), Refused> {
        let v = lookup(vars, vr, BaseType::Real)?;
        match v.quantity {
            Quantity::Input(i) => self.inputs[i] = x,
            Quantity::Param(i) => {
                let late = !matches!(self.phase, Phase::Instantiated | Phase::Initialization);
                if v.variability == Variability::Fixed && late {
                    return Err(Refused(format!(
                        "{} is a fixed parameter: set it before fmi2ExitInitializationMode",
                        v.name
                    )));
                }
                self.params[i] = x;
            }
            _ => {
                return Err(Refused(format!("{} is an output", v.name)));
            }
        }
        self.dirty = true;
        Ok(())
    }
}

fn lookup(vars: &[Variable], vr: u32, base: BaseType) -> Result<&Variable, Refused> {
    match vars.get(vr as usize) {
        Some(v) if v.base == base => Ok(v),
        Some(v) => Err(Refused(format!(
            "value reference {vr} ({}) is not of type {base:?}",
            v.name
        ))),
        None => Err(Refused(format!("unknown value reference {vr}"))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rates take the sign the shift and yaw take: d(dy)/dt of the kernel's dy is the
    /// kernel's lateral velocity, for either side.
    #[test]
    fn rates_follow_the_pose_convention() {
        for side in [Side::Right, Side::Left] {
            let inputs = [2.0, 0.004, 0.001, 80e3, 50e3, 20.0, 0.01];
            let i = step_input(side, &inputs, &[0.3, 460.0]);
            assert_eq!(i.pose, WheelsetPose::towards_wheel(side, 2.0, 0.004, 0.001));
            assert_eq!(i.kinematics.lateral_velocity / 20.0, i.pose.dy / 2.0);
            assert_eq!(i.kinematics.yaw_rate / 0.01, i.pose.yaw / 0.004);
            assert_eq!(i.kinematics.pitch_rate, 50e3 / 460.0);
            assert_eq!(i.kinematics.roll_rate, 0.0);
            assert_eq!((i.fz, i.mu, i.kinematics.speed), (80e3, 0.3, 50e3));
        }
    }

    #[test]
    fn value_references_are_positions_and_names_unique() {
        let v = variables();
        let mut names: Vec<&str> = v.iter().map(|x| x.name.as_str()).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), v.len());
        for x in &v {
            let has_start = matches!(x.causality, Causality::Input | Causality::Parameter);
            assert_eq!(x.start.is_some(), has_start, "{}", x.name);
        }
    }
}
