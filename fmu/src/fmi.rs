//! The FMI 2.0 co-simulation C API (the types follow the standard's `fmi2TypesPlatform.h` and
//! `fmi2FunctionTypes.h`). Every entry point checks its pointers, runs its body under
//! [`std::panic::catch_unwind`] (a panic returns `fmi2Fatal` / a null component, never unwinds
//! into the caller) and is the only place with `unsafe`.

#![allow(non_camel_case_types, non_snake_case)]

use crate::model::{Instance, Phase};
use crate::xml::{guid, vars};
use std::ffi::{c_char, c_void, CStr, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;
use std::sync::Mutex;
use wrc_kernel::table::ContactTable;

/// `fmi2Component`: the instance handle.
pub type fmi2Component = *mut c_void;
/// `fmi2ComponentEnvironment`: the environment's pointer passed back to its callbacks.
pub type fmi2ComponentEnvironment = *mut c_void;
/// `fmi2FMUstate` (not supported).
pub type fmi2FMUstate = *mut c_void;
/// `fmi2ValueReference`.
pub type fmi2ValueReference = u32;
/// `fmi2Real`.
pub type fmi2Real = f64;
/// `fmi2Integer`.
pub type fmi2Integer = i32;
/// `fmi2Boolean` (0 false, 1 true).
pub type fmi2Boolean = i32;
/// `fmi2String`.
pub type fmi2String = *const c_char;
/// `fmi2Byte`.
pub type fmi2Byte = c_char;

/// `fmi2Status`.
pub type fmi2Status = i32;
/// All well.
pub const FMI2_OK: fmi2Status = 0;
/// Something the environment should know, results usable.
pub const FMI2_WARNING: fmi2Status = 1;
/// The step could not be completed.
pub const FMI2_DISCARD: fmi2Status = 2;
/// This call failed; the instance may go on after fmi2Reset.
pub const FMI2_ERROR: fmi2Status = 3;
/// The instance is unusable.
pub const FMI2_FATAL: fmi2Status = 4;

/// `fmi2Type`: model exchange.
pub const FMI2_MODEL_EXCHANGE: i32 = 0;
/// `fmi2Type`: co-simulation.
pub const FMI2_CO_SIMULATION: i32 = 1;

/// `fmi2StatusKind`.
pub type fmi2StatusKind = i32;
/// `fmi2LastSuccessfulTime`.
pub const FMI2_LAST_SUCCESSFUL_TIME: fmi2StatusKind = 2;
/// `fmi2Terminated`.
pub const FMI2_TERMINATED: fmi2StatusKind = 3;

/// `fmi2CallbackLogger` (C-variadic; this FMU passes a message without format directives).
pub type fmi2CallbackLogger = Option<
    unsafe extern "C" fn(
        fmi2ComponentEnvironment,
        fmi2String,
        fmi2Status,
        fmi2String,
        fmi2String,
        ...
    ),
>;
/// `fmi2CallbackAllocateMemory`.
pub type fmi2CallbackAllocateMemory = Option<unsafe extern "C" fn(usize, usize) -> *mut c_void>;
/// `fmi2CallbackFreeMemory`.
pub type fmi2CallbackFreeMemory = Option<unsafe extern "C" fn(*mut c_void)>;
/// `fmi2StepFinished`.
pub type fmi2StepFinished = Option<unsafe extern "C" fn(fmi2ComponentEnvironment, fmi2Status)>;

/// `fmi2CallbackFunctions`.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct fmi2CallbackFunctions {
    /// Logger.
    pub logger: fmi2CallbackLogger,
    /// Memory allocation (not used: the FMU allocates with Rust's allocator).
    pub allocateMemory: fmi2CallbackAllocateMemory,
    /// Memory release (not used).
    pub freeMemory: fmi2CallbackFreeMemory,
    /// Asynchronous step completion (not used).
    pub stepFinished: fmi2StepFinished,
    /// Passed back to the callbacks.
    pub componentEnvironment: fmi2ComponentEnvironment,
}

