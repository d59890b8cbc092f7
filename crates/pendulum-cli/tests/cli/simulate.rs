//! `pendulum simulate`.

use crate::util::{f, files_in, interrupt, json, pendulum, refuses};
use std::path::Path;
use std::time::{Duration, Instant};

fn simulate<'a>(extra: &[&'a str]) -> Vec<&'a str> {
    let mut v = vec!["simulate", "--length", "0.99362m", "--amplitude", "3deg"];
    v.extend_from_slice(extra);
    v
}

fn read_csv(path: &Path) -> (Vec<String>, Vec<csv::StringRecord>) {
    let mut reader = csv::Reader::from_path(path).unwrap();
    let header = reader.headers().unwrap().iter().map(String::from).collect();
    let rows = reader.records().map(|r| r.unwrap()).collect();
    (header, rows)
}

#[test]
fn json_has_the_documented_keys() {
    let v = json(&simulate(&["--duration", "10s", "--q", "1000"]));
    for key in [
        "final_time_s",
        "final_angle_rad",
        "final_angular_velocity_rad_s",
        "final_amplitude_rad",
    ] {
        assert!(v[key].is_number(), "{key} in {v}");
    }
    for key in ["swings", "steps", "function_evaluations"] {
        assert!(v[key].is_u64(), "{key} in {v}");
    }
    assert_eq!(v["method"], "dop853");
    assert_eq!(v["stopped"], "duration");
    assert_eq!(f(&v, "final_time_s"), 10.0);
    // At 3° each half swing takes 1.00017 s, so the tenth turning point
    // comes 1.7 ms after the tenth second: nine within 10 s.
    assert_eq!(v["swings"], 9);
}

#[test]
fn methods_agree_without_damping() {
    let args = |m| simulate(&["--duration", "30s", "--method", m, "--tolerance", "1e-12"]);
    let exact = json(&args("exact"));
    for method in ["dop853", "vern9", "symplectic"] {
        let v = json(&args(method));
        assert_eq!(v["swings"], exact["swings"], "{method}");
        let d = (f(&v, "final_angle_rad") - f(&exact, "final_angle_rad")).abs();
        assert!(d < 1e-9, "{method}: {d:e}");
    }
}

#[test]
fn swings_file_has_one_row_per_turning_point() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("swings.csv");
    let v = json(&simulate(&[
        "--duration",
        "100s",
        "--q",
        "1e4",
        "--swings",
        path.to_str().unwrap(),
    ]));
    let (header, rows) = read_csv(&path);
    assert_eq!(
        header,
        [
            "index",
            "time_s",
            "angle_rad",
            "half_period_s",
            "rate_s_per_day"
        ]
    );
    assert_eq!(rows.len() as u64, v["swings"].as_u64().unwrap() + 1);
    assert_eq!(&rows[0][3], "");
    assert_eq!(&rows[0][4], "");
    // At 3° the beat is slower than the small-angle beat: the clock loses
    // about 14.8 s/day, a rate of -14.8 (positive rates gain, as everywhere).
    let rate: f64 = rows[1][4].parse().unwrap();
    assert!((rate + 14.8).abs() < 0.1, "{rate}");
    let half: f64 = rows[5][3].parse().unwrap();
    let t: Vec<f64> = (4..=5).map(|i| rows[i][1].parse().unwrap()).collect();
    assert!((half - (t[1] - t[0])).abs() < 1e-12);
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
}

#[test]
fn friction_stops_the_run() {
    let v = json(&simulate(&[
        "--duration",
        "1000s",
        "--friction-angle",
        "0.1deg",
    ]));
    assert_eq!(v["stopped"], "friction");
    assert!(f(&v, "final_time_s") < 1000.0);
    assert_eq!(f(&v, "final_angular_velocity_rad_s"), 0.0);
}

#[test]
fn trajectory_samples_every_interval() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("run.csv");
    json(&simulate(&[
        "--duration",
        "5s",
        "--zeta",
        "0.01",
        "--trajectory",
        path.to_str().unwrap(),
        "--sample-interval",
        "0.25s",
    ]));
    let (header, rows) = read_csv(&path);
    assert_eq!(header, ["time_s", "angle_rad", "angular_velocity_rad_s"]);
    assert_eq!(rows.len(), 21);
    assert_eq!(rows[20][0].parse::<f64>().unwrap(), 5.0);
}

#[test]
fn ctrl_c_leaves_complete_files() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("swings.csv");
    let child = std::process::Command::new(env!("CARGO_BIN_EXE_pendulum"))
        .args(simulate(&[
            "--duration",
            "1e8s",
            "--q",
            "1e6",
            "--force",
            "--quiet",
            "--json",
            "--swings",
            path.to_str().unwrap(),
        ]))
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // Wait until the run is under way (its partial file exists), then interrupt.
    let started = Instant::now();
    while std::fs::read_dir(dir.path()).unwrap().count() == 0 {
        assert!(
            started.elapsed() < Duration::from_secs(60),
            "the run never started"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    std::thread::sleep(Duration::from_millis(200));
    interrupt(&child);
    let out = child.wait_with_output().unwrap();
    // Interrupted: the files are complete, the summary is printed, and the
    // status is 130 as for any Unix tool stopped by Ctrl-C.
    assert_eq!(out.status.code(), Some(130), "{:?}", out.status);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["stopped"], "interrupted");
    let (_, rows) = read_csv(&path);
    assert_eq!(rows.len() as u64, v["swings"].as_u64().unwrap() + 1);
    let names = files_in(dir.path());
    assert_eq!(names.len(), 1, "{names:?}");
}

#[test]
fn bad_input_is_refused_without_a_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("s.csv");
    let out = out.to_str().unwrap();
    refuses(
        &simulate(&[
            "--duration",
            "10s",
            "--tolerance",
            "-1e-10",
            "--swings",
            out,
        ]),
        "--tolerance",
    );
    refuses(
        &simulate(&["--duration", "10s", "--tolerance", "0"]),
        "--tolerance",
    );
    refuses(
        &simulate(&["--duration", "2e9s", "--swings", out]),
        "--force",
    );
    refuses(&simulate(&["--duration", "-1s"]), "--duration");
    refuses(
        &simulate(&["--duration", "10s", "--method", "exact", "--q", "100"]),
        "--method",
    );
    refuses(
        &simulate(&[
            "--duration",
            "10s",
            "--method",
            "exact",
            "--friction-angle",
            "0.1deg",
        ]),
        "--method",
    );
    refuses(
        &simulate(&[
            "--duration",
            "10s",
            "--trajectory",
            out,
            "--sample-interval",
            "0s",
        ]),
        "--sample-interval",
    );
    refuses(
        &simulate(&[
            "--duration",
            "1e7s",
            "--trajectory",
            out,
            "--sample-interval",
            "1ms",
        ]),
        "--force",
    );
    refuses(
        &simulate(&["--duration", "10s", "--quadratic-drag", "-1"]),
        "--quadratic-drag",
    );
    refuses(&simulate(&["--duration", "10s", "--method", "rk4"]), "rk4");
    refuses(
        &simulate(&["--duration", "10s", "--zeta", "0.1", "--q", "3"]),
        "--q",
    );
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
    pendulum()
        .args(simulate(&["--duration", "1s"]))
        .assert()
        .success();
}
