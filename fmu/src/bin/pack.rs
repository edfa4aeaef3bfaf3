//! `wrc-fmu-pack [--table FILE] --out target/wrc.fmu`: builds the packaged contact table (or takes
//! an f64 table written by `wrc table`, validated first) and writes the FMU (docs/fmu.md). Build the shared library first (`cargo build --release -p wrc-fmu`): it is
//! taken from next to this executable (`libwrc_fmu.so` in `target/release`).

use std::path::PathBuf;

fn run() -> Result<(), String> {
    let mut out = PathBuf::from("target/wrc.fmu");
    let mut given: Option<PathBuf> = None;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out" => out = args.next().ok_or("--out needs a path")?.into(),
            "--table" => given = Some(args.next().ok_or("--table needs a path")?.into()),
            "-h" | "--help" => {
                println!(
                    "usage: wrc-fmu-pack [--table FILE] [--out FILE.fmu]   (default target/wrc.fmu; \
                     FILE: an f64 table of `wrc table`, else the built-in S1002/UIC60 one)"
                );
                return Ok(());
            }
            _ => return Err(format!("unknown argument {a:?} (see --help)")),
        }
    }
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let dir = exe.parent().ok_or("no directory of the executable")?;
    let lib = dir.join("libwrc_fmu.so");
    let library = std::fs::read(&lib).map_err(|e| {
        format!(
            "{}: {e} (build it first: cargo build --release -p wrc-fmu)",
            lib.display()
        )
    })?;
    if let Some(path) = given {
        let table =
            std::fs::read(&path).map_err(|e| format!("{}: cannot read: {e}", path.display()))?;
        let t = wrc_kernel::table::ContactTable::<f64>::from_bytes(&table).map_err(|e| {
            format!(
                "{}: {e} (the FMU takes f64 tables of `wrc table`)",
                path.display()
            )
        })?;
        if t.slots() > wrc_fmu::model::SLOTS || t.strips() > wrc_fmu::model::STRIP_CAP {
            return Err(format!(
                "{}: {} slots × {} strips; the FMU steps at most {} × {}",
                path.display(),
                t.slots(),
                t.strips(),
                wrc_fmu::model::SLOTS,
                wrc_fmu::model::STRIP_CAP
            ));
        }
        wrc_fmu::pack::write_fmu(&out, &library, &table)?;
        println!(
            "{}: modelDescription.xml (GUID {}), binaries/linux64/wrc.so ({} bytes), resources/table.bin \
             ({} bytes, from {})",
            out.display(),
            wrc_fmu::xml::guid(),
            library.len(),
            table.len(),
            path.display()
        );
        return Ok(());
    }
    let t0 = std::time::Instant::now();
    let (table, rep) = wrc_fmu::pack::default_table()?;
    if rep.not_converged != 0 {
        return Err(format!("table: {} nodes not converged", rep.not_converged));
    }
    wrc_fmu::pack::write_fmu(&out, &library, &table)?;
    println!(
        "{}: modelDescription.xml (GUID {}), binaries/linux64/wrc.so ({} bytes, from {}), \
         resources/table.bin ({} bytes, {} shift nodes, {} slots used; built in {:.1} s)",
        out.display(),
        wrc_fmu::xml::guid(),
        library.len(),
        lib.display(),
        table.len(),
        rep.dy_nodes,
        rep.slots_used,
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}

fn main() {
    if let Err(e) = run() {
        eprintln!("wrc-fmu-pack: {e}");
        std::process::exit(1);
    }
}
