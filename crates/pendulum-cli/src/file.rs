//! Files written whole or not at all: the data go to a temporary file in
//! the target's own folder, which is renamed over the target only when
//! everything has been written. An error, a refusal before any data, or
//! Ctrl-C leaves nothing behind. `-` as a path means standard output; a
//! symbolic link is written through (its target is replaced, the link
//! stays). [`check_outputs`] refuses, before any work, two outputs to one
//! path, a folder where a file is wanted, and two outputs to standard output.

use crate::error::CliError;
use crate::interrupt;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// Whether `path` is `-`, standard output.
pub fn is_stdout(path: &Path) -> bool {
    path.as_os_str() == "-"
}

/// Checks a command's output paths (flag and path, `None` when not asked
/// for) before anything is computed or written: no two name the same file,
/// none is an existing folder, at most one is `-` (standard output), and
/// `-` only when the command's own summary does not also go there
/// (`summary_on_stdout`: `--json`, or text that cannot move to standard
/// error).
pub fn check_outputs(outputs: &[(&'static str, Option<&Path>)]) -> Result<(), CliError> {
    let given: Vec<(&str, &Path)> = outputs
        .iter()
        .filter_map(|(flag, path)| path.map(|p| (*flag, p)))
        .collect();
    for (i, (flag, path)) in given.iter().enumerate() {
        if !is_stdout(path) && path.is_dir() {
            return Err(CliError::flag(
                flag,
                format!("'{}' is a folder; give a file name", path.display()),
            ));
        }
        for (other_flag, other) in &given[..i] {
            if is_stdout(path) && is_stdout(other) {
                return Err(CliError::flag(
                    flag,
                    format!("{other_flag} already writes to standard output ('-')"),
                ));
            }
            if !is_stdout(path) && same_file(path, other) {
                return Err(CliError::flag(
                    flag,
                    format!(
                        "'{}' is also the file of {other_flag}; give each output its own file",
                        path.display()
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// Whether two output paths name one file: the same folder (resolved) and
/// the same name, or the same existing file through links.
fn same_file(a: &Path, b: &Path) -> bool {
    if is_stdout(b) {
        return false;
    }
    let (ra, rb) = (resolve_link(a), resolve_link(b));
    if let (Ok(x), Ok(y)) = (ra.canonicalize(), rb.canonicalize()) {
        return x == y;
    }
    let folder = |p: &Path| {
        let parent = p.parent().filter(|q| !q.as_os_str().is_empty());
        parent
            .unwrap_or(Path::new("."))
            .canonicalize()
            .unwrap_or_else(|_| parent.unwrap_or(Path::new(".")).to_path_buf())
    };
    folder(&ra) == folder(&rb) && ra.file_name() == rb.file_name()
}

/// The file a path finally names: a symbolic link's target (followed
/// through chains, relative targets taken from the link's folder), or the
/// path itself.
fn resolve_link(path: &Path) -> PathBuf {
    let mut current = path.to_path_buf();
    for _ in 0..40 {
        let is_link = std::fs::symlink_metadata(&current)
            .map(|m| m.file_type().is_symlink())
            .unwrap_or(false);
        if !is_link {
            break;
        }
        match std::fs::read_link(&current) {
            Ok(target) if target.is_absolute() => current = target,
            Ok(target) => {
                let folder = current.parent().unwrap_or(Path::new("")).to_path_buf();
                current = folder.join(target);
            }
            Err(_) => break,
        }
    }
    current
}

/// The hidden temporary name beside `target`, `.NAME.PID.partial`, in the
/// same folder so that the final rename stays on one file system; `None`
/// when `target` has no file name (`/`, `..`).
fn temporary_beside(target: &Path) -> Option<PathBuf> {
    let mut name = std::ffi::OsString::from(".");
    name.push(target.file_name()?);
    name.push(format!(".{}.partial", std::process::id()));
    Some(target.with_file_name(name))
}

/// Where the bytes go.
enum Sink {
    /// A temporary file beside the target, renamed into place at the end.
    File {
        target: PathBuf,
        temporary: PathBuf,
        writer: BufWriter<File>,
    },
    /// Standard output.
    Stdout(BufWriter<std::io::Stdout>),
}

/// A file being written; [`AtomicFile::commit`] puts it in place.
pub struct AtomicFile {
    sink: Option<Sink>,
    shown: String,
    flag: &'static str,
}

impl AtomicFile {
    /// Starts writing `target` (named on the command line by `flag`); `-`
    /// writes to standard output.
    pub fn create(target: &Path, flag: &'static str) -> Result<Self, CliError> {
        if is_stdout(target) {
            return Ok(Self {
                sink: Some(Sink::Stdout(BufWriter::with_capacity(
                    1 << 16,
                    std::io::stdout(),
                ))),
                shown: "standard output".to_string(),
                flag,
            });
        }
        let shown = target.display().to_string();
        if target.is_dir() {
            return Err(CliError::flag(
                flag,
                format!("'{shown}' is a folder; give a file name"),
            ));
        }
        let real = resolve_link(target);
        let temporary = temporary_beside(&real)
            .ok_or_else(|| CliError::flag(flag, format!("'{shown}' is not a file name")))?;
        let file = File::create(&temporary).map_err(|e| {
            CliError::flag(
                flag,
                format!("cannot write in the folder of '{shown}': {e}"),
            )
        })?;
        Ok(Self {
            sink: Some(Sink::File {
                target: real,
                temporary,
                writer: BufWriter::with_capacity(1 << 16, file),
            }),
            shown,
            flag,
        })
    }

    /// The buffered writer.
    pub fn writer(&mut self) -> &mut dyn Write {
        match self.sink.as_mut().expect("not yet committed") {
            Sink::File { writer, .. } => writer,
            Sink::Stdout(writer) => writer,
        }
    }

    /// Turns a write error into a message that names the file.
    pub fn write_error(&self, e: impl std::fmt::Display) -> CliError {
        CliError::flag(self.flag, format!("writing '{}' failed: {e}", self.shown))
    }

    /// Flushes and renames the file into place; returns its path (or
    /// "standard output").
    ///
    /// No `fsync`: it would cost more than a short simulation (2 ms measured
    /// against 4 ms of computing), and the rename alone already guarantees
    /// that a failed or interrupted run never leaves a half-written file
    /// under the target's name; only an operating-system crash could.
    pub fn commit(mut self) -> Result<String, CliError> {
        match self.sink.take().expect("committed once") {
            Sink::Stdout(mut writer) => {
                writer.flush().map_err(|e| self.write_error(e))?;
            }
            Sink::File {
                target,
                temporary,
                writer,
            } => {
                let flushed = writer.into_inner().map_err(|e| e.error().to_string());
                let renamed = flushed
                    .and_then(|_| std::fs::rename(&temporary, &target).map_err(|e| e.to_string()));
                if let Err(e) = renamed {
                    let _ = std::fs::remove_file(&temporary);
                    return Err(self.write_error(e));
                }
            }
        }
        Ok(self.shown.clone())
    }
}

impl Drop for AtomicFile {
    /// An uncommitted file is removed.
    fn drop(&mut self) {
        if let Some(Sink::File { temporary, .. }) = self.sink.take() {
            let _ = std::fs::remove_file(&temporary);
        }
    }
}

/// A CSV file of numbers written row by row through an [`AtomicFile`]:
/// shortest round-trip formatting (ryu), one buffer reused for every row.
/// A non-finite number is refused, naming its column.
pub struct CsvFile {
    file: AtomicFile,
    columns: Vec<String>,
    line: String,
    cells: usize,
    bad_column: Option<usize>,
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
            columns: header.split(',').map(str::to_string).collect(),
            line: String::with_capacity(96),
            cells: 0,
            bad_column: None,
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
            if v.is_finite() {
                self.line.push_str(self.ryu.format(v));
            } else {
                self.bad_column.get_or_insert(self.cells - 1);
            }
        }
        self
    }

    fn separate(&mut self) {
        if self.cells > 0 {
            self.line.push(',');
        }
        self.cells += 1;
    }

    /// Ends the row and writes it.
    pub fn end_row(&mut self) -> Result<(), CliError> {
        if let Some(column) = self.bad_column.take() {
            let name = self.columns.get(column).map_or("?", String::as_str);
            return Err(self.file.write_error(format!(
                "the computed {name} is not a finite number (an overflow of the inputs)"
            )));
        }
        self.line.push('\n');
        let result = self.file.writer().write_all(self.line.as_bytes());
        self.line.clear();
        self.cells = 0;
        result.map_err(|e| self.file.write_error(e))
    }

    /// Puts the file in place; returns its path.
    pub fn commit(self) -> Result<String, CliError> {
        self.file.commit()
    }
}

/// A folder written whole or not at all: files go into a temporary folder
/// beside the target, which replaces the target at [`AtomicFolder::commit`]
/// (an older folder of that name is moved aside first, then removed).
pub struct AtomicFolder {
    target: PathBuf,
    temporary: Option<PathBuf>,
}

impl AtomicFolder {
    /// Starts the folder `target` (named by `flag`).
    pub fn create(target: &Path, flag: &'static str) -> Result<Self, CliError> {
        let shown = target.display().to_string();
        if target.exists() && !target.is_dir() {
            return Err(CliError::flag(
                flag,
                format!("'{shown}' exists and is not a folder"),
            ));
        }
        let temporary = temporary_beside(target)
            .ok_or_else(|| CliError::flag(flag, format!("'{shown}' is not a folder name")))?;
        if let Some(parent) = target.parent().filter(|p| !p.as_os_str().is_empty()) {
            std::fs::create_dir_all(parent)
                .map_err(|e| CliError::flag(flag, format!("cannot create '{shown}': {e}")))?;
        }
        std::fs::create_dir(&temporary)
            .map_err(|e| CliError::flag(flag, format!("cannot create '{shown}': {e}")))?;
        Ok(Self {
            target: target.to_path_buf(),
            temporary: Some(temporary),
        })
    }

    /// Where to write the folder's files until the commit.
    pub fn path(&self) -> &Path {
        self.temporary.as_deref().expect("not yet committed")
    }

    /// Puts the folder in place; returns its path.
    pub fn commit(mut self, flag: &'static str) -> Result<PathBuf, CliError> {
        let temporary = self.temporary.take().expect("committed once");
        let fail = |e: std::io::Error| {
            let _ = std::fs::remove_dir_all(&temporary);
            CliError::flag(
                flag,
                format!("writing '{}' failed: {e}", self.target.display()),
            )
        };
        if interrupt::requested() {
            let _ = std::fs::remove_dir_all(&temporary);
            return Err(interrupt::error());
        }
        if self.target.exists() {
            let mut aside = temporary.clone().into_os_string();
            aside.push(".old");
            let aside = PathBuf::from(aside);
            std::fs::rename(&self.target, &aside).map_err(fail)?;
            if let Err(e) = std::fs::rename(&temporary, &self.target) {
                let _ = std::fs::rename(&aside, &self.target);
                return Err(fail(e));
            }
            let _ = std::fs::remove_dir_all(&aside);
        } else {
            std::fs::rename(&temporary, &self.target).map_err(fail)?;
        }
        Ok(self.target.clone())
    }
}

impl Drop for AtomicFolder {
    /// An uncommitted folder is removed with everything in it.
    fn drop(&mut self) {
        if let Some(temporary) = self.temporary.take() {
            let _ = std::fs::remove_dir_all(&temporary);
        }
    }
}
