//! Writes `bench/firmware/src/expected.rs`: the host's results of every on-target test case, in
//! `f32` and `f64`, bit-exact (`from_bits`), for the QEMU firmware to compare against; and
//! `bench/firmware/src/profiles.rs`: the S1002 wheel and UIC60 rail tables (host preprocessing of
//! `data/profiles/`) as const data in both precisions, bit-exact copies of the tables the
//! host used for the wheel cases; and `table_f32_<c>.bin` / `table_f64_<c>.bin` beside them: the
//! contact tables of the step cases (`wrc_host_tests::realtime::CASES`, S1002/UIC60 at 1353 and 1360 mm, right
//! and left wheel, `cases::SWEEP_TABLES`; the first as `examples/realtime_step.rs`) built with
//! `wrc_kernel::table::build_table`, which the firmware embeds with `include_bytes!` and reads in
//! place.
//!
//! Usage: `cargo run -p wrc-bench --release --bin firmware-expected [OUTPUT]` (default output:
//! `bench/firmware/src/expected.rs`; `profiles.rs` goes beside it). `.ci/run` runs it before the
//! cross build; the files are generated, not committed (see `.gitignore`), so they always match
//! the kernel and the profile preprocessing being tested.

use std::fmt::Write as _;
use std::path::PathBuf;

#[path = "../../firmware/src/cases.rs"]
#[allow(dead_code)]
mod cases;

use cases::{NoMeter, Outs, WheelProfiles, NAMES, N_CASES, PROFILE_NODES, STEP_SLOTS, STEP_STRIPS};
use std::sync::OnceLock;
use wrc_kernel::profile::ProfileTable;
use wrc_kernel::table::narrow_to_f32;

type Table<T> = ProfileTable<T, PROFILE_NODES>;

/// The Manchester tables copied into the firmware's capacity (only `len` nodes are used).
fn shrink<T: wrc_kernel::Real>(t: &ProfileTable<T, 2048>) -> &'static Table<T> {
    assert!(
        t.len <= PROFILE_NODES,
        "profile has {} nodes > {PROFILE_NODES}",
        t.len
    );
    let mut s = Box::new(Table::<T>::empty(t.kind));
    s.len = t.len;
    s.ds = t.ds;
    s.filter_wavelength = t.filter_wavelength;
    s.y[..t.len].copy_from_slice(&t.y[..t.len]);
    s.z[..t.len].copy_from_slice(&t.z[..t.len]);
    s.angle[..t.len].copy_from_slice(&t.angle[..t.len]);
    s.curvature[..t.len].copy_from_slice(&t.curvature[..t.len]);
    s.dz_dy[..t.len].copy_from_slice(&t.dz_dy[..t.len]);
    s.d2z_dy2[..t.len].copy_from_slice(&t.d2z_dy2[..t.len]);
    Box::leak(s)
}

type Pair<T> = (&'static Table<T>, &'static Table<T>);

fn pair<T: wrc_kernel::Real>() -> Pair<T> {
    let (w, r) = wrc_bench::tables::<T>();
    (shrink(&w), shrink(&r))
}

/// The state sweep's contact table `c` (`cases::SWEEP_TABLES`: back-to-back and side) in f64:
/// the host tests' table of that case (`wrc_host_tests::realtime::CASES`, its grid from flange to
/// flange, 3 slots × 16 strips of capacity, the recommended configuration at μ 0.3), as
/// `examples/realtime_step.rs` builds table 0.
fn sweep_table_f64(c: usize) -> &'static [u8] {
    let case = wrc_host_tests::realtime::CASES[c];
    let (b2b, side) = cases::SWEEP_TABLES[c];
    assert!(
        case.back_to_back == b2b && case.side == side,
        "SWEEP_TABLES follow CASES"
    );
    let (out, rep) = case
        .table::<f64, STEP_SLOTS, STEP_STRIPS>(&case.spec())
        .expect("contact table build");
    println!(
        "contact table {c} ({b2b} mm, {side:?}) f64: {} shift nodes, {} nodes solved ({} not converged, {} slots used), {} bytes",
        rep.dy_nodes, rep.nodes, rep.not_converged, rep.slots_used, rep.bytes
    );
    out.leak()
}

