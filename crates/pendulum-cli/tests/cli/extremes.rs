//! Extreme but valid inputs across every command, arbitrary argument
//! vectors, and a full disk: the binary answers with status 0 or 2, never
//! panics, never prints a non-finite number, never runs past 10 s, and
//! leaves no file behind when it fails.

use super::util::files_in;
use proptest::prelude::*;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// The longest any single run may take.
const LIMIT: Duration = Duration::from_secs(10);

/// What one run did.
struct Ran {
    code: Option<i32>,
    stdout: String,
    stderr: String,
    elapsed: Duration,
    timed_out: bool,
}

/// Runs the binary with `args` in `dir`, killing it after [`LIMIT`].
fn run(dir: &Path, args: &[String]) -> Ran {
    let started = Instant::now();
    let mut child = Command::new(env!("CARGO_BIN_EXE_pendulum"))
        .current_dir(dir)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let drain = |mut pipe: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut text = Vec::new();
            let _ = pipe.read_to_end(&mut text);
            String::from_utf8_lossy(&text).into_owned()
        })
    };
    let out = drain(Box::new(child.stdout.take().unwrap()));
    let err = drain(Box::new(child.stderr.take().unwrap()));
    let mut timed_out = false;
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if started.elapsed() > LIMIT {
            timed_out = true;
            let _ = child.kill();
            break child.wait().unwrap();
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    Ran {
        code: status.code(),
        stdout: out.join().unwrap(),
        stderr: err.join().unwrap(),
        elapsed: started.elapsed(),
        timed_out,
    }
}

/// The contract every run must keep; returns a description of the breach.
fn breach(args: &[String], ran: &Ran) -> Option<String> {
    let shown = args.join(" ");
    if ran.timed_out {
        return Some(format!("ran past {LIMIT:?}: {shown}"));
    }
    match ran.code {
        Some(0) => {}
        Some(2) => {
            if !ran.stdout.is_empty() {
                return Some(format!("error with standard output: {shown}"));
            }
            if ran.stderr.lines().count() != 1 || !ran.stderr.starts_with("error: ") {
                return Some(format!("not one error line: {shown}: {}", ran.stderr));
            }
        }
        other => {
            return Some(format!(
                "status {other:?} (a panic is 101): {shown}: {}",
                ran.stderr
            ))
        }
    }
    for text in [&ran.stdout, &ran.stderr] {
        // What the user typed is echoed in quotes ('nan' is not a number):
        // only computed values must be finite.
        // Words typed as arguments (a folder called nan) are echoes too.
        let text = without_quoted(text);
        let split = |t: &str| -> Vec<String> {
            t.split(|c: char| !(c.is_ascii_alphanumeric() || c == '.' || c == '_'))
                .map(String::from)
                .collect()
        };
        let typed: Vec<String> = args.iter().flat_map(|a| split(a)).collect();
        let bad = split(&text).into_iter().find(|w| {
            matches!(w.as_str(), "NaN" | "nan" | "inf" | "infinity" | "Infinity")
                && !typed.contains(w)
        });
        if let Some(word) = bad {
            return Some(format!("'{word}' printed: {shown}"));
        }
    }
    None
}

/// `text` without the parts in single quotes.
fn without_quoted(text: &str) -> String {
    text.split('\'').step_by(2).collect::<Vec<_>>().join(" ")
}

/// Runs every argument vector on two threads; fails listing every breach.
fn run_all(cases: Vec<Vec<String>>) {
    let dir = tempfile::tempdir().unwrap();
    let next = AtomicUsize::new(0);
    let breaches = Mutex::new(Vec::new());
    let slowest = Mutex::new((Duration::ZERO, String::new()));
    std::thread::scope(|scope| {
        for _ in 0..2 {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::SeqCst);
                let Some(args) = cases.get(i) else { break };
                let ran = run(dir.path(), args);
                if let Some(b) = breach(args, &ran) {
                    breaches.lock().unwrap().push(b);
                }
                let mut s = slowest.lock().unwrap();
                if ran.elapsed > s.0 {
                    *s = (ran.elapsed, args.join(" "));
                }
            });
        }
    });
    let (time, args) = slowest.into_inner().unwrap();
    eprintln!(
        "{} runs; slowest {:.2} s: {args}",
        cases.len(),
        time.as_secs_f64()
    );
    let breaches = breaches.into_inner().unwrap();
    assert!(breaches.is_empty(), "{}", breaches.join("\n"));
}

