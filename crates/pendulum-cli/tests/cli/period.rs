//! `pendulum period`, `length`, `amplitude`, `gravity`.

use crate::util::{f, json, p, pendulum, refuses};
use predicates::prelude::*;

#[test]
fn period_json_has_the_documented_keys() {
    let v = json(&["period", "--length", "0.99362m", "--amplitude", "2deg"]);
    for key in [
        "length_m",
        "g_m_s2",
        "amplitude_rad",
        "period_s",
        "small_angle_period_s",
        "period_ratio",
        "beats_per_hour",
        "circular_error_s_per_day",
        "circular_error_s_per_day_per_deg",
    ] {
        assert!(v[key].is_number(), "{key} in {v}");
    }
    assert_eq!(v["series"]["terms"], 3);
    assert!(v["series"]["period_s"].is_number());
    assert!(v["series"]["relative_error"].as_f64().unwrap() < 0.0);
    // The seconds pendulum at 2 degrees loses 6.58 s/day.
    assert!((f(&v, "circular_error_s_per_day") - 6.58).abs() < 0.005);
    assert_eq!(f(&v, "amplitude_rad"), 2.0_f64.to_radians());
    assert!((f(&v, "beats_per_hour") - 7200.0 / f(&v, "period_s")).abs() < 1e-9);
}

#[test]
fn period_ratio_at_ten_and_ninety_degrees() {
    let r10 = f(
        &json(&["period", "--length", "1", "--amplitude", "10"]),
        "period_ratio",
    );
    let r90 = f(
        &json(&["period", "--length", "1", "--amplitude", "90deg"]),
        "period_ratio",
    );
    assert!((r10 - 1.001_907_188_143_216_6).abs() < 1e-15);
    assert!((r90 - 1.180_340_599_016_096_2).abs() < 1e-15);
}

#[test]
fn units_agree() {
    let a = json(&["period", "--length", "994mm", "--amplitude", "30arcmin"]);
    let b = json(&["period", "--length", "0.994m", "--amplitude", "0.5deg"]);
    assert_eq!(f(&a, "length_m"), f(&b, "length_m"));
    assert!((f(&a, "period_s") - f(&b, "period_s")).abs() < 1e-15);
}

#[test]
fn series_terms_are_honoured() {
    let v = json(&[
        "period",
        "--length",
        "1",
        "--amplitude",
        "30deg",
        "--series-terms",
        "8",
    ]);
    assert_eq!(v["series"]["terms"], 8);
    let v3 = json(&["period", "--length", "1", "--amplitude", "30deg"]);
    let e8 = v["series"]["relative_error"].as_f64().unwrap().abs();
    let e3 = v3["series"]["relative_error"].as_f64().unwrap().abs();
    assert!(e8 < e3 / 100.0, "{e8} vs {e3}");
}

#[test]
fn latitude_changes_g() {
    let v = json(&[
        "period",
        "--length",
        "1",
        "--amplitude",
        "3",
        "--latitude",
        "-33.87",
        "--height",
        "50m",
    ]);
    let g = json(&["gravity", "--latitude", "-33.87", "--height", "50"]);
    assert_eq!(f(&v, "g_m_s2"), f(&g, "g_m_s2"));
    assert!((f(&g, "g_m_s2") - 9.7962).abs() < 1e-3);
}

#[test]
fn period_table_has_one_row_per_amplitude() {
    let args = [
        "period",
        "--length",
        "1",
        "--amplitude",
        "1deg..10deg",
        "--steps",
        "10",
    ];
    let out = pendulum()
        .args(args)
        .arg("--csv")
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    let mut reader = csv::Reader::from_reader(out.as_slice());
    let header: Vec<String> = reader.headers().unwrap().iter().map(String::from).collect();
    for key in [
        "amplitude_rad",
        "period_s",
        "circular_error_s_per_day",
        "series_relative_error",
    ] {
        assert!(header.iter().any(|h| h == key), "{key} in {header:?}");
    }
    let rows: Vec<csv::StringRecord> = reader.records().map(|r| r.unwrap()).collect();
    assert_eq!(rows.len(), 10);
    let deg = header.iter().position(|h| h == "amplitude_deg").unwrap();
    assert_eq!(rows[0][deg].parse::<f64>().unwrap(), 1.0);
    assert_eq!(rows[9][deg].parse::<f64>().unwrap(), 10.0);
    // The text table: a title, a header and ten rows.
    pendulum()
        .args(args)
        .assert()
        .success()
        .stdout(predicate::function(|s: &str| s.lines().count() == 12));
}

