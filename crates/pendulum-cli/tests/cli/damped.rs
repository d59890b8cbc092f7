//! `pendulum damped`.

use crate::util::{f, files_in, json, pendulum, refuses};
use std::path::Path;

fn damped<'a>(extra: &[&'a str]) -> Vec<&'a str> {
    let mut v = vec!["damped", "--length", "0.99362m", "--amplitude", "3deg"];
    v.extend_from_slice(extra);
    v
}

/// No file and no temporary file left in `dir`.
fn folder_is_empty(dir: &Path) {
    let left = files_in(dir);
    assert!(left.is_empty(), "left behind: {left:?}");
}

#[test]
fn json_has_the_documented_keys() {
    let v = json(&damped(&["--q", "1e4", "--mass", "1kg"]));
    for key in [
        "zeta",
        "q_factor",
        "log_decrement",
        "natural_angular_frequency_rad_s",
        "damped_angular_frequency_rad_s",
        "damped_period_s",
        "phase_rad",
        "amplitude_loss_per_period_rad",
        "amplitude_loss_per_period_approx_rad",
        "amplitude_half_life_s",
        "energy_j",
        "energy_loss_per_period_j",
        "power_w",
        "impulse_per_beat_kg_m2_s",
    ] {
        assert!(v[key].is_number(), "{key} in {v}");
    }
    assert_eq!(v["regime"], "underdamped");
    assert_eq!(f(&v, "zeta"), 5e-5);
    let extrema = v["extrema"].as_array().unwrap();
    assert_eq!(extrema.len(), 11);
    assert_eq!(extrema[0]["index"], 0);
    assert_eq!(extrema[0]["time_s"], 0.0);
    // Every half period, alternating in sign, shrinking by e^{-ζπ/sqrt(1-ζ²)}.
    let half = f(&v, "damped_period_s") / 2.0;
    let e3 = &extrema[3];
    assert!((e3["time_s"].as_f64().unwrap() - 3.0 * half).abs() < 1e-12);
    assert!(e3["angle_rad"].as_f64().unwrap() < 0.0);
}

#[test]
fn every_damping_form_gives_the_same_zeta() {
    let z = f(&json(&damped(&["--zeta", "0.01"])), "zeta");
    let by_q = f(&json(&damped(&["--q", "50"])), "zeta");
    let v = json(&damped(&["--zeta", "0.01"]));
    let delta = format!("{}", f(&v, "log_decrement"));
    let tau = format!("{}s", f(&v, "decay_time_s"));
    let by_delta = f(&json(&damped(&["--log-decrement", &delta])), "zeta");
    let by_tau = f(&json(&damped(&["--decay-time", &tau])), "zeta");
    for other in [by_q, by_delta, by_tau] {
        assert!(
            (other - z).abs() <= 4.0 * f64::EPSILON * z,
            "{other} vs {z}"
        );
    }
    // c = 2 m ζ sqrt(g l) with m = 2 kg.
    let c = 2.0 * 2.0 * 0.01 * (9.80665_f64 * 0.99362).sqrt();
    let by_c = f(
        &json(&damped(&[
            "--damping-coefficient",
            &c.to_string(),
            "--mass",
            "2kg",
        ])),
        "zeta",
    );
    assert!((by_c - z).abs() <= 4.0 * f64::EPSILON * z);
}

#[test]
fn regimes_without_oscillation_have_nulls() {
    for (zeta, regime) in [("1", "critically damped"), ("3", "overdamped")] {
        let v = json(&damped(&["--zeta", zeta]));
        assert_eq!(v["regime"], regime);
        assert!(v["damped_period_s"].is_null());
        assert!(v["log_decrement"].is_null());
        assert!(v["phase_rad"].is_null());
        assert_eq!(v["extrema"].as_array().unwrap().len(), 1);
    }
}

#[test]
fn friction_ends_the_list_at_the_stop() {
    // No viscous damping: 2r lost per half swing, 3° / (2 × 0.25°) = 6 half swings.
    let v = json(&damped(&[
        "--zeta",
        "0",
        "--friction-angle",
        "0.25deg",
        "--extrema",
        "50",
    ]));
    let extrema = v["extrema"].as_array().unwrap();
    assert_eq!(extrema.len(), 7);
    let stop = &v["stop"];
    assert_eq!(stop["angle_rad"], extrema[6]["angle_rad"]);
    assert!(stop["angle_rad"].as_f64().unwrap().abs() <= 0.25_f64.to_radians());
}

#[test]
fn trajectory_is_written_whole() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("run.csv");
    let path_text = path.to_str().unwrap();
    let v = json(&damped(&[
        "--q",
        "100",
        "--trajectory",
        path_text,
        "--duration",
        "10s",
        "--sample-interval",
        "0.1s",
    ]));
    assert_eq!(v["trajectory"]["samples"], 101);
    let mut reader = csv::Reader::from_path(&path).unwrap();
    assert_eq!(
        reader.headers().unwrap(),
        vec!["time_s", "angle_rad", "angular_velocity_rad_s"]
    );
    let rows: Vec<csv::StringRecord> = reader.records().map(|r| r.unwrap()).collect();
    assert_eq!(rows.len(), 101);
    assert_eq!(rows[0][1].parse::<f64>().unwrap(), 3.0_f64.to_radians());
    assert_eq!(rows[100][0].parse::<f64>().unwrap(), 10.0);
    let names = files_in(dir.path());
    assert_eq!(names.len(), 1, "only the CSV is left: {names:?}");
}

#[test]
fn bad_input_is_refused_without_a_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("run.csv");
    let out = path.to_str().unwrap();
    refuses(&damped(&["--zeta", "-0.1"]), "--zeta");
    refuses(&damped(&["--q", "0"]), "--q");
    refuses(&damped(&["--q", "-5"]), "--q");
    refuses(
        &damped(&["--zeta", "0.1", "--friction-angle", "-0.1deg"]),
        "--friction-angle",
    );
    refuses(
        &damped(&["--zeta", "0.1", "--friction-angle", "3deg"]),
        "--friction-angle",
    );
    refuses(&damped(&["--zeta", "0.1", "--q", "10"]), "--q");
    refuses(&damped(&["--damping-coefficient", "0.1"]), "--mass");
    refuses(&damped(&[]), "--zeta");
    refuses(&damped(&["--zeta", "0.1", "--mass", "-1kg"]), "--mass");
    refuses(
        &damped(&[
            "--zeta",
            "0.1",
            "--trajectory",
            out,
            "--sample-interval",
            "0s",
        ]),
        "--sample-interval",
    );
    refuses(
        &damped(&[
            "--zeta",
            "0.1",
            "--trajectory",
            out,
            "--sample-interval",
            "-1ms",
        ]),
        "--sample-interval",
    );
    refuses(
        &damped(&[
            "--zeta",
            "0.1",
            "--trajectory",
            out,
            "--duration",
            "1e6s",
            "--sample-interval",
            "1ms",
        ]),
        "--force",
    );
    refuses(
        &damped(&["--zeta", "0.1", "--trajectory", out, "--duration", "-1s"]),
        "--duration",
    );
    folder_is_empty(dir.path());
    let missing = dir.path().join("no/such/folder/run.csv");
    refuses(
        &damped(&["--zeta", "0.1", "--trajectory", missing.to_str().unwrap()]),
        "--trajectory",
    );
    folder_is_empty(dir.path());
    // And the plain run still works.
    pendulum()
        .args(damped(&["--zeta", "0.1"]))
        .assert()
        .success();
}
