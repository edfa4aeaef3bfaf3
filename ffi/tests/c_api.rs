//! The C interface from C and from Rust (issue 15).
//!
//! Builds the S1002/UIC60 contact tables (1353 mm, right wheel, equilibrium roll, dy −11.8…11.8 mm
//! every 0.5 mm refined to 1 % × 15–260 kN in 5 loads, 1 slot (of 3) × 32 strips, as host-tests
//! `realtime_step`) in f64 and f32 plus a small table over the library's strip capacity, writes them to files,
//! compiles `tests/c/step_test.c` with the system C compiler (`cc -std=c11 -Wall -Wextra
//! -Werror`) against `libwrc_ffi.a` of this cargo invocation, runs it, and checks its lateral
//! shift sweep bit for bit against the Rust API (`wrc_kernel::step::step`) and its bad-input
//! status codes; the same bad inputs through the Rust-callable entry points.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;
use wrc_ffi::*;
use wrc_host_tests::realtime::{s1002_uic60_table, standard_spec};
use wrc_kernel::geometry::{Kinematics, Normalisation, WheelsetPose};
use wrc_kernel::step::{step, step_from, StepInput};
use wrc_kernel::table::{ContactTable, TableSpec};
use wrc_kernel::Real;

const K: usize = 3;
const ST: usize = 32;

fn build<T: Real, const KK: usize, const SS: usize>(spec: &TableSpec<T>) -> Vec<u8> {
    s1002_uic60_table::<T, KK, SS>(spec).expect("table build").0
}

fn spec<T: Real>() -> TableSpec<T> {
    standard_spec()
}

/// The shift node count in a table's header (the refined grid's, not known before the build).
fn n_dy(bytes: &[u8]) -> u32 {
    u32::from_le_bytes([bytes[16], bytes[17], bytes[18], bytes[19]])
}

/// The slot count in a table's header (the slots the build used: 1 for S1002/UIC60).
fn slots(bytes: &[u8]) -> u32 {
    u32::from_le_bytes([bytes[24], bytes[25], bytes[26], bytes[27]])
}

struct Tables {
    f64: Vec<u8>,
    f32: Vec<u8>,
    over_capacity: Vec<u8>,
}

fn tables() -> &'static Tables {
    static T: OnceLock<Tables> = OnceLock::new();
    T.get_or_init(|| {
        let small = TableSpec {
            dy_min: -1.0,
            dy_max: 1.0,
            n_dy: 2,
            n_load: 2,
            refine_tol: 0.0,
            ..spec::<f64>()
        };
        Tables {
            f64: build::<f64, K, ST>(&spec()),
            f32: build::<f32, K, ST>(&spec()),
            // more strips than the library's step holds (tables store only the slots they
            // use, so a slot capacity above WRC_MAX_SLOTS does not make one)
            over_capacity: build::<f64, 1, { WRC_MAX_STRIPS + 1 }>(&small),
        }
    })
}

/// The sweep's input at `i`, as step_test.c builds it.
fn input<T: Real>(i: usize) -> StepInput<T> {
    let dy = -8.0 + 0.5 * i as f64;
    let speed = T::from_f64(100.0 / 3.6 * 1000.0);
    StepInput {
        pose: WheelsetPose {
            dy: T::from_f64(dy),
            yaw: T::ZERO,
            roll: T::ZERO,
        },
        fz: T::from_f64(83_300.0),
        kinematics: Kinematics {
            speed,
            pitch_rate: speed / T::from_f64(460.0),
            lateral_velocity: T::ZERO,
            yaw_rate: T::ZERO,
            roll_rate: T::ZERO,
            normalisation: Normalisation::Forward,
        },
        mu: T::from_f64(0.3),
    }
}

/// The hex of a value's IEEE bits as step_test.c prints it.
fn hex<T: Real>(x: T) -> String {
    if T::BYTES == 8 {
        format!("{:016x}", x.to_f64().to_bits())
    } else {
        format!("{:08x}", (x.to_f64() as f32).to_bits())
    }
}

