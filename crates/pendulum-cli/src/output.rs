//! Rendering: aligned text for people, JSON and CSV for programs.
//!
//! Every command builds its whole output as a `String` first and prints it
//! at the end, so an error half-way leaves nothing on standard output.
//! Nothing non-finite is printed: [`json`] refuses a NaN or infinite
//! number (serde_json would silently print `null`), naming its key, and
//! `main` passes every text through [`check_finite_text`]. A value that is
//! legitimately undefined is an `Option` (JSON `null`) and a word in text.

use crate::error::CliError;
use serde::Serialize;
use serde_value::Value;

/// Warnings from the parts a command shares (the file reader), printed on
/// standard error after the command's own output is built.
static WARNINGS: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());

/// Adds a warning to be printed on standard error as `warning: …`.
pub fn warn(message: String) {
    if let Ok(mut w) = WARNINGS.lock() {
        if !w.contains(&message) {
            w.push(message);
        }
    }
}

/// The warnings added so far, emptied.
pub fn take_warnings() -> Vec<String> {
    WARNINGS
        .lock()
        .map(|mut w| w.drain(..).collect())
        .unwrap_or_default()
}

/// What a command prints, and its exit status.
#[derive(Debug, Default)]
pub struct Output {
    /// For standard output.
    pub stdout: String,
    /// For standard error (a summary when standard output carries data).
    pub stderr: String,
    /// 0, or 130 for a run that Ctrl-C ended with its files complete.
    pub status: u8,
}

impl From<String> for Output {
    fn from(stdout: String) -> Self {
        Self {
            stdout,
            ..Self::default()
        }
    }
}

/// The words of `text` as the finiteness check splits them.
fn words(text: &str) -> impl Iterator<Item = &str> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '.' || c == '_'))
}

/// Refuses text holding a non-finite number (`NaN`, `inf`, `-inf` as a
/// word): the one check every printed text passes, whatever made it.
/// Words the user typed (a file called `nan`) are echoes, not results.
pub fn check_finite_text(text: &str) -> Result<(), CliError> {
    let typed: Vec<String> = std::env::args_os()
        .skip(1)
        .map(|a| a.to_string_lossy().into_owned())
        .collect();
    let typed_words: Vec<&str> = typed.iter().flat_map(|a| words(a)).collect();
    let bad = words(text).find(|word| {
        matches!(*word, "NaN" | "inf" | "infinity" | "Infinity" | "nan")
            && !typed_words.contains(word)
    });
    match bad {
        Some(_) => Err(CliError::other(
            "a result is not a finite number for these inputs (an overflow or an undefined \
             value); please report it with the command line",
        )),
        None => Ok(()),
    }
}

/// The dotted path of the first non-finite number in `value`, if any.
fn non_finite(value: &Value, path: &str) -> Option<String> {
    match value {
        Value::F64(x) if !x.is_finite() => Some(path.to_string()),
        Value::F32(x) if !x.is_finite() => Some(path.to_string()),
        Value::Option(Some(inner)) | Value::Newtype(inner) => non_finite(inner, path),
        Value::Seq(items) => items
            .iter()
            .enumerate()
            .find_map(|(i, v)| non_finite(v, &format!("{path}[{i}]"))),
        Value::Map(map) => map.iter().find_map(|(k, v)| {
            let key = match k {
                Value::String(s) => s.clone(),
                other => format!("{other:?}"),
            };
            let joined = if path.is_empty() {
                key
            } else {
                format!("{path}.{key}")
            };
            non_finite(v, &joined)
        }),
        _ => None,
    }
}

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
    check_json(value)?;
    let mut text = serde_json::to_string_pretty(value)
        .map_err(|e| CliError::other(format!("could not encode JSON: {e}")))?;
    text.push('\n');
    Ok(text)
}

/// Refuses a value holding a number that is not finite (JSON has none).
fn check_json<T: Serialize + ?Sized>(value: &T) -> Result<(), CliError> {
    let tree = serde_value::to_value(value)
        .map_err(|e| CliError::other(format!("could not encode JSON: {e}")))?;
    match non_finite(&tree, "") {
        Some(key) => Err(CliError::other(format!(
            "the result {key} is not a finite number for these inputs (an overflow); \
             please report it with the command line"
        ))),
        None => Ok(()),
    }
}

/// One JSON object on one line (JSON Lines, for output that comes a
/// record at a time), its numbers checked finite as [`json`]'s.
pub fn json_line<T: Serialize + ?Sized>(value: &T) -> Result<String, CliError> {
    check_json(value)?;
    let mut text = serde_json::to_string(value)
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
    csv_text(writer)
}

