//! The file formats read whole and turned into table text before the
//! table reader sees them: each one a [`FileFormat`] in [`FORMATS`], the
//! list every reader of files reads (the command line and the page hand
//! their bytes to [`crate::stream_table`], which asks the list). A file is
//! taken by the first format whose extension it has or whose first bytes
//! it recognises; anything else is read as a text table (CSV, semicolon,
//! tab or space separated). A new format is one file with its reader and
//! its [`FileFormat`], and one line in [`FORMATS`] (see [`crate::ticc`]).

/// A file turned into table text.
#[derive(Debug, Default)]
pub struct Converted {
    /// The rows as a text table (a header line, then the numbers), as an
    /// export of the same data would hold them.
    pub text: String,
    /// The part of the file read, where it holds several (a workbook's
    /// sheet): the output's `format.sheet`.
    pub sheet: Option<String>,
    /// The track read from a video analysis: `format.tracker_track`.
    pub track: Option<String>,
    /// The file's line of each line of `text`, where they differ (empty:
    /// the same), so that messages name the file's lines.
    pub lines: Vec<u64>,
    /// What the reader left out or chose that the user should hear of,
    /// one sentence each (the file's name is put before it).
    pub notes: Vec<String>,
}

/// One file format read whole.
#[derive(Clone, Copy, Debug)]
pub struct FileFormat {
    /// Its name in messages and in the output's `format.reader`.
    pub name: &'static str,
    /// The extensions that name it (lower case, without the dot).
    pub extensions: &'static [&'static str],
    /// Whether the first bytes of a file (up to 8 KiB) are this format's,
    /// for a format told by its contents rather than its name.
    pub recognise: Option<fn(head: &[u8]) -> bool>,
    /// Reads the whole file into table text, or says why it cannot.
    pub read: fn(bytes: Vec<u8>) -> Result<Converted, String>,
}

/// Every format read whole, in the order they are asked.
pub const FORMATS: &[FileFormat] = &[
    crate::workbook::FORMAT,
    crate::tracker::FORMAT,
    crate::ticc::FORMAT,
];

/// The format a file called `name` has by its extension.
pub fn by_name(name: &str) -> Option<&'static FileFormat> {
    let extension = name
        .rsplit_once('.')
        .map(|(_, e)| e)
        .filter(|e| !e.contains(['/', '\\']))?;
    FORMATS.iter().find(|f| {
        f.extensions
            .iter()
            .any(|x| extension.eq_ignore_ascii_case(x))
    })
}

/// The format whose contents begin as `head` does.
pub fn by_contents(head: &[u8]) -> Option<&'static FileFormat> {
    FORMATS
        .iter()
        .find(|f| f.recognise.is_some_and(|recognise| recognise(head)))
}
