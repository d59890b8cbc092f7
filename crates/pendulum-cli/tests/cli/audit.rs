//! The audit of issue 21: hundreds of odd inputs over every command, each
//! run through the real binary as a user would, under a CPU-time limit.
//!
//! The cases are data, `tests/data/audit/cases.jsonl`, written by
//! `tools/audit/make_cases.py` (which also writes the small odd files of
//! `tests/data/audit/fixtures/`): grow the generator, run it, commit both.
//! Each case runs in a folder of its own holding the fixtures and the
//! files of `examples/`, after its `setup` (links, folders, user files).
//! A case fails when the binary
//! - panics, aborts, is killed, or uses more than 10 s of CPU;
//! - exits other than 0 or 2, or refuses in anything but one line
//!   `error: …` with nothing on standard output;
//! - prints a non-finite number ("NaN", "inf") the user did not type, a
//!   number of 40 digits or more, or an internal error ("please report");
//! - changes or deletes any file that was there before (byte for byte);
//! - leaves any new file or folder after a refusal, or a temporary
//!   (`.partial`) file after anything;
//! - accepts a case the generator marks as one to refuse.

use serde_json::Value;
use std::collections::BTreeMap;
use std::io::Read;
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::Mutex;

/// CPU seconds a case may use.
const CPU_SECONDS: u32 = 10;

fn data_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/audit")
}

fn examples_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// One case of the generator.
struct Case {
    id: String,
    args: Vec<String>,
    expect: String,
    setup: Vec<Vec<String>>,
}

fn cases() -> Vec<Case> {
    let text = std::fs::read_to_string(data_dir().join("cases.jsonl"))
        .expect("tests/data/audit/cases.jsonl (run tools/audit/make_cases.py)");
    text.lines()
        .filter(|l| !l.trim().is_empty())
        .map(|line| {
            let v: Value = serde_json::from_str(line).expect("a case is one JSON object");
            let strings = |v: &Value| -> Vec<String> {
                v.as_array()
                    .map(|a| {
                        a.iter()
                            .map(|x| x.as_str().expect("strings").to_string())
                            .collect()
                    })
                    .unwrap_or_default()
            };
            Case {
                id: v["id"].as_str().expect("an id").to_string(),
                args: strings(&v["args"]),
                expect: v["expect"].as_str().unwrap_or("either").to_string(),
                setup: v["setup"]
                    .as_array()
                    .map(|a| a.iter().map(strings).collect())
                    .unwrap_or_default(),
            }
        })
        .collect()
}

/// Copies the files of `from` (a flat folder) that `mentioned` names into
/// `to`: a case's folder holds what its command line and setup name,
/// not the whole fixture set (which would make thousands of copies).
fn copy_named(from: &Path, to: &Path, mentioned: &str) {
    for entry in std::fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let name = entry.file_name().to_string_lossy().into_owned();
        if entry.file_type().unwrap().is_file() && mentioned.contains(&name) {
            std::fs::copy(entry.path(), to.join(&name)).unwrap();
        }
    }
}

