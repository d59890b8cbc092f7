//! Helpers: run the real binary, read its JSON, check the error contract.

use assert_cmd::Command;
use serde_json::Value;

pub fn pendulum() -> Command {
    Command::cargo_bin("pendulum").expect("the pendulum binary is built")
}

/// Runs with `args`, expects success, parses standard output as JSON.
pub fn json(args: &[&str]) -> Value {
    let out = pendulum()
        .args(args)
        .arg("--json")
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    serde_json::from_slice(&out).expect("standard output is JSON")
}

/// Runs with `args`, expects success, returns standard output as text.
pub fn text(args: &[&str]) -> String {
    let out = pendulum()
        .args(args)
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    String::from_utf8(out).expect("standard output is UTF-8")
}

/// Runs with `args` and expects the one-line error contract: status 2,
/// nothing on standard output, one line on standard error naming `flag`.
pub fn refuses(args: &[&str], flag: &str) -> String {
    refuses_given(args, b"", flag)
}

/// [`refuses`], with `stdin` on standard input.
pub fn refuses_given(args: &[&str], stdin: &[u8], flag: &str) -> String {
    let out = pendulum()
        .args(args)
        .write_stdin(stdin.to_vec())
        .assert()
        .code(2)
        .stdout("")
        .get_output()
        .stderr
        .clone();
    let text = String::from_utf8(out).unwrap();
    assert_eq!(text.lines().count(), 1, "one line expected, got: {text}");
    assert!(text.starts_with("error: "), "{text}");
    assert!(text.contains(flag), "{text} should name {flag}");
    text
}

pub fn f(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} missing in {v}"))
}

/// `period --length 1 --amplitude 3` followed by `extra`.
pub fn p<'a>(extra: &[&'a str]) -> Vec<&'a str> {
    let mut v = vec!["period", "--length", "1", "--amplitude", "3"];
    v.extend_from_slice(extra);
    v
}

/// The names of the entries of `dir` (to check what a run left behind).
/// Sends `child` Ctrl-C (SIGINT, by the system's `kill`).
pub fn interrupt(child: &std::process::Child) {
    let status = std::process::Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(status.success());
}

pub fn files_in(dir: &std::path::Path) -> Vec<std::ffi::OsString> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect()
}

/// Decodes a PNG into its width, height and RGB bytes (alpha dropped,
/// grey widened).
pub fn decode_png(bytes: Vec<u8>) -> (u32, u32, Vec<u8>) {
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
        .read_info()
        .unwrap();
    let mut pixels = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut pixels).unwrap();
    let channels = info.color_type.samples();
    let rgb = pixels
        .chunks(channels)
        .flat_map(|p| {
            if channels >= 3 {
                [p[0], p[1], p[2]]
            } else {
                [p[0]; 3]
            }
        })
        .collect();
    (info.width, info.height, rgb)
}

/// A system program a test needs (Debian's `package`), found on the PATH
/// under any of `names`. CI must have it (`.ci/run` installs it): there a
/// missing one fails the test. Elsewhere the test is skipped with a line
/// written straight to standard error, past the test harness's capture,
/// so that `cargo test` never reports a skipped test as a silent `ok`.
pub fn system_program(names: &[&str], package: &str, test: &str) -> Option<std::path::PathBuf> {
    let found = names.iter().find_map(|name| {
        std::env::var_os("PATH").and_then(|paths| {
            std::env::split_paths(&paths)
                .map(|p| p.join(name))
                .find(|p| p.is_file())
        })
    });
    if found.is_none() {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI must run {test}: install Debian's {package} (.ci/run does)"
        );
        use std::io::Write;
        let _ = writeln!(
            std::io::stderr().lock(),
            "skipped: {test}: install {package} (sudo apt-get install {package})"
        );
    }
    found
}

/// The repository's top folder.
pub fn repo_root() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The documentation: `README.md`, then every page of the book's sources
/// (`book/src/**/*.md`, sorted by path), each as (path from the
/// repository's top, text). The reference pages the book's build writes
/// from the binary's help (`book/src/reference/`) are left out: their
/// examples are the help's, which the tests read from the binary.
pub fn docs_files() -> Vec<(String, String)> {
    fn pages(dir: &std::path::Path, found: &mut Vec<std::path::PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                pages(&path, found);
            } else if path.extension().is_some_and(|e| e == "md") {
                found.push(path);
            }
        }
    }
    let root = repo_root();
    let src = root.join("book/src");
    let mut found = Vec::new();
    pages(&src, &mut found);
    let mut names: Vec<String> = found
        .iter()
        .map(|p| {
            p.strip_prefix(&root)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/")
        })
        .filter(|p| !p.starts_with("book/src/reference/"))
        .collect();
    names.sort();
    assert!(
        names.iter().any(|n| n == "book/src/SUMMARY.md"),
        "the book's sources: {names:?}"
    );
    std::iter::once("README.md".to_string())
        .chain(names)
        .map(|name| {
            let text =
                std::fs::read_to_string(root.join(&name)).unwrap_or_else(|e| panic!("{name}: {e}"));
            (name, text)
        })
        .collect()
}

/// The whole documentation as one text, the files in [`docs_files`]'s
/// order, a blank line between them.
pub fn docs_text() -> String {
    docs_files()
        .into_iter()
        .map(|(_, text)| text)
        .collect::<Vec<_>>()
        .join("\n\n")
}

/// One line of a command with its `#` comment and repeated spaces taken
/// out.
pub fn normalise(line: &str) -> String {
    let code = match line.find(" #") {
        Some(i) => &line[..i],
        None => line,
    };
    code.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The commands of the documentation's `sh` code blocks (continuation
/// lines joined, comment lines and blank lines skipped), in
/// [`docs_files`]'s order.
pub fn docs_commands() -> Vec<String> {
    let mut commands = Vec::new();
    for (_, text) in docs_files() {
        let mut in_block = false;
        let mut pending = String::new();
        for line in text.lines() {
            if line.starts_with("```") {
                in_block = line == "```sh";
                continue;
            }
            if !in_block || line.trim_start().starts_with('#') || line.trim().is_empty() {
                continue;
            }
            match line.trim_end().strip_suffix('\\') {
                Some(head) => pending.push_str(head),
                None => {
                    pending.push_str(line);
                    commands.push(normalise(&pending));
                    pending.clear();
                }
            }
        }
    }
    commands
}
