//! Finds the repository's `memory.x` and links with cortex-m-rt's `link.x` on thumb targets;
//! checks that the host-generated sources and contact tables are present (see `firmware-expected`).

use std::path::PathBuf;

fn main() {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("set by cargo"));
    let root = manifest
        .parent()
        .and_then(|p| p.parent())
        .expect("bench/firmware sits two levels below the repository root")
        .to_path_buf();
    println!("cargo:rustc-link-search={}", root.display());
    println!("cargo:rerun-if-changed={}", root.join("memory.x").display());
    let expected = manifest.join("src").join("expected.rs");
    println!("cargo:rerun-if-changed={}", expected.display());
    let profiles = manifest.join("src").join("profiles.rs");
    println!("cargo:rerun-if-changed={}", profiles.display());
    let tables: Vec<PathBuf> = (0..4)
        .flat_map(|c| [format!("table_f32_{c}.bin"), format!("table_f64_{c}.bin")])
        .map(|f| manifest.join("src").join(f))
        .collect();
    for t in &tables {
        println!("cargo:rerun-if-changed={}", t.display());
    }
    if !expected.is_file() || !profiles.is_file() || tables.iter().any(|t| !t.is_file()) {
        panic!(
            "{}, profiles.rs or the contact tables table_f32_<c>.bin / table_f64_<c>.bin are missing: \
             generate them on the host with \
             `cargo run -p wrc-bench --release --bin firmware-expected` (as .ci/run does)",
            expected.display()
        );
    }
    // Board label printed by the firmware (.ci/run sets it per QEMU machine).
    println!("cargo:rerun-if-env-changed=WRC_BOARD");
    let board = std::env::var("WRC_BOARD").unwrap_or_else(|_| "unspecified-board".into());
    println!("cargo:rustc-env=WRC_BOARD={board}");
    if std::env::var("TARGET")
        .unwrap_or_default()
        .starts_with("thumb")
    {
        println!("cargo:rustc-link-arg=-Tlink.x");
    }
}