/// An instance as the C side holds it.
struct Component {
    name: CString,
    logger: fmi2CallbackLogger,
    env: fmi2ComponentEnvironment,
    logging_on: bool,
    model: Instance,
}

impl Component {
    /// Sends `msg` to the environment's logger (debug messages only when logging is on).
    fn log(&self, status: fmi2Status, category: &str, msg: &str) {
        if status == FMI2_OK && !self.logging_on {
            return;
        }
        log_to(self.logger, self.env, &self.name, status, category, msg);
    }
}

fn cstring(s: &str) -> CString {
    // The logger's message is a printf format: no directives, no interior NULs.
    CString::new(s.replace('%', " pct").replace('\0', " ")).unwrap_or_default()
}

fn log_to(
    logger: fmi2CallbackLogger,
    env: fmi2ComponentEnvironment,
    name: &CStr,
    status: fmi2Status,
    category: &str,
    msg: &str,
) {
    if let Some(f) = logger {
        let (c, m) = (cstring(category), cstring(msg));
        // SAFETY: `f` is the environment's logger from fmi2CallbackFunctions; all strings are
        // NUL-terminated and live across the call; the message has no format directives, so
        // the variadic part is not read.
        unsafe { f(env, name.as_ptr(), status, c.as_ptr(), m.as_ptr()) };
    }
}

/// Tables read so far, leaked once per distinct content so that every instance can borrow its
/// table for `'static` (bounded by the distinct table files a process loads).
static TABLES: Mutex<Vec<&'static [u8]>> = Mutex::new(Vec::new());

fn load_table(path: &std::path::Path) -> Result<ContactTable<'static, f64>, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut cache = TABLES.lock().unwrap_or_else(|p| p.into_inner());
    let stored: &'static [u8] = match cache.iter().find(|b| ***b == bytes[..]) {
        Some(b) => b,
        None => {
            let b: &'static [u8] = Box::leak(bytes.into_boxed_slice());
            cache.push(b);
            b
        }
    };
    let t =
        ContactTable::<f64>::from_bytes(stored).map_err(|e| format!("{}: {e}", path.display()))?;
    if t.slots() > crate::model::SLOTS || t.strips() > crate::model::STRIP_CAP {
        return Err(format!(
            "{}: {} slots × {} strips exceed the FMU's {} × {}",
            path.display(),
            t.slots(),
            t.strips(),
            crate::model::SLOTS,
            crate::model::STRIP_CAP
        ));
    }
    Ok(t)
}

/// The directory of a `file:` URI (`file:///a/b`, `file://localhost/a/b`, `file:/a/b`),
/// percent-decoded.
pub fn uri_to_path(uri: &str) -> Result<PathBuf, String> {
    let rest = uri
        .strip_prefix("file://localhost/")
        .map(|r| format!("/{r}"))
        .or_else(|| uri.strip_prefix("file:///").map(|r| format!("/{r}")))
        .or_else(|| uri.strip_prefix("file:/").map(|r| format!("/{r}")))
        .ok_or_else(|| format!("resource location {uri:?} is not a file: URI"))?;
    let b = rest.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'%' && i + 2 < b.len() {
            let hex = std::str::from_utf8(&b[i + 1..i + 3]).unwrap_or("");
            if let Ok(v) = u8::from_str_radix(hex, 16) {
                out.push(v);
                i += 3;
                continue;
            }
        }
        out.push(b[i]);
        i += 1;
    }
    let s = String::from_utf8(out).map_err(|_| format!("resource location {uri:?}: not UTF-8"))?;
    Ok(PathBuf::from(s))
}

