//! Measurement files as people have them, read from text and bytes into
//! the pendulum library's columns: CSV and semicolon files with decimal
//! commas, Tracker's exports and projects (`.trk`), phyphox's CSV and
//! workbooks, loggers' tables with date-times, a TICC counter's log (the
//! formats read whole are one list, [`formats::FORMATS`]). No file system: the command
//! line opens a file and hands its reader here; the browser page hands
//! the bytes of a dropped file or a pasted table. Both therefore read a
//! file the same way and refuse it in the same words.

pub mod figure;
pub mod fits;
pub mod formats;
pub mod lab;
pub mod measured;
pub mod request;
pub mod table;
pub mod ticc;
pub mod tracker;
pub mod units;
pub mod workbook;

pub use table::{
    need, read_table, stream_table, AngleUnit, Choose, Format, Found, ReadOptions, Role, Table,
    DEG, RATE_ROLES,
};

use std::fmt;
use std::io::BufRead;

/// A refusal of a file: its sentence, which names the file (and where it
/// can the line, the column and the separator), and the reading option it
/// concerns, if one (`run`, `frame_rate`, `columns`: the command line says
/// it of `--run`, the page of its field).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReadError {
    /// The reading option the refusal concerns (`ReadOptions`' field name).
    pub option: Option<&'static str>,
    /// The sentence.
    pub message: String,
}

impl ReadError {
    /// A refusal of the file itself.
    pub fn other(message: impl Into<String>) -> Self {
        Self {
            option: None,
            message: message.into(),
        }
    }

    /// A refusal of a reading option's value.
    pub fn option(option: &'static str, message: impl Into<String>) -> Self {
        Self {
            option: Some(option),
            message: message.into(),
        }
    }
}

/// The library's field names that are not their command-line flag's
/// (`--` and the name with hyphens): one table for every front end.
const FLAGS: [(&str, &str); 4] = [
    ("length_standard_error", "--length-uncertainty"),
    ("pendulum_length", "--length"),
    ("pendulum_length_standard_error", "--length-uncertainty"),
    ("time", "FILE"),
];

impl ReadError {
    /// The command line's flag for the option, if one.
    pub fn flag(&self) -> Option<String> {
        let option = self.option?;
        Some(match FLAGS.iter().find(|(o, _)| *o == option) {
            Some((_, flag)) => flag.to_string(),
            None => format!("--{}", option.replace('_', "-")),
        })
    }

    /// The command line's sentence: the flag, then the message.
    pub fn sentence(&self) -> String {
        match self.flag() {
            Some(flag) => format!("{flag}: {}", self.message),
            None => self.message.clone(),
        }
    }
}

/// The run of a file whose times restart, counted from 1.
pub fn run_number(n: u64) -> Result<usize, ReadError> {
    match n {
        0 => Err(ReadError::option(
            "run",
            "must be at least 1 (the first run), got 0",
        )),
        n => Ok(usize::try_from(n).unwrap_or(usize::MAX)),
    }
}

/// A frame rate to rebuild times from, checked by the library.
pub fn frame_rate(fps: f64) -> Result<f64, ReadError> {
    pendulum_theory::fitting::track::frame_rate(fps)
        .map_err(|e| ReadError::option("frame_rate", e.reason))
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for ReadError {}

/// How a file's bytes are laid out, told by its name's extension.
#[derive(Clone, Copy, Debug)]
pub enum Layout {
    /// Lines of text (CSV, semicolon, tab or space separated), unless its
    /// first bytes are a format's of [`formats::FORMATS`] (a TICC log).
    Text,
    /// A format of [`formats::FORMATS`], read whole (a workbook, a
    /// Tracker project).
    Whole(&'static formats::FileFormat),
}

impl PartialEq for Layout {
    fn eq(&self, other: &Self) -> bool {
        match (self, other) {
            (Layout::Text, Layout::Text) => true,
            (Layout::Whole(a), Layout::Whole(b)) => a.name == b.name,
            _ => false,
        }
    }
}

impl Layout {
    /// The layout of a file called `name`, by its extension.
    pub fn of_name(name: &str) -> Layout {
        formats::by_name(name).map_or(Layout::Text, Layout::Whole)
    }
}

/// A file to read: its name as the user gave it (for messages, and its
/// layout) and its bytes, as a reader.
pub struct Source<'a> {
    /// The name said in messages (`run.csv`, `pasted table`).
    pub name: String,
    /// How its bytes are laid out.
    pub layout: Layout,
    /// Its bytes.
    pub reader: Box<dyn BufRead + 'a>,
}

impl<'a> Source<'a> {
    /// A file called `name`, its layout told by its extension.
    pub fn new(name: impl Into<String>, reader: impl BufRead + 'a) -> Self {
        let name = name.into();
        Source {
            layout: Layout::of_name(&name),
            name,
            reader: Box::new(reader),
        }
    }

    /// Bytes in memory (a dropped file, a pasted table).
    pub fn bytes(name: impl Into<String>, bytes: &'a [u8]) -> Self {
        Source::new(name, bytes)
    }
}
