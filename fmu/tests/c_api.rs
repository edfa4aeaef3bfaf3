//! The C entry points driven from Rust as an FMI importer would: instantiation from a
//! resource URI, the co-simulation sequence, the outputs against the model's evaluation, a
//! shift outside the table (status output, fmi2OK), and the refusals.

use std::ffi::{c_char, CString};
use std::ptr::{null, null_mut};
use wrc_fmu::fmi::*;
use wrc_fmu::model::{Quantity, INPUTS, PARAMS};
use wrc_fmu::xml::{guid, model_description, vars};

fn vr(name: &str) -> u32 {
    vars().iter().position(|v| v.name == name).unwrap() as u32
}

fn resources() -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("wrc-fmu-test-{}", std::process::id()));
    let res = dir.join("my resources");
    std::fs::create_dir_all(&res).unwrap();
    let (table, _) = wrc_fmu::pack::default_table().unwrap();
    std::fs::write(res.join("table.bin"), table).unwrap();
    res
}

fn instantiate(uri: &str, g: &str, kind: i32) -> fmi2Component {
    let (name, g, uri) = (
        CString::new("t").unwrap(),
        CString::new(g).unwrap(),
        CString::new(uri).unwrap(),
    );
    let cb = fmi2CallbackFunctions {
        logger: None,
        allocateMemory: None,
        freeMemory: None,
        stepFinished: None,
        componentEnvironment: null_mut(),
    };
    fmi2Instantiate(name.as_ptr(), kind, g.as_ptr(), uri.as_ptr(), &cb, 0, 0)
}

fn get(c: fmi2Component, names: &[&str]) -> Vec<f64> {
    let r: Vec<u32> = names.iter().map(|n| vr(n)).collect();
    let mut v = vec![f64::NAN; r.len()];
    assert_eq!(fmi2GetReal(c, r.as_ptr(), r.len(), v.as_mut_ptr()), FMI2_OK);
    v
}

fn set(c: fmi2Component, name: &str, x: f64) -> fmi2Status {
    fmi2SetReal(c, &vr(name), 1, &x)
}

fn status(c: fmi2Component) -> i32 {
    let mut s = -1;
    assert_eq!(fmi2GetInteger(c, &vr("status"), 1, &mut s), FMI2_OK);
    s
}