/// Runs `f` on the component behind `c`; null, panic → `fmi2Fatal`.
fn with(c: fmi2Component, f: impl FnOnce(&mut Component) -> fmi2Status) -> fmi2Status {
    if c.is_null() {
        return FMI2_ERROR;
    }
    // SAFETY: a non-null fmi2Component is a pointer returned by fmi2Instantiate (a leaked
    // Box<Component>) and not yet passed to fmi2FreeInstance; the FMI standard forbids calling
    // one instance from two threads at once, so this exclusive borrow is unique.
    let comp = unsafe { &mut *(c as *mut Component) };
    match catch_unwind(AssertUnwindSafe(|| f(comp))) {
        Ok(s) => s,
        Err(_) => {
            comp.model.phase = Phase::Error;
            FMI2_FATAL
        }
    }
}

/// A C string argument (null → `None`).
fn arg_str<'a>(p: fmi2String) -> Option<&'a str> {
    if p.is_null() {
        return None;
    }
    // SAFETY: the FMI standard passes NUL-terminated strings that outlive the call.
    unsafe { CStr::from_ptr(p) }.to_str().ok()
}

/// The `n` elements behind `p` (an empty slice when `n` is 0; `None` for null with n > 0).
fn arg_slice<'a, T>(p: *const T, n: usize) -> Option<&'a [T]> {
    if n == 0 {
        return Some(&[]);
    }
    if p.is_null() {
        return None;
    }
    // SAFETY: the caller passes an array of at least `n` elements (FMI 2.0 §2.1.7).
    Some(unsafe { std::slice::from_raw_parts(p, n) })
}

/// The `n` writable elements behind `p`.
fn arg_slice_mut<'a, T>(p: *mut T, n: usize) -> Option<&'a mut [T]> {
    if n == 0 {
        return Some(&mut []);
    }
    if p.is_null() {
        return None;
    }
    // SAFETY: the caller passes a writable array of at least `n` elements, not aliased by the
    // other arguments (FMI 2.0 §2.1.7).
    Some(unsafe { std::slice::from_raw_parts_mut(p, n) })
}

static TYPES_PLATFORM: &CStr = c"default";
static VERSION: &CStr = c"2.0";

/// `fmi2GetTypesPlatform`: "default".
#[no_mangle]
pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
    TYPES_PLATFORM.as_ptr()
}

/// `fmi2GetVersion`: "2.0".
#[no_mangle]
pub extern "C" fn fmi2GetVersion() -> *const c_char {
    VERSION.as_ptr()
}

/// `fmi2SetDebugLogging`: switches debug messages on or off (categories are not filtered).
#[no_mangle]
pub extern "C" fn fmi2SetDebugLogging(
    c: fmi2Component,
    loggingOn: fmi2Boolean,
    _nCategories: usize,
    _categories: *const fmi2String,
) -> fmi2Status {
    with(c, |comp| {
        comp.logging_on = loggingOn != 0;
        FMI2_OK
    })
}

/// A copy of the environment's callbacks (null → `None`).
fn callbacks(p: *const fmi2CallbackFunctions) -> Option<fmi2CallbackFunctions> {
    if p.is_null() {
        return None;
    }
    // SAFETY: a non-null `functions` argument of fmi2Instantiate points to the environment's
    // callback struct, valid for the call; it is copied.
    Some(unsafe { *p })
}

/// `fmi2Instantiate`: co-simulation only; checks the GUID and reads
/// `<fmuResourceLocation>/table.bin`. Null on any failure (logged).
#[no_mangle]
pub extern "C" fn fmi2Instantiate(
    instanceName: fmi2String,
    fmuType: i32,
    fmuGUID: fmi2String,
    fmuResourceLocation: fmi2String,
    functions: *const fmi2CallbackFunctions,
    _visible: fmi2Boolean,
    loggingOn: fmi2Boolean,
) -> fmi2Component {
    let r = catch_unwind(|| {
        let cb = callbacks(functions);
        let (logger, env) = cb.map_or((None, std::ptr::null_mut()), |f| {
            (f.logger, f.componentEnvironment)
        });
        let name = CString::new(arg_str(instanceName).unwrap_or("wrc")).unwrap_or_default();
        let fail = |msg: String| {
            log_to(logger, env, &name, FMI2_ERROR, "logStatusError", &msg);
            std::ptr::null_mut()
        };
        if fmuType != FMI2_CO_SIMULATION {
            return fail("this FMU supports co-simulation only".into());
        }
        match arg_str(fmuGUID) {
            Some(g) if g == guid() => {}
            g => return fail(format!("GUID {g:?} differs from the library's {}", guid())),
        }
        let Some(loc) = arg_str(fmuResourceLocation) else {
            return fail("no resource location".into());
        };
        let table = match uri_to_path(loc).and_then(|p| load_table(&p.join("table.bin"))) {
            Ok(t) => t,
            Err(e) => return fail(e),
        };
        let comp = Box::new(Component {
            name,
            logger,
            env,
            logging_on: loggingOn != 0,
            model: Instance::new(table),
        });
        comp.log(FMI2_OK, "logAll", &format!("table {loc}/table.bin loaded"));
        Box::into_raw(comp) as fmi2Component
    });
    r.unwrap_or(std::ptr::null_mut())
}