/// Rows as CSV, each row's keys in the order it writes them, through its
/// JSON: for rows the `csv` crate cannot write (a flattened map of keys a
/// list decides, as the stability rows' deviations). Numbers as JSON
/// writes them (the shortest that reads back), `None` an empty cell.
pub fn csv_flat<T: Serialize>(rows: &[T]) -> Result<String, CliError> {
    let encode = |e: String| CliError::other(format!("could not encode CSV: {e}"));
    let mut writer = csv::Writer::from_writer(Vec::new());
    for (i, row) in rows.iter().enumerate() {
        let json = serde_json::to_string(row).map_err(|e| encode(e.to_string()))?;
        let Ordered(cells) = serde_json::from_str(&json).map_err(|e| encode(e.to_string()))?;
        if i == 0 {
            writer
                .write_record(cells.iter().map(|(k, _)| k.as_str()))
                .map_err(|e| encode(e.to_string()))?;
        }
        let text = |v: &serde_json::Value| match v {
            serde_json::Value::Null => String::new(),
            serde_json::Value::String(s) => s.clone(),
            other => other.to_string(),
        };
        writer
            .write_record(cells.iter().map(|(_, v)| text(v)))
            .map_err(|e| encode(e.to_string()))?;
    }
    csv_text(writer)
}

/// A JSON object's entries in their written order.
struct Ordered(Vec<(String, serde_json::Value)>);

impl<'de> serde::Deserialize<'de> for Ordered {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Entries;
        impl<'de> serde::de::Visitor<'de> for Entries {
            type Value = Ordered;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("an object")
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(
                self,
                mut map: A,
            ) -> Result<Ordered, A::Error> {
                let mut entries = Vec::new();
                while let Some(entry) = map.next_entry()? {
                    entries.push(entry);
                }
                Ok(Ordered(entries))
            }
        }
        d.deserialize_map(Entries)
    }
}

/// The text a CSV writer holds.
fn csv_text(writer: csv::Writer<Vec<u8>>) -> Result<String, CliError> {
    let bytes = writer
        .into_inner()
        .map_err(|e| CliError::other(format!("could not encode CSV: {e}")))?;
    String::from_utf8(bytes).map_err(|e| CliError::other(format!("could not encode CSV: {e}")))
}

/// The columns `names` (comma-separated, in the order given) of a CSV
/// text `csv`, refused in `flag`'s name when one is not among its header's.
pub fn csv_columns(csv: &str, names: &str, flag: &str) -> Result<String, CliError> {
    let encode = |e: csv::Error| CliError::other(format!("could not encode CSV: {e}"));
    let mut reader = csv::Reader::from_reader(csv.as_bytes());
    let header: Vec<String> = reader
        .headers()
        .map_err(encode)?
        .iter()
        .map(String::from)
        .collect();
    let mut picked = Vec::new();
    for name in names.split(',').map(str::trim) {
        match header.iter().position(|h| h == name) {
            Some(i) => picked.push(i),
            None => {
                return Err(CliError::flag(
                    flag,
                    format!(
                        "'{name}' is not a column; the columns are {}",
                        header.join(", ")
                    ),
                ))
            }
        }
    }
    let mut writer = csv::Writer::from_writer(Vec::new());
    writer
        .write_record(picked.iter().map(|&i| header[i].as_str()))
        .map_err(encode)?;
    for record in reader.records() {
        let record = record.map_err(encode)?;
        writer
            .write_record(picked.iter().map(|&i| record.get(i).unwrap_or("")))
            .map_err(encode)?;
    }
    csv_text(writer)
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
    fn non_finite_numbers_are_refused() {
        #[derive(Serialize)]
        struct Inner {
            value_s: f64,
        }
        #[derive(Serialize)]
        struct Outer {
            fine: Option<f64>,
            inner: Vec<Inner>,
        }
        let bad = Outer {
            fine: None,
            inner: vec![
                Inner { value_s: 1.0 },
                Inner {
                    value_s: f64::INFINITY,
                },
            ],
        };
        let message = json(&bad).unwrap_err().to_string();
        assert!(message.contains("inner[1].value_s"), "{message}");
        assert!(json(&Outer {
            fine: None,
            inner: vec![]
        })
        .is_ok());
        assert!(check_finite_text("Length  inf m").is_err());
        assert!(check_finite_text("Simulated NaN s").is_err());
        assert!(check_finite_text("undamped, infinite Q: none; 1e-300 m").is_ok());
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