/// The f64 tables of the state sweep, built once (in parallel: the 1360 mm ones take longest).
fn sweep_tables_f64() -> &'static [&'static [u8]; 4] {
    static B: OnceLock<[&'static [u8]; 4]> = OnceLock::new();
    B.get_or_init(|| {
        std::thread::scope(|s| {
            let h: Vec<_> = (0..4)
                .map(|c| s.spawn(move || sweep_table_f64(c)))
                .collect();
            let v: Vec<&'static [u8]> = h.into_iter().map(|h| h.join().expect("build")).collect();
            [v[0], v[1], v[2], v[3]]
        })
    })
}

impl WheelProfiles for f32 {
    fn tables() -> Pair<f32> {
        static P: OnceLock<Pair<f32>> = OnceLock::new();
        *P.get_or_init(pair::<f32>)
    }
    /// The f64 table rounded to f32 (`table::narrow_to_f32`): the f64 solve rounded once. The
    /// f32 build's own solve differed from the f64 one by up to 1.07e-4 of μF_z in the step's
    /// ΣF_x on the refined grid (dy −3.53 mm), above the firmware's 1e-4 f32-vs-f64 limit.
    fn contact_table() -> &'static [u8] {
        Self::sweep_table(0)
    }
    fn sweep_table(c: usize) -> &'static [u8] {
        static B: OnceLock<[&'static [u8]; 4]> = OnceLock::new();
        B.get_or_init(|| {
            sweep_tables_f64().map(|src| {
                let mut out = vec![0u8; src.len()];
                let n = narrow_to_f32(src, &mut out).expect("f32 copy of the f64 table");
                out.truncate(n);
                &*out.leak()
            })
        })[c]
    }
}

impl WheelProfiles for f64 {
    fn tables() -> Pair<f64> {
        static P: OnceLock<Pair<f64>> = OnceLock::new();
        *P.get_or_init(pair::<f64>)
    }
    fn contact_table() -> &'static [u8] {
        Self::sweep_table(0)
    }
    fn sweep_table(c: usize) -> &'static [u8] {
        sweep_tables_f64()[c]
    }
}

/// Rust source of one table as a `static` (values bit-exact, nodes beyond `len` zero).
fn table_source<T: wrc_kernel::Real>(
    s: &mut String,
    name: &str,
    ty: &str,
    t: &Table<T>,
    bits: impl Fn(T) -> String,
) {
    let kind = match t.kind {
        wrc_kernel::profile::ProfileKind::Rail => "Rail",
        wrc_kernel::profile::ProfileKind::Wheel => "Wheel",
    };
    writeln!(
        s,
        "pub static {name}: ProfileTable<{ty}, {PROFILE_NODES}> = ProfileTable {{"
    )
    .unwrap();
    writeln!(s, "    kind: ProfileKind::{kind},\n    len: {},", t.len).unwrap();
    writeln!(
        s,
        "    ds: {},\n    filter_wavelength: {},",
        bits(t.ds),
        bits(t.filter_wavelength)
    )
    .unwrap();
    for (field, arr) in [
        ("y", &t.y),
        ("z", &t.z),
        ("angle", &t.angle),
        ("curvature", &t.curvature),
        ("dz_dy", &t.dz_dy),
        ("d2z_dy2", &t.d2z_dy2),
    ] {
        writeln!(s, "    {field}: [").unwrap();
        for x in arr.iter() {
            writeln!(s, "        {},", bits(*x)).unwrap();
        }
        s.push_str("    ],\n");
    }
    s.push_str("};\n");
}

fn write_profiles(out: &std::path::Path) {
    let mut s = String::new();
    s.push_str(
        "// @generated by `cargo run -p wrc-bench --release --bin firmware-expected`: the S1002 wheel\n\
         // and UIC60 rail tables of the host (default preprocessing), bit-exact. Do not edit; not\n\
         // committed.\n\n\
         use wrc_kernel::profile::{ProfileKind, ProfileTable};\n\n",
    );
    let (w32, r32) = f32::tables();
    let (w64, r64) = f64::tables();
    let b32 = |x: f32| format!("f32::from_bits(0x{:08x})", x.to_bits());
    let b64 = |x: f64| format!("f64::from_bits(0x{:016x})", x.to_bits());
    s.push_str("/// S1002 wheel, f32.\n");
    table_source(&mut s, "WHEEL_F32", "f32", w32, b32);
    s.push_str("/// UIC60 rail, f32.\n");
    table_source(&mut s, "RAIL_F32", "f32", r32, b32);
    s.push_str("/// S1002 wheel, f64.\n");
    table_source(&mut s, "WHEEL_F64", "f64", w64, b64);
    s.push_str("/// UIC60 rail, f64.\n");
    table_source(&mut s, "RAIL_F64", "f64", r64, b64);
    std::fs::write(out, s).unwrap_or_else(|e| panic!("writing {}: {e}", out.display()));
    println!("wrote {}", out.display());
}