/// `fmi2FreeInstance`.
#[no_mangle]
pub extern "C" fn fmi2FreeInstance(c: fmi2Component) {
    if c.is_null() {
        return;
    }
    // SAFETY: `c` came from fmi2Instantiate (Box::into_raw) and the standard forbids using it
    // after this call, so it is reclaimed exactly once.
    let b = unsafe { Box::from_raw(c as *mut Component) };
    let _ = catch_unwind(AssertUnwindSafe(move || drop(b)));
}

/// `fmi2SetupExperiment`: records the start time (tolerance and stop time are not used).
#[no_mangle]
pub extern "C" fn fmi2SetupExperiment(
    c: fmi2Component,
    _toleranceDefined: fmi2Boolean,
    _tolerance: fmi2Real,
    startTime: fmi2Real,
    _stopTimeDefined: fmi2Boolean,
    _stopTime: fmi2Real,
) -> fmi2Status {
    with(c, |comp| {
        if comp.model.phase != Phase::Instantiated {
            comp.log(
                FMI2_ERROR,
                "logStatusError",
                "fmi2SetupExperiment only after fmi2Instantiate",
            );
            return FMI2_ERROR;
        }
        comp.model.time = startTime;
        FMI2_OK
    })
}

/// `fmi2EnterInitializationMode`.
#[no_mangle]
pub extern "C" fn fmi2EnterInitializationMode(c: fmi2Component) -> fmi2Status {
    with(c, |comp| {
        if comp.model.phase != Phase::Instantiated {
            comp.log(
                FMI2_ERROR,
                "logStatusError",
                "fmi2EnterInitializationMode only after fmi2Instantiate",
            );
            return FMI2_ERROR;
        }
        comp.model.phase = Phase::Initialization;
        FMI2_OK
    })
}

/// `fmi2ExitInitializationMode`: evaluates the outputs at the initial inputs.
#[no_mangle]
pub extern "C" fn fmi2ExitInitializationMode(c: fmi2Component) -> fmi2Status {
    with(c, |comp| {
        if comp.model.phase != Phase::Initialization {
            comp.log(
                FMI2_ERROR,
                "logStatusError",
                "fmi2ExitInitializationMode only in initialisation mode",
            );
            return FMI2_ERROR;
        }
        comp.model.evaluate();
        comp.model.phase = Phase::StepComplete;
        report_status(comp);
        FMI2_OK
    })
}

/// Logs a warning when the evaluation's status is not 0.
fn report_status(comp: &Component) {
    let s = comp.model.outputs.status;
    if s != 0 {
        comp.log(
            FMI2_WARNING,
            "logStatusWarning",
            &format!(
                "t = {} s: the step failed (status {s}, docs/fmu.md) at dy {} mm, fz {} N; \
                 forces are 0",
                comp.model.time, comp.model.inputs[0], comp.model.inputs[3]
            ),
        );
    }
}

/// `fmi2Terminate`.
#[no_mangle]
pub extern "C" fn fmi2Terminate(c: fmi2Component) -> fmi2Status {
    with(c, |comp| {
        comp.model.phase = Phase::Terminated;
        FMI2_OK
    })
}

