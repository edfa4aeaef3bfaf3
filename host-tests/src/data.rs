//! Locating the project's shared data (`../shared/data` next to the repository).

use std::path::PathBuf;

/// The `shared/data` directory: `$WRC_SHARED_DATA` if set, else the first `shared/data` found
/// beside the repository or beside one of its ancestors (`<repo>/../shared/data` in CI and in the
/// main checkout; also found from git worktrees nested deeper).
pub fn shared_data_dir() -> PathBuf {
    if let Ok(p) = std::env::var("WRC_SHARED_DATA") {
        return PathBuf::from(p);
    }
    let manifest = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    for dir in manifest.ancestors().skip(1) {
        let cand = dir.join("shared").join("data");
        if cand.is_dir() {
            return cand;
        }
    }
    manifest.join("..").join("..").join("shared").join("data")
}

/// Path of a file below `shared/data`.
pub fn shared_file(rel: &str) -> PathBuf {
    shared_data_dir().join(rel)
}

#[cfg(test)]
mod tests {
    #[test]
    fn shared_data_is_present() {
        assert!(super::shared_file("kalker_coefficients.csv").is_file());
    }
}