#[test]
fn length_of_the_seconds_pendulum() {
    let v = json(&["length", "--period", "2s"]);
    assert!((f(&v, "length_m") - 0.99362).abs() < 5e-6);
    let b = json(&["length", "--bph", "3600"]);
    assert_eq!(f(&b, "length_m"), f(&v, "length_m"));
    // At 3 degrees the same period needs a slightly shorter rod.
    let a = json(&["length", "--period", "2s", "--amplitude", "3deg"]);
    assert!(f(&a, "length_m") < f(&v, "length_m"));
}

#[test]
fn amplitude_inverts_period() {
    let p = json(&["period", "--length", "0.99362", "--amplitude", "4.5deg"]);
    let period = format!("{}s", f(&p, "period_s"));
    let a = json(&["amplitude", "--period", &period, "--length", "0.99362"]);
    assert!((f(&a, "amplitude_rad") - 4.5_f64.to_radians()).abs() < 1e-10);
    let kappa = f(&a, "condition_number");
    // About 8/A0² at small amplitudes.
    let expected = 8.0 / 4.5_f64.to_radians().powi(2);
    assert!(
        (kappa / expected - 1.0).abs() < 0.01,
        "{kappa} vs {expected}"
    );
}

#[test]
fn help_and_version_succeed() {
    pendulum()
        .arg("--help")
        .assert()
        .success()
        .stdout(predicate::str::contains("period"));
    pendulum().arg("--version").assert().success();
    pendulum()
        .args(["period", "--help"])
        .assert()
        .success()
        .stdout(predicate::str::contains("--amplitude"));
}

#[test]
fn bad_input_is_one_line_with_status_two() {
    let m = refuses(
        &["period", "--length", "-1", "--amplitude", "3"],
        "--length",
    );
    assert_eq!(m.trim_end(), "error: --length: must be positive, got -1 m");
    refuses(&["period", "--length", "0", "--amplitude", "3"], "--length");
    refuses(
        &["period", "--length", "3parsecs", "--amplitude", "3"],
        "parsecs",
    );
    refuses(
        &["period", "--length", "1", "--amplitude", "3m"],
        "--amplitude",
    );
    refuses(
        &["period", "--length", "nan", "--amplitude", "3"],
        "--length",
    );
    refuses(
        &["period", "--length", "inf", "--amplitude", "3"],
        "--length",
    );
    refuses(
        &["period", "--length", "1", "--amplitude", "NaN"],
        "--amplitude",
    );
    refuses(
        &["period", "--length", "1e999", "--amplitude", "3"],
        "--length",
    );
    let m = refuses(
        &["period", "--length", "1", "--amplitude", "180deg"],
        "--amplitude",
    );
    assert!(m.contains("inverted"), "{m}");
    refuses(
        &["period", "--length", "1", "--amplitude", "200"],
        "--amplitude",
    );
    refuses(
        &["period", "--length", "1", "--amplitude", "-3deg"],
        "--amplitude",
    );
    refuses(&p(&["--g", "-9.8"]), "--g");
    refuses(&p(&["--g", "0"]), "--g");
    refuses(&p(&["--latitude", "91"]), "--latitude");
    refuses(&p(&["--latitude", "-90.5"]), "--latitude");
    refuses(&p(&["--series-terms", "0"]), "--series-terms");
    refuses(&p(&["--bogus"]), "--bogus");
    refuses(
        &["period", "--length", "1", "--amplitude", "1..190"],
        "--amplitude",
    );
    refuses(
        &[
            "period",
            "--length",
            "1",
            "--amplitude",
            "1..10",
            "--steps",
            "0",
        ],
        "--steps",
    );
    refuses(&["period", "--amplitude", "3"], "--length");
    refuses(
        &["amplitude", "--period", "1.9s", "--length", "0.99362"],
        "--period",
    );
    refuses(
        &["amplitude", "--period", "-2s", "--length", "0.99362"],
        "--period",
    );
    refuses(&["length", "--period", "0s"], "--period");
    refuses(&["length", "--bph", "-3600"], "--bph");
    refuses(&["length", "--bph", "fast"], "--bph");
    refuses(&["gravity", "--latitude", "100"], "--latitude");
    refuses(
        &["gravity", "--latitude", "10", "--height", "3kg"],
        "--height",
    );
}

