//! Minimal reader for the shared CSV tables (`#` comment lines, one header line, comma separated).

use std::path::Path;

/// A CSV table: the header's column names and the data rows as strings.
#[derive(Clone, Debug)]
pub struct Table {
    /// Column names.
    pub header: Vec<String>,
    /// Data rows (same length as the header).
    pub rows: Vec<Vec<String>>,
}

impl Table {
    /// Reads `path`, skipping blank lines and lines starting with `#`. Panics with a message on I/O
    /// errors or ragged rows (test helper).
    pub fn read(path: &Path) -> Table {
        let text = std::fs::read_to_string(path)
            .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
        let mut lines = text
            .lines()
            .map(str::trim)
            .filter(|l| !l.is_empty() && !l.starts_with('#'));
        let header: Vec<String> = lines
            .next()
            .unwrap_or_else(|| panic!("{}: no header", path.display()))
            .split(',')
            .map(|s| s.trim().to_string())
            .collect();
        let rows: Vec<Vec<String>> = lines
            .map(|l| {
                l.split(',')
                    .map(|s| s.trim().to_string())
                    .collect::<Vec<_>>()
            })
            .collect();
        for r in &rows {
            assert_eq!(
                r.len(),
                header.len(),
                "{}: ragged row {r:?}",
                path.display()
            );
        }
        Table { header, rows }
    }

    /// Index of column `name` (panics if absent).
    pub fn col(&self, name: &str) -> usize {
        self.header
            .iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("no column {name} in {:?}", self.header))
    }

    /// Cell as `f64` (`None` if empty or not a number).
    pub fn f64(&self, row: usize, name: &str) -> Option<f64> {
        self.rows[row][self.col(name)].parse().ok()
    }

    /// Cell as string.
    pub fn str(&self, row: usize, name: &str) -> &str {
        &self.rows[row][self.col(name)]
    }
}
