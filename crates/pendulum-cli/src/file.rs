//! A run's outputs, written whole or not at all, and together: each goes
//! to a temporary in the target's own folder (data for standard output to
//! an unnamed temporary file), and [`commit_all`] puts every one in place
//! only when the whole command has succeeded; an error, a refusal, Ctrl-C
//! or SIGTERM, or a panic leaves nothing behind ([`abandon_all`]). `-` as
//! a path means standard output; a symbolic link is written through (its
//! target is replaced, the link stays); a device or a pipe is written
//! directly. [`check_outputs`] refuses, before any work, two outputs to one
//! path, an output that is an input, a folder where a file is wanted, a
//! missing folder, and two outputs to standard output.

use crate::error::CliError;
use std::fs::File;
use std::io::{BufWriter, Seek, SeekFrom, Write};
use std::os::unix::fs::MetadataExt;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Whether `path` is `-`, standard output.
pub fn is_stdout(path: &Path) -> bool {
    path.as_os_str() == "-"
}

/// Checks a command's output paths (flag and path, `None` when not asked
/// for) before anything is read, computed or written: each names a file
/// in an existing folder, none is an existing folder, none is one of the
/// command's `inputs` (through links and hard links too), no two name the
/// same file, and at most one is `-` (standard output).
pub fn check_outputs(
    outputs: &[(String, std::path::PathBuf)],
    inputs: &[(String, std::path::PathBuf)],
) -> Result<(), CliError> {
    let given: Vec<(&str, &Path)> = outputs
        .iter()
        .map(|(flag, path)| (flag.as_str(), path.as_path()))
        .collect();
    for (i, (flag, path)) in given.iter().enumerate() {
        if !is_stdout(path) {
            check_writable_place(flag, path)?;
            for (input_flag, input) in inputs {
                if same_file(path, input) {
                    return Err(CliError::flag(
                        flag,
                        format!(
                            "'{}' is also the input of {input_flag}; an output never \
                             replaces an input: give it another name",
                            path.display()
                        ),
                    ));
                }
            }
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

/// An output file's path: not a folder, a file name, in a folder that
/// exists.
fn check_writable_place(flag: &str, path: &Path) -> Result<(), CliError> {
    let shown = path.display();
    if path.is_dir() {
        return Err(CliError::flag(
            flag,
            format!("'{shown}' is a folder; give a file name"),
        ));
    }
    let real = resolve_link(path);
    if real.file_name().is_none() {
        return Err(CliError::flag(
            flag,
            format!("'{shown}' is not a file name"),
        ));
    }
    let folder = real
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    if !folder.is_dir() {
        return Err(CliError::flag(
            flag,
            format!("the folder '{}' does not exist", folder.display()),
        ));
    }
    Ok(())
}

/// Whether two output paths name one file: the same folder (resolved) and
/// the same name, or the same existing file through links.
fn same_file(a: &Path, b: &Path) -> bool {
    if is_stdout(b) {
        return false;
    }
    if let (Ok(x), Ok(y)) = (std::fs::metadata(a), std::fs::metadata(b)) {
        return x.dev() == y.dev() && x.ino() == y.ino();
    }
    let (ra, rb) = (resolve_link(a), resolve_link(b));
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

// ---- The run's outputs, one transaction -------------------------------------
//
// Every output of a run (a file, a report folder, data for standard output)
// is written to a temporary first and registered here. A command's
// `commit` only marks its output ready; `main` puts them all in place
// together once the command has succeeded ([`commit_all`]), or removes
// them all when it failed, was interrupted, or panicked ([`abandon_all`]).
// So an error found late (a bad value, a plot into a missing folder, a
// full disk) never leaves an earlier output behind. The files the run read
// are registered too ([`open_input`]): an output that would replace one of
// them is refused at the commit, whatever path named it.

/// One output of the run.
#[derive(Debug)]
enum Pending {
    /// A temporary file or folder to rename over `target` (a folder that
    /// holds an earlier report is moved aside first, then removed).
    Path {
        temporary: PathBuf,
        target: PathBuf,
        folder: bool,
        ready: bool,
    },
    /// Data for standard output, held in an unnamed temporary file.
    Stdout { data: Option<File>, ready: bool },
}

/// The outputs of this run, in the order they were started.
static PENDING: Mutex<Vec<Option<Pending>>> = Mutex::new(Vec::new());
/// The files this run has read: (device, inode) and the path as given.
static INPUTS: Mutex<Vec<(u64, u64, PathBuf)>> = Mutex::new(Vec::new());

fn pending() -> std::sync::MutexGuard<'static, Vec<Option<Pending>>> {
    PENDING
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

fn register(item: Pending) -> usize {
    let mut list = pending();
    list.push(Some(item));
    list.len() - 1
}

/// Marks output `id` ready to be put in place.
fn mark_ready(id: usize) {
    if let Some(Some(Pending::Path { ready, .. } | Pending::Stdout { ready, .. })) =
        pending().get_mut(id)
    {
        *ready = true;
    }
}

/// Removes output `id`'s temporary (an output given up before it was ready).
fn discard(id: usize) {
    let item = pending().get_mut(id).and_then(Option::take);
    if let Some(item) = item {
        remove_temporary(&item);
    }
}

fn remove_temporary(item: &Pending) {
    if let Pending::Path {
        temporary, folder, ..
    } = item
    {
        if *folder {
            let _ = std::fs::remove_dir_all(temporary);
        } else {
            let _ = std::fs::remove_file(temporary);
        }
    }
}

/// Opens a device or a pipe for writing without waiting for a reader (a
/// FIFO nobody reads is an error, not a hang).
fn open_special_for_writing(path: &Path) -> std::io::Result<File> {
    use std::os::unix::fs::OpenOptionsExt;
    let file = std::fs::OpenOptions::new()
        .write(true)
        .custom_flags(libc::O_NONBLOCK)
        .open(path)?;
    blocking(&file)?;
    Ok(file)
}

/// Clears `O_NONBLOCK` on an open file, so that its reads and writes wait
/// as usual.
fn blocking(file: &File) -> std::io::Result<()> {
    use std::os::unix::io::AsRawFd;
    let fd = file.as_raw_fd();
    // SAFETY: fcntl on a descriptor this process owns, with flags it
    // returned.
    let flags = unsafe { libc::fcntl(fd, libc::F_GETFL) };
    if flags < 0 || unsafe { libc::fcntl(fd, libc::F_SETFL, flags & !libc::O_NONBLOCK) } < 0 {
        return Err(std::io::Error::last_os_error());
    }
    Ok(())
}

/// Opens `path` for reading without waiting for a writer (a FIFO that has
/// none then reads as empty, so a named pipe never hangs a run), and
/// remembers it so that no output of the run may replace it.
fn open_registered(path: &Path) -> std::io::Result<File> {
    use std::os::unix::fs::OpenOptionsExt;
    let file = std::fs::OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NONBLOCK)
        .open(path)?;
    blocking(&file)?;
    if let Ok(meta) = file.metadata() {
        let mut inputs = INPUTS
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        inputs.push((meta.dev(), meta.ino(), path.to_path_buf()));
    }
    Ok(file)
}

/// Opens a file the run reads by position (a sound file, which a decoder
/// seeks in). A pipe or a device opened here is read once, as it comes:
/// its caller refuses anything but a regular file.
pub fn open_input_file(path: &Path) -> std::io::Result<File> {
    open_registered(path)
}

/// The bytes of a stream this run has read (a pipe, `/dev/stdin`, a
/// terminal, a device), kept so that every reader of it reads them all:
/// a pipe gives its bytes once, and a first look at a file (its width,
/// its separator) must not take them from the reader that follows.
struct Replay {
    /// The stream.
    source: File,
    /// Everything read from it so far.
    bytes: Vec<u8>,
    /// Whether its end was reached.
    ended: bool,
}

/// A stream's bytes, shared by its readers.
type Shared = std::sync::Arc<Mutex<Replay>>;

/// The streams this run has opened, by (device, inode).
static STREAMS: Mutex<Vec<((u64, u64), Shared)>> = Mutex::new(Vec::new());

/// A file the run reads from its start: a regular file (or a folder, for
/// its caller to refuse) from the disk; anything else (a pipe,
/// `/dev/stdin`, `<(…)`, a terminal, a device) through the run's one copy
/// of its bytes, so that every opening of it reads the same bytes from
/// the first. The copy holds what was read, no more: a reader that stops
/// early (a line too long, a file too large) stops the reading.
pub struct Input {
    source: Source,
    /// How far this reader has read a stream's bytes.
    position: usize,
}

enum Source {
    File(File),
    Stream(Shared),
}

impl Input {
    /// The metadata of what was opened (a stream's own: a FIFO, a
    /// character device).
    pub fn metadata(&self) -> std::io::Result<std::fs::Metadata> {
        match &self.source {
            Source::File(f) => f.metadata(),
            Source::Stream(s) => s
                .lock()
                .unwrap_or_else(std::sync::PoisonError::into_inner)
                .source
                .metadata(),
        }
    }
}

impl std::io::Read for Input {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let replay = match &mut self.source {
            Source::File(f) => return f.read(buf),
            Source::Stream(s) => s.clone(),
        };
        let mut replay = replay
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        if self.position == replay.bytes.len() && !replay.ended && !buf.is_empty() {
            // Past what any reader has read: read on, keeping the bytes.
            let Replay {
                source,
                bytes,
                ended,
            } = &mut *replay;
            let start = bytes.len();
            bytes.resize(start + buf.len().max(1 << 16), 0);
            let read = source.read(&mut bytes[start..]);
            bytes.truncate(start + *read.as_ref().unwrap_or(&0));
            *ended = read? == 0;
        }
        let held = &replay.bytes[self.position..];
        let n = held.len().min(buf.len());
        buf[..n].copy_from_slice(&held[..n]);
        self.position += n;
        Ok(n)
    }
}

/// Opens a file the run reads as an [`Input`], and remembers it so that
/// no output of the run may replace it. A stream opened before (the same
/// pipe, by any path) is read again from its first byte.
pub fn open_input(path: &Path) -> std::io::Result<Input> {
    let file = open_registered(path)?;
    let meta = file.metadata()?;
    if meta.is_file() || meta.is_dir() {
        return Ok(Input {
            source: Source::File(file),
            position: 0,
        });
    }
    let key = (meta.dev(), meta.ino());
    let mut streams = STREAMS
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    let replay = match streams.iter().find(|(k, _)| *k == key) {
        // (The new descriptor is closed: the first one reads on.)
        Some((_, replay)) => replay.clone(),
        None => {
            let replay = std::sync::Arc::new(Mutex::new(Replay {
                source: file,
                bytes: Vec::new(),
                ended: false,
            }));
            streams.push((key, replay.clone()));
            replay
        }
    };
    Ok(Input {
        source: Source::Stream(replay),
        position: 0,
    })
}

/// The input (as its path was given) that `target` is, or that lies
/// inside the folder `target`.
fn input_at(target: &Path, folder: bool) -> Option<PathBuf> {
    let inputs = INPUTS
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    if let Ok(meta) = std::fs::metadata(target) {
        if let Some((.., path)) = inputs
            .iter()
            .find(|(dev, ino, _)| *dev == meta.dev() && *ino == meta.ino())
        {
            return Some(path.clone());
        }
    }
    if folder {
        let root = target.canonicalize().ok()?;
        return inputs
            .iter()
            .find(|(.., path)| path.canonicalize().is_ok_and(|p| p.starts_with(&root)))
            .map(|(.., path)| path.clone());
    }
    None
}

/// Puts every ready output of the run in place, in the order they were
/// started, folders last (a report's files before its folder), and writes
/// the data meant for standard output. An output that would replace a file the run
/// read is refused, and then nothing is put in place.
pub fn commit_all() -> Result<(), CliError> {
    let items: Vec<Pending> = pending().drain(..).flatten().collect();
    let refused = items.iter().find_map(|item| match item {
        Pending::Path {
            target,
            folder,
            ready: true,
            ..
        } => input_at(target, *folder).map(|input| (target.clone(), input)),
        _ => None,
    });
    if let Some((target, input)) = refused {
        items.iter().for_each(remove_temporary);
        return Err(CliError::other(format!(
            "'{}' would replace '{}', which this command reads; give the output another name",
            target.display(),
            input.display()
        )));
    }
    // Files first, folders last: a report's files are put in place inside
    // its temporary folder before the folder takes its name.
    let (folders, mut items): (Vec<Pending>, Vec<Pending>) = items
        .into_iter()
        .partition(|item| matches!(item, Pending::Path { folder: true, .. }));
    items.extend(folders);
    let mut first_error = None;
    for item in items {
        let result = match item {
            Pending::Path {
                ref temporary,
                ref target,
                folder,
                ready: true,
            } => put_in_place(temporary, target, folder),
            Pending::Stdout {
                data: Some(mut data),
                ready: true,
            } => copy_to_stdout(&mut data),
            other => {
                remove_temporary(&other);
                Ok(())
            }
        };
        if let Err(e) = result {
            first_error.get_or_insert(e);
        }
    }
    first_error.map_or(Ok(()), Err)
}

/// Removes every temporary of the run: nothing it started is left.
pub fn abandon_all() {
    let items: Vec<Pending> = pending().drain(..).flatten().collect();
    items.iter().for_each(remove_temporary);
}

fn put_in_place(temporary: &Path, target: &Path, folder: bool) -> Result<(), CliError> {
    let fail =
        |e: std::io::Error| CliError::other(format!("writing '{}' failed: {e}", target.display()));
    if folder && target.exists() {
        // Checked again: the folder may have changed during the run.
        let earlier = earlier_report(target).map_err(|why| {
            let _ = std::fs::remove_dir_all(temporary);
            CliError::other(format!("'{}' {why}", target.display()))
        })?;
        let mut aside = temporary.as_os_str().to_owned();
        aside.push(".old");
        let aside = PathBuf::from(aside);
        std::fs::rename(target, &aside).map_err(|e| {
            let _ = std::fs::remove_dir_all(temporary);
            fail(e)
        })?;
        if let Err(e) = std::fs::rename(temporary, target) {
            let _ = std::fs::rename(&aside, target);
            let _ = std::fs::remove_dir_all(temporary);
            return Err(fail(e));
        }
        // Only the earlier report's own files go, one by one.
        for name in earlier
            .iter()
            .map(std::ffi::OsString::as_os_str)
            .chain([std::ffi::OsStr::new(REPORT_MARKER)])
        {
            let _ = std::fs::remove_file(aside.join(name));
        }
        if std::fs::remove_dir(&aside).is_err() {
            crate::output::warn(format!(
                "the earlier report's folder is kept as '{}': something else was written into \
                 it during the run",
                aside.display()
            ));
        }
        return Ok(());
    }
    std::fs::rename(temporary, target).map_err(|e| {
        if folder {
            let _ = std::fs::remove_dir_all(temporary);
        } else {
            let _ = std::fs::remove_file(temporary);
        }
        fail(e)
    })
}

/// Writes the held data to standard output; a closed pipe is not an error.
fn copy_to_stdout(data: &mut File) -> Result<(), CliError> {
    let fail =
        |e: std::io::Error| CliError::other(format!("could not write to standard output: {e}"));
    data.seek(SeekFrom::Start(0)).map_err(fail)?;
    let mut stdout = std::io::stdout().lock();
    match std::io::copy(data, &mut stdout).and_then(|_| stdout.flush()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(fail(e)),
        _ => Ok(()),
    }
}

/// A file being written; [`AtomicFile::commit`] marks it ready, and
/// [`commit_all`] puts it in place with every other output of the run.
pub struct AtomicFile {
    /// The temporary file beside the target (unnamed for standard
    /// output); `None` once committed.
    sink: Option<BufWriter<File>>,
    id: usize,
    shown: String,
    flag: &'static str,
}

impl AtomicFile {
    /// Starts writing `target` (named on the command line by `flag`); `-`
    /// writes to standard output.
    pub fn create(target: &Path, flag: &'static str) -> Result<Self, CliError> {
        if is_stdout(target) {
            let data = tempfile::tempfile().map_err(|e| {
                CliError::flag(
                    flag,
                    format!("cannot hold the data for standard output: {e}"),
                )
            })?;
            let writer = data.try_clone().map_err(|e| {
                CliError::flag(
                    flag,
                    format!("cannot hold the data for standard output: {e}"),
                )
            })?;
            let id = register(Pending::Stdout {
                data: Some(data),
                ready: false,
            });
            return Ok(Self {
                sink: Some(BufWriter::with_capacity(1 << 16, writer)),
                id,
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
        // A device or a pipe (/dev/null, /dev/full, a FIFO) is written
        // directly: it is no file to replace (renaming over it would put a
        // regular file in place of /dev/null) and keeps nothing to lose.
        let special = std::fs::metadata(&real).is_ok_and(|m| !m.is_file());
        if special {
            let file = open_special_for_writing(&real)
                .map_err(|e| CliError::flag(flag, format!("cannot write to '{shown}': {e}")))?;
            return Ok(Self {
                sink: Some(BufWriter::with_capacity(1 << 16, file)),
                id: usize::MAX,
                shown,
                flag,
            });
        }
        let temporary = temporary_beside(&real)
            .ok_or_else(|| CliError::flag(flag, format!("'{shown}' is not a file name")))?;
        let file = File::create(&temporary).map_err(|e| {
            CliError::flag(
                flag,
                format!("cannot write in the folder of '{shown}': {e}"),
            )
        })?;
        let id = register(Pending::Path {
            temporary,
            target: real,
            folder: false,
            ready: false,
        });
        Ok(Self {
            sink: Some(BufWriter::with_capacity(1 << 16, file)),
            id,
            shown,
            flag,
        })
    }

    /// The buffered writer.
    pub fn writer(&mut self) -> &mut dyn Write {
        self.sink.as_mut().expect("not yet committed")
    }

    /// Turns a write error into a message that names the file.
    pub fn write_error(&self, e: impl std::fmt::Display) -> CliError {
        CliError::flag(self.flag, format!("writing '{}' failed: {e}", self.shown))
    }

    /// Flushes the file and marks it ready to be put in place with the
    /// run's other outputs; returns its path (or "standard output").
    ///
    /// No `fsync`: it would cost more than a short simulation (2 ms measured
    /// against 4 ms of computing), and the rename alone already guarantees
    /// that a failed or interrupted run never leaves a half-written file
    /// under the target's name; only an operating-system crash could.
    pub fn commit(mut self) -> Result<String, CliError> {
        let Some(writer) = self.sink.take() else {
            return Ok(self.shown.clone());
        };
        if let Err(e) = writer.into_inner().map_err(|e| e.error().to_string()) {
            discard(self.id);
            return Err(self.write_error(e));
        }
        mark_ready(self.id);
        Ok(self.shown.clone())
    }
}

impl Drop for AtomicFile {
    /// A file dropped before its commit is removed.
    fn drop(&mut self) {
        if self.sink.take().is_some() {
            discard(self.id);
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

/// The file a report writes into its folder: the list of the files it
/// wrote there, which a later report into the same folder removes, and
/// nothing else.
pub const REPORT_MARKER: &str = ".pendulum-report";

/// The marker's first line; the file names follow, one a line.
const MARKER_HEAD: &str = "pendulum report: the files below were written here by `pendulum \
                           report`; a later report removes them and nothing else.";

/// The whole marker of the reports before 2026-11-27, which named no
/// files; the files those reports wrote are [`LEGACY_FILES`].
const LEGACY_MARKER: &str =
    "This folder was written by `pendulum report`; a later report may replace it.\n";

/// The files a report before 2026-11-27 could write.
const LEGACY_FILES: [&str; 9] = [
    "index.html",
    "period.svg",
    "decay.svg",
    "rundown.svg",
    "log-rate.svg",
    "log-weather.svg",
    "log-stability.svg",
    "log-spectrum.svg",
    "log-folds.svg",
];

/// The longest marker read (a report writes a dozen names).
const MAX_MARKER_BYTES: u64 = 64 * 1024;

/// The files of `folder` an earlier report wrote, as its marker lists
/// them (none when the folder is empty), or why the folder is not one a
/// report may clear: files its marker does not list, a marker that is
/// missing, a link, empty, or not one a report wrote, a listed name that
/// is not a plain file of the folder.
fn earlier_report(folder: &Path) -> Result<Vec<std::ffi::OsString>, String> {
    let entries: Vec<std::ffi::OsString> = std::fs::read_dir(folder)
        .and_then(|d| d.map(|e| e.map(|e| e.file_name())).collect())
        .map_err(|e| format!("cannot be read: {e}"))?;
    if entries.is_empty() {
        return Ok(Vec::new());
    }
    let not_a_report = |why: &str| {
        format!(
            "is a folder that holds other files, not an earlier report ({why}); give a new or \
             empty folder"
        )
    };
    let marker = folder.join(REPORT_MARKER);
    let meta = std::fs::symlink_metadata(&marker)
        .map_err(|_| not_a_report(&format!("it has no {REPORT_MARKER}")))?;
    if meta.file_type().is_symlink() {
        return Err(not_a_report(&format!(
            "its {REPORT_MARKER} is a symbolic link, not the list of files a report writes"
        )));
    }
    if !meta.is_file() || meta.len() > MAX_MARKER_BYTES {
        return Err(not_a_report(&format!(
            "its {REPORT_MARKER} is not the list of files a report writes"
        )));
    }
    let text = std::fs::read(&marker)
        .ok()
        .and_then(|b| String::from_utf8(b).ok())
        .unwrap_or_default();
    let listed: Vec<&str> = if text == LEGACY_MARKER {
        LEGACY_FILES.to_vec()
    } else if let Some(names) = text
        .strip_prefix(MARKER_HEAD)
        .and_then(|rest| rest.strip_prefix('\n'))
    {
        names.lines().filter(|n| !n.is_empty()).collect()
    } else {
        return Err(not_a_report(&format!(
            "its {REPORT_MARKER} is {}not the list of files a report writes",
            if text.trim().is_empty() {
                "empty: "
            } else {
                ""
            }
        )));
    };
    for name in &listed {
        let plain = Path::new(name).file_name() == Some(std::ffi::OsStr::new(name))
            && *name != REPORT_MARKER;
        if !plain {
            return Err(not_a_report(&format!(
                "its {REPORT_MARKER} names '{}', not a file of the folder",
                name.escape_debug()
            )));
        }
    }
    let others: Vec<String> = entries
        .iter()
        .filter(|e| *e != REPORT_MARKER && !listed.iter().any(|n| *e == *n))
        .map(|e| e.to_string_lossy().escape_debug().to_string())
        .collect();
    if !others.is_empty() {
        let shown: Vec<&str> = others.iter().take(3).map(String::as_str).collect();
        return Err(format!(
            "holds {} the earlier report there did not write ({}{}); move {} out, or give a new \
             or empty folder",
            if others.len() == 1 { "a file" } else { "files" },
            shown.join(", "),
            if others.len() > 3 { ", …" } else { "" },
            if others.len() == 1 { "it" } else { "them" },
        ));
    }
    let mut present = Vec::new();
    for name in listed {
        match std::fs::symlink_metadata(folder.join(name)) {
            Ok(m) if m.is_file() => present.push(name.into()),
            Ok(_) => {
                return Err(format!(
                    "holds '{}', which is not a file the earlier report wrote (a folder or a \
                     link); move it out, or give a new or empty folder",
                    name.escape_debug()
                ))
            }
            Err(_) => {}
        }
    }
    Ok(present)
}

/// A folder written whole or not at all: files go into a temporary folder
/// beside the target, which replaces the target with the run's other
/// outputs ([`commit_all`]). The target must be new, empty, or a folder an
/// earlier report wrote that holds nothing else (its [`REPORT_MARKER`]
/// lists its files): any other folder is refused before any work, and of
/// an earlier report only the files its marker lists are removed.
pub struct AtomicFolder {
    id: Option<usize>,
    temporary: PathBuf,
    /// The names of the files written into it.
    files: Vec<String>,
    shown: String,
    flag: &'static str,
}

impl AtomicFolder {
    /// Checks that `target` (named by `flag`) may be written: not `-`, not
    /// a file, and new, empty or an earlier report that holds nothing
    /// else.
    pub fn check(target: &Path, flag: &'static str) -> Result<(), CliError> {
        let shown = target.display().to_string();
        if is_stdout(target) {
            return Err(CliError::flag(
                flag,
                "a report is a folder of files and cannot go to standard output ('-'); give a folder name",
            ));
        }
        let entry = std::fs::symlink_metadata(target);
        if entry.is_ok() && !target.is_dir() {
            return Err(CliError::flag(
                flag,
                format!("'{shown}' exists and is not a folder"),
            ));
        }
        if entry.is_ok_and(|m| m.file_type().is_symlink()) {
            return Err(CliError::flag(
                flag,
                format!("'{shown}' is a symbolic link; give the folder itself"),
            ));
        }
        if target.is_dir() {
            earlier_report(target)
                .map_err(|why| CliError::flag(flag, format!("'{shown}' {why}")))?;
        }
        if temporary_beside(target).is_none() {
            return Err(CliError::flag(
                flag,
                format!("'{shown}' is not a folder name"),
            ));
        }
        if let Some(parent) = target.parent().filter(|p| !p.as_os_str().is_empty()) {
            if !parent.is_dir() {
                return Err(CliError::flag(
                    flag,
                    format!("the folder '{}' does not exist", parent.display()),
                ));
            }
        }
        Ok(())
    }

    /// Starts the folder `target` (named by `flag`).
    pub fn create(target: &Path, flag: &'static str) -> Result<Self, CliError> {
        Self::check(target, flag)?;
        let shown = target.display().to_string();
        let temporary = temporary_beside(target)
            .ok_or_else(|| CliError::flag(flag, format!("'{shown}' is not a folder name")))?;
        std::fs::create_dir(&temporary)
            .map_err(|e| CliError::flag(flag, format!("cannot create '{shown}': {e}")))?;
        let id = register(Pending::Path {
            temporary: temporary.clone(),
            target: target.to_path_buf(),
            folder: true,
            ready: false,
        });
        Ok(Self {
            id: Some(id),
            temporary,
            files: Vec::new(),
            shown,
            flag,
        })
    }

    /// Where to write the folder's file `name`, which its marker will
    /// list.
    pub fn file(&mut self, name: &str) -> PathBuf {
        if !self.files.iter().any(|f| f == name) {
            self.files.push(name.to_string());
        }
        self.temporary.join(name)
    }

    /// Writes the marker listing the folder's files and marks the folder
    /// ready, after every file in it; returns its path.
    pub fn commit(mut self, target: &Path) -> Result<PathBuf, CliError> {
        let mut marker = format!("{MARKER_HEAD}\n");
        for name in &self.files {
            marker.push_str(name);
            marker.push('\n');
        }
        std::fs::write(self.temporary.join(REPORT_MARKER), marker).map_err(|e| {
            CliError::flag(self.flag, format!("cannot write in '{}': {e}", self.shown))
        })?;
        if let Some(id) = self.id.take() {
            mark_ready(id);
        }
        Ok(target.to_path_buf())
    }
}

impl Drop for AtomicFolder {
    /// A folder dropped before its commit is removed with everything in it.
    fn drop(&mut self) {
        if let Some(id) = self.id.take() {
            discard(id);
        }
    }
}
