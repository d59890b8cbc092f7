//! A full disk, for real: each kind of output (a streamed CSV, a WAV, an
//! SVG and a PNG figure, a design file, a report folder, a table of
//! ticks or turning points) is written into a small tmpfs that it cannot
//! fit. The command must refuse in one line with exit 2, and the tmpfs
//! must hold afterwards exactly what it held before: no half-written file,
//! no temporary.
//!
//! The tmpfs is mounted in a private mount namespace (`unshare --mount`,
//! as root; `unshare --user --map-root-user --mount` otherwise), so the
//! test needs no mount of the machine's and leaves none behind. If
//! neither can mount, the test fails and says so: it never skips.

use std::path::{Path, PathBuf};
use std::process::Command;

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// Runs `args` in a fresh tmpfs of `size_kib` KiB holding `inputs` and a
/// filler that leaves about `free_kib` KiB free; returns (exit status,
/// standard error, the tmpfs's listing before, and after).
fn run_full(args: &[&str], inputs: &[&Path], free_kib: u64) -> (i32, String, String, String) {
    let work = tempfile::tempdir().unwrap();
    let mount = work.path().join("disk");
    std::fs::create_dir(&mount).unwrap();
    let staged = work.path().join("inputs");
    std::fs::create_dir(&staged).unwrap();
    for input in inputs {
        std::fs::copy(input, staged.join(input.file_name().unwrap())).unwrap();
    }
    let binary = env!("CARGO_BIN_EXE_pendulum");
    let quoted: Vec<String> = args
        .iter()
        .map(|a| format!("'{}'", a.replace('\'', "'\\''")))
        .collect();
    // Inputs take what they take; a filler takes the whole rest, then
    // gives back `free_kib`.
    let script = format!(
        "set -e
        mount -t tmpfs -o size=4m tmpfs '{m}'
        cp '{s}'/* '{m}'/ 2>/dev/null || true
        cd '{m}'
        dd if=/dev/zero of=.filler bs=4k status=none 2>/dev/null || true
        [ {free_kib} -gt 0 ] && truncate -s -{free_kib}K .filler || true
        ls -la --time-style=+ . | sort > '{w}/before'
        set +e
        '{binary}' {args} > /dev/null 2> '{w}/stderr'
        echo $? > '{w}/status'
        ls -la --time-style=+ . | sort > '{w}/after'",
        m = mount.display(),
        s = staged.display(),
        w = work.path().display(),
        args = quoted.join(" "),
    );
    let root = unsafe_is_root();
    let mut command = Command::new("unshare");
    if !root {
        command.args(["--user", "--map-root-user"]);
    }
    let out = command
        .args(["--mount", "sh", "-c", &script])
        .output()
        .expect("unshare runs");
    assert!(
        out.status.success(),
        "could not mount a tmpfs for the full-disk test (unshare/mount failed): {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let read = |name: &str| std::fs::read_to_string(work.path().join(name)).unwrap_or_default();
    (
        read("status").trim().parse().unwrap_or(-1),
        read("stderr"),
        read("before"),
        read("after"),
    )
}

/// Whether this process runs as root (uid 0), from /proc.
fn unsafe_is_root() -> bool {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("Uid:"))
                .map(|l| l.split_whitespace().nth(1) == Some("0"))
        })
        .unwrap_or(false)
}

/// The output does not fit: one error line that says so (`says`: "No
/// space left" when the disk filled during the write, "free" when the
/// size estimate refused it first), exit 2, the disk as before.
fn refused_and_nothing_left(args: &[&str], inputs: &[&Path], free_kib: u64, says: &str) {
    let (status, stderr, before, after) = run_full(args, inputs, free_kib);
    assert_eq!(status, 2, "{args:?}: exit {status}, {stderr}");
    assert!(
        stderr.contains(says),
        "{args:?}: '{says}' expected in {stderr}"
    );
    assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
    assert!(stderr.starts_with("error: "), "{args:?}: {stderr}");
    assert_eq!(before, after, "{args:?} left the disk changed: {stderr}");
}

#[test]
fn a_full_disk_leaves_nothing_behind() {
    let rundown = examples().join("rundown.csv");
    let design = examples().join("seconds-steel-brass.toml");
    let tracker = examples().join("tracker.txt");
    // A streamed CSV refused by its size estimate before any byte.
    refused_and_nothing_left(
        &[
            "simulate",
            "--length",
            "1",
            "--amplitude",
            "3",
            "--q",
            "1e6",
            "--duration",
            "1day",
            "--method",
            "symplectic",
            "--swings",
            "s.csv",
        ],
        &[],
        16,
        "free",
    );
    // A streamed CSV whose estimate fits the free space, and a figure
    // that then does not: the disk fills during the second output, after
    // the first was written whole.
    refused_and_nothing_left(
        &[
            "damped",
            "--length",
            "1",
            "--amplitude",
            "3",
            "--q",
            "100",
            "--duration",
            "420s",
            "--trajectory",
            "t.csv",
            "--plot",
            "p.png",
        ],
        &[],
        1000,
        "No space left",
    );
    // A WAV, and its truth file: refused by the size estimate.
    refused_and_nothing_left(
        &[
            "synth",
            "ticks",
            "o.wav",
            "--bph",
            "3600",
            "--duration",
            "2min",
            "--truth",
            "t.csv",
        ],
        &[],
        64,
        "free",
    );
    // Figures: SVG and PNG.
    refused_and_nothing_left(
        &[
            "period",
            "--length",
            "1",
            "--amplitude",
            "1..30",
            "--plot",
            "p.png",
        ],
        &[],
        8,
        "No space left",
    );
    refused_and_nothing_left(
        &["fit", "decay", "rundown.csv", "--plot", "p.svg"],
        &[&rundown],
        4,
        "No space left",
    );
    // A design file.
    refused_and_nothing_left(
        &[
            "compensate",
            "--design",
            "seconds-steel-brass.toml",
            "--compensator",
            "mercury",
            "--write",
            "jar.toml",
        ],
        &[&design],
        0,
        "No space left",
    );
    // A report folder.
    refused_and_nothing_left(&["report", "--output", "rep"], &[], 16, "No space left");
    // A table from a fit of a large file.
    refused_and_nothing_left(
        &[
            "fit",
            "decay",
            "tracker.txt",
            "--turning-points",
            "turns.csv",
            "--plot",
            "d.png",
        ],
        &[&tracker],
        8,
        "No space left",
    );
}

#[test]
fn the_full_disk_test_can_fail() {
    // With room enough the same command succeeds and writes its file: the
    // tmpfs is really where the command writes.
    let (status, stderr, before, after) = run_full(
        &[
            "period",
            "--length",
            "1",
            "--amplitude",
            "1..30",
            "--plot",
            "p.svg",
        ],
        &[],
        1024,
    );
    assert_eq!(status, 0, "{stderr}");
    assert_ne!(before, after);
    assert!(after.contains("p.svg"), "{after}");
}