fn strings(args: &[&str]) -> Vec<String> {
    args.iter().map(|s| s.to_string()).collect()
}

const LENGTHS: [&str; 4] = ["1e-6m", "1e-3m", "1m", "1e4m"];
const AMPLITUDES: [&str; 5] = ["1e-12rad", "1e-6rad", "3deg", "90deg", "179.999deg"];
const DAMPINGS: [[&str; 2]; 9] = [
    ["--zeta", "0"],
    ["--zeta", "1e-9"],
    ["--zeta", "0.5"],
    ["--zeta", "1"],
    ["--zeta", "2"],
    ["--zeta", "1e6"],
    ["--q", "1e-6"],
    ["--q", "1"],
    ["--q", "1e15"],
];
const DURATIONS: [&str; 4] = ["0s", "1s", "1e5s", "1e9s"];

/// Text for even cases, JSON for odd ones.
fn with_format(mut args: Vec<String>, i: usize) -> Vec<String> {
    if i % 2 == 1 {
        args.push("--json".into());
    }
    args
}

#[test]
fn extreme_inputs_in_every_command() {
    let mut cases = Vec::new();
    for l in LENGTHS {
        for a in AMPLITUDES {
            cases.push(strings(&["period", "--length", l, "--amplitude", a]));
            for period in ["1e-6s", "2s", "1e6s"] {
                cases.push(strings(&["length", "--period", period, "--amplitude", a]));
            }
            for [flag, value] in DAMPINGS {
                cases.push(strings(&[
                    "damped",
                    "--length",
                    l,
                    "--amplitude",
                    a,
                    flag,
                    value,
                    "--mass",
                    "1kg",
                ]));
                for d in DURATIONS {
                    cases.push(strings(&[
                        "simulate",
                        "--length",
                        l,
                        "--amplitude",
                        a,
                        flag,
                        value,
                        "--duration",
                        d,
                    ]));
                }
            }
        }
        cases.push(strings(&[
            "period",
            "--length",
            l,
            "--amplitude",
            "1e-12rad..179.999deg",
            "--steps",
            "50",
        ]));
        for period in ["1e-6s", "2s", "1e4s"] {
            cases.push(strings(&["amplitude", "--period", period, "--length", l]));
        }
        for [flag, value] in DAMPINGS {
            cases.push(strings(&[
                "report", "--length", l, flag, value, "--output", "r",
            ]));
            for d in DURATIONS {
                cases.push(strings(&[
                    "damped",
                    "--length",
                    l,
                    "--amplitude",
                    "3deg",
                    flag,
                    value,
                    "--trajectory",
                    "t.csv",
                    "--duration",
                    d,
                    "--sample-interval",
                    "10s",
                ]));
            }
        }
        for file in ["rundown.csv", "video.csv"] {
            let command = if file == "video.csv" {
                "trajectory"
            } else {
                "decay"
            };
            let path = examples().join(file);
            cases.push(strings(&[
                "fit",
                command,
                path.to_str().unwrap(),
                "--length",
                l,
            ]));
        }
    }
    for a in AMPLITUDES {
        cases.push(strings(&["report", "--amplitude", a, "--output", "r"]));
    }
    for (lat, h) in [
        ("-90", "-11km"),
        ("90", "100km"),
        ("0", "0m"),
        ("45", "-1e7m"),
    ] {
        cases.push(strings(&["gravity", "--latitude", lat, "--height", h]));
    }
    let cases = cases
        .into_iter()
        .enumerate()
        .map(|(i, c)| with_format(c, i))
        .collect();
    run_all(cases);
}

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// Each subcommand's words, the flags it needs (always given, with
/// arbitrary values) and the flags it may take (given at random).
type Spec = (
    &'static [&'static str],
    &'static [&'static str],
    &'static [&'static str],
);
const COMMANDS: [Spec; 10] = [
    (
        &["period"],
        &["--length", "--amplitude"],
        &[
            "--steps",
            "--series-terms",
            "--g",
            "--latitude",
            "--height",
            "--plot",
            "--csv",
        ],
    ),
    (
        &["length"],
        &["--bph"],
        &["--amplitude", "--g", "--latitude", "--height"],
    ),
    (
        &["amplitude"],
        &["--period", "--length"],
        &["--period-uncertainty", "--g", "--latitude", "--height"],
    ),
    (&["gravity"], &["--latitude"], &["--height"]),
    (
        &["damped"],
        &["--length", "--amplitude", "--q"],
        &[
            "--friction-angle",
            "--extrema",
            "--plot",
            "--g",
            "--mass",
            "--trajectory",
            "--duration",
            "--sample-interval",
        ],
    ),
    (
        &["simulate"],
        &["--length", "--amplitude", "--duration"],
        &[
            "--zeta",
            "--q",
            "--friction-angle",
            "--quadratic-drag",
            "--method",
            "--tolerance",
            "--swings",
            "--plot",
            "--phase-plot",
            "--decay-time",
            "--mass",
        ],
    ),
    (
        &["report"],
        &[],
        &[
            "--length",
            "--amplitude",
            "--zeta",
            "--q",
            "--mass",
            "--output",
            "--g",
        ],
    ),
    (
        &["fit", "decay"],
        &[],
        &["--model", "--length", "--mass", "--plot"],
    ),
    (
        &["fit", "trajectory"],
        &[],
        &["--length", "--model", "--residuals", "--plot"],
    ),
    (&["fit", "beats"], &[], &["--bph", "--period", "--plot"]),
];

