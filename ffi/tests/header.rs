//! The committed C header `ffi/include/wrc.h` is what cbindgen generates from `src/lib.rs` with
//! `cbindgen.toml` (the CI drift check). After changing the interface, regenerate it with
//! `WRC_BLESS=1 cargo test -p wrc-ffi --release --test header` and commit the header.

use std::path::Path;

#[test]
fn committed_header_matches_cbindgen() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let cfg = cbindgen::Config::from_file(dir.join("cbindgen.toml")).expect("cbindgen.toml");
    let mut out = Vec::new();
    cbindgen::Builder::new()
        .with_config(cfg)
        .with_src(dir.join("src/lib.rs"))
        .generate()
        .expect("cbindgen generates the header")
        .write(&mut out);
    let generated = String::from_utf8(out).expect("UTF-8 header");
    let path = dir.join("include/wrc.h");
    if std::env::var_os("WRC_BLESS").is_some() {
        std::fs::write(&path, &generated).expect("write include/wrc.h");
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == generated,
        "ffi/include/wrc.h differs from what cbindgen generates from src/lib.rs: run \
         `WRC_BLESS=1 cargo test -p wrc-ffi --release --test header` and commit the header"
    );
}
