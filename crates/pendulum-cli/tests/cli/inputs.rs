//! Issue 44, the data and inputs: pipes read whole, a report's folder
//! cleared only of its own files, a raw stream's layout refused in one
//! line, a header glued to its first row, one unit per quantity.

use super::util::{json, pendulum};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// A file of the repository's examples.
fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name)
}

/// The binary's JSON (`args` and `--json`) with `stdin` on standard input.
fn json_given(args: &[&str], stdin: &[u8]) -> Value {
    let out = pendulum()
        .args(args)
        .arg("--json")
        .write_stdin(stdin.to_vec())
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    serde_json::from_slice(&out).expect("standard output is JSON")
}

/// `value` without the key naming the file it was read from.
fn without_file(mut value: Value) -> Value {
    value.as_object_mut().unwrap().remove("file");
    value
}

/// 1,000 fractional frequencies, one a line: 13.5 kB, well past the 8 KiB
/// a buffered first look takes from a pipe.
fn bare_column() -> String {
    (0..1000)
        .map(|i| format!("{:.9e}\n", 1e-9 * (f64::from(i) * 0.7).sin()))
        .collect()
}

// ---- Pipes are read whole ---------------------------------------------------

/// A bare column on standard input (`/dev/stdin`) gives what the same
/// file gives: every value (the first look at its width took the first
/// 8 KiB, and 1,000 values were analysed as 394).
#[test]
fn a_bare_column_through_dev_stdin_is_read_whole() {
    let dir = tempfile::tempdir().unwrap();
    let column = bare_column();
    assert!(column.len() > 8192);
    let path = dir.path().join("column.txt");
    std::fs::write(&path, &column).unwrap();
    let args =
        |file: &str| ["stability", file, "--kind", "frequency", "--tau0", "1s"].map(String::from);
    let from_file = json(&args(path.to_str().unwrap()).each_ref().map(String::as_str));
    let from_pipe = json_given(
        &args("/dev/stdin").each_ref().map(String::as_str),
        column.as_bytes(),
    );
    assert_eq!(from_file["phase_points"], 1001);
    assert_eq!(without_file(from_pipe), without_file(from_file));
}

/// The same through a shell's process substitution, `<(cat file)`: a
/// pipe named `/dev/fd/N`.
#[test]
fn a_bare_column_through_process_substitution_is_read_whole() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("column.txt");
    std::fs::write(&path, bare_column()).unwrap();
    let binary = assert_cmd::cargo::cargo_bin("pendulum");
    let out = std::process::Command::new("bash")
        .arg("-c")
        .arg(format!(
            "'{}' stability <(cat '{}') --kind frequency --tau0 1s --json",
            binary.display(),
            path.display()
        ))
        .output()
        .expect("bash runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["phase_points"], 1001);
}

/// A log's events on standard input: the first look at a headerless
/// file's width left nothing for the reader ("no rows of numbers").
#[test]
fn events_through_dev_stdin_are_read_whole() {
    let log = example("clock-log.csv");
    let events = example("clock-events.csv");
    let from_file = json(&[
        "log",
        log.to_str().unwrap(),
        "--events",
        events.to_str().unwrap(),
    ]);
    let from_pipe = json_given(
        &["log", log.to_str().unwrap(), "--events", "/dev/stdin"],
        &std::fs::read(&events).unwrap(),
    );
    assert_eq!(from_pipe, from_file);
}

/// A design read twice by one run (the report's page and its log's
/// predicted coefficients) from standard input: the second reading found
/// nothing ("no [[part]] sections").
#[test]
fn a_design_through_dev_stdin_is_read_by_every_reader() {
    let dir = tempfile::tempdir().unwrap();
    let design = example("seconds-steel-brass.toml");
    let log = example("clock-log.csv");
    let args = |design: &str, output: &str| {
        [
            "report",
            "--design",
            design,
            "--log",
            log.to_str().unwrap(),
            "--output",
            output,
        ]
        .map(String::from)
    };
    let first = dir.path().join("from-file");
    let second = dir.path().join("from-pipe");
    let from_file = json(
        &args(design.to_str().unwrap(), first.to_str().unwrap())
            .each_ref()
            .map(String::as_str),
    );
    let from_pipe = json_given(
        &args("/dev/stdin", second.to_str().unwrap())
            .each_ref()
            .map(String::as_str),
        &std::fs::read(&design).unwrap(),
    );
    assert!(
        from_pipe["log"]["design"].is_object(),
        "{}",
        from_pipe["log"]
    );
    assert_eq!(from_pipe, from_file);
}