/// A design on a stiff suspension spring (`examples/invar-spring.toml`
/// with a spring 3 mm thick: an elastic share of 0.86): `period --design`
/// takes the spring's circular error, which at 2° is `1 - ε` of the rigid
/// pendulum's of the same equivalent length to the order `A²` (1e-3 here),
/// its JSON has the design's share and no series; `simulate --design` and
/// `amplitude --design`, which swing the rigid pendulum, warn with both
/// figures; `amplitude --design` inverts the spring's period.
#[test]
fn a_design_on_a_spring() {
    let dir = tempfile::tempdir().unwrap();
    let example = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/invar-spring.toml"),
    )
    .unwrap();
    assert!(example.contains("thickness = \"0.1 mm\""), "{example}");
    let stiff = dir.path().join("stiff.toml");
    std::fs::write(
        &stiff,
        example.replace("thickness = \"0.1 mm\"", "thickness = \"3 mm\""),
    )
    .unwrap();
    let design = stiff.to_str().unwrap();
    let sheet = json(&["design", design]);
    let share = sheet["spring"]["elastic_share"].as_f64().unwrap();
    let length = f(&sheet, "equivalent_length_m").to_string();
    assert!((0.5..0.95).contains(&share), "{share}");
    let on_spring = json(&["period", "--design", design, "--amplitude", "2deg"]);
    let rigid = json(&["period", "--length", &length, "--amplitude", "2deg"]);
    let (ours, theirs) = (
        f(&on_spring, "circular_error_s_per_day"),
        f(&rigid, "circular_error_s_per_day"),
    );
    assert!(
        (ours / ((1.0 - share) * theirs) - 1.0).abs() < 1e-3,
        "{ours} {theirs}"
    );
    assert_eq!(f(&on_spring, "elastic_share"), share);
    assert!(on_spring.get("series").is_none(), "{on_spring}");
    assert!(rigid.get("elastic_share").is_none());
    let swing = |design: &str| {
        json(&[
            "simulate",
            "--design",
            design,
            "--amplitude",
            "10deg",
            "--q",
            "1e9",
            "--duration",
            "6s",
        ])
    };
    let warned = swing(design)["warnings"].to_string();
    assert!(warned.contains("suspension spring"), "{warned}");
    // The amplitude a period implies on the spring is the spring's: the
    // period at 2° gives back 2° (within the period's 1e-12 printed digits
    // times its conditioning, 1e4 at 2°).
    let implied = json(&[
        "amplitude",
        "--design",
        design,
        "--period",
        &format!("{}s", f(&on_spring, "period_s")),
    ]);
    let back = f(&implied, "amplitude_deg");
    assert!((back / 2.0 - 1.0).abs() < 1e-6, "{implied}");
    // A rigid design is not warned.
    let plain = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/seconds-steel-brass.toml");
    let run = swing(plain.to_str().unwrap());
    assert_eq!(run["warnings"].as_array().map(Vec::len), Some(0), "{run}");
}