/// The sweep line the C program must print, from the Rust API: `step`, or for the `g64`/`g32`
/// lines `step_from` the cold step's result.
fn expected_line<T: Real>(name: &str, bytes: &[u8], i: usize) -> String {
    let t = ContactTable::<T>::from_bytes(bytes).expect("valid table");
    let mut r = step::<T, K, ST>(&t, &input::<T>(i)).expect("state inside the table");
    if name.starts_with('g') {
        r = step_from::<T, K, ST>(&t, &input::<T>(i), &r).expect("state inside the table");
    }
    let mut s = format!(
        "{name} {i} 0 {} {} {}",
        hex(r.vertical_approach),
        hex(r.vertical_load),
        t.header.slots
    );
    for sl in r.slots.iter().take(t.header.slots) {
        for v in [
            sl.load,
            sl.angle,
            sl.rolling_radius,
            sl.x_ref,
            sl.y_ref_track,
            sl.z_ref_track,
            sl.y_ref_rail,
            sl.creepage.xi,
            sl.creepage.eta,
            sl.creepage.phi,
            sl.fx,
            sl.fy,
            sl.mz,
            sl.pmax,
            sl.area,
        ] {
            s.push(' ');
            s.push_str(&hex(v));
        }
    }
    s
}

/// `libwrc_ffi.a` of this cargo invocation. `cargo test` builds the library once with both
/// crate types into `target/<profile>/deps/` (`libwrc_ffi-<hash>.a` beside the `.rlib` this test
/// links) without copying the staticlib up to `target/<profile>/`, so: the newest
/// `deps/libwrc_ffi-*.a` that has its `.rlib` twin, else `target/<profile>/libwrc_ffi.a` (a
/// `cargo build -p wrc-ffi`), else built with `cargo build -p wrc-ffi` of the same profile.
fn staticlib() -> PathBuf {
    let exe = std::env::current_exe().expect("test executable path");
    let deps = exe.parent().expect("target/<profile>/deps").to_path_buf();
    let profile_dir = deps.parent().expect("target/<profile>").to_path_buf();
    let mut best: Option<(std::time::SystemTime, PathBuf)> = None;
    for e in std::fs::read_dir(&deps).expect("deps folder").flatten() {
        let p = e.path();
        let name = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
        if !(name.starts_with("libwrc_ffi-") && name.ends_with(".a")) {
            continue;
        }
        if !p.with_extension("rlib").exists() {
            continue;
        }
        let t = e.metadata().and_then(|m| m.modified()).ok();
        if let Some(t) = t {
            if best.as_ref().is_none_or(|(b, _)| t > *b) {
                best = Some((t, p));
            }
        }
    }
    if let Some((_, p)) = best {
        return p;
    }
    let lib = profile_dir.join("libwrc_ffi.a");
    if !lib.exists() {
        let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
        let mut c = Command::new(cargo);
        c.args(["build", "-p", "wrc-ffi", "--lib"]);
        if profile_dir.file_name().is_some_and(|n| n == "release") {
            c.arg("--release");
        }
        let st = c.status().expect("cargo build -p wrc-ffi");
        assert!(st.success(), "cargo build -p wrc-ffi failed");
    }
    assert!(lib.exists(), "no {}", lib.display());
    lib
}