/// `fmi2Reset`: back to the state after fmi2Instantiate (start values).
#[no_mangle]
pub extern "C" fn fmi2Reset(c: fmi2Component) -> fmi2Status {
    with(c, |comp| {
        comp.model.reset();
        FMI2_OK
    })
}

/// Applies `f` to each (value reference, value) pair; the first refusal is logged, gives
/// `fmi2Error`.
fn for_each<T>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    values: Option<&mut [T]>,
    what: &str,
    mut f: impl FnMut(&mut Instance, u32, &mut T) -> Result<(), crate::model::Refused>,
) -> fmi2Status {
    with(c, |comp| {
        let (Some(vrs), Some(vals)) = (arg_slice(vr, n), values) else {
            comp.log(FMI2_ERROR, "logStatusError", &format!("{what}: null array"));
            return FMI2_ERROR;
        };
        for (r, x) in vrs.iter().zip(vals.iter_mut()) {
            if let Err(e) = f(&mut comp.model, *r, x) {
                comp.log(FMI2_ERROR, "logStatusError", &format!("{what}: {}", e.0));
                return FMI2_ERROR;
            }
        }
        FMI2_OK
    })
}

/// `fmi2GetReal`: inputs, parameters and outputs (outputs are evaluated first if an input
/// changed since the last evaluation: the model is algebraic, with direct feed-through).
#[no_mangle]
pub extern "C" fn fmi2GetReal(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Real,
) -> fmi2Status {
    let vals = arg_slice_mut(value, nvr);
    for_each(c, vr, nvr, vals, "fmi2GetReal", |m, r, x| {
        *x = m.get_real(vars(), r)?;
        Ok(())
    })
}

/// `fmi2GetInteger`: `n_patches` and `status`.
#[no_mangle]
pub extern "C" fn fmi2GetInteger(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Integer,
) -> fmi2Status {
    let vals = arg_slice_mut(value, nvr);
    for_each(c, vr, nvr, vals, "fmi2GetInteger", |m, r, x| {
        *x = m.get_integer(vars(), r)?;
        Ok(())
    })
}

/// `fmi2SetReal`: inputs and parameters.
#[no_mangle]
pub extern "C" fn fmi2SetReal(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Real,
) -> fmi2Status {
    let mut vals: Option<Vec<f64>> = arg_slice(value, nvr).map(|v| v.to_vec());
    for_each(c, vr, nvr, vals.as_deref_mut(), "fmi2SetReal", |m, r, x| {
        m.set_real(vars(), r, *x)
    })
}

/// Refuses an access to a type the model has no variables of (any value reference is unknown).
fn no_such(c: fmi2Component, nvr: usize, what: &str) -> fmi2Status {
    with(c, |comp| {
        if nvr == 0 {
            return FMI2_OK;
        }
        comp.log(
            FMI2_ERROR,
            "logStatusError",
            &format!("{what}: the model has no variables of this type"),
        );
        FMI2_ERROR
    })
}

/// `fmi2SetInteger`: the integer variables are outputs, so any reference is refused.
#[no_mangle]
pub extern "C" fn fmi2SetInteger(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    nvr: usize,
    _value: *const fmi2Integer,
) -> fmi2Status {
    no_such(c, nvr, "fmi2SetInteger (integer variables are outputs)")
}

/// `fmi2GetBoolean`: no boolean variables.
#[no_mangle]
pub extern "C" fn fmi2GetBoolean(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    nvr: usize,
    _value: *mut fmi2Boolean,
) -> fmi2Status {
    no_such(c, nvr, "fmi2GetBoolean")
}

/// `fmi2SetBoolean`: no boolean variables.
#[no_mangle]
pub extern "C" fn fmi2SetBoolean(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    nvr: usize,
    _value: *const fmi2Boolean,
) -> fmi2Status {
    no_such(c, nvr, "fmi2SetBoolean")
}

