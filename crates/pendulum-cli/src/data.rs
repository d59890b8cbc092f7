//! Measurement files opened from the file system and read by
//! `pendulum-data` (the reader the browser page shares): a refusal names
//! the file, and what the reader left out is said as a warning.

use crate::error::CliError;
pub use pendulum_data::table::*;
use pendulum_data::Source;
use std::io::BufReader;
use std::path::Path;

/// The file at `path`, opened for the reader.
pub fn source(path: &Path) -> Result<Source<'static>, CliError> {
    let file = path.display().to_string();
    let handle = crate::file::open_input(path)
        .map_err(|e| CliError::other(format!("{file}: cannot read it: {e}")))?;
    if handle.metadata().is_ok_and(|m| m.is_dir()) {
        return Err(CliError::other(format!("{file}: is a folder; give a file")));
    }
    Ok(Source::new(file, BufReader::new(handle)))
}

/// Warns of what the reader left out (the fits of `pendulum-data`, which
/// read the file themselves, pass their result's format here).
pub fn say(format: &Format) {
    for note in &format.notes {
        crate::output::warn(note.clone());
    }
}

/// Reads the columns `choose` picks from `path` into memory.
pub fn read_table(
    path: &Path,
    options: &ReadOptions,
    choose: &Choose<'_>,
) -> Result<Table, CliError> {
    let table = pendulum_data::read_table(source(path)?, options, choose)?;
    say(&table.format);
    Ok(table)
}

/// Hands each row of the columns `choose` picks from `path` to `each`.
pub fn stream_table(
    path: &Path,
    options: &ReadOptions,
    choose: &Choose<'_>,
    each: impl FnMut(&[f64], u64) -> Result<(), CliError>,
) -> Result<(String, Vec<Role>, Vec<String>, Format), CliError> {
    let read = pendulum_data::stream_table(source(path)?, options, choose, each)?;
    say(&read.3);
    Ok(read)
}

/// The number of cells of the first data line of a headerless file at
/// `path` (see `pendulum_data::table::headerless_width`).
pub fn headerless_width(path: &Path) -> Option<usize> {
    let handle = crate::file::open_input(path).ok()?;
    pendulum_data::table::headerless_width(BufReader::new(handle))
}
