//! Files written whole or not at all: the data go to a temporary file in
//! the target's own folder, which is renamed over the target only when
//! everything has been written. An error (or a refusal before
//! any data) leaves nothing behind.

use crate::error::CliError;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// A file being written; [`AtomicFile::commit`] puts it in place.
pub struct AtomicFile {
    target: PathBuf,
    temporary: PathBuf,
    writer: Option<BufWriter<File>>,
    flag: &'static str,
}

impl AtomicFile {
    /// Starts writing `target` (named on the command line by `flag`).
    pub fn create(target: &Path, flag: &'static str) -> Result<Self, CliError> {
        let name = target.file_name().ok_or_else(|| {
            CliError::flag(flag, format!("'{}' is not a file name", target.display()))
        })?;
        let mut temporary_name = std::ffi::OsString::from(".");
        temporary_name.push(name);
        temporary_name.push(format!(".{}.partial", std::process::id()));
        let temporary = target.with_file_name(temporary_name);
        let file = File::create(&temporary).map_err(|e| {
            CliError::flag(
                flag,
                format!("cannot write in the folder of '{}': {e}", target.display()),
            )
        })?;
        Ok(Self {
            target: target.to_path_buf(),
            temporary,
            writer: Some(BufWriter::with_capacity(1 << 16, file)),
            flag,
        })
    }

    /// The buffered writer.
    pub fn writer(&mut self) -> &mut BufWriter<File> {
        self.writer.as_mut().expect("not yet committed")
    }

    /// Turns a write error into a message that names the file.
    pub fn write_error(&self, e: impl std::fmt::Display) -> CliError {
        CliError::flag(
            self.flag,
            format!("writing '{}' failed: {e}", self.target.display()),
        )
    }

    /// Flushes and renames the file into place; returns its path.
    ///
    /// No `fsync`: it would cost more than a short simulation (2 ms measured
    /// against 4 ms of computing), and the rename alone already guarantees
    /// that a failed or interrupted run never leaves a half-written file
    /// under the target's name; only an operating-system crash could.
    pub fn commit(mut self) -> Result<String, CliError> {
        let writer = self.writer.take().expect("committed once");
        writer
            .into_inner()
            .map_err(|e| self.write_error(e.error()))?;
        std::fs::rename(&self.temporary, &self.target).map_err(|e| self.write_error(e))?;
        Ok(self.target.display().to_string())
    }
}

impl Drop for AtomicFile {
    /// An uncommitted file is removed.
    fn drop(&mut self) {
        if self.writer.take().is_some() {
            let _ = std::fs::remove_file(&self.temporary);
        }
    }
}

/// A CSV file of numbers written row by row through an [`AtomicFile`]:
/// shortest round-trip formatting (ryu), one buffer reused for every row.
pub struct CsvFile {
    file: AtomicFile,
    line: String,
    ryu: ryu::Buffer,
}

impl CsvFile {
    /// Creates `target` and writes `header` (its column names, comma-separated).
    pub fn create(target: &Path, flag: &'static str, header: &str) -> Result<Self, CliError> {
        let mut file = AtomicFile::create(target, flag)?;
        let head = format!("{header}\n");
        file.writer()
            .write_all(head.as_bytes())
            .map_err(|e| file.write_error(e))?;
        Ok(Self {
            file,
            line: String::with_capacity(96),
            ryu: ryu::Buffer::new(),
        })
    }

    /// Appends a whole number to the row.
    pub fn integer(&mut self, value: u64) -> &mut Self {
        self.separate();
        self.line.push_str(&value.to_string());
        self
    }

    /// Appends a number to the row; `None` leaves the cell empty.
    pub fn number(&mut self, value: Option<f64>) -> &mut Self {
        self.separate();
        if let Some(v) = value {
            self.line.push_str(self.ryu.format(v));
        }
        self
    }

    fn separate(&mut self) {
        if !self.line.is_empty() {
            self.line.push(',');
        }
    }

    /// Ends the row and writes it.
    pub fn end_row(&mut self) -> Result<(), CliError> {
        self.line.push('\n');
        let result = self.file.writer().write_all(self.line.as_bytes());
        self.line.clear();
        result.map_err(|e| self.file.write_error(e))
    }

    /// Puts the file in place; returns its path.
    pub fn commit(self) -> Result<String, CliError> {
        self.file.commit()
    }
}