/// Values as a user types them, sensible or hostile.
fn value() -> impl Strategy<Value = String> {
    let number = prop_oneof![
        any::<f64>().prop_map(|x| format!("{x}")),
        (-320i32..320).prop_map(|e| format!("1e{e}")),
        (-1000.0f64..1000.0).prop_map(|x| format!("{x}")),
    ];
    let unit = prop::sample::select(vec![
        "", "m", "mm", "deg", "rad", "°", "s", "ms", "day", "kg", "in", "arcmin", "x", "..3deg",
    ]);
    prop_oneof![
        6 => prop::sample::select(vec![
            "1m", "0.99362m", "3deg", "0.5rad", "10s", "1h", "0.05", "100", "1e-3", "5kg", "3600",
            "1e4", "2s", "45", "170deg", "1e-9", "1e9", "7day",
        ])
        .prop_map(String::from),
        1 => (number, unit).prop_map(|(n, u)| format!("{n}{u}")),
        1 => prop::sample::select(vec![
            "",
            "-",
            "--",
            "nan",
            "inf",
            "-inf",
            "NaN",
            "1e309",
            "0",
            "-0",
            "..",
            "1..",
            "3deg..1deg",
            "dop853",
            "exact",
            "symplectic",
            "vern9",
            "all",
            "nonlinear",
            "linear",
            "ε",
            "１",
            "0x10",
            "r.csv",
            "p.svg",
            "p.png",
            "p.pdf",
            "/",
            ".",
            "r",
        ])
        .prop_map(String::from),
        1 => "[ -~]{0,12}",
    ]
}

fn argv() -> impl Strategy<Value = Vec<String>> {
    (
        0..COMMANDS.len(),
        prop::collection::vec(value(), 3),
        prop::collection::vec((any::<prop::sample::Index>(), value()), 0..5),
    )
        .prop_map(|(c, needed, pairs)| {
            let (words, required, optional) = COMMANDS[c];
            let mut args: Vec<String> = words.iter().map(|w| w.to_string()).collect();
            if words[0] == "fit" {
                let name = match words[1] {
                    "trajectory" => "video.csv",
                    "beats" => "beats.csv",
                    _ => "rundown.csv",
                };
                args.push(examples().join(name).to_str().unwrap().to_string());
            }
            for (flag, v) in required.iter().zip(needed) {
                args.push(flag.to_string());
                args.push(v);
            }
            for (index, v) in pairs {
                let flag = index.get(optional);
                args.push(flag.to_string());
                // Flags without a value take none.
                if *flag != "--csv" {
                    args.push(v);
                }
            }
            args
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(
        std::env::var("PROPTEST_CASES").ok().and_then(|c| c.parse().ok()).unwrap_or(96)
    ))]
    #[test]
    fn arbitrary_arguments_never_panic(args in argv()) {
        let dir = tempfile::tempdir().unwrap();
        let ran = run(dir.path(), &args);
        if let Some(b) = breach(&args, &ran) {
            return Err(TestCaseError::fail(b));
        }
        // A refusal leaves nothing behind.
        if ran.code == Some(2) {
            prop_assert!(files_in(dir.path()).is_empty(), "left files: {:?}", args);
        }
    }
}