/// Compiles `tests/c/<file>` with the system C compiler (`$CC`, else `cc`) as C11 with all
/// warnings as errors, linked against this invocation's `libwrc_ffi.a`; returns the executable.
fn compile_c(file: &str, dir: &Path) -> PathBuf {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let exe = dir.join(file.trim_end_matches(".c"));
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let lib = staticlib();
    eprintln!("linking {}", lib.display());
    let out = Command::new(&cc)
        .args(["-std=c11", "-Wall", "-Wextra", "-Werror", "-O2", "-I"])
        .arg(manifest.join("include"))
        .arg(manifest.join("tests/c").join(file))
        .arg(lib)
        .args([
            "-lm",
            "-lpthread",
            "-ldl",
            "-lrt",
            "-lutil",
            "-lgcc_s",
            "-o",
        ])
        .arg(&exe)
        .output()
        .expect("run the C compiler");
    assert!(
        out.status.success(),
        "{cc} {file} failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    exe
}

/// The tables as files, written once (tests run in parallel): (folder, f64, f32, over capacity).
fn table_files() -> (PathBuf, PathBuf, PathBuf, PathBuf) {
    static F: OnceLock<(PathBuf, PathBuf, PathBuf, PathBuf)> = OnceLock::new();
    F.get_or_init(|| {
        let t = tables();
        let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("wrc-ffi-c");
        std::fs::create_dir_all(&dir).unwrap();
        let (p64, p32, pcap) = (
            dir.join("s1002_uic60_f64.wrct"),
            dir.join("s1002_uic60_f32.wrct"),
            dir.join("over_capacity_f64.wrct"),
        );
        std::fs::write(&p64, &t.f64).unwrap();
        std::fs::write(&p32, &t.f32).unwrap();
        std::fs::write(&pcap, &t.over_capacity).unwrap();
        (dir, p64, p32, pcap)
    })
    .clone()
}

#[test]
fn readme_c_example_compiles_runs_and_is_the_readme_text() {
    let (dir, p64, _, _) = table_files();
    let exe = compile_c("minimal.c", &dir);
    let run = Command::new(&exe).arg(&p64).output().expect("run minimal");
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    eprintln!("{stdout}");
    assert!(stdout.contains("vertical load"));
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let src = std::fs::read_to_string(manifest.join("tests/c/minimal.c")).unwrap();
    let doc = std::fs::read_to_string(manifest.join("../docs/ffi.md")).unwrap();
    assert!(
        doc.contains(&src),
        "docs/ffi.md's minimal program differs from ffi/tests/c/minimal.c"
    );
}

#[test]
fn c_program_matches_the_rust_api_bit_for_bit_and_checks_bad_inputs() {
    let t = tables();
    let (dir, p64, p32, pcap) = table_files();
    let exe = compile_c("step_test.c", &dir);
    let run = Command::new(&exe)
        .args([&p64, &p32, &pcap])
        .output()
        .expect("run step_test");
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "step_test failed:\n{}\n{stdout}",
        String::from_utf8_lossy(&run.stderr)
    );
    let lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(lines.last(), Some(&"ok"));
    assert_eq!(
        lines.iter().find(|l| l.starts_with("info ")),
        Some(
            &format!(
                "info 8 {} 5 {} {ST} 1 {}",
                n_dy(&t.f64),
                slots(&t.f64),
                t.f64.len()
            )
            .as_str()
        )
    );
    let mut compared = 0;
    for i in 0..=24 {
        for (name, want) in [
            ("f64", expected_line::<f64>("f64", &t.f64, i)),
            ("f32", expected_line::<f32>("f32", &t.f32, i)),
            ("g64", expected_line::<f64>("g64", &t.f64, i)),
            ("g32", expected_line::<f32>("g32", &t.f32, i)),
        ] {
            let got = lines
                .iter()
                .find(|l| l.starts_with(&format!("{name} {i} ")))
                .unwrap_or_else(|| panic!("no {name} line {i}"));
            assert_eq!(*got, want, "{name} dy {}", -8.0 + 0.5 * i as f64);
            compared += 1;
        }
    }
    assert_eq!(compared, 100);
    // every status the C program checked (4 successful loads and steps, 32 bad inputs; it
    // exits 1 on a mismatch)
    assert_eq!(lines.iter().filter(|l| l.starts_with("bad ")).count(), 36);
}

fn step64(bytes: &[u8], len: usize, inp: &wrc_step_input_f64) -> (wrc_status, wrc_step_output_f64) {
    let mut out = wrc_step_output_f64::default();
    // SAFETY: `bytes` has at least `len` bytes (callers pass len ≤ bytes.len()), input and
    // output are valid references.
    let s = unsafe { wrc_step_f64(bytes.as_ptr(), len, inp, &mut out) };
    (s, out)
}