/// `fmi2GetString`: no string variables.
#[no_mangle]
pub extern "C" fn fmi2GetString(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    nvr: usize,
    _value: *mut fmi2String,
) -> fmi2Status {
    no_such(c, nvr, "fmi2GetString")
}

/// `fmi2SetString`: no string variables.
#[no_mangle]
pub extern "C" fn fmi2SetString(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    nvr: usize,
    _value: *const fmi2String,
) -> fmi2Status {
    no_such(c, nvr, "fmi2SetString")
}

/// Logs that an optional capability is not provided; `fmi2Error`.
fn unsupported(c: fmi2Component, what: &str) -> fmi2Status {
    with(c, |comp| {
        comp.log(
            FMI2_ERROR,
            "logStatusError",
            &format!("{what} is not supported (modelDescription.xml declares it)"),
        );
        FMI2_ERROR
    })
}

/// `fmi2GetFMUstate`: not supported (`canGetAndSetFMUstate="false"`).
#[no_mangle]
pub extern "C" fn fmi2GetFMUstate(c: fmi2Component, _s: *mut fmi2FMUstate) -> fmi2Status {
    unsupported(c, "fmi2GetFMUstate")
}

/// `fmi2SetFMUstate`: not supported.
#[no_mangle]
pub extern "C" fn fmi2SetFMUstate(c: fmi2Component, _s: fmi2FMUstate) -> fmi2Status {
    unsupported(c, "fmi2SetFMUstate")
}

/// `fmi2FreeFMUstate`: not supported.
#[no_mangle]
pub extern "C" fn fmi2FreeFMUstate(c: fmi2Component, _s: *mut fmi2FMUstate) -> fmi2Status {
    unsupported(c, "fmi2FreeFMUstate")
}

/// `fmi2SerializedFMUstateSize`: not supported.
#[no_mangle]
pub extern "C" fn fmi2SerializedFMUstateSize(
    c: fmi2Component,
    _s: fmi2FMUstate,
    _size: *mut usize,
) -> fmi2Status {
    unsupported(c, "fmi2SerializedFMUstateSize")
}

/// `fmi2SerializeFMUstate`: not supported.
#[no_mangle]
pub extern "C" fn fmi2SerializeFMUstate(
    c: fmi2Component,
    _s: fmi2FMUstate,
    _bytes: *mut fmi2Byte,
    _size: usize,
) -> fmi2Status {
    unsupported(c, "fmi2SerializeFMUstate")
}

/// `fmi2DeSerializeFMUstate`: not supported.
#[no_mangle]
pub extern "C" fn fmi2DeSerializeFMUstate(
    c: fmi2Component,
    _bytes: *const fmi2Byte,
    _size: usize,
    _s: *mut fmi2FMUstate,
) -> fmi2Status {
    unsupported(c, "fmi2DeSerializeFMUstate")
}

/// `fmi2GetDirectionalDerivative`: not supported (`providesDirectionalDerivative="false"`).
#[no_mangle]
pub extern "C" fn fmi2GetDirectionalDerivative(
    c: fmi2Component,
    _vUnknown: *const fmi2ValueReference,
    _nUnknown: usize,
    _vKnown: *const fmi2ValueReference,
    _nKnown: usize,
    _dvKnown: *const fmi2Real,
    _dvUnknown: *mut fmi2Real,
) -> fmi2Status {
    unsupported(c, "fmi2GetDirectionalDerivative")
}

/// `fmi2SetRealInputDerivatives`: not supported (`canInterpolateInputs="false"`).
#[no_mangle]
pub extern "C" fn fmi2SetRealInputDerivatives(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    _nvr: usize,
    _order: *const fmi2Integer,
    _value: *const fmi2Real,
) -> fmi2Status {
    unsupported(c, "fmi2SetRealInputDerivatives")
}

/// `fmi2GetRealOutputDerivatives`: not supported (`maxOutputDerivativeOrder="0"`).
#[no_mangle]
pub extern "C" fn fmi2GetRealOutputDerivatives(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    _nvr: usize,
    _order: *const fmi2Integer,
    _value: *mut fmi2Real,
) -> fmi2Status {
    unsupported(c, "fmi2GetRealOutputDerivatives")
}

