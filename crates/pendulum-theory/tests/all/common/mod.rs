//! Shared by the reference tests: loading mpmath data files and tracking
//! the worst error. Each value is stored as `hi + lo` (two doubles).
#![allow(dead_code)]

pub mod parts;

pub struct Reference {
    pub rows: Vec<Vec<f64>>,
}

impl Reference {
    /// Loads `tests/data/NAME`, skipping `#` comments and the header.
    pub fn load(name: &str, columns: usize) -> Self {
        let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        let rows: Vec<Vec<f64>> = text
            .lines()
            .filter(|l| !l.starts_with('#'))
            .skip(1)
            .map(|l| {
                let row: Vec<f64> = l.split(',').map(|c| c.parse().unwrap()).collect();
                assert_eq!(row.len(), columns, "{name}: {l}");
                row
            })
            .collect();
        assert!(rows.len() > 100, "{name}: only {} rows", rows.len());
        Reference { rows }
    }
}

/// Error of `value` against `hi + lo`, in ulp of `hi`.
pub fn ulp_error(value: f64, hi: f64, lo: f64) -> f64 {
    let ulp = hi.abs().next_up() - hi.abs();
    ((value - hi) - lo).abs() / ulp
}

/// Tracks the worst error and where it happened.
pub struct Worst {
    name: &'static str,
    error: f64,
    at: f64,
}

impl Worst {
    pub fn new(name: &'static str) -> Self {
        Worst {
            name,
            error: 0.0,
            at: f64::NAN,
        }
    }
    pub fn see(&mut self, error: f64, at: f64) {
        assert!(!error.is_nan(), "{}: NaN error at {at:e}", self.name);
        if error > self.error {
            self.error = error;
            self.at = at;
        }
    }
    /// Reports the worst error; returns a failure message if it is too large.
    pub fn report(&self, allowed: f64) -> Option<String> {
        eprintln!(
            "{:<34} max error {:6.2} ulp (allowed {allowed}) at {:e}",
            self.name, self.error, self.at
        );
        (self.error > allowed).then(|| {
            format!(
                "{}: {} ulp at {:e} exceeds {allowed}",
                self.name, self.error, self.at
            )
        })
    }
}

/// Reports every quantity, then fails if any exceeded its allowance.
pub fn check_all(results: &[(&Worst, f64)]) {
    let failures: Vec<String> = results
        .iter()
        .filter_map(|(w, allowed)| w.report(*allowed))
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
pub mod logs;
pub mod records;
