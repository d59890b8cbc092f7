//! A phone's gyroscope swinging with the pendulum (phyphox's exports, CSV
//! and the Excel workbook), fitted by the models' derivative, through the
//! real binary. The records in `tests/data/gyroscope/` and their truth
//! were made by SciPy (`tools/reference/gyroscope_records.py`), not by the
//! tool.

use super::util::{f, json, pendulum, refuses};
use serde_json::Value;
use std::path::Path;

fn data(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/gyroscope")
        .join(name)
        .to_str()
        .unwrap()
        .to_string()
}

fn truth(name: &str) -> Value {
    let text = std::fs::read_to_string(data("truth.json")).unwrap();
    serde_json::from_str::<Value>(&text).unwrap()[name].clone()
}

/// Fits a committed record with its length and checks g, ω_n, the first
/// crest's time and amplitude within three standard errors of the truth,
/// and the swing's axis in the sensor's axes.
fn fits_its_truth(name: &str) -> Value {
    let t = truth(name);
    let length = format!("{}m", f(&t, "length_m"));
    let r = json(&["fit", "trajectory", &data(name), "--length", &length]);
    assert_eq!(r["observed"], "angular_velocity", "{r}");
    assert!(r.get("residual_rms_rad").is_none(), "{r}");
    assert!(f(&r, "residual_rms_rad_s") > 0.0);
    for key in [
        "g_m_s2",
        "omega_n_rad_s",
        "first_crest_time_s",
        "first_crest_amplitude_rad",
    ] {
        let (v, se) = (f(&r["parameters"], key), f(&r["standard_errors"], key));
        let z = (v - f(&t, key)) / se;
        assert!(
            z.abs() < 3.0,
            "{name} {key}: {v} ± {se}, truth {} ({z}σ)",
            t[key]
        );
    }
    let axis: Vec<f64> = r["gyroscope_axis"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    for (got, want) in axis.iter().zip(t["axis"].as_array().unwrap()) {
        assert!(
            (got - want.as_f64().unwrap()).abs() < 0.01,
            "{axis:?} vs {}",
            t["axis"]
        );
    }
    assert!(f(&r, "gyroscope_axis_share") > 0.99, "{r}");
    r
}

#[test]
fn a_phyphox_gyroscope_csv_is_fitted_by_the_derivative_of_the_motion() {
    let r = fits_its_truth("gyroscope-comma.csv");
    assert_eq!(r["format"]["separator"], "comma");
    // The magnitude column would double the frequency: never read.
    let columns = r["format"]["angular_velocity_columns"].as_array().unwrap();
    assert_eq!(columns.len(), 3, "{columns:?}");
    assert!(columns
        .iter()
        .all(|c| c.as_str().unwrap().starts_with("Gyroscope")));
    assert!(r["format"]["columns_used"]
        .as_array()
        .unwrap()
        .iter()
        .all(|c| c != "Absolute (rad/s)"));
    assert_eq!(r["parameters"].get("offset_rad"), None);
    assert!(r["parameters"]["rate_offset_rad_s"].is_number());
    assert_eq!(r["warnings"].as_array().unwrap().len(), 0, "{r}");
}

#[test]
fn the_pendulum_experiments_semicolon_export_with_decimal_commas_is_read() {
    let r = fits_its_truth("rotation-semicolon.csv");
    assert_eq!(r["format"]["separator"], "semicolon");
    assert_eq!(r["format"]["decimal"], "comma");
    // A 60° swing in air: quadratic drag, the law the record was made with.
    assert!(
        r["damping_law"].as_str().unwrap().contains("quadratic"),
        "{r}"
    );
}

#[test]
fn the_excel_workbooks_raw_data_sheet_is_read_and_a_held_phone_left_out() {
    let r = fits_its_truth("gyroscope.xls");
    assert_eq!(r["format"]["sheet"], "Raw Data");
    // Held still for its first second at 100 samples a second.
    let held = r["held_samples"].as_u64().unwrap();
    assert!((95..=101).contains(&held), "{held}");
}

#[test]
fn a_window_leaves_out_the_ends_of_a_record() {
    let r = json(&[
        "fit",
        "trajectory",
        &data("gyroscope.xls"),
        "--from",
        "2s",
        "--to",
        "9000ms",
    ]);
    let w = r["format"]["window_s"].as_array().unwrap();
    assert!((w[0].as_f64().unwrap() - 2.0).abs() < 0.011, "{w:?}");
    assert!((w[1].as_f64().unwrap() - 9.0).abs() < 0.011, "{w:?}");
    assert_eq!(r["held_samples"], 0);
    let points = r["points"].as_u64().unwrap();
    assert!((699..=701).contains(&points), "{points}");
    let e = refuses(
        &["fit", "trajectory", &data("gyroscope.xls"), "--from", "50"],
        "--from",
    );
    assert!(e.contains("from 50 s on") && !e.contains("inf"), "{e}");
    let e = refuses(
        &["fit", "trajectory", &data("gyroscope.xls"), "--to", "-5"],
        "--to",
    );
    assert!(e.contains("up to -5 s") && !e.contains("inf"), "{e}");
    refuses(
        &[
            "fit",
            "trajectory",
            &data("gyroscope.xls"),
            "--from",
            "5",
            "--to",
            "4",
        ],
        "--to",
    );
}

/// Rates in degrees a second under a radian's name: a swing of many turns,
/// refused with the likely cause.
#[test]
fn rates_in_degrees_under_a_radians_name_are_refused() {
    let text = std::fs::read_to_string(data("gyroscope-comma.csv")).unwrap();
    let mut lines = text.lines();
    let mut out = format!("{}\n", lines.next().unwrap());
    for line in lines {
        let cells: Vec<String> = line
            .split(',')
            .enumerate()
            .map(|(i, c)| {
                let v: f64 = c.parse().unwrap();
                if i == 0 {
                    c.to_string()
                } else {
                    (v.to_degrees()).to_string()
                }
            })
            .collect();
        out.push_str(&cells.join(","));
        out.push('\n');
    }
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("degrees.csv");
    std::fs::write(&path, out).unwrap();
    let e = refuses(&["fit", "trajectory", path.to_str().unwrap()], "degrees");
    assert!(e.contains("half turn"), "{e}");
}

#[test]
fn a_gyroscope_record_given_to_fit_decay_is_sent_to_fit_trajectory() {
    let e = refuses(
        &["fit", "decay", &data("gyroscope-comma.csv")],
        "fit trajectory",
    );
    assert!(e.contains("gyroscope"), "{e}");
}

#[test]
fn a_magnitude_alone_is_no_swing() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("abs.csv");
    let mut text = String::from("\"Time (s)\",\"Absolute (rad/s)\"\n");
    for i in 0..200 {
        let t = i as f64 * 0.01;
        text.push_str(&format!("{t},{}\n", (4.0 * t).sin().abs()));
    }
    std::fs::write(&path, text).unwrap();
    refuses(&["fit", "trajectory", path.to_str().unwrap()], "no angle");
}

