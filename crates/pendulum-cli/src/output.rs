//! Rendering: aligned text for people, JSON and CSV for programs.
//!
//! Every command builds its whole output as a `String` first and prints it
//! at the end, so an error half-way leaves nothing on standard output.

use crate::error::CliError;
use serde::Serialize;

/// A two-column summary: labels padded to one width.
#[derive(Default)]
pub struct Summary {
    rows: Vec<(String, String)>,
}

impl Summary {
    /// Adds a row.
    pub fn row(&mut self, label: &str, value: impl Into<String>) -> &mut Self {
        self.rows.push((label.to_string(), value.into()));
        self
    }

    /// The rows, labels left-aligned.
    pub fn render(&self) -> String {
        let width = self
            .rows
            .iter()
            .map(|(l, _)| l.chars().count())
            .max()
            .unwrap_or(0);
        let mut out = String::new();
        for (label, value) in &self.rows {
            let pad = width - label.chars().count();
            out.push_str(&format!("{label}{}  {value}\n", " ".repeat(pad)));
        }
        out
    }
}

/// One JSON document, pretty-printed, with a final newline.
pub fn json<T: Serialize + ?Sized>(value: &T) -> Result<String, CliError> {
    let mut text = serde_json::to_string_pretty(value)
        .map_err(|e| CliError::other(format!("could not encode JSON: {e}")))?;
    text.push('\n');
    Ok(text)
}

/// CSV with a header row taken from the field names.
pub fn csv<T: Serialize>(rows: &[T]) -> Result<String, CliError> {
    let mut writer = csv::Writer::from_writer(Vec::new());
    for row in rows {
        writer
            .serialize(row)
            .map_err(|e| CliError::other(format!("could not encode CSV: {e}")))?;
    }
    let bytes = writer
        .into_inner()
        .map_err(|e| CliError::other(format!("could not encode CSV: {e}")))?;
    String::from_utf8(bytes).map_err(|e| CliError::other(format!("could not encode CSV: {e}")))
}

/// A right-aligned table with a header, for people.
pub fn table(header: &[&str], rows: &[Vec<String>]) -> String {
    let mut widths: Vec<usize> = header.iter().map(|h| h.chars().count()).collect();
    for row in rows {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let line = |cells: Vec<String>| {
        let padded: Vec<String> = cells
            .iter()
            .zip(&widths)
            .map(|(c, &w)| format!("{}{c}", " ".repeat(w - c.chars().count())))
            .collect();
        padded.join("  ").trim_end().to_string() + "\n"
    };
    let mut out = line(header.iter().map(|h| h.to_string()).collect());
    for row in rows {
        out.push_str(&line(row.clone()));
    }
    out
}

/// A number for people: `digits` significant digits, no trailing zeros.
pub fn num(value: f64, digits: usize) -> String {
    pendulum_theory::error::format_significant(value, digits)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_for_people() {
        assert_eq!(num(2.000_152_3, 7), "2.000152");
        assert_eq!(num(6.5812, 3), "6.58");
        assert_eq!(num(1.5e-12, 3), "1.5e-12");
        assert_eq!(num(-0.25, 3), "-0.25");
    }

    #[test]
    fn table_aligns_right() {
        let t = table(
            &["a", "bb"],
            &[vec!["1".into(), "2".into()], vec!["10".into(), "3".into()]],
        );
        assert_eq!(t, " a  bb\n 1   2\n10   3\n");
    }
}