/// Every entry below `dir`: relative path, and for a file its bytes'
/// digest (a link is recorded as where it points).
fn snapshot(dir: &Path) -> BTreeMap<PathBuf, String> {
    fn walk(root: &Path, dir: &Path, out: &mut BTreeMap<PathBuf, String>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            let rel = path.strip_prefix(root).unwrap().to_path_buf();
            let kind = std::fs::symlink_metadata(&path).unwrap().file_type();
            if kind.is_symlink() {
                let to = std::fs::read_link(&path).unwrap();
                out.insert(rel, format!("link to {}", to.display()));
            } else if kind.is_dir() {
                out.insert(rel, "folder".into());
                walk(root, &path, out);
            } else if !kind.is_file() {
                // A FIFO (reading it would wait for a writer) or a device.
                out.insert(rel, "special file".into());
            } else {
                let bytes = std::fs::read(&path).unwrap_or_default();
                out.insert(rel, digest(&bytes));
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(dir, dir, &mut out);
    out
}

/// FNV-1a 64 of the bytes, with their length: enough to see any change.
fn digest(bytes: &[u8]) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    format!("{}:{h:016x}", bytes.len())
}

fn setup(dir: &Path, steps: &[Vec<String>]) -> Result<(), String> {
    for step in steps {
        let at = |i: usize| dir.join(&step[i]);
        match step.first().map(String::as_str) {
            Some("symlink") => std::os::unix::fs::symlink(&step[2], at(1)),
            Some("hardlink") => std::fs::hard_link(at(2), at(1)),
            Some("mkdir") => std::fs::create_dir_all(at(1)),
            Some("write") => std::fs::write(at(1), &step[2]),
            Some("copy") => std::fs::copy(at(2), at(1)).map(|_| ()),
            Some("remove") => std::fs::remove_file(at(1)),
            Some("mkfifo") => Command::new("mkfifo").arg(at(1)).status().and_then(|s| {
                s.success()
                    .then_some(())
                    .ok_or_else(|| std::io::Error::other("mkfifo failed"))
            }),
            Some("chmod") => {
                use std::os::unix::fs::PermissionsExt;
                let mode = u32::from_str_radix(&step[2], 8).map_err(|e| e.to_string())?;
                std::fs::set_permissions(at(1), std::fs::Permissions::from_mode(mode))
            }
            other => return Err(format!("unknown setup step {other:?}")),
        }
        .map_err(|e| format!("setup {step:?}: {e}"))?;
    }
    Ok(())
}

/// The words of `text` that are non-finite numbers and not among the
/// words the user typed; a word in single quotes is a quotation of the
/// input (`'NaN' is not a number`) and does not count.
fn non_finite_words(text: &str, typed: &[String]) -> Vec<String> {
    let unquoted: String = text
        .split('\'')
        .enumerate()
        .filter(|(i, _)| i % 2 == 0)
        .map(|(_, part)| part)
        .collect::<Vec<_>>()
        .join(" ");
    let text = unquoted.as_str();
    let words = |t: &str| -> Vec<String> {
        t.split(|c: char| !(c.is_ascii_alphanumeric() || c == '.' || c == '_'))
            .filter(|w| !w.is_empty())
            .map(str::to_string)
            .collect()
    };
    let typed_words: Vec<String> = typed.iter().flat_map(|a| words(a)).collect();
    words(text)
        .into_iter()
        .filter(|w| {
            matches!(
                w.to_ascii_lowercase().as_str(),
                "nan" | "inf" | "infinity" | "-inf"
            ) && !typed_words.contains(w)
        })
        .collect()
}

/// The longest run of digits in `text`.
fn longest_digit_run(text: &str) -> usize {
    text.split(|c: char| !c.is_ascii_digit())
        .map(str::len)
        .max()
        .unwrap_or(0)
}

/// Runs one case; `Err` says what went wrong.
fn run_case(case: &Case, binary: &Path) -> Result<(), String> {
    let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
    let mentioned = format!("{:?} {:?}", case.args, case.setup);
    copy_named(&examples_dir(), dir.path(), &mentioned);
    copy_named(&data_dir().join("fixtures"), dir.path(), &mentioned);
    setup(dir.path(), &case.setup)?;
    let before = snapshot(dir.path());
    // The CPU limit set in the child before it runs the binary (SIGXCPU
    // kills the run); a wall-clock guard of ten times that only keeps a
    // hang from stopping the suite.
    let mut command = Command::new(binary);
    command
        .args(&case.args)
        .current_dir(dir.path())
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    // SAFETY: setrlimit is async-signal-safe, and the closure allocates
    // nothing between fork and exec.
    unsafe {
        command.pre_exec(|| {
            let limit = libc::rlimit {
                rlim_cur: libc::rlim_t::from(CPU_SECONDS),
                rlim_max: libc::rlim_t::from(CPU_SECONDS),
            };
            if libc::setrlimit(libc::RLIMIT_CPU, &limit) == 0 {
                Ok(())
            } else {
                Err(std::io::Error::last_os_error())
            }
        });
    }
    let mut child = command.spawn().map_err(|e| e.to_string())?;
    // Both pipes drained as the command runs (a command writing much to
    // standard output would otherwise wait on a full pipe).
    let drain = |pipe: Option<Box<dyn std::io::Read + Send>>| {
        std::thread::spawn(move || {
            let mut bytes = Vec::new();
            if let Some(mut p) = pipe {
                let _ = p.read_to_end(&mut bytes);
            }
            bytes
        })
    };
    let out_reader = drain(child.stdout.take().map(|p| Box::new(p) as _));
    let err_reader = drain(child.stderr.take().map(|p| Box::new(p) as _));
    let pid = child.id() as libc::pid_t;
    let (ended, watched) = std::sync::mpsc::channel::<()>();
    let guard = std::thread::spawn(move || {
        let wall = std::time::Duration::from_secs(u64::from(10 * CPU_SECONDS));
        let hung = watched.recv_timeout(wall).is_err();
        if hung {
            // SAFETY: a plain signal to the child, which has not been
            // waited for yet (its pid is still its own).
            unsafe { libc::kill(pid, libc::SIGKILL) };
        }
        hung
    });
    let status = child.wait().map_err(|e| e.to_string())?;
    let _ = ended.send(());
    if guard.join().unwrap_or(false) {
        return Err("hung: no end after 100 s (waiting, not computing)".into());
    }
    let stdout = String::from_utf8_lossy(&out_reader.join().unwrap_or_default()).into_owned();
    let stderr = String::from_utf8_lossy(&err_reader.join().unwrap_or_default()).into_owned();
    let first = |t: &str| t.chars().take(200).collect::<String>();
    let code = match status.code() {
        Some(c) => c,
        None => {
            use std::os::unix::process::ExitStatusExt;
            return Err(match status.signal() {
                Some(24) => format!("over {CPU_SECONDS} s of CPU (SIGXCPU)"),
                s => format!("killed by signal {s:?}: {}", first(&stderr)),
            });
        }
    };
    if code != 0 && code != 2 {
        return Err(format!("exit {code}: {}", first(&stderr)));
    }
    for bad in ["panicked", "backtrace", "please report", "RUST_BACKTRACE"] {
        if stderr.contains(bad) || stdout.contains(bad) {
            return Err(format!("'{bad}' in the output: {}", first(&stderr)));
        }
    }
    if code == 2 {
        if !stdout.is_empty() {
            return Err(format!("refused but printed: {}", first(&stdout)));
        }
        if stderr.lines().count() != 1 || !stderr.starts_with("error: ") {
            return Err(format!("a refusal not in one line: {}", first(&stderr)));
        }
    }
    let words = non_finite_words(&format!("{stdout}\n{stderr}"), &case.args);
    if !words.is_empty() {
        return Err(format!(
            "non-finite words {words:?}: {}",
            first(&format!("{stderr}{stdout}"))
        ));
    }
    // Messages, not data: a data file on standard output may hold long
    // numbers legitimately, the text may not.
    let text = if stdout.len() > 20_000 {
        &stderr
    } else {
        &stdout
    };
    if longest_digit_run(text) >= 40 || longest_digit_run(&stderr) >= 40 {
        return Err(format!("a number of 40 digits or more: {}", first(&stderr)));
    }
    let after = snapshot(dir.path());
    for (path, was) in &before {
        match after.get(path) {
            None => return Err(format!("deleted {}", path.display())),
            Some(now) if now != was => return Err(format!("changed {}", path.display())),
            _ => {}
        }
    }
    let new: Vec<&PathBuf> = after.keys().filter(|p| !before.contains_key(*p)).collect();
    if let Some(p) = new
        .iter()
        .find(|p| p.to_string_lossy().contains(".partial"))
    {
        return Err(format!("left a temporary file {}", p.display()));
    }
    if code == 2 && !new.is_empty() {
        return Err(format!("refused but left {new:?}: {}", first(&stderr)));
    }
    if code == 0 && case.expect == "refuse" {
        return Err(format!("accepted an input to refuse: {}", first(&stdout)));
    }
    if code == 2 && case.expect == "ok" {
        return Err(format!("refused a legitimate input: {}", first(&stderr)));
    }
    Ok(())
}

#[test]
fn every_odd_input_is_answered_safely() {
    let cases = cases();
    assert!(
        cases.len() >= 400,
        "the audit has {} cases; issue 21 asks for at least 400",
        cases.len()
    );
    let commands: std::collections::BTreeSet<String> = cases
        .iter()
        .filter_map(|c| c.args.first().cloned())
        .collect();
    // Every subcommand the binary lists (read from its help, so a new one
    // without audit cases fails here).
    let binary = PathBuf::from(env!("CARGO_BIN_EXE_pendulum"));
    let help = Command::new(&binary).arg("--help").output().unwrap();
    let help = String::from_utf8_lossy(&help.stdout).into_owned();
    let listed: Vec<&str> = help
        .lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "help")
        .collect();
    assert!(listed.len() >= 15, "the help lists {listed:?}");
    for command in listed {
        assert!(commands.contains(command), "no audit case runs '{command}'");
    }
    let next = Mutex::new(0usize);
    let failures = Mutex::new(Vec::new());
    std::thread::scope(|scope| {
        // (Three workers on two cores: a case's start and its files are
        // waiting, not computing.)
        for _ in 0..3 {
            scope.spawn(|| loop {
                let i = {
                    let mut n = next.lock().unwrap();
                    *n += 1;
                    *n - 1
                };
                let Some(case) = cases.get(i) else { break };
                if let Err(why) = run_case(case, &binary) {
                    failures.lock().unwrap().push(format!(
                        "{}: {why}\n    pendulum {}",
                        case.id,
                        case.args.join(" ")
                    ));
                }
            });
        }
    });
    let failures = failures.into_inner().unwrap();
    assert!(
        failures.is_empty(),
        "{} of {} audit cases failed:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );
}

#[test]
fn the_audit_can_fail() {
    // The checks themselves: a non-finite word the user did not type, a
    // 309-digit number.
    assert_eq!(
        non_finite_words("rate inf s/day", &["--rate".into(), "3".into()]),
        vec!["inf".to_string()]
    );
    assert!(non_finite_words("got inf", &["inf".into()]).is_empty());
    assert!(non_finite_words("line 5: 'NaN' is not a number", &[]).is_empty());
    assert_eq!(
        non_finite_words("'x' gives NaN", &[]),
        vec!["NaN".to_string()]
    );
    assert_eq!(longest_digit_run(&format!("got 1{}", "0".repeat(308))), 309);
    assert_ne!(digest(b"thesis\n"), digest(b"thesis \n"));
}