fn run_all<T: WheelProfiles>() -> Vec<Outs<T>> {
    let table = cases::table::<T, NoMeter>();
    (0..N_CASES)
        .map(|i| {
            let mut o = Outs::<T>::new();
            if let Err(e) = table[i](&mut NoMeter, &mut o) {
                panic!("case `{}` failed on the host: {e}", NAMES[i]);
            }
            assert!(!o.overflow, "case `{}` pushed too many values", NAMES[i]);
            o
        })
        .collect()
}

fn main() {
    let out = std::env::args_os()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("firmware/src/expected.rs")
        });
    let r32 = run_all::<f32>();
    let r64 = run_all::<f64>();
    let mut s = String::new();
    s.push_str(
        "// @generated by `cargo run -p wrc-bench --release --bin firmware-expected`: the host's\n\
         // results of bench/firmware/src/cases.rs (bit-exact). Do not edit; not committed.\n\n",
    );
    writeln!(s, "/// Case names the values were generated for.").unwrap();
    writeln!(s, "pub const NAMES: [&str; {N_CASES}] = {NAMES:?};").unwrap();
    writeln!(s, "/// Host f32 results per case.").unwrap();
    writeln!(s, "pub const F32: [&[f32]; {N_CASES}] = [").unwrap();
    for (i, o) in r32.iter().enumerate() {
        writeln!(s, "    // {}", NAMES[i]).unwrap();
        s.push_str("    &[\n");
        for x in &o.v[..o.n] {
            writeln!(s, "        f32::from_bits(0x{:08x}), // {x:e}", x.to_bits()).unwrap();
        }
        s.push_str("    ],\n");
    }
    s.push_str("];\n");
    writeln!(s, "/// Host f64 results per case.").unwrap();
    writeln!(s, "pub const F64: [&[f64]; {N_CASES}] = [").unwrap();
    for (i, o) in r64.iter().enumerate() {
        writeln!(s, "    // {}", NAMES[i]).unwrap();
        s.push_str("    &[\n");
        for x in &o.v[..o.n] {
            writeln!(
                s,
                "        f64::from_bits(0x{:016x}), // {x:e}",
                x.to_bits()
            )
            .unwrap();
        }
        s.push_str("    ],\n");
    }
    s.push_str("];\n");
    for i in 0..N_CASES {
        assert_eq!(
            r32[i].n, r64[i].n,
            "case `{}` pushes different counts in f32 and f64",
            NAMES[i]
        );
    }
    std::fs::write(&out, s).unwrap_or_else(|e| panic!("writing {}: {e}", out.display()));
    println!("wrote {} ({} cases)", out.display(), N_CASES);
    write_profiles(&out.with_file_name("profiles.rs"));
    for c in 0..cases::SWEEP_TABLES.len() {
        for (name, bytes) in [
            (format!("table_f32_{c}.bin"), f32::sweep_table(c)),
            (format!("table_f64_{c}.bin"), f64::sweep_table(c)),
        ] {
            let p = out.with_file_name(name);
            std::fs::write(&p, bytes).unwrap_or_else(|e| panic!("writing {}: {e}", p.display()));
            println!("wrote {} ({} bytes)", p.display(), bytes.len());
        }
    }
    // The firmware's f32-against-host-f64 check, run here first: a case that fails it on the
    // host would fail on every board.
    for i in 0..N_CASES {
        let (mut worst, mut at) = (0.0f64, 0);
        for k in 0..r32[i].n {
            if let cases::Kind::Real { floor } = r32[i].kind[k] {
                let w = r64[i].v[k];
                let den = w.abs().max(floor).max(f64::MIN_POSITIVE);
                let d = (r32[i].v[k] as f64 - w).abs() / den;
                if d > worst {
                    (worst, at) = (d, k);
                }
            }
        }
        println!(
            "  {:24} f32 vs f64: worst deviation {worst:.2e} at #{at} (firmware limit 1e-4)",
            NAMES[i]
        );
    }
}