fn check64(bytes: &[u8], len: usize) -> wrc_status {
    // SAFETY: `bytes` has at least `len` bytes; out_info may be NULL.
    unsafe { wrc_table_check_f64(bytes.as_ptr(), len, std::ptr::null_mut()) }
}

fn c_input(dy: f64) -> wrc_step_input_f64 {
    let speed = 100.0 / 3.6 * 1000.0;
    wrc_step_input_f64 {
        dy,
        fz: 83_300.0,
        speed,
        pitch_rate: speed / 460.0,
        mu: 0.3,
        ..Default::default()
    }
}

#[test]
fn rust_callers_get_the_same_results_and_status_codes() {
    use wrc_status::*;
    let t = tables();
    let b = &t.f64[..];
    let n = b.len();
    let mut info = wrc_table_info::default();
    // SAFETY: valid slice and output reference.
    let s = unsafe { wrc_table_check_f64(b.as_ptr(), n, &mut info) };
    assert_eq!(s, WRC_OK);
    assert_eq!(
        (info.slots, info.strips, info.total_bytes),
        (slots(b), 32, n)
    );
    assert!(info.slots as usize <= K);
    // the sweep through the entry point equals the kernel's step
    let table = ContactTable::<f64>::from_bytes(b).unwrap();
    for i in 0..=24 {
        let dy = -8.0 + 0.5 * i as f64;
        let (s, o) = step64(b, n, &c_input(dy));
        assert_eq!(s, WRC_OK, "dy {dy}");
        let r = step::<f64, K, ST>(&table, &input::<f64>(i)).unwrap();
        assert_eq!(o.n_slots, slots(b));
        assert_eq!(o.vertical_load.to_bits(), r.vertical_load.to_bits());
        for (c, k) in o.slots.iter().zip(r.slots.iter()) {
            assert_eq!(c.fx.to_bits(), k.fx.to_bits());
            assert_eq!(c.fy.to_bits(), k.fy.to_bits());
            assert_eq!(c.mz.to_bits(), k.mz.to_bits());
            assert_eq!(c.load.to_bits(), k.load.to_bits());
        }
        assert_eq!(o.slots[3], wrc_slot_f64::default());
    }
    let with = |f: &dyn Fn(&mut wrc_step_input_f64)| {
        let mut i = c_input(0.0);
        f(&mut i);
        step64(b, n, &i).0
    };
    assert_eq!(with(&|i| i.fz = f64::NAN), WRC_ERR_NON_FINITE);
    assert_eq!(with(&|i| i.dy = f64::INFINITY), WRC_ERR_NON_FINITE);
    assert_eq!(with(&|i| i.fz = -83_300.0), WRC_ERR_NON_POSITIVE);
    assert_eq!(with(&|i| i.mu = 0.0), WRC_ERR_NON_POSITIVE);
    assert_eq!(with(&|i| i.dy = 30.0), WRC_ERR_OUT_OF_RANGE);
    assert_eq!(with(&|i| i.fz = 1e7), WRC_ERR_OUT_OF_RANGE);
    assert_eq!(with(&|i| i.normalisation = 7), WRC_ERR_BAD_ARGUMENT);
    assert_eq!(with(&|i| i.normalisation = 1), WRC_OK);
    // damaged, truncated, foreign tables
    let mut bad = t.f64.clone();
    bad[4000] ^= 0x10;
    assert_eq!(check64(&bad, n), WRC_ERR_TABLE_CHECKSUM);
    bad[4000] ^= 0x10;
    bad[0] ^= 1;
    assert_eq!(step64(&bad, n, &c_input(0.0)).0, WRC_ERR_TABLE_MAGIC);
    assert_eq!(check64(b, n - 1), WRC_ERR_TABLE_LENGTH);
    assert_eq!(check64(b, 100), WRC_ERR_TABLE_LENGTH);
    assert_eq!(step64(b, n - 1, &c_input(0.0)).0, WRC_ERR_TABLE_LENGTH);
    assert_eq!(check64(&t.f32, t.f32.len()), WRC_ERR_TABLE_PRECISION);
    assert_eq!(
        check64(&t.over_capacity, t.over_capacity.len()),
        WRC_ERR_CAPACITY
    );
    // a corrupted count in the header (slots 0) is a bad table
    let mut bad = t.f64.clone();
    bad[24..28].copy_from_slice(&0u32.to_le_bytes());
    assert_eq!(check64(&bad, n), WRC_ERR_BAD_TABLE);
    // null pointers
    let mut out = wrc_step_output_f64::default();
    // SAFETY: NULL pointers are what is tested; the others are valid.
    unsafe {
        assert_eq!(
            wrc_table_check_f64(std::ptr::null(), n, &mut info),
            WRC_ERR_NULL_POINTER
        );
        assert_eq!(info, wrc_table_info::default());
        assert_eq!(
            wrc_step_f64(std::ptr::null(), n, &c_input(0.0), &mut out),
            WRC_ERR_NULL_POINTER
        );
        assert_eq!(
            wrc_step_f64(b.as_ptr(), n, std::ptr::null(), &mut out),
            WRC_ERR_NULL_POINTER
        );
        assert_eq!(
            wrc_step_f64(b.as_ptr(), n, &c_input(0.0), std::ptr::null_mut()),
            WRC_ERR_NULL_POINTER
        );
        assert_eq!(
            wrc_step_f64(b.as_ptr(), usize::MAX, &c_input(0.0), &mut out),
            WRC_ERR_BAD_ARGUMENT
        );
        let mut len = 0usize;
        assert_eq!(
            wrc_table_bytes_f64(n_dy(&t.f64), 5, slots(&t.f64), 32, &mut len),
            WRC_OK
        );
        assert_eq!(len, n);
        assert_eq!(
            wrc_table_bytes_f32(n_dy(&t.f32), 5, slots(&t.f32), 32, &mut len),
            WRC_OK
        );
        assert_eq!(len, t.f32.len());
        assert_eq!(
            wrc_table_bytes_f64(u32::MAX, u32::MAX, u32::MAX, u32::MAX, &mut len),
            WRC_ERR_BAD_ARGUMENT
        );
        let name = std::ffi::CStr::from_ptr(wrc_status_name(WRC_ERR_CAPACITY as i32));
        assert_eq!(name.to_str(), Ok("WRC_ERR_CAPACITY"));
    }
    // f32 entry point
    let b32 = &t.f32[..];
    let speed = (100.0 / 3.6 * 1000.0) as f32;
    let i32in = wrc_step_input_f32 {
        dy: -2.0,
        fz: 83_300.0,
        speed,
        pitch_rate: speed / 460.0,
        mu: 0.3,
        ..Default::default()
    };
    let mut o32 = wrc_step_output_f32::default();
    // SAFETY: valid slice and references.
    let s = unsafe { wrc_step_f32(b32.as_ptr(), b32.len(), &i32in, &mut o32) };
    assert_eq!(s, WRC_OK);
    assert!((o32.vertical_load - 83_300.0).abs() < 100.0);
}

#[test]
fn threads_stepping_on_one_table_get_the_single_threaded_results() {
    let t = tables();
    let b = &t.f64[..];
    let single: Vec<wrc_step_output_f64> = (0..=24)
        .map(|i| step64(b, b.len(), &c_input(-8.0 + 0.5 * i as f64)).1)
        .collect();
    std::thread::scope(|s| {
        let hs: Vec<_> = (0..4)
            .map(|_| {
                s.spawn(|| {
                    (0..=24)
                        .map(|i| step64(b, b.len(), &c_input(-8.0 + 0.5 * i as f64)).1)
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        for h in hs {
            assert_eq!(h.join().unwrap(), single);
        }
    });
}