/// `fmi2DoStep`: evaluates the real-time step at the inputs held over
/// [currentCommunicationPoint, + communicationStepSize] and advances the time. A failing step
/// (e.g. a shift outside the table) returns `fmi2OK` with the `status` output set and the forces 0
/// (logged as a warning), so that a simulation goes on; a negative or non-finite step size is
/// `fmi2Error`.
#[no_mangle]
pub extern "C" fn fmi2DoStep(
    c: fmi2Component,
    currentCommunicationPoint: fmi2Real,
    communicationStepSize: fmi2Real,
    _noSetFMUStatePriorToCurrentPoint: fmi2Boolean,
) -> fmi2Status {
    with(c, |comp| {
        if comp.model.phase != Phase::StepComplete {
            comp.log(
                FMI2_ERROR,
                "logStatusError",
                "fmi2DoStep only after fmi2ExitInitializationMode",
            );
            return FMI2_ERROR;
        }
        let h = communicationStepSize;
        if !(h >= 0.0 && h.is_finite() && currentCommunicationPoint.is_finite()) {
            comp.log(
                FMI2_ERROR,
                "logStatusError",
                &format!("fmi2DoStep: bad communication step {h}"),
            );
            return FMI2_ERROR;
        }
        let was = comp.model.outputs.status;
        comp.model.evaluate();
        comp.model.time = currentCommunicationPoint + h;
        if was == 0 {
            report_status(comp);
        }
        FMI2_OK
    })
}

/// `fmi2CancelStep`: steps are synchronous, nothing to cancel; `fmi2Error`.
#[no_mangle]
pub extern "C" fn fmi2CancelStep(c: fmi2Component) -> fmi2Status {
    unsupported(c, "fmi2CancelStep (steps are synchronous)")
}

/// `fmi2GetStatus`: steps are synchronous, no pending status; `fmi2Discard`.
#[no_mangle]
pub extern "C" fn fmi2GetStatus(
    c: fmi2Component,
    _s: fmi2StatusKind,
    _value: *mut fmi2Status,
) -> fmi2Status {
    with(c, |_| FMI2_DISCARD)
}

/// `fmi2GetRealStatus`: `fmi2LastSuccessfulTime` is the current time; others `fmi2Discard`.
#[no_mangle]
pub extern "C" fn fmi2GetRealStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Real,
) -> fmi2Status {
    with(c, |comp| match (s, arg_slice_mut(value, 1)) {
        (FMI2_LAST_SUCCESSFUL_TIME, Some(v)) => {
            v[0] = comp.model.time;
            FMI2_OK
        }
        _ => FMI2_DISCARD,
    })
}

/// `fmi2GetIntegerStatus`: none; `fmi2Discard`.
#[no_mangle]
pub extern "C" fn fmi2GetIntegerStatus(
    c: fmi2Component,
    _s: fmi2StatusKind,
    _value: *mut fmi2Integer,
) -> fmi2Status {
    with(c, |_| FMI2_DISCARD)
}

/// `fmi2GetBooleanStatus`: `fmi2Terminated` is false (the FMU never ends a simulation);
/// others `fmi2Discard`.
#[no_mangle]
pub extern "C" fn fmi2GetBooleanStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    with(c, |_| match (s, arg_slice_mut(value, 1)) {
        (FMI2_TERMINATED, Some(v)) => {
            v[0] = 0;
            FMI2_OK
        }
        _ => FMI2_DISCARD,
    })
}

/// `fmi2GetStringStatus`: none; `fmi2Discard`.
#[no_mangle]
pub extern "C" fn fmi2GetStringStatus(
    c: fmi2Component,
    _s: fmi2StatusKind,
    _value: *mut fmi2String,
) -> fmi2Status {
    with(c, |_| FMI2_DISCARD)
}
