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

// ---- A report's folder: only the files it wrote are removed ------------------

/// `report --output DIR` into `dir`: its one line of refusal (status 2,
/// nothing on standard output), or `None` when it wrote the report.
fn report_into(dir: &Path, extra: &[&str]) -> Option<String> {
    let out = pendulum()
        .args(["report", "--output", dir.to_str().unwrap()])
        .args(extra)
        .output()
        .unwrap();
    if out.status.success() {
        return None;
    }
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let line = String::from_utf8(out.stderr).unwrap();
    assert_eq!(line.lines().count(), 1, "{line}");
    assert!(line.starts_with("error: --output: "), "{line}");
    Some(line)
}

/// The sorted names in `dir`.
fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// Puts a marker into a folder.
type MakeMarker<'a> = dyn Fn(&Path) + 'a;

/// A marker that is empty, a symbolic link, written by something else,
/// or naming a file outside the folder makes no folder the report's: the
/// user's files beside it stay (an empty marker, or a link named like
/// it, was enough for the folder to be replaced whole).
#[test]
fn a_marker_the_report_did_not_write_deletes_nothing() {
    let root = tempfile::tempdir().unwrap();
    let outside = root.path().join("outside.txt");
    std::fs::write(&outside, "the user's").unwrap();
    let cases: [(&str, &MakeMarker<'_>, &str); 5] = [
        (
            "empty",
            &|d| std::fs::write(d.join(".pendulum-report"), "").unwrap(),
            "is empty",
        ),
        (
            "link",
            &|d| std::os::unix::fs::symlink(&outside, d.join(".pendulum-report")).unwrap(),
            "symbolic link",
        ),
        (
            "foreign",
            &|d| std::fs::write(d.join(".pendulum-report"), "index.html\nnotes.txt\n").unwrap(),
            "not the list of files a report writes",
        ),
        (
            "outside",
            &|d| {
                std::fs::write(
                    d.join(".pendulum-report"),
                    "pendulum report: the files below were written here by `pendulum report`; a \
                     later report removes them and nothing else.\n../outside.txt\nnotes.txt\n",
                )
                .unwrap()
            },
            "names '../outside.txt'",
        ),
        (
            "a folder",
            &|d| std::fs::create_dir(d.join(".pendulum-report")).unwrap(),
            "not the list of files a report writes",
        ),
    ];
    for (name, make_marker, says) in cases {
        let dir = root.path().join(name);
        std::fs::create_dir(&dir).unwrap();
        make_marker(&dir);
        std::fs::write(dir.join("notes.txt"), "the user's").unwrap();
        let before = names(&dir);
        let line = report_into(&dir, &[]).unwrap_or_else(|| panic!("{name}: written"));
        assert!(line.contains("not an earlier report"), "{name}: {line}");
        assert!(line.contains(says), "{name}: {line}");
        assert_eq!(names(&dir), before, "{name}");
        assert_eq!(
            std::fs::read_to_string(dir.join("notes.txt")).unwrap(),
            "the user's"
        );
    }
    assert_eq!(std::fs::read_to_string(&outside).unwrap(), "the user's");
}

/// An earlier report is replaced file for file: the new report's files,
/// the old one's that it does not write removed (a log's figures), its
/// marker listing what it wrote; a file of the user's put in beside the
/// report is named in the refusal and kept, the report with it.
#[test]
fn an_earlier_report_is_replaced_only_of_its_own_files() {
    let root = tempfile::tempdir().unwrap();
    let dir = root.path().join("report");
    let log = example("clock-log.csv");
    assert_eq!(report_into(&dir, &["--log", log.to_str().unwrap()]), None);
    let with_log = names(&dir);
    assert!(
        with_log.contains(&"log-rate.svg".to_string()),
        "{with_log:?}"
    );
    std::fs::write(dir.join("notes.txt"), "the user's").unwrap();
    let line = report_into(&dir, &[]).expect("refused");
    assert!(
        line.contains("holds a file the earlier report there did not write (notes.txt)"),
        "{line}"
    );
    let mut kept = with_log.clone();
    kept.push("notes.txt".to_string());
    kept.sort();
    assert_eq!(names(&dir), kept);
    std::fs::remove_file(dir.join("notes.txt")).unwrap();
    assert_eq!(report_into(&dir, &[]), None);
    assert_eq!(
        names(&dir),
        [
            ".pendulum-report",
            "decay.svg",
            "index.html",
            "period.svg",
            "rundown.svg"
        ]
    );
    let marker = std::fs::read_to_string(dir.join(".pendulum-report")).unwrap();
    let mut listed: Vec<&str> = marker.lines().skip(1).collect();
    listed.sort_unstable();
    assert_eq!(
        listed,
        ["decay.svg", "index.html", "period.svg", "rundown.svg"]
    );
    // A listed name that is now a folder is not the report's file.
    std::fs::remove_file(dir.join("decay.svg")).unwrap();
    std::fs::create_dir(dir.join("decay.svg")).unwrap();
    std::fs::write(dir.join("decay.svg").join("inside.txt"), "the user's").unwrap();
    let line = report_into(&dir, &[]).expect("refused");
    assert!(line.contains("'decay.svg', which is not a file"), "{line}");
    assert!(dir.join("decay.svg").join("inside.txt").is_file());
}

/// A folder of a report from before the marker listed its files (its
/// marker a fixed sentence) is replaced when it holds only the files
/// those reports wrote, and refused when it holds anything else.
#[test]
fn a_report_from_before_the_list_is_replaced_only_when_it_holds_its_own_files() {
    let root = tempfile::tempdir().unwrap();
    let legacy = "This folder was written by `pendulum report`; a later report may replace it.\n";
    let dir = root.path().join("old");
    std::fs::create_dir(&dir).unwrap();
    std::fs::write(dir.join(".pendulum-report"), legacy).unwrap();
    for f in ["index.html", "period.svg", "log-folds.svg"] {
        std::fs::write(dir.join(f), "old").unwrap();
    }
    std::fs::write(dir.join("thesis.tex"), "the user's").unwrap();
    let line = report_into(&dir, &[]).expect("refused");
    assert!(line.contains("(thesis.tex)"), "{line}");
    assert!(dir.join("thesis.tex").is_file() && dir.join("log-folds.svg").is_file());
    std::fs::remove_file(dir.join("thesis.tex")).unwrap();
    assert_eq!(report_into(&dir, &[]), None);
    assert!(!dir.join("log-folds.svg").exists());
    assert_ne!(
        std::fs::read_to_string(dir.join("index.html")).unwrap(),
        "old"
    );
}

// ---- A raw stream's layout ----------------------------------------------------

/// `--channels 1000000000` aborted on a block of 9.6 TB; every count past
/// a WAV stream's 65,535 is refused in one line, the last one allowed is
/// read.
#[test]
fn listen_refuses_more_channels_than_a_stream_holds() {
    let zeros = vec![0_u8; 1 << 16];
    for channels in ["1000000000", "65536", "0"] {
        let line = super::util::refuses_given(
            &[
                "listen",
                "-",
                "--raw",
                "s16le",
                "--sample-rate",
                "48000",
                "--channels",
                channels,
            ],
            &zeros,
            "--channels",
        );
        assert!(
            line.contains(&format!(
                "must be 1 to 65535 (the most a WAV stream can hold), got {channels}"
            )),
            "{line}"
        );
    }
    // The most allowed is read (and found silent), not refused.
    let line = super::util::refuses_given(
        &[
            "listen",
            "-",
            "--raw",
            "s16le",
            "--sample-rate",
            "4294967295",
            "--channels",
            "65535",
        ],
        &zeros,
        "-: no regular ticking",
    );
    assert!(!line.contains("--channels"), "{line}");
}

/// A WAV stream whose header claims 65,535 channels at 4.29 GHz aborted
/// on a block of 56 TB; it is read in blocks of at most a mebibyte.
#[test]
fn a_wav_stream_of_the_most_channels_at_the_highest_rate_is_read_in_bounded_blocks() {
    let channels: u16 = u16::MAX;
    let rate = u32::MAX;
    let mut wav = Vec::new();
    wav.extend_from_slice(b"RIFF");
    wav.extend_from_slice(&u32::MAX.to_le_bytes());
    wav.extend_from_slice(b"WAVEfmt ");
    wav.extend_from_slice(&16_u32.to_le_bytes());
    wav.extend_from_slice(&1_u16.to_le_bytes());
    wav.extend_from_slice(&channels.to_le_bytes());
    wav.extend_from_slice(&rate.to_le_bytes());
    wav.extend_from_slice(&0_u32.to_le_bytes());
    wav.extend_from_slice(&channels.wrapping_mul(2).to_le_bytes());
    wav.extend_from_slice(&16_u16.to_le_bytes());
    wav.extend_from_slice(b"data");
    wav.extend_from_slice(&u32::MAX.to_le_bytes());
    wav.resize(wav.len() + 2_000_000, 0);
    super::util::refuses_given(&["listen", "-"], &wav, "-: no regular ticking");
}

// ---- A rate that stops the clock ----------------------------------------------

/// `clock --drive-file` with a `rate_change_s_per_day` column (Python's
/// `rate_schedule`): a change of rate from outside moves the time error
/// by its integral, and a rate of -86,400 s/day or below (a clock that
/// has stopped; a run towards it hung in Python) is refused by its line
/// and column; close to it the run ends, warned.
#[test]
fn a_drive_file_rate_change_of_a_stopped_clock_is_refused_by_line() {
    let dir = tempfile::tempdir().unwrap();
    let run = |last: &str| {
        let path = dir.path().join("rate.csv");
        std::fs::write(
            &path,
            format!("time_s,rate_change_s_per_day\n0,0\n86400,{last}\n"),
        )
        .unwrap();
        let args = [
            "clock",
            "--length",
            "0.99362m",
            "--drive",
            "20uJ",
            "--duration",
            "2day",
            "--every",
            "1h",
            "--drive-file",
            path.to_str().unwrap(),
        ];
        (path.clone(), args.map(String::from))
    };
    for (last, says) in [
        (
            "-86400",
            "above -86400 s/day: a clock that loses a day a day has stopped; got -86400 s/day",
        ),
        ("-86401", "has stopped; got -86401 s/day"),
        ("-1e300", "has stopped; got -1e300 s/day"),
        ("86400", "below 86400 s/day"),
    ] {
        let (path, args) = run(last);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let line = super::util::refuses(&args, "--drive-file");
        assert!(
            line.contains(&format!(
                "{}: line 3, column rate_change_s_per_day: must be a rate change within a day per day, ",
                path.display()
            )) && line.contains(says),
            "{line}"
        );
    }
    // Near it: the run ends, its last beat long past the duration, said.
    let (_, args) = run("-86399.999999");
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let v = json(&args);
    let warning = v["long_run"]["warnings"][0]["message"].as_str().unwrap();
    assert!(warning.contains("days after the 2 days asked"), "{warning}");
    assert!(warning.contains("(a clock all but stopped)"), "{warning}");
    // A constant 2 s/day for two days puts the clock 4 s further ahead
    // than without: the integral of the rate, in closed form.
    let (path, args) = run("2");
    std::fs::write(&path, "time_s,rate_change_s_per_day\n0,2\n").unwrap();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let with = json(&args);
    let without = json(&args[..args.len() - 2]);
    let (a, b) = (&with["long_run"], &without["long_run"]);
    let elapsed = a["duration_s"].as_f64().unwrap();
    let gained = a["time_error_s"].as_f64().unwrap() - b["time_error_s"].as_f64().unwrap();
    assert!((gained - 2.0 * elapsed / 86_400.0).abs() < 1e-6, "{gained}");
    assert!(a.get("warnings").is_none(), "{a}");
}

/// Every flag that takes a clock's rate refuses -86,400 s/day and below
/// in one line, and answers close to it without a non-finite number.
#[test]
fn rate_flags_at_and_near_a_stopped_clock() {
    for rate in ["-86400", "-86401", "-1e300", "-86400s/day", "-1000000ppm"] {
        let flag = format!("--rate={rate}");
        super::util::refuses(&["regulate", "--length", "0.994m", &flag], "--rate");
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("t.wav");
        super::util::refuses(
            &[
                "synth",
                "ticks",
                out.to_str().unwrap(),
                &flag,
                "--duration",
                "10s",
            ],
            "--rate",
        );
    }
    let line = super::util::refuses(
        &["regulate", "--length", "0.994m", "--rate=-86399.99"],
        "--rate",
    );
    assert!(line.contains("-100%"), "{line}");
}

// ---- The tide's work ------------------------------------------------------------

/// Rows centuries apart cost their own knots and months, not every knot
/// between (21 rows over two centuries took 48 s); a row every 40 days
/// over them (1,827 rows, 2,437 months of K1 means, 30 s of computing)
/// needs --force, as a long table does.
#[test]
fn a_tide_over_centuries_is_judged_by_its_months() {
    let args = |every| {
        [
            "tide",
            "--latitude",
            "48.33",
            "--longitude",
            "8.33",
            "--from",
            "1900-01-02",
            "--to",
            "2099-12-30",
            "--every",
            every,
        ]
    };
    let v = json(&args("3650day"));
    assert_eq!(v["rows"].as_array().unwrap().len(), 21);
    let line = super::util::refuses(&args("40day"), "--every");
    assert!(line.contains("1827 times over 73040 days"), "{line}");
    assert!(line.contains("force it"), "{line}");
}

// ---- A header run together with its first row --------------------------------

/// A header whose line end was lost is refused by its line, naming the
/// header and the row it holds: under --columns the line was skipped and
/// its row dropped without a word (63 phase points of 64), and without it
/// the refusal spoke of a header of three columns. The same table with
/// its line end, and headers whose names end in digits, are read whole.
#[test]
fn a_header_run_together_with_its_first_row_is_refused_by_line() {
    let dir = tempfile::tempdir().unwrap();
    let offsets: Vec<String> = (0..64)
        .map(|i| format!("{:.6e}", 1e-6 * (f64::from(i) * 0.9).sin()))
        .collect();
    let column = |head: &str, line_end: &str| format!("{head}{line_end}{}\n", offsets.join("\n"));
    let table = |head: &str, sep: &str, line_end: &str| {
        let rows: Vec<String> = offsets
            .iter()
            .enumerate()
            .map(|(i, v)| format!("{i}.0{sep}{v}"))
            .collect();
        format!("{head}{line_end}{}\n", rows.join("\n"))
    };
    let write = |name: &str, text: String| {
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        path.display().to_string()
    };
    let points = |path: &str, extra: &[&str]| {
        let mut args = vec!["stability", path, "--tau0", "1s"];
        args.extend(extra);
        json(&args)["phase_points"].as_u64().unwrap()
    };
    let whole = write("column.csv", column("offset_s", "\n"));
    assert_eq!(points(&whole, &[]), 64);
    assert_eq!(points(&whole, &["--columns", "offset_s"]), 64);
    assert_eq!(
        points(&write("t.csv", table("t_1,offset_s", ",", "\n")), &[]),
        64
    );
    let named = write("named.csv", column("clock2", "\n"));
    assert_eq!(points(&named, &["--columns", "offset_s"]), 64);
    let first = &offsets[0];
    let glued = write("glued.csv", column("offset_s", ""));
    for extra in [&[][..], &["--columns", "offset_s"][..]] {
        let mut args = vec!["stability", glued.as_str(), "--tau0", "1s"];
        args.extend(extra);
        let line = super::util::refuses(&args, "glued.csv");
        assert!(
            line.ends_with(&format!(
                "line 1 holds the header and the first row of numbers run together \
                 ('offset_s' then '{first}'): put the row on a line of its own\n"
            )),
            "{line}"
        );
    }
    for (name, text, shown) in [
        ("comma.csv", table("time_s,offset_s", ",", ""), ","),
        ("spaces.txt", table("time_s offset_s", " ", " "), " "),
        ("semicolon.csv", table("time_s;offset_s", ";", ";"), ";"),
    ] {
        let path = write(name, text);
        let line = super::util::refuses(&["stability", &path], name);
        assert!(
            line.contains(&format!(
                "line 1 holds the header and the first row of numbers run together \
                 ('time_s{shown}offset_s' then '0.0{shown}{first}')"
            )),
            "{line}"
        );
    }
}

// ---- One unit table for a quantity -------------------------------------------

/// A drive file's pressure column takes the units `--pressure` takes, from
/// the same table (bar, atm and Torr were not known to the reader: a
/// `pressure_bar` column was "no weather column"): 1.01325 to 0.98325 bar
/// runs the clock as 1013.25 to 983.25 hPa, and 760 to 737.5 Torr as
/// those pressures in hPa (× 1.33322387415). `x_bar` stays a name.
#[test]
fn a_pressure_column_takes_the_flags_units() {
    let dir = tempfile::tempdir().unwrap();
    let design = example("seconds-steel-brass.toml");
    let run = |header: &str, a: f64, b: f64| {
        let path = dir
            .path()
            .join(format!("{}.csv", header.replace([' ', '(', ')'], "")));
        std::fs::write(&path, format!("time_s,{header}\n0,{a}\n86400,{b}\n")).unwrap();
        let path = path.display().to_string();
        let v = json(&[
            "clock",
            "--design",
            design.to_str().unwrap(),
            "--drive",
            "2e-5J",
            "--duration",
            "2day",
            "--every",
            "1h",
            "--drive-file",
            &path,
        ]);
        v["long_run"]["final_rate_s_per_day"].as_f64().unwrap()
    };
    let hpa = run("pressure_hpa", 1013.25, 983.25);
    assert!(hpa > 0.25, "{hpa}");
    assert_eq!(run("pressure_bar", 1.01325, 0.98325), hpa);
    let torr = 133.322_387_415 / 100.0;
    let in_hpa = run("pressure_hpa", 760.0 * torr, 737.5 * torr);
    for header in ["pressure_torr", "pressure (Torr)", "Pressure [TORR]"] {
        let r = run(header, 760.0, 737.5);
        assert!(
            (r - in_hpa).abs() < 1e-9 * in_hpa.abs(),
            "{header}: {r} against {in_hpa}"
        );
    }
    let path = dir.path().join("x.csv");
    std::fs::write(&path, "time_s,x_bar\n0,1\n86400,2\n").unwrap();
    super::util::refuses(
        &[
            "clock",
            "--design",
            design.to_str().unwrap(),
            "--drive",
            "2e-5J",
            "--duration",
            "2day",
            "--drive-file",
            path.to_str().unwrap(),
        ],
        "found: time_s, x_bar",
    );
}