/// A phone's export that writes a sample twice, out of time order: the
/// copy is dropped and named; a row out of order with readings of its
/// own is still refused.
#[test]
fn a_row_repeated_out_of_time_order_is_dropped_and_named() {
    let text = std::fs::read_to_string(data("gyroscope-comma.csv")).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let mut rows: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
    // Line 501 (row 500) written again after line 502.
    rows.insert(502, lines[500].to_string());
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("repeat.csv");
    std::fs::write(&path, rows.join("\n")).unwrap();
    let r = json(&["fit", "trajectory", path.to_str().unwrap()]);
    assert_eq!(
        r["format"]["repeated_rows_dropped"][0], 503,
        "{}",
        r["format"]
    );
    assert_eq!(r["points"], 2000);
    // The copy written under a time of its own that runs back (the
    // stamp of the row before it, as a real phyphox export has one):
    // dropped as well.
    let mut restamped: Vec<String> = rows.clone();
    let mut cells: Vec<String> = rows[502].split(',').map(str::to_string).collect();
    cells[0] = rows[501].split(',').next().unwrap().to_string();
    restamped[502] = cells.join(",");
    std::fs::write(&path, restamped.join("\n")).unwrap();
    let r = json(&["fit", "trajectory", path.to_str().unwrap()]);
    assert_eq!(
        r["format"]["repeated_rows_dropped"][0], 503,
        "{}",
        r["format"]
    );
    // The same row with its readings changed is a time out of order.
    let mut changed: Vec<String> = rows.clone();
    let mut cells: Vec<&str> = rows[502].split(',').collect();
    cells[1] = "1.5E-1";
    changed[502] = cells.join(",");
    std::fs::write(&path, changed.join("\n")).unwrap();
    let out = pendulum()
        .args(["fit", "trajectory", path.to_str().unwrap()])
        .assert()
        .code(2)
        .get_output()
        .stderr
        .clone();
    let e = String::from_utf8(out).unwrap();
    assert!(e.contains("line 503"), "{e}");
}

/// A record whose fit is estimated beyond five seconds (60,000 samples at
/// the measured 100 µs each) needs --force, and says so before any work;
/// nothing is written.
#[test]
fn a_long_record_needs_force() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("long.csv");
    let mut text = String::from("time_s,angle_deg\n");
    for i in 0..60_000 {
        let t = i as f64 / 500.0;
        text.push_str(&format!("{t},{}\n", 10.0 * (3.0 * t).cos()));
    }
    std::fs::write(&path, text).unwrap();
    let e = refuses(&["fit", "trajectory", path.to_str().unwrap()], "--force");
    assert!(e.contains("60000 rows"), "{e}");
    assert_eq!(super::util::files_in(dir.path()).len(), 1);
}
