//! Locating the repository's `data/` directory at run time (profiles, coefficient tables, CONTACT
//! reference extracts; see `data/README.md`).
//!
//! The directory is found when the program runs, never through a path frozen at build time, so a
//! moved checkout or a shared target directory reads its own data: `$WRC_DATA` if set, else the first
//! `data/` holding `README.md` found walking up from the current directory, then from the running
//! executable's directory (`cargo test` and `cargo run` start inside the repository).

use std::path::{Path, PathBuf};

/// The environment variable that names the data directory explicitly.
pub const DATA_ENV: &str = "WRC_DATA";

/// The `data/` directories searched when [`DATA_ENV`] is unset, in order: upwards from the current
/// directory, then upwards from the running executable's directory.
fn candidates() -> impl Iterator<Item = PathBuf> {
    let cwd = std::env::current_dir().ok();
    let exe_dir = std::env::current_exe()
        .ok()
        .and_then(|e| e.parent().map(Path::to_path_buf));
    cwd.into_iter().chain(exe_dir).flat_map(|start| {
        start
            .ancestors()
            .map(|d| d.join("data"))
            .collect::<Vec<_>>()
    })
}

fn is_data_dir(dir: &Path) -> bool {
    dir.join("README.md").is_file() && dir.join("profiles").is_dir()
}

/// The data directory, or an error that says where it was looked for and how to point at it.
pub fn try_data_dir() -> Result<PathBuf, String> {
    if let Ok(p) = std::env::var(DATA_ENV) {
        let p = PathBuf::from(p);
        return if p.is_dir() {
            Ok(p)
        } else {
            Err(format!("{DATA_ENV}={} is not a directory", p.display()))
        };
    }
    candidates().find(|d| is_data_dir(d)).ok_or_else(|| {
        format!(
            "wrc's data directory was not found: looked for data/README.md upwards from the current \
             directory and from the executable's directory; run from inside the repository or set \
             {DATA_ENV}=<repository>/data"
        )
    })
}

/// The data directory. Panics with [`try_data_dir`]'s message when it is not found (test and study
/// code; the `wrc` tool has its defaults built in).
pub fn data_dir() -> PathBuf {
    try_data_dir().unwrap_or_else(|e| panic!("{e}"))
}

/// Path of a file below the data directory; panics naming the file, the place looked in and
/// [`DATA_ENV`] when it does not exist.
pub fn data_file(rel: &str) -> PathBuf {
    let p = data_dir().join(rel);
    if !p.is_file() {
        panic!(
            "data file {rel} not found at {}; set {DATA_ENV}=<repository>/data to point at another copy",
            p.display()
        );
    }
    p
}

#[cfg(test)]
mod tests {
    #[test]
    fn data_is_found_at_run_time() {
        assert!(super::data_file("kalker_coefficients.csv").is_file());
        assert!(super::data_file("profiles/MBench_S1002_v3.prw").is_file());
    }
}
