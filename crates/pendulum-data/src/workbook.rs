//! Spreadsheet workbooks (`.xls`, `.xlsx`, `.xlsb`, `.ods`) read with
//! calamine: one sheet's cells handed to the table reader as tab-separated
//! text, as a CSV export of the same sheet would hold them. phyphox's
//! Excel export keeps its measurements on a sheet named `Raw Data` (beside
//! `Metadata Device` and `Metadata Time`); any other workbook is read from
//! its first sheet that holds numbers.

use calamine::{open_workbook_auto_from_rs, Data, Range, Reader};
use std::io::Cursor;

/// Extensions read as workbooks.
pub const EXTENSIONS: [&str; 5] = ["xls", "xlsx", "xlsm", "xlsb", "ods"];

/// The workbook's entry in [`crate::formats::FORMATS`].
pub const FORMAT: crate::formats::FileFormat = crate::formats::FileFormat {
    name: "spreadsheet workbook",
    extensions: &EXTENSIONS,
    recognise: None,
    read: |bytes| {
        let sheet = read(bytes)?;
        Ok(crate::formats::Converted {
            text: sheet.text,
            sheet: Some(sheet.name),
            ..Default::default()
        })
    },
};

/// A sheet, as table text.
#[derive(Debug)]
pub struct Sheet {
    /// The sheet's name.
    pub name: String,
    /// Its rows, tab-separated, one line each.
    pub text: String,
}

/// The sheet names phyphox gives its measurements, in its languages.
const RAW_DATA: [&str; 5] = [
    "raw data",
    "rohdaten",
    "données brutes",
    "datos sin procesar",
    "dati grezzi",
];

/// Reads the measurement sheet of a workbook's `bytes`.
pub fn read(bytes: Vec<u8>) -> Result<Sheet, String> {
    let mut book = open_workbook_auto_from_rs(Cursor::new(bytes)).map_err(|e| {
        format!("cannot read it as a spreadsheet workbook (xls, xlsx, xlsb, ods): {e}")
    })?;
    let names = book.sheet_names();
    if names.is_empty() {
        return Err("the workbook has no sheets".to_string());
    }
    let raw = names
        .iter()
        .find(|n| RAW_DATA.contains(&n.trim().to_lowercase().as_str()));
    let order: Vec<&String> = raw.into_iter().chain(names.iter()).collect();
    for name in order {
        let range = book
            .worksheet_range(name)
            .map_err(|e| format!("cannot read its sheet '{name}': {e}"))?;
        if holds_numbers(&range) {
            return Ok(Sheet {
                name: name.clone(),
                text: text_of(&range),
            });
        }
    }
    Err(format!(
        "none of its sheets holds numbers (sheets: {})",
        names.join(", ")
    ))
}

/// Whether a sheet has a number in any cell.
fn holds_numbers(range: &Range<Data>) -> bool {
    range.rows().any(|row| {
        row.iter()
            .any(|c| matches!(c, Data::Float(_) | Data::Int(_)))
    })
}

/// The sheet's cells as tab-separated lines: numbers in Rust's shortest
/// exact form, dates as ISO 8601 text, durations in seconds, errors and
/// empty cells blank.
fn text_of(range: &Range<Data>) -> String {
    let mut out = String::new();
    for row in range.rows() {
        // Trailing empty cells are no columns.
        let used = row
            .iter()
            .rposition(|c| !matches!(c, Data::Empty))
            .map_or(0, |i| i + 1);
        let cells: Vec<String> = row[..used].iter().map(cell).collect();
        out.push_str(&cells.join("\t"));
        out.push('\n');
    }
    out
}

/// One cell as text.
fn cell(c: &Data) -> String {
    match c {
        Data::Int(i) => i.to_string(),
        Data::Float(f) => f.to_string(),
        Data::String(s) | Data::DateTimeIso(s) | Data::DurationIso(s) => {
            s.replace(['\t', '\n', '\r'], " ")
        }
        Data::Bool(b) => b.to_string(),
        Data::DateTime(d) if d.is_duration() => (d.as_f64() * 86_400.0).to_string(),
        Data::DateTime(d) => {
            let (y, mo, da, h, mi, s, ms) = d.to_ymd_hms_milli();
            format!("{y:04}-{mo:02}-{da:02}T{h:02}:{mi:02}:{s:02}.{ms:03}")
        }
        Data::Error(_) | Data::Empty => String::new(),
    }
}