#[test]
fn co_simulation_sequence_matches_the_model() {
    let res = resources();
    let uri = format!("file://{}", res.display()).replace(' ', "%20");
    assert!(instantiate(&uri, "{wrong}", FMI2_CO_SIMULATION).is_null());
    assert!(instantiate(&uri, guid(), FMI2_MODEL_EXCHANGE).is_null());
    assert!(instantiate("file:///nonexistent", guid(), FMI2_CO_SIMULATION).is_null());
    let c = instantiate(&uri, guid(), FMI2_CO_SIMULATION);
    assert!(!c.is_null());
    // SAFETY: the version functions return pointers to static NUL-terminated strings.
    let s = |p: *const c_char| unsafe { std::ffi::CStr::from_ptr(p) }.to_str().unwrap();
    assert_eq!(s(fmi2GetVersion()), "2.0");
    assert_eq!(s(fmi2GetTypesPlatform()), "default");
    assert_eq!(fmi2DoStep(c, 0.0, 1e-3, 1), FMI2_ERROR, "not initialised");
    assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), FMI2_OK);
    assert_eq!(fmi2EnterInitializationMode(c), FMI2_OK);
    assert_eq!(set(c, "r0", 460.0), FMI2_OK);
    assert_eq!(fmi2ExitInitializationMode(c), FMI2_OK);
    assert_eq!(
        set(c, "r0", 450.0),
        FMI2_ERROR,
        "fixed after initialisation"
    );
    assert_eq!(set(c, "fx", 1.0), FMI2_ERROR, "an output");
    assert_eq!(set(c, "mu", 0.25), FMI2_OK, "tunable");

    let bytes = std::fs::read(res.join("table.bin")).unwrap();
    let table = wrc_kernel::table::ContactTable::<f64>::from_bytes(&bytes).unwrap();
    let mut t = 0.0;
    for (dy, lat, yr) in [(0.0, 0.0, 0.0), (3.0, 20.0, 0.01), (-2.5, -15.0, -0.02)] {
        assert_eq!(set(c, "dy", dy), FMI2_OK);
        assert_eq!(set(c, "lateral_velocity", lat), FMI2_OK);
        assert_eq!(set(c, "yaw_rate", yr), FMI2_OK);
        assert_eq!(fmi2DoStep(c, t, 1e-3, 1), FMI2_OK);
        t += 1e-3;
        let mut inputs = INPUTS.map(|i| i.2);
        inputs[0] = dy;
        inputs[5] = lat;
        inputs[6] = yr;
        let mut params = PARAMS.map(|p| p.2);
        params[0] = 0.25;
        let want = wrc_fmu::model::evaluate(&table, &inputs, &params);
        assert_eq!(want.status, 0);
        for (i, v) in vars().iter().enumerate() {
            let x = match v.quantity {
                Quantity::Total(k) => want.totals[k],
                Quantity::Slot(k, f) => want.slots[k][f],
                _ => continue,
            };
            assert_eq!(
                get(c, &[&v.name])[0].to_bits(),
                x.to_bits(),
                "{} (vr {i})",
                v.name
            );
        }
        assert_eq!(status(c), 0);
        assert!(get(c, &["fn"])[0] > 0.0);
    }
    let mut last = f64::NAN;
    assert_eq!(
        fmi2GetRealStatus(c, FMI2_LAST_SUCCESSFUL_TIME, &mut last),
        FMI2_OK
    );
    assert!((last - t).abs() < 1e-15);

    // Outside the table: fmi2OK, status 3 (OutOfRange), forces 0.
    assert_eq!(set(c, "dy", 30.0), FMI2_OK);
    assert_eq!(fmi2DoStep(c, t, 1e-3, 1), FMI2_OK);
    assert_eq!(status(c), 3);
    assert_eq!(
        get(c, &["fx", "fy", "fn", "dy_used"]),
        vec![0.0, 0.0, 0.0, 30.0]
    );
    // Back inside: recovers.
    assert_eq!(set(c, "dy", 1.0), FMI2_OK);
    assert_eq!(fmi2DoStep(c, t + 1e-3, 1e-3, 1), FMI2_OK);
    assert_eq!(status(c), 0);

    // Refusals: unknown reference, wrong type, null arrays, unsupported types and functions.
    let mut x = 0.0;
    assert_eq!(fmi2GetReal(c, &9999, 1, &mut x), FMI2_ERROR);
    assert_eq!(fmi2GetReal(c, &vr("status"), 1, &mut x), FMI2_ERROR);
    assert_eq!(fmi2GetReal(c, null(), 1, &mut x), FMI2_ERROR);
    let mut b = 0;
    assert_eq!(fmi2GetBoolean(c, &0, 1, &mut b), FMI2_ERROR);
    assert_eq!(fmi2GetFMUstate(c, null_mut()), FMI2_ERROR);
    assert_eq!(fmi2DoStep(c, t, -1.0, 1), FMI2_ERROR);
    assert_eq!(fmi2DoStep(null_mut(), t, 1e-3, 1), FMI2_ERROR);

    assert_eq!(fmi2Reset(c), FMI2_OK);
    assert_eq!(get(c, &["mu", "dy"]), vec![0.3, 0.0]);
    assert_eq!(fmi2Terminate(c), FMI2_OK);
    fmi2FreeInstance(c);
    fmi2FreeInstance(null_mut());
    let _ = std::fs::remove_dir_all(res.parent().unwrap());
}

#[test]
fn model_description_lists_every_variable_once() {
    let md = model_description();
    for (i, v) in vars().iter().enumerate() {
        let decl = format!("name=\"{}\" valueReference=\"{i}\"", v.name);
        assert_eq!(md.matches(&decl).count(), 1, "{decl}");
    }
    assert!(md.contains(guid()));
    assert!(md.contains("modelIdentifier=\"wrc\""));
    assert!(md.contains("canHandleVariableCommunicationStepSize=\"true\""));
    assert_eq!(vars().len(), 7 + 2 + 5 + 3 * 7 + 2);
}

#[test]
fn file_uris() {
    for (u, p) in [
        ("file:///a/b%20c", "/a/b c"),
        ("file://localhost/a/b", "/a/b"),
        ("file:/a/b/", "/a/b/"),
    ] {
        assert_eq!(uri_to_path(u).unwrap(), std::path::PathBuf::from(p), "{u}");
    }
    assert!(uri_to_path("http://x/y").is_err());
}
