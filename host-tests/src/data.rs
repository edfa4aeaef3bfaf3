//! Locating the project's shared data (`../shared/data` next to the repository).

use std::path::PathBuf;

/// The `shared/data` directory: `$WRC_SHARED_DATA` if set, else `<repo>/../shared/data`.
pub fn shared_data_dir() -> PathBuf {
    if let Ok(p) = std::env::var("WRC_SHARED_DATA") {
        return PathBuf::from(p);
    }
    let repo = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("host-tests lives inside the repository")
        .to_path_buf();
    repo.parent()
        .expect("repository has a parent directory")
        .join("shared")
        .join("data")
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
